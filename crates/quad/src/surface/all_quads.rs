//! All quads on a surface with boundary: each triangle a maximum pairing leaves is turned into
//! part of a quad by one vertex added on a boundary edge.
//!
//! # The construction
//! A maximum pairing of a piece leaves `d` triangles, `d` being the piece's deficiency (the
//! Tutte–Berge bound of its certificate; 0 on a closed piece). Splitting a boundary edge `xy` of
//! an unpaired triangle `(x, y, z)` at its midpoint `w` gives the triangles `(x, w, z)` and
//! `(w, y, z)`, which pair into the quad `[w, y, z, x]`. An unpaired triangle with no boundary
//! side is first moved to one that has one: in the alternating tree grown from it by the
//! barrier's search, every even node can be left unpaired instead of the root by flipping the
//! even path between them (`surftopo_matching::shift_unmatched`), which keeps the pairing's
//! size. Each round moves the unpaired triangle of every tree that holds a boundary triangle
//! there and splits it; the rounds repeat on the refined surface until nothing is left.
//!
//! **Every round makes progress.** In the final forest of the barrier's search, with `d > 0`
//! trees, let the outer components be the blossoms and single even nodes (odd sets of
//! triangles), `I` the odd nodes; each tree has one more outer component than odd nodes, so
//! there are `I + d` of them. An outer component's neighbours are odd nodes only. The sides of
//! an odd set S of triangles that do not cancel inside it form a non-empty 1-cycle mod 2 (empty
//! only for a union of closed pieces, which have an even number of triangles); on a simplicial
//! surface a non-empty cycle has at least 3 edges, so S has at least 3 sides that are boundary
//! edges or shared with a triangle outside: `3 − bnd(S)` or more edges to odd nodes. An odd node
//! t has at most `3 − bnd(t)` edges. Summing, `3 (I + d) − bnd(outer) ≤ 3 I − bnd(odd)`, so the
//! even triangles have at least `3 d` boundary sides: some tree holds a boundary triangle.
//!
//! **The count is minimal** among refinements that add vertices on boundary edges: adding a
//! vertex on a boundary edge splits one triangle in two (one more node in the dual), and a
//! matching of the refined dual gives one of the old dual with at most one pair less (merge the
//! two halves back: drop their pair, or one of their two outside pairs), so the unpaired count
//! drops by at most one per vertex: `d` vertices are needed, and the construction adds `d`.
//! Beyond that class (ours, not searched): a vertex added inside the surface splits two
//! triangles (on an interior edge) or one into three, and can lower the unpaired count by two
//! (a triangle with three ears, `d = 2`, is paired entirely by one vertex inside its middle
//! triangle), so no refinement needs fewer than `⌈d/2⌉`. The positions and per-vertex data of the
//! input are kept; an added vertex is the midpoint of its edge (its quad has a straight corner
//! there: quality 0 by Remacle et al.'s measure).

use surftopo_matching::{
    DualGraph, MaximumPairing, Pairing, SurfaceDual, shift_unmatched, verify_perfect_pairing,
};
use surftopo_mesh::ClosedCover;

use crate::QuadError;

const NONE: u32 = u32::MAX;

/// The quads of a surface after [`all_quads`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AllQuads {
    /// Every quad, as surface vertex ids and added ones (see [`super::SurfaceQuads::quads`]):
    /// the pairing's in its edge order, then those of the split triangles.
    pub quads: Vec<[u32; 4]>,
    /// Per added vertex, the boundary edge it is the midpoint of.
    pub added: Vec<[u32; 2]>,
    /// Added vertices per piece.
    pub added_per_component: Vec<usize>,
}

/// Turns a maximum pairing of the surface's dual into all quads by adding one vertex on a
/// boundary edge per unpaired triangle (see the module doc). The result's pairing is checked
/// perfect by the independent verifier, and its count of added vertices equal, piece by piece,
/// to the certificate's bound.
///
/// # Errors
/// [`QuadError::Internal`] when a round finds no boundary triangle to move a hole to, or the
/// result fails its checks (a bug).
pub fn all_quads(
    cover: &ClosedCover,
    dual: &SurfaceDual,
    pairing: MaximumPairing,
) -> Result<AllQuads, QuadError> {
    let vertex_count = super::surface_vertex_count(cover) as u32;
    let mut work = Refined::new(cover, dual, pairing.component_of());
    let bounds: Vec<usize> = pairing
        .components()
        .iter()
        .map(|c| c.deficiency_lower_bound)
        .collect();
    let mut added: Vec<[u32; 2]> = Vec::new();
    let mut added_per_component = vec![0usize; bounds.len()];
    let mut current = pairing.pairing().clone();
    loop {
        if current.unmatched_count(&work) == 0 {
            break;
        }
        // Triangles of the input first: a half of a split triangle is split again only when
        // no other boundary triangle is reachable.
        let mut moved = shift_unmatched(&work, &mut current, |v| {
            !work.split[v as usize] && work.boundary_slot(v).is_some()
        })
        .map_err(|err| QuadError::Internal(format!("all quads: {err}")))?;
        if moved.is_empty() {
            moved = shift_unmatched(&work, &mut current, |v| work.boundary_slot(v).is_some())
                .map_err(|err| QuadError::Internal(format!("all quads: {err}")))?;
        }
        if moved.is_empty() {
            return Err(QuadError::Internal(
                "all quads: no unpaired triangle can reach a boundary triangle".into(),
            ));
        }
        let mut matched = current.matched_edges(&work);
        for v in moved {
            let w = vertex_count + added.len() as u32;
            let (edge, pair) = work.split(v, w);
            added.push(edge);
            added_per_component[work.component[v as usize] as usize] += 1;
            matched.push(pair);
        }
        current = Pairing::from_edges(&work, matched.iter().copied())
            .map_err(|err| QuadError::Internal(format!("all quads: {err}")))?;
    }
    let perfect = verify_perfect_pairing(&work, current).map_err(|err| {
        QuadError::Internal(format!("all quads: the result is not all quads: {err}"))
    })?;
    if added_per_component != bounds {
        return Err(QuadError::Internal(format!(
            "all quads: {added_per_component:?} vertices added per piece, not the deficiencies \
             {bounds:?}"
        )));
    }
    let quads = perfect
        .matched_edges(&work)
        .iter()
        .map(|&e| work.quad(e))
        .collect();
    Ok(AllQuads {
        quads,
        added,
        added_per_component,
    })
}

