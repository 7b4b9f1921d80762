//! The dual graph of a closed triangle mesh, read implicitly from the half-edge structure, and the
//! pairing (matching) representation shared by the greedy, Pulli–Segal and augmenting-path code.
//!
//! # Dual graph
//! [`DualGraph`] is the small interface every pairing algorithm of this crate (other than
//! Diks–Stanczyk, which owns its own dynamic structures) is generic over. It has two
//! implementations:
//! - [`SurfaceMesh`]: nodes are face ids, edges are primal edge ids; the dual edge of primal edge
//!   `e` joins `face(e.halfedge())` and `face(e.halfedge().twin())`. Nothing is materialised: a
//!   node's three neighbours are read through `face_halfedge`, `next` and `face` (three dependent
//!   loads). Tombstoned faces and edges are not nodes or edges.
//! - [`CubicGraph`]: the validated edge-list multigraph of the Diks–Stanczyk code, so that the same
//!   algorithms run on abstract cubic graphs (and the oracle tests compare them with `petgraph`).
//!
//! Ids are plain `u32` indices: on a mesh, node `f` is `FaceId(f)` and edge `e` is `EdgeId(e)`.
//!
//! # Pairings
//! A [`Pairing`] stores one *mate edge* per node slot (`u32::MAX` for unmatched), so a node's
//! partner is `opposite(mate, node)` and the matched dual edge is directly the primal edge whose
//! removal merges the two triangles into a quad. This is the representation the augmenting-path
//! search needs (O(1) mate lookup, parallel edges told apart); [`Pairing::edge_flags`] converts it
//! to the per-edge flags of [`crate::verify`] and of Diks–Stanczyk, [`Pairing::from_edges`]
//! converts back (checked), which is how a Diks–Stanczyk result plugs into the quad pipeline.

use std::borrow::Cow;

use surftopo_mesh::{EdgeId, FaceId, SurfaceMesh};
use thiserror::Error;

use crate::cubic_graph::CubicGraph;

/// "No node" / "no edge" / "unmatched".
pub(crate) const NONE: u32 = u32::MAX;

/// A multigraph in which every live node has exactly three incident edge slots (a loop fills two
/// slots of its node). Implemented for the implicit dual of a [`SurfaceMesh`] and for
/// [`CubicGraph`].
pub trait DualGraph {
    /// Size of the node id range (live and removed), for per-node arrays.
    fn node_slots(&self) -> usize;
    /// Size of the edge id range (live and removed), for per-edge arrays.
    fn edge_slots(&self) -> usize;
    /// Whether `v` is a live node.
    fn is_node(&self, v: u32) -> bool;
    /// Whether `e` is a live edge.
    fn is_edge(&self, e: u32) -> bool;
    /// Number of live nodes.
    fn node_count(&self) -> usize;
    /// The three `(edge, neighbour)` pairs of live node `v`; a loop appears with neighbour `v`.
    fn adjacent(&self, v: u32) -> [(u32, u32); 3];
    /// The two nodes of live edge `e` (equal for a loop).
    fn endpoints(&self, e: u32) -> [u32; 2];
    /// The node at the other end of edge `e` from node `v`.
    #[inline]
    fn opposite(&self, e: u32, v: u32) -> u32 {
        let [a, b] = self.endpoints(e);
        if a == v { b } else { a }
    }
    /// The two nodes of every edge slot, indexed by edge id (`[u32::MAX; 2]` for removed edges):
    /// the edge list that verifiers and materialised graphs ([`mesh_dual_graph`]) read.
    fn edge_list(&self) -> Vec<[u32; 2]> {
        (0..self.edge_slots() as u32)
            .map(|e| {
                if self.is_edge(e) {
                    self.endpoints(e)
                } else {
                    [NONE, NONE]
                }
            })
            .collect()
    }
    /// The array [`DualGraph::adjacent`] reads, when it is one ([`CompactDual`]), so that the
    /// searches may load it ahead of need; `None` by default (a mesh computes adjacency from
    /// its half-edges).
    #[inline]
    fn flat_adjacency(&self) -> Option<&[[(u32, u32); 3]]> {
        None
    }
    /// The three `(edge, neighbour)` pairs of every node slot (`NONE` pairs for removed nodes), in
    /// some fixed order per node, with the non-loop degrees: what [`CompactDual`] stores. By
    /// default [`DualGraph::adjacent`] node by node.
    fn adjacency_table(&self) -> AdjacencyTable {
        let adjacent: Vec<[(u32, u32); 3]> = (0..self.node_slots() as u32)
            .map(|v| {
                if self.is_node(v) {
                    self.adjacent(v)
                } else {
                    [(NONE, NONE); 3]
                }
            })
            .collect();
        let non_loop_degrees = non_loop_degrees_of(&adjacent);
        AdjacencyTable {
            adjacent,
            non_loop_degrees,
        }
    }
}

