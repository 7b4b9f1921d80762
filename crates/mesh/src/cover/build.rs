//! Building the [`ClosedCover`] of a triangle soup.

use super::{ClosedCover, Sheets};
use crate::build::pairing::{CornerPairing, next_corner, prev_corner};
use crate::build::{BuildReport, build_topology_closed, classify, closed_topology_of_trusted};
use crate::error::BuildError;
use crate::ids::{FaceId, HalfedgeId, VertexId};
use crate::union_find::UnionFind;

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
        crate::stop::check();
        let nv = p.new_to_old.len();
        let ins = &p.inspection;
        if ins.boundary_edges == 0 && ins.orientable {
            let surfaces = classify::classify(&p);
            crate::stop::check();
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
        let orientable = |f: usize| kinds[face_component[f] as usize].orientable;
        let reoriented_faces = (0..triangles.len())
            .filter(|&f| p.flip[f] && orientable(f))
            .count();
        let report = BuildReport {
            reoriented_faces,
            dropped_vertices: p.dropped.clone(),
            vertex_old_to_new: p.old_to_new.clone(),
            surfaces: kinds.clone(),
        };
        // Orientable components in their majority orientation; the others as given.
        let mut closed: Vec<[u32; 3]> = p.remapped.to_vec();
        for (f, t) in closed.iter_mut().enumerate() {
            if p.flip[f] && orientable(f) {
                t.swap(1, 2);
            }
        }
        // The boundary corners of `closed`, in corner order: a reversed face (b, a, c) has its
        // sides i = 0, 1, 2 on the sides 2, 1, 0 of the face as given, (a, b, c).
        let boundary: Vec<u32> = (0..3 * closed.len() as u32)
            .filter(|&c| {
                let (f, i) = (c / 3, c % 3);
                let given = if p.flip[f as usize] && orientable(f as usize) {
                    3 * f + 2 - i
                } else {
                    c
                };
                p.edges.across(given).is_none()
            })
            .collect();
        let mut component = face_component;
        let apexes = close_boundary_loops(nv, &mut closed, &boundary, &mut component);
        let doubled: Vec<bool> = kinds.iter().map(|k| !k.orientable).collect();
        let cover = double(nv, apexes, &closed, &component, &doubled)?;
        Ok((cover, report))
    }
}

/// Cones each boundary loop of `faces` (vertices `0..nv`, consistently oriented on orientable
/// components; `boundary` their corners on a boundary edge, increasing) over a new apex vertex
/// `nv + k`: appends a triangle `(b, a, apex)` for each face's boundary edge `a -> b`, which
/// orients the cone as the face beside it. Returns the number of apexes; `component` gets the
/// component of each new face.
fn close_boundary_loops(
    nv: usize,
    faces: &mut Vec<[u32; 3]>,
    boundary: &[u32],
    component: &mut Vec<u32>,
) -> usize {
    let corner_vertex = |c: u32| faces[(c / 3) as usize][(c % 3) as usize];
    let mut loops = UnionFind::new(nv);
    for &c in boundary {
        loops.union(corner_vertex(c), corner_vertex(next_corner(c)));
    }
    let mut apex_of_root = vec![u32::MAX; nv];
    let mut apexes = 0;
    let mut cones = Vec::with_capacity(boundary.len());
    for &c in boundary {
        let (a, b) = (corner_vertex(c), corner_vertex(next_corner(c)));
        let root = loops.find(a) as usize;
        if apex_of_root[root] == u32::MAX {
            apex_of_root[root] = (nv + apexes) as u32;
            apexes += 1;
        }
        cones.push(([b, a, apex_of_root[root]], component[(c / 3) as usize]));
    }
    for (t, k) in cones {
        faces.push(t);
        component.push(k);
    }
    apexes
}

