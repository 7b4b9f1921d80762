//! Numerically robust triangle formulas from side lengths alone.
//!
//! Everything here follows W. Kahan, "Miscalculating area and angles of a needle-like triangle"
//! (2014): with the sides sorted `a >= b >= c`, the four factors
//! `a + (b + c)`, `c - (a - b)`, `c + (a - b)`, `a + (b - c)` (that is `2s`, `2(s - a)`, `2(s - b)`,
//! `2(s - c)`) are each computed with a small *relative* error, however thin the triangle. Angles
//! are then taken through the tangent of the half angle, `tan²(A/2) = (s-b)(s-c) / (s(s-a))`, which
//! keeps relative accuracy for angles near 0 and near π alike.
//!
//! The intrinsic Delaunay test, the flip length, the cotangent weights and the planar layouts of
//! the crate are all derived from these half-angle tangents (see each function).

/// `[2s, 2(s - o), 2(s - x), 2(s - y)]` for the triangle with sides `o, x, y`, each with small
/// relative error (Kahan's ordering). The triangle inequality holds strictly iff all four are
/// positive.
///
/// With `a >= b >= c` the sides sorted (max, median, min: exact, and branch-free), the factors
/// are `a + (b + c)`, `c - (a - b)`, `c + (a - b)`, `a + (b - c)`; each side then takes the factor
/// of its rank (equal sides get equal factors, so ties do not matter).
#[inline]
pub fn excesses(o: f64, x: f64, y: f64) -> [f64; 4] {
    let a = o.max(x).max(y);
    let c = o.min(x).min(y);
    let b = o.min(x).max(o.max(x).min(y));
    let (e_a, e_b, e_c) = (c - (a - b), c + (a - b), a + (b - c));
    let rank = |v: f64| {
        if v == a {
            e_a
        } else if v == c {
            e_c
        } else {
            e_b
        }
    };
    [a + (b + c), rank(o), rank(x), rank(y)]
}

/// Lengths whose products of four (Kahan's Heron formula) neither overflow nor underflow: the
/// largest side within `[2^-250, 2^250]` needs no scaling.
const SAFE_EXPONENT: i32 = 250;
/// `2^-SAFE_EXPONENT` and `2^(SAFE_EXPONENT + 1)`: the largest side needs no scaling in between.
const SAFE_LOW: f64 = f64::from_bits(((1023 - SAFE_EXPONENT) as u64) << 52);
const SAFE_HIGH: f64 = f64::from_bits(((1023 + SAFE_EXPONENT + 1) as u64) << 52);

/// The sides scaled by an exact power of two `2^-k` so that the largest lies in `[1, 2)`, and `k`;
/// the sides themselves and `k = 0` when the largest is within `[2^-250, 2^250]` (or is zero or
/// not finite). Angles and the triangle inequality do not change under scaling, lengths scale by
/// `2^k` and areas by `4^k`, so the formulas below are scale-free: no overflow for sides up to
/// `f64::MAX`, no underflow down to the smallest normal numbers (Kahan's factors stay accurate).
#[inline]
fn normalized(o: f64, x: f64, y: f64) -> (f64, f64, f64, i32) {
    let m = o.max(x).max(y);
    // The common case first, by two comparisons (no logarithm): `2^-250 <= m < 2^251` is
    // `-250 <= floor(log2 m) <= 250`; also the case of zero and non-finite sides.
    if !(m.is_finite() && m > 0.0) || (SAFE_LOW..SAFE_HIGH).contains(&m) {
        return (o, x, y, 0);
    }
    let k = m.log2().floor() as i32;
    if (-SAFE_EXPONENT..=SAFE_EXPONENT).contains(&k) {
        return (o, x, y, 0);
    }
    let s = pow2(-k);
    (o * s, x * s, y * s, k)
}

/// `2^k` exactly, for `|k| <= 2000` (two steps, so that `2^-1074..2^1023` sides scale without
/// overflowing the factor itself).
#[inline]
fn pow2(k: i32) -> f64 {
    let half = k / 2;
    2f64.powi(half) * 2f64.powi(k - half)
}

