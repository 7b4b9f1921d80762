//! The flip algorithm on synthetic surfaces: results checked by the independent verifiers of
//! `common` (law of cosines, Heron), never by the crate's own formulas.

mod common;

use proptest::prelude::*;
use surftopo_intrinsic::generators::{flat_torus, random_flips, sheared_torus};
use surftopo_intrinsic::{
    DelaunayError, DelaunayOptions, GeometryError, IntrinsicTriangulation, delaunay_with_stats,
    flip_to_delaunay,
};
use surftopo_mesh::generators::{icosphere, torus};
use surftopo_mesh::{EdgeId, SurfaceMesh};

fn from_surface(s: surftopo_mesh::Surface) -> IntrinsicTriangulation {
    IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap()
}

/// Flips to Delaunay and checks the result independently: Delaunay edges, same area, same angle
/// sums, valid mesh.
fn flip_and_check(mut tri: IntrinsicTriangulation) -> (IntrinsicTriangulation, u64) {
    let area = common::area(&tri);
    let sums = common::angle_sums(&tri);
    let report = flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
    assert_eq!(report.non_delaunay_edges, 0);
    common::check_delaunay(&tri, 1e-9).unwrap();
    let after = common::area(&tri);
    assert!(
        (area - after).abs() <= 1e-9 * area,
        "area {area} -> {after}"
    );
    common::assert_same_angle_sums(&tri, &sums, 1e-8);
    (tri, report.flips)
}

#[test]
fn delaunay_input_needs_no_flip() {
    // A regular icosahedron is Delaunay (all edges have opposite angles π/3 + π/3).
    let (_, flips) = flip_and_check(from_surface(icosphere(0)));
    assert_eq!(flips, 0);
}

#[test]
fn randomly_flipped_spheres_and_tori_come_back_to_delaunay() {
    for (k, surface) in [icosphere(2), torus(12, 7), torus(5, 30)]
        .into_iter()
        .enumerate()
    {
        let mut tri = from_surface(surface);
        let made = random_flips(&mut tri, 400, k as u64);
        assert!(made > 100, "only {made} random flips");
        assert!(tri.non_delaunay_edges(1e-12) > 0);
        let (tri, flips) = flip_and_check(tri);
        assert!(flips > 0);
        tri.mesh().check_invariants().unwrap();
    }
}

#[test]
fn sheared_tori_end_delaunay() {
    for shear in [1, 4, 9] {
        let s = sheared_torus(20, 24, shear);
        let (_, flips) = flip_and_check(from_surface(s));
        assert!(flips > 0, "shear {shear}");
    }
}

#[test]
fn stats_have_the_promised_keys_and_figures() {
    let mut tri = from_surface(sheared_torus(10, 12, 3));
    let stats = delaunay_with_stats(&mut tri, &DelaunayOptions::default()).unwrap();
    assert_eq!((stats.vertices, stats.edges, stats.faces), (120, 360, 240));
    let json = serde_json::to_value(&stats).unwrap();
    for key in [
        "vertices",
        "edges",
        "faces",
        "flips",
        "non_delaunay_edges",
        "seconds",
    ] {
        assert!(json.get(key).is_some(), "missing {key}");
    }
    assert_eq!(json["non_delaunay_edges"], 0);
    assert_eq!(json["flips"].as_u64().unwrap(), stats.flips);
    assert!(stats.flips > 0);
}

#[test]
fn flip_budget_stops_with_a_typed_error() {
    let mut tri = flat_torus(1000.0, 1).unwrap();
    let options = DelaunayOptions {
        max_flips: Some(10),
        ..DelaunayOptions::default()
    };
    match flip_to_delaunay(&mut tri, &options) {
        Err(DelaunayError::MaxFlips { flips, pending }) => {
            assert_eq!(flips, 10);
            assert!(pending >= 1);
        }
        other => panic!("expected MaxFlips, got {other:?}"),
    }
    // The triangulation is still a valid one of the same torus.
    tri.validate().unwrap();
    tri.mesh().check_invariants().unwrap();
    assert!((common::area(&tri) - 2.0).abs() < 1e-6);
}

/// A tetrahedron-shaped sphere (4 vertices) with given lengths: edges of [0,2,1],[0,1,3],[1,2,3],
/// [0,3,2] in build order.
fn tetrahedron_with(lengths: impl Fn(u32, u32) -> f64) -> IntrinsicTriangulation {
    let mesh = SurfaceMesh::tetrahedron();
    let l = (0..mesh.edge_slots())
        .map(|e| {
            let [a, b] = mesh.edge_vertices(EdgeId::new(e));
            lengths(a.0.min(b.0), a.0.max(b.0))
        })
        .collect();
    IntrinsicTriangulation::from_parts(mesh, l).unwrap()
}

