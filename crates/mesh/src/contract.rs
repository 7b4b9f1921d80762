//! Edge contraction with the link condition, and its exact inverse, the vertex split.
//!
//! Contracting `h = u -> v` identifies v with u (Figure 7 of the irreducible-triangulations paper):
//! vertex v, edges `[u,v]`, `[v,x]`, `[v,y]` and faces `[u,v,x]`, `[u,v,y]` are removed (tombstoned);
//! edges `[u,x]` and `[u,y]` keep their ids. The returned [`Contraction`] is the record pushed on the
//! stack S of Algorithm 4.5, plus what [`SurfaceMesh::split_vertex`] needs to restore the mesh
//! exactly (same ids, same orientation, same stored half-edges).

use crate::error::EditError;
use crate::ids::{EdgeId, FaceId, HalfedgeId, VertexId};
use crate::topology::SurfaceMesh;

/// The record of one edge contraction; enough to undo it with [`SurfaceMesh::split_vertex`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Contraction {
    /// `u -> v` before the contraction (u kept, v removed).
    h: HalfedgeId,
    /// `v -> x`, `x -> u` (face `[u,v,x]`), `u -> y`, `y -> v` (face `[u,v,y]`).
    a: HalfedgeId,
    b: HalfedgeId,
    c: HalfedgeId,
    d: HalfedgeId,
    /// Stored half-edges of u, v, x, y before the contraction.
    vertex_halfedges: [HalfedgeId; 4],
    /// Stored half-edges of the faces `[u,v,x]`, `[u,v,y]` and of the faces across `[v,x]` and `[v,y]`.
    face_halfedges: [HalfedgeId; 4],
    vertices: [VertexId; 4],
    pub(crate) faces: [FaceId; 4],
}

impl Contraction {
    /// The kept vertex u.
    pub fn kept(&self) -> VertexId {
        self.vertices[0]
    }
    /// The removed vertex v.
    pub fn removed(&self) -> VertexId {
        self.vertices[1]
    }
    /// The two link vertices x and y of edge `[u, v]`.
    pub fn link(&self) -> [VertexId; 2] {
        [self.vertices[2], self.vertices[3]]
    }
    /// The contracted edge `[u, v]`.
    pub fn edge_uv(&self) -> EdgeId {
        self.h.edge()
    }
    /// The removed edges `[v, x]` and `[v, y]`.
    pub fn removed_edges(&self) -> [EdgeId; 2] {
        [self.a.edge(), self.d.edge()]
    }
    /// The surviving edges `[u, x]` and `[u, y]` ("split edges" of the quadrangulation paper, Alg. 3.2).
    pub fn split_edges(&self) -> [EdgeId; 2] {
        [self.b.edge(), self.c.edge()]
    }
    /// The removed faces `[u, v, x]` and `[u, v, y]`.
    pub fn removed_faces(&self) -> [FaceId; 2] {
        [self.faces[0], self.faces[1]]
    }
    /// The half-edge `u -> v` of the contracted edge, as it was.
    pub fn halfedge_uv(&self) -> HalfedgeId {
        self.h
    }
}

/// Reusable marks for link-condition tests (generation-stamped, so a test costs O(degree)).
#[derive(Clone, Debug, Default)]
pub struct LinkScratch {
    pub(crate) mark: Vec<u32>,
    stamp: u32,
}

impl LinkScratch {
    pub(crate) fn next_stamp(&mut self, slots: usize) -> u32 {
        if self.mark.len() < slots {
            self.mark.resize(slots, 0);
        }
        self.stamp = self.stamp.wrapping_add(1);
        if self.stamp == 0 {
            self.mark.fill(0);
            self.stamp = 1;
        }
        self.stamp
    }
}

impl SurfaceMesh {
    /// The link condition for the edge of `h = u -> v` in a simplicial mesh: the common neighbours
    /// of u and v are exactly the two vertices opposite the edge, and the mesh is not the
    /// tetrahedron. Contracting such an edge yields a simplicial triangulation of the same surface
    /// (Dey et al.; Section 2 of the irreducible-triangulations paper). O(deg u + deg v).
    pub fn satisfies_link_condition(&self, h: HalfedgeId, scratch: &mut LinkScratch) -> bool {
        if !self.is_edge_live(h.edge()) {
            return false;
        }
        let (u, v) = (self.origin(h), self.dest(h));
        let stamp = scratch.next_stamp(self.vertex_slots());
        let mut degree_u = 0usize;
        for w in self.neighbors(u) {
            scratch.mark[w.idx()] = stamp;
            degree_u += 1;
        }
        let mut common = 0usize;
        let mut degree_v = 0usize;
        for w in self.neighbors(v) {
            degree_v += 1;
            if scratch.mark[w.idx()] == stamp {
                common += 1;
            }
        }
        common == 2 && !(degree_u == 3 && degree_v == 3)
    }

