//! The general surface model: every generated kind is classified as it should be, its cover is a
//! closed oriented mesh whose lifting is consistent, and every modifier keeps the kind.

use surftopo_mesh::generators::{
    self, annulus, connected_sum, copies, crosscaps, cut_holes, disk, klein_bottle, mobius_band,
    projective_plane,
};
use surftopo_mesh::{CoveredSurface, Lifting, SurfaceKind, inspect};

/// The classification of a covered surface's own triangles, by `inspect` (which knows nothing of
/// covers).
fn kinds(s: &CoveredSurface) -> Vec<SurfaceKind> {
    let (positions, triangles) = s.to_triangles();
    let ins = inspect(positions.len(), &triangles);
    assert!(ins.is_valid(), "{:?}", ins.problems);
    ins.surfaces
}

fn names(s: &CoveredSurface) -> Vec<String> {
    kinds(s).iter().map(|k| k.name()).collect()
}

/// The cover is closed and oriented, classes and mirrors are consistent.
fn check_cover(s: &CoveredSurface) {
    let c = &s.cover;
    c.mesh.check_invariants().unwrap();
    for h in c.mesh.halfedges() {
        if let Some(m) = c.sheets.mirror(h) {
            assert_eq!(c.sheets.mirror(m), Some(h));
            assert_ne!(c.mesh.face(h), c.mesh.face(m));
            let ends = |k| (c.class(c.mesh.origin(k)), c.class(c.mesh.dest(k)));
            let (a, b) = ends(h);
            assert_eq!(ends(m), (b, a), "mirror of {h:?}");
        }
    }
    // Every live vertex's class has it as a lift or shares the class with its mirror's.
    for v in c.mesh.vertices() {
        assert!((c.class(v) as usize) < c.sheets.class_count());
    }
}

#[test]
fn every_kind_is_classified() {
    let cases: Vec<(CoveredSurface, &str)> = vec![
        (disk(3), "disk"),
        (annulus(6, 2), "annulus"),
        (mobius_band(7, 2), "Möbius band"),
        (projective_plane(), "projective plane"),
        (klein_bottle(6, 5), "Klein bottle"),
        (crosscaps(3), "N_3"),
        (crosscaps(4), "N_4"),
        (generators::torus(5, 4).into(), "torus"),
    ];
    for (s, name) in cases {
        check_cover(&s);
        assert_eq!(names(&s), vec![name.to_string()]);
        assert_eq!(s.cover.surface_faces().count(), s.to_triangles().1.len());
    }
}

#[test]
fn holes_copies_and_sums() {
    let torus: CoveredSurface = generators::torus(12, 8).into();
    let (holed, cut) = cut_holes(&torus, 3, 7);
    assert_eq!(cut, 3);
    check_cover(&holed);
    assert_eq!(names(&holed), vec!["genus 1 with 3 boundary loops"]);
    let (kb_holed, cut) = cut_holes(&klein_bottle(10, 8), 1, 1);
    assert_eq!(cut, 1);
    assert_eq!(names(&kb_holed), vec!["N_2 with 1 boundary loop"]);
    let many = copies(&mobius_band(6, 1), 3);
    check_cover(&many);
    assert_eq!(names(&many), vec!["Möbius band"; 3]);
    let sum = connected_sum(
        &generators::torus(5, 5).into(),
        &generators::torus(6, 5).into(),
    );
    assert_eq!(names(&sum), vec!["genus-2 surface"]);
    let mixed = connected_sum(&generators::torus(5, 5).into(), &projective_plane());
    assert_eq!(names(&mixed), vec!["N_3"]);
}

#[test]
fn modifiers_keep_the_kind() {
    let inputs: Vec<CoveredSurface> = vec![
        disk(4),
        annulus(8, 3),
        mobius_band(8, 2),
        projective_plane(),
        klein_bottle(8, 6),
        crosscaps(3),
        copies(&mobius_band(6, 2), 2),
        cut_holes(&generators::torus(10, 8).into(), 2, 3).0,
    ];
    for s in inputs {
        let want = kinds(&s)
            .iter()
            .map(|k| (k.orientable, k.euler_characteristic, k.boundary_loops))
            .collect::<Vec<_>>();
        let sub = generators::subdivide_midpoint_covered(&s, 1);
        let flipped = generators::random_flips_covered(&sub, 200, 5);
        let split = generators::random_vertex_splits_covered(&flipped, 40, 6);
        let simplified = generators::simplify_covered(&split, 20, 7);
        let shuffled = generators::shuffle_faces_covered(&simplified, 8);
        for t in [&sub, &flipped, &split, &simplified, &shuffled] {
            check_cover(t);
            let got = kinds(t)
                .iter()
                .map(|k| (k.orientable, k.euler_characteristic, k.boundary_loops))
                .collect::<Vec<_>>();
            assert_eq!(got, want);
        }
        assert_eq!(sub.to_triangles().1.len(), 4 * s.to_triangles().1.len());
        // A split adds a vertex and two faces, one of them a cone face at a boundary vertex
        // whose new edge runs to the apex.
        let (before, after) = (flipped.to_triangles(), split.to_triangles());
        assert_eq!(after.0.len(), before.0.len() + 40);
        assert!((40..=80).contains(&(after.1.len() - before.1.len())));
    }
}
