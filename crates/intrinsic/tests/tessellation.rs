//! The Delaunay tessellation: co-circular triangles merged into inscribed polygons, checked
//! with independent planar geometry (circumcircles from coordinates).

mod common;

use surftopo_intrinsic::generators::{flat_torus, random_flips};
use surftopo_intrinsic::{
    DEFAULT_COCIRCULAR_TOLERANCE, DelaunayOptions, IntrinsicTriangulation, Portalgon,
    delaunay_tessellation, flip_to_delaunay,
};
use surftopo_mesh::generators::icosphere;

/// A unit cube, each square face split along one diagonal.
pub fn cube(flip_diagonals: bool) -> IntrinsicTriangulation {
    let (positions, quads) = surftopo_testkit::unit_cube();
    let mut triangles = Vec::new();
    for [a, b, c, d] in quads {
        if flip_diagonals {
            triangles.extend([[a, b, d], [b, c, d]]);
        } else {
            triangles.extend([[a, b, c], [a, c, d]]);
        }
    }
    IntrinsicTriangulation::from_soup(&positions, &triangles)
        .unwrap()
        .0
}

/// Independent check: every polygon is convex, counter-clockwise, and inscribed in a circle
/// (circumcentre of its first three corners, by Cramer's rule).
fn check_inscribed_convex(p: &Portalgon, tol: f64) {
    for q in p.polygons() {
        let c = p.corners(q);
        let k = c.len();
        for i in 0..k {
            let (a, b, d) = (c[i], c[(i + 1) % k], c[(i + 2) % k]);
            let turn = (b[0] - a[0]) * (d[1] - b[1]) - (b[1] - a[1]) * (d[0] - b[0]);
            assert!(
                turn > 0.0,
                "polygon {q:?} not strictly convex at corner {}",
                (i + 1) % k
            );
        }
        let (a, b, d) = (c[0], c[1], c[2]);
        let det = 2.0 * ((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]));
        let (b2, d2) = (
            (b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2),
            (d[0] - a[0]).powi(2) + (d[1] - a[1]).powi(2),
        );
        let ux = ((d[1] - a[1]) * b2 - (b[1] - a[1]) * d2) / det;
        let uy = ((b[0] - a[0]) * d2 - (d[0] - a[0]) * b2) / det;
        let r = ux.hypot(uy);
        for x in &c {
            let rr = (x[0] - a[0] - ux).hypot(x[1] - a[1] - uy);
            assert!(
                (rr - r).abs() <= tol * r,
                "polygon {q:?} not inscribed: {rr} vs {r}"
            );
        }
    }
}

#[test]
fn the_cube_tessellation_is_six_unit_squares() {
    for flip in [false, true] {
        let mut tri = cube(flip);
        let report = flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
        assert_eq!(report.flips, 0);
        let t = delaunay_tessellation(&tri, DEFAULT_COCIRCULAR_TOLERANCE);
        let p = &t.portalgon;
        assert_eq!(p.polygon_count(), 6);
        assert_eq!(t.merged_edges.len(), 6);
        assert_eq!(t.cycle_edges, 0);
        for q in p.polygons() {
            assert_eq!(p.polygon_sides(q).len(), 4);
            for &s in p.polygon_sides(q) {
                assert!((p.side_length(s) - 1.0).abs() < 1e-14);
            }
        }
        p.check_closed().unwrap();
        assert_eq!(p.vertex_classes().1, 8);
        assert!((p.area() - 6.0).abs() < 1e-12);
        check_inscribed_convex(p, 1e-12);
    }
}

#[test]
fn integer_t_x_gives_one_rectangle_and_fractional_t_x_two_triangles() {
    let mut tri = flat_torus(5.0, 1).unwrap();
    flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
    let t = delaunay_tessellation(&tri, DEFAULT_COCIRCULAR_TOLERANCE);
    let p = &t.portalgon;
    assert_eq!(p.polygon_count(), 1);
    let q = p.polygons().next().unwrap();
    let mut l: Vec<f64> = p
        .polygon_sides(q)
        .iter()
        .map(|&s| p.side_length(s))
        .collect();
    l.sort_by(f64::total_cmp);
    for (got, want) in l.iter().zip([1.0, 1.0, 2.0, 2.0]) {
        assert!((got - want).abs() < 1e-9, "{l:?}");
    }
    // Opposite sides of the rectangle are glued: side i to side i + 2.
    for (i, &s) in p.polygon_sides(q).iter().enumerate() {
        assert_eq!(p.mate(s), Some(p.polygon_sides(q)[(i + 2) % 4]));
    }
    check_inscribed_convex(p, 1e-9);

    let mut tri = flat_torus(5.4, 1).unwrap();
    flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
    let t = delaunay_tessellation(&tri, DEFAULT_COCIRCULAR_TOLERANCE);
    assert_eq!(t.portalgon.polygon_count(), 2);
    assert!(t.merged_edges.is_empty());
}

#[test]
fn tessellations_of_generic_surfaces_are_their_triangulations() {
    let s = icosphere(2);
    let mut tri = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap();
    random_flips(&mut tri, 500, 7);
    flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
    let t = delaunay_tessellation(&tri, DEFAULT_COCIRCULAR_TOLERANCE);
    let p = &t.portalgon;
    // Every polygon is inscribed; the surface is the same (area, vertices, Euler characteristic).
    check_inscribed_convex(p, 1e-9);
    p.check_closed().unwrap();
    let v = p.vertex_classes().1;
    assert_eq!(v, tri.mesh().vertex_count());
    let euler = v as i64 - (p.side_count() / 2) as i64 + p.polygon_count() as i64;
    assert_eq!(euler, 2);
    assert!((p.area() - common::area(&tri)).abs() < 1e-9);
    // The faces listed per polygon partition the triangulation's faces.
    assert_eq!(t.faces.len(), tri.mesh().face_count());
    let mut seen = vec![false; tri.mesh().face_slots()];
    for (k, q) in p.polygons().enumerate() {
        assert_eq!(p.polygon_sides(q).len(), t.faces_of(k).len() + 2);
        for f in t.faces_of(k) {
            assert!(!std::mem::replace(&mut seen[f.idx()], true));
        }
    }
}

#[test]
fn refined_flat_torus_tessellates_into_parallelograms_or_triangles() {
    // The 4 x 4 refinement of T_1 ((1,0), (1,2)): the Delaunay tessellation of 16 points on a
    // lattice is made of lattice cells; every polygon is inscribed and the area is 2.
    let mut tri = flat_torus(1.0, 4).unwrap();
    flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
    let t = delaunay_tessellation(&tri, DEFAULT_COCIRCULAR_TOLERANCE);
    let p = &t.portalgon;
    check_inscribed_convex(p, 1e-9);
    assert!((p.area() - 2.0).abs() < 1e-9);
    assert_eq!(p.vertex_classes().1, 16);
    // (1,0)/4 and (0,2)/4 span rectangles: 16 rectangles.
    assert_eq!(p.polygon_count(), 16);
}