/// The adjacency of a [`DualGraph`] copied into flat arrays ([`DualGraph::adjacency_table`]).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct AdjacencyTable {
    /// Per node slot, its three `(edge, neighbour)` pairs (`NONE` pairs for removed nodes).
    pub adjacent: Vec<[(u32, u32); 3]>,
    /// Per node slot, its number of non-loop edge slots (0 for removed nodes): each node's free
    /// degree while nothing is paired.
    pub non_loop_degrees: Vec<u8>,
}

impl DualGraph for SurfaceMesh {
    #[inline]
    fn node_slots(&self) -> usize {
        self.face_slots()
    }
    #[inline]
    fn edge_slots(&self) -> usize {
        SurfaceMesh::edge_slots(self)
    }
    #[inline]
    fn is_node(&self, v: u32) -> bool {
        self.is_face_live(FaceId(v))
    }
    #[inline]
    fn is_edge(&self, e: u32) -> bool {
        self.is_edge_live(EdgeId(e))
    }
    #[inline]
    fn node_count(&self) -> usize {
        self.face_count()
    }
    #[inline]
    fn adjacent(&self, v: u32) -> [(u32, u32); 3] {
        self.face_halfedges(FaceId(v))
            .map(|h| (h.edge().0, self.face(h.twin()).0))
    }
    #[inline]
    fn endpoints(&self, e: u32) -> [u32; 2] {
        let h = EdgeId(e).halfedge();
        [self.face(h).0, self.face(h.twin()).0]
    }
    /// Edge by edge: the two faces of an edge are two sequential reads (a face's own half-edge
    /// cycle is a chain of dependent random reads when half-edges are not in face order), and
    /// each face gets the edge in its next free slot, so a node's pairs are in increasing edge id
    /// order rather than in [`DualGraph::adjacent`]'s; the degrees are counted on the way, and
    /// without removed edges the edges are read straight from the half-edges' faces
    /// ([`SurfaceMesh::halfedge_faces`]): one sequential pass instead of a dependent chain of
    /// random reads per node.
    fn adjacency_table(&self) -> AdjacencyTable {
        let mut adjacent = vec![[(NONE, NONE); 3]; self.face_slots()];
        let mut filled = vec![0u8; self.face_slots()];
        let mut any_loop = false;
        let mut fill = |e: u32, a: u32, b: u32| {
            any_loop |= a == b;
            for (v, w) in [(a, b), (b, a)] {
                let slot = &mut filled[v as usize];
                adjacent[v as usize][usize::from(*slot)] = (e, w);
                *slot += 1;
            }
        };
        if self.edge_count() == self.edge_slots() {
            for (e, faces) in self.halfedge_faces().chunks_exact(2).enumerate() {
                fill(e as u32, faces[0].0, faces[1].0);
            }
        } else {
            for e in self.edges() {
                let h = e.halfedge();
                fill(e.0, self.face(h).0, self.face(h.twin()).0);
            }
        }
        // A loop filled two slots of its face (rare: counted again only then).
        if any_loop {
            for (v, pairs) in adjacent.iter().enumerate() {
                filled[v] = non_loop_degree(v as u32, pairs);
            }
        }
        AdjacencyTable {
            adjacent,
            non_loop_degrees: filled,
        }
    }
}

