//! Bifaces and good bifaces (Dubois, Section 3; the kernel standing in for Lemma 25 of
//! Appendix B, docs/dubois.md §3.1): the kernel is checked against a brute-force ladder oracle
//! written here from the definitions alone.
//!
//! The oracle unfolds the strip of triangles `T′_k = (p_k, q_k, q_{k+1})`,
//! `T_k = (p_k, q_{k+1}, p_{k+1})` (`p_k = gᵏ(A)`, `q_k = gᵏ(D)`, by iterating `g` and `g⁻¹`),
//! walks each candidate segment `p₀q_m` through it triangle by triangle with exact orientation
//! tests (a segment is valid when it reaches the vertex `q_m` without leaving the strip, touching
//! a boundary side or passing through another vertex), and takes Section 3's definition of a good
//! biface literally. It runs in exact arithmetic; f64 bifaces are converted exactly.

use std::cmp::Ordering;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use surftopo_intrinsic::geometry::{
    Motion, Point, Rational, Scalar, cross, dist2, dot, orient, sub,
};
use surftopo_intrinsic::{Biface, BifaceKind};

fn r(s: &str) -> Rational {
    s.parse().unwrap()
}

fn ri(v: i64) -> Rational {
    Rational::from_i64(v)
}

/// A vertex of the strip: a lift of `b₀` or of `b₁`, by index.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum V {
    P(i64),
    Q(i64),
}

/// The unfolded strip over offsets `[-w - 2, w + 2]`.
struct Strip {
    w: i64,
    p: Vec<Point<Rational>>,
    q: Vec<Point<Rational>>,
}

impl Strip {
    fn new(corners: &[Point<Rational>; 4], w: i64) -> Strip {
        let [a, d, b, c] = corners.clone();
        let g = Motion::taking(&a, &d, &c, &b);
        let g_inv = g.inverse();
        let n = (2 * w + 5) as usize;
        let (mut p, mut q) = (vec![a.clone(); n], vec![d.clone(); n]);
        let mid = (w + 2) as usize;
        for k in mid + 1..n {
            p[k] = g.apply(&p[k - 1]);
            q[k] = g.apply(&q[k - 1]);
        }
        for k in (0..mid).rev() {
            p[k] = g_inv.apply(&p[k + 1]);
            q[k] = g_inv.apply(&q[k + 1]);
        }
        Strip { w, p, q }
    }

    fn at(&self, v: V) -> &Point<Rational> {
        match v {
            V::P(k) => &self.p[(k + self.w + 2) as usize],
            V::Q(k) => &self.q[(k + self.w + 2) as usize],
        }
    }

    /// The two strip triangles on an interior edge (rung `p_kq_k` or diagonal `p_kq_{k+1}`);
    /// `None` for a boundary side.
    fn triangles_on(e: (V, V)) -> Option<[[V; 3]; 2]> {
        let (p, q) = match e {
            (V::P(k), V::Q(l)) | (V::Q(l), V::P(k)) => (k, l),
            _ => return None,
        };
        if q == p {
            Some([
                [V::P(p - 1), V::Q(p), V::P(p)],
                [V::P(p), V::Q(p), V::Q(p + 1)],
            ])
        } else if q == p + 1 {
            Some([
                [V::P(p), V::Q(p), V::Q(p + 1)],
                [V::P(p), V::Q(p + 1), V::P(p + 1)],
            ])
        } else {
            panic!("not an edge of the strip: {e:?}")
        }
    }

    /// Whether the segment `p₀q_m` lies in the strip, by walking it through the triangles.
    fn valid(&self, m: i64) -> bool {
        if m == 0 || m == 1 {
            return true;
        }
        let o = self.at(V::P(0)).clone();
        let target = self.at(V::Q(m)).clone();
        // The fan at p₀: T_{-1} = (p₋₁, q₀, p₀), T′₀ = (p₀, q₀, q₁), T₀ = (p₀, q₁, p₁).
        let fan = [
            ([V::P(-1), V::Q(0), V::P(0)], V::P(-1), V::Q(0)),
            ([V::P(0), V::Q(0), V::Q(1)], V::Q(0), V::Q(1)),
            ([V::P(0), V::Q(1), V::P(1)], V::Q(1), V::P(1)),
        ];
        let Some((mut triangle, mut u, mut v)) = fan.into_iter().find(|(_, u, v)| {
            orient(&o, self.at(*u), &target) == Ordering::Greater
                && orient(&o, &target, self.at(*v)) == Ordering::Greater
        }) else {
            return false; // along a fan edge or outside the angle at p₀
        };
        for _ in 0..4 * (m.abs() + 4) {
            // Leave `triangle` through the edge (u, v), which the segment's line crosses.
            let Some(pair) = Self::triangles_on((u, v)) else {
                return false; // a boundary side
            };
            let (pu, pv) = (self.at(u), self.at(v));
            let before = orient(pu, pv, &o);
            let after = orient(pu, pv, &target);
            if after == Ordering::Equal || after == before {
                return false; // the segment ends before the edge, or on it
            }
            let next = if pair[0] == triangle {
                pair[1]
            } else {
                pair[0]
            };
            let w = *next.iter().find(|x| **x != u && **x != v).unwrap();
            match orient(&o, &target, self.at(w)) {
                Ordering::Equal => return w == V::Q(m),
                side => {
                    if orient(&o, &target, pu) == side {
                        u = w;
                    } else {
                        v = w;
                    }
                }
            }
            triangle = next;
        }
        panic!("the walk of p0 q_{m} did not end");
    }
}

