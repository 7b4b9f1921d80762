//! Exact Theorem 1 on huge numbers: `T_x` at `x = 10^1000` gives `D_x` in few outer iterations
//! (the periodic exit of docs/dubois.md §3.2, charts at their first corners), and coordinates
//! past the growth limit stop the reduction with a typed error; surfaces with cone points
//! (pillowcases, thin pillowcases, tetrahedra with integer edges) stop at the Delaunay exit of
//! docs/dubois.md §3.8 after about `log₂` of their aspect ratio outer iterations, with a
//! Delaunay tessellation of the input's surface. The growth table is the example `exact_growth`
//! (`results/exact_growth.md`).

use surftopo_intrinsic::Portalgon;
use surftopo_intrinsic::dubois::{
    CapsError, DuboisError, FlatDelaunayOptions, MAX_WORKING_BITS, ReduceOptions,
    delaunay_tessellation_dubois, reduce,
};
use surftopo_intrinsic::generators::{flat_torus_portalgon, pillowcase};
use surftopo_intrinsic::geometry::{Rational, Scalar};

type P = [Rational; 2];

fn corners(t: &Portalgon<Rational>) -> Vec<Vec<P>> {
    t.polygons()
        .map(|p| t.polygon_sides(p).iter().map(|&s| t.start(s)).collect())
        .collect()
}

fn diff(a: &P, b: &P) -> P {
    [a[0].clone() - b[0].clone(), a[1].clone() - b[1].clone()]
}

fn dot(a: &P, b: &P) -> Rational {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone()
}

#[test]
fn t_x_at_ten_to_the_thousand_gives_d_x() {
    let x: Rational = format!("1{}", "0".repeat(1000)).parse().unwrap();
    let t = flat_torus_portalgon(&x, 1).unwrap();
    let out = delaunay_tessellation_dubois(&t, &FlatDelaunayOptions::default()).unwrap();
    // N = ⌈log₂(2 + x² + 4)⌉ = 6644 asked for, a few run.
    assert_eq!(out.reduction.outer_iterations, 6644);
    assert!(
        out.reduction.inner_passes.len() <= 8,
        "{:?}",
        out.reduction.inner_passes
    );
    // D_x: one polygon, a 1 × 2 rectangle (right angles, sides 1, 2, 1, 2), area 2.
    let p = corners(&out.delaunay.tessellation);
    assert_eq!(p.len(), 1);
    let q = &p[0];
    assert_eq!(q.len(), 4);
    let sides: Vec<P> = (0..4).map(|i| diff(&q[(i + 1) % 4], &q[i])).collect();
    for i in 0..4 {
        assert!(dot(&sides[i], &sides[(i + 1) % 4]).is_zero(), "{q:?}");
    }
    let mut lengths: Vec<Rational> = sides.iter().map(|s| dot(s, s)).collect();
    lengths.sort();
    let [one, four] = [Rational::one(), Rational::from_i64(4)];
    assert_eq!(lengths, [one.clone(), one, four.clone(), four]);
    let twice_area = (0..4).fold(Rational::zero(), |acc, i| {
        let (a, b) = (&q[i], &q[(i + 1) % 4]);
        acc + a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone()
    });
    assert_eq!(twice_area, Rational::from_i64(4));
    // The reduced triangulation's corners are small again.
    assert!(out.reduced.max_coordinate_bits() <= 8);
}