impl DualGraph for CubicGraph {
    #[inline]
    fn node_slots(&self) -> usize {
        self.node_count() as usize
    }
    #[inline]
    fn edge_slots(&self) -> usize {
        self.edge_count() as usize
    }
    #[inline]
    fn is_node(&self, v: u32) -> bool {
        v < CubicGraph::node_count(self)
    }
    #[inline]
    fn is_edge(&self, e: u32) -> bool {
        e < self.edge_count()
    }
    #[inline]
    fn node_count(&self) -> usize {
        CubicGraph::node_count(self) as usize
    }
    #[inline]
    fn adjacent(&self, v: u32) -> [(u32, u32); 3] {
        self.incident_edges(v)
            .map(|e| (e, CubicGraph::opposite(self, e, v)))
    }
    #[inline]
    fn endpoints(&self, e: u32) -> [u32; 2] {
        CubicGraph::endpoints(self, e)
    }
}

/// The number of non-loop pairs among `pairs`, node `v`'s (0 for `NONE` pairs).
fn non_loop_degree(v: u32, pairs: &[(u32, u32); 3]) -> u8 {
    pairs.iter().filter(|&&(_, w)| w != NONE && w != v).count() as u8
}

/// The non-loop degree of every node slot of a flat adjacency array.
fn non_loop_degrees_of(adjacent: &[[(u32, u32); 3]]) -> Vec<u8> {
    adjacent
        .iter()
        .enumerate()
        .map(|(v, pairs)| non_loop_degree(v as u32, pairs))
        .collect()
}

/// The non-loop degree of every node slot ([`AdjacencyTable::non_loop_degrees`]), node by node.
pub(crate) fn non_loop_degrees<G: DualGraph + ?Sized>(graph: &G) -> Vec<u8> {
    (0..graph.node_slots() as u32)
        .map(|v| {
            if graph.is_node(v) {
                non_loop_degree(v, &graph.adjacent(v))
            } else {
                0
            }
        })
        .collect()
}

/// A [`DualGraph`] whose adjacency is copied into one flat array: per node its three
/// `(edge, neighbour)` pairs in one 24-byte record. Reading a node's neighbours is then one memory
/// access instead of the half-edge chain `face_halfedge → next → next → face(twin)` (up to six
/// dependent cache misses when a search jumps around a large mesh). Building it is one sequential
/// pass (over the edges, for a mesh); a graph that already is such an array
/// ([`DualGraph::flat_adjacency`]) is borrowed, not copied. Everything else (liveness, edge
/// endpoints) is read from the wrapped graph. The augmenting searches ([`crate::augment_to_perfect`],
/// [`crate::karp_sipser_perfect`]) use it when they expect to reach many nodes.
#[derive(Clone, Debug)]
pub struct CompactDual<'g, G: ?Sized> {
    graph: &'g G,
    adjacency: Cow<'g, [[(u32, u32); 3]]>,
}

impl<'g, G: DualGraph + ?Sized> CompactDual<'g, G> {
    /// Copies the adjacency of `graph` ([`DualGraph::adjacency_table`]; removed nodes get `NONE`
    /// entries), or borrows its flat array. O(n).
    pub fn new(graph: &'g G) -> Self {
        Self::with_degrees(graph).0
    }

