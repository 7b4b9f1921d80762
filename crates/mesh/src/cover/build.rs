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
        if ins.orientable && ins.reoriented_faces == 0 {
            let report = BuildReport {
                reoriented_faces: 0,
                dropped_vertices: std::mem::take(&mut p.dropped),
                vertex_old_to_new: std::mem::take(&mut p.old_to_new),
                surfaces: classify::classify(&p),
            };
            return Ok((coned(&p)?, report));
        }
        Self::from_pairing(p, triangles.len())
    }

    /// [`Self::from_triangles`] of a surface with boundary or non-orientable pieces, from its
    /// corner pairing: the soup's gluing handed to [`Self::from_twisted_gluing`].
    fn from_pairing(
        p: CornerPairing<'_>,
        face_count: usize,
    ) -> Result<(Self, BuildReport), BuildError> {
        let nv = p.new_to_old.len();
        let (face_component, kinds) = classify::components(&p);
        let reoriented_faces = (0..face_count)
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
            face_count,
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

/// The cover of a soup that forms an orientable surface with boundary, as given (no face
/// reoriented): the mesh [`ClosedCover::from_twisted_gluing`] builds from the soup's gluing
/// (same ids, same arrays, so every later result is the same), made directly from the corner
/// pairing. The general construction's steps reduce to this when no gluing is reversed and no
/// face is reoriented: every triangle is its own first lift (no mirror copy), K's edge `e` is
/// D's edge `e` (the pairing's half-edges `2e`, `2e + 1`), cone `k` (face `face_count + k`,
/// corners `(b, a, apex)`) lies on the `k`-th boundary side in face and side order, glued by
/// edge `E + k` (its side 0 half-edge `2(E + k)`, the side of K `2(E + k) + 1`), and the cones'
/// apex sides are glued in the general order (per cone, its side 2 then its side 1, each to the
/// cone at the other end of the vertex's fan unless already glued). A vertex's corners form one
/// fan (the pairing checked it), so D's vertex at a corner is its class: K's vertex (new id),
/// or the apex of its loop (`vertex_count + ` the loop's rank in order of first cone). O(n).
///
/// # Errors
/// [`BuildError::TooLarge`] beyond `u32` half-edge ids (the general construction's limit);
/// [`BuildError::SideUnglued`] if a fan does not end at a boundary side (not a surface: the
/// pairing refuses such soups first).
fn coned(p: &CornerPairing<'_>) -> Result<ClosedCover, BuildError> {
    use crate::build::pairing::{next_corner, prev_corner};
    use crate::ids::VertexId;
    use crate::topology::SurfaceMesh;
    use crate::union_find::UnionFind;
    let edges = &p.edges;
    let (nf, nv) = (p.remapped.len(), p.new_to_old.len());
    let corners = 3 * nf;
    let interior = edges.halfedge_corner.len() / 2;
    let mut cone_of = vec![u32::MAX; corners];
    let mut cone: Vec<u32> = Vec::new();
    for (c, h) in edges.corner_halfedge.iter().enumerate() {
        if !h.is_valid() {
            cone_of[c] = cone.len() as u32;
            cone.push(c as u32);
        }
    }
    let nc = cone.len();
    if 3 * (nf + nc) >= u32::MAX as usize / 2 {
        return Err(BuildError::TooLarge { what: "faces" });
    }
    // The half-edge of each apex side (`3k + 1`, `3k + 2`) of cone k, and the loops.
    let mut apex_side = vec![HalfedgeId::INVALID; 3 * nc];
    let mut loops = UnionFind::new(nc);
    let mut pair = interior + nc;
    for (k, &s) in cone.iter().enumerate() {
        for at_start in [false, true] {
            // The boundary side at the other end of the fan around s's end (its start when
            // `at_start`): `around_fan` of the general construction, no gluing reversed.
            let (mut entering, mut steps) = (s, 0);
            let leaving = loop {
                let leaving = if at_start {
                    prev_corner(entering)
                } else {
                    next_corner(entering)
                };
                match edges.across(leaving) {
                    None => break leaving,
                    Some(t) => entering = t,
                }
                steps += 1;
                if steps > corners {
                    return Err(BuildError::SideUnglued {
                        face: s as usize / 3,
                        side: s as usize % 3,
                    });
                }
            };
            let other = cone_of[leaving as usize] as usize;
            let (mine, theirs) = if at_start {
                (3 * k + 1, 3 * other + 2)
            } else {
                (3 * k + 2, 3 * other + 1)
            };
            if apex_side[mine].is_valid() || apex_side[theirs].is_valid() {
                continue;
            }
            apex_side[mine] = HalfedgeId::new(2 * pair);
            apex_side[theirs] = HalfedgeId::new(2 * pair + 1);
            pair += 1;
            loops.union(k as u32, other as u32);
        }
    }
    if let Some(i) = apex_side
        .iter()
        .enumerate()
        .position(|(i, h)| i % 3 != 0 && !h.is_valid())
    {
        return Err(BuildError::SideUnglued {
            face: nf + i / 3,
            side: i % 3,
        });
    }
    // Apex of each cone: `nv + ` the rank of its loop.
    let mut apex_of_root = vec![u32::MAX; nc];
    let mut apexes = 0u32;
    let apex: Vec<u32> = (0..nc as u32)
        .map(|k| {
            let root = loops.find(k) as usize;
            if apex_of_root[root] == u32::MAX {
                apex_of_root[root] = nv as u32 + apexes;
                apexes += 1;
            }
            apex_of_root[root]
        })
        .collect();
    // Half-edge and class of each side (corner) of D.
    let halfedge = |d: usize| -> HalfedgeId {
        if d < corners {
            let h = edges.corner_halfedge[d];
            if h.is_valid() {
                h
            } else {
                HalfedgeId::new(2 * (interior + cone_of[d] as usize) + 1)
            }
        } else if d.is_multiple_of(3) {
            HalfedgeId::new(2 * (interior + (d - corners) / 3))
        } else {
            apex_side[d - corners]
        }
    };
    let label = |d: usize| -> u32 {
        if d < corners {
            p.remapped[d / 3][d % 3]
        } else {
            let k = (d - corners) / 3;
            let s = cone[k];
            match d % 3 {
                0 => p.remapped[(next_corner(s) / 3) as usize][(next_corner(s) % 3) as usize],
                1 => p.remapped[(s / 3) as usize][(s % 3) as usize],
                _ => apex[k],
            }
        }
    };
    let vertices = nv + apexes as usize;
    let mesh = SurfaceMesh::from_sides(
        nf + nc,
        vertices,
        |f, i| halfedge(3 * f + i),
        |f, i| VertexId(label(3 * f + i)),
    );
    let sheets = Sheets {
        class: (0..vertices as u32).map(|v| v.min(nv as u32)).collect(),
        lift: (0..=nv as u32).map(VertexId).collect(),
        mirror: Vec::new(),
        apex: Some(nv as u32),
    };
    Ok(ClosedCover { mesh, sheets })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::CoveredSurface;
    use crate::generators::{self, annulus, copies, cut_holes, disk, shuffle_faces_covered};

    /// The soup of a surface, with `unused` unreferenced vertices put first.
    fn soup(s: &CoveredSurface, unused: u32) -> (usize, Vec<[u32; 3]>) {
        let (positions, triangles) = s.to_triangles();
        let shifted = triangles.iter().map(|t| t.map(|v| v + unused)).collect();
        (positions.len() + unused as usize, shifted)
    }

    /// The direct construction of an oriented soup with boundary gives the general one's
    /// cover (every id and table) and report.
    #[test]
    fn coned_is_the_general_construction() {
        let torus: CoveredSurface = generators::torus(12, 8).into();
        // A disk beside a closed sphere: two pieces, one of them closed.
        let closed_and_open = {
            let sphere: CoveredSurface = generators::icosphere(1).into();
            let (n, mut triangles) = soup(&disk(3), 0);
            let (m, t) = soup(&sphere, 0);
            triangles.extend(t.iter().map(|f| f.map(|v| v + n as u32)));
            CoveredSurface::from_triangles(vec![[0.0; 3]; n + m], &triangles)
                .expect("a surface")
                .0
        };
        let inputs = [
            (disk(1), 0),
            (disk(5), 3),
            (annulus(8, 3), 0),
            (cut_holes(&torus, 4, 11).0, 2),
            (copies(&annulus(6, 2), 3), 0),
            (shuffle_faces_covered(&cut_holes(&torus, 2, 5).0, 9), 1),
            (closed_and_open, 0),
        ];
        for (s, unused) in inputs {
            let (n, triangles) = soup(&s, unused);
            let p = CornerPairing::run(n, &triangles);
            let ins = &p.inspection;
            assert!(ins.problems.is_empty() && ins.boundary_edges > 0);
            assert!(ins.orientable && ins.reoriented_faces == 0);
            let general = ClosedCover::from_pairing(p, triangles.len()).expect("a surface");
            let direct = ClosedCover::from_triangles(n, &triangles).expect("a surface");
            assert_eq!(direct, general);
        }
    }
}
