//! Every compact surface as a closed oriented mesh that covers it.
//!
//! [`SurfaceMesh`] is a closed oriented half-edge structure, and everything built on it (rotation
//! around a vertex, flips, contractions and their exact inverse, compaction) relies on that. A
//! triangulated surface K may instead have boundary loops, no orientation, several components.
//! [`ClosedCover`] represents K by a closed oriented mesh D and a [`Lifting`] that says how D's
//! vertices and half-edges stand for K's:
//!
//! - **Boundary loops are closed by cones.** Each boundary loop gets an *apex* vertex joined to
//!   its vertices by one cone triangle per boundary edge (Dey, Edelsbrunner, Guha and Nekhayev's
//!   construction; one apex per loop keeps the result a 2-manifold). The apexes are not vertices
//!   of K, their edges and triangles are not K's, and all apexes form one vertex class: with them
//!   identified into a single vertex ω, an edge of K contracts keeping the topology iff the link
//!   condition holds in the coned complex (Dey et al., Theorem 2; see [`satisfies_link_condition`]).
//! - **Non-orientable components are doubled.** Such a component is replaced by its orientable
//!   double cover: every face appears twice, with both orientations, and every vertex has two
//!   lifts (one per orientation of its star). The *mirror* of a half-edge is the half-edge on the
//!   same side of the other copy of its face; it is an involution that contractions keep (the
//!   surviving half-edges keep their ids), so an edit of K is the same edit made on both lifts.
//!   Orientable components, with or without boundary, are not doubled.
//!
//! A closed orientable surface is its own cover ([`ClosedCover::is_plain`]): no apex, no mirror,
//! vertex classes the identity, so the algorithms that take a [`Lifting`] run, monomorphised with
//! [`Plain`], exactly the code they ran on a [`SurfaceMesh`].
//!
//! Vertex ids of D: the surface's vertices keep theirs (one lift each), the apexes follow, then
//! the second lifts of the doubled vertices. Classes: the surface's vertex ids, then the apex
//! class, then the vertices that edits (vertex splits) add. Face ids: the surface's faces keep
//! theirs, the cone faces follow, then the mirror copies.

mod build;
mod edit;
mod surface;
mod twisted;

pub use edit::{contract_lifts, flip_lifts, satisfies_link_condition, split_lifts};
pub use surface::CoveredSurface;
pub use twisted::{TwistedCover, TwistedGluing};

use crate::compact::Renumbering;
use crate::ids::{EdgeId, FaceId, HalfedgeId, VertexId};
use crate::topology::SurfaceMesh;

/// How the vertices and half-edges of a closed oriented mesh stand for those of the surface it
/// covers (see the [module documentation](self)).
pub trait Lifting {
    /// The surface vertex a mesh vertex stands for: a class in `0..class_count()`; every apex
    /// is in [`Self::apex_class`].
    fn class(&self, v: VertexId) -> u32;
    /// The number of classes: surface vertex ids (input ids first, then vertices made by
    /// edits), and one for the apexes when there are any.
    fn class_count(&self) -> usize;
    /// The class of the apexes, if the surface has boundary loops.
    fn apex_class(&self) -> Option<u32>;
    /// The other lift of a half-edge of a doubled (non-orientable) component.
    fn mirror(&self, h: HalfedgeId) -> Option<HalfedgeId>;
    /// A mesh vertex standing for class `c` (its first lift; the first apex for the apex class).
    fn lift(&self, c: u32) -> VertexId;
    /// Whether some component is doubled (else [`Self::mirror`] is always `None`).
    fn doubled(&self) -> bool;
    /// Whether a mesh vertex is an apex.
    #[inline]
    fn is_apex(&self, v: VertexId) -> bool {
        self.apex_class() == Some(self.class(v))
    }
    /// One id per edge of the surface: the smaller of an edge's and its mirror's.
    #[inline]
    fn edge_key(&self, e: EdgeId) -> EdgeId {
        match self.mirror(e.halfedge()) {
            Some(m) => e.min(m.edge()),
            None => e,
        }
    }
}

/// The lifting of a closed orientable surface by itself: classes are vertex ids, no apex, no
/// mirror.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Plain {
    /// The mesh's vertex slots.
    pub slots: usize,
}

