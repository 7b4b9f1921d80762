//! The optimality certificate of a minimum-cost perfect matching, and its independent verifier.
//!
//! # The linear program (Edmonds 1965)
//! For a graph with edge costs `c`, the perfect matching polytope is described by `x ≥ 0`,
//! `x(δ(v)) = 1` for every node and `x(δ(S)) ≥ 1` for every odd set `S` of at least three nodes.
//! Its dual: maximise `Σ_v y_v + Σ_S z_S` subject to `z_S ≥ 0` and, for every non-loop edge
//! `e = uv`, the reduced cost `c_e − y_u − y_v − Σ_{S : |S ∩ {u,v}| = 1} z_S ≥ 0`. A perfect
//! matching `M` and a feasible dual are both optimal iff complementary slackness holds: every
//! matched edge has reduced cost 0, and every set with `z_S > 0` has exactly one matched edge
//! leaving it, i.e. `(|S| − 1) / 2` matched edges inside it (Kolmogorov 2009, Section 2).
//!
//! # The certificate
//! [`Certificate`] holds the duals for the doubled costs `2c` (the solver's integer scale): one
//! `y` per node slot and one `z` per set of a laminar family given as a forest (each set's parent
//! set, each node's innermost set). Sets are the blossoms of the solver; sets not listed have
//! `z = 0`.
//!
//! # The verifier
//! [`verify_min_cost_perfect_matching`] reads only the graph, the costs, the matched edges and the
//! certificate (no code of the solver), in `i128` arithmetic so that no certificate, however
//! corrupted, can overflow it. It checks: the edges form a perfect matching; the family is a
//! forest (no cycle of parents) whose sets have odd size ≥ 3 and `z ≥ 0`; every non-loop edge has
//! reduced cost ≥ 0 and every matched edge 0; every set with `z > 0` has `(|S| − 1) / 2` matched
//! edges inside. Then the matching's cost equals half the dual objective (checked too), and is
//! the minimum. O(n + m · d) for sets nested d deep.

use thiserror::Error;

use crate::dual_graph::DualGraph;

/// "No set" (a top-level set's parent, a node in no set).
const NO_SET: u32 = u32::MAX;

/// One odd set of the certificate's laminar family (a blossom).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BlossomDual {
    /// The smallest set strictly containing this one (an index into [`Certificate::blossoms`]),
    /// or `u32::MAX` for a top-level set.
    pub parent: u32,
    /// Its dual `z ≥ 0`, for the doubled costs.
    pub dual: i64,
}

/// A dual solution for the doubled costs `2c` (see the module doc).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Certificate {
    /// `y_v` per node slot (0 for removed nodes).
    pub node_duals: Vec<i64>,
    /// The innermost set of each node slot (an index into [`Certificate::blossoms`]), or
    /// `u32::MAX` for a node in no set.
    pub node_blossom: Vec<u32>,
    /// The laminar family of odd sets with their duals.
    pub blossoms: Vec<BlossomDual>,
}

