//! Theorem 1 on flat tori (`dubois::delaunay_tessellation_flat`): the exact pipeline on Section
//! 9's `T_x` gives exactly `D_x`, checked here with exact rational arithmetic on the output's
//! corners — integer `x`: one rectangle with sides of squared lengths 1 and 4 meeting at right
//! angles; otherwise two triangles with squared sides `{1, p² + 4, (1 − p)² + 4}`, `p = x − ⌊x⌋`.

use surftopo_intrinsic::Portalgon;
use surftopo_intrinsic::dubois::{
    FlatDelaunayError, FlatDelaunayOptions, delaunay_tessellation_flat,
};
use surftopo_intrinsic::geometry::Rational;

fn q(s: &str) -> Rational {
    s.parse().unwrap()
}

/// The triangle `(0, 0), (1, 0), (x, 2)`.
fn needle(x: &Rational) -> [[Rational; 2]; 3] {
    [[q("0"), q("0")], [q("1"), q("0")], [x.clone(), q("2")]]
}

/// `T_x = R²/⟨(1, 0), (x, 2)⟩` as the triangles `0, u, v` and `u + v, v, u`, side i to side i.
fn t_x(x: &Rational) -> Portalgon<Rational> {
    let (z, one, two) = (q("0"), q("1"), q("2"));
    let mut p = Portalgon::<Rational>::empty();
    let a = p.add_polygon(&needle(x)).unwrap();
    let b = p
        .add_polygon(&[
            [x.clone() + one.clone(), two.clone()],
            [x.clone(), two],
            [one, z],
        ])
        .unwrap();
    for i in 0..3 {
        p.glue(p.side(a, i), p.side(b, i), 0.0).unwrap();
    }
    p
}

/// Squared side lengths of a polygon given by its corners, and the dot products of consecutive
/// sides (at each corner).
fn sides_and_dots(c: &[[Rational; 2]]) -> (Vec<Rational>, Vec<Rational>) {
    let n = c.len();
    let e: Vec<[Rational; 2]> = (0..n)
        .map(|i| {
            let j = (i + 1) % n;
            [
                c[j][0].clone() - c[i][0].clone(),
                c[j][1].clone() - c[i][1].clone(),
            ]
        })
        .collect();
    let len2 = e
        .iter()
        .map(|v| v[0].clone() * v[0].clone() + v[1].clone() * v[1].clone())
        .collect();
    let dots = (0..n)
        .map(|i| {
            let (a, b) = (&e[i], &e[(i + 1) % n]);
            a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone()
        })
        .collect();
    (len2, dots)
}

fn sorted(mut v: Vec<Rational>) -> Vec<Rational> {
    v.sort_by(|a, b| a.partial_cmp(b).unwrap());
    v
}

#[test]
fn the_exact_pipeline_gives_d_x_on_t_x() {
    for (x, p) in [
        ("1000", None),
        ("1000000000", None),
        ("1000000000000000000", None),
        ("3000000001/3", Some(q("1/3"))),
    ] {
        let out = delaunay_tessellation_flat(&t_x(&q(x)), &FlatDelaunayOptions::default())
            .unwrap_or_else(|e| panic!("T_{x}: {e}"));
        let t = &out.delaunay.tessellation;
        let polygons: Vec<_> = t.polygons().collect();
        assert_eq!(out.delaunay.sources.len(), 1, "T_{x}: one vertex");
        assert!(t.unmatched_sides().next().is_none(), "T_{x}: closed");
        assert_eq!(t.area(), q("2"), "T_{x}: the area of T_x");
        assert!(out.reduction.outer_iterations > 0);
        assert!(out.reduction.inner_passes_total <= out.reduction.inner_passes_bound);
        match p {
            None => {
                assert_eq!(polygons.len(), 1, "T_{x}: one rectangle");
                let (len2, dots) = sides_and_dots(&t.corners(polygons[0]));
                assert_eq!(len2.len(), 4, "T_{x}: four sides");
                let (a, b) = (len2[0].clone(), len2[1].clone());
                assert_eq!(sorted(vec![a.clone(), b.clone()]), vec![q("1"), q("4")]);
                assert_eq!(len2, vec![a.clone(), b.clone(), a, b], "T_{x}");
                assert!(dots.iter().all(|d| *d == q("0")), "T_{x}: right angles");
            }
            Some(p) => {
                assert_eq!(polygons.len(), 2, "T_{x}: two triangles");
                let one = q("1");
                let four = q("4");
                let want = sorted(vec![
                    one.clone(),
                    p.clone() * p.clone() + four.clone(),
                    (one.clone() - p.clone()) * (one - p) + four,
                ]);
                for &poly in &polygons {
                    let (len2, _) = sides_and_dots(&t.corners(poly));
                    assert_eq!(sorted(len2), want, "T_{x}");
                }
            }
        }
    }
}