impl Lifting for Plain {
    #[inline(always)]
    fn class(&self, v: VertexId) -> u32 {
        v.0
    }
    #[inline(always)]
    fn class_count(&self) -> usize {
        self.slots
    }
    #[inline(always)]
    fn apex_class(&self) -> Option<u32> {
        None
    }
    #[inline(always)]
    fn mirror(&self, _: HalfedgeId) -> Option<HalfedgeId> {
        None
    }
    #[inline(always)]
    fn lift(&self, c: u32) -> VertexId {
        VertexId(c)
    }
    #[inline(always)]
    fn doubled(&self) -> bool {
        false
    }
    #[inline(always)]
    fn is_apex(&self, _: VertexId) -> bool {
        false
    }
    #[inline(always)]
    fn edge_key(&self, e: EdgeId) -> EdgeId {
        e
    }
}

/// The lifting of a [`ClosedCover`]: vertex classes, apexes and mirrors as tables.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Sheets {
    /// Class of each mesh vertex slot.
    class: Vec<u32>,
    /// First lift of each class.
    lift: Vec<VertexId>,
    /// Mirror of each half-edge slot (`INVALID` outside doubled components); empty when no
    /// component is doubled.
    mirror: Vec<HalfedgeId>,
    /// The apex class (= the number of surface vertex ids), when there are apexes.
    apex: Option<u32>,
}

impl Lifting for Sheets {
    #[inline]
    fn class(&self, v: VertexId) -> u32 {
        self.class[v.idx()]
    }
    #[inline]
    fn class_count(&self) -> usize {
        self.lift.len()
    }
    #[inline]
    fn apex_class(&self) -> Option<u32> {
        self.apex
    }
    #[inline]
    fn mirror(&self, h: HalfedgeId) -> Option<HalfedgeId> {
        self.mirror.get(h.idx()).copied().filter(|m| m.is_valid())
    }
    #[inline]
    fn lift(&self, c: u32) -> VertexId {
        self.lift[c as usize]
    }
    #[inline]
    fn doubled(&self) -> bool {
        !self.mirror.is_empty()
    }
}

impl Sheets {
    /// The lifting of a closed orientable mesh of `slots` vertex slots by itself.
    fn identity(slots: usize) -> Self {
        Sheets {
            class: (0..slots as u32).collect(),
            lift: (0..slots as u32).map(VertexId).collect(),
            mirror: Vec::new(),
            apex: None,
        }
    }
    /// Whether some component is doubled.
    pub fn has_mirror(&self) -> bool {
        !self.mirror.is_empty()
    }
    /// A new surface vertex class with the given lifts (two for a doubled component); returns
    /// the class (appended after every other, the apex class included).
    pub(crate) fn push_class(&mut self, lifts: &[VertexId]) -> u32 {
        let c = self.lift.len() as u32;
        for &v in lifts {
            if self.class.len() <= v.idx() {
                self.class.resize(v.idx() + 1, u32::MAX);
            }
            self.class[v.idx()] = c;
        }
        self.lift.push(lifts[0]);
        c
    }
    /// Sets the mirror of two half-edges (each the other's).
    pub(crate) fn set_mirror(&mut self, h: HalfedgeId, m: HalfedgeId) {
        let need = h.idx().max(m.idx()) + 1;
        if self.mirror.len() < need {
            self.mirror.resize(need, HalfedgeId::INVALID);
        }
        self.mirror[h.idx()] = m;
        self.mirror[m.idx()] = h;
    }
}

/// A compact triangulated surface (boundary loops, non-orientable and several components
/// allowed) as a closed oriented mesh that covers it (see the [module documentation](self)).
#[derive(Clone, Debug, PartialEq)]
pub struct ClosedCover {
    /// The closed oriented mesh D.
    pub mesh: SurfaceMesh,
    /// How D stands for the surface.
    pub sheets: Sheets,
}

impl ClosedCover {
    /// A closed orientable mesh as its own cover.
    pub fn plain(mesh: SurfaceMesh) -> Self {
        let sheets = Sheets::identity(mesh.vertex_slots());
        ClosedCover { mesh, sheets }
    }

