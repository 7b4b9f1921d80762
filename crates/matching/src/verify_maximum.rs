//! Independent verification of maximum matchings by their Tutte–Berge certificate.
//!
//! A surface with boundary may have no perfect pairing: its dual graph G (maximum degree 3,
//! boundary sides as half-loops) is paired by a *maximum* matching, and the proof that no
//! matching leaves fewer nodes unmatched is a set A of nodes, the *barrier*: by the Tutte–Berge
//! formula every matching leaves at least `odd(G − A) − |A|` nodes unmatched, `odd(G − A)` being
//! the number of connected components of G without A that have an odd number of nodes (each
//! such component has a node matched outside it or not at all, and at most `|A|` of them are
//! matched to A). The formula holds in each connected component of G on its own, with the part
//! of A inside it, so the verifier checks the count component by component.
//!
//! [`verify_maximum_pairing`] reads only the graph's endpoints and liveness, the pairing and the
//! barrier (no code of the algorithms, nor of their search for the barrier): it checks that the
//! pairing is a matching, that the barrier is a set of live nodes, counts with its own
//! union-find the components of G and of G − A, and compares, per component, the unmatched
//! nodes with the bound. [`MaximumPairing`], the only way to hold a verified maximum pairing, is
//! built there; a perfect pairing is the case of an empty barrier on a graph whose components
//! all have an even number of nodes.

use surftopo_mesh::UnionFind;

use crate::dual_graph::{DualGraph, NONE, Pairing};
use crate::verify::MatchingError;

/// The figures of one connected component of the graph in a [`MaximumPairing`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ComponentPairing {
    /// Its first node (the smallest id): components are listed in that order.
    pub first_node: u32,
    /// Its nodes.
    pub nodes: usize,
    /// Its nodes left unmatched.
    pub unmatched: usize,
    /// `odd(C − A) − |A ∩ C|` for the component C: no matching leaves fewer of its nodes
    /// unmatched (Tutte–Berge); equal to `unmatched` once verified.
    pub deficiency_lower_bound: usize,
    /// `|A ∩ C|`.
    pub barrier_nodes: usize,
    /// `odd(C − A)`.
    pub odd_components: usize,
}

/// A verified maximum matching of a [`DualGraph`] with its certificate: built only by
/// [`verify_maximum_pairing`], so holding one is the proof that no matching of the graph leaves
/// fewer nodes unmatched, in every connected component. It reads as the [`Pairing`] it wraps.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MaximumPairing {
    pairing: Pairing,
    barrier: Vec<u32>,
    component: Vec<u32>,
    components: Vec<ComponentPairing>,
    flags: Vec<bool>,
    /// Per node slot: whether it lies in an odd component of G − A.
    odd_part: Vec<bool>,
}

impl MaximumPairing {
    /// Whether node `v` lies in an odd component of G − A: the only nodes a maximum matching
    /// can leave unmatched (every maximum matching matches the nodes of A into distinct odd
    /// components, and the even components and the other odd ones inside themselves, the
    /// bound being tight).
    pub fn is_exposable(&self, v: u32) -> bool {
        self.odd_part.get(v as usize).copied().unwrap_or(false)
    }

    /// The pairing (one mate edge per node slot, `u32::MAX` for unmatched nodes).
    pub fn pairing(&self) -> &Pairing {
        &self.pairing
    }

    /// The barrier A (sorted node ids) that proves maximality.
    pub fn barrier(&self) -> &[u32] {
        &self.barrier
    }

    /// The connected component of each node slot (`u32::MAX` for removed slots), numbered in the
    /// order of their first node.
    pub fn component_of(&self) -> &[u32] {
        &self.component
    }

    /// The figures of each connected component, in the order of their first node.
    pub fn components(&self) -> &[ComponentPairing] {
        &self.components
    }

    /// Per edge slot: whether the edge is matched.
    pub fn matched_flags(&self) -> &[bool] {
        &self.flags
    }

    /// Nodes left unmatched, over all components.
    pub fn unmatched(&self) -> usize {
        self.components.iter().map(|c| c.unmatched).sum()
    }

    /// Whether every node is matched.
    pub fn is_perfect(&self) -> bool {
        self.unmatched() == 0
    }
}

impl std::ops::Deref for MaximumPairing {
    type Target = Pairing;

    fn deref(&self) -> &Pairing {
        &self.pairing
    }
}