#[test]
fn coordinates_past_the_growth_limit_stop_with_a_typed_error() {
    // x = 2^65536: more bits than MAX_WORKING_BITS (a library user can build it; the readers
    // refuse numbers past MAX_INPUT_BITS before).
    let mut x = Rational::from_i64(2);
    for _ in 0..16 {
        x = x.clone() * x;
    }
    assert!(x.bits() > MAX_WORKING_BITS);
    let t = flat_torus_portalgon(&x, 1).unwrap();
    let err = reduce(&t, &ReduceOptions::default()).unwrap_err();
    assert!(
        matches!(err, DuboisError::GrowthLimit { bits, .. } if bits > MAX_WORKING_BITS),
        "{err:?}"
    );
    let message = err.to_string();
    assert!(message.contains(&MAX_WORKING_BITS.to_string()), "{message}");
    assert!(message.contains("fewer digits"), "{message}");
    let err = delaunay_tessellation_dubois(&t, &FlatDelaunayOptions::default()).unwrap_err();
    assert!(
        matches!(err, CapsError::Reduction(DuboisError::GrowthLimit { .. })),
        "{err:?}"
    );
    // Just below the limit, the reduction runs.
    let y: Rational = format!("1{}", "0".repeat(100)).parse().unwrap();
    assert!(
        reduce(
            &flat_torus_portalgon(&y, 1).unwrap(),
            &ReduceOptions::default()
        )
        .is_ok()
    );
}

fn cross(a: &P, b: &P) -> Rational {
    a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone()
}

fn q(s: &str) -> Rational {
    s.parse().unwrap()
}

/// The in-circle determinant of `d` against the counter-clockwise `a, b, c` (positive inside).
fn in_circle(a: &P, b: &P, c: &P, d: &P) -> Rational {
    let (ad, bd, cd) = (diff(a, d), diff(b, d), diff(c, d));
    let (la, lb, lc) = (dot(&ad, &ad), dot(&bd, &bd), dot(&cd, &cd));
    la * cross(&bd, &cd) - lb * cross(&ad, &cd) + lc * cross(&ad, &bd)
}

/// Exact and written from the definitions: every polygon strictly convex with its corners on
/// one circle, and no corner of the polygon across any side (laid out by the gluing
/// `z ↦ s₁ + (z − t₀)(s₀ − s₁)/(t₁ − t₀)`, `t` the mate of `s`) strictly inside that circle.
/// Returns the number of sides checked.
fn assert_delaunay(t: &Portalgon<Rational>) -> usize {
    let mut checked = 0;
    for p in t.polygons() {
        let c: Vec<P> = t.polygon_sides(p).iter().map(|&s| t.start(s)).collect();
        let m = c.len();
        for i in 0..m {
            let turn = cross(
                &diff(&c[(i + 1) % m], &c[i]),
                &diff(&c[(i + 2) % m], &c[(i + 1) % m]),
            );
            assert!(
                turn.sign() == std::cmp::Ordering::Greater,
                "not strictly convex: {c:?}"
            );
            assert!(
                in_circle(&c[0], &c[1], &c[2], &c[i]).is_zero(),
                "not on one circle: {c:?}"
            );
        }
        for &s in t.polygon_sides(p) {
            let u = t.mate(s).expect("a closed tessellation");
            let (s0, s1, t0, t1) = (t.start(s), t.end(s), t.start(u), t.end(u));
            let (a, b) = (diff(&s0, &s1), diff(&t1, &t0));
            let n = dot(&b, &b);
            let w = [dot(&a, &b) / n.clone(), cross(&b, &a) / n];
            for &x in t.polygon_sides(t.owner(u)) {
                let z = diff(&t.start(x), &t0);
                let moved = [
                    s1[0].clone() + z[0].clone() * w[0].clone() - z[1].clone() * w[1].clone(),
                    s1[1].clone() + z[0].clone() * w[1].clone() + z[1].clone() * w[0].clone(),
                ];
                assert!(
                    in_circle(&c[0], &c[1], &c[2], &moved).sign() != std::cmp::Ordering::Greater,
                    "a corner across side {} lies inside the circle of its polygon",
                    s.idx()
                );
            }
            checked += 1;
        }
    }
    checked
}

/// Twice the area of a portalgon (shoelace, exact).
fn twice_area(t: &Portalgon<Rational>) -> Rational {
    corners(t).iter().fold(Rational::zero(), |acc, c| {
        (0..c.len()).fold(acc, |acc, i| acc + cross(&c[i], &c[(i + 1) % c.len()]))
    })
}

