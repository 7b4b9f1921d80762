//! Minimum-cost *maximum* matchings: the pairing of least total cost among those that leave the
//! fewest nodes unmatched, for graphs without a perfect matching (the duals of surfaces with
//! boundary), with a certificate and its independent verifier.
//!
//! # The reduction (ours)
//! A maximum matching M of G leaves `d_C` nodes unmatched in each connected component C, its
//! deficiency, all of them in the odd components of `G − A` for the Tutte–Berge barrier A (a
//! matching that leaves `d_C` nodes of C unmatched matches every node of `A ∩ C` into a distinct
//! odd component and leaves one node in each of the others: Tutte–Berge's count is tight). Let H
//! be G with `d_C` new *dummy* nodes per component, each joined to every node of C's odd
//! components by an edge of cost κ. A perfect matching of H is a matching of G leaving exactly
//! `d_C` nodes of C unmatched, all in its odd components (each taken by a dummy), so of maximum
//! size; conversely every maximum matching of G extends to a perfect matching of H by matching
//! its unmatched nodes to the dummies. All perfect matchings of H hold `Σ d_C` dummy edges, so
//! they cost κ `Σ d_C` more than their part in G: the minimum-cost perfect matching of H is a
//! minimum-cost maximum matching of G. κ is the largest cost of G (any value would do; the
//! largest keeps the dummy edges from lowering the solver's initial duals).
//!
//! The exact solver of [`super::blossom`] pairs H, with the dummies' edges beyond the three of
//! each vertex record as extra lists; a graph with a perfect matching (every `d_C = 0`) is paired
//! by [`super::min_cost_perfect_matching`] itself.
//!
//! # The certificate and its verifier
//! [`MaximumCertificate`]: the barrier A, κ, which dummy takes each unmatched node, and the dual
//! solution of H ([`Certificate`], node duals for G's node slots then the dummies).
//! [`verify_min_cost_maximum_matching`] reads only G, the costs, the matched edges and the
//! certificate: it checks the matching's maximality with the barrier
//! ([`crate::verify_maximum_pairing`], the cardinality's independent verifier, which also gives
//! the components and their odd parts), builds H itself from them, and checks the perfect
//! matching `M ∪ {unmatched node — its dummy}` of H against the dual solution with the checks of
//! [`super::certificate`] (dual feasibility of every edge of H, tightness of the matched ones,
//! the blossoms' complementary slackness, the objectives' equality). Optimal on H, hence of least
//! cost among the maximum matchings of G.
//!
//! Cost: H has `n + Σ d_C` nodes and `m + Σ d_C |S_C|` edges (`S_C` the nodes of C's odd
//! components): linear while the deficiencies are small (surfaces with a few holes: `d_C` of 0
//! or 1); a piece with a large deficiency and many candidate nodes makes H large, so
//! [`MAX_AUXILIARY_EDGES`] bounds it ([`WeightedError::AuxiliaryTooLarge`]).

use surftopo_mesh::UnionFind;

use super::blossom::{BlossomStats, ExtraLists, solve_with_extra};
use super::certificate::{Certificate, CertificateError, CostGraph, cost_count, verify_on};
use super::{WeightedError, check_costs, min_cost_perfect_matching};
use crate::augment::AugmentStrategy;
use crate::dual_graph::{DualGraph, NONE};
use crate::verify_maximum::verify_maximum_pairing;

/// The most dummy edges the auxiliary graph may have beyond `4 m + 10⁶` (m the graph's edge
/// slots): past that, [`min_cost_maximum_matching`] refuses instead of building a quadratic
/// graph.
pub const MAX_AUXILIARY_EDGES: usize = 1_000_000;

/// The proof that a matching is of least cost among the maximum matchings (see the module doc).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct MaximumCertificate {
    /// The Tutte–Berge barrier A (sorted): the matching is maximum.
    pub barrier: Vec<u32>,
    /// κ, the cost of every dummy edge.
    pub exposure_cost: i64,
    /// Per unmatched node, the dummy it is matched to in H: `(node, dummy)`, the dummies of a
    /// component numbered `0..d_C` after those of the components before it (components in the
    /// order of their first node).
    pub exposed: Vec<(u32, u32)>,
    /// The dual solution of H for the doubled costs: node duals and sets for G's node slots,
    /// then one per dummy.
    pub duals: Certificate,
}

