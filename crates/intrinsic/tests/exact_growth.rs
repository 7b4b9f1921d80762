//! Exact Theorem 1 on huge numbers: `T_x` at `x = 10^1000` gives `D_x` in few outer iterations
//! (the periodic exit of docs/dubois.md §3.2, charts at their first corners), and coordinates
//! past the growth limit stop the reduction with a typed error. The growth table is the example
//! `exact_growth` (`results/exact_growth.md`).

use surftopo_intrinsic::Portalgon;
use surftopo_intrinsic::dubois::{
    CapsError, DuboisError, FlatDelaunayOptions, MAX_WORKING_BITS, ReduceOptions,
    delaunay_tessellation_dubois, reduce,
};
use surftopo_intrinsic::generators::flat_torus_portalgon;
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
