//! Compaction back to dense ids, and renumbering (e.g. Morton order).

use crate::ids::{EdgeId, FaceId, HalfedgeId, VertexId};
use crate::topology::SurfaceMesh;

/// Old-to-new id maps returned by [`SurfaceMesh::compact`] and [`SurfaceMesh::renumber`]
/// (`INVALID` for removed elements). A half-edge `h` maps to `2 * edges[h.edge()] + (h & 1)`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Renumbering {
    /// Old vertex id -> new vertex id.
    pub vertices: Vec<VertexId>,
    /// Old edge id -> new edge id.
    pub edges: Vec<EdgeId>,
    /// Old face id -> new face id.
    pub faces: Vec<FaceId>,
}

impl Renumbering {
    /// New id of an old half-edge.
    pub fn halfedge(&self, h: HalfedgeId) -> HalfedgeId {
        let e = self.edges[h.edge().idx()];
        if e.is_valid() {
            HalfedgeId(e.halfedge().0 | (h.0 & 1))
        } else {
            HalfedgeId::INVALID
        }
    }
}

/// Old -> new map keeping the order of the live ids.
fn dense_map<T: Copy>(
    slots: usize,
    live: impl Fn(usize) -> bool,
    make: fn(usize) -> T,
    none: T,
) -> Vec<T> {
    let mut next = 0;
    (0..slots)
        .map(|i| {
            if live(i) {
                next += 1;
                make(next - 1)
            } else {
                none
            }
        })
        .collect()
}

impl SurfaceMesh {
    /// Removes the tombstones: live elements get dense ids in their old order. O(n).
    pub fn compact(&mut self) -> Renumbering {
        let map = Renumbering {
            vertices: dense_map(
                self.vertex_slots(),
                |i| self.is_vertex_live(VertexId::new(i)),
                VertexId::new,
                VertexId::INVALID,
            ),
            edges: dense_map(
                self.edge_slots(),
                |i| self.is_edge_live(EdgeId::new(i)),
                EdgeId::new,
                EdgeId::INVALID,
            ),
            faces: dense_map(
                self.face_slots(),
                |i| self.is_face_live(FaceId::new(i)),
                FaceId::new,
                FaceId::INVALID,
            ),
        };
        self.renumber(&map);
        map
    }

    /// Renumbers every live element by the given old-to-new maps, which must be bijections from
    /// the live elements onto `0..count` (removed elements map to `INVALID`). O(n).
    ///
    /// # Panics
    /// If a map is not such a bijection (a programming error, caught by the range checks).
    pub fn renumber(&mut self, map: &Renumbering) {
        let (nv, ne, nf) = (self.live_vertices, self.live_edges, self.live_faces);
        let mut next = vec![HalfedgeId::INVALID; 2 * ne];
        let mut origin = vec![VertexId::INVALID; 2 * ne];
        let mut face = vec![FaceId::INVALID; 2 * ne];
        let mut vertex_halfedge = vec![HalfedgeId::INVALID; nv];
        let mut face_halfedge = vec![HalfedgeId::INVALID; nf];
        for h in self.halfedges() {
            let n = map.halfedge(h).idx();
            next[n] = map.halfedge(self.next(h));
            origin[n] = map.vertices[self.origin(h).idx()];
            face[n] = map.faces[self.face(h).idx()];
        }
        for v in self.vertices() {
            vertex_halfedge[map.vertices[v.idx()].idx()] = map.halfedge(self.vertex_halfedge(v));
        }
        for f in self.faces() {
            face_halfedge[map.faces[f.idx()].idx()] = map.halfedge(self.face_halfedge(f));
        }
        self.next = next;
        self.origin = origin;
        self.face = face;
        self.vertex_halfedge = vertex_halfedge;
        self.face_halfedge = face_halfedge;
    }
}