    /// [`CompactDual::new`], and the non-loop degrees of the node slots
    /// ([`AdjacencyTable::non_loop_degrees`]) counted on the way.
    pub fn with_degrees(graph: &'g G) -> (Self, Vec<u8>) {
        if let Some(adjacent) = graph.flat_adjacency() {
            let degrees = non_loop_degrees_of(adjacent);
            let compact = CompactDual {
                graph,
                adjacency: Cow::Borrowed(adjacent),
            };
            return (compact, degrees);
        }
        let table = graph.adjacency_table();
        let compact = CompactDual {
            graph,
            adjacency: Cow::Owned(table.adjacent),
        };
        (compact, table.non_loop_degrees)
    }
}

/// The [`DualGraph`] methods that read a flat adjacency array, the field `adjacency` of the
/// implementing type (`[(edge, neighbour); 3]` per node slot): its length is the node slots.
macro_rules! flat_adjacency_methods {
    () => {
        #[inline]
        fn node_slots(&self) -> usize {
            self.adjacency.len()
        }
        #[inline]
        fn adjacent(&self, v: u32) -> [(u32, u32); 3] {
            self.adjacency[v as usize]
        }
        #[inline]
        fn flat_adjacency(&self) -> Option<&[[(u32, u32); 3]]> {
            Some(&self.adjacency)
        }
    };
}
pub(crate) use flat_adjacency_methods;

impl<G: DualGraph + ?Sized> DualGraph for CompactDual<'_, G> {
    flat_adjacency_methods!();
    #[inline]
    fn edge_slots(&self) -> usize {
        self.graph.edge_slots()
    }
    #[inline]
    fn is_node(&self, v: u32) -> bool {
        self.graph.is_node(v)
    }
    #[inline]
    fn is_edge(&self, e: u32) -> bool {
        self.graph.is_edge(e)
    }
    #[inline]
    fn node_count(&self) -> usize {
        self.graph.node_count()
    }
    #[inline]
    fn endpoints(&self, e: u32) -> [u32; 2] {
        self.graph.endpoints(e)
    }
}

/// Why a set of edges is not a matching of a [`DualGraph`] ([`Pairing::from_edges`]).
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum PairingError {
    /// The edge is not a live edge of the graph.
    #[error("edge {edge} is not a live edge of the graph")]
    NotAnEdge {
        /// The offending edge id.
        edge: u32,
    },
    /// The edge is a loop (its node cannot be paired with itself).
    #[error("edge {edge} is a loop at node {node}")]
    Loop {
        /// The offending edge id.
        edge: u32,
        /// Its node.
        node: u32,
    },
    /// Two edges of the set share a node.
    #[error("node {node} is covered by edges {first} and {second}")]
    CoveredTwice {
        /// The shared node.
        node: u32,
        /// The first edge met at it.
        first: u32,
        /// The second edge.
        second: u32,
    },
}

/// A matching of a [`DualGraph`] (a pairing of triangles), as one mate edge per node slot.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Pairing {
    pub(crate) mate: Vec<u32>,
}

impl Pairing {
    /// The empty matching on `node_slots` node ids.
    pub fn empty(node_slots: usize) -> Self {
        Pairing {
            mate: vec![NONE; node_slots],
        }
    }

    /// The matching made of the given edges, checked: every edge live, no loop, no node covered
    /// twice. O(number of edges + node slots).
    ///
    /// # Errors
    /// The first violation, as a [`PairingError`] naming the edge or node.
    pub fn from_edges<G: DualGraph + ?Sized>(
        graph: &G,
        edges: impl IntoIterator<Item = u32>,
    ) -> Result<Self, PairingError> {
        let mut pairing = Pairing::empty(graph.node_slots());
        for e in edges {
            if !graph.is_edge(e) {
                return Err(PairingError::NotAnEdge { edge: e });
            }
            let [a, b] = graph.endpoints(e);
            if a == b {
                return Err(PairingError::Loop { edge: e, node: a });
            }
            for v in [a, b] {
                let first = pairing.mate[v as usize];
                if first != NONE {
                    return Err(PairingError::CoveredTwice {
                        node: v,
                        first,
                        second: e,
                    });
                }
            }
            pairing.mate[a as usize] = e;
            pairing.mate[b as usize] = e;
        }
        Ok(pairing)
    }