/// The cover of the closed surface `faces` (vertices `0..nv + apexes`, apexes last), its
/// components flagged in `doubled` replaced by their orientable double covers.
///
/// The double cover's vertices are the pairs (vertex, orientation of its star). A walk around
/// each vertex of a doubled component gives each of its corners a sign ε: whether the face's
/// orientation agrees with the star's orientation at the walk's first face (it flips across an
/// edge that the two faces run the same way). Face `(a, b, c)` then becomes `(a^ε, b^ε, c^ε)` as
/// given, and its mirror `(a^-ε, c^-ε, b^-ε)` reversed, where `v^+` is v and `v^-` its second lift.
fn double(
    nv: usize,
    apexes: usize,
    faces: &[[u32; 3]],
    component: &[u32],
    doubled: &[bool],
) -> Result<ClosedCover, BuildError> {
    let n = nv + apexes;
    let is_doubled = |f: usize| doubled[component[f] as usize];
    // The negative sign of each corner of the doubled faces, and the second lifts.
    let mut negative = vec![false; 3 * faces.len()];
    let mut second = vec![u32::MAX; n];
    let mut next_id = n as u32;
    if doubled.iter().any(|&d| d) {
        let p = CornerPairing::pair_only(n, faces);
        debug_assert!(p.inspection.problems.is_empty() && p.inspection.boundary_edges == 0);
        let mut start = vec![u32::MAX; n];
        for (f, t) in faces.iter().enumerate() {
            for (i, &v) in t.iter().enumerate() {
                if is_doubled(f) && start[v as usize] == u32::MAX {
                    start[v as usize] = (3 * f + i) as u32;
                }
            }
        }
        for v in 0..n as u32 {
            let s = start[v as usize];
            if s == u32::MAX {
                continue;
            }
            second[v as usize] = next_id;
            next_id += 1;
            sign_corners_around(&p, v, s, &mut negative);
        }
    }
    let lift = |c: usize, flip: bool| {
        let v = faces[c / 3][c % 3];
        if negative[c] ^ flip {
            second[v as usize]
        } else {
            v
        }
    };
    let mut lifted: Vec<[u32; 3]> = Vec::with_capacity(faces.len());
    lifted.extend((0..faces.len()).map(|f| {
        if is_doubled(f) {
            [0, 1, 2].map(|i| lift(3 * f + i, false))
        } else {
            faces[f]
        }
    }));
    let mut mirror_of = Vec::new();
    for f in (0..faces.len()).filter(|&f| is_doubled(f)) {
        mirror_of.push((f, lifted.len()));
        lifted.push([0, 2, 1].map(|i| lift(3 * f + i, true)));
    }
    let mesh = closed_topology_of_trusted(next_id as usize, &lifted);
    let mut class: Vec<u32> = (0..next_id).collect();
    for (v, &s) in second.iter().enumerate() {
        if s != u32::MAX {
            class[s as usize] = v as u32;
        }
    }
    for k in class
        .iter_mut()
        .filter(|k| (nv..n).contains(&(**k as usize)))
    {
        *k = nv as u32;
    }
    let lift = (0..nv as u32)
        .chain((apexes > 0).then_some(nv as u32))
        .map(VertexId)
        .collect();
    let mut sheets = Sheets {
        class,
        lift,
        mirror: Vec::new(),
        apex: (apexes > 0).then_some(nv as u32),
    };
    for (f, m) in mirror_of {
        pair_mirror_faces(&mesh, &mut sheets, FaceId::new(f), FaceId::new(m));
    }
    Ok(ClosedCover { mesh, sheets })
}

/// Walks around vertex `v` of a closed soup from its corner `start` and marks each corner at v
/// whose face runs against the first face's orientation of the star.
fn sign_corners_around(p: &CornerPairing, v: u32, start: u32, negative: &mut [bool]) {
    let (mut leave, mut sign) = (start, false);
    loop {
        let entered = p
            .edges
            .across(leave)
            .expect("a closed surface: every edge in two faces");
        sign ^= p.edges.same_direction_at(leave);
        let (at_v, next_leave) = if p.corner_vertex(entered) == v {
            (entered, prev_corner(entered))
        } else {
            (next_corner(entered), next_corner(entered))
        };
        if at_v / 3 == start / 3 {
            debug_assert!(!sign, "the star of a vertex is a disk, hence orientable");
            return;
        }
        negative[at_v as usize] = sign;
        leave = next_leave;
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
