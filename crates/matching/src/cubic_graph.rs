//! Connected, bridgeless, 3-regular multigraphs: the input of every pairing algorithm of this crate.
//!
//! The dual graph of a closed triangle mesh is such a graph: its nodes are the faces, and edge `e`
//! joins the two faces on either side of primal edge `e`. A matching given as a `Vec<bool>` indexed by
//! edge id (or as a list of edge ids) therefore maps straight back to primal edges.
//!
//! Parallel edges are allowed (the two-node, three-edge "theta" graph is the smallest such graph);
//! loops are refused, since a loop in a cubic graph always sits next to a bridge.

use thiserror::Error;

/// Why a list of edges is not a connected, bridgeless, 3-regular multigraph. Every variant names
/// the offending node or edge by its index in the input.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum GraphError {
    /// The graph has no node.
    #[error("empty graph: no nodes")]
    Empty,
    /// More edges than `u32` edge ids can name.
    #[error("{edge_count} edges: more than u32 edge ids can name")]
    TooManyEdges {
        /// Number of edges in the input.
        edge_count: usize,
    },
    /// An edge of the list names a node beyond the node count.
    #[error("edge {edge}: node {node} out of range ({node_count} nodes)")]
    NodeOutOfRange {
        /// The edge's index in the list.
        edge: u32,
        /// The node index it names.
        node: u32,
        /// The node count given.
        node_count: u32,
    },
    /// An edge joins a node to itself.
    #[error("edge {edge} is a loop at node {node}")]
    Loop {
        /// The offending edge.
        edge: u32,
        /// Its node.
        node: u32,
    },
    /// A node does not have exactly three incident edges.
    #[error("node {node} has degree {degree}, not 3")]
    WrongDegree {
        /// The offending node (the smallest such index).
        node: u32,
        /// Its degree (parallel edges counted with multiplicity).
        degree: usize,
    },
    /// The graph is not connected.
    #[error("graph is disconnected: node {node} is not reachable from node 0")]
    Disconnected {
        /// A node not reachable from node 0 (the smallest such index).
        node: u32,
    },
    /// An edge whose removal disconnects the graph.
    #[error("edge {edge} ({} - {}) is a bridge", endpoints[0], endpoints[1])]
    Bridge {
        /// The bridge (the first one met by a depth-first search from node 0).
        edge: u32,
        /// Its two nodes.
        endpoints: [u32; 2],
    },
    /// An edge index given to an algorithm (for example an edge to avoid) does not exist.
    #[error("edge {edge} out of range ({edge_count} edges)")]
    EdgeOutOfRange {
        /// The offending edge index.
        edge: u32,
        /// Number of edges of the graph.
        edge_count: u32,
    },
}

/// A connected, bridgeless, 3-regular multigraph (parallel edges allowed, loops refused).
///
/// Edge ids are indices into [`CubicGraph::edges`]; node ids are `0..node_count`. The three edges at
/// each node are kept in the order in which they appear in the edge list.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CubicGraph {
    node_count: u32,
    edges: Vec<[u32; 2]>,
    incidence: Vec<[u32; 3]>,
}

impl CubicGraph {
    /// Validates and builds a graph from its node count and edge list (edge id = index).
    ///
    /// Checks, in this order: at least one node, ids in range, no loop, every node of degree
    /// exactly 3, connected, bridgeless (one iterative depth-first search computing lowpoints).
    /// Runs in O(n) time and memory.
    ///
    /// # Errors
    /// The first [`GraphError`] found, naming the offending node or edge.
    pub fn new(node_count: u32, edges: Vec<[u32; 2]>) -> Result<Self, GraphError> {
        if node_count == 0 {
            return Err(GraphError::Empty);
        }
        if edges.len() >= u32::MAX as usize {
            return Err(GraphError::TooManyEdges {
                edge_count: edges.len(),
            });
        }
        for (e, &[a, b]) in edges.iter().enumerate() {
            for node in [a, b] {
                if node >= node_count {
                    return Err(GraphError::NodeOutOfRange {
                        edge: e as u32,
                        node,
                        node_count,
                    });
                }
            }
            if a == b {
                return Err(GraphError::Loop {
                    edge: e as u32,
                    node: a,
                });
            }
        }
        let mut degree = vec![0usize; node_count as usize];
        for &[a, b] in &edges {
            degree[a as usize] += 1;
            degree[b as usize] += 1;
        }
        if let Some(node) = degree.iter().position(|&d| d != 3) {
            return Err(GraphError::WrongDegree {
                node: node as u32,
                degree: degree[node],
            });
        }
        let mut incidence = vec![[u32::MAX; 3]; node_count as usize];
        let mut filled = vec![0u8; node_count as usize];
        for (e, &[a, b]) in edges.iter().enumerate() {
            for node in [a, b] {
                let slot = &mut filled[node as usize];
                incidence[node as usize][*slot as usize] = e as u32;
                *slot += 1;
            }
        }
        let graph = CubicGraph {
            node_count,
            edges,
            incidence,
        };
        graph.check_connected_bridgeless()?;
        Ok(graph)
    }

