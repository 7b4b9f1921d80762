//! Building the [`ClosedCover`] of a triangle soup.

use super::twisted::TwistedGluing;
use super::{ClosedCover, Sheets};
use crate::build::pairing::CornerPairing;
use crate::build::{BuildReport, build_topology_closed, classify};
use crate::error::BuildError;
use crate::gluing::Side;
use crate::ids::{FaceId, HalfedgeId};

impl ClosedCover {
    /// The cover of the surface a triangle soup forms: a compact 2-manifold whose components
    /// may have boundary loops and may be non-orientable.
    ///
    /// Unreferenced vertices are dropped and surface vertex ids are the input indices without
    /// them ([`BuildReport::vertex_old_to_new`]); surface face ids are the input face indices.
    /// Orientable components are reoriented to their majority orientation
    /// ([`BuildReport::reoriented_faces`]); each boundary loop is coned over an apex (numbered in
    /// the order of the loops' first boundary edge in face order), and each non-orientable
    /// component is replaced by its orientable double cover (see the [module
    /// documentation](super)). A closed orientable soup gives [`ClosedCover::plain`] of the mesh
    /// [`crate::build()`] would give, at the same cost. O(n).
    ///
    /// # Errors
    /// The first problem [`crate::inspect`] lists (non-manifold edge or vertex, degenerate or
    /// duplicate face, bad index, no face), naming the input element.
    pub fn from_triangles(
        vertex_count: usize,
        triangles: &[[u32; 3]],
    ) -> Result<(Self, BuildReport), BuildError> {
        let mut p = CornerPairing::run(vertex_count, triangles);
        if let Some(e) = p.inspection.problems.first() {
            return Err(e.clone());
        }
        let nv = p.new_to_old.len();
        let ins = &p.inspection;
        if ins.boundary_edges == 0 && ins.orientable {
            let surfaces = classify::classify(&p);
            let mut report = BuildReport {
                reoriented_faces: ins.reoriented_faces.min(triangles.len()),
                dropped_vertices: std::mem::take(&mut p.dropped),
                vertex_old_to_new: std::mem::take(&mut p.old_to_new),
                surfaces,
            };
            let mesh = if report.reoriented_faces == 0 {
                p.into_mesh()
            } else {
                build_topology_closed(nv, &p.oriented_triangles(), true)?
            };
            report.reoriented_faces = report.reoriented_faces.min(triangles.len());
            return Ok((ClosedCover::plain(mesh), report));
        }
        let (face_component, kinds) = classify::components(&p);
        let reoriented_faces = (0..triangles.len())
            .filter(|&f| p.flip[f] && kinds[face_component[f] as usize].orientable)
            .count();
        let report = BuildReport {
            reoriented_faces,
            dropped_vertices: p.dropped.clone(),
            vertex_old_to_new: p.old_to_new.clone(),
            surfaces: kinds,
        };
        // The soup's gluing: each edge in two faces glues their sides, reversed where the two
        // faces run it the same way.
        let edges = &p.edges;
        let side = |c: u32| Side {
            face: c / 3,
            side: (c % 3) as u8,
        };
        let (pairs, reversed): (Vec<(Side, Side)>, Vec<bool>) = (0..edges.same_direction.len())
            .map(|e| {
                let [a, b] = [2 * e, 2 * e + 1].map(|h| edges.halfedge_corner[h]);
                ((side(a), side(b)), edges.same_direction[e])
            })
            .unzip();
        let labels: Vec<u32> = p.remapped.iter().flatten().copied().collect();
        let gluing = TwistedGluing {
            face_count: triangles.len(),
            pairs: &pairs,
            reversed: &reversed,
        };
        let cover = ClosedCover::from_twisted_gluing(&gluing, &labels, nv)?.cover;
        Ok((cover, report))
    }
}

/// Records the mirrors of the half-edges of face `f` and its mirror copy `m`: the half-edge on
/// the same side, which runs the other way between the same classes.
pub(super) fn pair_mirror_faces(
    mesh: &crate::SurfaceMesh,
    sheets: &mut Sheets,
    f: FaceId,
    m: FaceId,
) {
    use super::Lifting;
    let ends = |h: HalfedgeId, sheets: &Sheets| {
        (
            sheets.class(mesh.origin(h)),
            sheets.class(mesh.origin(mesh.next(h))),
        )
    };
    let theirs = mesh.face_halfedges(m);
    for h in mesh.face_halfedges(f) {
        let (a, b) = ends(h, sheets);
        let k = theirs
            .into_iter()
            .find(|&k| ends(k, sheets) == (b, a))
            .expect("a mirror face has the same classes in reverse order");
        sheets.set_mirror(h, k);
    }
}
