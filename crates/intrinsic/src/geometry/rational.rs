//! [`Rational`]: exact rational numbers for the exact arithmetic mode.

use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};
use std::str::FromStr;

use dashu_int::ops::{BitTest, UnsignedAbs};
use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;

use super::{Point, Scalar};

/// An exact rational number (arbitrary-precision numerator and denominator, always reduced).
///
/// Backed by `dashu`'s `RBig` (ARCHITECTURE.md gives the measurement behind the choice); the
/// newtype keeps the backend replaceable. Parsed from an integer (`"-7"`), a decimal with an
/// optional exponent (`"1000000000.333"`, `"2.5e-3"`) or a fraction (`"3000000001/3"`); written
/// as `"p/q"` or `"p"` ([`fmt::Display`]).
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Debug)]
pub struct Rational(RBig);

/// Why a string is not a rational number.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("not an exact number (an integer, a decimal or a fraction p/q with q > 0): {0:?}")]
pub struct ParseRationalError(pub String);

impl Rational {
    /// `numerator / denominator`; `None` when the denominator is zero.
    pub fn new(numerator: i64, denominator: i64) -> Option<Self> {
        (denominator != 0).then(|| {
            Rational(RBig::from_parts_signed(
                IBig::from(numerator),
                IBig::from(denominator),
            ))
        })
    }

    /// Whether the value is an integer.
    pub fn is_integer(&self) -> bool {
        self.0.is_int()
    }

    /// The exact value as a double when it is one (`Some(x)` with `Rational::from_f64(x) == self`).
    pub fn as_exact_f64(&self) -> Option<f64> {
        let x = self.0.to_f64().value();
        (x.is_finite() && RBig::try_from(x).ok().as_ref() == Some(&self.0)).then_some(x)
    }

    /// The number of bits of the numerator plus those of the denominator (a measure of size).
    pub fn bits(&self) -> u64 {
        (self.0.numerator().unsigned_abs().bit_len() + self.0.denominator().bit_len()) as u64
    }
}

impl fmt::Display for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.0.is_int() {
            write!(f, "{}", self.0.numerator())
        } else {
            write!(f, "{}/{}", self.0.numerator(), self.0.denominator())
        }
    }
}

fn parse_integer(s: &str) -> Option<IBig> {
    let digits = s.strip_prefix(['+', '-']).unwrap_or(s);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    IBig::from_str_radix(s, 10).ok()
}

/// Parses `[sign]digits[.digits][(e|E)[sign]digits]` exactly.
fn parse_decimal(s: &str) -> Option<RBig> {
    let (mantissa, exponent) = match s.find(['e', 'E']) {
        Some(i) => (&s[..i], s[i + 1..].parse::<i32>().ok()?),
        None => (s, 0),
    };
    let (negative, unsigned) = match mantissa.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, mantissa.strip_prefix('+').unwrap_or(mantissa)),
    };
    let (int_part, frac_part) = unsigned.split_once('.').unwrap_or((unsigned, ""));
    if int_part.is_empty() && frac_part.is_empty() {
        return None;
    }
    let all_digits = |t: &str| t.bytes().all(|b| b.is_ascii_digit());
    if !all_digits(int_part) || !all_digits(frac_part) {
        return None;
    }
    // Exponents beyond this would build numbers of more than ~33,000 digits: refuse them.
    if exponent.unsigned_abs() > 100_000 {
        return None;
    }
    let digits = IBig::from_str_radix(&format!("0{int_part}{frac_part}"), 10).ok()?;
    let shift = i64::from(exponent) - frac_part.len() as i64;
    let power = UBig::from(10u32).pow(shift.unsigned_abs() as usize);
    let value = if shift >= 0 {
        RBig::from(digits * IBig::from(power))
    } else {
        RBig::from_parts(digits, power)
    };
    Some(if negative { -value } else { value })
}

impl FromStr for Rational {
    type Err = ParseRationalError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let err = || ParseRationalError(s.to_string());
        let t = s.trim();
        if let Some((p, q)) = t.split_once('/') {
            let (p, q) = (
                parse_integer(p.trim()).ok_or_else(err)?,
                parse_integer(q.trim()).ok_or_else(err)?,
            );
            if q <= IBig::ZERO {
                return Err(err());
            }
            return Ok(Rational(RBig::from_parts_signed(p, q)));
        }
        parse_decimal(t).map(Rational).ok_or_else(err)
    }
}

macro_rules! binary_op {
    ($trait:ident, $method:ident) => {
        impl $trait for Rational {
            type Output = Rational;
            #[inline]
            fn $method(self, rhs: Rational) -> Rational {
                Rational(self.0.$method(rhs.0))
            }
        }
    };
}
binary_op!(Add, add);
binary_op!(Sub, sub);
binary_op!(Mul, mul);
binary_op!(Div, div);

impl Neg for Rational {
    type Output = Rational;
    #[inline]
    fn neg(self) -> Rational {
        Rational(-self.0)
    }
}

impl Scalar for Rational {
    const EXACT: bool = true;
    const ARITHMETIC: &'static str = "exact";

