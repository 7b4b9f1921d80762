//! The published counts, each census output checked by the independent verifier: closed surface
//! of the asked kind, irreducible, no two isomorphic.

mod verify;

use surftopo_census::{CensusOptions, SurfaceKind, census};

/// Runs the census of `name` and checks it against `expected` (vertex count, classes) and the
/// independent verifier; returns the chiral counts per vertex count.
fn check(name: &str, expected: &[(usize, usize)]) -> Vec<usize> {
    let surface = SurfaceKind::parse(name).unwrap();
    let c = census(surface, CensusOptions::default()).unwrap();
    assert!(c.complete);
    let found: Vec<(usize, usize)> = c
        .per_vertex_count
        .iter()
        .filter(|f| f.classes > 0)
        .map(|f| (f.vertices, f.classes))
        .collect();
    assert_eq!(found, expected, "{name}: classes per vertex count");
    let list: Vec<Vec<[u32; 3]>> = c
        .triangulations
        .iter()
        .map(|t| t.faces().to_vec())
        .collect();
    verify::check_census(&list, surface.euler_characteristic(), surface.orientable);
    assert_eq!(c.duplicates, c.candidates - list.len() as u64);
    c.per_vertex_count
        .iter()
        .filter(|f| f.classes > 0)
        .map(|f| f.chiral)
        .collect()
}

// Ramaswami–Siqueira, Section 1: the sphere has one irreducible triangulation, the tetrahedron.
#[test]
fn sphere_has_one() {
    assert_eq!(check("sphere", &[(4, 1)]), vec![0]);
}

// Barnette (1982): two, with 6 and 7 vertices. The search goes to Joret–Wood's 9 vertices.
#[test]
fn projective_plane_has_two() {
    let c = census(SurfaceKind::non_orientable(1), CensusOptions::default()).unwrap();
    assert_eq!(c.searched_up_to, 9);
    check("projective-plane", &[(6, 1), (7, 1)]);
}

// Lawrencenko (1987): 21, with 7 to 10 vertices (one with 7: K7, one with 10). K7 on the torus
// is chiral.
#[test]
fn torus_has_twenty_one() {
    let chiral = check("torus", &[(7, 1), (8, 4), (9, 15), (10, 1)]);
    assert_eq!(chiral, vec![1, 0, 8, 1]);
}

// Lawrencenko–Negami (1997) and Sulanke (2006): 29, with 8 to 11 vertices.
#[test]
fn klein_bottle_has_twenty_nine() {
    check("klein-bottle", &[(8, 6), (9, 19), (10, 2), (11, 2)]);
}

// A census cut below the surface's bound says it is incomplete; a surface without a bound in
// reach needs a cut.
#[test]
fn cut_census_is_marked_incomplete() {
    let c = census(
        SurfaceKind::orientable(1),
        CensusOptions {
            max_vertices: Some(8),
            ..Default::default()
        },
    )
    .unwrap();
    assert!(!c.complete);
    assert_eq!(c.searched_up_to, 8);
    assert_eq!(c.triangulations.len(), 5);
    let err = census(SurfaceKind::non_orientable(3), CensusOptions::default()).unwrap_err();
    assert!(
        matches!(err, surftopo_census::CensusError::BeyondReach { .. }),
        "{err}"
    );
    let n3 = census(
        SurfaceKind::non_orientable(3),
        CensusOptions {
            max_vertices: Some(9),
            ..Default::default()
        },
    )
    .unwrap();
    assert!(!n3.complete);
    let list: Vec<Vec<[u32; 3]>> = n3
        .triangulations
        .iter()
        .map(|t| t.faces().to_vec())
        .collect();
    verify::check_census(&list, -1, false);
}

// A stop request ends the run with `Cancelled`; the jobs finished before it are reported and a
// second run resumed from them gives the full census.
#[test]
fn stopped_runs_resume() {
    use std::sync::atomic::{AtomicBool, Ordering};
    let stop_now = AtomicBool::new(false);
    let stop = || stop_now.load(Ordering::Relaxed);
    let mut finished = Vec::new();
    let mut on_job = |r: &surftopo_census::JobResult, _p: surftopo_census::Progress| {
        finished.push(r.clone());
        if r.job.vertices == 10 {
            stop_now.store(true, Ordering::Relaxed);
        }
    };
    let err = census(
        SurfaceKind::non_orientable(2),
        CensusOptions {
            on_job: Some(&mut on_job),
            stop: Some(&stop),
            ..Default::default()
        },
    )
    .unwrap_err();
    assert_eq!(err, surftopo_census::CensusError::Cancelled);
    assert!(finished.iter().all(|r| r.job.vertices <= 11));
    let resumed = census(
        SurfaceKind::non_orientable(2),
        CensusOptions {
            done: finished,
            ..Default::default()
        },
    )
    .unwrap();
    assert_eq!(resumed.triangulations.len(), 29);
}

// Past the published bound: no irreducible triangulation of the torus with 11 vertices, nor of
// the projective plane with 8 or 9 (the default range already goes to Joret–Wood's 9).
#[test]
fn nothing_past_the_published_bounds() {
    let c = census(
        SurfaceKind::orientable(1),
        CensusOptions {
            max_vertices: Some(11),
            ..Default::default()
        },
    )
    .unwrap();
    assert!(c.complete);
    assert_eq!(c.searched_up_to, 11);
    assert_eq!(c.triangulations.len(), 21);
    let c = census(SurfaceKind::non_orientable(1), CensusOptions::default()).unwrap();
    assert!(
        c.per_vertex_count
            .iter()
            .any(|f| f.vertices == 9 && f.classes == 0)
    );
}