/// A minimum-cost maximum matching and its proof.
#[derive(Clone, Debug, PartialEq)]
pub struct MinCostMaximumMatching {
    /// The matched edges of G, in increasing order.
    pub edges: Vec<u32>,
    /// Their total cost.
    pub cost: i64,
    /// Nodes left unmatched.
    pub unmatched: usize,
    /// The proof.
    pub certificate: MaximumCertificate,
    /// How the solver's run went (on H).
    pub stats: BlossomStats,
}

/// The minimum-cost maximum matching of `graph` for `costs` (one per edge slot), with its
/// certificate (see the module doc): the cardinality by KS ([`crate::karp_sipser_maximum_with`])
/// and its barrier, then the exact solver on the auxiliary graph H. On a graph with a perfect
/// matching, [`super::min_cost_perfect_matching`]'s matching and duals. Deterministic.
///
/// # Errors
/// [`WeightedError::CostCount`] / [`WeightedError::CostOutOfRange`] for bad costs;
/// [`WeightedError::AuxiliaryTooLarge`] when H would exceed its bound;
/// [`WeightedError::NoPerfectMatching`] if the solver finds none in H (a bug: H has one).
pub fn min_cost_maximum_matching<G: DualGraph + ?Sized>(
    graph: &G,
    costs: &[i64],
) -> Result<MinCostMaximumMatching, WeightedError> {
    check_costs(graph, costs)?;
    let (mut pairing, _, mut barrier) = crate::karp_sipser_maximum_with(graph, &Default::default());
    if barrier.is_empty() && pairing.unmatched_count(graph) > 0 {
        // KS proved maximality by parity alone; the exposure sets want the Gallai–Edmonds
        // barrier, which a search from the unmatched nodes gives.
        barrier = crate::augment_to_maximum(graph, &mut pairing, AugmentStrategy::Forest)
            .expect("KS's pairing fits its graph")
            .1;
    }
    let sets = ExposureSets::of(graph, &barrier);
    if sets.dummies == 0 {
        let exact = min_cost_perfect_matching(graph, costs)?;
        return Ok(MinCostMaximumMatching {
            edges: exact.edges,
            cost: exact.cost,
            unmatched: 0,
            certificate: MaximumCertificate {
                barrier,
                exposure_cost: 0,
                exposed: Vec::new(),
                duals: exact.certificate,
            },
            stats: exact.stats,
        });
    }
    let (n, m) = (graph.node_slots(), graph.edge_slots());
    let dummy_edges: usize = sets
        .deficiency
        .iter()
        .zip(&sets.candidates)
        .map(|(&d, s)| d * s.len())
        .sum();
    if dummy_edges > 4 * m + MAX_AUXILIARY_EDGES {
        return Err(WeightedError::AuxiliaryTooLarge {
            dummies: sets.dummies,
            dummy_edges,
        });
    }
    let kappa = (0..m as u32)
        .filter(|&e| graph.is_edge(e))
        .map(|e| costs[e as usize])
        .max()
        .unwrap_or(0);
    // H: G's records, the dummies after; G's edges, then the dummy edges.
    let mut adjacency = graph.adjacency_table().adjacent;
    adjacency.resize(n + sets.dummies, [(NONE, NONE); 3]);
    let mut edges: Vec<([u32; 2], i64)> = (0..m as u32)
        .map(|e| {
            let ends = if graph.is_edge(e) {
                graph.endpoints(e)
            } else {
                [NONE, NONE]
            };
            (ends, costs[e as usize].max(0))
        })
        .collect();
    let mut extra: Vec<Vec<(u32, u32)>> = vec![Vec::new(); n + sets.dummies];
    let mut dummy = n as u32;
    for (c, candidates) in sets.candidates.iter().enumerate() {
        for _ in 0..sets.deficiency[c] {
            for &v in candidates {
                let e = edges.len() as u32;
                edges.push(([v, dummy], kappa));
                extra[v as usize].push((e, dummy));
                extra[dummy as usize].push((e, v));
            }
            dummy += 1;
        }
    }
    let mut start = Vec::with_capacity(extra.len() + 1);
    let mut pairs = Vec::with_capacity(2 * dummy_edges);
    for list in &extra {
        start.push(pairs.len() as u32);
        pairs.extend_from_slice(list);
    }
    start.push(pairs.len() as u32);
    let lists = ExtraLists {
        start: start.into(),
        pairs: pairs.into(),
    };
    let mut is_live: Vec<bool> = (0..n as u32).map(|v| graph.is_node(v)).collect();
    is_live.resize(n + sets.dummies, true);
    let (matched, duals, stats) = solve_with_extra(adjacency, lists, &edges, is_live)?;
    let mut real = Vec::new();
    let mut exposed = Vec::new();
    for e in matched {
        if (e as usize) < m {
            real.push(e);
        } else {
            let [v, z] = edges[e as usize].0;
            exposed.push((v, z - n as u32));
        }
    }
    exposed.sort_unstable();
    let cost = real.iter().map(|&e| costs[e as usize]).sum();
    Ok(MinCostMaximumMatching {
        edges: real,
        cost,
        unmatched: exposed.len(),
        certificate: MaximumCertificate {
            barrier,
            exposure_cost: kappa,
            exposed,
            duals,
        },
        stats,
    })
}

