//! Exact Theorem 1 (`delaunay --method dubois --exact`) against the size of the input's numbers:
//! Dubois' `T_x` (Section 9) at `x = 10^d` for `d` from 18 to 1000 digits; pillowcases (four
//! cone points of angle π, the double of the parallelogram of `u`, `v`) with the shear
//! `v = (k, 1)` for `k` up to `10^100`, with a fractional shear (`k + 1/3`, an input the code
//! was not tuned on) and thin ones (`v = (1/3, 10^-d)`); and tetrahedra with integer edge
//! lengths (isosceles tetrahedra, whose four cone points have angle π: the pillowcase of `u`,
//! `v` with `|u|`, `|v|`, `|u − v|` integers), acute (`u = (4m, 0)`, `v = (2m, m² − 1)`, edges
//! `4m, m² + 1, m² + 1`) and flat (`u = (2m² − 2, 0)`, `v = (m² − 1, 2m)`).
//!
//! ```text
//! cargo run --release -p surftopo-intrinsic --example exact_growth [-- --repeat N] [--only TEXT]
//! ```
//!
//! `--only TEXT` runs the rows whose name contains `TEXT` (e.g. `pillowcase`, `10^18`). The
//! pillowcase at `10^100` (about 1,330 outer iterations on corners of over 1,500 bits: minutes)
//! runs only when `--only` names it (`--only "10^100, 1"`). Prints a Markdown table: seconds
//! (median of `--repeat`, default 3), `N` (outer iterations asked for), the outer iterations
//! run and why they stopped (the periodic exit of docs/dubois.md §3.2, or the Delaunay exit of
//! §3.8), and the largest corner coordinate of the reduced triangulation in bits. Every answer is checked
//! here, without the algorithm's code: `T_x` at integer `x` must give `D_x`, one rectangle
//! `1 × 2` (four sides of squared lengths 1, 4, 1, 4, right angles, area 2); a pillowcase of
//! the lattice `⟨(1, 0), (k, 1)⟩` with integer `k` must give two unit squares (area 2); with
//! `k + 1/3` the polygons must have total area 2; the thin pillowcases and the tetrahedra their
//! input's area; every output has no non-Delaunay edge (an in-circle test across every edge
//! written here). A failed check panics.

use std::time::Instant;

use surftopo_intrinsic::Portalgon;
use surftopo_intrinsic::dubois::{FlatDelaunayOptions, delaunay_tessellation_dubois};
use surftopo_intrinsic::generators::{flat_torus_portalgon, pillowcase};
use surftopo_intrinsic::geometry::{Rational, Scalar};

fn r(s: &str) -> Rational {
    s.parse().expect("a rational")
}

fn power_of_ten(digits: usize) -> String {
    format!("1{}", "0".repeat(digits))
}

/// The corners of every polygon of `t`, as points.
fn polygons(t: &Portalgon<Rational>) -> Vec<Vec<[Rational; 2]>> {
    t.polygons()
        .map(|p| t.polygon_sides(p).iter().map(|&s| t.start(s)).collect())
        .collect()
}

fn diff(a: &[Rational; 2], b: &[Rational; 2]) -> [Rational; 2] {
    [a[0].clone() - b[0].clone(), a[1].clone() - b[1].clone()]
}

fn dot(a: &[Rational; 2], b: &[Rational; 2]) -> Rational {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone()
}

/// Twice the signed area of a polygon (shoelace).
fn twice_area(p: &[[Rational; 2]]) -> Rational {
    (0..p.len()).fold(Rational::zero(), |acc, i| {
        let (a, b) = (&p[i], &p[(i + 1) % p.len()]);
        acc + a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone()
    })
}

/// Whether `p` is a rectangle with sides of squared lengths `w2, h2, w2, h2` (from some corner).
fn is_rectangle(p: &[[Rational; 2]], w2: &Rational, h2: &Rational) -> bool {
    if p.len() != 4 {
        return false;
    }
    let sides: Vec<[Rational; 2]> = (0..4).map(|i| diff(&p[(i + 1) % 4], &p[i])).collect();
    let right_angles = (0..4).all(|i| dot(&sides[i], &sides[(i + 1) % 4]).is_zero());
    let lengths: Vec<Rational> = sides.iter().map(|s| dot(s, s)).collect();
    let fits = |start: usize| {
        (0..4).all(|i| &lengths[(start + i) % 4] == if i % 2 == 0 { w2 } else { h2 })
    };
    right_angles && (fits(0) || fits(1))
}

struct Row {
    name: String,
    seconds: f64,
    n: u32,
    run: usize,
    exit: &'static str,
    bits: u64,
    check: String,
}