    /// Contracts the edge of `h = u -> v` into u if it satisfies the link condition.
    ///
    /// # Errors
    /// [`EditError::NotContractible`] when the link condition fails (nothing changes).
    pub fn contract(
        &mut self,
        h: HalfedgeId,
        scratch: &mut LinkScratch,
    ) -> Result<Contraction, EditError> {
        if !self.satisfies_link_condition(h, scratch) {
            return Err(EditError::NotContractible(h.edge()));
        }
        Ok(self.contract_unchecked(h))
    }

    /// Contracts the edge of `h = u -> v` into u without testing the link condition; the caller
    /// guarantees it (algorithms that decide contractibility themselves, such as RS). O(deg v).
    ///
    /// What breaks when the link condition fails: if u and v have a common neighbour besides x and
    /// y (a separating triangle), or both have degree 3, the result is still a closed mesh of the
    /// same surface that passes [`Self::check_invariants`], but it has a multi-edge and is no
    /// longer simplicial; if the two faces of the edge share another edge (possible only on a
    /// mesh that is not simplicial), the half-edge structure is corrupted: `check_invariants`
    /// fails and later queries and edits may panic. `h` must be live (a removed half-edge
    /// panics or corrupts the mesh likewise).
    pub fn contract_unchecked(&mut self, h: HalfedgeId) -> Contraction {
        let t = h.twin();
        let (a, c) = (self.next(h), self.next(t));
        let (b, d) = (self.next(a), self.next(c));
        let (a2, d2) = (a.twin(), d.twin());
        let (u, v, x, y) = (
            self.origin(h),
            self.origin(t),
            self.origin(b),
            self.origin(d),
        );
        let (f0, f1, fa, fd) = (self.face(h), self.face(t), self.face(a2), self.face(d2));
        let record = Contraction {
            h,
            a,
            b,
            c,
            d,
            vertex_halfedges: [u, v, x, y].map(|w| self.vertex_halfedge(w)),
            face_halfedges: [f0, f1, fa, fd].map(|f| self.face_halfedge(f)),
            vertices: [u, v, x, y],
            faces: [f0, f1, fa, fd],
        };
        // v's surviving outgoing half-edges, from rotate(d2) up to (excluding) a, now leave u.
        let mut k = self.rotate(d2);
        while k != a {
            self.origin[k.idx()] = u;
            k = self.rotate(k);
        }
        // b = x -> u takes the place of a2 = x -> v; c = u -> y takes the place of d2 = v -> y.
        self.replace_in_face(a2, b);
        self.replace_in_face(d2, c);
        self.vertex_halfedge[u.idx()] = c;
        self.vertex_halfedge[x.idx()] = b;
        self.vertex_halfedge[y.idx()] = c.twin();
        self.vertex_halfedge[v.idx()] = HalfedgeId::INVALID;
        if self.face_halfedge[fa.idx()] == a2 {
            self.face_halfedge[fa.idx()] = b;
        }
        if self.face_halfedge[fd.idx()] == d2 {
            self.face_halfedge[fd.idx()] = c;
        }
        self.face_halfedge[f0.idx()] = HalfedgeId::INVALID;
        self.face_halfedge[f1.idx()] = HalfedgeId::INVALID;
        for r in [h, t, a, a2, d, d2] {
            self.origin[r.idx()] = VertexId::INVALID;
        }
        self.live_vertices -= 1;
        self.live_edges -= 3;
        self.live_faces -= 2;
        record
    }

    /// Puts `new` where `old` is in old's (triangular) face.
    fn replace_in_face(&mut self, old: HalfedgeId, new: HalfedgeId) {
        let (n, p) = (self.next(old), self.prev(old));
        self.next[p.idx()] = new;
        self.next[new.idx()] = n;
        self.face[new.idx()] = self.face(old);
    }

