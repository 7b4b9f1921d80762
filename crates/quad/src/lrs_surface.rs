//! LRS on compact surfaces other than one closed orientable piece.
//!
//! LRS (Section 3.3 of the quadrangulation paper) contracts the triangulation to an irreducible
//! one (Ramaswami–Siqueira) and expands it back while pairing and flipping (Algorithm 3.1), on a
//! closed orientable surface. What we do elsewhere (ours; the paper treats closed orientable
//! surfaces only):
//!
//! - **Orientable pieces, closed or with boundary, several pieces**: the contraction runs on the
//!   surface's cover, as `surftopo irreducible` does (`surftopo_irreducible::reduce_surface`:
//!   Ramaswami–Siqueira with Dey, Edelsbrunner, Guha and Nekhayev's link condition, the boundary
//!   loops closed by cones over apexes that are never contracted), and Algorithm 3.1 replays its
//!   history backwards on the cover's mesh ([`crate::lrs::expand_guarded`]) with one change: a
//!   step that would flip an edge with an end on the boundary (or on a cone), or pair a triangle
//!   with a cone triangle, is skipped (its triangles stay unpaired). Every flip is then inside the
//!   surface and leaves the triangles with a boundary side as they are: K, the flipped
//!   triangulation, is a triangulation of the same surface on the same vertices with the same
//!   boundary triangles. The augmenting paths that follow reach a maximum pairing of K. The
//!   paper's bound on the triangles left (`max(4, 56g − 12)`, Proposition 3.3) is not claimed:
//!   the skipped steps leave more near the boundary (about 1% of the triangles on pieces of a few
//!   thousand with short boundary loops, 20% on pieces of 200). The maximum is K's: flips change
//!   the dual, and on a small piece K may leave more triangles than the input would (a 31-triangle
//!   disk: 3 where 1 is the input's least; on pieces of a few hundred triangles and more the
//!   tests find the same count); `deficiency_lower_bound` is then K's.
//! - **Non-orientable pieces are refused** (with a typed error naming the piece): the expansion's
//!   flips would have to be made on both sheets of the cover, where neither the case analysis
//!   of Algorithms 3.2–3.4 (stated for one oriented vertex split) nor the argument that K stays
//!   simplicial carries over; `ks`, `sg`, `ps` and `ds` pair them.
//!
//! K is checked before it is used: a triangulation of the input's surface pieces with no two
//! triangles on the same three vertices and no edge twice (simplicial).

use std::collections::HashSet;

use surftopo_irreducible::{Algorithm, reduce_surface};
use surftopo_matching::{DualGraph, Pairing, SurfaceDual};
use surftopo_mesh::{ClosedCover, EdgeId, FaceId, Lifting, SurfaceKind, SurfaceMesh};

use crate::QuadError;
use crate::lrs::{ExpansionCases, Guard, expand_guarded};

/// LRS's expansion on a cover: K's cover, its pairing (on K's dual) and the figures.
pub(crate) struct SurfaceExpansion {
    /// K: the input's cover with the flips applied (same classes, same apexes).
    pub cover: ClosedCover,
    /// M, as pairs of K's triangles (faces of `cover`).
    matched: Vec<[FaceId; 2]>,
    /// Edges of K whose flip is in K.
    pub flipped_edges: usize,
    /// Branch counts of Algorithm 3.1.
    pub cases: ExpansionCases,
}

impl SurfaceExpansion {
    /// M as a pairing of `dual`, K's surface dual (two triangles of a simplicial surface share
    /// at most one edge).
    pub fn pairing_on(&self, dual: &SurfaceDual) -> Result<Pairing, QuadError> {
        let edges = self.matched.iter().map(|&[f, g]| {
            dual.adjacent(f.0)
                .into_iter()
                .find(|&(_, w)| w == g.0)
                .map_or(u32::MAX, |(e, _)| e)
        });
        Pairing::from_edges(dual, edges).map_err(|err| {
            QuadError::Internal(format!("LRS on the cover: M is not a matching: {err}"))
        })
    }
}

/// The cone guard: an edge may be flipped or pair its triangles when both its triangles are
/// triangles of the surface (no apex among their corners).
struct ConeGuard<'a, L> {
    lifting: &'a L,
}

impl<L: Lifting> ConeGuard<'_, L> {
    fn inside(&self, mesh: &SurfaceMesh, e: EdgeId) -> bool {
        let h = e.halfedge();
        [h, h.twin()].into_iter().all(|g| {
            mesh.face_vertices(mesh.face(g))
                .iter()
                .all(|&v| !self.lifting.is_apex(v))
        })
    }
}