/// What the oracle knows about a biface over the offsets `[-w, w]`.
struct Oracle {
    w: i64,
    valid: Vec<bool>,
    d: Vec<Rational>,
    d_min: Rational,
}

impl Oracle {
    fn new(corners: &[Point<Rational>; 4], w: i64) -> Oracle {
        let strip = Strip::new(corners, w);
        let offsets = -w..=w;
        let valid: Vec<bool> = offsets.clone().map(|m| strip.valid(m)).collect();
        let d: Vec<Rational> = offsets
            .map(|m| dist2(strip.at(V::P(0)), strip.at(V::Q(m))))
            .collect();
        let d_min = d
            .iter()
            .zip(&valid)
            .filter(|(_, v)| **v)
            .map(|(d, _)| d.clone())
            .min()
            .unwrap();
        Oracle { w, valid, d, d_min }
    }

    fn valid(&self, m: i64) -> bool {
        assert!(m.abs() <= self.w, "offset {m} outside the oracle's window");
        self.valid[(m + self.w) as usize]
    }

    fn d(&self, m: i64) -> &Rational {
        &self.d[(m + self.w) as usize]
    }

    fn valid_set_is_an_interval(&self) -> bool {
        let first = self.valid.iter().position(|v| *v).unwrap();
        let last = self.valid.iter().rposition(|v| *v).unwrap();
        self.valid[first..=last].iter().all(|v| *v)
    }

    /// The window holds every shortest offset: for a translation the squared distance is a
    /// convex quadratic in m, so an interior minimum is global; otherwise the window's two ends
    /// are invalid and the valid set is an interval.
    fn window_is_conclusive(&self, translation: bool) -> bool {
        let interior_min = *self.d(-self.w) > self.d_min && *self.d(self.w) > self.d_min;
        if translation {
            interior_min
        } else {
            !self.valid(-self.w) && !self.valid(self.w) && self.valid_set_is_an_interval()
        }
    }

    /// Section 3: rung offset j is good when one of p₀q_j, p₀q_{j+1} is a shortest path and the
    /// other is the shorter diagonal of the quadrilateral cut along it.
    fn good(&self, j: i64) -> bool {
        let e_second =
            *self.d(j + 1) == self.d_min && (!self.valid(j + 2) || self.d(j) <= self.d(j + 2));
        let e_first =
            *self.d(j) == self.d_min && (!self.valid(j - 1) || self.d(j + 1) <= self.d(j - 1));
        self.valid(j) && self.valid(j + 1) && (e_first || e_second)
    }

    /// Whether the shortest length, or the diagonal choice, is decided by a relative margin
    /// below `eps` (where f64 may legitimately differ from the exact answer).
    fn near_tie(&self, eps: f64) -> bool {
        let d_min = self.d_min.to_f64();
        let close = |m: i64| {
            self.valid(m) && *self.d(m) != self.d_min && self.d(m).to_f64() - d_min <= eps * d_min
        };
        let m_star = (-self.w..=self.w)
            .find(|m| self.valid(*m) && *self.d(*m) == self.d_min)
            .unwrap();
        let neighbours = self.valid(m_star - 1)
            && self.valid(m_star + 1)
            && (self.d(m_star - 1).to_f64() - self.d(m_star + 1).to_f64()).abs()
                <= eps * self.d(m_star + 1).to_f64();
        (-self.w..=self.w).any(close) || neighbours
    }
}

fn corners_of(b: &Biface<Rational>) -> [Point<Rational>; 4] {
    [b.a(), b.d(), b.b(), b.c()].map(|p| p.clone())
}

fn point(x: Rational, y: Rational) -> Point<Rational> {
    [x, y]
}

/// A random rational with denominator at most `den` and absolute value at most `span`.
fn random_rational(rng: &mut ChaCha8Rng, span: i64, den: i64) -> Rational {
    let q = rng.random_range(1..=den);
    Rational::new(rng.random_range(-span * q..=span * q), q).unwrap()
}