fn run(
    name: String,
    t: &Portalgon<Rational>,
    repeat: usize,
    check: &dyn Fn(&Portalgon<Rational>) -> String,
) -> Row {
    let options = FlatDelaunayOptions::default();
    let mut times = Vec::new();
    let mut out = None;
    for _ in 0..repeat {
        let start = Instant::now();
        let result = delaunay_tessellation_dubois(t, &options).expect("Theorem 1");
        times.push(start.elapsed().as_secs_f64());
        out = Some(result);
    }
    times.sort_by(f64::total_cmp);
    let out = out.expect("one run");
    Row {
        name,
        seconds: times[times.len() / 2],
        n: out.reduction.outer_iterations,
        run: out.reduction.inner_passes.len(),
        exit: if out.reduction.stopped_by_caller {
            "Delaunay"
        } else if (out.reduction.inner_passes.len() as u32) < out.reduction.outer_iterations {
            "periodic"
        } else {
            "N reached"
        },
        bits: out.reduced.max_coordinate_bits(),
        check: format!(
            "{}; {}",
            check(&out.delaunay.tessellation),
            delaunay_check(&out.delaunay.tessellation)
        ),
    }
}

/// `D_x`: one 1 × 2 rectangle.
fn is_d_x(t: &Portalgon<Rational>) -> String {
    let p = polygons(t);
    assert_eq!(p.len(), 1, "D_x is one polygon");
    assert!(
        is_rectangle(&p[0], &Rational::one(), &Rational::from_i64(4)),
        "D_x: {p:?}"
    );
    assert_eq!(twice_area(&p[0]), Rational::from_i64(4), "area 2");
    "D_x (1 x 2 rectangle)".into()
}

/// Two unit squares.
fn two_unit_squares(t: &Portalgon<Rational>) -> String {
    let p = polygons(t);
    assert_eq!(p.len(), 2, "two squares");
    for q in &p {
        assert!(
            is_rectangle(q, &Rational::one(), &Rational::one()),
            "a unit square: {q:?}"
        );
    }
    "two unit squares".into()
}

/// Total area `twice / 2`, every polygon counter-clockwise.
fn area(t: &Portalgon<Rational>, twice: &Rational) -> String {
    let p = polygons(t);
    assert!(
        p.iter()
            .all(|q| twice_area(q).sign() == std::cmp::Ordering::Greater)
    );
    let total = p
        .iter()
        .fold(Rational::zero(), |acc, q| acc + twice_area(q));
    assert_eq!(&total, twice, "the input's area");
    "the input's area".into()
}

/// Every edge of the tessellation is locally Delaunay: each polygon is strictly convex with its
/// corners on one circle, and the polygon across each side, laid out by the gluing (footnote 2's
/// `z ↦ t₀ + (z − s₀)(t₁ − t₀)/(s₁ − s₀)`), has no corner strictly inside that circle.
fn delaunay_check(t: &Portalgon<Rational>) -> String {
    let mut edges = 0;
    for p in t.polygons() {
        let c = polygons_corners(t, p);
        let m = c.len();
        for i in 0..m {
            assert!(
                cross(
                    &diff(&c[(i + 1) % m], &c[i]),
                    &diff(&c[(i + 2) % m], &c[(i + 1) % m])
                )
                .sign()
                    == std::cmp::Ordering::Greater,
                "not strictly convex"
            );
            assert!(
                in_circle(&c[0], &c[1], &c[2], &c[i]).is_zero(),
                "corners not on one circle"
            );
        }
        for &s in t.polygon_sides(p) {
            let u = t.mate(s).expect("closed");
            let (s0, s1) = (t.start(s), t.end(s));
            // u runs from s1 to s0: z ↦ s1 + (z − u0)·(s0 − s1)/(u1 − u0).
            let (u0, u1) = (t.start(u), t.end(u));
            let w = complex_div(&diff(&s0, &s1), &diff(&u1, &u0));
            for z in polygons_corners(t, t.owner(u)) {
                let moved = add(&s1, &complex_mul(&diff(&z, &u0), &w));
                assert!(
                    in_circle(&c[0], &c[1], &c[2], &moved).sign() != std::cmp::Ordering::Greater,
                    "a corner across side {} is inside the circle",
                    s.idx()
                );
            }
            edges += 1;
        }
    }
    format!("{} edges Delaunay", edges / 2)
}

fn polygons_corners(
    t: &Portalgon<Rational>,
    p: surftopo_intrinsic::PolygonId,
) -> Vec<[Rational; 2]> {
    t.polygon_sides(p).iter().map(|&s| t.start(s)).collect()
}

fn add(a: &[Rational; 2], b: &[Rational; 2]) -> [Rational; 2] {
    [a[0].clone() + b[0].clone(), a[1].clone() + b[1].clone()]
}

fn cross(a: &[Rational; 2], b: &[Rational; 2]) -> Rational {
    a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone()
}

fn complex_mul(a: &[Rational; 2], b: &[Rational; 2]) -> [Rational; 2] {
    [
        a[0].clone() * b[0].clone() - a[1].clone() * b[1].clone(),
        a[0].clone() * b[1].clone() + a[1].clone() * b[0].clone(),
    ]
}

