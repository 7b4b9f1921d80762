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
/// Two representations behind one canonical form: a value whose reduced numerator and
/// denominator both fit in an `i64` (numerator not `i64::MIN`) is stored inline and its
/// arithmetic runs on `i128` products and a binary gcd; any other value is `dashu`'s `RBig`
/// (ARCHITECTURE.md gives the measurements behind both). Every result is normalised to the
/// inline form when it fits, so equality and hashing compare representations. Parsed from an
/// integer (`"-7"`), a decimal with an optional exponent (`"1000000000.333"`, `"2.5e-3"`) or a
/// fraction (`"3000000001/3"`); written as `"p/q"` or `"p"` ([`fmt::Display`]).
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub struct Rational(Repr);

/// The two representations of [`Rational`]; `Small` whenever the value fits.
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
enum Repr {
    /// `num / den`, reduced, `den > 0`, `num ≠ i64::MIN`.
    Small { num: i64, den: i64 },
    /// Any value that does not fit `Small`.
    Big(RBig),
}

/// The most bits an exact number read from text may have: those of its numerator and
/// denominator together, as written (a fraction `p/q`: `p` and `q`; a decimal `d.ddde±k`: its
/// digits and the power of ten), about 1,233 decimal digits. Dubois' T_x at x = 10¹⁰⁰⁰ takes
/// 3,322; a longer number is refused before it is parsed, so that exact arithmetic never starts
/// on numbers whose products it could not hold.
pub const MAX_INPUT_BITS: u64 = 4096;

/// Why a string is not a rational number.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ParseRationalError {
    /// Not an integer, a decimal or a fraction.
    #[error("not an exact number (an integer, a decimal or a fraction p/q with q > 0): {0:?}")]
    Syntax(String),
    /// More bits than [`MAX_INPUT_BITS`].
    #[error(
        "an exact number of about {bits} bits ({start}...): exact numbers in input are limited to \
         {MAX_INPUT_BITS} bits (about 1,233 decimal digits) in numerator and denominator together"
    )]
    TooLarge {
        /// Its size in bits, as written (at least).
        bits: u64,
        /// Its first characters.
        start: String,
    },
}

/// log₂(10), rounded up in the third decimal: digit counts to bit counts.
const BITS_PER_DIGIT: f64 = 3.322;

/// Refuses `s` when `digits` decimal digits and a power of ten `10^power` would exceed
/// [`MAX_INPUT_BITS`] (counted before anything is parsed).
fn check_input_size(s: &str, digits: usize, power: u64) -> Result<(), ParseRationalError> {
    let bits = ((digits as f64 + power as f64) * BITS_PER_DIGIT) as u64;
    if bits > MAX_INPUT_BITS + 4 {
        return Err(ParseRationalError::TooLarge {
            bits,
            start: s.chars().take(20).collect(),
        });
    }
    Ok(())
}

/// A JSON number literal (`text`, JSON's syntax) against the double `nearest` it rounds to,
/// decided on its digits without big integers when it has at most 19 significant digits and a
/// small exponent: `Some(None)` when its value is `nearest` exactly, `Some(Some(r))` with its
/// value `r` otherwise; `None` when undecided here (then [`Rational`]'s parser decides).
pub(crate) fn small_literal(text: &str, nearest: f64) -> Option<Option<Rational>> {
    let negative = text.starts_with('-');
    let unsigned = text.strip_prefix('-').unwrap_or(text);
    let (mantissa, exponent) = match unsigned.find(['e', 'E']) {
        Some(i) => (&unsigned[..i], unsigned[i + 1..].parse::<i64>().ok()?),
        None => (unsigned, 0),
    };
    let (int_part, frac_part) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let mut m = 0u64;
    let mut significant = 0usize;
    for b in int_part.bytes().chain(frac_part.bytes()) {
        if m > 0 || b != b'0' {
            significant += 1;
            if significant > 19 || !b.is_ascii_digit() {
                return None;
            }
            m = 10 * m + u64::from(b - b'0');
        }
    }
    if m == 0 {
        return Some(None); // zero
    }
    let mut e10 = exponent.checked_sub(frac_part.len() as i64)?;
    while m.is_multiple_of(10) {
        m /= 10;
        e10 += 1;
    }
    let signed = |v: i64| if negative { -v } else { v };
    if e10 >= 0 {
        let value = u128::from(m).checked_mul(10u128.checked_pow(u32::try_from(e10).ok()?)?)?;
        // A correctly rounded double equals the value whenever the value is a double.
        if nearest.is_finite() && nearest.abs() < 2f64.powi(127) && nearest.abs() as u128 == value {
            return Some(None);
        }
        let value = i64::try_from(value).ok()?;
        return Some(Some(Rational::from_i64(signed(value))));
    }
    let k = u32::try_from(-e10).ok().filter(|&k| k <= 18)?;
    let q = m.is_multiple_of(5u64.pow(k)).then(|| m / 5u64.pow(k)); // value = q / 2^k when dyadic
    if q.is_some_and(|q| q >> q.trailing_zeros() < 1 << 53) {
        return Some(None);
    }
    // m / 10^k reduced: only the factors 2 and 5 of m can cancel.
    let twos = m.trailing_zeros().min(k);
    let (mut m, mut den) = (m >> twos, 10u64.pow(k) >> twos);
    let mut fives = 0;
    while fives < k && m.is_multiple_of(5) {
        (m, den, fives) = (m / 5, den / 5, fives + 1);
    }
    let (num, den) = (i64::try_from(m).ok()?, i64::try_from(den).ok()?);
    Some(Some(Rational(Repr::Small {
        num: signed(num),
        den,
    })))
}

