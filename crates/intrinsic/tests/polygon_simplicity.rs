//! `check_polygon`'s simplicity test (the Shamos–Hoey sweep, O(k log k)) against an oracle
//! written here: every pair of sides tested with integer predicates (i128, exact), O(k²). Small
//! random polygons on a coarse grid (level, collinear, touching and repeated corners are frequent)
//! must get the oracle's verdict, and a refusal must name a pair the oracle finds offending;
//! large polygons (a regular 20,000-gon, a star, a comb of 20,000 corners) are accepted, with a
//! certificate of simplicity checked here, and their variants with two far-apart sides crossing,
//! a corner touching a side, or sides overlapping are refused naming an offending pair.

use proptest::prelude::*;
use rand::{RngExt, SeedableRng};
use std::collections::BTreeSet;
use surftopo_intrinsic::geometry::{Point, Rational, Scalar};
use surftopo_intrinsic::{PortalgonError, check_polygon};

type P = [i64; 2];

fn orient_sign(a: P, b: P, c: P) -> i128 {
    let d = (b[0] as i128 - a[0] as i128) * (c[1] as i128 - a[1] as i128)
        - (b[1] as i128 - a[1] as i128) * (c[0] as i128 - a[0] as i128);
    d.signum()
}

fn on_closed_segment(a: P, b: P, c: P) -> bool {
    orient_sign(a, b, c) == 0
        && a[0].min(b[0]) <= c[0]
        && c[0] <= a[0].max(b[0])
        && a[1].min(b[1]) <= c[1]
        && c[1] <= a[1].max(b[1])
}

/// Whether the closed segments `pq` and `rs` meet.
fn meet(p: P, q: P, r: P, s: P) -> bool {
    let (d1, d2) = (orient_sign(r, s, p), orient_sign(r, s, q));
    let (d3, d4) = (orient_sign(p, q, r), orient_sign(p, q, s));
    (d1 * d2 < 0 && d3 * d4 < 0)
        || on_closed_segment(r, s, p)
        || on_closed_segment(r, s, q)
        || on_closed_segment(p, q, r)
        || on_closed_segment(p, q, s)
}

/// Whether sides `a` and `b` of `c` offend simplicity: consecutive ones folding back onto each
/// other, or other ones meeting.
fn offending(c: &[P], a: usize, b: usize) -> bool {
    let k = c.len();
    let side = |i: usize| (c[i], c[(i + 1) % k]);
    if a == b {
        return false;
    }
    let (first, second) = if b == (a + 1) % k {
        (a, b)
    } else if a == (b + 1) % k {
        (b, a)
    } else {
        let ((p, q), (r, s)) = (side(a), side(b));
        return meet(p, q, r, s);
    };
    let (p, q) = side(first);
    let r = side(second).1;
    let dot = (q[0] - p[0]) as i128 * (r[0] - q[0]) as i128
        + (q[1] - p[1]) as i128 * (r[1] - q[1]) as i128;
    orient_sign(p, q, r) == 0 && dot < 0
}

#[derive(Debug, PartialEq)]
enum Verdict {
    Valid,
    ZeroSide(usize),
    NotCounterClockwise,
    /// Every offending pair.
    NotSimple(BTreeSet<(usize, usize)>),
}

/// The oracle: `check_polygon`'s contract, every pair tested.
fn oracle(c: &[P]) -> Verdict {
    let k = c.len();
    if let Some(i) = (0..k).find(|&i| c[i] == c[(i + 1) % k]) {
        return Verdict::ZeroSide(i);
    }
    let area: i128 = (0..k)
        .map(|i| {
            let (a, b) = (c[i], c[(i + 1) % k]);
            a[0] as i128 * b[1] as i128 - a[1] as i128 * b[0] as i128
        })
        .sum();
    if area <= 0 {
        return Verdict::NotCounterClockwise;
    }
    let pairs: BTreeSet<(usize, usize)> = (0..k)
        .flat_map(|a| (0..k).map(move |b| (a, b)))
        .filter(|&(a, b)| offending(c, a, b))
        .collect();
    if pairs.is_empty() {
        Verdict::Valid
    } else {
        Verdict::NotSimple(pairs)
    }
}

fn as_f64(c: &[P]) -> Vec<Point<f64>> {
    c.iter().map(|p| [p[0] as f64, p[1] as f64]).collect()
}

/// The corners divided by 7 in exact rationals (a scale that f64 cannot represent exactly).
fn as_rational(c: &[P]) -> Vec<Point<Rational>> {
    let r = |x: i64| Rational::new(x, 7).expect("nonzero denominator");
    c.iter().map(|p| [r(p[0]), r(p[1])]).collect()
}