/// Checks that `pairing` is a maximum matching of `graph`, with `barrier` (a set of nodes) as
/// the Tutte–Berge certificate, and wraps it with the figures of every connected component (see
/// the module doc). O((n + m) α(n)).
///
/// # Errors
/// - The pairing's faults as [`verify_perfect_pairing`](crate::verify_perfect_pairing) names
///   them (an unmatched node is not one);
/// - [`MatchingError::BadBarrier`] for a barrier node that is not a live node, or listed twice;
/// - [`MatchingError::NotProvenMaximum`] for the first component whose unmatched nodes exceed
///   the bound the barrier gives.
pub fn verify_maximum_pairing<G: DualGraph + ?Sized>(
    graph: &G,
    pairing: Pairing,
    barrier: &[u32],
) -> Result<MaximumPairing, MatchingError> {
    let slots = graph.node_slots();
    let mates = pairing.mates();
    if mates.len() != slots {
        return Err(MatchingError::LengthMismatch {
            expected: slots,
            got: mates.len(),
        });
    }
    let flags = matching_flags(graph, mates)?;
    let mut in_barrier = vec![false; slots];
    for &a in barrier {
        if (a as usize) >= slots || !graph.is_node(a) || in_barrier[a as usize] {
            return Err(MatchingError::BadBarrier { node: a });
        }
        in_barrier[a as usize] = true;
    }
    let mut whole = UnionFind::new(slots);
    let mut rest = UnionFind::new(slots);
    for e in 0..graph.edge_slots() as u32 {
        if !graph.is_edge(e) {
            continue;
        }
        let [a, b] = graph.endpoints(e);
        if a == b {
            continue;
        }
        whole.union(a, b);
        if !in_barrier[a as usize] && !in_barrier[b as usize] {
            rest.union(a, b);
        }
    }
    // Components of G numbered by first node; sizes of the components of G − A.
    let mut number = vec![NONE; slots];
    let mut component = vec![NONE; slots];
    let mut components: Vec<ComponentPairing> = Vec::new();
    let mut rest_size = vec![0u32; slots];
    for v in 0..slots as u32 {
        if !graph.is_node(v) {
            continue;
        }
        let root = whole.find(v) as usize;
        if number[root] == NONE {
            number[root] = components.len() as u32;
            components.push(ComponentPairing {
                first_node: v,
                ..ComponentPairing::default()
            });
        }
        let c = number[root];
        component[v as usize] = c;
        let figures = &mut components[c as usize];
        figures.nodes += 1;
        if mates[v as usize] == NONE {
            figures.unmatched += 1;
        }
        if in_barrier[v as usize] {
            figures.barrier_nodes += 1;
        } else {
            rest_size[rest.find(v) as usize] += 1;
        }
    }
    for v in 0..slots as u32 {
        // A root of G − A's union-find (a live node outside A) stands for its component.
        if graph.is_node(v)
            && !in_barrier[v as usize]
            && rest.find(v) == v
            && rest_size[v as usize] % 2 == 1
        {
            components[component[v as usize] as usize].odd_components += 1;
        }
    }
    let odd_part: Vec<bool> = (0..slots as u32)
        .map(|v| {
            graph.is_node(v) && !in_barrier[v as usize] && rest_size[rest.find(v) as usize] % 2 == 1
        })
        .collect();
    for (index, figures) in components.iter_mut().enumerate() {
        let bound = figures.odd_components as i64 - figures.barrier_nodes as i64;
        if bound < figures.unmatched as i64 {
            return Err(MatchingError::NotProvenMaximum {
                component: index as u32,
                first_node: figures.first_node,
                unmatched: figures.unmatched,
                bound,
            });
        }
        figures.deficiency_lower_bound = bound as usize;
    }
    Ok(MaximumPairing {
        pairing,
        barrier: {
            let mut sorted = barrier.to_vec();
            sorted.sort_unstable();
            sorted
        },
        component,
        components,
        flags,
        odd_part,
    })
}

/// Per edge slot whether it is matched, after checking that `mates` is a matching of `graph`:
/// a removed slot has no mate edge, and a mate edge is a live non-loop edge at its node, the
/// mate edge of its other end too.
fn matching_flags<G: DualGraph + ?Sized>(
    graph: &G,
    mates: &[u32],
) -> Result<Vec<bool>, MatchingError> {
    let mut flags = vec![false; graph.edge_slots()];
    for (v, &e) in mates.iter().enumerate() {
        let v = v as u32;
        if e == NONE {
            continue;
        }
        if !graph.is_node(v) {
            return Err(MatchingError::RemovedNode { node: v, edge: e });
        }
        if e as usize >= graph.edge_slots() || !graph.is_edge(e) {
            return Err(MatchingError::EdgeOutOfRange {
                edge: e,
                edge_count: graph.edge_slots(),
            });
        }
        let [a, b] = graph.endpoints(e);
        if a == b {
            return Err(MatchingError::MatchedLoop { edge: e });
        }
        let other = match v {
            _ if v == a => b,
            _ if v == b => a,
            _ => return Err(MatchingError::NotAtNode { node: v, edge: e }),
        };
        if mates[other as usize] != e {
            return Err(MatchingError::OneSided {
                node: v,
                edge: e,
                other,
            });
        }
        flags[e as usize] = true;
    }
    Ok(flags)
}
