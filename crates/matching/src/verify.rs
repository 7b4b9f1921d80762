//! Independent verification of perfect matchings, shared by every pairing algorithm of the crate
//! and by the quad pipeline.
//!
//! Written without sharing code with any algorithm: it reads only the graph's endpoints and
//! liveness, and checks, for every node, the matched edges at it. [`PerfectPairing`], the one
//! verified pairing type, can only be built through [`verify_perfect_pairing`]; the flag and
//! edge-list checks ([`verify_perfect_matching_on`], [`verify_perfect_matching`],
//! [`verify_perfect_matching_edges`]) serve graphs given as edge lists.
//!
//! A matcher with an optimality claim (a weighted matching and its dual certificate) returns a
//! [`Pairing`]; its verifier checks perfection here and the certificate beside it.

use crate::cubic_graph::CubicGraph;
use crate::dual_graph::{DualGraph, NONE, Pairing};
use thiserror::Error;

/// Why a set of edges is not a perfect matching (or not a proven maximum one:
/// [`crate::verify_maximum_pairing`]).
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum MatchingError {
    /// The flag vector does not have one entry per edge (or the pairing one mate per node slot).
    #[error("{got} entries for a graph of {expected} edges (flags) or node slots (mates)")]
    LengthMismatch {
        /// Number of edges (node slots) of the graph.
        expected: usize,
        /// Length of the flag vector (of the mates).
        got: usize,
    },
    /// An edge list or a pairing names an edge that does not exist (out of range, or removed).
    #[error("edge {edge} out of range ({edge_count} edges)")]
    EdgeOutOfRange {
        /// The offending edge index.
        edge: u32,
        /// Number of edges of the graph.
        edge_count: usize,
    },
    /// A matched edge of a raw edge list has an end beyond the node count.
    #[error("matched edge {edge} ends at node {end}, beyond the {node_count} nodes")]
    MatchedEdgeEndOutOfRange {
        /// The matched edge.
        edge: u32,
        /// Its end out of range.
        end: u32,
        /// The node count given.
        node_count: u32,
    },
    /// A matched edge is a loop (it would cover its node twice).
    #[error("matched edge {edge} is a loop")]
    MatchedLoop {
        /// The offending edge.
        edge: u32,
    },
    /// No matched edge covers a node.
    #[error("node {node} is not covered by the matching")]
    Uncovered {
        /// The first uncovered node.
        node: u32,
    },
    /// A pairing gives a removed node slot a mate edge.
    #[error("node slot {node} is not a node of the graph but has mate edge {edge}")]
    RemovedNode {
        /// The removed node slot.
        node: u32,
        /// Its mate edge.
        edge: u32,
    },
    /// A pairing gives a node a mate edge that does not end at it.
    #[error("mate edge {edge} of node {node} does not end at it")]
    NotAtNode {
        /// The node.
        node: u32,
        /// Its mate edge.
        edge: u32,
    },
    /// A pairing gives a node a mate edge that is not the mate edge of its other end.
    #[error("mate edge {edge} of node {node} is not the mate edge of its other end {other}")]
    OneSided {
        /// The node.
        node: u32,
        /// Its mate edge.
        edge: u32,
        /// The edge's other end.
        other: u32,
    },
    /// Two matched edges (or one edge listed twice) cover the same node.
    #[error("node {node} is covered by edges {first} and {second}")]
    CoveredTwice {
        /// The node.
        node: u32,
        /// The first matched edge met at it.
        first: u32,
        /// The second one.
        second: u32,
    },
    /// A barrier node of a maximality certificate is not a live node, or is listed twice.
    #[error("barrier node {node} is not a node of the graph, or is listed twice")]
    BadBarrier {
        /// The offending node.
        node: u32,
    },
    /// The barrier does not prove the matching maximum in a connected component: it leaves more
    /// nodes unmatched than `odd(C − A) − |A ∩ C|`.
    #[error(
        "component {component} (first node {first_node}): {unmatched} nodes unmatched, but the \
         barrier only proves that at least {bound} must be"
    )]
    NotProvenMaximum {
        /// The component (numbered in the order of its first node).
        component: u32,
        /// Its first node.
        first_node: u32,
        /// Its unmatched nodes.
        unmatched: usize,
        /// The barrier's bound `odd(C − A) − |A ∩ C|`.
        bound: i64,
    },
}