fn random_point(rng: &mut ChaCha8Rng, span: i64, den: i64) -> Point<Rational> {
    [
        random_rational(rng, span, den),
        random_rational(rng, span, den),
    ]
}

/// A random translation biface with its shortest offset within ±13.
fn random_translation(rng: &mut ChaCha8Rng) -> Biface<Rational> {
    loop {
        let a = random_point(rng, 4, 4);
        let t = random_point(rng, 3, 2);
        // |t| ≥ 1 keeps the shortest offset within ±13 (|k| ≤ 8, |⟨w, t⟩|/|t|² ≤ 3√2).
        if dot(&t, &t) < ri(1) {
            continue;
        }
        let k = random_rational(rng, 8, 3);
        let w = random_point(rng, 3, 4);
        let d = [
            a[0].clone() + k.clone() * t[0].clone() + w[0].clone(),
            a[1].clone() + k * t[1].clone() + w[1].clone(),
        ];
        let c = [a[0].clone() + t[0].clone(), a[1].clone() + t[1].clone()];
        let b = [d[0].clone() + t[0].clone(), d[1].clone() + t[1].clone()];
        if let Ok(biface) = Biface::new(a, d, b, c, 0.0) {
            return biface;
        }
    }
}

/// A rational point of the unit circle `((1 − u²) + 2ui)/(1 + u²)`, of argument `2 atan u`.
fn unit_complex(u: &Rational) -> Point<Rational> {
    let u2 = u.clone() * u.clone();
    let n = ri(1) + u2.clone();
    [(ri(1) - u2) / n.clone(), (ri(2) * u.clone()) / n]
}

/// A random rotation biface with `|θ| = 2|atan u|` for `min_u ≤ |u| ≤ 2`.
fn random_rotation(rng: &mut ChaCha8Rng, min_u: f64) -> Biface<Rational> {
    loop {
        let u = random_rational(rng, 2, 12);
        if u.to_f64().abs() < min_u {
            continue;
        }
        let omega = unit_complex(&u);
        let a = random_point(rng, 4, 4);
        let d = random_point(rng, 4, 4);
        let c = random_point(rng, 4, 4);
        let rot = surftopo_intrinsic::geometry::complex_mul(&omega, &sub(&d, &a));
        let b = [c[0].clone() + rot[0].clone(), c[1].clone() + rot[1].clone()];
        if let Ok(biface) = Biface::new(a, d, b, c, 0.0) {
            return biface;
        }
    }
}

/// Twice-π-turns plus a principal argument: an exact total of corner angles.
#[derive(Clone, Debug, PartialEq)]
struct AngleSum {
    turns: i64,
    z: Point<Rational>,
}

/// 0: (−π, 0), 1: 0, 2: (0, π), 3: π.
fn arg_class(z: &Point<Rational>) -> u8 {
    match (z[1].sign(), z[0].sign()) {
        (Ordering::Less, _) => 0,
        (Ordering::Equal, Ordering::Greater) => 1,
        (Ordering::Greater, _) => 2,
        _ => 3,
    }
}

fn arg_less(a: &Point<Rational>, b: &Point<Rational>) -> bool {
    let (ca, cb) = (arg_class(a), arg_class(b));
    ca < cb || (ca == cb && (ca == 0 || ca == 2) && cross(a, b).sign() == Ordering::Greater)
}

impl AngleSum {
    fn zero() -> Self {
        AngleSum {
            turns: 0,
            z: point(ri(1), ri(0)),
        }
    }

    /// Adds the corner angle at `o` of a counter-clockwise triangle `(o, u, w)` (in `(0, π)`).
    fn add_corner(&mut self, o: &Point<Rational>, u: &Point<Rational>, w: &Point<Rational>) {
        let (du, dw) = (sub(u, o), sub(w, o));
        assert_eq!(cross(&du, &dw).sign(), Ordering::Greater);
        // w/u up to the positive factor |u|²: dw · conj(du).
        let ratio = [
            dw[0].clone() * du[0].clone() + dw[1].clone() * du[1].clone(),
            dw[1].clone() * du[0].clone() - dw[0].clone() * du[1].clone(),
        ];
        let z = surftopo_intrinsic::geometry::complex_mul(&self.z, &ratio);
        if arg_less(&z, &self.z) {
            self.turns += 1;
        }
        self.z = z;
    }

    fn same(&self, other: &AngleSum) -> bool {
        self.turns == other.turns
            && cross(&self.z, &other.z).is_zero()
            && dot(&self.z, &other.z).sign() == Ordering::Greater
    }
}