    /// Undoes a contraction exactly: the mesh becomes identical (ids, orientation, stored
    /// half-edges) to the one before [`Self::contract`]. Contractions must be undone in reverse
    /// order (last in, first out). O(deg v).
    ///
    /// Edges may be flipped between contractions and splits (the LRS expansion of the
    /// quadrangulation paper does), as long as the split edges `[u,x]` and `[u,y]` of pending
    /// records are not flipped: v then takes the half-edges between `[u,y]` and `[u,x]` in the
    /// current rotation at u, and the result is a valid triangulation (no longer identical to the
    /// one before the contraction).
    pub fn split_vertex(&mut self, record: &Contraction) {
        let Contraction { h, a, b, c, d, .. } = *record;
        let t = h.twin();
        let (a2, d2) = (a.twin(), d.twin());
        let [u, v, x, y] = record.vertices;
        let [f0, f1, _, _] = record.faces;
        // The faces that b and c are in now (flips since the contraction may have moved them).
        let (fa, fd) = (self.face(b), self.face(c));
        // v's fan is the rotation at u strictly between c and b's twin.
        let mut k = self.rotate(c);
        while k != b.twin() {
            self.origin[k.idx()] = v;
            k = self.rotate(k);
        }
        self.replace_in_face(c, d2);
        self.replace_in_face(b, a2);
        for (face, [p, q, r]) in [(f0, [h, a, b]), (f1, [t, c, d])] {
            self.next[p.idx()] = q;
            self.next[q.idx()] = r;
            self.next[r.idx()] = p;
            for s in [p, q, r] {
                self.face[s.idx()] = face;
            }
        }
        for (s, o) in [
            (h, u),
            (t, v),
            (a, v),
            (a2, x),
            (b, x),
            (c, u),
            (d, y),
            (d2, v),
        ] {
            self.origin[s.idx()] = o;
        }
        // The stored half-edges as they were, unless flips made since the contraction moved them:
        // then the split's own half-edges (`h`, `t`, `b`, `d` leave u, v, x, y; `h`, `t`, `a2`, `d2`
        // bound the four faces). Without intervening flips the restoration is exact.
        let leaves = |mesh: &Self, s: HalfedgeId, w: VertexId| mesh.origin[s.idx()] == w;
        for ((w, s), own) in [u, v, x, y]
            .into_iter()
            .zip(record.vertex_halfedges)
            .zip([h, t, b, d])
        {
            self.vertex_halfedge[w.idx()] = if leaves(self, s, w) { s } else { own };
        }
        for ((f, s), own) in [fd, fa, f1, f0]
            .into_iter()
            .zip([3, 2, 1, 0].map(|i| record.face_halfedges[i]))
            .zip([d2, a2, t, h])
        {
            let bounds = self.origin[s.idx()].is_valid() && self.face[s.idx()] == f;
            self.face_halfedge[f.idx()] = if bounds { s } else { own };
        }
        self.live_vertices += 1;
        self.live_edges += 3;
        self.live_faces += 2;
    }

    /// Splits vertex u into u and a new vertex v (the inverse of a contraction, with fresh ids):
    /// the outgoing half-edges strictly between `to_y = u -> y` and `to_x = u -> x` in rotation order
    /// move to v; new edges `[u,v]`, `[v,x]`, `[v,y]` and faces `[u,v,x]`, `[u,v,y]` are created.
    /// Returns the record whose [`Self::split_vertex`] would redo this split after a contraction.
    ///
    /// # Errors
    /// [`EditError::NotLive`] when the half-edges are not two distinct live outgoing half-edges of
    /// the same vertex with distinct destinations.
    pub fn split_vertex_new(
        &mut self,
        to_y: HalfedgeId,
        to_x: HalfedgeId,
    ) -> Result<Contraction, EditError> {
        let ok = to_y != to_x
            && self.is_edge_live(to_y.edge())
            && self.is_edge_live(to_x.edge())
            && self.origin(to_y) == self.origin(to_x)
            && self.dest(to_y) != self.dest(to_x);
        if !ok {
            return Err(EditError::NotLive(format!(
                "split of {to_y:?} and {to_x:?}"
            )));
        }
        let (u, x, y) = (self.origin(to_y), self.dest(to_x), self.dest(to_y));
        let v = VertexId::new(self.vertex_slots());
        let e0 = self.edge_slots();
        let (h, a, d) = (
            EdgeId::new(e0).halfedge(),
            EdgeId::new(e0 + 1).halfedge(),
            EdgeId::new(e0 + 2).halfedge().twin(),
        );
        let (f0, f1) = (
            FaceId::new(self.face_slots()),
            FaceId::new(self.face_slots() + 1),
        );
        self.next.resize(self.next.len() + 6, HalfedgeId::INVALID);
        self.origin.resize(self.origin.len() + 6, VertexId::INVALID);
        self.face.resize(self.face.len() + 6, FaceId::INVALID);
        self.vertex_halfedge.push(HalfedgeId::INVALID);
        self.face_halfedge.extend([HalfedgeId::INVALID; 2]);
        let (b, c) = (to_x.twin(), to_y);
        let (fa, fd) = (self.face(b), self.face(c));
        // b moves to face [u,v,x] and c to [u,v,y]: faces that stored them store their replacements.
        let stored = |s: HalfedgeId| match s {
            s if s == b => a.twin(),
            s if s == c => d.twin(),
            s => s,
        };
        let record = Contraction {
            h,
            a,
            b,
            c,
            d,
            vertex_halfedges: [h, h.twin(), b, d],
            face_halfedges: [
                h,
                h.twin(),
                stored(self.face_halfedge(fa)),
                stored(self.face_halfedge(fd)),
            ],
            vertices: [u, v, x, y],
            faces: [f0, f1, fa, fd],
        };
        self.split_vertex(&record);
        Ok(record)
    }
}
