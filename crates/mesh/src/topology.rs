//! The half-edge surface mesh: topology only, no geometry.

use crate::ids::{EdgeId, FaceId, HalfedgeId, VertexId};

/// A triangulated closed surface as an index-based half-edge structure (struct of arrays).
///
/// Half-edges are stored in pairs (`twin(h) = h ^ 1`), so an edge id is stable under flips.
/// Every face is a triangle. Loops and multi-edges are representable (intrinsic triangulations
/// need them); [`SurfaceMesh::is_simplicial`] tells whether the mesh is a simplicial complex.
/// Removed elements are tombstones until [`SurfaceMesh::compact`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SurfaceMesh {
    /// Next half-edge counter-clockwise in the same face, per half-edge.
    pub(crate) next: Vec<HalfedgeId>,
    /// Origin vertex per half-edge (`INVALID` marks a removed half-edge).
    pub(crate) origin: Vec<VertexId>,
    /// Face to the left of each half-edge.
    pub(crate) face: Vec<FaceId>,
    /// One outgoing half-edge per vertex (`INVALID` marks a removed vertex).
    pub(crate) vertex_halfedge: Vec<HalfedgeId>,
    /// One half-edge per face (`INVALID` marks a removed face).
    pub(crate) face_halfedge: Vec<HalfedgeId>,
    pub(crate) live_vertices: usize,
    pub(crate) live_edges: usize,
    pub(crate) live_faces: usize,
}

impl SurfaceMesh {
    /// Number of live vertices.
    #[inline]
    pub fn vertex_count(&self) -> usize {
        self.live_vertices
    }
    /// Number of live edges.
    #[inline]
    pub fn edge_count(&self) -> usize {
        self.live_edges
    }
    /// Number of live faces.
    #[inline]
    pub fn face_count(&self) -> usize {
        self.live_faces
    }
    /// Size of the vertex id range (live and removed), for per-vertex arrays.
    #[inline]
    pub fn vertex_slots(&self) -> usize {
        self.vertex_halfedge.len()
    }
    /// Size of the edge id range (live and removed), for per-edge arrays.
    #[inline]
    pub fn edge_slots(&self) -> usize {
        self.next.len() / 2
    }
    /// Size of the half-edge id range.
    #[inline]
    pub fn halfedge_slots(&self) -> usize {
        self.next.len()
    }
    /// Size of the face id range (live and removed), for per-face arrays.
    #[inline]
    pub fn face_slots(&self) -> usize {
        self.face_halfedge.len()
    }

    /// Whether the vertex id is live.
    #[inline]
    pub fn is_vertex_live(&self, v: VertexId) -> bool {
        self.vertex_halfedge
            .get(v.idx())
            .is_some_and(|h| h.is_valid())
    }
    /// Whether the edge id is live.
    #[inline]
    pub fn is_edge_live(&self, e: EdgeId) -> bool {
        self.origin
            .get(e.halfedge().idx())
            .is_some_and(|v| v.is_valid())
    }
    /// Whether the face id is live.
    #[inline]
    pub fn is_face_live(&self, f: FaceId) -> bool {
        self.face_halfedge
            .get(f.idx())
            .is_some_and(|h| h.is_valid())
    }

    /// Next half-edge in the same face.
    #[inline(always)]
    pub fn next(&self, h: HalfedgeId) -> HalfedgeId {
        self.next[h.idx()]
    }
    /// Previous half-edge in the same face (faces are triangles).
    #[inline(always)]
    pub fn prev(&self, h: HalfedgeId) -> HalfedgeId {
        self.next(self.next(h))
    }
    /// Origin vertex of a half-edge.
    #[inline(always)]
    pub fn origin(&self, h: HalfedgeId) -> VertexId {
        self.origin[h.idx()]
    }
    /// Destination vertex of a half-edge.
    #[inline(always)]
    pub fn dest(&self, h: HalfedgeId) -> VertexId {
        self.origin[h.twin().idx()]
    }
    /// Face to the left of a half-edge.
    #[inline(always)]
    pub fn face(&self, h: HalfedgeId) -> FaceId {
        self.face[h.idx()]
    }
    /// The face of every half-edge slot, by half-edge id (a half-edge and its twin are
    /// `2e` and `2e + 1`, edge `e`'s), as stored: a read-only view for sequential passes over
    /// the edges. Removed half-edges hold [`FaceId::INVALID`] or the stale face of their last
    /// use, so a caller must skip them (by [`Self::is_edge_live`]) whenever the mesh has
    /// tombstones; the view is the mesh's own and changes with the next edit.
    #[inline]
    pub fn halfedge_faces(&self) -> &[FaceId] {
        &self.face
    }
    /// One outgoing half-edge of a vertex.
    #[inline(always)]
    pub fn vertex_halfedge(&self, v: VertexId) -> HalfedgeId {
        self.vertex_halfedge[v.idx()]
    }
    /// One half-edge of a face.
    #[inline(always)]
    pub fn face_halfedge(&self, f: FaceId) -> HalfedgeId {
        self.face_halfedge[f.idx()]
    }
    /// The two endpoints of an edge (origin and destination of its first half-edge).
    #[inline]
    pub fn edge_vertices(&self, e: EdgeId) -> [VertexId; 2] {
        let h = e.halfedge();
        [self.origin(h), self.dest(h)]
    }
    /// The three half-edges of a face, starting at its stored half-edge.
    #[inline]
    pub fn face_halfedges(&self, f: FaceId) -> [HalfedgeId; 3] {
        let h0 = self.face_halfedge(f);
        let h1 = self.next(h0);
        [h0, h1, self.next(h1)]
    }
    /// The three corners of a face, counter-clockwise.
    #[inline]
    pub fn face_vertices(&self, f: FaceId) -> [VertexId; 3] {
        self.face_halfedges(f).map(|h| self.origin(h))
    }
    /// The vertex opposite a half-edge in its face: `dest(next(h))`, one read into a random place
    /// of the mesh where `origin(prev(h))` takes two dependent ones.
    #[inline]
    pub fn opposite_vertex(&self, h: HalfedgeId) -> VertexId {
        self.dest(self.next(h))
    }