/// The total angle at `b₀` (corners A and C of (A, B, C), corner A of (A, D, B)).
fn angle_at_b0(corners: &[Point<Rational>; 4]) -> AngleSum {
    let [a, d, b, c] = corners;
    let mut sum = AngleSum::zero();
    sum.add_corner(a, b, c);
    sum.add_corner(c, a, b);
    sum.add_corner(a, d, b);
    sum
}

/// The total angle at `b₀` in f64 (atan2 of the corners).
fn angle_at_b0_f64(b: &Biface<f64>) -> f64 {
    let corner = |o: &Point<f64>, u: &Point<f64>, w: &Point<f64>| {
        let (du, dw) = (sub(u, o), sub(w, o));
        cross(&du, &dw).atan2(dot(&du, &dw))
    };
    corner(b.a(), b.b(), b.c()) + corner(b.c(), b.a(), b.b()) + corner(b.a(), b.d(), b.b())
}

/// Checks the exact kernel on one biface against the oracle; returns the kind.
fn check_exact(biface: &Biface<Rational>, w: i64) -> BifaceKind {
    let corners = corners_of(biface);
    let oracle = Oracle::new(&corners, w);
    assert!(
        oracle.window_is_conclusive(biface.is_translation()),
        "window ±{w} too small for {corners:?}"
    );
    let good = biface.make_good().unwrap();
    assert_eq!(good.shortest_length2, oracle.d_min, "{corners:?}");
    let j = good.rung_offset.to_f64() as i64;
    assert!(oracle.good(j), "rung offset {j} not good for {corners:?}");
    assert_eq!(good.unchanged, oracle.good(0), "{corners:?}");
    if good.unchanged {
        assert_eq!(&good.biface, biface);
    }
    // The result is good by the oracle, and returned unchanged by the kernel.
    let out = corners_of(&good.biface);
    let oracle_out = Oracle::new(&out, w);
    assert!(oracle_out.good(0), "result not good: {out:?}");
    assert_eq!(oracle_out.d_min, oracle.d_min);
    let again = good.biface.make_good().unwrap();
    assert!(again.unchanged && again.biface == good.biface);
    // Invariants, exactly: area, boundary lengths, angle at b₀ (so at b₁: the sum is 2π), the
    // gluing.
    assert_eq!(good.biface.twice_area(), biface.twice_area());
    assert_eq!(good.biface.boundary_lengths2(), biface.boundary_lengths2());
    assert!(angle_at_b0(&out).same(&angle_at_b0(&corners)));
    assert_eq!(good.biface.gluing(), biface.gluing());
    let kind = good.biface.kind().unwrap();
    assert_eq!(
        biface.kind().unwrap() == BifaceKind::NotGood,
        !good.unchanged
    );
    kind
}

fn kind_counts(kinds: &[BifaceKind]) -> (usize, usize) {
    let thin = kinds.iter().filter(|k| **k == BifaceKind::Thin).count();
    let thick = kinds.iter().filter(|k| **k == BifaceKind::Thick).count();
    assert_eq!(thin + thick, kinds.len());
    (thin, thick)
}

/// `translations` and `rotations` random bifaces, the oracle over offsets `±w_t` and `±w_r`.
fn exact_agreement(
    translations: usize,
    rotations: usize,
    min_u: f64,
    [w_t, w_r]: [i64; 2],
    seed: u64,
) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    // Per kind: count, generator, window, the thin and not-good fractions expected at least.
    type Generator = Box<dyn Fn(&mut ChaCha8Rng) -> Biface<Rational>>;
    let kinds: [(usize, bool, Generator, i64, usize, usize); 2] = [
        (translations, true, Box::new(random_translation), w_t, 20, 2),
        (
            rotations,
            false,
            Box::new(move |rng| random_rotation(rng, min_u)),
            w_r,
            50,
            4,
        ),
    ];
    for (count, translation, generate, w, thin_part, changed_part) in kinds {
        let mut seen = Vec::new();
        let mut changed = 0;
        for _ in 0..count {
            let b = generate(&mut rng);
            assert_eq!(b.is_translation(), translation);
            changed += usize::from(!b.is_good().unwrap());
            seen.push(check_exact(&b, w));
        }
        let (thin, thick) = kind_counts(&seen);
        assert!(
            thin > count / thin_part && thick > count / 20,
            "{thin} thin, {thick} thick"
        );
        assert!(
            changed > count / changed_part,
            "only {changed} of {count} bifaces were not good"
        );
    }
}

#[test]
fn kernel_agrees_with_the_ladder_oracle_exact() {
    exact_agreement(800, 800, 0.16, [14, 22], 1);
}