/// The dual of the surface refined by the boundary vertices added so far, with the triangles'
/// corners: the surface's dual copied, then each split triangle keeps its node for its first
/// half and gets a new node for the second.
struct Refined {
    adjacency: Vec<[(u32, u32); 3]>,
    node: Vec<bool>,
    nodes: usize,
    ends: Vec<[u32; 2]>,
    /// Per node, its corners; slot `i` of its adjacency is the side from corner `i` to `i + 1`.
    corners: Vec<[u32; 3]>,
    /// Per node, its piece.
    component: Vec<u32>,
    /// Per node, whether it is half of a split triangle.
    split: Vec<bool>,
}

impl Refined {
    fn new(cover: &ClosedCover, dual: &SurfaceDual, component: &[u32]) -> Self {
        let slots = dual.node_slots();
        let mut corners = vec![[NONE; 3]; slots];
        for (f, c) in corners.iter_mut().enumerate() {
            if dual.is_node(f as u32) {
                *c = super::triangle_of(cover, f as u32);
            }
        }
        Refined {
            adjacency: (0..slots as u32).map(|v| dual.adjacent(v)).collect(),
            node: (0..slots as u32).map(|v| dual.is_node(v)).collect(),
            nodes: dual.node_count(),
            ends: (0..dual.edge_slots() as u32)
                .map(|e| dual.endpoints(e))
                .collect(),
            corners,
            component: component.to_vec(),
            split: vec![false; slots],
        }
    }

    /// The first boundary side of node `v` (a half-loop slot), if any.
    fn boundary_slot(&self, v: u32) -> Option<usize> {
        self.adjacency[v as usize].iter().position(|&(_, w)| w == v)
    }

    /// Splits the first boundary side `xy` of triangle `v = (x, y, z)` at new vertex `w`: `v`
    /// becomes `(x, w, z)`, a new node `(w, y, z)`. Returns the split edge and the edge between
    /// the two halves.
    fn split(&mut self, v: u32, w: u32) -> ([u32; 2], u32) {
        let i = self.boundary_slot(v).expect("a boundary triangle");
        let [x, y, z] = [0, 1, 2].map(|k| self.corners[v as usize][(i + k) % 3]);
        let old = self.adjacency[v as usize];
        let [side_xy, side_yz, side_zx] = [0, 1, 2].map(|k| old[(i + k) % 3]);
        let t = self.adjacency.len() as u32;
        let between = self.ends.len() as u32;
        self.ends.push([v, t]);
        let outer = self.ends.len() as u32;
        self.ends.push([t, t]);
        // The side yz moves to the new node, at its neighbour too.
        let (e_yz, n_yz) = side_yz;
        let moved_yz = if n_yz == v {
            self.ends[e_yz as usize] = [t, t];
            (e_yz, t)
        } else {
            let ends = &mut self.ends[e_yz as usize];
            for end in ends.iter_mut() {
                if *end == v {
                    *end = t;
                }
            }
            for pair in self.adjacency[n_yz as usize].iter_mut() {
                if pair.0 == e_yz {
                    pair.1 = t;
                }
            }
            (e_yz, n_yz)
        };
        self.corners[v as usize] = [x, w, z];
        self.adjacency[v as usize] = [side_xy, (between, t), side_zx];
        self.corners.push([w, y, z]);
        self.adjacency.push([(outer, t), moved_yz, (between, v)]);
        self.node.push(true);
        self.nodes += 1;
        let c = self.component[v as usize];
        self.component.push(c);
        self.split[v as usize] = true;
        self.split.push(true);
        ([x, y], between)
    }

    /// The quad `[a, d, b, c]` of matched edge `e`: its first end `(a, b, c)` along the shared
    /// side from `a` to `b`, `d` the other end's third corner.
    fn quad(&self, e: u32) -> [u32; 4] {
        let [f, g] = self.ends[e as usize];
        let i = self.adjacency[f as usize]
            .iter()
            .position(|&(edge, _)| edge == e)
            .expect("the edge is at its end");
        let corners = self.corners[f as usize];
        let [a, b, c] = [0, 1, 2].map(|k| corners[(i + k) % 3]);
        let d = self.corners[g as usize]
            .into_iter()
            .find(|&v| v != a && v != b)
            .expect("a triangle has a third corner");
        [a, d, b, c]
    }
}

impl DualGraph for Refined {
    fn node_slots(&self) -> usize {
        self.adjacency.len()
    }
    fn edge_slots(&self) -> usize {
        self.ends.len()
    }
    fn is_node(&self, v: u32) -> bool {
        self.node[v as usize]
    }
    fn is_edge(&self, e: u32) -> bool {
        (e as usize) < self.ends.len()
    }
    fn node_count(&self) -> usize {
        self.nodes
    }
    fn adjacent(&self, v: u32) -> [(u32, u32); 3] {
        self.adjacency[v as usize]
    }
    fn endpoints(&self, e: u32) -> [u32; 2] {
        self.ends[e as usize]
    }
}
