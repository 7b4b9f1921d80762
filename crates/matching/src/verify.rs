//! Independent verification of perfect matchings, shared by every pairing algorithm of the crate.
//!
//! Written without sharing code with any algorithm: it only counts, for every node, the matched
//! edges at it. A [`PerfectMatching`] can only be built through this check.

use crate::cubic_graph::CubicGraph;
use thiserror::Error;

/// Why a set of edges is not a perfect matching.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum MatchingError {
    /// The flag vector does not have one entry per edge.
    #[error("{got} edge flags for a graph of {expected} edges")]
    LengthMismatch {
        /// Number of edges of the graph.
        expected: usize,
        /// Length of the flag vector.
        got: usize,
    },
    /// An edge list names an edge that does not exist.
    #[error("edge {edge} out of range ({edge_count} edges)")]
    EdgeOutOfRange {
        /// The offending edge index.
        edge: u32,
        /// Number of edges of the graph.
        edge_count: usize,
    },
    /// An edge names a node that does not exist.
    #[error("edge {edge}: node {node} out of range ({node_count} nodes)")]
    NodeOutOfRange {
        /// The offending edge.
        edge: u32,
        /// The node index it names.
        node: u32,
        /// Number of nodes.
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
                return Err(MatchingError::NodeOutOfRange {
                    edge: e,
                    node,
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

/// A verified perfect matching of a [`CubicGraph`]: one flag per edge id, every node covered by
/// exactly one flagged edge. Built only through [`PerfectMatching::new`], which runs the check.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PerfectMatching {
    matched: Vec<bool>,
    len: usize,
}

impl PerfectMatching {
    /// Verifies `matched` (indexed by edge id) against `graph` and wraps it.
    ///
    /// # Errors
    /// The [`MatchingError`] of [`verify_perfect_matching`].
    pub fn new(graph: &CubicGraph, matched: Vec<bool>) -> Result<Self, MatchingError> {
        verify_perfect_matching(graph, &matched)?;
        let len = matched.iter().filter(|&&m| m).count();
        Ok(PerfectMatching { matched, len })
    }

    /// Whether edge `e` is in the matching (false for out-of-range ids).
    pub fn contains(&self, e: u32) -> bool {
        self.matched.get(e as usize).copied().unwrap_or(false)
    }

    /// The flags, indexed by edge id.
    pub fn flags(&self) -> &[bool] {
        &self.matched
    }

    /// The matched edge ids in increasing order.
    pub fn edges(&self) -> Vec<u32> {
        self.matched
            .iter()
            .enumerate()
            .filter(|&(_, &m)| m)
            .map(|(e, _)| e as u32)
            .collect()
    }

    /// Number of matched edges (half the node count).
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether the matching is empty (never, for a valid graph).
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The flags, indexed by edge id.
    pub fn into_flags(self) -> Vec<bool> {
        self.matched
    }
}

/// Panics unless `pairing` is a perfect matching of `graph`, checked by
/// [`verify_perfect_matching_on`] on the graph's edge list (for the crate's unit tests).
#[cfg(test)]
pub(crate) fn assert_perfect_pairing<G: crate::DualGraph + ?Sized>(
    graph: &G,
    pairing: &crate::Pairing,
) {
    let edges: Vec<[u32; 2]> = (0..graph.edge_slots() as u32)
        .map(|e| graph.endpoints(e))
        .collect();
    let matched = pairing.edge_flags(graph.edge_slots());
    verify_perfect_matching_on(graph.node_slots() as u32, &edges, &matched).unwrap();
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
}