/// `check_polygon` on `c` (as `S`) agrees with the oracle: same verdict; for a polygon that is
/// not simple, a pair the oracle finds offending.
fn agrees<S: Scalar>(c: &[P], corners: &[Point<S>]) -> Result<(), String> {
    let got = check_polygon(5, corners);
    let ok = match (&got, oracle(c)) {
        (Ok(()), Verdict::Valid) => true,
        (Err(PortalgonError::ZeroSide { polygon: 5, side }), Verdict::ZeroSide(i)) => *side == i,
        (
            Err(PortalgonError::NotCounterClockwise { polygon: 5, .. }),
            Verdict::NotCounterClockwise,
        ) => true,
        (Err(PortalgonError::NotSimple { polygon: 5, a, b }), Verdict::NotSimple(pairs)) => {
            pairs.contains(&(*a, *b))
        }
        _ => false,
    };
    if ok {
        Ok(())
    } else {
        Err(format!(
            "{c:?}: check_polygon gave {got:?}, the oracle {:?}",
            oracle(c)
        ))
    }
}

/// A polygon of `k` corners: random on a `grid`² grid, or (`star`) at increasing angles around
/// the grid's centre with random radii, rounded to the grid.
fn random_polygon(rng: &mut impl RngExt, k: usize, grid: i64, star: bool) -> Vec<P> {
    if !star {
        return (0..k)
            .map(|_| [rng.random_range(0..grid), rng.random_range(0..grid)])
            .collect();
    }
    let half = grid as f64 / 2.0;
    (0..k)
        .map(|i| {
            let angle = std::f64::consts::TAU * (i as f64 + rng.random_range(0.0..0.9)) / k as f64;
            let r = half * rng.random_range(0.1..1.0);
            [
                (half + r * angle.cos()).round() as i64,
                (half + r * angle.sin()).round() as i64,
            ]
        })
        .collect()
}

#[test]
fn small_random_polygons_get_the_oracles_verdict() {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(20261204);
    let (mut valid, mut not_simple) = (0, 0);
    for n in 0..20_000 {
        let k = rng.random_range(3..11);
        let grid = rng.random_range(3..9);
        let c = random_polygon(&mut rng, k, grid, n % 2 == 0);
        agrees(&c, &as_f64(&c)).unwrap();
        if n % 10 == 0 {
            agrees(&c, &as_rational(&c)).unwrap();
        }
        match oracle(&c) {
            Verdict::Valid => valid += 1,
            Verdict::NotSimple(_) => not_simple += 1,
            _ => {}
        }
    }
    // Both verdicts are exercised often (the counts come from the oracle, not the sweep).
    assert!(
        valid > 2_000 && not_simple > 2_000,
        "{valid} valid, {not_simple} not simple"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2_000))]

    #[test]
    fn random_polygons_get_the_oracles_verdict(
        corners in prop::collection::vec((0i64..6, 0i64..6), 3..12),
        star_seed in any::<u64>(),
        k in 3usize..14,
    ) {
        let c: Vec<P> = corners.into_iter().map(|(x, y)| [x, y]).collect();
        prop_assert_eq!(agrees(&c, &as_f64(&c)), Ok(()));
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(star_seed);
        let s = random_polygon(&mut rng, k, 12, true);
        prop_assert_eq!(agrees(&s, &as_f64(&s)), Ok(()));
        prop_assert_eq!(agrees(&s, &as_rational(&s)), Ok(()));
    }
}

/// A certificate that `c` is simple: every corner strictly counter-clockwise of the previous one
/// seen from `o`, and the boundary winding once around `o` (upward crossings of the ray from `o`
/// towards +x), so the polygon is star-shaped from `o`.
fn star_shaped_from(c: &[P], o: P) -> bool {
    let k = c.len();
    let turning = (0..k).all(|i| orient_sign(o, c[i], c[(i + 1) % k]) > 0);
    let crossings = (0..k)
        .filter(|&i| c[i][1] < o[1] && c[(i + 1) % k][1] >= o[1])
        .count();
    turning && crossings == 1
}

/// The regular `k`-gon of radius 10⁹ around the origin, rounded to integers.
fn regular(k: usize) -> Vec<P> {
    (0..k)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / k as f64;
            [
                (1e9 * a.cos()).round() as i64,
                (1e9 * a.sin()).round() as i64,
            ]
        })
        .collect()
}

