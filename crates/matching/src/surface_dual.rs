//! The dual graph of any compact triangulated surface, read from its [`ClosedCover`]: boundary
//! loops, non-orientable and several components.
//!
//! The dual of a surface K has one node per triangle and one edge per edge of K with a triangle
//! on both sides. On the cover D (see `surftopo_mesh::ClosedCover`) a triangle of K is a surface
//! face (one of a mirror pair on a doubled component) and an edge of K is one edge key
//! ([`Lifting::edge_key`]); a cone triangle stands beyond a boundary edge. [`SurfaceDual`]
//! copies this graph into flat arrays, in the form every pairing algorithm of the crate reads
//! ([`DualGraph`]):
//!
//! - node `f` is surface face `f` of the cover (the input triangle `f` for a cover built from a
//!   soup); the other face slots (cone faces, mirror copies) are not nodes;
//! - edges are numbered densely in the order the triangles' sides are met (triangle by triangle,
//!   side by side);
//! - a *boundary* side of a triangle is a loop at its node filling that one slot (a half-loop):
//!   every algorithm skips loops (a loop is never matched), so a triangle with `k` boundary
//!   sides has free degree `3 − k`, and the graph is a multigraph of maximum degree 3 whose
//!   nodes of degree below 3 are the triangles on the boundary.
//!
//! [`SurfaceDual::coned`] is the dual of the *coned closure* instead: the cone triangles are
//! nodes too (on a doubled component, one per mirror pair), so every side has a neighbour. The
//! coned closure is a closed surface without loops (an apex is joined to a boundary vertex by one
//! edge), so its dual is cubic and bridgeless: a dual edge is a bridge only when its primal edge
//! alone bounds a region (a loop). Diks–Stanczyk pairs it (`surftopo-quad` then drops the pairs
//! with a cone triangle).
//!
//! [`SurfaceDual::components`] numbers the connected components (the surface's pieces, in the
//! order of their first triangle: faces joined through edges; a manifold vertex's star is one
//! fan, so these are the pieces `surftopo info` lists).

use surftopo_mesh::{ClosedCover, FaceId, HalfedgeId, Lifting};

use prefetch_index::prefetch_index;

use crate::augment::PREFETCH_AHEAD;
use crate::dual_graph::{DualGraph, NONE, flat_adjacency_methods};

/// The dual graph of a compact surface (see the module doc), as flat arrays.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SurfaceDual {
    /// Per node slot (face slot of the cover): its three `(edge, neighbour)` pairs, in the order
    /// of the face's half-edges; `NONE` pairs for slots that are not nodes.
    adjacency: Vec<[(u32, u32); 3]>,
    /// Per node slot: whether it is a node.
    node: Vec<bool>,
    nodes: usize,
    /// Per edge: its two nodes (equal for a boundary half-loop), the first being the node whose
    /// side met it first.
    ends: Vec<[u32; 2]>,
    /// Per edge: the half-edge of the cover on the first end's side (in the face of that node).
    halfedge: Vec<HalfedgeId>,
}

impl SurfaceDual {
    /// The dual of the surface `cover` stands for (see the module doc). O(n).
    pub fn of_cover(cover: &ClosedCover) -> Self {
        Self::build(cover, false)
    }

    /// The dual of the surface's coned closure: the cone triangles are nodes too (see the module
    /// doc). Cubic; bridgeless on a cover built from a soup. O(n).
    pub fn coned(cover: &ClosedCover) -> Self {
        Self::build(cover, true)
    }

    fn build(cover: &ClosedCover, cones: bool) -> Self {
        let (mesh, sheets) = (&cover.mesh, &cover.sheets);
        let is_cone = |f: FaceId| mesh.face_vertices(f).iter().any(|&v| sheets.is_apex(v));
        // The face standing for `f`'s triangle: itself, or its mirror copy with the smaller id.
        let primary = |f: FaceId| match sheets.mirror(mesh.face_halfedge(f)) {
            Some(m) => f.min(mesh.face(m)),
            None => f,
        };
        let is_node = |f: FaceId| primary(f) == f && (cones || !is_cone(f));
        let slots = mesh.face_slots();
        let mut node = vec![false; slots];
        for f in mesh.faces() {
            node[f.idx()] = is_node(f);
        }
        let mut adjacency = vec![[(NONE, NONE); 3]; slots];
        let mut edge_of_key = vec![NONE; mesh.edge_slots()];
        let mut ends = Vec::with_capacity(3 * slots / 2);
        let mut halfedge = Vec::with_capacity(3 * slots / 2);
        let mut nodes = 0;
        for f in mesh.faces().filter(|&f| node[f.idx()]) {
            nodes += 1;
            for (slot, h) in mesh.face_halfedges(f).into_iter().enumerate() {
                let across = mesh.face(h.twin());
                let neighbour = if !cones && is_cone(across) {
                    None
                } else {
                    Some(primary(across))
                };
                let key = sheets.edge_key(h.edge()).idx();
                let e = match neighbour {
                    Some(_) if edge_of_key[key] != NONE => edge_of_key[key],
                    _ => {
                        let e = ends.len() as u32;
                        let other = neighbour.unwrap_or(f).0;
                        ends.push([f.0, other]);
                        halfedge.push(h);
                        if neighbour.is_some() {
                            edge_of_key[key] = e;
                        }
                        e
                    }
                };
                adjacency[f.idx()][slot] = (e, neighbour.unwrap_or(f).0);
            }
        }
        SurfaceDual {
            adjacency,
            node,
            nodes,
            ends,
            halfedge,
        }
    }

