//! Exact Theorem 1 (`delaunay --method dubois --exact`) against the size of the input's numbers:
//! Dubois' `T_x` (Section 9) at `x = 10^d` for `d` from 18 to 1000 digits, and pillowcases (four
//! cone points of angle π) with the shear `v = (k, 1)` for `k` up to `10^100`, plus sheared
//! pillowcases with a fractional shear (`k + 1/3`, an input the code was not tuned on).
//!
//! ```text
//! cargo run --release -p surftopo-intrinsic --example exact_growth [-- --repeat N] [--only TEXT]
//! ```
//!
//! `--only TEXT` runs the rows whose name contains `TEXT` (e.g. `pillowcase`, `10^18`). The
//! pillowcase at `10^100` (about 1,330 outer iterations on corners of over 1,500 bits: minutes)
//! runs only when `--only` names it (`--only "10^100, 1"`). Prints a Markdown table: seconds (median of `--repeat`, default 3), `N` (outer iterations
//! asked for), the outer iterations run (the exact-mode periodic exit, docs/dubois.md §3.2), and
//! the largest corner coordinate of the reduced triangulation in bits. Every answer is checked
//! here, without the algorithm's code: `T_x` at integer `x` must give `D_x`, one rectangle
//! `1 × 2` (four sides of squared lengths 1, 4, 1, 4, right angles, area 2); a pillowcase of
//! the lattice `⟨(1, 0), (k, 1)⟩` with integer `k` must give two unit squares (area 2); with
//! `k + 1/3` the polygons must have total area 2. A failed check panics.

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
    bits: u64,
    check: &'static str,
}

fn run(
    name: String,
    t: &Portalgon<Rational>,
    repeat: usize,
    check: fn(&Portalgon<Rational>) -> &'static str,
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
        bits: out.reduced.max_coordinate_bits(),
        check: check(&out.delaunay.tessellation),
    }
}

/// `D_x`: one 1 × 2 rectangle.
fn is_d_x(t: &Portalgon<Rational>) -> &'static str {
    let p = polygons(t);
    assert_eq!(p.len(), 1, "D_x is one polygon");
    assert!(
        is_rectangle(&p[0], &Rational::one(), &Rational::from_i64(4)),
        "D_x: {p:?}"
    );
    assert_eq!(twice_area(&p[0]), Rational::from_i64(4), "area 2");
    "D_x (1 x 2 rectangle)"
}

/// Two unit squares.
fn two_unit_squares(t: &Portalgon<Rational>) -> &'static str {
    let p = polygons(t);
    assert_eq!(p.len(), 2, "two squares");
    for q in &p {
        assert!(
            is_rectangle(q, &Rational::one(), &Rational::one()),
            "a unit square: {q:?}"
        );
    }
    "two unit squares"
}

/// Total area 2 (the pillowcase's), every polygon counter-clockwise.
fn area_two(t: &Portalgon<Rational>) -> &'static str {
    let p = polygons(t);
    assert!(
        p.iter()
            .all(|q| twice_area(q).sign() == std::cmp::Ordering::Greater)
    );
    let total = p
        .iter()
        .fold(Rational::zero(), |acc, q| acc + twice_area(q));
    assert_eq!(total, Rational::from_i64(4), "area 2");
    "area 2"
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
        rows.push(run(name, &t, repeat, is_d_x));
    }
    for (name, k, check) in [
        (
            "10^3",
            power_of_ten(3),
            two_unit_squares as fn(&Portalgon<Rational>) -> &'static str,
        ),
        ("10^6", power_of_ten(6), two_unit_squares),
        ("10^9", power_of_ten(9), two_unit_squares),
        ("10^18", power_of_ten(18), two_unit_squares),
        ("10^100", power_of_ten(100), two_unit_squares),
        (
            "10^9 + 1/3",
            format!("{}/3", 3 * 1_000_000_000u64 + 1),
            area_two,
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
        let t = pillowcase(&u, &v).expect("a pillowcase");
        rows.push(run(name, &t, repeat, check));
    }
    println!(
        "| input | seconds (median of {repeat}) | N | outer iterations run | largest coordinate of T' (bits) | checked |"
    );
    println!("|---|---|---|---|---|---|");
    for row in rows {
        println!(
            "| {} | {:.4} | {} | {} | {} | {} |",
            row.name, row.seconds, row.n, row.run, row.bits, row.check
        );
    }
}
