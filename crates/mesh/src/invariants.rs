//! Structural self-check, for tests and debug builds.

use crate::error::InvariantError;
use crate::ids::{FaceId, HalfedgeId};
use crate::topology::SurfaceMesh;

macro_rules! ensure {
    ($cond:expr, $($arg:tt)*) => {
        if !$cond {
            return Err(InvariantError(format!($($arg)*)));
        }
    };
}

impl SurfaceMesh {
    /// Checks every structural invariant: array sizes; for each live half-edge, a live twin,
    /// `next` cycling in three steps within one live face, `origin(next(h)) == dest(h)`; stored
    /// face and vertex half-edges live and incident; every vertex's outgoing half-edges forming one
    /// rotation (a closed manifold); live counts. O(n).
    ///
    /// # Errors
    /// The first violated invariant, described.
    pub fn check_invariants(&self) -> Result<(), InvariantError> {
        let nh = self.next.len();
        ensure!(nh.is_multiple_of(2), "odd half-edge count {nh}");
        ensure!(
            self.origin.len() == nh && self.face.len() == nh,
            "half-edge arrays differ in length"
        );
        let mut outgoing = vec![0u32; self.vertex_slots()];
        let mut live_halfedges = 0usize;
        for h in self.halfedges() {
            live_halfedges += 1;
            let t = h.twin();
            ensure!(
                self.origin(t).is_valid(),
                "{h:?} live but its twin is removed"
            );
            let n = self.next(h);
            ensure!(
                n.idx() < nh && self.origin(n).is_valid(),
                "{h:?}: next {n:?} not live"
            );
            ensure!(
                self.next(self.next(n)) == h,
                "{h:?}: face is not a triangle"
            );
            ensure!(self.face(n) == self.face(h), "{h:?}: next in another face");
            ensure!(
                self.origin(n) == self.dest(h),
                "{h:?}: origin(next) != dest"
            );
            let f = self.face(h);
            ensure!(self.is_face_live(f), "{h:?}: face {f:?} not live");
            let v = self.origin(h);
            ensure!(self.is_vertex_live(v), "{h:?}: origin {v:?} not live");
            outgoing[v.idx()] += 1;
        }
        ensure!(live_halfedges == 2 * self.live_edges, "live edge count");
        let mut faces = 0usize;
        for f in (0..self.face_slots())
            .map(FaceId::new)
            .filter(|&f| self.is_face_live(f))
        {
            faces += 1;
            let h = self.face_halfedge(f);
            ensure!(
                h.idx() < nh && self.origin(h).is_valid() && self.face(h) == f,
                "face {f:?}: stored half-edge {h:?} not in it"
            );
        }
        ensure!(faces == self.live_faces, "live face count");
        ensure!(3 * faces == live_halfedges, "3F != 2E");
        let mut vertices = 0usize;
        for v in self.vertices() {
            vertices += 1;
            let h: HalfedgeId = self.vertex_halfedge(v);
            ensure!(
                h.idx() < nh && self.origin(h) == v,
                "vertex {v:?}: stored half-edge {h:?} does not leave it"
            );
            let mut ring = 0u32;
            for _ in self.outgoing(v) {
                ring += 1;
                ensure!(
                    ring <= outgoing[v.idx()],
                    "vertex {v:?}: rotation does not close"
                );
            }
            ensure!(
                ring == outgoing[v.idx()],
                "vertex {v:?}: {} outgoing half-edges but one rotation has {ring} (not a single fan)",
                outgoing[v.idx()]
            );
        }
        ensure!(vertices == self.live_vertices, "live vertex count");
        Ok(())
    }
}