/// The greatest common divisor; `gcd(0, b) = b`. A power of two shortcuts; operands that fit
/// 64 bits run the 64-bit loop.
fn gcd_u128(a: u128, b: u128) -> u128 {
    if a == 0 || b == 0 {
        return a | b;
    }
    if a.is_power_of_two() || b.is_power_of_two() {
        return 1 << (a | b).trailing_zeros();
    }
    match (u64::try_from(a), u64::try_from(b)) {
        (Ok(a), Ok(b)) => u128::from(binary_gcd_u64(a, b)),
        _ => binary_gcd_u128(a, b),
    }
}

/// Stein's binary gcd of two non-zero operands.
macro_rules! binary_gcd {
    ($name:ident, $t:ty) => {
        fn $name(mut a: $t, mut b: $t) -> $t {
            let shift = (a | b).trailing_zeros();
            a >>= a.trailing_zeros();
            loop {
                b >>= b.trailing_zeros();
                if a > b {
                    std::mem::swap(&mut a, &mut b);
                }
                b -= a;
                if b == 0 {
                    return a << shift;
                }
            }
        }
    };
}
binary_gcd!(binary_gcd_u64, u64);
binary_gcd!(binary_gcd_u128, u128);

impl Rational {
    /// `num / den` from a reduced or unreduced fraction with `den > 0`.
    fn from_i128(num: i128, den: i128) -> Self {
        debug_assert!(den > 0);
        let g = gcd_u128(num.unsigned_abs(), den as u128) as i128;
        if g > 1 {
            Self::from_reduced_i128(num / g, den / g)
        } else {
            Self::from_reduced_i128(num, den)
        }
    }

    /// `num / den` already reduced, `den > 0`.
    fn from_reduced_i128(num: i128, den: i128) -> Self {
        match (i64::try_from(num), i64::try_from(den)) {
            (Ok(num), Ok(den)) if num != i64::MIN => Rational(Repr::Small { num, den }),
            _ => Rational(Repr::Big(RBig::from_parts(
                IBig::from(num),
                UBig::from(den as u128),
            ))),
        }
    }

    /// The canonical form of an `RBig`: inline when it fits.
    fn from_rbig(r: RBig) -> Self {
        match (i64::try_from(r.numerator()), i64::try_from(r.denominator())) {
            (Ok(num), Ok(den)) if num != i64::MIN => Rational(Repr::Small { num, den }),
            _ => Rational(Repr::Big(r)),
        }
    }

    /// The value as an `RBig` (a copy).
    fn to_rbig(&self) -> RBig {
        match &self.0 {
            Repr::Small { num, den } => RBig::from_parts(IBig::from(*num), UBig::from(*den as u64)),
            Repr::Big(r) => r.clone(),
        }
    }

    /// The value as an `RBig`, moved out when it is one.
    fn into_rbig(self) -> RBig {
        match self.0 {
            Repr::Big(r) => r,
            small => Rational(small).to_rbig(),
        }
    }

