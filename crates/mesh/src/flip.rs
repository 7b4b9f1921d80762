//! Edge flip (check-then-edit pair), O(1).

use crate::error::EditError;
use crate::ids::EdgeId;
use crate::topology::SurfaceMesh;

impl SurfaceMesh {
    /// Whether `e` can be flipped at all: it is live and its two sides are different faces.
    /// The result may have loops or multi-edges (allowed for intrinsic triangulations).
    #[inline]
    pub fn can_flip(&self, e: EdgeId) -> bool {
        let h = e.halfedge();
        self.is_edge_live(e) && self.face(h) != self.face(h.twin())
    }

    /// Whether flipping `e` keeps a simplicial mesh simplicial (Definition 3.3 of the
    /// quadrangulation paper: "flippable"): both endpoints have degree above 3 and the two opposite
    /// vertices are distinct and not yet adjacent. O(degree).
    pub fn can_flip_simplicial(&self, e: EdgeId) -> bool {
        if !self.can_flip(e) {
            return false;
        }
        let h = e.halfedge();
        let (a, b) = (self.origin(h), self.dest(h));
        let (c, d) = (self.opposite_vertex(h), self.opposite_vertex(h.twin()));
        if c == d || self.degree(a) <= 3 || self.degree(b) <= 3 {
            return false;
        }
        let (small, other) = if self.degree(c) <= self.degree(d) {
            (c, d)
        } else {
            (d, c)
        };
        !self.neighbors(small).any(|w| w == other)
    }

    /// Flips edge `e`: the two triangles (a, b, c) and (b, a, d) on either side become (d, c, a) and
    /// (c, d, b). The edge keeps its id; the new edge joins c and d.
    ///
    /// # Errors
    /// [`EditError::NotFlippable`] when [`Self::can_flip`] is false (nothing changes).
    pub fn flip(&mut self, e: EdgeId) -> Result<(), EditError> {
        if !self.can_flip(e) {
            return Err(EditError::NotFlippable(e));
        }
        let h = e.halfedge();
        let t = h.twin();
        let (h1, t1) = (self.next(h), self.next(t));
        let (h2, t2) = (self.next(h1), self.next(t1));
        let (f0, f1) = (self.face(h), self.face(t));
        let (a, b) = (self.origin(h), self.origin(t));
        let (c, d) = (self.origin(h2), self.origin(t2));
        self.next[h.idx()] = h2;
        self.next[h2.idx()] = t1;
        self.next[t1.idx()] = h;
        self.next[t.idx()] = t2;
        self.next[t2.idx()] = h1;
        self.next[h1.idx()] = t;
        self.origin[h.idx()] = d;
        self.origin[t.idx()] = c;
        self.face[t1.idx()] = f0;
        self.face[h1.idx()] = f1;
        self.face_halfedge[f0.idx()] = h;
        self.face_halfedge[f1.idx()] = t;
        if self.vertex_halfedge[a.idx()] == h {
            self.vertex_halfedge[a.idx()] = t1;
        }
        if self.vertex_halfedge[b.idx()] == t {
            self.vertex_halfedge[b.idx()] = h1;
        }
        Ok(())
    }
}