#[test]
#[ignore = "large sweep: cargo test --release -p surftopo-intrinsic --test bifaces -- --ignored"]
fn kernel_agrees_with_the_ladder_oracle_exact_large() {
    exact_agreement(20_000, 20_000, 0.16, [14, 22], 2);
    // Slower rotations: longer valid intervals.
    exact_agreement(100, 2_000, 0.05, [14, 66], 3);
}

#[test]
fn validity_criterion_agrees_with_the_walk() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let w = 30;
    let mut valid_far = 0;
    for _ in 0..400 {
        let b = random_rotation(&mut rng, 0.16);
        let strip = Strip::new(&corners_of(&b), w);
        for m in -w..=w {
            let walk = strip.valid(m);
            assert_eq!(
                b.is_valid_offset(&ri(m)).unwrap(),
                walk,
                "offset {m} of {:?}",
                corners_of(&b)
            );
            valid_far += usize::from(walk && !(0..=1).contains(&m));
        }
    }
    assert!(
        valid_far > 400,
        "only {valid_far} valid offsets besides 0 and 1"
    );
    // Translations: every offset is valid.
    for _ in 0..100 {
        let b = random_translation(&mut rng);
        let strip = Strip::new(&corners_of(&b), w);
        assert!((-w..=w).all(|m| strip.valid(m)));
    }
}

/// f64: the kernel's answer is the exact answer for the same biface up to near ties.
fn f64_agreement(count: usize, seed: u64) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (mut compared, mut ties) = (0, 0);
    for i in 0..count {
        let exact = if i % 2 == 0 {
            random_translation(&mut rng)
        } else {
            random_rotation(&mut rng, 0.16)
        };
        let corners = corners_of(&exact);
        let [a, d, b, c] = corners.clone().map(|p| [p[0].to_f64(), p[1].to_f64()]);
        let Ok(rounded) = Biface::new(a, d, b, c, 1e-12) else {
            continue;
        };
        let oracle = Oracle::new(&corners, if exact.is_translation() { 14 } else { 22 });
        assert!(oracle.window_is_conclusive(exact.is_translation()));
        let good = rounded.make_good().unwrap();
        let good_exact = exact.make_good().unwrap();
        let rel = (good.shortest_length2 - oracle.d_min.to_f64()).abs() / oracle.d_min.to_f64();
        assert!(rel < 1e-12, "shortest length off by {rel} for {corners:?}");
        if oracle.near_tie(1e-9) {
            ties += 1;
            continue;
        }
        compared += 1;
        assert_eq!(
            good.rung_offset,
            good_exact.rung_offset.to_f64(),
            "{corners:?}"
        );
        assert_eq!(good.unchanged, good_exact.unchanged);
        // Invariants to 1e-12 relative.
        let close = |x: f64, y: f64| (x - y).abs() <= 1e-12 * x.abs().max(y.abs());
        assert!(close(good.biface.twice_area(), rounded.twice_area()));
        let (l0, l1) = (good.biface.boundary_lengths2(), rounded.boundary_lengths2());
        assert!(close(l0[0], l1[0]) && close(l0[1], l1[1]));
        assert!(close(
            angle_at_b0_f64(&good.biface),
            angle_at_b0_f64(&rounded)
        ));
        assert!(good.biface.make_good().unwrap().unchanged);
    }
    assert!(
        compared > count * 9 / 10,
        "{compared} compared, {ties} near ties"
    );
}

#[test]
fn f64_kernel_agrees_with_the_exact_one() {
    f64_agreement(1000, 11);
}

#[test]
#[ignore = "large sweep: cargo test --release -p surftopo-intrinsic --test bifaces -- --ignored"]
fn f64_kernel_agrees_with_the_exact_one_large() {
    f64_agreement(40_000, 12);
}

/// `T_x` (Section 9; docs/dubois.md §5) cut along its unit loop `u`: Δ₁ = (0,0),(1,0),(x,2) and
/// Δ₂ = (1+x,2),(x,2),(1,0), sides 1 and 2 still matched. In the chart A = (1,0), D = (1+x,2),
/// B = (x,2), C = (0,0) (boundary sides CA and DB are the two copies of u).
fn t_x_cut<S: Scalar>(x: S) -> Biface<S> {
    let (zero, one, two) = (S::zero(), S::one(), S::from_i64(2));
    Biface::new(
        [one.clone(), zero.clone()],
        [one + x.clone(), two.clone()],
        [x, two],
        [zero.clone(), zero],
        0.0,
    )
    .unwrap()
}