/// Why a matching and certificate do not prove a minimum-cost perfect matching. Each variant
/// names the node, edge or set at fault.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum CertificateError {
    /// The cost or certificate arrays do not fit the graph.
    #[error("size mismatch: {0}")]
    Size(String),
    /// A matched edge is not a live non-loop edge.
    #[error("matched edge {edge} is not a live non-loop edge")]
    BadEdge {
        /// The edge.
        edge: u32,
    },
    /// A node is covered by two matched edges.
    #[error("node {node} is covered by matched edges {first} and {second}")]
    CoveredTwice {
        /// The node.
        node: u32,
        /// First edge.
        first: u32,
        /// Second edge.
        second: u32,
    },
    /// A live node is covered by no matched edge.
    #[error("node {node} is not covered by the matching")]
    Uncovered {
        /// The node.
        node: u32,
    },
    /// A set's parent or a node's set is out of range, or a removed node is in a set.
    #[error("set index out of range or misplaced at {0}")]
    BadSetIndex(String),
    /// The parents of the sets form a cycle.
    #[error("set {set} is its own ancestor")]
    CyclicFamily {
        /// A set on the cycle.
        set: u32,
    },
    /// A set does not have an odd number ≥ 3 of nodes.
    #[error("set {set} has {size} nodes (needs an odd number >= 3)")]
    SetSize {
        /// The set.
        set: u32,
        /// Its node count.
        size: u64,
    },
    /// A set has a negative dual.
    #[error("set {set} has negative dual {dual}")]
    NegativeSetDual {
        /// The set.
        set: u32,
        /// Its dual.
        dual: i64,
    },
    /// An edge has negative reduced cost.
    #[error("edge {edge} has negative reduced cost {reduced} (doubled units)")]
    Infeasible {
        /// The edge.
        edge: u32,
        /// Its reduced cost.
        reduced: i128,
    },
    /// A matched edge has positive reduced cost.
    #[error("matched edge {edge} has reduced cost {reduced}, not 0 (doubled units)")]
    MatchedNotTight {
        /// The edge.
        edge: u32,
        /// Its reduced cost.
        reduced: i128,
    },
    /// A set with positive dual does not have (|S| − 1) / 2 matched edges inside.
    #[error("set {set} of {size} nodes has dual {dual} > 0 but {inside} matched edges inside")]
    SetNotFull {
        /// The set.
        set: u32,
        /// Its node count.
        size: u64,
        /// Its dual.
        dual: i64,
        /// Matched edges with both ends inside.
        inside: u64,
    },
    /// The barrier of a maximum-cardinality certificate does not prove the matching maximum
    /// ([`super::verify_min_cost_maximum_matching`]).
    #[error("the matching is not proven maximum: {0}")]
    NotMaximum(String),
    /// Primal and dual objectives differ (cannot happen when the other checks pass; kept as
    /// an arithmetic cross-check).
    #[error("primal cost {primal} (doubled) differs from dual objective {dual}")]
    ObjectiveGap {
        /// Twice the matching's cost.
        primal: i128,
        /// The dual objective.
        dual: i128,
    },
}

/// Checks that `matched` is a minimum-cost perfect matching of `graph` for `costs` (one per edge
/// slot), with `certificate` as the proof (see the module doc). Returns the matching's cost.
///
/// # Errors
/// The first failed check, as a [`CertificateError`] naming the node, edge or set.
pub fn verify_min_cost_perfect_matching<G: DualGraph + ?Sized>(
    graph: &G,
    costs: &[i64],
    matched: &[u32],
    certificate: &Certificate,
) -> Result<i64, CertificateError> {
    cost_count(graph, costs)?;
    verify_on(&(graph, costs), matched, certificate)
}

/// A verifier's first check: one cost per edge slot of `graph`.
pub(super) fn cost_count<G: DualGraph + ?Sized>(
    graph: &G,
    costs: &[i64],
) -> Result<(), CertificateError> {
    if costs.len() != graph.edge_slots() {
        return Err(CertificateError::Size(format!(
            "{} costs for {} edge slots",
            costs.len(),
            graph.edge_slots()
        )));
    }
    Ok(())
}

/// A graph with edge costs as the verifier reads it: node slots and their liveness, edge slots
/// with their ends (live edges only) and costs.
pub(super) trait CostGraph {
    /// Node slots.
    fn node_slots(&self) -> usize;
    /// Whether node slot `v` is a live node.
    fn is_node(&self, v: u32) -> bool;
    /// Edge slots.
    fn edge_slots(&self) -> usize;
    /// The ends of live edge `e` (equal for a loop), `None` for a removed slot.
    fn ends(&self, e: u32) -> Option<[u32; 2]>;
    /// The cost of live edge `e`.
    fn cost(&self, e: u32) -> i64;
}

impl<G: DualGraph + ?Sized> CostGraph for (&G, &[i64]) {
    fn node_slots(&self) -> usize {
        self.0.node_slots()
    }
    fn is_node(&self, v: u32) -> bool {
        self.0.is_node(v)
    }
    fn edge_slots(&self) -> usize {
        self.0.edge_slots()
    }
    fn ends(&self, e: u32) -> Option<[u32; 2]> {
        self.0.is_edge(e).then(|| self.0.endpoints(e))
    }
    fn cost(&self, e: u32) -> i64 {
        self.1[e as usize]
    }
}

/// [`verify_min_cost_perfect_matching`] on any [`CostGraph`].
pub(super) fn verify_on<C: CostGraph>(
    graph: &C,
    matched: &[u32],
    certificate: &Certificate,
) -> Result<i64, CertificateError> {
    check_sizes(graph, certificate)?;
    let cover = perfect_cover(graph, matched)?;
    let family = Family::new(graph, certificate)?;
    let (primal, inside_here) = check_edges(graph, certificate, &family, &cover)?;
    family.check_slackness(inside_here)?;
    let dual: i128 = (0..graph.node_slots())
        .filter(|&v| graph.is_node(v as u32))
        .map(|v| i128::from(certificate.node_duals[v]))
        .sum::<i128>()
        + family.sets.iter().map(|s| i128::from(s.dual)).sum::<i128>();
    if primal != dual {
        return Err(CertificateError::ObjectiveGap { primal, dual });
    }
    Ok((primal / 2) as i64)
}

