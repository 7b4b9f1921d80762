//! [`DoubleDouble`]: an unevaluated sum of two doubles (about 106 bits of significand), the
//! working precision of Dubois' reduction in `f64` mode ([`crate::dubois::caps`]).
//!
//! The algorithms are the classical error-free transformations: Knuth's two-sum, Dekker's
//! splitting product (no fused multiply-add, which is a slow library call on targets without
//! it), and the accurate addition of Hida, Li and Bailey's QD library ("Library for
//! double-double and quad-double arithmetic", 2007); division by two Newton-style corrections.
//! The invariant is `|lo| ≤ ulp(hi) / 2` (normalised), so comparisons look at `hi` first.

use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

use super::{Point, Rational, Scalar};

/// `hi + lo`, normalised: `hi` is the double nearest to the sum.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DoubleDouble {
    hi: f64,
    lo: f64,
}

/// `a + b = s + e` exactly (Knuth).
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a + b = s + e` exactly, for `|a| ≥ |b|` (Dekker).
#[inline]
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// Veltkamp's split of `a` into two halves of 26 bits.
#[inline]
fn split(a: f64) -> (f64, f64) {
    const SPLITTER: f64 = 134_217_729.0; // 2^27 + 1
    let t = SPLITTER * a;
    let hi = t - (t - a);
    (hi, a - hi)
}

/// `a · b = p + e` exactly (Dekker), barring overflow.
#[inline]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

impl DoubleDouble {
    /// The exact value of a double.
    pub const fn from_f64_exact(x: f64) -> Self {
        DoubleDouble { hi: x, lo: 0.0 }
    }

    /// The leading double (the nearest double to the value).
    pub fn hi(&self) -> f64 {
        self.hi
    }

    /// The trailing double.
    pub fn lo(&self) -> f64 {
        self.lo
    }

    /// The square root, to about 106 bits (one Newton step from the double square root); 0 for
    /// values not above 0.
    pub fn sqrt(&self) -> Self {
        if self.hi <= 0.0 {
            return Self::default();
        }
        let x = DoubleDouble::from_f64_exact(self.hi.sqrt());
        // x + (a − x²) / (2x)
        let residual = *self - x * x;
        x + DoubleDouble::from_f64_exact(residual.hi / (2.0 * x.hi))
    }

    fn from_sum(s: f64, e: f64) -> Self {
        let (hi, lo) = quick_two_sum(s, e);
        DoubleDouble { hi, lo }
    }

    fn mul_f64(self, b: f64) -> Self {
        let (p, e) = two_prod(self.hi, b);
        Self::from_sum(p, e + self.lo * b)
    }
}

impl Add for DoubleDouble {
    type Output = Self;
    #[inline]
    fn add(self, b: Self) -> Self {
        let (s, e) = two_sum(self.hi, b.hi);
        let (t, f) = two_sum(self.lo, b.lo);
        let (s, e) = quick_two_sum(s, e + t);
        Self::from_sum(s, e + f)
    }
}

impl Neg for DoubleDouble {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        DoubleDouble {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl Sub for DoubleDouble {
    type Output = Self;
    #[inline]
    fn sub(self, b: Self) -> Self {
        self + (-b)
    }
}

impl Mul for DoubleDouble {
    type Output = Self;
    #[inline]
    fn mul(self, b: Self) -> Self {
        let (p, e) = two_prod(self.hi, b.hi);
        Self::from_sum(p, e + (self.hi * b.lo + self.lo * b.hi))
    }
}

impl Div for DoubleDouble {
    type Output = Self;
    fn div(self, b: Self) -> Self {
        let q1 = self.hi / b.hi;
        let r = self - b.mul_f64(q1);
        let q2 = r.hi / b.hi;
        let r = r - b.mul_f64(q2);
        let q3 = r.hi / b.hi;
        let (q1, q2) = quick_two_sum(q1, q2);
        DoubleDouble { hi: q1, lo: q2 } + DoubleDouble::from_f64_exact(q3)
    }
}

impl PartialOrd for DoubleDouble {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        match self.hi.partial_cmp(&other.hi)? {
            Ordering::Equal => self.lo.partial_cmp(&other.lo),
            unequal => Some(unequal),
        }
    }
}

impl fmt::Display for DoubleDouble {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.hi + self.lo)
    }
}

impl Scalar for DoubleDouble {
    const EXACT: bool = false;
    /// The mode it serves: `f64` input, rounded arithmetic (reports name that mode).
    const ARITHMETIC: &'static str = "f64";

    fn zero() -> Self {
        Self::default()
    }
    fn one() -> Self {
        Self::from_f64_exact(1.0)
    }
    fn from_i64(v: i64) -> Self {
        let hi = v as f64;
        // What the rounding to a double lost: below 2^11 in size, exact (i128 holds 2^63).
        let lo = (i128::from(v) - hi as i128) as f64;
        Self::from_sum(hi, lo)
    }
    fn from_f64(v: f64) -> Option<Self> {
        v.is_finite().then(|| Self::from_f64_exact(v))
    }
    fn to_f64(&self) -> f64 {
        self.hi
    }
    fn from_rational(v: &Rational) -> Self {
        let hi = v.to_f64();
        let rest = v.clone() - Rational::from_f64(hi).unwrap_or_else(Rational::zero);
        Self::from_sum(hi, rest.to_f64())
    }
    fn to_rational(&self) -> Option<Rational> {
        Some(Rational::from_f64(self.hi)? + Rational::from_f64(self.lo)?)
    }
    fn is_finite(&self) -> bool {
        self.hi.is_finite() && self.lo.is_finite()
    }
    fn is_zero(&self) -> bool {
        self.hi == 0.0
    }
    fn half(&self) -> Self {
        DoubleDouble {
            hi: self.hi * 0.5,
            lo: self.lo * 0.5,
        }
    }
    fn floor(&self) -> Self {
        let hi = self.hi.floor();
        if hi != self.hi {
            return Self::from_f64_exact(hi);
        }
        Self::from_sum(hi, self.lo.floor())
    }
    fn lengths_match(a: &Self, b: &Self, tolerance: f64) -> bool {
        (*a - *b).hi.abs() <= tolerance * a.hi.abs().max(b.hi.abs())
    }
    fn approximate_sqrt(&self) -> Option<Self> {
        Some(self.sqrt())
    }

    /// The sign of the orientation determinant: from the leading doubles when it exceeds a
    /// bound on what the trailing parts and the rounding can change, else in double-double.
    fn orient2d(a: &Point<Self>, b: &Point<Self>, c: &Point<Self>) -> Ordering {
        const U: f64 = f64::EPSILON / 2.0;
        let (d1x, d1y) = (b[0].hi - a[0].hi, b[1].hi - a[1].hi);
        let (d2x, d2y) = (c[0].hi - a[0].hi, c[1].hi - a[1].hi);
        let (l, r) = (d1x * d2y, d1y * d2x);
        let det = l - r;
        let m = [a, b, c]
            .iter()
            .flat_map(|p| [p[0].hi.abs(), p[1].hi.abs()])
            .fold(0.0, f64::max);
        // Each difference is within `e` of the exact one (trailing parts ≤ U·|hi| each, and the
        // subtraction's rounding); the products and their difference round by 3U.
        let e = 4.0 * U * m;
        let bound = e * (d1x.abs() + d1y.abs() + d2x.abs() + d2y.abs())
            + 2.0 * e * e
            + 3.0 * U * (l.abs() + r.abs());
        if det.abs() > 2.0 * bound {
            return det.partial_cmp(&0.0).unwrap_or(Ordering::Equal);
        }
        let ab = super::sub(b, a);
        let ac = super::sub(c, a);
        super::cross(&ab, &ac).sign()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dd(x: &str) -> DoubleDouble {
        DoubleDouble::from_rational(&x.parse().unwrap())
    }

    fn error(x: DoubleDouble, exact: &Rational) -> f64 {
        (x.to_rational().unwrap() - exact.clone()).to_f64().abs() / exact.to_f64().abs()
    }

    #[test]
    fn arithmetic_keeps_about_106_bits() {
        let (a, b) = ("1/3", "-2718281828459045/1000000000000000");
        let (ra, rb): (Rational, Rational) = (a.parse().unwrap(), b.parse().unwrap());
        let (x, y) = (dd(a), dd(b));
        for (value, exact) in [
            (x + y, ra.clone() + rb.clone()),
            (x - y, ra.clone() - rb.clone()),
            (x * y, ra.clone() * rb.clone()),
            (x / y, ra.clone() / rb.clone()),
        ] {
            assert!(error(value, &exact) < 1e-30, "{value:?}");
        }
        // One third is not a double: its double-double is 2^-106-close, its double is not.
        assert!(error(x, &ra) < 1e-31);
        assert!(error(DoubleDouble::from_f64_exact(1.0 / 3.0), &ra) > 1e-17);
    }

    /// The filtered orientation agrees with the exact sign of the rational values, on triples
    /// close to collinear at every scale (the filter's bound decides most, the double-double
    /// determinant the rest).
    #[test]
    fn orientation_signs_are_those_of_the_exact_values() {
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for k in 0..20_000 {
            let scale = 10f64.powi(k % 9 - 4);
            let offset = 10f64.powi(k % 5);
            let d = DoubleDouble::from_f64_exact;
            // A point of the line y = x (shifted), with trailing parts of its own.
            let point = |t: f64, lo: [f64; 2]| {
                [
                    d(offset + t * scale) + d(lo[0] * 1e-17 * offset),
                    d(offset + t * scale) + d(lo[1] * 1e-17 * offset),
                ]
            };
            let p = point(next(), [next(), next()]);
            let q = point(next(), [next(), next()]);
            let mut c = point(next(), [next(), next()]);
            c[1] = c[1] + d(next() * 10f64.powi(-(k % 30)) * scale);
            let exact = |p: &Point<DoubleDouble>| (*p).map(|v| v.to_rational().unwrap());
            let expected = Rational::orient2d(&exact(&p), &exact(&q), &exact(&c));
            assert_eq!(
                DoubleDouble::orient2d(&p, &q, &c),
                expected,
                "{k}: {p:?} {q:?} {c:?}"
            );
        }
    }

    #[test]
    fn square_roots_and_orders() {
        let two = DoubleDouble::from_i64(2);
        let r = two.sqrt();
        let back = r * r - two;
        assert!(back.hi.abs() < 1e-30, "{back:?}");
        let tiny = DoubleDouble::from_sum(1.0, 1e-20);
        assert!(tiny > DoubleDouble::one());
        assert_eq!(tiny.sign(), Ordering::Greater);
        assert_eq!((-tiny).abs(), tiny);
        assert_eq!(
            DoubleDouble::from_i64(i64::MAX).to_rational(),
            Some(Rational::from_i64(i64::MAX))
        );
        assert_eq!(dd("7/2").floor(), DoubleDouble::from_i64(3));
        assert_eq!(dd("-7/2").floor(), DoubleDouble::from_i64(-4));
    }
}