/// Checks that `matched` (one flag per edge of `edges`, edge id = index) covers each of the
/// `node_count` nodes exactly once. Works for any multigraph, cubic or not. O(n + m).
///
/// # Errors
/// The first violation found, as a [`MatchingError`] naming the edge or node.
pub fn verify_perfect_matching_on(
    node_count: u32,
    edges: &[[u32; 2]],
    matched: &[bool],
) -> Result<(), MatchingError> {
    if matched.len() != edges.len() {
        return Err(MatchingError::LengthMismatch {
            expected: edges.len(),
            got: matched.len(),
        });
    }
    let chosen: Vec<u32> = matched
        .iter()
        .enumerate()
        .filter(|&(_, &m)| m)
        .map(|(e, _)| e as u32)
        .collect();
    verify_edge_list(node_count, edges, &chosen)
}

/// Checks that the matched flags (indexed by edge id) form a perfect matching of `graph`.
///
/// # Errors
/// See [`verify_perfect_matching_on`].
pub fn verify_perfect_matching(graph: &CubicGraph, matched: &[bool]) -> Result<(), MatchingError> {
    verify_perfect_matching_on(graph.node_count(), graph.edges(), matched)
}

/// Checks that a list of edge ids (each at most once) is a perfect matching of `graph`.
///
/// # Errors
/// See [`verify_perfect_matching_on`]; an edge listed twice is reported as
/// [`MatchingError::CoveredTwice`].
pub fn verify_perfect_matching_edges(
    graph: &CubicGraph,
    matching: &[u32],
) -> Result<(), MatchingError> {
    verify_edge_list(graph.node_count(), graph.edges(), matching)
}

fn verify_edge_list(
    node_count: u32,
    edges: &[[u32; 2]],
    chosen: &[u32],
) -> Result<(), MatchingError> {
    const NONE: u32 = u32::MAX;
    let mut cover = vec![NONE; node_count as usize];
    for &e in chosen {
        let Some(&[a, b]) = edges.get(e as usize) else {
            return Err(MatchingError::EdgeOutOfRange {
                edge: e,
                edge_count: edges.len(),
            });
        };
        if a == b {
            return Err(MatchingError::MatchedLoop { edge: e });
        }
        for node in [a, b] {
            let Some(slot) = cover.get_mut(node as usize) else {
                return Err(MatchingError::MatchedEdgeEndOutOfRange {
                    edge: e,
                    end: node,
                    node_count,
                });
            };
            if *slot != NONE {
                return Err(MatchingError::CoveredTwice {
                    node,
                    first: *slot,
                    second: e,
                });
            }
            *slot = e;
        }
    }
    match cover.iter().position(|&c| c == NONE) {
        Some(node) => Err(MatchingError::Uncovered { node: node as u32 }),
        None => Ok(()),
    }
}