    /// Number of nodes.
    pub fn node_count(&self) -> u32 {
        self.node_count
    }

    /// Number of edges (always `3 * node_count / 2`).
    pub fn edge_count(&self) -> u32 {
        self.edges.len() as u32
    }

    /// The edge list: `edges()[e]` holds the two nodes of edge `e`.
    pub fn edges(&self) -> &[[u32; 2]] {
        &self.edges
    }

    /// The two nodes of edge `e`.
    ///
    /// # Panics
    /// If `e` is out of range.
    pub fn endpoints(&self, e: u32) -> [u32; 2] {
        self.edges[e as usize]
    }

    /// The three edges at node `v` (a parallel edge appears once per copy).
    ///
    /// # Panics
    /// If `v` is out of range.
    pub fn incident_edges(&self, v: u32) -> [u32; 3] {
        self.incidence[v as usize]
    }

    /// The node at the other end of edge `e` from node `v`.
    ///
    /// # Panics
    /// If `e` is out of range; debug builds also panic if `v` is not a node of `e`.
    pub fn opposite(&self, e: u32, v: u32) -> u32 {
        let [a, b] = self.edges[e as usize];
        debug_assert!(a == v || b == v, "node {v} is not on edge {e}");
        if a == v { b } else { a }
    }

    /// One iterative DFS from node 0: reports the first unreached node, else the first bridge
    /// (an edge `parent -> child` of the DFS tree with `low(child) > disc(parent)`). Parallel edges
    /// are told apart by edge id, so a doubled edge is never a bridge.
    fn check_connected_bridgeless(&self) -> Result<(), GraphError> {
        const UNSEEN: u32 = u32::MAX;
        let n = self.node_count as usize;
        let mut disc = vec![UNSEEN; n];
        let mut low = vec![0u32; n];
        // (node, edge by which it was entered, next incidence slot to look at)
        let mut stack: Vec<(u32, u32, u8)> = Vec::with_capacity(64);
        let mut time = 0u32;
        disc[0] = time;
        low[0] = time;
        time += 1;
        stack.push((0, u32::MAX, 0));
        let mut bridge: Option<u32> = None;
        let mut ticker = surftopo_mesh::stop::Ticker::default();
        while let Some(top) = stack.last_mut() {
            ticker.tick();
            let (v, via, slot) = *top;
            if slot < 3 {
                top.2 += 1;
                let e = self.incidence[v as usize][slot as usize];
                if e == via {
                    continue;
                }
                let w = self.opposite(e, v);
                if disc[w as usize] == UNSEEN {
                    disc[w as usize] = time;
                    low[w as usize] = time;
                    time += 1;
                    stack.push((w, e, 0));
                } else {
                    let l = &mut low[v as usize];
                    *l = (*l).min(disc[w as usize]);
                }
            } else {
                stack.pop();
                if let Some(&(p, _, _)) = stack.last() {
                    let lv = low[v as usize];
                    let lp = &mut low[p as usize];
                    *lp = (*lp).min(lv);
                    if lv > disc[p as usize] && bridge.is_none() {
                        bridge = Some(via);
                    }
                }
            }
        }
        if let Some(node) = disc.iter().position(|&d| d == UNSEEN) {
            return Err(GraphError::Disconnected { node: node as u32 });
        }
        if let Some(edge) = bridge {
            return Err(GraphError::Bridge {
                edge,
                endpoints: self.edges[edge as usize],
            });
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn theta_is_valid() {
        let g = CubicGraph::new(2, vec![[0, 1], [1, 0], [0, 1]]).unwrap();
        assert_eq!(g.edge_count(), 3);
        assert_eq!(g.incident_edges(1), [0, 1, 2]);
        assert_eq!(g.opposite(1, 1), 0);
    }

    #[test]
    fn dumbbell_bridge_is_named() {
        // Two triangles with a doubled side, {0,1,2} and {3,4,5}, joined by edge 6 = 2-5.
        let edges = vec![
            [0, 1],
            [0, 1],
            [0, 2],
            [1, 2],
            [3, 4],
            [3, 4],
            [2, 5],
            [3, 5],
            [4, 5],
        ];
        let err = CubicGraph::new(6, edges).unwrap_err();
        assert_eq!(
            err,
            GraphError::Bridge {
                edge: 6,
                endpoints: [2, 5]
            }
        );
    }
}