/// One dual and one set per node slot.
fn check_sizes<C: CostGraph>(graph: &C, certificate: &Certificate) -> Result<(), CertificateError> {
    let node_slots = graph.node_slots();
    if certificate.node_duals.len() != node_slots || certificate.node_blossom.len() != node_slots {
        return Err(CertificateError::Size(format!(
            "{} node duals and {} node sets for {node_slots} node slots",
            certificate.node_duals.len(),
            certificate.node_blossom.len()
        )));
    }
    Ok(())
}

/// The primal check: `matched` are live non-loop edges covering every live node once. Returns
/// each node slot's matched edge (`NO_SET` for none).
fn perfect_cover<C: CostGraph>(graph: &C, matched: &[u32]) -> Result<Vec<u32>, CertificateError> {
    let mut cover = vec![NO_SET; graph.node_slots()];
    for &e in matched {
        let Some([a, b]) = ((e as usize) < graph.edge_slots())
            .then(|| graph.ends(e))
            .flatten()
        else {
            return Err(CertificateError::BadEdge { edge: e });
        };
        if a == b {
            return Err(CertificateError::BadEdge { edge: e });
        }
        for v in [a, b] {
            if cover[v as usize] != NO_SET {
                return Err(CertificateError::CoveredTwice {
                    node: v,
                    first: cover[v as usize],
                    second: e,
                });
            }
            cover[v as usize] = e;
        }
    }
    match (0..graph.node_slots() as u32).find(|&v| graph.is_node(v) && cover[v as usize] == NO_SET)
    {
        Some(node) => Err(CertificateError::Uncovered { node }),
        None => Ok(cover),
    }
}

/// The certificate's laminar family, checked to be a forest of odd sets of at least three nodes
/// with non-negative duals, and what the edge checks need of it.
struct Family<'a> {
    sets: &'a [BlossomDual],
    /// Per set: its depth in the forest (0 at the top).
    depth: Vec<u32>,
    /// The sets, deepest first (children before parents).
    order: Vec<u32>,
    /// Per set: the sum of its dual and its ancestors'.
    above: Vec<i128>,
    /// Per set: its node count.
    size: Vec<u64>,
}

impl<'a> Family<'a> {
    fn new<C: CostGraph>(
        graph: &C,
        certificate: &'a Certificate,
    ) -> Result<Self, CertificateError> {
        let sets = &certificate.blossoms[..];
        let set_count = sets.len();
        for (s, set) in sets.iter().enumerate() {
            if set.parent != NO_SET && set.parent as usize >= set_count {
                return Err(CertificateError::BadSetIndex(format!("set {s}")));
            }
            if set.dual < 0 {
                return Err(CertificateError::NegativeSetDual {
                    set: s as u32,
                    dual: set.dual,
                });
            }
        }
        for (v, &s) in certificate.node_blossom.iter().enumerate() {
            if s != NO_SET && (s as usize >= set_count || !graph.is_node(v as u32)) {
                return Err(CertificateError::BadSetIndex(format!("node {v}")));
            }
        }
        let depth = set_depths(sets)?;
        let mut order: Vec<u32> = (0..set_count as u32).collect();
        order.sort_by_key(|&s| std::cmp::Reverse(depth[s as usize]));
        let mut above = vec![0i128; set_count];
        for &s in order.iter().rev() {
            let parent = sets[s as usize].parent;
            let up = if parent == NO_SET {
                0
            } else {
                above[parent as usize]
            };
            above[s as usize] = up + i128::from(sets[s as usize].dual);
        }
        let mut size = vec![0u64; set_count];
        for &s in &certificate.node_blossom {
            if s != NO_SET {
                size[s as usize] += 1;
            }
        }
        let family = Family {
            sets,
            depth,
            order,
            above,
            size,
        };
        let size = family.sum_up(family.size.clone());
        if let Some(s) = size.iter().position(|&k| k < 3 || k.is_multiple_of(2)) {
            return Err(CertificateError::SetSize {
                set: s as u32,
                size: size[s],
            });
        }
        Ok(Family { size, ..family })
    }