/// The angle sums at the vertices of a closed portalgon, sorted (in doubles from the exact
/// corners: the vertices are read from the gluings, the angles with `atan2`).
fn angle_sums(t: &Portalgon<Rational>) -> Vec<f64> {
    let (class, count) = t.vertex_classes();
    let mut sums = vec![0.0; count];
    for s in t.sides() {
        let (a, b, c) = (t.start(t.prev_side(s)), t.start(s), t.end(s));
        let (u, v) = (diff(&c, &b), diff(&a, &b));
        sums[class[s.idx()] as usize] += cross(&u, &v).to_f64().atan2(dot(&u, &v).to_f64());
    }
    sums.sort_by(f64::total_cmp);
    sums
}

#[test]
fn surfaces_with_cone_points_stop_at_the_delaunay_exit() {
    let (one, zero) = (Rational::one(), Rational::zero());
    let thousand_million = "1000000000";
    let m = 100_000i64;
    let m2 = i128::from(m) * i128::from(m);
    // (name, u, v, log₂ of the aspect ratio of the parallelogram's triangles, rounded up)
    let cases: Vec<(&str, P, P, usize)> = vec![
        (
            "pillowcase (10^9, 1)",
            [one.clone(), zero.clone()],
            [q(thousand_million), one.clone()],
            60,
        ),
        (
            "pillowcase (10^9 + 1/3, 1)",
            [one.clone(), zero.clone()],
            [q("3000000001/3"), one.clone()],
            60,
        ),
        (
            "thin pillowcase (1/3, 10^-9)",
            [one.clone(), zero.clone()],
            [q("1/3"), q("1/1000000000")],
            30,
        ),
        // Tetrahedra with integer edges 4m, m² + 1, m² + 1 (acute faces) and 2m² − 2, m² + 1,
        // m² + 1 (flat faces).
        (
            "acute tetrahedron",
            [Rational::from_i64(4 * m), zero.clone()],
            [Rational::from_i64(2 * m), q(&(m2 - 1).to_string())],
            17,
        ),
        (
            "flat tetrahedron",
            [q(&(2 * m2 - 2).to_string()), zero.clone()],
            [q(&(m2 - 1).to_string()), Rational::from_i64(2 * m)],
            17,
        ),
    ];
    for (name, u, v, log_aspect) in cases {
        let t = pillowcase(&u, &v).unwrap();
        let out = delaunay_tessellation_dubois(&t, &FlatDelaunayOptions::default()).unwrap();
        let run = out.reduction.inner_passes.len();
        // The exit fires once the needles are halved down to the triangles' widths (Proposition
        // 10: one halving per outer iteration), after about half of log₂ of the aspect ratio
        // (the shear 10^9: aspect 10^18, about 30 iterations), far below N = log₂(2 + L/s)
        // (s = d/(12r): about twice log₂ of the aspect ratio).
        assert!(out.reduction.stopped_by_caller, "{name}: N = {} run", run);
        assert!(run <= log_aspect / 2 + 4, "{name}: {run} outer iterations");
        assert!(
            (run as u32) < out.reduction.outer_iterations / 3,
            "{name}: {run} of N = {}",
            out.reduction.outer_iterations
        );
        let tess = &out.delaunay.tessellation;
        assert!(assert_delaunay(tess) >= 6, "{name}");
        // The input's surface: area, four cone points of angle π, a sphere.
        assert_eq!(twice_area(tess), twice_area(&t), "{name}: area");
        let sums = angle_sums(tess);
        assert_eq!(sums.len(), 4, "{name}: {sums:?}");
        assert!(
            sums.iter().all(|a| (a - std::f64::consts::PI).abs() < 1e-9),
            "{name}: {sums:?}"
        );
        let edges = tess.side_count() / 2;
        assert_eq!(4 - edges as i64 + tess.polygon_count() as i64, 2, "{name}");
    }
}
