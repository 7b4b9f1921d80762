//! Edits of the covered surface: each is the mesh's own edit made on every lift (once on an
//! undoubled component, on both copies of a doubled one), with the link condition of the
//! surface decided on vertex classes.

use super::{Lifting, Sheets, build::pair_mirror_faces};
use crate::contract::{Contraction, LinkScratch};
use crate::error::EditError;
use crate::ids::{EdgeId, FaceId, HalfedgeId};
use crate::topology::SurfaceMesh;

/// The link condition of the surface for the edge of `h = u -> v` (Dey, Edelsbrunner, Guha and
/// Nekhayev, "Topology preserving edge contraction", 1999, Theorem 2, on the complex with the
/// boundary coned over one vertex ω): u and v have exactly two common neighbours (the vertices
/// opposite the edge, ω among them for a boundary edge) with all apexes counted as ω, and the
/// component is not the tetrahedron (which is also the cone over a lone triangle, the edge
/// condition of the theorem). Edges at an apex are not edges of the surface: never contractible.
///
/// On a closed orientable surface ([`super::Plain`]) this is
/// [`SurfaceMesh::satisfies_link_condition`]. The consequences on a surface with boundary: an
/// interior edge whose two ends are on the boundary never contracts (ω is a third common
/// neighbour), and a boundary edge `ab` of triangle `abc` contracts iff a and b have no common
/// neighbour but c and ω. O(deg u + deg v).
pub fn satisfies_link_condition<L: Lifting>(
    mesh: &SurfaceMesh,
    lifting: &L,
    h: HalfedgeId,
    scratch: &mut LinkScratch,
) -> bool {
    if !mesh.is_edge_live(h.edge()) {
        return false;
    }
    let (u, v) = (mesh.origin(h), mesh.dest(h));
    if lifting.is_apex(u) || lifting.is_apex(v) {
        return false;
    }
    let stamp = scratch.next_stamp(lifting.class_count());
    let mut degree_u = 0usize;
    for w in mesh.neighbors(u) {
        scratch.mark[lifting.class(w) as usize] = stamp;
        degree_u += 1;
    }
    let mut common = 0usize;
    let mut degree_v = 0usize;
    for w in mesh.neighbors(v) {
        degree_v += 1;
        if scratch.mark[lifting.class(w) as usize] == stamp {
            common += 1;
        }
    }
    common == 2 && !(degree_u == 3 && degree_v == 3)
}

/// Contracts the edge of `h = u -> v` into u on every lift
/// ([`SurfaceMesh::contract_unchecked`]; on a doubled component also the mirror edge, into u's
/// mirror), pushing the records on `history` (undo them last-in first-out with
/// [`SurfaceMesh::split_vertex`]). The caller guarantees [`satisfies_link_condition`]. The
/// mirrors of the surviving half-edges stay right: a contraction keeps the ids of the half-edges
/// it does not remove, and the two contractions remove mirror pairs. Returns how many records
/// were pushed (1 or 2).
pub fn contract_lifts<L: Lifting>(
    mesh: &mut SurfaceMesh,
    lifting: &L,
    h: HalfedgeId,
    history: &mut Vec<Contraction>,
) -> usize {
    let mirror = lifting.mirror(h);
    history.push(mesh.contract_unchecked(h));
    match mirror {
        Some(m) => {
            // m runs τv -> τu on the mirror side: its twin is τu -> τv.
            history.push(mesh.contract_unchecked(m.twin()));
            2
        }
        None => 1,
    }
}

/// Flips edge `e` on every lift ([`SurfaceMesh::flip`]) and repairs the mirrors of the four
/// faces involved. The caller checks that the flip suits the surface (not a boundary edge: no
/// apex among the four vertices of its two faces).
///
/// # Errors
/// [`EditError::NotFlippable`] when the mesh cannot flip it (nothing changes).
pub fn flip_lifts(mesh: &mut SurfaceMesh, sheets: &mut Sheets, e: EdgeId) -> Result<(), EditError> {
    let mirror = sheets.mirror(e.halfedge()).map(|m| m.edge());
    if !mesh.can_flip(e) || mirror.is_some_and(|m| !mesh.can_flip(m)) {
        return Err(EditError::NotFlippable(e));
    }
    mesh.flip(e)?;
    if let Some(m) = mirror {
        mesh.flip(m)?;
        repair_mirrors(mesh, sheets, faces_of(mesh, e), faces_of(mesh, m));
    }
    Ok(())
}

/// Splits u, the origin of `to_y = u -> y` and `to_x = u -> x`, on every lift
/// ([`SurfaceMesh::split_vertex_new`]: the neighbours strictly between y and x in rotation order
/// move to a new vertex joined to u, x and y); the new vertex is a new class. Returns the class
/// and the record of the first lift's split.
///
/// # Errors
/// As [`SurfaceMesh::split_vertex_new`] (nothing changes).
pub fn split_lifts(
    mesh: &mut SurfaceMesh,
    sheets: &mut Sheets,
    to_y: HalfedgeId,
    to_x: HalfedgeId,
) -> Result<(u32, Contraction), EditError> {
    let mirrors = sheets.mirror(to_y).zip(sheets.mirror(to_x));
    let record = mesh.split_vertex_new(to_y, to_x)?;
    let v = record.removed();
    let Some((my, mx)) = mirrors else {
        return Ok((sheets.push_class(&[v]), record));
    };
    // The mirror image turns the other way around τu: the same neighbours lie strictly between
    // τx and τy there.
    let mirrored = mesh.split_vertex_new(mx.twin(), my.twin())?;
    let class = sheets.push_class(&[v, mirrored.removed()]);
    let ours = [record.removed_faces(), [record.faces[2], record.faces[3]]].concat();
    let theirs = [
        mirrored.removed_faces(),
        [mirrored.faces[2], mirrored.faces[3]],
    ]
    .concat();
    repair_mirrors(mesh, sheets, ours, theirs);
    Ok((class, record))
}

/// The two faces of edge `e`.
fn faces_of(mesh: &SurfaceMesh, e: EdgeId) -> Vec<FaceId> {
    let h = e.halfedge();
    vec![mesh.face(h), mesh.face(h.twin())]
}

/// Pairs each face of `ours` with the face of `theirs` on the same classes, and their
/// half-edges as mirrors.
fn repair_mirrors(mesh: &SurfaceMesh, sheets: &mut Sheets, ours: Vec<FaceId>, theirs: Vec<FaceId>) {
    let classes = |f: FaceId, sheets: &Sheets| {
        let mut c = mesh.face_vertices(f).map(|v| sheets.class(v));
        c.sort_unstable();
        c
    };
    for f in ours {
        let key = classes(f, sheets);
        if let Some(&m) = theirs.iter().find(|&&m| classes(m, sheets) == key) {
            pair_mirror_faces(mesh, sheets, f, m);
        }
    }
}