/// Whether three lengths are finite, positive and satisfy the triangle inequality strictly
/// (the triangle has positive area).
#[inline]
pub fn is_triangle(a: f64, b: f64, c: f64) -> bool {
    let all_finite = a.is_finite() && b.is_finite() && c.is_finite();
    let [p, ea, eb, ec] = excesses(a, b, c);
    all_finite && p > 0.0 && ea > 0.0 && eb > 0.0 && ec > 0.0
}

/// `tan²(θ/2)` of the angle θ opposite side `o` in the triangle with sides `o, x, y`.
///
/// Relative error a few ulps for any valid triangle. Degenerate triangles give 0 (θ = 0) or
/// `+inf` (θ = π); invalid ones give a negative value or NaN.
#[inline]
pub fn tan_half_sq(o: f64, x: f64, y: f64) -> f64 {
    let (o, x, y, _) = normalized(o, x, y);
    let [p, eo, ex, ey] = excesses(o, x, y);
    (ex * ey) / (p * eo)
}

/// The angle opposite side `o` in the triangle with sides `o, x, y`, in `[0, π]` (the tests
/// check the half-angle formulas through it; the algorithms never need the angle itself).
#[cfg(test)]
pub fn angle(o: f64, x: f64, y: f64) -> f64 {
    2.0 * tan_half_sq(o, x, y).sqrt().atan()
}

/// The cotangent of the angle opposite side `o`: `(1 - t²) / (2t)` with `t = tan(θ/2)` (for the
/// tests; the Laplacian uses [`cot_from_tan_half_sq`] on the flips' tangents).
#[cfg(test)]
pub fn cot(o: f64, x: f64, y: f64) -> f64 {
    let t2 = tan_half_sq(o, x, y);
    (1.0 - t2) / (2.0 * t2.sqrt())
}

/// The cotangent from `t² = tan²(θ/2)`.
#[inline]
pub fn cot_from_tan_half_sq(t2: f64) -> f64 {
    (1.0 - t2) / (2.0 * t2.sqrt())
}

/// The area of the triangle with sides `a, b, c` (Kahan's Heron formula, on the sides scaled by a
/// power of two when needed and scaled back: finite whenever the area is); NaN if invalid.
#[inline]
pub fn area(a: f64, b: f64, c: f64) -> f64 {
    let (a, b, c, k) = normalized(a, b, c);
    let [p, ea, eb, ec] = excesses(a, b, c);
    let area = 0.25 * (p * ea * eb * ec).sqrt();
    if k == 0 {
        area
    } else {
        area * pow2(k) * pow2(k)
    }
}

/// Position of corner 2 of a triangle laid out with corner 0 at the origin and corner 1 at
/// `(l01, 0)`, counter-clockwise (positive y). The angle at corner 0 is taken from its half-angle
/// tangent, so thin triangles keep their shape.
#[inline]
pub fn third_corner(l01: f64, l12: f64, l20: f64) -> [f64; 2] {
    let t2 = tan_half_sq(l12, l01, l20);
    let t = t2.sqrt();
    let d = 1.0 + t2;
    if t2.is_infinite() {
        return [-l20, 0.0];
    }
    [l20 * (1.0 - t2) / d, l20 * (2.0 * t) / d]
}

/// The five lengths around an edge, from the point of view of its half-edge `a -> b`:
/// triangle `(a, b, c)` on its left and `(b, a, d)` on its right.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quad {
    /// `|ab|`, the edge itself.
    pub ab: f64,
    /// `|bc|`.
    pub bc: f64,
    /// `|ca|`.
    pub ca: f64,
    /// `|ad|`.
    pub ad: f64,
    /// `|db|`.
    pub db: f64,
}

impl Quad {
    /// `tan²` of the half angle at c (opposite the edge in the left triangle).
    #[inline]
    pub fn tan_half_sq_c(&self) -> f64 {
        tan_half_sq(self.ab, self.bc, self.ca)
    }
    /// `tan²` of the half angle at d (opposite the edge in the right triangle).
    #[inline]
    pub fn tan_half_sq_d(&self) -> f64 {
        tan_half_sq(self.ab, self.ad, self.db)
    }