/// Per connected component of G (in the order of their first node): its deficiency
/// `odd(C − A) − |A ∩ C|` and the nodes of its odd components of `G − A` (increasing), from the
/// barrier A.
struct ExposureSets {
    deficiency: Vec<usize>,
    candidates: Vec<Vec<u32>>,
    dummies: usize,
}

impl ExposureSets {
    fn of<G: DualGraph + ?Sized>(graph: &G, barrier: &[u32]) -> Self {
        let slots = graph.node_slots();
        let mut in_barrier = vec![false; slots];
        for &a in barrier {
            in_barrier[a as usize] = true;
        }
        let mut whole = UnionFind::new(slots);
        let mut rest = UnionFind::new(slots);
        for e in 0..graph.edge_slots() as u32 {
            if !graph.is_edge(e) {
                continue;
            }
            let [a, b] = graph.endpoints(e);
            if a != b {
                whole.union(a, b);
                if !in_barrier[a as usize] && !in_barrier[b as usize] {
                    rest.union(a, b);
                }
            }
        }
        let mut number = vec![NONE; slots];
        let mut component = vec![NONE; slots];
        let mut size = vec![0u32; slots];
        let mut count = 0usize;
        for v in (0..slots as u32).filter(|&v| graph.is_node(v)) {
            let root = whole.find(v) as usize;
            if number[root] == NONE {
                number[root] = count as u32;
                count += 1;
            }
            component[v as usize] = number[root];
            if !in_barrier[v as usize] {
                size[rest.find(v) as usize] += 1;
            }
        }
        let mut odd = vec![0i64; count];
        for v in (0..slots as u32).filter(|&v| graph.is_node(v)) {
            if in_barrier[v as usize] {
                odd[component[v as usize] as usize] -= 1;
            } else if rest.find(v) == v && size[v as usize] % 2 == 1 {
                odd[component[v as usize] as usize] += 1;
            }
        }
        let deficiency: Vec<usize> = odd.iter().map(|&d| d.max(0) as usize).collect();
        let mut candidates = vec![Vec::new(); count];
        for v in (0..slots as u32).filter(|&v| graph.is_node(v) && !in_barrier[v as usize]) {
            let c = component[v as usize] as usize;
            if deficiency[c] > 0 && size[rest.find(v) as usize] % 2 == 1 {
                candidates[c].push(v);
            }
        }
        let dummies = deficiency.iter().sum();
        ExposureSets {
            deficiency,
            candidates,
            dummies,
        }
    }
}

