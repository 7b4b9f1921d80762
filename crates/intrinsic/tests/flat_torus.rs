//! The flat torus T_x of Section 9: exact flip counts and the final rectangle.

mod common;

use proptest::prelude::*;
use std::f64::consts::TAU;
use surftopo_intrinsic::generators::flat_torus;
use surftopo_intrinsic::{DelaunayOptions, flip_to_delaunay};

#[test]
fn t_x_has_one_vertex_two_triangles_three_edges() {
    let tri = flat_torus(3.0, 1).unwrap();
    let m = tri.mesh();
    assert_eq!(
        (m.vertex_count(), m.edge_count(), m.face_count()),
        (1, 3, 2)
    );
    assert_eq!(m.genus(), 1);
    m.check_invariants().unwrap();
    // Triangle (0,0), (1,0), (3,2): sides 1, √8, √13; area 1 each.
    let mut l: Vec<f64> = tri.lengths().to_vec();
    l.sort_by(f64::total_cmp);
    for (got, want) in l.iter().zip([1.0, 8f64.sqrt(), 13f64.sqrt()]) {
        assert!((got - want).abs() < 1e-15);
    }
    assert!((common::area(&tri) - 2.0).abs() < 1e-12);
    // The one vertex is flat.
    let sums = common::angle_sums(&tri);
    assert!((sums[0] - TAU).abs() < 1e-12);
}

#[test]
fn integer_x_needs_exactly_x_minus_1_flips_and_ends_in_the_rectangle() {
    for x in [2u32, 3, 4, 7, 10, 37, 100, 1000] {
        let mut tri = flat_torus(f64::from(x), 1).unwrap();
        let report = flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
        assert_eq!(report.flips, u64::from(x) - 1, "x = {x}");
        let mut l: Vec<f64> = tri.lengths().to_vec();
        l.sort_by(f64::total_cmp);
        for (got, want) in l.iter().zip([1.0, 2.0, 5f64.sqrt()]) {
            assert!((got - want).abs() < 1e-8, "x = {x}: lengths {l:?}");
        }
        common::check_delaunay(&tri, 1e-9).unwrap();
        assert!((common::area(&tri) - 2.0).abs() < 1e-9);
    }
}

#[test]
fn refined_torus_is_flat_everywhere_and_ends_delaunay() {
    for (x, m) in [(5.0, 2), (7.5, 3), (20.0, 4)] {
        let mut tri = flat_torus(x, m).unwrap();
        let mesh = tri.mesh();
        let n = (m * m) as usize;
        assert_eq!(
            (mesh.vertex_count(), mesh.edge_count(), mesh.face_count()),
            (n, 3 * n, 2 * n)
        );
        mesh.check_invariants().unwrap();
        let sums = common::angle_sums(&tri);
        assert!(sums.iter().all(|s| (s - TAU).abs() < 1e-9), "{sums:?}");
        flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
        common::check_delaunay(&tri, 1e-9).unwrap();
        assert!((common::area(&tri) - 2.0).abs() < 1e-9);
        common::assert_same_angle_sums(&tri, &sums, 1e-9);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]
    /// Non-integer x: ⌈x⌉ - 1 flips (the first coordinate of the long side drops by 1 per flip
    /// while it exceeds 1), and the result is Delaunay.
    #[test]
    fn fractional_x_needs_ceil_x_minus_1_flips(x in 1.01f64..60.0) {
        prop_assume!((x - x.round()).abs() > 1e-6);
        let mut tri = flat_torus(x, 1).unwrap();
        let report = flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
        prop_assert_eq!(report.flips, x.ceil() as u64 - 1);
        common::check_delaunay(&tri, 1e-9).unwrap();
        // The final lattice basis: (1, 0), (x - ⌈x⌉ + 1, 2), (x - ⌈x⌉, 2).
        let f = x - x.ceil();
        let mut want = [1.0, (f + 1.0).hypot(2.0), f.hypot(2.0)];
        want.sort_by(f64::total_cmp);
        let mut l: Vec<f64> = tri.lengths().to_vec();
        l.sort_by(f64::total_cmp);
        for (got, w) in l.iter().zip(want) {
            prop_assert!((got - w).abs() < 1e-9);
        }
    }
}
