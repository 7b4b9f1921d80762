//! The [`Scalar`] trait: what the plane geometry needs of a number type.

use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

use super::Point;

/// An ordered field for plane geometry: `f64` (rounded constructions, exact-sign predicates),
/// [`super::DoubleDouble`] (about 106 bits) or [`super::Rational`] (exact). Operators take
/// values; clone where a value is reused.
pub trait Scalar:
    Clone
    + fmt::Debug
    + fmt::Display
    + PartialEq
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + Send
    + Sync
    + 'static
{
    /// Whether arithmetic is exact (`false` for `f64`). Algorithms ask the decision methods
    /// below (`same_value`, `same_point`, `tie`, ...) rather than this constant.
    const EXACT: bool;
    /// Whether Dubois' reduction (Proposition 2) on input of this type runs in
    /// [`super::DoubleDouble`] and rounds its result back: `true` for `f64` only
    /// (`docs/dubois.md` §4); exact types need no more precision, and `DoubleDouble` is that
    /// precision.
    const REDUCES_IN_DOUBLE_DOUBLE: bool = false;
    /// `"f64"` or `"exact"`, as reports and the CLI's `--json` name the arithmetic.
    const ARITHMETIC: &'static str;

    /// 0.
    fn zero() -> Self;
    /// 1.
    fn one() -> Self;
    /// The integer `v` (exact for rationals; rounded beyond 2⁵³ for `f64`).
    fn from_i64(v: i64) -> Self;
    /// The exact value of a finite double; `None` for NaN and infinities.
    fn from_f64(v: f64) -> Option<Self>;
    /// The nearest double.
    fn to_f64(&self) -> f64;
    /// The value of an exact rational (exact for rationals; the nearest double for `f64`).
    fn from_rational(v: &super::Rational) -> Self;
    /// The exact value as a rational; `None` for a non-finite double.
    fn to_rational(&self) -> Option<super::Rational>;
    /// Whether the value is finite (always for exact types; not NaN or infinite for `f64`).
    fn is_finite(&self) -> bool {
        true
    }
    /// Whether the value is exactly zero.
    fn is_zero(&self) -> bool;
    /// The value halved (exact in both modes, barring `f64` underflow).
    fn half(&self) -> Self;
    /// The largest integer not above the value.
    fn floor(&self) -> Self;

    /// The size of an exact value in bits: those of its numerator and denominator together
    /// (0 for rounded types, whose size is fixed).
    fn bits(&self) -> u64 {
        0
    }

    /// The square root to the type's precision, for rounded types (`None` for exact ones).
    fn approximate_sqrt(&self) -> Option<Self> {
        None
    }

    /// The sign of the value, compared with zero.
    fn sign(&self) -> Ordering {
        self.partial_cmp(&Self::zero()).unwrap_or(Ordering::Equal)
    }

    /// The absolute value.
    fn abs(&self) -> Self {
        if self.sign() == Ordering::Less {
            -self.clone()
        } else {
            self.clone()
        }
    }

    /// Whether two (squared) lengths are equal: exactly in exact mode; in `f64` up to the
    /// relative tolerance `|a − b| ≤ tolerance · max(|a|, |b|)`.
    fn lengths_match(a: &Self, b: &Self, tolerance: f64) -> bool;

    // The exact/rounded decisions: exact arithmetic decides exactly and never evaluates the
    // tolerance (a closure, often a computation); rounded arithmetic decides on doubles within
    // it. Tolerances come from [`super::Tolerances`].

    /// Whether `a` and `b` are one value: `a == b` exactly; rounded, `|a − b| ≤ tolerance`.
    fn same_value(a: &Self, b: &Self, tolerance: impl FnOnce() -> f64) -> bool {
        if Self::EXACT {
            a == b
        } else {
            (a.to_f64() - b.to_f64()).abs() <= tolerance()
        }
    }

    /// Whether `a ≤ b`: exactly; rounded, `a ≤ b + tolerance`.
    fn at_most(a: &Self, b: &Self, tolerance: impl FnOnce() -> f64) -> bool {
        if Self::EXACT {
            a <= b
        } else {
            a.to_f64() <= b.to_f64() + tolerance()
        }
    }

    /// Whether `x ≤ 0`: exactly; rounded, `x ≤ tolerance`.
    fn at_most_zero(x: &Self, tolerance: impl FnOnce() -> f64) -> bool {
        if Self::EXACT {
            x.sign() != Ordering::Greater
        } else {
            x.to_f64() <= tolerance()
        }
    }

    /// Whether `x` is zero: exactly; rounded, `|x| ≤ tolerance`.
    fn negligible(x: &Self, tolerance: impl FnOnce() -> f64) -> bool {
        if Self::EXACT {
            x.is_zero()
        } else {
            x.to_f64().abs() <= tolerance()
        }
    }

    /// Whether `a` and `b` are one point: exactly; rounded, when their squared distance is at
    /// most `tolerance2` (a squared distance).
    fn same_point(a: &Point<Self>, b: &Point<Self>, tolerance2: impl FnOnce() -> f64) -> bool {
        if Self::EXACT {
            a == b
        } else {
            super::dist2(a, b).to_f64() <= tolerance2()
        }
    }

    /// The margin within which a difference is a tie: zero exactly; rounded, `tolerance` (zero
    /// when not finite).
    fn tie(tolerance: impl FnOnce() -> f64) -> Self {
        if Self::EXACT {
            Self::zero()
        } else {
            Self::from_f64(tolerance()).unwrap_or_else(Self::zero)
        }
    }

    /// A tolerance that only rounded arithmetic uses: 0 exactly; rounded, `tolerance`.
    fn slack(tolerance: impl FnOnce() -> f64) -> f64 {
        if Self::EXACT { 0.0 } else { tolerance() }
    }

    /// The factor that keeps a computed upper bound a bound: 1 exactly; rounded, `1 + relative`.
    fn upward_margin(relative: f64) -> Self {
        if Self::EXACT {
            Self::one()
        } else {
            Self::one() + Self::from_f64(relative).expect("a finite margin")
        }
    }

    /// `|a − b|²` (see [`super::dist2`]). The default forms the differences, squares and sum in
    /// the type's arithmetic.
    fn squared_distance(a: &Point<Self>, b: &Point<Self>) -> Self {
        super::norm2(&super::sub(a, b))
    }

    /// The sign of the orientation determinant of `a, b, c` (see [`super::orient`]). The default
    /// evaluates the determinant, which is exact for exact types.
    fn orient2d(a: &Point<Self>, b: &Point<Self>, c: &Point<Self>) -> Ordering {
        let ab = super::sub(b, a);
        let ac = super::sub(c, a);
        super::cross(&ab, &ac).sign()
    }

    /// The sign of the in-circle determinant (see [`super::incircle`]). The default evaluates the
    /// lifted 3×3 determinant, which is exact for exact types.
    fn incircle(a: &Point<Self>, b: &Point<Self>, c: &Point<Self>, d: &Point<Self>) -> Ordering {
        let [ad, bd, cd] = [super::sub(a, d), super::sub(b, d), super::sub(c, d)];
        let [la, lb, lc] = [super::norm2(&ad), super::norm2(&bd), super::norm2(&cd)];
        let det =
            la * super::cross(&bd, &cd) + lb * super::cross(&cd, &ad) + lc * super::cross(&ad, &bd);
        det.sign()
    }
}