    /// The intrinsic Delaunay quantity `tan²(γ/2) · tan²(δ/2)` of the edge, γ and δ its two
    /// opposite angles: `γ + δ > π` iff `tan(γ/2) tan(δ/2) > 1` (since `γ/2 + δ/2 > π/2`).
    /// So the edge is locally Delaunay iff this is `<= 1`, and its two triangles are co-circular iff
    /// it is exactly 1. A product of two accurately computed numbers: relative error a few ulps,
    /// with no cancellation, for needle-like triangles too.
    #[inline]
    pub fn delaunay_product(&self) -> f64 {
        self.tan_half_sq_c() * self.tan_half_sq_d()
    }

    /// Half-angle tangents squared of the two angles at a (in the left and right triangles).
    #[inline]
    pub fn tan_half_sq_at_a(&self) -> [f64; 2] {
        [
            tan_half_sq(self.bc, self.ab, self.ca),
            tan_half_sq(self.db, self.ab, self.ad),
        ]
    }
    /// Half-angle tangents squared of the two angles at b (in the left and right triangles).
    #[inline]
    pub fn tan_half_sq_at_b(&self) -> [f64; 2] {
        [
            tan_half_sq(self.ca, self.ab, self.bc),
            tan_half_sq(self.ad, self.ab, self.db),
        ]
    }

    /// `tan(α₁/2) · tan(α₂/2)` squared at a: the quad's angle `α₁ + α₂` at a is below π iff this is
    /// below 1.
    #[inline]
    pub fn convexity_at_a(&self) -> f64 {
        let [t1, t2] = self.tan_half_sq_at_a();
        t1 * t2
    }
    /// As [`Self::convexity_at_a`], at b.
    #[inline]
    pub fn convexity_at_b(&self) -> f64 {
        let [t1, t2] = self.tan_half_sq_at_b();
        t1 * t2
    }

    /// Length of the other diagonal `cd` of the quad (the edge after a flip).
    ///
    /// With θ the quad's angle at a (`θ/2 = atan t₁ + atan t₂`, t the half-angle tangents of the
    /// two triangles' angles at a), `|cd|² = (|ac| - |ad|)² + 4|ac||ad| sin²(θ/2)` and
    /// `sin²(θ/2) = (t₁ + t₂)² / ((1 + t₁²)(1 + t₂²))`: a sum of non-negative terms, so the new
    /// length has a relative error of a few ulps whatever the shape (unlike the law of cosines,
    /// which cancels catastrophically for thin quads). Valid for any θ in `[0, 2π)`; the flip is
    /// geometrically meaningful only if the quad is convex (see [`Self::convexity_at_a`]).
    #[inline]
    pub fn flipped_length(&self) -> f64 {
        let [s1, s2] = self.tan_half_sq_at_a();
        chord(s1, s2, self.ca, self.ad)
    }
}

/// The distance between the ends of two segments of lengths `r1`, `r2` leaving a common point
/// with angle `θ = θ₁ + θ₂` between them, given `s_k = tan²(θ_k/2)`:
/// `sqrt((r1 - r2)² + 4 r1 r2 sin²(θ/2))`, `sin²(θ/2) = (t₁ + t₂)² / ((1 + t₁²)(1 + t₂²))`
/// (see [`Quad::flipped_length`]).
#[inline]
pub fn chord(s1: f64, s2: f64, r1: f64, r2: f64) -> f64 {
    let (r1, r2, _, k) = normalized(r1, r2, 0.0);
    let (t1, t2) = (s1.sqrt(), s2.sqrt());
    let sin2 = (t1 + t2) * (t1 + t2) / ((1.0 + s1) * (1.0 + s2));
    let diff = r1 - r2;
    let length = (diff * diff + 4.0 * r1 * r2 * sin2).sqrt();
    if k == 0 { length } else { length * pow2(k) }
}