#[test]
fn t_x_cut_along_its_unit_loop_gives_d_x() {
    let xs = [
        "2",
        "3",
        "7/2",
        "10/3",
        "1000000000.333",
        "1000000000",
        "1000000000000000000",
        "1000000000000000000.5",
        "3000000000000000001/3",
        "2000000000000000001/2000",
        "999999999999999999.999999",
    ];
    for s in xs {
        let x = r(s);
        let biface = t_x_cut(x.clone());
        assert!(biface.is_translation());
        let good = biface.make_good().unwrap();
        let frac = x.clone() - x.floor();
        // The good biface's triangle (A, B, C) is (1,0), (x − ⌊x⌋, 2), (0,0).
        assert_eq!(good.biface.a(), &[ri(1), ri(0)], "x = {s}");
        assert_eq!(good.biface.c(), &[ri(0), ri(0)], "x = {s}");
        assert_eq!(good.biface.b(), &[frac.clone(), ri(2)], "x = {s}");
        assert_eq!(good.rung_offset, x.floor(), "x = {s}");
        // Its other triangle (A, D, B) is the translate of (0,0), (1,0), ... by construction:
        // D = B + (1, 0).
        assert_eq!(good.biface.d(), &[frac + ri(1), ri(2)], "x = {s}");
        assert_eq!(good.biface.twice_area(), biface.twice_area());
        assert!(good.biface.make_good().unwrap().unchanged);
    }
    // T_1 is already good (its two interior edges are the short diagonal and a side).
    assert!(t_x_cut(ri(1)).is_good().unwrap());
    // f64: exact for dyadic x well inside 2⁵³.
    for x in [2.0, 3.5, 1e6 + 0.25, 12345.75] {
        let good = t_x_cut(x).make_good().unwrap();
        assert_eq!(good.biface.b(), &[x - x.floor(), 2.0], "x = {x}");
    }
}

mod common_tubes;

use common_tubes::{RandomTube, random_tube};
use surftopo_intrinsic::geometry::twice_signed_area;
use surftopo_intrinsic::{GoodBiface, Portalgon, TubeReport, TubeRoute};

/// Maps `x`'s chart onto `y`'s by their `b₀` sides (`C → A`) and compares the other corners.
fn same_biface(x: &Biface<Rational>, y: &Biface<Rational>) -> bool {
    let m = Motion::taking(x.c(), x.a(), y.c(), y.a());
    m.apply(x.d()) == *y.d() && m.apply(x.b()) == *y.b()
}

/// Proposition 4 by both routes on a random exact tube, checked against the data it was built
/// from and the oracle.
fn check_random_tube(
    seed: u64,
    rotation: bool,
    rung: usize,
    inner: usize,
) -> ([GoodBiface<Rational>; 2], TubeReport, bool) {
    let tube: RandomTube<Rational> = random_tube(seed, rotation, rung, inner);
    let p = &tube.portalgon;
    p.check_invariants().unwrap();
    let polygons: Vec<_> = p.polygons().collect();
    let recognised = p.tube(&polygons, 0.0).unwrap();
    let mut boundary = tube.boundary;
    boundary.sort();
    assert_eq!(recognised.boundary, boundary);
    let [qa, qd, qb, qc] = tube.quad.map(|v| point(ri(v[0]), ri(v[1])));
    let (a, b, c) = tube.omega;
    let omega = [ri(a) / ri(c), ri(b) / ri(c)];
    // The quad's angles at b₀ (corners A and C) and at b₁ (corners D and B).
    let mut angle = AngleSum::zero();
    angle.add_corner(&qa, &qd, &qc);
    angle.add_corner(&qc, &qa, &qb);
    let mut angle_b1 = AngleSum::zero();
    angle_b1.add_corner(&qd, &qb, &qa);
    angle_b1.add_corner(&qb, &qc, &qd);
    // The first boundary side in id order is CA or DB of the quad.
    let ca_first = tube.boundary[0] < tube.boundary[1];
    let mut results = Vec::new();
    let mut paper = TubeReport::default();
    for route in [TubeRoute::Direct, TubeRoute::Paper] {
        let (good, report) = p.good_biface_of_tube(&polygons, route, 0.0).unwrap();
        let out = &good.biface;
        let corners = corners_of(out);
        assert_eq!(
            out.twice_area(),
            twice_signed_area(&[qa.clone(), qd.clone(), qb.clone(), qc.clone()])
        );
        // Charted from DB, the deck transformation taking p₀ to p₁ is g⁻¹.
        let want = if ca_first {
            omega.clone()
        } else {
            [omega[0].clone(), -omega[1].clone()]
        };
        assert_eq!(out.gluing().rotation, want, "seed {seed} {route:?}");
        let [l0, l1] = out.boundary_lengths2();
        let (ca, db) = (dist2(&qc, &qa), dist2(&qd, &qb));
        if ca_first {
            assert_eq!((l0, l1), (ca, db));
            assert!(angle_at_b0(&corners).same(&angle), "seed {seed} {route:?}");
        } else {
            assert_eq!((l0, l1), (db, ca));
            assert!(
                angle_at_b0(&corners).same(&angle_b1),
                "seed {seed} {route:?}"
            );
        }
        let w = if rotation { 26 } else { 14 };
        let oracle = Oracle::new(&corners, w);
        assert!(oracle.window_is_conclusive(!rotation));
        assert!(oracle.good(0), "seed {seed} {route:?}: not good");
        assert!(out.is_good().unwrap());
        if route == TubeRoute::Paper {
            assert_eq!(report.merges + 1, report.bifaces);
            assert!(report.deleted_vertices <= tube.interior_vertices);
            // Lemma 28: fewer than 3n bifaces.
            assert!(report.bifaces < 3 * report.triangles);
            paper = report;
        }
        results.push(good);
    }
    // The routes agree unless the good biface is not unique (a tie of lengths: then the tie
    // rules, which keep the current edges, depend on the intermediate bifaces).
    let tie = {
        let oracle = Oracle::new(
            &corners_of(&results[0].biface),
            if rotation { 26 } else { 14 },
        );
        oracle.good(-1) || oracle.good(1)
    };
    assert!(
        tie || same_biface(&results[0].biface, &results[1].biface),
        "seed {seed}: the routes differ"
    );
    // In place: the tube becomes the two triangles, boundary ids kept.
    let mut q = p.clone();
    let (created, good, _) = q
        .replace_tube_by_good_biface(&polygons, TubeRoute::Direct, 0.0)
        .unwrap();
    q.check_invariants().unwrap();
    assert_eq!(q.polygon_count(), 2);
    assert_eq!(q.area(), p.area());
    assert!(
        tube.boundary
            .iter()
            .all(|&s| q.is_side_live(s) && q.mate(s).is_none())
    );
    assert!(same_biface(&good.biface, &results[0].biface));
    assert!(q.tube(&created, 0.0).is_ok());
    let [x, y] = results.try_into().unwrap_or_else(|_| unreachable!());
    ([x, y], paper, tie)
}