#[test]
fn a_cone_point_is_refused_by_name() {
    // The regular tetrahedron of side 1 in f64: four cone points of angle π.
    let h = 3f64.sqrt() / 2.0;
    let tri = [[0.0, 0.0], [1.0, 0.0], [0.5, h]];
    let mut p = Portalgon::<f64>::empty();
    let f: Vec<_> = (0..4).map(|_| p.add_polygon(&tri).unwrap()).collect();
    // Faces 0..3 around vertex 0 (faces 0, 1, 2) and face 3 opposite.
    let pairs = [
        ((0, 0), (1, 2)),
        ((1, 0), (2, 2)),
        ((2, 0), (0, 2)),
        ((0, 1), (3, 0)),
        ((1, 1), (3, 2)),
        ((2, 1), (3, 1)),
    ];
    for ((a, i), (b, j)) in pairs {
        p.glue(p.side(f[a], i), p.side(f[b], j), 1e-9).unwrap();
    }
    p.check_closed().unwrap();
    let err = delaunay_tessellation_flat(&p, &FlatDelaunayOptions::default()).unwrap_err();
    assert!(
        matches!(err, FlatDelaunayError::ConePoint { side: 0, .. }),
        "{err}"
    );
    assert!(err.to_string().contains("cone point"), "{err}");
}

/// The doubly covered triangle `(0, 0), (1, 0), (x, 2)`: three cone points, a needle for large x.
fn needle_pillow(x: &Rational) -> Portalgon<Rational> {
    let (z, one, two) = (q("0"), q("1"), q("2"));
    let mut p = Portalgon::<Rational>::empty();
    let a = p.add_polygon(&needle(x)).unwrap();
    // Its mirror image across the x axis, counter-clockwise.
    let b = p
        .add_polygon(&[[z.clone(), z.clone()], [x.clone(), -two], [one, z]])
        .unwrap();
    for (i, j) in [(0, 2), (1, 1), (2, 0)] {
        p.glue(p.side(a, i), p.side(b, j), 0.0).unwrap();
    }
    p.check_closed().unwrap();
    p
}