    fn zero() -> Self {
        Rational(RBig::ZERO)
    }
    fn one() -> Self {
        Rational(RBig::ONE)
    }
    fn from_i64(v: i64) -> Self {
        Rational(RBig::from(v))
    }
    fn from_f64(v: f64) -> Option<Self> {
        RBig::try_from(v).ok().map(Rational)
    }
    fn to_f64(&self) -> f64 {
        self.0.to_f64().value()
    }
    fn from_rational(v: &Rational) -> Self {
        v.clone()
    }
    fn to_rational(&self) -> Option<Rational> {
        Some(self.clone())
    }
    fn is_zero(&self) -> bool {
        self.0.is_zero()
    }
    fn half(&self) -> Self {
        Rational(&self.0 / RBig::from(2u8))
    }
    fn floor(&self) -> Self {
        Rational(RBig::from(self.0.floor()))
    }
    fn sign(&self) -> Ordering {
        self.0.cmp(&RBig::ZERO)
    }
    fn lengths_match(a: &Self, b: &Self, _tolerance: f64) -> bool {
        a == b
    }

    /// The sign of `(b − a) × (c − a)` on unreduced fractions: the four differences and the two
    /// products are formed on numerators and denominators without the gcd normalisation of
    /// [`RBig`] arithmetic, and compared by cross-multiplication (denominators are positive).
    /// Equal denominators (dyadic charts share them often) skip their products.
    fn orient2d(a: &Point<Self>, b: &Point<Self>, c: &Point<Self>) -> Ordering {
        let (ux, uxd) = unreduced_difference(&b[0], &a[0]);
        let (uy, uyd) = unreduced_difference(&b[1], &a[1]);
        let (vx, vxd) = unreduced_difference(&c[0], &a[0]);
        let (vy, vyd) = unreduced_difference(&c[1], &a[1]);
        // (ux/uxd)(vy/vyd) − (uy/uyd)(vx/vxd): compare ux·vy·uyd·vxd with uy·vx·uxd·vyd.
        let (left_sign, right_sign) = (ux.signum() * vy.signum(), uy.signum() * vx.signum());
        if left_sign != right_sign {
            return left_sign.cmp(&right_sign);
        }
        if left_sign == IBig::ZERO {
            return Ordering::Equal;
        }
        let (left_den, right_den) = (uxd * vyd, uyd * vxd);
        let (left, right) = if left_den == right_den {
            (ux * vy, uy * vx)
        } else {
            (
                ux * vy * IBig::from(right_den),
                uy * vx * IBig::from(left_den),
            )
        };
        left.cmp(&right)
    }
}

/// `p − q` as an unreduced fraction (numerator, positive denominator).
fn unreduced_difference(p: &Rational, q: &Rational) -> (IBig, UBig) {
    let (pn, pd) = (p.0.numerator(), p.0.denominator());
    let (qn, qd) = (q.0.numerator(), q.0.denominator());
    if pd == qd {
        (pn - qn, pd.clone())
    } else {
        (
            pn * IBig::from(qd.clone()) - qn * IBig::from(pd.clone()),
            pd * qd,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orientation_on_unreduced_fractions_agrees_with_the_determinant() {
        let r = |s: &str| s.parse::<Rational>().unwrap();
        let values = [
            "0",
            "1",
            "-3/4",
            "7/6",
            "1000000000000000001/2",
            "5/12",
            "-2",
            "1/3",
        ];
        let mut checked = 0;
        for (i, a) in values.iter().enumerate() {
            for (j, b) in values.iter().enumerate() {
                for (k, c) in values.iter().enumerate() {
                    let p = [r(a), r(b)];
                    let q = [r(b), r(c)];
                    let s = [r(c), r(values[(i + j + k) % values.len()])];
                    let by_determinant =
                        super::super::cross(&super::super::sub(&q, &p), &super::super::sub(&s, &p))
                            .sign();
                    assert_eq!(
                        Rational::orient2d(&p, &q, &s),
                        by_determinant,
                        "{p:?} {q:?} {s:?}"
                    );
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, 512);
        // Collinear points with different denominators.
        let (p, q, s) = (
            [r("1/3"), r("2/3")],
            [r("1/2"), r("1")],
            [r("5/6"), r("5/3")],
        );
        assert_eq!(Rational::orient2d(&p, &q, &s), Ordering::Equal);
    }

    #[test]
    fn parses_integers_decimals_and_fractions() {
        let r = |s: &str| s.parse::<Rational>().unwrap();
        assert_eq!(r("3000000001/3").to_string(), "3000000001/3");
        assert_eq!(r("6/4").to_string(), "3/2");
        assert_eq!(r("1000000000.333"), r("1000000000333/1000"));
        assert_eq!(r("-2.5e-3"), r("-1/400"));
        assert_eq!(r("1e18"), r("1000000000000000000"));
        assert_eq!(r(".5"), r("1/2"));
        for bad in [
            "",
            "1/0",
            "1/-2",
            "abc",
            "1.2.3",
            "1e",
            "--1",
            "0x10",
            "1e999999999",
            "nan",
        ] {
            assert!(bad.parse::<Rational>().is_err(), "{bad:?}");
        }
    }

    #[test]
    fn doubles_convert_exactly() {
        let x = Rational::from_f64(0.1).unwrap();
        assert_ne!(x, Rational::new(1, 10).unwrap());
        assert_eq!(x.as_exact_f64(), Some(0.1));
        assert_eq!(Rational::new(1, 3).unwrap().as_exact_f64(), None);
        assert_eq!(Rational::from_f64(f64::NAN), None);
        assert_eq!(
            Rational::new(-7, 2).unwrap().floor(),
            Rational::from_i64(-4)
        );
    }
}