#[test]
fn random_tubes_give_one_good_biface_by_both_routes() {
    let (mut changed, mut deleted, mut extra, mut ties) = (0, 0, 0, 0);
    for seed in 0..24 {
        let rotation = seed % 2 == 1;
        let ([direct, _], paper, tie) = check_random_tube(
            seed,
            rotation,
            1 + (seed % 4) as usize,
            (seed % 7) as usize * 3,
        );
        changed += usize::from(direct.rung_offset != ri(0));
        deleted += paper.deleted_vertices;
        extra += paper.bifaces - 1;
        ties += usize::from(tie);
    }
    assert!(ties <= 3, "{ties} tubes of 24 have several good bifaces");
    assert!(changed >= 6, "only {changed} tubes needed a new rung");
    // Lemma 28 deleted vertices, and left concatenations of several bifaces to merge.
    assert!(
        deleted > 24 && extra > 6,
        "{deleted} deleted, {extra} extra bifaces"
    );
}

#[test]
#[ignore = "large sweep: cargo test --release -p surftopo-intrinsic --test bifaces -- --ignored"]
fn random_tubes_give_one_good_biface_by_both_routes_large() {
    for seed in 0..300 {
        check_random_tube(
            seed,
            seed % 2 == 1,
            1 + (seed % 6) as usize,
            (seed % 13) as usize * 5,
        );
    }
}

#[test]
fn f64_tubes_agree_with_exact_ones() {
    for seed in 0..12u64 {
        let rotation = seed % 2 == 0;
        let exact: RandomTube<Rational> = random_tube(seed + 100, rotation, 2, 6);
        let rounded: RandomTube<f64> = random_tube(seed + 100, rotation, 2, 6);
        let polygons: Vec<_> = exact.portalgon.polygons().collect();
        let (good, _) = exact
            .portalgon
            .good_biface_of_tube(&polygons, TubeRoute::Direct, 0.0)
            .unwrap();
        let want = good.biface.interior_lengths2().map(|x| x.to_f64());
        for route in [TubeRoute::Direct, TubeRoute::Paper] {
            let (g, _) = rounded
                .portalgon
                .good_biface_of_tube(&polygons, route, 1e-9)
                .unwrap();
            let got = g.biface.interior_lengths2();
            for i in 0..2 {
                assert!(
                    (got[i] - want[i]).abs() <= 1e-9 * want[i],
                    "seed {seed} {route:?}: {got:?} {want:?}"
                );
            }
            assert!(
                (g.biface.twice_area() - good.biface.twice_area().to_f64()).abs()
                    <= 1e-9 * g.biface.twice_area()
            );
        }
    }
}