/// Checks that `pairing` is a perfect matching of `graph` and wraps it, with its matched edges as
/// per-edge flags ([`PerfectPairing::matched_flags`]). Works on any [`DualGraph`], tombstones
/// included. O(n) time, one flag per edge slot of memory.
///
/// The check, in two sequential passes: every live node has a mate edge (removed node slots have
/// none), whose flag is set; then every flagged edge is live, not a loop, and the mate edge of
/// both its ends; and the flagged edges are half as many as the live nodes. Then every live node
/// is covered by exactly one flagged edge: the flagged edges have disjoint ends (each end's mate
/// edge is that edge), so they cover twice their number of nodes, all of them; and a node whose
/// mate edge did not end at it would make that edge the mate edge of three nodes, one too many
/// for the count. The edges are read in increasing id order, one endpoint lookup per matched
/// edge: for a mesh, a sequential pass over its half-edges.
///
/// # Errors
/// The first violation in node order (found by a second, node-by-node pass once the check has
/// failed), as a [`MatchingError`] naming the node and the edge.
pub fn verify_perfect_pairing<G: DualGraph + ?Sized>(
    graph: &G,
    pairing: Pairing,
) -> Result<PerfectPairing, MatchingError> {
    let mates = pairing.mates();
    if mates.len() != graph.node_slots() {
        return Err(MatchingError::LengthMismatch {
            expected: graph.node_slots(),
            got: mates.len(),
        });
    }
    let edge_slots = graph.edge_slots();
    let mut flags = vec![false; edge_slots];
    let mut live = 0usize;
    let mut fits = true;
    for (v, &e) in mates.iter().enumerate() {
        if graph.is_node(v as u32) {
            live += 1;
            match flags.get_mut(e as usize) {
                Some(flag) => *flag = true,
                None => fits = false,
            }
        } else {
            fits &= e == NONE;
        }
    }
    let mut matched = 0usize;
    if fits {
        for (e, _) in flags.iter().enumerate().filter(|&(_, &m)| m) {
            let e = e as u32;
            let [a, b] = if graph.is_edge(e) {
                graph.endpoints(e)
            } else {
                [NONE, NONE]
            };
            if a == b || mates[a as usize] != e || mates[b as usize] != e {
                fits = false;
                break;
            }
            matched += 1;
        }
    }
    if !fits || 2 * matched != live {
        if let Some(violation) = first_violation(graph, mates) {
            return Err(violation);
        }
        // Never reached (both passes characterise a perfect matching), but then the node-by-node
        // pass has proved the matching perfect.
        flags = pairing.edge_flags(edge_slots);
        matched = live / 2;
    }
    Ok(PerfectPairing {
        pairing,
        flags,
        len: matched,
    })
}

/// The first node, in node order, whose mate edge shows that `mates` is not a perfect matching of
/// `graph`: a live node without a mate edge, or whose mate edge is not a live non-loop edge ending
/// at it and matched at its other end too, or a removed node slot with a mate edge. These conditions
/// hold at every node exactly when the mates are a perfect matching (a second edge covering a node
/// would be the mate edge of another node ending at it, hence its own): `None` then.
fn first_violation<G: DualGraph + ?Sized>(graph: &G, mates: &[u32]) -> Option<MatchingError> {
    for (v, &e) in mates.iter().enumerate() {
        let v = v as u32;
        if !graph.is_node(v) {
            if e != NONE {
                return Some(MatchingError::RemovedNode { node: v, edge: e });
            }
            continue;
        }
        if e == NONE {
            return Some(MatchingError::Uncovered { node: v });
        }
        if e as usize >= graph.edge_slots() || !graph.is_edge(e) {
            return Some(MatchingError::EdgeOutOfRange {
                edge: e,
                edge_count: graph.edge_slots(),
            });
        }
        let [a, b] = graph.endpoints(e);
        if a == b {
            return Some(MatchingError::MatchedLoop { edge: e });
        }
        let other = match v {
            _ if v == a => b,
            _ if v == b => a,
            _ => return Some(MatchingError::NotAtNode { node: v, edge: e }),
        };
        if mates[other as usize] != e {
            return Some(MatchingError::OneSided {
                node: v,
                edge: e,
                other,
            });
        }
    }
    None
}

/// A verified perfect matching of a [`DualGraph`] (a pairing of every triangle): built only by
/// [`verify_perfect_pairing`], so holding one is the proof that every live node is matched
/// exactly once. It reads as the [`Pairing`] it wraps (`Deref`, read-only: nothing can unmatch a
/// node of it).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PerfectPairing {
    pairing: Pairing,
    /// Per edge slot: whether the edge is matched.
    flags: Vec<bool>,
    len: usize,
}

impl PerfectPairing {
    /// The pairing (one mate edge per node slot).
    pub fn pairing(&self) -> &Pairing {
        &self.pairing
    }

    /// The pairing, unwrapped (for an algorithm that changes it, which then verifies it again).
    pub fn into_pairing(self) -> Pairing {
        self.pairing
    }

    /// Per edge slot of the graph it was verified on: whether the edge is matched.
    pub fn matched_flags(&self) -> &[bool] {
        &self.flags
    }

    /// Number of matched edges (half the live nodes).
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether the matching is empty (only for a graph without nodes).
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

impl std::ops::Deref for PerfectPairing {
    type Target = Pairing;