#[test]
fn degenerate_input_is_refused_naming_the_element() {
    // A zero-length edge.
    let mut tri = tetrahedron_with(|a, b| if (a, b) == (0, 1) { 0.0 } else { 1.0 });
    let zero = tri.mesh().edges().find(|&e| tri.length(e) == 0.0).unwrap();
    match flip_to_delaunay(&mut tri, &DelaunayOptions::default()) {
        Err(DelaunayError::Geometry(GeometryError::NonPositiveLength { edge, .. })) => {
            assert_eq!(edge, zero.0)
        }
        other => panic!("{other:?}"),
    }
    // A violated triangle inequality: edge (2,3) of length 5 with the others 1.
    let mut tri = tetrahedron_with(|a, b| if (a, b) == (2, 3) { 5.0 } else { 1.0 });
    match flip_to_delaunay(&mut tri, &DelaunayOptions::default()) {
        Err(DelaunayError::Geometry(GeometryError::TriangleInequality { face, sides })) => {
            assert!(sides.contains(&5.0));
            let f = surftopo_mesh::FaceId(face);
            let long = tri
                .mesh()
                .face_halfedges(f)
                .iter()
                .any(|h| tri.length(h.edge()) == 5.0);
            assert!(long);
        }
        other => panic!("{other:?}"),
    }
    // Zero area: 2 = 1 + 1.
    let mut tri = tetrahedron_with(|a, b| if (a, b) == (2, 3) { 2.0 } else { 1.0 });
    assert!(matches!(
        flip_to_delaunay(&mut tri, &DelaunayOptions::default()),
        Err(DelaunayError::Geometry(GeometryError::ZeroArea { .. }))
    ));
    // Non-finite lengths never enter.
    let mesh = SurfaceMesh::tetrahedron();
    let mut l = vec![1.0; mesh.edge_slots()];
    l[3] = f64::NAN;
    assert!(matches!(
        IntrinsicTriangulation::from_parts(mesh, l),
        Err(GeometryError::NonFiniteLength { edge: 3, .. })
    ));
}

#[test]
fn mollification_repairs_degenerate_input() {
    for (bad, value) in [((0, 1), 0.0), ((2, 3), 2.0), ((2, 3), 2.5)] {
        let mut tri = tetrahedron_with(|a, b| if (a, b) == bad { value } else { 1.0 });
        let options = DelaunayOptions {
            mollify: Some(1e-6),
            ..DelaunayOptions::default()
        };
        let report = flip_to_delaunay(&mut tri, &options).unwrap();
        let delta = report.mollify_delta.unwrap();
        assert!(delta > 0.0);
        // Every triangle now satisfies l_ij + l_jk - l_ki >= ε = 1e-6 · mean (up to rounding).
        let mean = tri.lengths().iter().sum::<f64>() / 6.0;
        for f in tri.mesh().faces() {
            let [a, b, c] = common::sides(&tri, f);
            for (x, y, z) in [(a, b, c), (b, c, a), (c, a, b)] {
                assert!(x + y - z >= 1e-6 * (mean - delta) * 0.999, "{a} {b} {c}");
            }
        }
        common::check_delaunay(&tri, 1e-9).unwrap();
    }
    // Valid input: nothing to add.
    let mut tri = from_surface(icosphere(1));
    let before = tri.lengths().to_vec();
    let options = DelaunayOptions {
        mollify: Some(1e-6),
        ..DelaunayOptions::default()
    };
    let report = flip_to_delaunay(&mut tri, &options).unwrap();
    assert_eq!(report.mollify_delta, Some(0.0));
    assert_eq!(tri.lengths(), &before[..]);
    // A bad epsilon is refused.
    let bad = DelaunayOptions {
        mollify: Some(-1.0),
        ..DelaunayOptions::default()
    };
    assert!(matches!(
        flip_to_delaunay(&mut tri, &bad),
        Err(DelaunayError::InvalidMollify(_))
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]
    #[test]
    fn random_flips_of_a_torus_then_delaunay(seed in any::<u64>(), count in 1u64..300) {
        let mut tri = from_surface(torus(9, 6));
        random_flips(&mut tri, count, seed);
        let (tri, _) = flip_and_check(tri);
        // Same seed, same result.
        let mut again = from_surface(torus(9, 6));
        random_flips(&mut again, count, seed);
        flip_to_delaunay(&mut again, &DelaunayOptions::default()).unwrap();
        prop_assert_eq!(tri, again);
    }
}