fn complex_div(a: &[Rational; 2], b: &[Rational; 2]) -> [Rational; 2] {
    let n = dot(b, b);
    [dot(a, b) / n.clone(), cross(b, a) / n]
}

/// The in-circle determinant of `d` against the counter-clockwise `a, b, c` (positive inside).
fn in_circle(
    a: &[Rational; 2],
    b: &[Rational; 2],
    c: &[Rational; 2],
    d: &[Rational; 2],
) -> Rational {
    let (ad, bd, cd) = (diff(a, d), diff(b, d), diff(c, d));
    let (la, lb, lc) = (dot(&ad, &ad), dot(&bd, &bd), dot(&cd, &cd));
    la * cross(&bd, &cd) - lb * cross(&ad, &cd) + lc * cross(&ad, &bd)
}

fn pillowcase_row(
    name: String,
    u: [Rational; 2],
    v: [Rational; 2],
    repeat: usize,
    check: Option<fn(&Portalgon<Rational>) -> String>,
) -> Row {
    let t = pillowcase(&u, &v).expect("a pillowcase");
    // The pillowcase's area is twice the parallelogram's.
    let twice = Rational::from_i64(4) * cross(&u, &v);
    let check = move |out: &Portalgon<Rational>| match check {
        Some(known) => known(out),
        None => area(out, &twice),
    };
    run(name, &t, repeat, &check)
}

fn main() {
    let mut repeat = 3usize;
    let mut only: Option<String> = None;
    let mut args = std::env::args().skip(1);
    while let Some(flag) = args.next() {
        match flag.as_str() {
            "--repeat" => {
                repeat = args
                    .next()
                    .and_then(|v| v.parse().ok())
                    .expect("--repeat N")
            }
            "--only" => only = Some(args.next().expect("--only WORD")),
            other => panic!("unknown option {other}"),
        }
    }
    let mut rows = Vec::new();
    let wanted = |name: &str| only.as_ref().is_none_or(|w| name.contains(w.as_str()));
    let slow = |name: &str| name.contains("(10^100, 1)") && only.is_none();
    for digits in [18usize, 50, 100, 200, 500, 1000] {
        let name = format!("T_x, x = 10^{digits}");
        if !wanted(&name) {
            continue;
        }
        let x = r(&power_of_ten(digits));
        let t = flat_torus_portalgon(&x, 1).expect("T_x");
        rows.push(run(name, &t, repeat, &is_d_x));
    }
    let known: Option<fn(&Portalgon<Rational>) -> String> = Some(two_unit_squares);
    for (name, k, check) in [
        ("10^3", power_of_ten(3), known),
        ("10^6", power_of_ten(6), known),
        ("10^9", power_of_ten(9), known),
        ("10^18", power_of_ten(18), known),
        ("10^100", power_of_ten(100), known),
        (
            "10^9 + 1/3",
            format!("{}/3", 3 * 1_000_000_000u64 + 1),
            None,
        ),
    ] {
        let name = format!("pillowcase, v = ({name}, 1)");
        if !wanted(&name) || slow(&name) {
            continue;
        }
        let (u, v) = (
            [Rational::one(), Rational::zero()],
            [r(&k), Rational::one()],
        );
        rows.push(pillowcase_row(name, u, v, repeat, check));
    }
    for digits in [9usize, 18] {
        let name = format!("thin pillowcase, v = (1/3, 10^-{digits})");
        if !wanted(&name) {
            continue;
        }
        let (u, v) = (
            [Rational::one(), Rational::zero()],
            [r("1/3"), r(&format!("1/{}", power_of_ten(digits)))],
        );
        rows.push(pillowcase_row(name, u, v, repeat, None));
    }
    for (shape, m) in [
        ("acute", 100_000i64),
        ("flat", 100_000),
        ("flat", 1_000_000_000),
    ] {
        let name = format!("tetrahedron, {shape} faces, m = {m}");
        if !wanted(&name) {
            continue;
        }
        let (u, v) = if shape == "acute" {
            // Edges 4m, m² + 1, m² + 1.
            (
                [Rational::from_i64(4 * m), Rational::zero()],
                [
                    Rational::from_i64(2 * m),
                    r(&format!("{}", (m as i128) * (m as i128) - 1)),
                ],
            )
        } else {
            // Edges 2m² − 2, m² + 1, m² + 1.
            let m2 = (m as i128) * (m as i128);
            (
                [r(&format!("{}", 2 * m2 - 2)), Rational::zero()],
                [r(&format!("{}", m2 - 1)), Rational::from_i64(2 * m)],
            )
        };
        rows.push(pillowcase_row(name, u, v, repeat, None));
    }
    println!(
        "| input | seconds (median of {repeat}) | N | outer iterations run | exit | largest coordinate of T' (bits) | checked |"
    );
    println!("|---|---|---|---|---|---|---|");
    for row in rows {
        println!(
            "| {} | {:.4} | {} | {} | {} | {} | {} |",
            row.name, row.seconds, row.n, row.run, row.exit, row.bits, row.check
        );
    }
}