impl<L: Lifting> ConeGuard<'_, L> {
    /// Whether `v` is on the boundary (a neighbour of an apex).
    fn on_boundary(&self, mesh: &SurfaceMesh, v: surftopo_mesh::VertexId) -> bool {
        mesh.neighbors(v).any(|w| self.lifting.is_apex(w))
    }
}

impl<L: Lifting> Guard for ConeGuard<'_, L> {
    /// An interior edge without an end on the boundary: its flip keeps every triangle with a
    /// boundary side as it is (the four sides of its quad have an interior end).
    fn may_flip(&self, mesh: &SurfaceMesh, e: EdgeId) -> bool {
        self.inside(mesh, e)
            && mesh
                .edge_vertices(e)
                .iter()
                .all(|&v| !self.on_boundary(mesh, v))
    }
    fn may_pair(&self, mesh: &SurfaceMesh, e: EdgeId) -> bool {
        self.inside(mesh, e)
    }
}

/// LRS's contraction and guarded expansion on the cover of a surface of orientable pieces (see
/// the module doc).
///
/// # Errors
/// [`QuadError::Unsupported`] for a non-orientable piece (named, in the order of the pieces);
/// [`QuadError::Internal`] when the expansion or K's check fails (a bug).
pub(crate) fn pair(
    cover: &ClosedCover,
    pieces: &[SurfaceKind],
) -> Result<SurfaceExpansion, QuadError> {
    if let Some((index, piece)) = pieces.iter().enumerate().find(|(_, k)| !k.orientable) {
        return Err(QuadError::Unsupported(format!(
            "lrs: piece {index} ({}) is non-orientable: LRS's expansion (Algorithm 3.1) flips \
             edges of an oriented triangulation; ks, sg, ps and ds pair non-orientable surfaces",
            piece.name()
        )));
    }
    if cover.sheets.doubled() {
        return Err(QuadError::Unsupported(
            "lrs: a piece is non-orientable; ks, sg, ps and ds pair non-orientable surfaces".into(),
        ));
    }
    let reduction = reduce_surface(cover.clone(), Algorithm::RamaswamiSiqueira)?;
    let guard = ConeGuard {
        lifting: &cover.sheets,
    };
    let expansion = expand_guarded(reduction.cover.mesh, &reduction.history, &guard)?;
    let k = ClosedCover {
        mesh: expansion.mesh,
        sheets: cover.sheets.clone(),
    };
    check_k(cover, &k)?;
    let matched = (0..expansion.flipped.len() as u32)
        .map(EdgeId)
        .filter(|&e| expansion.pairing.contains_edge(&k.mesh, e.0))
        .map(|e| {
            let h = e.halfedge();
            [k.mesh.face(h), k.mesh.face(h.twin())]
        })
        .collect();
    Ok(SurfaceExpansion {
        cover: k,
        matched,
        flipped_edges: expansion.flipped_edges,
        cases: expansion.cases,
    })
}

/// K is the input's surface re-triangulated on the same vertices: the cone triangles unchanged,
/// as many surface triangles, none repeated, no edge of K in three triangles or twice between
/// the same vertices, and every surface triangle with three distinct corners.
fn check_k(input: &ClosedCover, k: &ClosedCover) -> Result<(), QuadError> {
    k.mesh
        .check_invariants()
        .map_err(|err| QuadError::Internal(format!("LRS on the cover: K is broken: {err}")))?;
    let fail = |what: String| Err(QuadError::Internal(format!("LRS on the cover: K {what}")));
    let cones = |c: &ClosedCover| c.mesh.faces().count() - c.surface_faces().count();
    if cones(k) != cones(input) || k.surface_faces().count() != input.surface_faces().count() {
        return fail("does not keep the input's triangles and cones".into());
    }
    let mut triangles = HashSet::new();
    let mut edges = HashSet::new();
    for t in k.surface_triangles() {
        let mut sorted = t;
        sorted.sort_unstable();
        if sorted[0] == sorted[1] || sorted[1] == sorted[2] {
            return fail(format!("has a degenerate triangle {t:?}"));
        }
        if !triangles.insert(sorted) {
            return fail(format!("has the triangle {t:?} twice"));
        }
    }
    for e in k.mesh.edges() {
        let [a, b] = k.mesh.edge_vertices(e).map(|v| k.class(v));
        if k.sheets.apex_class().is_some_and(|x| a == x || b == x) {
            continue;
        }
        if !edges.insert([a.min(b), a.max(b)]) {
            return fail(format!("has two edges between vertices {a} and {b}"));
        }
    }
    Ok(())
}