    /// Whether the surface is closed and orientable, so that the mesh is the surface itself.
    pub fn is_plain(&self) -> bool {
        self.sheets.apex.is_none() && self.sheets.mirror.is_empty()
    }

    /// The class of a vertex (see [`Lifting::class`]).
    #[inline]
    pub fn class(&self, v: VertexId) -> u32 {
        self.sheets.class(v)
    }

    /// Whether a live face is a face of the surface: not a cone face, and the first of its
    /// mirror pair (the one with the smaller id) when its component is doubled.
    pub fn is_surface_face(&self, f: FaceId) -> bool {
        let h = self.mesh.face_halfedge(f);
        let primary = self.sheets.mirror(h).is_none_or(|m| f <= self.mesh.face(m));
        primary
            && self
                .mesh
                .face_vertices(f)
                .iter()
                .all(|&v| !self.sheets.is_apex(v))
    }

    /// The live faces of the surface (see [`Self::is_surface_face`]), in id order.
    pub fn surface_faces(&self) -> impl Iterator<Item = FaceId> + '_ {
        self.mesh.faces().filter(|&f| self.is_surface_face(f))
    }

    /// The surface's triangles in vertex classes, in face id order (corners in the order of the
    /// face's first lift; a non-orientable component has no consistent order).
    pub fn surface_triangles(&self) -> Vec<[u32; 3]> {
        self.surface_faces()
            .map(|f| self.mesh.face_vertices(f).map(|v| self.class(v)))
            .collect()
    }

    /// The number of live surface vertices (classes with a live lift, apexes excluded).
    pub fn surface_vertex_count(&self) -> usize {
        let mut seen = vec![false; self.sheets.class_count()];
        self.mesh
            .vertices()
            .filter(|&v| !self.sheets.is_apex(v))
            .filter(|&v| !std::mem::replace(&mut seen[self.class(v) as usize], true))
            .count()
    }

    /// Removes the mesh's tombstones ([`SurfaceMesh::compact`]) and renumbers the tables to
    /// match; classes keep their ids, but those of a plain cover, which are its vertex ids.
    /// Returns the mesh's old-to-new maps. O(n).
    pub fn compact(&mut self) -> Renumbering {
        let plain = self.is_plain();
        let map = self.mesh.compact();
        if plain {
            self.sheets = Sheets::identity(self.mesh.vertex_slots());
            return map;
        }
        let sheets = &mut self.sheets;
        let mut class = vec![u32::MAX; self.mesh.vertex_slots()];
        for (old, new) in map.vertices.iter().enumerate() {
            if new.is_valid() {
                class[new.idx()] = sheets.class[old];
            }
        }
        sheets.class = class;
        for l in sheets.lift.iter_mut() {
            *l = VertexId::INVALID;
        }
        for v in self.mesh.vertices() {
            let l = &mut sheets.lift[sheets.class[v.idx()] as usize];
            if !l.is_valid() {
                *l = v;
            }
        }
        if !sheets.mirror.is_empty() {
            let mut mirror = vec![HalfedgeId::INVALID; self.mesh.halfedge_slots()];
            for (old, &m) in sheets.mirror.iter().enumerate() {
                let new = map.halfedge(HalfedgeId::new(old));
                if new.is_valid() && m.is_valid() {
                    mirror[new.idx()] = map.halfedge(m);
                }
            }
            sheets.mirror = mirror;
        }
        map
    }

    /// Renumbers the classes densely, in their order, dropping those without a live vertex;
    /// returns the old-to-new class map (`u32::MAX` for dropped classes). O(n).
    pub fn compact_classes(&mut self) -> Vec<u32> {
        let sheets = &mut self.sheets;
        let mut map = vec![u32::MAX; sheets.lift.len()];
        let mut lift = Vec::new();
        for (c, &l) in sheets.lift.iter().enumerate() {
            if l.is_valid() && self.mesh.is_vertex_live(l) {
                map[c] = lift.len() as u32;
                lift.push(l);
            }
        }
        for v in self.mesh.vertices() {
            sheets.class[v.idx()] = map[sheets.class[v.idx()] as usize];
        }
        sheets.apex = sheets.apex.map(|a| map[a as usize]);
        sheets.lift = lift;
        map
    }
}