#[test]
fn auto_flips_moderate_surfaces_and_reduces_flat_needles() {
    use surftopo_intrinsic::{
        AUTO_ASPECT_LIMIT, DUBOIS_TAKES_CONE_POINTS, DelaunayMethod as Method, choose_method,
        largest_aspect_ratio,
    };
    // T_x's triangles have aspect ratio ℓ²/(2A) = (x² + 4)/2 (area 1, longest side² x² + 4).
    assert_eq!(largest_aspect_ratio(&t_x(&q("10"))), 52.0);
    assert_eq!(choose_method(&t_x(&q("10"))), Method::Flip);
    assert_eq!(choose_method(&t_x(&q("447"))), Method::Flip); // aspect 99906.5
    assert_eq!(choose_method(&t_x(&q("448"))), Method::Dubois); // aspect 100354
    assert_eq!(choose_method(&t_x(&q("3000000001/3"))), Method::Dubois);
    // A needle with cone points: dubois exactly when `DUBOIS_TAKES_CONE_POINTS` (see its doc).
    let pillow = needle_pillow(&q("1000"));
    assert!(largest_aspect_ratio(&pillow) > AUTO_ASPECT_LIMIT);
    let expected = if DUBOIS_TAKES_CONE_POINTS {
        Method::Dubois
    } else {
        Method::Flip
    };
    assert_eq!(choose_method(&pillow), expected);
    // The same pillow, not a needle: flipping.
    assert_eq!(choose_method(&needle_pillow(&q("3"))), Method::Flip);
    // The same rule on intrinsic triangulations (lengths in f64).
    let by_lengths = |p: &Portalgon<Rational>| {
        let tri = surftopo_intrinsic::PortalgonDoc::from_portalgon(p)
            .to_triangulation(1e-9)
            .unwrap();
        surftopo_intrinsic::choose_method_for_triangulation(&tri)
    };
    assert_eq!(by_lengths(&t_x(&q("10"))), Method::Flip);
    assert_eq!(by_lengths(&t_x(&q("1000"))), Method::Dubois);
    assert_eq!(by_lengths(&pillow), expected);
    assert_eq!(by_lengths(&needle_pillow(&q("3"))), Method::Flip);
}

#[test]
fn flipping_unless_a_needle_leaves_needles_untouched_and_flips_the_rest_like_flipping() {
    use surftopo_intrinsic::{DelaunayMethod as Method, choose_method_for_triangulation};
    use surftopo_intrinsic::{DelaunayOptions, flip_to_delaunay, flip_to_delaunay_unless_needle};
    let options = DelaunayOptions::default();
    for (x, needle) in [("10", false), ("447", false), ("448", true), ("1000", true)] {
        let tri = surftopo_intrinsic::PortalgonDoc::from_portalgon(&t_x(&q(x)))
            .to_triangulation(1e-9)
            .unwrap();
        // The rule's own pass decides the same as the test inside flipping.
        assert_eq!(
            choose_method_for_triangulation(&tri) == Method::Dubois,
            needle,
            "x = {x}"
        );
        let mut fused = tri.clone();
        let report = flip_to_delaunay_unless_needle(&mut fused, &options).unwrap();
        if needle {
            assert!(report.is_none(), "x = {x}");
            assert_eq!(fused.lengths(), tri.lengths(), "x = {x}: nothing flipped");
        } else {
            let mut flipped = tri.clone();
            let expected = flip_to_delaunay(&mut flipped, &options).unwrap();
            assert_eq!(report, Some(expected), "x = {x}");
            assert!(expected.flips > 0);
            assert_eq!(fused.lengths(), flipped.lengths(), "x = {x}");
        }
    }
}

#[test]
fn a_degenerate_triangle_counts_as_a_needle_before_any_flip() {
    use surftopo_intrinsic::{
        DelaunayOptions, IntrinsicTriangulation, flip_to_delaunay, flip_to_delaunay_unless_needle,
    };
    // The unit tetrahedron with one triangle flattened: its sides 1, 1, 2.
    let mesh = surftopo_mesh::generators::tetrahedron().mesh;
    let mut lengths = vec![1.0; mesh.edge_slots()];
    let f = mesh.faces().next().unwrap();
    let e = mesh.face_halfedges(f)[0].edge();
    lengths[e.idx()] = 2.0;
    let tri = IntrinsicTriangulation::from_parts(mesh, lengths).unwrap();
    let options = DelaunayOptions::default();
    let mut flipped = tri.clone();
    assert!(flip_to_delaunay(&mut flipped, &options).is_err());
    let mut fused = tri.clone();
    assert!(
        flip_to_delaunay_unless_needle(&mut fused, &options)
            .unwrap()
            .is_none()
    );
    assert_eq!(fused.lengths(), tri.lengths(), "nothing flipped");
}