    /// The next outgoing half-edge around `origin(h)` (clockwise rotation: `twin(prev(h))`).
    #[inline(always)]
    pub fn rotate(&self, h: HalfedgeId) -> HalfedgeId {
        self.prev(h).twin()
    }

    /// Outgoing half-edges of `v`, allocation-free.
    #[inline]
    pub fn outgoing(&self, v: VertexId) -> Outgoing<'_> {
        let start = self.vertex_halfedge(v);
        Outgoing {
            mesh: self,
            start,
            current: start,
        }
    }
    /// Neighbouring vertices of `v` (with repetitions if there are multi-edges or loops).
    #[inline]
    pub fn neighbors(&self, v: VertexId) -> impl Iterator<Item = VertexId> + '_ {
        self.outgoing(v).map(|h| self.dest(h))
    }
    /// Number of outgoing half-edges of `v` (its degree; a loop counts twice).
    #[inline]
    pub fn degree(&self, v: VertexId) -> usize {
        self.outgoing(v).count()
    }

    /// Live vertex ids.
    pub fn vertices(&self) -> impl Iterator<Item = VertexId> + '_ {
        (0..self.vertex_slots())
            .map(VertexId::new)
            .filter(|&v| self.is_vertex_live(v))
    }
    /// Live edge ids.
    pub fn edges(&self) -> impl Iterator<Item = EdgeId> + '_ {
        (0..self.edge_slots())
            .map(EdgeId::new)
            .filter(|&e| self.is_edge_live(e))
    }
    /// Live face ids.
    pub fn faces(&self) -> impl Iterator<Item = FaceId> + '_ {
        (0..self.face_slots())
            .map(FaceId::new)
            .filter(|&f| self.is_face_live(f))
    }
    /// Live half-edge ids.
    pub fn halfedges(&self) -> impl Iterator<Item = HalfedgeId> + '_ {
        (0..self.halfedge_slots())
            .map(HalfedgeId::new)
            .filter(|&h| self.origin(h).is_valid())
    }

    /// Euler characteristic `V - E + F`.
    pub fn euler_characteristic(&self) -> i64 {
        self.live_vertices as i64 - self.live_edges as i64 + self.live_faces as i64
    }
    /// Genus `(2 - χ) / 2` of the (closed, orientable, connected) surface.
    pub fn genus(&self) -> i64 {
        (2 - self.euler_characteristic()) / 2
    }

    /// Whether the mesh is a simplicial complex: no loops, no multi-edges, and no two faces on the
    /// same three vertices (for a closed connected surface this excludes only the two-triangle sphere).
    ///
    /// O(E) time, one scratch array of size V.
    pub fn is_simplicial(&self) -> bool {
        if self.live_faces <= 2 {
            return false;
        }
        let mut mark = vec![VertexId::INVALID; self.vertex_slots()];
        for v in self.vertices() {
            for w in self.neighbors(v) {
                if w == v || mark[w.idx()] == v {
                    return false;
                }
                mark[w.idx()] = v;
            }
        }
        true
    }
}

/// Iterator over the outgoing half-edges of a vertex (see [`SurfaceMesh::outgoing`]).
#[derive(Clone)]
pub struct Outgoing<'a> {
    mesh: &'a SurfaceMesh,
    start: HalfedgeId,
    current: HalfedgeId,
}

impl Iterator for Outgoing<'_> {
    type Item = HalfedgeId;
    #[inline]
    fn next(&mut self) -> Option<HalfedgeId> {
        if !self.current.is_valid() {
            return None;
        }
        let h = self.current;
        let n = self.mesh.rotate(h);
        self.current = if n == self.start {
            HalfedgeId::INVALID
        } else {
            n
        };
        Some(h)
    }
}