/// `T_x` as a portalgon cut along its unit loop: Δ₁ = (0,0),(1,0),(x,2), Δ₂ = (1+x,2),(x,2),(1,0),
/// sides 1 and 2 matched, sides 0 the two boundary loops.
fn t_x_tube(x: &str) -> Portalgon<Rational> {
    let x = r(x);
    let mut p = Portalgon::<Rational>::empty();
    let d1 = p
        .add_polygon(&[
            point(ri(0), ri(0)),
            point(ri(1), ri(0)),
            point(x.clone(), ri(2)),
        ])
        .unwrap();
    let d2 = p
        .add_polygon(&[
            point(ri(1) + x.clone(), ri(2)),
            point(x, ri(2)),
            point(ri(1), ri(0)),
        ])
        .unwrap();
    for i in [1, 2] {
        p.glue(p.side(d1, i), p.side(d2, i), 0.0).unwrap();
    }
    p
}

#[test]
fn t_x_tube_gives_d_x_by_both_routes() {
    for x in [
        "7/2",
        "10/3",
        "1000000000.333",
        "1000000000000000000",
        "3000000000000000001/3",
    ] {
        let p = t_x_tube(x);
        let polygons: Vec<_> = p.polygons().collect();
        let frac = r(x) - r(x).floor();
        for route in [TubeRoute::Direct, TubeRoute::Paper] {
            let (good, _) = p.good_biface_of_tube(&polygons, route, 0.0).unwrap();
            let b = &good.biface;
            // Chart it so that the b₀ side runs (0,0) → (1,0): B lands on (x − ⌊x⌋, 2).
            let m = Motion::taking(b.c(), b.a(), &point(ri(0), ri(0)), &point(ri(1), ri(0)));
            assert_eq!(
                m.apply(b.b()),
                point(frac.clone(), ri(2)),
                "x = {x} {route:?}"
            );
            assert_eq!(
                m.apply(b.d()),
                point(frac.clone() + ri(1), ri(2)),
                "x = {x} {route:?}"
            );
        }
    }
}

/// An annulus cut from a hexagon A, r, D, B, r′, C (A = (0,0), D = (0,2h), B = (−w,2h),
/// C = (−w,0), r = (1,h)) with the bent rung A → r → D glued to r′ → C and B → r′. With
/// r′ = r − (w, 0) = g(r) the vertex r is flat; with r′ mirrored to (−w − 1, h) its angle is
/// below 2π: a cone point, not a tube.
fn bent_rung_annulus<S: Scalar>(mirrored: bool) -> Portalgon<S> {
    let (h, w) = (3, 5);
    let p = |x: i64, y: i64| [S::from_i64(x), S::from_i64(y)];
    let (a, r, d, b, c) = (p(0, 0), p(1, h), p(0, 2 * h), p(-w, 2 * h), p(-w, 0));
    let r2 = if mirrored { p(-w - 1, h) } else { p(1 - w, h) };
    let mut x = Portalgon::<S>::empty();
    let fan = [[&a, &r, &d], [&a, &d, &b], [&a, &b, &r2], [&a, &r2, &c]]
        .map(|t| x.add_polygon(&t.map(|q| q.clone())).unwrap());
    for k in 0..3 {
        x.glue(x.side(fan[k], 2), x.side(fan[k + 1], 0), 1e-12)
            .unwrap();
    }
    x.glue(x.side(fan[0], 0), x.side(fan[3], 1), 1e-12).unwrap();
    x.glue(x.side(fan[0], 1), x.side(fan[2], 1), 1e-12).unwrap();
    x
}

#[test]
fn a_cone_point_inside_is_not_a_tube() {
    fn check<S: Scalar>(tolerance: f64) {
        let flat = bent_rung_annulus::<S>(false);
        flat.check_invariants().unwrap();
        let all: Vec<_> = flat.polygons().collect();
        assert!(flat.tube(&all, tolerance).is_ok());
        let (direct, _) = flat
            .good_biface_of_tube(&all, TubeRoute::Direct, tolerance)
            .unwrap();
        let (paper, _) = flat
            .good_biface_of_tube(&all, TubeRoute::Paper, tolerance)
            .unwrap();
        assert_eq!(direct.shortest_length2, paper.shortest_length2);
        let cone = bent_rung_annulus::<S>(true);
        cone.check_invariants().unwrap();
        assert!(matches!(
            cone.tube(&all, tolerance),
            Err(surftopo_intrinsic::TubeError::NotFlat { .. })
        ));
    }
    check::<Rational>(0.0);
    check::<f64>(1e-9);
}