    /// The numerator and the (positive) denominator, reduced.
    fn parts(&self) -> (IBig, UBig) {
        match &self.0 {
            Repr::Small { num, den } => (IBig::from(*num), UBig::from(*den as u64)),
            Repr::Big(r) => (r.numerator().clone(), r.denominator().clone()),
        }
    }

    /// `numerator / denominator`; `None` when the denominator is zero.
    pub fn new(numerator: i64, denominator: i64) -> Option<Self> {
        (denominator != 0).then(|| {
            let (num, den) = (i128::from(numerator), i128::from(denominator));
            if den < 0 {
                Self::from_i128(-num, -den)
            } else {
                Self::from_i128(num, den)
            }
        })
    }

    /// Whether the value is an integer.
    pub fn is_integer(&self) -> bool {
        match &self.0 {
            Repr::Small { den, .. } => *den == 1,
            Repr::Big(r) => r.is_int(),
        }
    }

    /// The exact value as a double when it is one (`Some(x)` with `Rational::from_f64(x) == self`).
    pub fn as_exact_f64(&self) -> Option<f64> {
        let r = self.to_rbig();
        let x = r.to_f64().value();
        (x.is_finite() && RBig::try_from(x).ok().as_ref() == Some(&r)).then_some(x)
    }

    /// The exact decimal text of the value (`-0.125`, `1000000000000000001`) when its
    /// denominator divides a power of ten; `None` otherwise.
    pub fn to_decimal(&self) -> Option<String> {
        let (num, den) = self.parts();
        let twos = den.trailing_zeros().unwrap_or(0);
        let mut rest = den >> twos;
        let five = UBig::from(5u8);
        let mut fives = 0usize;
        while rest > UBig::ONE {
            let (q, r) = (&rest / &five, &rest % &five);
            if r != UBig::ZERO {
                return None;
            }
            rest = q;
            fives += 1;
        }
        let places = twos.max(fives);
        let scale = (UBig::ONE << (places - twos)) * five.pow(places - fives);
        let sign = if num < IBig::ZERO { "-" } else { "" };
        let digits = (num.unsigned_abs() * scale).to_string();
        if places == 0 {
            return Some(format!("{sign}{digits}"));
        }
        let padded = format!("{digits:0>width$}", width = places + 1);
        let (int_part, frac_part) = padded.split_at(padded.len() - places);
        Some(format!("{sign}{int_part}.{frac_part}"))
    }

    /// The number of bits of the numerator plus those of the denominator (a measure of size).
    pub fn bits(&self) -> u64 {
        match &self.0 {
            Repr::Small { num, den } => {
                u64::from(64 - num.unsigned_abs().leading_zeros())
                    + u64::from(64 - den.leading_zeros())
            }
            Repr::Big(r) => {
                (r.numerator().unsigned_abs().bit_len() + r.denominator().bit_len()) as u64
            }
        }
    }
}

impl fmt::Display for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            Repr::Small { num, den: 1 } => write!(f, "{num}"),
            Repr::Small { num, den } => write!(f, "{num}/{den}"),
            Repr::Big(r) if r.is_int() => write!(f, "{}", r.numerator()),
            Repr::Big(r) => write!(f, "{}/{}", r.numerator(), r.denominator()),
        }
    }
}

impl Ord for Rational {
    fn cmp(&self, other: &Self) -> Ordering {
        match (&self.0, &other.0) {
            (Repr::Small { num: a, den: b }, Repr::Small { num: c, den: d }) => {
                (i128::from(*a) * i128::from(*d)).cmp(&(i128::from(*c) * i128::from(*b)))
            }
            _ => self.to_rbig().cmp(&other.to_rbig()),
        }
    }
}