    fn deref(&self) -> &Pairing {
        &self.pairing
    }
}

/// Panics unless `pairing` is a perfect matching of `graph` ([`verify_perfect_pairing`]), for the
/// crate's unit tests.
#[cfg(test)]
pub(crate) fn assert_perfect_pairing<G: DualGraph + ?Sized>(graph: &G, pairing: &Pairing) {
    verify_perfect_pairing(graph, pairing.clone()).unwrap();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn theta() {
        let g = CubicGraph::new(2, vec![[0, 1], [0, 1], [1, 0]]).unwrap();
        assert!(verify_perfect_matching(&g, &[false, true, false]).is_ok());
        assert_eq!(
            verify_perfect_matching(&g, &[true, true, false]),
            Err(MatchingError::CoveredTwice {
                node: 0,
                first: 0,
                second: 1
            })
        );
        assert_eq!(
            verify_perfect_matching(&g, &[false, false, false]),
            Err(MatchingError::Uncovered { node: 0 })
        );
        assert_eq!(
            verify_perfect_matching_edges(&g, &[3]),
            Err(MatchingError::EdgeOutOfRange {
                edge: 3,
                edge_count: 3
            })
        );
        assert!(matches!(
            verify_perfect_matching_edges(&g, &[2, 2]),
            Err(MatchingError::CoveredTwice { .. })
        ));
    }

    /// Every violation of a perfect pairing is named, and only a perfect one is wrapped.
    #[test]
    fn pairings_are_verified_node_by_node() {
        // The theta graph: nodes 0 and 1 joined by edges 0, 1 and 2.
        let g = CubicGraph::new(2, vec![[0, 1], [0, 1], [1, 0]]).unwrap();
        let pairing = |mate: Vec<u32>| Pairing { mate };
        let ok = verify_perfect_pairing(&g, pairing(vec![2, 2])).unwrap();
        assert_eq!((ok.len(), ok.edge_flags(3)), (1, vec![false, false, true]));
        assert_eq!(ok.pairing().mates(), &[2, 2]);
        assert_eq!(ok.matched_flags(), &[false, false, true]);
        let check = |mate: Vec<u32>| verify_perfect_pairing(&g, pairing(mate)).unwrap_err();
        assert_eq!(
            check(vec![0]),
            MatchingError::LengthMismatch {
                expected: 2,
                got: 1
            }
        );
        assert_eq!(
            check(vec![NONE, NONE]),
            MatchingError::Uncovered { node: 0 }
        );
        assert_eq!(
            check(vec![7, 7]),
            MatchingError::EdgeOutOfRange {
                edge: 7,
                edge_count: 3
            }
        );
        assert_eq!(
            check(vec![0, 1]),
            MatchingError::OneSided {
                node: 0,
                edge: 0,
                other: 1
            }
        );
        let four =
            CubicGraph::new(4, vec![[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]]).unwrap();
        assert_eq!(
            verify_perfect_pairing(&four, pairing(vec![0, 0, 0, 5])).unwrap_err(),
            MatchingError::NotAtNode { node: 2, edge: 0 }
        );
        // Every edge consistent at its ends, but too few of them: the count finds it.
        assert_eq!(
            verify_perfect_pairing(&four, pairing(vec![0, 0, 0, 0])).unwrap_err(),
            MatchingError::NotAtNode { node: 2, edge: 0 }
        );
        // A mesh with removed faces: their slots must stay unmatched.
        let mut mesh = surftopo_mesh::generators::torus(6, 4).mesh;
        let mut scratch = surftopo_mesh::LinkScratch::default();
        mesh.contract(surftopo_mesh::EdgeId(10).halfedge(), &mut scratch)
            .unwrap();
        let removed = (0..mesh.face_slots() as u32)
            .find(|&f| !mesh.is_node(f))
            .unwrap();
        let (perfect, _) = crate::karp_sipser_perfect(&mesh).unwrap();
        verify_perfect_pairing(&mesh, perfect.clone()).unwrap();
        let mut mate = perfect.mate;
        mate[removed as usize] = 0;
        assert_eq!(
            verify_perfect_pairing(&mesh, pairing(mate)).unwrap_err(),
            MatchingError::RemovedNode {
                node: removed,
                edge: 0
            }
        );
    }
}