/// `tan²` of the half angles of a triangle with sides `[l0, l1, l2]`: entry `i` is for the angle
/// opposite side `i`; and the smallest of Kahan's four factors (positive iff the triangle
/// inequality holds strictly). One sort for the three angles.
#[inline]
pub fn tan_half_sq_all(l: [f64; 3]) -> ([f64; 3], f64) {
    let (l0, l1, l2, _) = normalized(l[0], l[1], l[2]);
    let [p, e0, e1, e2] = excesses(l0, l1, l2);
    let smallest = p.min(e0).min(e1).min(e2);
    (
        [e1 * e2 / (p * e0), e0 * e2 / (p * e1), e0 * e1 / (p * e2)],
        smallest,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_3, PI};

    #[test]
    fn excesses_are_permutation_consistent() {
        let (o, x, y) = (3.0, 4.0, 5.0);
        let s = (o + x + y) / 2.0;
        let want = [2.0 * s, 2.0 * (s - o), 2.0 * (s - x), 2.0 * (s - y)];
        for (o, x, y, perm) in [
            (o, x, y, [0, 1, 2, 3]),
            (o, y, x, [0, 1, 3, 2]),
            (x, o, y, [0, 2, 1, 3]),
            (x, y, o, [0, 2, 3, 1]),
            (y, o, x, [0, 3, 1, 2]),
            (y, x, o, [0, 3, 2, 1]),
        ] {
            let got = excesses(o, x, y);
            for k in 0..4 {
                assert_eq!(got[k], want[perm[k]], "{o} {x} {y}");
            }
        }
    }

    #[test]
    fn angles_of_known_triangles() {
        assert!((angle(5.0, 3.0, 4.0) - FRAC_PI_2).abs() < 1e-15);
        assert!((angle(1.0, 1.0, 1.0) - FRAC_PI_3).abs() < 1e-15);
        assert!((cot(5.0, 3.0, 4.0)).abs() < 1e-15);
        assert!((cot(3.0, 4.0, 5.0) - 4.0 / 3.0).abs() < 1e-15);
        assert!((area(3.0, 4.0, 5.0) - 6.0).abs() < 1e-15);
        let sum = angle(3.0, 4.0, 5.0) + angle(4.0, 5.0, 3.0) + angle(5.0, 3.0, 4.0);
        assert!((sum - PI).abs() < 1e-15);
    }

    #[test]
    fn needle_triangles_keep_relative_accuracy() {
        // Exactly representable sides, so every error comes from the formulas.
        for l in [10.0f64, 1e4, 1e8] {
            // Isosceles (1, l, l): the apex angle is 2 asin(1 / 2l).
            let apex = 2.0 * (0.5 / l).asin();
            assert!((angle(1.0, l, l) - apex).abs() <= 1e-14 * apex, "l = {l}");
            let base = (std::f64::consts::PI - apex) / 2.0;
            assert!((angle(l, 1.0, l) - base).abs() <= 1e-15 * base, "l = {l}");
            let want = 0.5 * (l * l - 0.25).sqrt();
            assert!((area(1.0, l, l) - want).abs() <= 1e-14 * want, "l = {l}");
        }
        // (1, 1, 2 - d): the angle opposite the long side is π minus 2 asin(sqrt(2δ - δ²)),
        // δ = d / 2, an angle near π.
        for k in [10, 20, 40] {
            let d = 2f64.powi(-k);
            let delta = d / 2.0;
            let gap = 2.0 * (2.0 * delta - delta * delta).sqrt().asin();
            let got = std::f64::consts::PI - angle(2.0 - d, 1.0, 1.0);
            assert!(
                (got - gap).abs() <= 1e-15 + 1e-12 * gap,
                "k = {k}: {got} vs {gap}"
            );
            // tan²(θ/2) of that angle is huge but finite and accurate: 1 / tan²(gap/2).
            let t2 = tan_half_sq(2.0 - d, 1.0, 1.0);
            let want = 1.0 / (gap / 2.0).tan().powi(2);
            assert!((t2 - want).abs() <= 1e-10 * want, "k = {k}");
        }
    }

    #[test]
    fn validity() {
        assert!(is_triangle(3.0, 4.0, 5.0));
        assert!(!is_triangle(1.0, 2.0, 3.0));
        assert!(!is_triangle(1.0, 2.0, 3.5));
        assert!(!is_triangle(0.0, 1.0, 1.0));
        assert!(!is_triangle(f64::NAN, 1.0, 1.0));
        assert!(!is_triangle(f64::INFINITY, 1.0, 1.0));
    }

    #[test]
    fn flip_of_unit_square_diagonal() {
        // Square a=(0,0), b=(1,1) diagonal, c=(0,1) on the left of a->b, d=(1,0) on the right.
        let q = Quad {
            ab: 2f64.sqrt(),
            bc: 1.0,
            ca: 1.0,
            ad: 1.0,
            db: 1.0,
        };
        assert!((q.delaunay_product() - 1.0).abs() < 1e-15);
        assert!((q.flipped_length() - 2f64.sqrt()).abs() < 1e-15);
        assert!(q.convexity_at_a() < 1.0 && q.convexity_at_b() < 1.0);
        // A thin rhombus: the long diagonal is not Delaunay, the short one is.
        let h = 0.01f64;
        let side = (1.0 + h * h).sqrt();
        let q = Quad {
            ab: 2.0,
            bc: side,
            ca: side,
            ad: side,
            db: side,
        };
        assert!(q.delaunay_product() > 1.0);
        assert!((q.flipped_length() - 2.0 * h).abs() < 1e-10 * h);
        let short = Quad { ab: 2.0 * h, ..q };
        assert!(short.delaunay_product() < 1.0);
        assert!((short.flipped_length() - 2.0).abs() < 1e-14);
    }

    #[test]
    fn third_corner_matches_coordinates() {
        let [x, y] = third_corner(1.0, (16.0f64 + 4.0).sqrt(), (25.0f64 + 4.0).sqrt());
        assert!((x - 5.0).abs() < 1e-14 && (y - 2.0).abs() < 1e-14);
    }

    #[test]
    fn the_comparisons_bound_the_unscaled_range() {
        assert_eq!(SAFE_LOW, 2f64.powi(-SAFE_EXPONENT));
        assert_eq!(SAFE_HIGH, 2f64.powi(SAFE_EXPONENT + 1));
        // Either side of each bound, scaled or not, the formulas give the bits of the same
        // triangle scaled exactly into [1, 2).
        for bound in [SAFE_LOW, SAFE_HIGH] {
            for m in [bound.next_down(), bound, bound.next_up()] {
                let sides = [m, 0.75 * m, 0.6 * m];
                let s = pow2(1023 - (m.to_bits() >> 52) as i32);
                let unit = sides.map(|l| l * s);
                assert!((1.0..2.0).contains(&unit[0]));
                assert_eq!(tan_half_sq_all(sides).0, tan_half_sq_all(unit).0, "{m:e}");
                let [a, b, c] = sides;
                assert_eq!(area(a, b, c), area(unit[0], unit[1], unit[2]) / (s * s));
            }
        }
    }

    #[test]
    fn formulas_are_scale_free() {
        let (a, b, c) = (3.0, 4.0, 5.0);
        for k in [-1000i32, -600, -251, 251, 600, 1000] {
            let s = pow2(k);
            let (x, y, z) = (a * s, b * s, c * s);
            assert_eq!(tan_half_sq(x, y, z), tan_half_sq(a, b, c), "2^{k}");
            assert_eq!(tan_half_sq_all([x, y, z]).0, tan_half_sq_all([a, b, c]).0);
            assert!(is_triangle(x, y, z));
            let want = 6.0 * s * s;
            let got = area(x, y, z);
            if want.is_finite() && want > f64::MIN_POSITIVE {
                assert!((got - want).abs() <= 1e-15 * want, "2^{k}: {got} vs {want}");
            }
            let square = Quad {
                ab: 2f64.sqrt() * s,
                bc: s,
                ca: s,
                ad: s,
                db: s,
            };
            let flipped = square.flipped_length();
            assert!(
                (flipped - 2f64.sqrt() * s).abs() <= 1e-15 * flipped,
                "2^{k}"
            );
        }
        // Coordinates scaled by 1e150: areas near 1e300 are finite.
        assert!(area(3e150, 4e150, 5e150).is_finite());
        assert!(area(3e-100, 4e-100, 5e-100) > 0.0);
    }
}
