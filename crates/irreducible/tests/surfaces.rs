//! Irreducible triangulations of every compact surface: boundary loops, non-orientable
//! components, several pieces. Each output is checked independently of the algorithms: the
//! topology of every piece (`surftopo_testkit::classify_surface`, hash maps over the triangles)
//! and irreducibility by Dey et al.'s rule on the triangles (`is_irreducible_surface`); the
//! known vertex counts are those of the literature (Barnette; Lawrencenko; Lawrencenko–Negami,
//! Sulanke; the Möbius band's two irreducible triangulations).

use surftopo_irreducible::{Algorithm, is_irreducible_surface, reduce_surface};
use surftopo_mesh::generators::{
    self, annulus, connected_sum, copies, crosscaps, cut_holes, disk, klein_bottle, mobius_band,
    projective_plane,
};
use surftopo_mesh::{CoveredSurface, Lifting};
use surftopo_testkit::classify_surface;

/// A random refinement of `s` (subdivided, flipped, split: irregular connectivity).
fn refined(s: &CoveredSurface, seed: u64) -> CoveredSurface {
    let sub = generators::subdivide_midpoint_covered(s, 1);
    let flips = 3 * sub.cover.surface_faces().count();
    let flipped = generators::random_flips_covered(&sub, flips, seed);
    generators::random_vertex_splits_covered(&flipped, 30, seed + 1)
}

/// Reduces `s` with `algorithm`, checks the result independently, and returns the vertex count
/// of each piece of the output (sorted by the pieces' classification).
fn reduce_and_check(s: &CoveredSurface, algorithm: Algorithm) -> Vec<usize> {
    let input = s.cover.surface_triangles();
    let want = classify_surface(&input).unwrap();
    let red = reduce_surface(s.cover.clone(), algorithm).unwrap();
    red.cover.mesh.check_invariants().unwrap();
    let output = red.cover.surface_triangles();
    let tag = algorithm.name();
    assert_eq!(
        classify_surface(&output).unwrap(),
        want,
        "{tag}: topology changed"
    );
    assert!(is_irreducible_surface(&output), "{tag}: output reducible");
    if algorithm == Algorithm::RamaswamiSiqueira {
        assert_eq!(
            red.counters.edges_tested_more_than_once, 0,
            "RS tests no edge twice"
        );
    }
    // Every contraction removes one vertex of the surface.
    let vertices = |t: &[[u32; 3]]| {
        let mut v: Vec<u32> = t.iter().flatten().copied().collect();
        v.sort_unstable();
        v.dedup();
        v.len()
    };
    assert_eq!(
        vertices(&input) - vertices(&output),
        red.counters.contractions as usize,
        "{tag}"
    );
    // The history replays back to the input cover.
    let mut back = red.cover.clone();
    for record in red.history.iter().rev() {
        back.mesh.split_vertex(record);
    }
    assert_eq!(back.mesh, s.cover.mesh, "{tag}: history does not replay");
    // Vertex count of each piece, pieces in the order of their classification.
    let mut pieces: Vec<(surftopo_testkit::Piece, usize)> = pieces_of(&output)
        .into_iter()
        .map(|p| (classify_surface(&p).unwrap()[0], vertices(&p)))
        .collect();
    pieces.sort();
    pieces.into_iter().map(|(_, v)| v).collect()
}

/// The triangles of each connected component (joined through shared vertices).
fn pieces_of(triangles: &[[u32; 3]]) -> Vec<Vec<[u32; 3]>> {
    let mut root: std::collections::HashMap<u32, u32> = Default::default();
    fn find(root: &mut std::collections::HashMap<u32, u32>, v: u32) -> u32 {
        let r = *root.entry(v).or_insert(v);
        if r == v {
            v
        } else {
            let r = find(root, r);
            root.insert(v, r);
            r
        }
    }
    for t in triangles {
        for i in 1..3 {
            let (a, b) = (find(&mut root, t[0]), find(&mut root, t[i]));
            root.insert(a, b);
        }
    }
    let mut by_root: std::collections::BTreeMap<u32, Vec<[u32; 3]>> = Default::default();
    for t in triangles {
        let r = find(&mut root, t[0]);
        by_root.entry(r).or_default().push(*t);
    }
    by_root.into_values().collect()
}

fn algorithms(seed: u64) -> [Algorithm; 3] {
    Algorithm::all(seed)
}

#[test]
fn known_vertex_counts() {
    // (surface, allowed vertex counts of its irreducible triangulations)
    let cases: Vec<(CoveredSurface, std::ops::RangeInclusive<usize>)> = vec![
        (generators::icosphere(1).into(), 4..=4),
        (generators::torus(6, 5).into(), 7..=10),
        (projective_plane(), 6..=7),
        (klein_bottle(6, 5), 8..=11),
        (disk(3), 3..=3),
        (mobius_band(6, 2), 5..=6),
    ];
    for (k, (s, range)) in cases.iter().enumerate() {
        for seed in 0..6 {
            let input = refined(s, 100 * k as u64 + seed);
            for algorithm in algorithms(seed) {
                let got = reduce_and_check(&input, algorithm);
                assert_eq!(got.len(), 1);
                assert!(
                    range.contains(&got[0]),
                    "{}: {} vertices",
                    algorithm.name(),
                    got[0]
                );
            }
        }
    }
}

#[test]
fn boundaries_crosscaps_and_pieces() {
    let torus: CoveredSurface = generators::torus(10, 8).into();
    let inputs = [
        annulus(8, 3),
        cut_holes(&torus, 3, 4).0,
        cut_holes(&klein_bottle(12, 9), 2, 5).0,
        crosscaps(3),
        connected_sum(&torus, &projective_plane()),
        copies(&mobius_band(7, 2), 2),
        copies(&projective_plane(), 3),
    ];
    for (k, s) in inputs.iter().enumerate() {
        let input = refined(s, 1000 + k as u64);
        assert!(!input.cover.is_plain());
        for algorithm in algorithms(k as u64) {
            reduce_and_check(&input, algorithm);
        }
    }
}

#[test]
fn a_lone_triangle_and_the_tetrahedron_stay() {
    for s in [disk(1), generators::tetrahedron().into()] {
        let s = generators::simplify_covered(&s, 1, 0);
        for algorithm in algorithms(0) {
            let red = reduce_surface(s.cover.clone(), algorithm).unwrap();
            assert!(red.counters.contractions <= 1);
            assert!(is_irreducible_surface(&red.cover.surface_triangles()));
        }
    }
    let red = reduce_surface(disk(1).cover, Algorithm::RamaswamiSiqueira).unwrap();
    assert_eq!(red.cover.surface_triangles().len(), 1);
}

#[test]
fn the_verifier_finds_a_contractible_edge() {
    // Two triangles of a disk: the shared edge joins two boundary vertices (not contractible),
    // a boundary edge is contractible.
    assert!(!is_irreducible_surface(&[[0, 1, 2], [0, 2, 3]]));
    assert!(is_irreducible_surface(&[[0, 1, 2]]));
    // The 6-vertex projective plane is irreducible; one vertex split makes it reducible.
    let rp2 = projective_plane();
    assert!(is_irreducible_surface(&rp2.cover.surface_triangles()));
    let split = generators::random_vertex_splits_covered(&rp2, 1, 3);
    assert!(!is_irreducible_surface(&split.cover.surface_triangles()));
    // An interior edge between two boundary loops of an annulus never contracts.
    let a = annulus(3, 1);
    assert!(a.cover.sheets.apex_class().is_some());
    assert!(is_irreducible_surface(&a.cover.surface_triangles()));
}