    /// The half-edge of the cover on the first end's side of edge `e` (in the face of node
    /// `endpoints(e)[0]`): for a pair of triangles, the side of the first triangle along the
    /// shared edge; for a boundary half-loop, the boundary side.
    pub fn halfedge(&self, e: u32) -> HalfedgeId {
        self.halfedge[e as usize]
    }

    /// Whether edge `e` is a boundary half-loop (a side of a triangle with no triangle beyond).
    pub fn is_boundary(&self, e: u32) -> bool {
        let [a, b] = self.ends[e as usize];
        a == b
    }

    /// The connected component of every node slot (`u32::MAX` for slots that are not nodes),
    /// numbered in the order of their first node, and the number of components
    /// ([`components_of`]). O(n).
    pub fn components(&self) -> (Vec<u32>, usize) {
        components_of(self)
    }
}

/// The connected components of any [`DualGraph`]: per node slot its component (`u32::MAX` for
/// removed slots), numbered in the order of their first node, and their number. A breadth-first
/// search over the adjacency ([`DualGraph::adjacent`]; boundary sides and loops join nothing):
/// one read of each node's neighbours, rather than a disjoint-set union per edge with its random
/// finds. O(n).
pub fn components_of<G: DualGraph + ?Sized>(graph: &G) -> (Vec<u32>, usize) {
    let mut component = vec![NONE; graph.node_slots()];
    let count = label_components(graph, &mut component, |_| {});
    (component, count)
}

/// The search of [`components_of`]: labels `component` (all `NONE` on entry, one entry per node
/// slot), calls `on_component` with the number of nodes of each component once it is labelled,
/// and returns the number of components.
///
/// Breadth-first, because the queue tells which nodes come next: the adjacency of the node
/// [`PREFETCH_AHEAD`] places ahead is asked for early, so the reads of a large graph overlap
/// instead of stalling one after the other (a depth-first stack knows its next node only when
/// it pops it; on a 100k-face open mesh that search waited on those reads most of its time).
/// The labels do not depend on the order of the search.
pub(crate) fn label_components<G: DualGraph + ?Sized>(
    graph: &G,
    component: &mut [u32],
    mut on_component: impl FnMut(usize),
) -> usize {
    let slots = graph.node_slots();
    let flat = graph.flat_adjacency();
    let mut queue = Vec::with_capacity(slots);
    let mut count = 0;
    for start in 0..slots as u32 {
        if component[start as usize] != NONE || !graph.is_node(start) {
            continue;
        }
        component[start as usize] = count;
        queue.clear();
        queue.push(start);
        let mut head = 0;
        while let Some(&v) = queue.get(head) {
            if let (Some(adjacency), Some(&ahead)) = (flat, queue.get(head + PREFETCH_AHEAD)) {
                prefetch_index(adjacency, ahead as usize);
            }
            head += 1;
            for (_, w) in graph.adjacent(v) {
                if w != NONE && component[w as usize] == NONE {
                    component[w as usize] = count;
                    queue.push(w);
                }
            }
        }
        on_component(queue.len());
        count += 1;
    }
    count as usize
}

impl DualGraph for SurfaceDual {
    flat_adjacency_methods!();
    #[inline]
    fn edge_slots(&self) -> usize {
        self.ends.len()
    }
    #[inline]
    fn is_node(&self, v: u32) -> bool {
        self.node.get(v as usize).copied().unwrap_or(false)
    }
    #[inline]
    fn is_edge(&self, e: u32) -> bool {
        (e as usize) < self.ends.len()
    }
    #[inline]
    fn node_count(&self) -> usize {
        self.nodes
    }
    #[inline]
    fn endpoints(&self, e: u32) -> [u32; 2] {
        self.ends[e as usize]
    }
}
