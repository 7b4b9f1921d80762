//! `intrinsic_delaunay`, the job by method: every method gives a triangulation that passes the
//! independent Delaunay check of `common` and the flip route's Laplacian; `auto` resolves as its
//! rule says; exact input gives `D_x` exactly; requests that cannot run are refused by their
//! typed error; what is not asked for is not computed.

mod common;

use surftopo_intrinsic::generators::{flat_torus, flat_torus_portalgon, random_flips};
use surftopo_intrinsic::geometry::Rational;
use surftopo_intrinsic::voronoi::Sources;
use surftopo_intrinsic::{
    AnyPortalgon, DelaunayInput, DelaunayMethod, DelaunayOutputs, DelaunayRequest,
    IntrinsicDelaunayError, IntrinsicTriangulation, RequestError, SparseMatrix, intrinsic_delaunay,
};
use surftopo_mesh::generators::torus;

/// Every output.
const ALL: DelaunayOutputs = DelaunayOutputs {
    triangulation: true,
    tessellation: true,
    reduced: false,
    laplacian: true,
    mass: true,
    figures: true,
};

fn request(method: DelaunayMethod, outputs: DelaunayOutputs) -> DelaunayRequest {
    DelaunayRequest {
        method,
        outputs,
        ..DelaunayRequest::default()
    }
}

/// A torus of revolution stretched along x (thin triangles: flipping has work to do), with
/// random intrinsic flips on top.
fn stretched_torus() -> IntrinsicTriangulation {
    let mut s = torus(14, 7);
    for p in &mut s.positions {
        p[0] *= 3.0;
    }
    let mut tri = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap();
    random_flips(&mut tri, 200, 5);
    tri
}

/// The largest entry of `a − b` relative to the largest entry of `b`.
fn relative_difference(a: &SparseMatrix, b: &SparseMatrix) -> f64 {
    assert_eq!(a.n, b.n);
    let scale = b.triplets().map(|t| t.2.abs()).fold(0.0, f64::max);
    (0..a.n)
        .flat_map(|i| (0..a.n).map(move |j| (i, j)))
        .map(|(i, j)| (a.get(i, j) - b.get(i, j)).abs())
        .fold(0.0, f64::max)
        / scale
}

#[test]
fn every_method_gives_a_delaunay_triangulation_with_the_flip_laplacian() {
    let tri = stretched_torus();
    let area = common::area(&tri);
    let flip = intrinsic_delaunay(
        DelaunayInput::Lengths(tri.clone()),
        &request(DelaunayMethod::Flip, ALL),
    )
    .unwrap();
    let reference = flip.laplacian.as_ref().unwrap();
    assert!(flip.stats.as_ref().unwrap().flips > 0);
    for method in DelaunayMethod::ALL {
        let out =
            intrinsic_delaunay(DelaunayInput::Lengths(tri.clone()), &request(method, ALL)).unwrap();
        let name = method.name();
        let resolved = if method == DelaunayMethod::Auto {
            DelaunayMethod::Flip
        } else {
            method
        };
        assert_eq!(out.method, resolved, "{name}");
        assert_eq!(out.arithmetic, "f64");
        let t = out.triangulation.as_ref().unwrap();
        common::check_delaunay(t, 1e-9).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!((common::area(t) - area).abs() <= 1e-10 * area, "{name}");
        let laplacian = out.laplacian.as_ref().unwrap();
        assert!(relative_difference(laplacian, reference) <= 1e-9, "{name}");
        let mass = out.mass.as_ref().unwrap();
        let total: f64 = (0..mass.n).map(|i| mass.get(i, i)).sum();
        assert!((total - area).abs() <= 1e-10 * area, "{name}");
        let stats = out.stats.as_ref().unwrap();
        assert_eq!(stats.non_delaunay_edges, 0, "{name}");
        assert_eq!(
            (stats.vertices, stats.faces),
            (t.mesh().vertex_count(), t.mesh().face_count())
        );
        assert_eq!(
            out.wave.is_some(),
            resolved != DelaunayMethod::Flip,
            "{name}"
        );
        assert_eq!(
            out.reduction.is_some(),
            resolved == DelaunayMethod::Dubois,
            "{name}"
        );
        let tessellation = out.tessellation.as_ref().unwrap().to_f64();
        assert!((tessellation.area() - area).abs() <= 1e-9 * area, "{name}");
    }
}

#[test]
fn auto_flips_unless_a_flat_needle_then_runs_dubois() {
    let outputs = DelaunayOutputs {
        triangulation: true,
        figures: true,
        ..DelaunayOutputs::default()
    };
    for (x, expected, flips) in [
        (10.0, DelaunayMethod::Flip, 9),
        (1000.0, DelaunayMethod::Dubois, 0),
    ] {
        let out = intrinsic_delaunay(
            DelaunayInput::Lengths(flat_torus(x, 1).unwrap()),
            &request(DelaunayMethod::Auto, outputs),
        )
        .unwrap();
        assert_eq!(out.method, expected, "x = {x}");
        assert_eq!(out.stats.unwrap().flips, flips, "x = {x}");
        // D_x: the rectangle 1 × 2 cut by a diagonal.
        let t = out.triangulation.unwrap();
        let mut lengths: Vec<f64> = t.mesh().edges().map(|e| t.length(e)).collect();
        lengths.sort_by(f64::total_cmp);
        for (l, e) in lengths.iter().zip([1.0, 2.0, 5f64.sqrt()]) {
            assert!((l - e).abs() <= 1e-6, "x = {x}: {lengths:?}");
        }
    }
    // Flipping's limits ask for flipping, the reduced triangulation for dubois.
    let limited = DelaunayRequest {
        max_flips: Some(10_000),
        ..request(DelaunayMethod::Auto, outputs)
    };
    let out = intrinsic_delaunay(
        DelaunayInput::Lengths(flat_torus(10.0, 1).unwrap()),
        &limited,
    )
    .unwrap();
    assert_eq!(out.method, DelaunayMethod::Flip);
    let reduced = DelaunayOutputs {
        reduced: true,
        ..outputs
    };
    let out = intrinsic_delaunay(
        DelaunayInput::Lengths(flat_torus(10.0, 1).unwrap()),
        &request(DelaunayMethod::Auto, reduced),
    )
    .unwrap();
    assert_eq!(out.method, DelaunayMethod::Dubois);
    assert!(out.reduced.is_some());
}