    /// The matching given by per-edge flags (`flags[e]` true for matched edges), checked as in
    /// [`Pairing::from_edges`].
    ///
    /// # Errors
    /// See [`Pairing::from_edges`].
    pub fn from_edge_flags<G: DualGraph + ?Sized>(
        graph: &G,
        flags: &[bool],
    ) -> Result<Self, PairingError> {
        Self::from_edges(
            graph,
            flags
                .iter()
                .enumerate()
                .filter(|&(_, &m)| m)
                .map(|(e, _)| e as u32),
        )
    }

    /// The mate edge of node `v`, if `v` is matched.
    #[inline]
    pub fn mate_edge(&self, v: u32) -> Option<u32> {
        match self.mate.get(v as usize) {
            Some(&e) if e != NONE => Some(e),
            _ => None,
        }
    }

    /// Whether edge `e` of `graph` is matched (false for removed or out-of-range edges).
    pub fn contains_edge<G: DualGraph + ?Sized>(&self, graph: &G, e: u32) -> bool {
        (e as usize) < graph.edge_slots()
            && graph.is_edge(e)
            && self.mate_edge(graph.endpoints(e)[0]) == Some(e)
    }

    /// The mate edge per node slot (`u32::MAX` for unmatched or removed nodes).
    pub fn mates(&self) -> &[u32] {
        &self.mate
    }

    /// Number of live nodes of `graph` left unmatched.
    pub fn unmatched_count<G: DualGraph + ?Sized>(&self, graph: &G) -> usize {
        self.unmatched_nodes(graph).len()
    }

    /// The live nodes of `graph` left unmatched, in increasing order.
    pub fn unmatched_nodes<G: DualGraph + ?Sized>(&self, graph: &G) -> Vec<u32> {
        (0..self.mate.len() as u32)
            .filter(|&v| self.mate[v as usize] == NONE && graph.is_node(v))
            .collect()
    }

    /// The matched edges, in increasing order (each once).
    pub fn matched_edges<G: DualGraph + ?Sized>(&self, graph: &G) -> Vec<u32> {
        let mut edges: Vec<u32> = (0..self.mate.len() as u32)
            .filter(|&v| {
                let e = self.mate[v as usize];
                e != NONE && graph.endpoints(e)[0] == v
            })
            .map(|v| self.mate[v as usize])
            .collect();
        edges.sort_unstable();
        edges
    }

    /// Per-edge flags (`edge_slots` entries): true for matched edges.
    pub fn edge_flags(&self, edge_slots: usize) -> Vec<bool> {
        let mut flags = vec![false; edge_slots];
        for &e in &self.mate {
            if e != NONE {
                flags[e as usize] = true;
            }
        }
        flags
    }

    /// Matches edge `e` between nodes `a` and `b` (the caller checks they are free).
    #[inline]
    pub(crate) fn join(&mut self, e: u32, a: u32, b: u32) {
        self.mate[a as usize] = e;
        self.mate[b as usize] = e;
    }
}

/// The dual graph of a compact mesh (dense face and edge ids) as a validated [`CubicGraph`] whose
/// node `f` is face `f` and edge `e` is primal edge `e`, for algorithms that need a materialised
/// graph (Diks–Stanczyk). O(n).
///
/// # Errors
/// A [`crate::GraphError`] if the dual is not connected, bridgeless and cubic (a primal loop), or
/// [`crate::GraphError::Empty`] if the mesh has tombstones (call `compact` first) or no faces.
pub fn mesh_dual_graph(mesh: &SurfaceMesh) -> Result<CubicGraph, crate::GraphError> {
    if mesh.face_slots() != mesh.face_count() || mesh.edge_slots() != mesh.edge_count() {
        return Err(crate::GraphError::Empty);
    }
    let edges = mesh.edge_list();
    CubicGraph::new(mesh.face_count() as u32, edges)
}