impl PartialOrd for Rational {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

fn parse_integer(s: &str) -> Option<IBig> {
    let digits = s.strip_prefix(['+', '-']).unwrap_or(s);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    IBig::from_str_radix(s, 10).ok()
}

/// The number of significant decimal digits of an integer's text (leading zeros and sign
/// aside).
fn significant_digits(s: &str) -> usize {
    s.trim_start_matches(['+', '-'])
        .trim_start_matches('0')
        .len()
}

/// Parses `[sign]digits[.digits][(e|E)[sign]digits]` exactly; `Ok(None)` when it is not
/// that, an error past [`MAX_INPUT_BITS`] (before the digits are parsed).
fn parse_decimal(s: &str) -> Result<Option<RBig>, ParseRationalError> {
    let Some((digits, shift)) = decimal_parts(s) else {
        return Ok(None);
    };
    check_input_size(s, significant_digits(&digits), shift.unsigned_abs())?;
    let Ok(digits) = IBig::from_str_radix(&format!("0{digits}"), 10) else {
        return Ok(None);
    };
    let power = UBig::from(10u32).pow(shift.unsigned_abs() as usize);
    let value = if shift >= 0 {
        RBig::from(digits * IBig::from(power))
    } else {
        RBig::from_parts(digits, power)
    };
    Ok(Some(if s.starts_with('-') { -value } else { value }))
}

/// The digits of a decimal `[sign]digits[.digits][(e|E)[sign]digits]` (integer and fraction
/// parts together, unparsed) and its power of ten.
fn decimal_parts(s: &str) -> Option<(String, i64)> {
    let (mantissa, exponent) = match s.find(['e', 'E']) {
        Some(i) => (&s[..i], s[i + 1..].parse::<i64>().ok()?),
        None => (s, 0),
    };
    let unsigned = mantissa.strip_prefix(['-', '+']).unwrap_or(mantissa);
    let (int_part, frac_part) = unsigned.split_once('.').unwrap_or((unsigned, ""));
    if int_part.is_empty() && frac_part.is_empty() {
        return None;
    }
    let all_digits = |t: &str| t.bytes().all(|b| b.is_ascii_digit());
    if !all_digits(int_part) || !all_digits(frac_part) {
        return None;
    }
    Some((
        format!("{int_part}{frac_part}"),
        exponent.checked_sub(frac_part.len() as i64)?,
    ))
}

impl FromStr for Rational {
    type Err = ParseRationalError;

    /// Parses an integer, a decimal or a fraction `p/q`; refuses, before parsing the digits,
    /// one of more than [`MAX_INPUT_BITS`].
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let err = || ParseRationalError::Syntax(s.chars().take(100).collect());
        let t = s.trim();
        if let Some((p, q)) = t.split_once('/') {
            let (p, q) = (p.trim(), q.trim());
            check_input_size(t, significant_digits(p) + significant_digits(q), 0)?;
            let (p, q) = (
                parse_integer(p).ok_or_else(err)?,
                parse_integer(q).ok_or_else(err)?,
            );
            if q <= IBig::ZERO {
                return Err(err());
            }
            return Ok(Rational::from_rbig(RBig::from_parts_signed(p, q)));
        }
        parse_decimal(t)?.map(Rational::from_rbig).ok_or_else(err)
    }
}

impl Add for Rational {
    type Output = Rational;
    #[inline]
    fn add(self, rhs: Rational) -> Rational {
        match (&self.0, &rhs.0) {
            (&Repr::Small { num: a, den: b }, &Repr::Small { num: c, den: d }) => {
                if b == d {
                    Rational::from_i128(i128::from(a) + i128::from(c), i128::from(b))
                } else {
                    let (a, b, c, d) = (i128::from(a), i128::from(b), i128::from(c), i128::from(d));
                    Rational::from_i128(a * d + c * b, b * d)
                }
            }
            _ => Rational::from_rbig(self.into_rbig() + rhs.into_rbig()),
        }
    }
}

impl Sub for Rational {
    type Output = Rational;
    #[inline]
    fn sub(self, rhs: Rational) -> Rational {
        self + (-rhs)
    }
}

impl Mul for Rational {
    type Output = Rational;
    #[inline]
    fn mul(self, rhs: Rational) -> Rational {
        match (&self.0, &rhs.0) {
            (&Repr::Small { num: a, den: b }, &Repr::Small { num: c, den: d }) => {
                // a/b · c/d with the cross gcds divided out first: the result is reduced.
                let g1 = gcd_u128(u128::from(a.unsigned_abs()), d as u128) as i64;
                let g2 = gcd_u128(u128::from(c.unsigned_abs()), b as u128) as i64;
                let (a, d) = (a / g1, d / g1);
                let (c, b) = (c / g2, b / g2);
                Rational::from_reduced_i128(
                    i128::from(a) * i128::from(c),
                    i128::from(b) * i128::from(d),
                )
            }
            _ => Rational::from_rbig(self.into_rbig() * rhs.into_rbig()),
        }
    }
}