#[test]
fn exact_input_gives_d_x_exactly_by_every_exact_method() {
    // The wave alone does work growing with x (its constellations grow like the flip count):
    // a moderate x for it, a needle for the others.
    let t_x = |x: &str| flat_torus_portalgon(&x.parse::<Rational>().unwrap(), 1).unwrap();
    let outputs = DelaunayOutputs {
        reduced: false,
        ..ALL
    };
    for (method, vertices, resolved, x) in [
        (
            DelaunayMethod::Auto,
            Sources::All,
            DelaunayMethod::Dubois,
            "1000000000001/3",
        ),
        (
            DelaunayMethod::Voronoi,
            Sources::Singular,
            DelaunayMethod::Voronoi,
            "301/3",
        ),
        (
            DelaunayMethod::Dubois,
            Sources::Singular,
            DelaunayMethod::Dubois,
            "1000000000001/3",
        ),
    ] {
        let p = t_x(x);
        let request = DelaunayRequest {
            vertices,
            ..request(method, outputs)
        };
        let out = intrinsic_delaunay(DelaunayInput::Exact(p.clone()), &request).unwrap();
        let name = method.name();
        assert_eq!((out.method, out.arithmetic), (resolved, "exact"), "{name}");
        // x − ⌊x⌋ = 1/3: D_x is two triangles congruent to (0,0), (1,0), (1/3, 2), squared
        // sides 1, 1/9 + 4 = 37/9 and 4/9 + 4 = 40/9.
        let Some(AnyPortalgon::Exact(t)) = &out.tessellation else {
            panic!("{name}: an exact tessellation");
        };
        let mut squared: Vec<Rational> = t.sides().map(|s| t.side_length2(s)).collect();
        squared.sort();
        squared.dedup();
        let expected: Vec<Rational> = ["1", "37/9", "40/9"]
            .iter()
            .map(|v| v.parse().unwrap())
            .collect();
        assert_eq!(squared, expected, "{name}");
        assert_eq!(t.polygon_count(), 2, "{name}");
        let exact = out.exact_triangulation.as_ref().unwrap();
        assert_eq!(exact.area(), p.area(), "{name}");
        common::check_delaunay(out.triangulation.as_ref().unwrap(), 1e-9).unwrap();
    }
}

#[test]
fn requests_that_cannot_run_are_refused_by_their_typed_error() {
    let lengths = || DelaunayInput::Lengths(flat_torus(10.0, 1).unwrap());
    let refused = |input, request: DelaunayRequest| match intrinsic_delaunay(input, &request) {
        Err(IntrinsicDelaunayError::Request(e)) => e,
        other => panic!("{request:?}: {other:?}"),
    };
    let exact = || {
        DelaunayInput::Exact(flat_torus_portalgon(&"10".parse::<Rational>().unwrap(), 1).unwrap())
    };
    let outputs = DelaunayOutputs::default();
    assert_eq!(
        refused(exact(), request(DelaunayMethod::Flip, outputs)),
        RequestError::ExactFlip
    );
    let faithful = DelaunayRequest {
        faithful: true,
        ..request(DelaunayMethod::Voronoi, outputs)
    };
    assert_eq!(
        refused(lengths(), faithful),
        RequestError::FaithfulWithoutDubois
    );
    let reduced = DelaunayOutputs {
        reduced: true,
        ..outputs
    };
    assert_eq!(
        refused(lengths(), request(DelaunayMethod::Flip, reduced)),
        RequestError::ReducedWithoutDubois
    );
    assert_eq!(
        refused(exact(), request(DelaunayMethod::Voronoi, reduced)),
        RequestError::ReducedWithoutDubois
    );
    let limited = DelaunayRequest {
        mollify: Some(1e-3),
        ..request(DelaunayMethod::Dubois, outputs)
    };
    assert_eq!(
        refused(lengths(), limited),
        RequestError::FlipLimitsWithoutFlip
    );
}

#[test]
fn what_is_not_asked_for_is_not_computed() {
    for method in DelaunayMethod::ALL {
        let out = intrinsic_delaunay(
            DelaunayInput::Lengths(stretched_torus()),
            &request(method, DelaunayOutputs::default()),
        )
        .unwrap();
        let name = method.name();
        assert!(out.triangulation.is_none(), "{name}");
        assert!(
            out.tessellation.is_none() && out.reduced.is_none(),
            "{name}"
        );
        assert!(out.laplacian.is_none() && out.mass.is_none(), "{name}");
        assert!(
            out.stats.is_none() && out.exact_triangulation.is_none(),
            "{name}"
        );
    }
}
