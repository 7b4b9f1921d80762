//! The Delaunay tessellation of a Delaunay triangulation (Bobenko & Springborn 2007, Section 2
//! and Proposition 4; Dubois, Appendix C, Lemma 29).
//!
//! Every Delaunay triangulation with vertex set V refines the unique Delaunay tessellation of
//! (S, V): its faces are the convex polygons inscribed in the empty immersed disks, and a
//! Delaunay triangulation splits each of them along diagonals. A diagonal is exactly an edge whose
//! two triangles share their circumcircle — opposite angles summing to π, i.e. `tan(γ/2) tan(δ/2)
//! = 1` (see [`crate::triangulation::trig::Quad::delaunay_product`]). So the tessellation is obtained by deleting
//! the co-circular edges: triangles are merged across every edge with
//! `|√(tan²(γ/2) tan²(δ/2)) - 1| <= tolerance` ([`DEFAULT_COCIRCULAR_TOLERANCE`]).
//!
//! Decision where exact arithmetic leaves nothing to decide: merging follows a spanning forest of
//! the co-circular edges (edges in increasing id order, union-find over faces). In exact
//! arithmetic the co-circular edges of a Delaunay triangulation never close a cycle (each face of
//! the tessellation is a disk triangulated by diagonals), but with a tolerance a cycle could
//! appear; an edge that would close one is kept as a side (matched to another side of the same
//! polygon), so every polygon stays a disk and the output is always a valid portalgon.
//!
//! Each polygon is laid out in the plane by unfolding its triangles along the merged edges
//! (breadth-first from its smallest face id), and listed counter-clockwise starting from its
//! smallest side half-edge. Vertex labels are the dense vertex indices. O(n α(n)).
//!
//! This is the Delaunay tessellation of (S, V) for V the triangulation's vertices; the paper's
//! canonical tessellation has V = the singular vertices (see [`crate::canonical_tessellation`],
//! which removes the flat ones first).

use crate::portalgon::{Portalgon, SideId};
use crate::triangulation::IntrinsicTriangulation;
use crate::triangulation::dense_vertex_index;
use crate::triangulation::trig;
use surftopo_mesh::{EdgeId, FaceId, HalfedgeId, UnionFind};

/// Default tolerance for co-circularity: `|tan(γ/2) tan(δ/2) - 1| <= 1e-9`.
pub const DEFAULT_COCIRCULAR_TOLERANCE: f64 = 1e-9;

/// A Delaunay tessellation as a portalgon, with its relation to the triangulation it came from.
#[derive(Clone, Debug, PartialEq)]
pub struct Tessellation {
    /// The polygons (dense ids) and their side matching; corners labelled with vertex indices.
    pub portalgon: Portalgon,
    /// The triangulation faces merged into polygon `k` are
    /// `faces[face_start[k] as usize..face_start[k + 1] as usize]`, increasing ids.
    pub faces: Vec<FaceId>,
    /// Offsets into [`Tessellation::faces`], one per polygon plus one.
    pub face_start: Vec<u32>,
    /// The triangulation half-edge of each side (indexed by side id).
    pub side_halfedge: Vec<HalfedgeId>,
    /// The edges deleted (merged across), increasing ids.
    pub merged_edges: Vec<EdgeId>,
    /// Co-circular edges kept as sides because merging across them would close a cycle (0 in
    /// exact arithmetic).
    pub cycle_edges: usize,
}

impl Tessellation {
    /// The triangulation faces merged into polygon `k`.
    pub fn faces_of(&self, k: usize) -> &[FaceId] {
        &self.faces[self.face_start[k] as usize..self.face_start[k + 1] as usize]
    }
}

/// Whether the edge's two triangles are co-circular within `tolerance` (and distinct).
pub fn is_cocircular(tri: &IntrinsicTriangulation, e: EdgeId, tolerance: f64) -> bool {
    let h = e.halfedge();
    let mesh = tri.mesh();
    mesh.face(h) != mesh.face(h.twin())
        && cocircular_product(tri.quad(h).delaunay_product(), tolerance)
}

/// `|√product - 1| <= tolerance`.
#[inline]
fn cocircular_product(product: f64, tolerance: f64) -> bool {
    (product.sqrt() - 1.0).abs() <= tolerance
}