    /// Per set, `own` summed over the set and the sets inside it.
    fn sum_up(&self, mut own: Vec<u64>) -> Vec<u64> {
        for &s in &self.order {
            let parent = self.sets[s as usize].parent;
            if parent != NO_SET {
                own[parent as usize] += own[s as usize];
            }
        }
        own
    }

    /// The sum of the duals of `s` and its ancestors (0 for `NO_SET`).
    fn dual_above(&self, s: u32) -> i128 {
        if s == NO_SET {
            0
        } else {
            self.above[s as usize]
        }
    }

    /// Complementary slackness of the sets: every set with a positive dual has `(|S| − 1) / 2`
    /// matched edges inside, given the matched edges whose smallest common set each set is.
    fn check_slackness(&self, inside_here: Vec<u64>) -> Result<(), CertificateError> {
        let inside = self.sum_up(inside_here);
        match (0..self.sets.len())
            .find(|&s| self.sets[s].dual > 0 && 2 * inside[s] + 1 != self.size[s])
        {
            Some(s) => Err(CertificateError::SetNotFull {
                set: s as u32,
                size: self.size[s],
                dual: self.sets[s].dual,
                inside: inside[s],
            }),
            None => Ok(()),
        }
    }
}

/// Dual feasibility of every non-loop edge and tightness of the matched ones. Returns twice the
/// matching's cost and, per set, the matched edges whose smallest common set it is.
fn check_edges<C: CostGraph>(
    graph: &C,
    certificate: &Certificate,
    family: &Family,
    cover: &[u32],
) -> Result<(i128, Vec<u64>), CertificateError> {
    let mut inside_here = vec![0u64; family.sets.len()];
    let mut primal: i128 = 0;
    for e in 0..graph.edge_slots() as u32 {
        let Some([u, v]) = graph.ends(e) else {
            continue;
        };
        if u == v {
            continue;
        }
        let (su, sv) = (
            certificate.node_blossom[u as usize],
            certificate.node_blossom[v as usize],
        );
        let common = smallest_common_set(family.sets, &family.depth, su, sv);
        let crossing =
            family.dual_above(su) + family.dual_above(sv) - 2 * family.dual_above(common);
        let cost = graph.cost(e);
        let reduced = 2 * i128::from(cost)
            - i128::from(certificate.node_duals[u as usize])
            - i128::from(certificate.node_duals[v as usize])
            - crossing;
        if reduced < 0 {
            return Err(CertificateError::Infeasible { edge: e, reduced });
        }
        if cover[u as usize] == e {
            if reduced != 0 {
                return Err(CertificateError::MatchedNotTight { edge: e, reduced });
            }
            primal += 2 * i128::from(cost);
            if common != NO_SET {
                inside_here[common as usize] += 1;
            }
        }
    }
    Ok((primal, inside_here))
}

/// Depth of every set in the parent forest (0 for top-level sets), rejecting cycles: each set's
/// chain of parents is walked once, and memoised depths stop the walk.
fn set_depths(sets: &[BlossomDual]) -> Result<Vec<u32>, CertificateError> {
    const UNKNOWN: u32 = u32::MAX;
    const ON_CHAIN: u32 = u32::MAX - 1;
    let mut depth = vec![UNKNOWN; sets.len()];
    let mut chain = Vec::new();
    for start in 0..sets.len() {
        let mut s = start as u32;
        while s != NO_SET && depth[s as usize] == UNKNOWN {
            depth[s as usize] = ON_CHAIN;
            chain.push(s);
            s = sets[s as usize].parent;
        }
        if s != NO_SET && depth[s as usize] == ON_CHAIN {
            return Err(CertificateError::CyclicFamily { set: s });
        }
        let mut d = if s == NO_SET {
            0
        } else {
            depth[s as usize] + 1
        };
        while let Some(t) = chain.pop() {
            depth[t as usize] = d;
            d += 1;
        }
    }
    Ok(depth)
}

/// The smallest set containing both `a` and `b` (sets or `NO_SET`), by walking up from the deeper.
fn smallest_common_set(sets: &[BlossomDual], depth: &[u32], mut a: u32, mut b: u32) -> u32 {
    let level = |s: u32| {
        if s == NO_SET {
            -1
        } else {
            depth[s as usize] as i64
        }
    };
    while a != b {
        if level(a) >= level(b) {
            a = sets[a as usize].parent;
        } else {
            b = sets[b as usize].parent;
        }
    }
    a
}