/// A comb of `teeth` teeth of width 1 and height `h` on a base from (0, 0) to (2·teeth − 1, 0),
/// the gaps between them going down to height 1; coordinates doubled (so a corner can sit
/// half-way), 4·teeth corners.
fn comb(teeth: i64, h: i64) -> Vec<P> {
    let mut c = vec![[0, 0], [2 * teeth - 1, 0]];
    for i in (0..teeth).rev() {
        c.push([2 * i + 1, h]);
        c.push([2 * i, h]);
        if i > 0 {
            c.push([2 * i, 1]);
            c.push([2 * i - 1, 1]);
        }
    }
    c.iter().map(|p| [2 * p[0], 2 * p[1]]).collect()
}

/// The pair `check_polygon` names for `c`, which must not be simple.
fn named_pair(c: &[P]) -> (usize, usize) {
    match check_polygon(2, &as_f64(c)) {
        Err(PortalgonError::NotSimple { polygon: 2, a, b }) => (a, b),
        other => panic!("expected a refusal as not simple, got {other:?}"),
    }
}

/// Every offending pair with a side in `changed` (the only sides a variant of a simple polygon
/// moved), O(k·|changed|).
fn offending_with(c: &[P], changed: &[usize]) -> BTreeSet<(usize, usize)> {
    let k = c.len();
    changed
        .iter()
        .flat_map(|&a| (0..k).flat_map(move |b| [(a, b), (b, a)]))
        .filter(|&(a, b)| offending(c, a, b))
        .collect()
}

#[test]
fn large_simple_polygons_are_accepted() {
    let r = regular(20_000);
    assert!(star_shaped_from(&r, [0, 0]));
    assert_eq!(check_polygon(0, &as_f64(&r)), Ok(()));
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
    let s: Vec<P> = random_polygon(&mut rng, 20_000, 2_000_000_000, true);
    assert!(star_shaped_from(&s, [1_000_000_000, 1_000_000_000]));
    assert_eq!(check_polygon(0, &as_f64(&s)), Ok(()));
    // Exact mode on the same kind of input, smaller (rational arithmetic).
    let r = regular(3_000);
    assert_eq!(check_polygon(0, &as_rational(&r)), Ok(()));
    // The comb: its construction checked by the oracle on small sizes, then 20,000 corners.
    for teeth in 1..8 {
        assert_eq!(oracle(&comb(teeth, 5)), Verdict::Valid, "{teeth} teeth");
    }
    let c = comb(5_000, 7);
    assert_eq!(c.len(), 20_000);
    assert_eq!(check_polygon(0, &as_f64(&c)), Ok(()));
}

#[test]
fn large_polygons_that_are_not_simple_are_refused_naming_the_sides() {
    // Two far-apart sides crossing: corner 0 of the regular polygon pulled across the far side,
    // so sides k−1 and 0 cross the sides near k/2.
    let k = 20_000;
    let mut r = regular(k);
    r[0] = [-1_200_000_000, 0];
    let pairs = offending_with(&r, &[k - 1, 0]);
    assert!(
        pairs
            .iter()
            .all(|&(a, b)| a.abs_diff(b) > k / 3 && a.abs_diff(b) < 2 * k / 3)
    );
    assert!(pairs.contains(&named_pair(&r)), "{:?}", named_pair(&r));
    // A corner touching a side: the middle gap of the comb made a V whose bottom corner lies
    // on the base (side 0).
    let mut c = comb(5_000, 7);
    let gap = 2 + 4 * 2_500 + 2; // the corners (2i, 1), (2i − 1, 1) of the gap at i = 2,499
    assert_eq!((c[gap][1], c[gap + 1][1]), (2, 2));
    let x = (c[gap][0] + c[gap + 1][0]) / 2;
    let v = c[gap];
    c[gap] = [x, 0];
    c.remove(gap + 1);
    let pairs = offending_with(&c, &[0, gap - 1, gap]);
    assert_eq!(
        pairs,
        BTreeSet::from([(0, gap - 1), (gap - 1, 0), (0, gap), (gap, 0)])
    );
    assert!(pairs.contains(&named_pair(&c)));
    // Collinear overlap: the gap's bottom side lowered onto the base.
    let mut c = comb(5_000, 7);
    c[gap][1] = 0;
    c[gap + 1][1] = 0;
    assert_eq!(c[gap][0], v[0]);
    let pairs = offending_with(&c, &[0, gap - 1, gap, gap + 1]);
    assert!(pairs.contains(&(0, gap)));
    assert!(pairs.contains(&named_pair(&c)));
}