/// The Delaunay tessellation of a Delaunay triangulation (see the module doc). The input is not
/// checked to be Delaunay: run [`crate::flip_to_delaunay`] first; an edge that is not Delaunay
/// simply stays a side.
pub fn delaunay_tessellation(tri: &IntrinsicTriangulation, tolerance: f64) -> Tessellation {
    let mesh = tri.mesh();
    let nf = mesh.face_slots();
    let mut regions = UnionFind::new(nf);
    let mut merged = vec![false; mesh.edge_slots()];
    let mut merged_edges = Vec::new();
    let mut cycle_edges = 0usize;
    let t2 = tri.halfedge_tan_half_sq();
    for e in mesh.edges() {
        let h = e.halfedge();
        let (f, g) = (mesh.face(h), mesh.face(h.twin()));
        if f == g || !cocircular_product(t2[h.idx()] * t2[h.twin().idx()], tolerance) {
            continue;
        }
        let (a, b) = (regions.find(f.0), regions.find(g.0));
        if a == b {
            cycle_edges += 1;
            continue;
        }
        regions.union(a, b);
        merged[e.idx()] = true;
        merged_edges.push(e);
    }

    // Lay out each region: position of origin(h) in the placement of face(h), per half-edge.
    let mut pos = vec![[f64::NAN; 2]; mesh.halfedge_slots()];
    let mut placed = vec![false; nf];
    let mut faces: Vec<FaceId> = Vec::with_capacity(mesh.face_count());
    let mut face_start: Vec<u32> = vec![0];
    let mut queue: Vec<FaceId> = Vec::new();
    for f0 in mesh.faces() {
        if placed[f0.idx()] {
            continue;
        }
        placed[f0.idx()] = true;
        let corners = tri.layout_face(f0);
        for (h, c) in mesh.face_halfedges(f0).into_iter().zip(corners) {
            pos[h.idx()] = c;
        }
        queue.clear();
        queue.push(f0);
        let mut head = 0;
        while head < queue.len() {
            let f = queue[head];
            head += 1;
            for h in mesh.face_halfedges(f) {
                let t = h.twin();
                let g = mesh.face(t);
                if !merged[h.edge().idx()] || placed[g.idx()] {
                    continue;
                }
                placed[g.idx()] = true;
                // t runs from dest(h) to origin(h).
                let p = pos[mesh.next(h).idx()];
                let q = pos[h.idx()];
                pos[t.idx()] = p;
                pos[mesh.next(t).idx()] = q;
                let [x, y] = trig::third_corner(
                    tri.halfedge_length(t),
                    tri.halfedge_length(mesh.next(t)),
                    tri.halfedge_length(mesh.prev(t)),
                );
                let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
                let norm = dx.hypot(dy);
                let (ux, uy) = (dx / norm, dy / norm);
                pos[mesh.prev(t).idx()] = [p[0] + x * ux - y * uy, p[1] + x * uy + y * ux];
                queue.push(g);
            }
        }
        queue.sort_unstable();
        faces.extend_from_slice(&queue);
        face_start.push(faces.len() as u32);
    }

    // Boundary walks.
    let (dense, _) = dense_vertex_index(tri);
    let mut portalgon = Portalgon::new();
    let mut side_of = vec![SideId::INVALID; mesh.halfedge_slots()];
    let mut side_halfedge = Vec::with_capacity(mesh.halfedge_slots());
    let (mut walk, mut corners, mut labels) = (Vec::new(), Vec::new(), Vec::new());
    for region in face_start.windows(2) {
        let region = &faces[region[0] as usize..region[1] as usize];
        let start = region
            .iter()
            .flat_map(|&f| mesh.face_halfedges(f))
            .filter(|h| !merged[h.edge().idx()])
            .min()
            .expect("a region has a side");
        walk.clear();
        walk.push(start);
        let mut h = start;
        loop {
            let mut g = mesh.next(h);
            while merged[g.edge().idx()] {
                g = mesh.next(g.twin());
            }
            if g == start {
                break;
            }
            walk.push(g);
            h = g;
        }
        debug_assert_eq!(walk.len(), region.len() + 2);
        corners.clear();
        corners.extend(walk.iter().map(|h| pos[h.idx()]));
        labels.clear();
        labels.extend(walk.iter().map(|&h| dense[mesh.origin(h).idx()]));
        let p = portalgon.push_polygon(&corners, Some(&labels));
        for (i, &h) in walk.iter().enumerate() {
            let s = portalgon.side(p, i);
            side_of[h.idx()] = s;
            side_halfedge.push(h);
        }
    }
    for e in mesh.edges() {
        if !merged[e.idx()] {
            let h = e.halfedge();
            portalgon.set_mates(side_of[h.idx()], side_of[h.twin().idx()]);
        }
    }
    Tessellation {
        portalgon,
        faces,
        face_start,
        side_halfedge,
        merged_edges,
        cycle_edges,
    }
}
