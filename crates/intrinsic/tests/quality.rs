//! Aspect ratios and singular vertices (Section 2.2), against closed forms.

use surftopo_intrinsic::generators::flat_torus;
use surftopo_intrinsic::{DEFAULT_ANGLE_TOLERANCE, IntrinsicTriangulation, quality};

#[test]
fn t_x_aspect_ratio_is_x_squared_over_2_plus_2() {
    // Triangle (0,0), (1,0), (x,2): longest side √(x² + 4), area 1, so the smallest height is
    // 2 / √(x² + 4) and the (local) aspect ratio (x² + 4) / 2 — Theorem 2's O(x²).
    for x in [1.5, 3.0, 10.0, 100.0] {
        let q = quality(&flat_torus(x, 1).unwrap(), DEFAULT_ANGLE_TOLERANCE);
        let want = (x * x + 4.0) / 2.0;
        assert!((q.aspect_ratio - want).abs() <= 1e-9 * want, "x = {x}");
        assert!((q.local_aspect_ratio - want).abs() <= 1e-9 * want);
        assert!((q.area - 2.0).abs() < 1e-9);
        assert_eq!((q.genus, q.loops, q.flat_vertices), (1, 3, 1));
        assert!(q.singular_vertices.is_empty());
    }
}

#[test]
fn aspect_ratio_compares_different_triangles() {
    // A unit cube split into right isosceles triangles: longest side √2, smallest height √2/2,
    // aspect ratio 2; every corner is singular (angle 3π/2).
    let (positions, quads) = surftopo_testkit::unit_cube();
    let mut triangles = Vec::new();
    for [a, b, c, d] in quads {
        triangles.extend([[a, b, c], [a, c, d]]);
    }
    let (tri, _) = IntrinsicTriangulation::from_soup(&positions, &triangles).unwrap();
    let q = quality(&tri, DEFAULT_ANGLE_TOLERANCE);
    assert!((q.aspect_ratio - 2.0).abs() < 1e-12);
    assert!((q.local_aspect_ratio - 2.0).abs() < 1e-12);
    assert_eq!(q.singular_vertices, (0..8).collect::<Vec<u32>>());
    assert_eq!((q.flat_vertices, q.loops, q.genus), (0, 0, 0));
    // Stretch the cube along z by 10: the side faces get sides 10 and √101 with heights down to
    // 10/√101, while the top and bottom keep heights √2/2. Aspect ratio √101 / (√2/2); local
    // aspect ratio √101 / (10 / √101) = 10.1.
    let tall: Vec<[f64; 3]> = positions
        .iter()
        .map(|p| [p[0], p[1], 10.0 * p[2]])
        .collect();
    let (tri, _) = IntrinsicTriangulation::from_soup(&tall, &triangles).unwrap();
    let q = quality(&tri, DEFAULT_ANGLE_TOLERANCE);
    let want = 101f64.sqrt() / (0.5 * 2f64.sqrt());
    assert!(
        (q.aspect_ratio - want).abs() < 1e-9 * want,
        "{}",
        q.aspect_ratio
    );
    assert!((q.local_aspect_ratio - 10.1).abs() < 1e-9);
    assert!(q.local_aspect_ratio <= q.aspect_ratio);
}