impl Scalar for f64 {
    const EXACT: bool = false;
    const REDUCES_IN_DOUBLE_DOUBLE: bool = true;
    const ARITHMETIC: &'static str = "f64";

    fn zero() -> Self {
        0.0
    }
    fn one() -> Self {
        1.0
    }
    fn from_i64(v: i64) -> Self {
        v as f64
    }
    fn from_f64(v: f64) -> Option<Self> {
        v.is_finite().then_some(v)
    }
    fn to_f64(&self) -> f64 {
        *self
    }
    fn from_rational(v: &super::Rational) -> Self {
        v.to_f64()
    }
    fn to_rational(&self) -> Option<super::Rational> {
        super::Rational::from_f64(*self)
    }
    fn is_finite(&self) -> bool {
        f64::is_finite(*self)
    }
    fn is_zero(&self) -> bool {
        *self == 0.0
    }
    fn half(&self) -> Self {
        self * 0.5
    }
    fn floor(&self) -> Self {
        f64::floor(*self)
    }
    fn lengths_match(a: &Self, b: &Self, tolerance: f64) -> bool {
        (a - b).abs() <= tolerance * a.abs().max(b.abs())
    }
    fn approximate_sqrt(&self) -> Option<Self> {
        Some(self.sqrt())
    }

    /// Shewchuk's adaptive orientation predicate: the exact sign for the given doubles.
    fn orient2d(a: &Point<f64>, b: &Point<f64>, c: &Point<f64>) -> Ordering {
        let det = robust::orient2d(coord(a), coord(b), coord(c));
        det.partial_cmp(&0.0).unwrap_or(Ordering::Equal)
    }

    /// Shewchuk's adaptive in-circle predicate: the exact sign for the given doubles.
    fn incircle(a: &Point<f64>, b: &Point<f64>, c: &Point<f64>, d: &Point<f64>) -> Ordering {
        let det = robust::incircle(coord(a), coord(b), coord(c), coord(d));
        det.partial_cmp(&0.0).unwrap_or(Ordering::Equal)
    }
}

#[inline]
fn coord(p: &Point<f64>) -> robust::Coord<f64> {
    robust::Coord { x: p[0], y: p[1] }
}
