//! `geometry::triangulate_polygon` and `Portalgon::triangulated` on simple polygons (star-shaped
//! with many reflex corners, straight corners and level corners; up to 8,000 corners), each
//! result checked by a verifier written here: every triangle strictly counter-clockwise, every
//! side of the polygon used once in its direction and every other edge twice in opposite
//! directions (so the triangles cover the polygon exactly once), areas summing to the polygon's.

use rand::{RngExt, SeedableRng};
use std::collections::HashMap;
use surftopo_intrinsic::Portalgon;
use surftopo_intrinsic::geometry::{Point, Rational, Scalar, triangulate_polygon};

fn cross<S: Scalar>(a: &Point<S>, b: &Point<S>, c: &Point<S>) -> S {
    (b[0].clone() - a[0].clone()) * (c[1].clone() - a[1].clone())
        - (b[1].clone() - a[1].clone()) * (c[0].clone() - a[0].clone())
}

/// Twice the polygon's area (shoelace).
fn twice_area<S: Scalar>(c: &[Point<S>]) -> S {
    let o = [S::zero(), S::zero()];
    (0..c.len()).fold(S::zero(), |acc, i| {
        acc + cross(&o, &c[i], &c[(i + 1) % c.len()])
    })
}

/// The verifier: panics unless `triangles` partition the polygon `c`.
fn check_partition<S: Scalar + std::fmt::Debug>(c: &[Point<S>], triangles: &[[usize; 3]]) {
    let k = c.len();
    assert_eq!(triangles.len(), k - 2, "n - 2 triangles");
    let mut edges: HashMap<(usize, usize), i32> = HashMap::new();
    let mut total = S::zero();
    for t in triangles {
        let a = cross(&c[t[0]], &c[t[1]], &c[t[2]]);
        assert!(
            a.sign() == std::cmp::Ordering::Greater,
            "flat or clockwise triangle {t:?}"
        );
        total = total + a;
        for m in 0..3 {
            let (x, y) = (t[m], t[(m + 1) % 3]);
            *edges.entry((x, y)).or_default() += 1;
        }
    }
    for i in 0..k {
        let side = (i, (i + 1) % k);
        assert_eq!(edges.remove(&side), Some(1), "side {side:?} used once");
        assert!(
            !edges.contains_key(&(side.1, side.0)),
            "side {side:?} reversed"
        );
    }
    for (&(x, y), &n) in &edges {
        assert_eq!(n, 1, "edge ({x}, {y}) used {n} times");
        assert_eq!(
            edges.get(&(y, x)),
            Some(&1),
            "diagonal ({x}, {y}) unmatched"
        );
    }
    assert!(total == twice_area(c), "areas sum to the polygon's");
}

/// `k` corners at increasing angles around the origin, at random radii, rounded to a grid of
/// `grid` units (level and straight corners are frequent on a small grid).
fn star_corners(k: usize, grid: f64, seed: u64) -> Vec<Point<f64>> {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    (0..k)
        .map(|i| {
            let angle = std::f64::consts::TAU * i as f64 / k as f64;
            let r = grid * rng.random_range(0.2..1.0);
            [(r * angle.cos()).round(), (r * angle.sin()).round()]
        })
        .collect()
}

/// A star-shaped polygon, or `None` if rounding made it not simple (`add_polygon`'s check).
fn star(k: usize, grid: f64, seed: u64) -> Option<Vec<Point<f64>>> {
    let corners = star_corners(k, grid, seed);
    let mut check = Portalgon::<f64>::empty();
    check.add_polygon(&corners).ok().map(|_| corners)
}

/// A comb: `teeth` vertical teeth up from a bar and `teeth` down, every corner on the
/// integer grid (split and merge corners, level corners, straight corners on the bar).
fn comb(teeth: usize) -> Vec<Point<f64>> {
    let n = teeth as f64;
    let mut c = vec![[0.0, 0.0]];
    for i in 0..teeth {
        let x = 2.0 * i as f64;
        c.extend([
            [x + 1.0, 0.0],
            [x + 1.0, -3.0],
            [x + 2.0, -3.0],
            [x + 2.0, 0.0],
        ]);
    }
    c.push([2.0 * n + 1.0, 0.0]);
    c.push([2.0 * n + 1.0, 1.0]);
    for i in (0..teeth).rev() {
        let x = 2.0 * i as f64;
        c.extend([
            [x + 2.0, 1.0],
            [x + 2.0, 4.0],
            [x + 1.0, 4.0],
            [x + 1.0, 1.0],
        ]);
    }
    c.push([0.0, 1.0]);
    c
}

#[test]
fn random_star_polygons_are_partitioned() {
    let mut tried = 0;
    for seed in 0..400u64 {
        let k = 3 + (seed as usize % 40);
        let grid = if seed % 2 == 0 { 6.0 } else { 1000.0 };
        let Some(c) = star(k, grid, seed) else {
            continue;
        };
        tried += 1;
        let t = triangulate_polygon(&c).expect("a simple polygon");
        check_partition(&c, &t);
        // The same polygon in exact rationals, and its straight corners (midpoints).
        let exact: Vec<Point<Rational>> = c
            .iter()
            .map(|p| p.map(|x| Rational::from_i64(x as i64)))
            .collect();
        let mut with_midpoints = Vec::new();
        for i in 0..exact.len() {
            let (a, b) = (&exact[i], &exact[(i + 1) % exact.len()]);
            with_midpoints.push(a.clone());
            with_midpoints.push([
                (a[0].clone() + b[0].clone()).half(),
                (a[1].clone() + b[1].clone()).half(),
            ]);
        }
        for poly in [exact, with_midpoints] {
            let t = triangulate_polygon(&poly).expect("a simple polygon");
            check_partition(&poly, &t);
        }
    }
    assert!(tried > 200, "{tried} simple polygons");
}

#[test]
fn combs_are_partitioned() {
    for teeth in [1, 2, 5, 50] {
        let c = comb(teeth);
        let t = triangulate_polygon(&c).expect("a simple polygon");
        check_partition(&c, &t);
    }
}

#[test]
fn large_polygons_are_partitioned() {
    // 2,000 and 8,000 corners (the shortcut rule, a full sort of the O(k²) corner pairs per cut,
    // took minutes and gigabytes there). At radii of 2·10⁶ to 10⁷ the corners keep their angular
    // order after rounding (steps of more than 1,500 units), so the stars are simple.
    for (k, seed) in [(2000, 7u64), (8000, 8)] {
        let c = star_corners(k, 1e7, seed);
        let t = triangulate_polygon(&c).expect("a simple polygon");
        check_partition(&c, &t);
        if k > 2000 {
            continue; // `add_polygon`'s simplicity check is quadratic: once is enough
        }
        let mut p = Portalgon::<f64>::empty();
        p.add_polygon(&c).unwrap();
        let t = p.triangulated().unwrap();
        assert_eq!(t.polygon_count(), k - 2);
        assert_eq!(
            t.unmatched_sides().count(),
            k,
            "only the polygon's own sides are free"
        );
        let area: f64 = t.polygons().map(|q| twice_area(&t.corners(q))).sum();
        let expected = twice_area(&c);
        assert!(
            (area - expected).abs() <= 1e-9 * expected,
            "{area} {expected}"
        );
    }
}