impl Div for Rational {
    type Output = Rational;
    #[inline]
    fn div(self, rhs: Rational) -> Rational {
        match rhs.0 {
            Repr::Small { num, den } => {
                assert!(num != 0, "division of a rational by zero");
                // num ≠ i64::MIN, so its negation fits; den > 0 fits the numerator of the inverse.
                let inverse = if num > 0 {
                    Repr::Small { num: den, den: num }
                } else {
                    Repr::Small {
                        num: -den,
                        den: -num,
                    }
                };
                self * Rational(inverse)
            }
            Repr::Big(r) => Rational::from_rbig(self.into_rbig() / r),
        }
    }
}

impl Neg for Rational {
    type Output = Rational;
    #[inline]
    fn neg(self) -> Rational {
        match self.0 {
            Repr::Small { num, den } => Rational(Repr::Small { num: -num, den }),
            Repr::Big(r) => Rational::from_rbig(-r),
        }
    }
}

impl Scalar for Rational {
    const EXACT: bool = true;
    const ARITHMETIC: &'static str = "exact";

    fn zero() -> Self {
        Rational(Repr::Small { num: 0, den: 1 })
    }
    fn one() -> Self {
        Rational(Repr::Small { num: 1, den: 1 })
    }
    fn from_i64(v: i64) -> Self {
        Rational::from_reduced_i128(i128::from(v), 1)
    }
    fn from_f64(v: f64) -> Option<Self> {
        RBig::try_from(v).ok().map(Rational::from_rbig)
    }
    fn to_f64(&self) -> f64 {
        match &self.0 {
            // Both exact doubles: one correctly rounded division.
            Repr::Small { num, den } if num.unsigned_abs() < 1 << 53 && *den < 1 << 53 => {
                *num as f64 / *den as f64
            }
            _ => self.to_rbig().to_f64().value(),
        }
    }
    fn from_rational(v: &Rational) -> Self {
        v.clone()
    }
    fn to_rational(&self) -> Option<Rational> {
        Some(self.clone())
    }
    fn is_zero(&self) -> bool {
        matches!(self.0, Repr::Small { num: 0, .. })
    }
    fn half(&self) -> Self {
        match self.0 {
            Repr::Small { num, den } => Rational::from_i128(i128::from(num), 2 * i128::from(den)),
            Repr::Big(ref r) => Rational::from_rbig(r / RBig::from(2u8)),
        }
    }
    fn floor(&self) -> Self {
        match self.0 {
            Repr::Small { num, den } => Rational::from_i64(num.div_euclid(den)),
            Repr::Big(ref r) => Rational::from_rbig(RBig::from(r.floor())),
        }
    }
    fn sign(&self) -> Ordering {
        match &self.0 {
            Repr::Small { num, .. } => num.cmp(&0),
            Repr::Big(r) => r.cmp(&RBig::ZERO),
        }
    }
    fn lengths_match(a: &Self, b: &Self, _tolerance: f64) -> bool {
        a == b
    }
    fn bits(&self) -> u64 {
        Rational::bits(self)
    }

    /// `|a − b|²`. Inline values: the rational operations. Otherwise the two differences, their
    /// squares and the sum are formed on unreduced fractions and reduced once at the end (one
    /// gcd instead of five: INSERTEDGES compares the squared distances of every corner pair).
    fn squared_distance(a: &Point<Self>, b: &Point<Self>) -> Self {
        let small = |p: &Point<Self>| p.iter().all(|v| matches!(v.0, Repr::Small { .. }));
        if small(a) && small(b) {
            return super::norm2(&super::sub(a, b));
        }
        let (x, xd) = unreduced_difference(&a[0], &b[0]);
        let (y, yd) = unreduced_difference(&a[1], &b[1]);
        let (num, den) = if xd == yd {
            (&x * &x + &y * &y, &xd * &xd)
        } else {
            let (xd2, yd2) = (&xd * &xd, &yd * &yd);
            (
                &x * &x * IBig::from(yd2.clone()) + &y * &y * IBig::from(xd2.clone()),
                xd2 * yd2,
            )
        };
        Self::from_rbig(RBig::from_parts(num, den))
    }