/// Checks that `matched` is a matching of least cost among the maximum matchings of `graph` for
/// `costs`, with `certificate` as the proof (see the module doc). Returns its cost.
///
/// # Errors
/// [`CertificateError::NotMaximum`] when the barrier does not prove the matching maximum; the
/// other [`CertificateError`]s when the dual solution does not prove it of least cost.
pub fn verify_min_cost_maximum_matching<G: DualGraph + ?Sized>(
    graph: &G,
    costs: &[i64],
    matched: &[u32],
    certificate: &MaximumCertificate,
) -> Result<i64, CertificateError> {
    cost_count(graph, costs)?;
    let kappa = certificate.exposure_cost;
    if !(0..=super::MAX_COST).contains(&kappa) {
        return Err(CertificateError::Size(format!("exposure cost {kappa}")));
    }
    let pairing = crate::Pairing::from_edges(graph, matched.iter().copied())
        .map_err(|err| CertificateError::Size(format!("not a matching: {err}")))?;
    let maximum = verify_maximum_pairing(graph, pairing, &certificate.barrier)
        .map_err(|err| CertificateError::NotMaximum(err.to_string()))?;
    // H: per component, its deficiency's dummies, each joined to the component's odd parts.
    let n = graph.node_slots();
    let mut first_dummy = Vec::with_capacity(maximum.components().len());
    let mut dummies = 0u32;
    for c in maximum.components() {
        first_dummy.push(dummies);
        dummies += c.deficiency_lower_bound as u32;
    }
    let mut candidates: Vec<Vec<u32>> = vec![Vec::new(); maximum.components().len()];
    for v in (0..n as u32).filter(|&v| maximum.is_exposable(v)) {
        candidates[maximum.component_of()[v as usize] as usize].push(v);
    }
    let mut dummy_component = Vec::with_capacity(dummies as usize);
    for (c, figures) in maximum.components().iter().enumerate() {
        dummy_component.extend(std::iter::repeat_n(
            c as u32,
            figures.deficiency_lower_bound,
        ));
    }
    let mut dummy_base = Vec::with_capacity(dummies as usize + 1);
    let mut next = graph.edge_slots();
    for &c in &dummy_component {
        dummy_base.push(next);
        next += candidates[c as usize].len();
    }
    dummy_base.push(next);
    let auxiliary = Auxiliary {
        graph,
        costs,
        kappa,
        n,
        dummy_component,
        dummy_base,
        candidates: &candidates,
    };
    // The perfect matching of H: M, and each unmatched node to its dummy.
    let mut h_matched = matched.to_vec();
    let unmatched = maximum.unmatched();
    if certificate.exposed.len() != unmatched {
        return Err(CertificateError::Size(format!(
            "{} exposures for {unmatched} unmatched nodes",
            certificate.exposed.len()
        )));
    }
    for &(v, z) in &certificate.exposed {
        let edge = auxiliary.dummy_edge(v, z).ok_or_else(|| {
            CertificateError::Size(format!("node {v} cannot be matched to dummy {z}"))
        })?;
        h_matched.push(edge);
    }
    let doubled = verify_on(&auxiliary, &h_matched, &certificate.duals)?;
    // The dummies' part is κ per unmatched node.
    Ok(doubled - kappa * unmatched as i64)
}

/// The auxiliary graph H of the verifier (see the module doc): G's nodes and edges, then the
/// dummies and their edges, dummy `z`'s edges numbered from `dummy_base[z]` in the order of its
/// component's candidates.
struct Auxiliary<'a, G: ?Sized> {
    graph: &'a G,
    costs: &'a [i64],
    kappa: i64,
    n: usize,
    dummy_component: Vec<u32>,
    dummy_base: Vec<usize>,
    candidates: &'a [Vec<u32>],
}

impl<G: DualGraph + ?Sized> Auxiliary<'_, G> {
    /// The edge of H between node `v` and dummy `z`, if there is one.
    fn dummy_edge(&self, v: u32, z: u32) -> Option<u32> {
        let c = *self.dummy_component.get(z as usize)?;
        let i = self.candidates[c as usize].binary_search(&v).ok()?;
        Some((self.dummy_base[z as usize] + i) as u32)
    }
}

impl<G: DualGraph + ?Sized> CostGraph for Auxiliary<'_, G> {
    fn node_slots(&self) -> usize {
        self.n + self.dummy_component.len()
    }
    fn is_node(&self, v: u32) -> bool {
        if (v as usize) < self.n {
            self.graph.is_node(v)
        } else {
            (v as usize) < self.node_slots()
        }
    }
    fn edge_slots(&self) -> usize {
        *self.dummy_base.last().expect("one entry at least")
    }
    fn ends(&self, e: u32) -> Option<[u32; 2]> {
        let m = self.graph.edge_slots();
        if (e as usize) < m {
            return self.graph.is_edge(e).then(|| self.graph.endpoints(e));
        }
        let z = self.dummy_base.partition_point(|&b| b <= e as usize) - 1;
        let c = self.dummy_component[z];
        let v = self.candidates[c as usize][e as usize - self.dummy_base[z]];
        Some([v, (self.n + z) as u32])
    }
    fn cost(&self, e: u32) -> i64 {
        if (e as usize) < self.graph.edge_slots() {
            self.costs[e as usize]
        } else {
            self.kappa
        }
    }
}