    /// The sign of `(b − a) × (c − a)`. Inline values: the rational operations (`i128`
    /// intermediates). Otherwise on unreduced fractions: the four differences and the two
    /// products are formed on numerators and denominators without the gcd normalisation of
    /// [`RBig`] arithmetic, and compared by cross-multiplication (denominators are positive).
    /// Equal denominators (dyadic charts share them often) skip their products.
    fn orient2d(a: &Point<Self>, b: &Point<Self>, c: &Point<Self>) -> Ordering {
        let small = |p: &Point<Self>| p.iter().all(|v| matches!(v.0, Repr::Small { .. }));
        if small(a) && small(b) && small(c) {
            let ab = super::sub(b, a);
            let ac = super::sub(c, a);
            return super::cross(&ab, &ac).sign();
        }
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
    let (pn, pd) = p.parts();
    let (qn, qd) = q.parts();
    if pd == qd {
        (pn - qn, pd)
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
            "1267650600228229401496703205377/3",
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
        assert_eq!(checked, 729);
        // Collinear points with different denominators.
        let (p, q, s) = (
            [r("1/3"), r("2/3")],
            [r("1/2"), r("1")],
            [r("5/6"), r("5/3")],
        );
        assert_eq!(Rational::orient2d(&p, &q, &s), Ordering::Equal);
    }

    #[test]
    fn squared_distance_on_unreduced_fractions_agrees_with_the_operations() {
        let r = |s: &str| s.parse::<Rational>().unwrap();
        let values = [
            "0",
            "-3/4",
            "1000000000000000001/2",
            "5/12",
            "1267650600228229401496703205377/3",
            "-1267650600228229401496703205377/1024",
        ];
        for a in values {
            for b in values {
                for c in values {
                    let (p, q) = ([r(a), r(b)], [r(c), r(a)]);
                    let dx = r(a) - r(c);
                    let dy = r(b) - r(a);
                    let expected = dx.clone() * dx + dy.clone() * dy;
                    let got = Rational::squared_distance(&p, &q);
                    assert_eq!(got, expected, "{p:?} {q:?}");
                    assert!(canonical(&got), "{got:?}");
                }
            }
        }
    }

    /// Whether `r` is in canonical form: inline exactly when the reduced value fits.
    fn canonical(r: &Rational) -> bool {
        let big = r.to_rbig();
        let fits = i64::try_from(big.numerator()).is_ok_and(|n| n != i64::MIN)
            && i64::try_from(big.denominator()).is_ok();
        fits == matches!(r.0, Repr::Small { .. })
    }

    #[test]
    fn inline_arithmetic_agrees_with_big_rationals_across_the_overflow_boundary() {
        let max = i64::MAX.to_string();
        let min1 = (i64::MIN + 1).to_string();
        let values: Vec<String> = [
            "0",
            "1",
            "-1",
            "3/4",
            "-7/6",
            "1/3",
            "5/1024",
            "-1000000000000000001/2",
            "4611686018427387904",
            "-4611686018427387904",
            "3037000499/2",
            "1/4611686018427387904",
            "9223372036854775807/2",
            "2/9223372036854775807",
            "-9223372036854775808",
            "9223372036854775808",
            "1/9223372036854775808",
            "1267650600228229401496703205376/3",
            "-5/1267650600228229401496703205376",
        ]
        .iter()
        .map(|v| v.to_string())
        .chain([
            max.clone(),
            min1.clone(),
            format!("1/{max}"),
            format!("{min1}/{max}"),
        ])
        .collect();
        let r = |s: &str| s.parse::<Rational>().unwrap();
        let mut checked = 0;
        for a in &values {
            let (x, bx) = (r(a), r(a).to_rbig());
            assert!(canonical(&x), "{a}");
            assert_eq!(x.to_string(), r(&x.to_string()).to_string());
            assert_eq!(Rational::from_rbig(-bx.clone()), -x.clone(), "-{a}");
            assert_eq!(
                x.half(),
                Rational::from_rbig(&bx / RBig::from(2u8)),
                "{a}/2"
            );
            assert_eq!(
                x.floor(),
                Rational::from_rbig(RBig::from(bx.floor())),
                "floor {a}"
            );
            assert_eq!(x.to_f64(), bx.to_f64().value(), "{a} as f64");
            assert_eq!(x.sign(), bx.cmp(&RBig::ZERO));
            for b in &values {
                let (y, by) = (r(b), r(b).to_rbig());
                let results = [
                    (x.clone() + y.clone(), &bx + &by),
                    (x.clone() - y.clone(), &bx - &by),
                    (x.clone() * y.clone(), &bx * &by),
                ];
                for (got, want) in results {
                    assert!(canonical(&got), "{a} {b}: {got:?}");
                    assert_eq!(got.to_rbig(), want, "{a} {b}");
                }
                if !y.is_zero() {
                    let q = x.clone() / y.clone();
                    assert!(canonical(&q), "{a} / {b}");
                    assert_eq!(q.to_rbig(), &bx / &by, "{a} / {b}");
                }
                assert_eq!(x.cmp(&y), bx.cmp(&by), "{a} <> {b}");
                assert_eq!(x == y, bx == by, "{a} == {b}");
                checked += 1;
            }
        }
        assert_eq!(checked, values.len() * values.len());
    }

    /// A value from a numerator and a denominator of up to 64 bits each, scaled by `2^shift`
    /// (`shift` up to ±80: many values then leave the inline range).
    fn value(num: i64, den: u64, shift: i32) -> Rational {
        let den = RBig::from(UBig::from(den.max(1)));
        let scale = RBig::from(UBig::ONE << shift.unsigned_abs() as usize);
        let r = RBig::from(IBig::from(num)) / den;
        Rational::from_rbig(if shift >= 0 { r * scale } else { r / scale })
    }

    proptest::proptest! {
        #[test]
        fn random_values_agree_with_big_rationals(
            a in proptest::prelude::any::<(i64, u64)>(), b in proptest::prelude::any::<(i64, u64)>(),
            sa in -80i32..80, sb in -80i32..80, small in 0u32..3,
        ) {
            // `small` = 1 or 2: narrow operands (the common case), else full 64-bit ones.
            let narrow = |(n, d): (i64, u64)| if small > 0 { (n >> 40, (d >> 40).max(1)) } else { (n, d) };
            let (a, b) = (narrow(a), narrow(b));
            let (sa, sb) = if small > 0 { (sa / 8, sb / 8) } else { (sa, sb) };
            let (x, y) = (value(a.0, a.1, sa), value(b.0, b.1, sb));
            let (bx, by) = (x.to_rbig(), y.to_rbig());
            for (got, want) in [
                (x.clone() + y.clone(), &bx + &by),
                (x.clone() - y.clone(), &bx - &by),
                (x.clone() * y.clone(), &bx * &by),
                (x.half(), &bx / RBig::from(2u8)),
                (x.floor(), RBig::from(bx.floor())),
            ] {
                proptest::prop_assert!(canonical(&got));
                proptest::prop_assert_eq!(got.to_rbig(), want);
            }
            if !y.is_zero() {
                let q = x.clone() / y.clone();
                proptest::prop_assert!(canonical(&q));
                proptest::prop_assert_eq!(q.to_rbig(), &bx / &by);
            }
            proptest::prop_assert_eq!(x.cmp(&y), bx.cmp(&by));
            proptest::prop_assert_eq!(x.to_f64(), bx.to_f64().value());
        }
    }

    /// dashu-int before 0.5.1 reserved a gcd's scratch memory from the operands' first lengths
    /// and panicked ("not enough memory allocated") when a later Euclidean step divided by a
    /// much shorter remainder: here `x = 5y + s`, `y` of 10,000 bits and `s` of 5,000.
    #[test]
    fn quotients_of_long_operands_with_a_short_remainder_do_not_panic() {
        let y = (UBig::ONE << 10_000) - UBig::from(12_345u32);
        let s = (UBig::ONE << 5_000) + UBig::from(7u32);
        let x = UBig::from(5u8) * &y + &s;
        let (rx, ry) = (
            Rational::from_rbig(RBig::from(x.clone())),
            Rational::from_rbig(RBig::from(y.clone())),
        );
        let q = rx / ry;
        assert_eq!(
            q.to_rbig(),
            RBig::from_parts(IBig::from(x), y),
            "x / y reduced by dashu's gcd"
        );
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
