//! Plane geometry over a [`Scalar`]: points as complex numbers, exact-sign predicates, and the
//! rigid motions of Dubois' footnote 2.
//!
//! Paper: L. Dubois, "Computing the Intrinsic Delaunay Triangulation of a Closed Polyhedral
//! Surface", Section 2.1 and footnote 2: a portalgon's gluing maps are orientation-preserving
//! rigid motions of the plane, written with no square root as
//! `z ↦ (z − s₀)(s′₁ − s′₀)/(s₁ − s₀) + s′₀` (the motion taking side `s₀s₁` to side `s′₀s′₁`).
//! With points as complex numbers that map is `z ↦ ω·z + b`; [`Motion`] stores `ω` and `b`, so
//! composing and inverting motions stays in the field of the coordinates (the rationals in exact
//! mode: everything of Dubois' algorithm then lives in `Q(i)`).
//!
//! Two scalar types implement [`Scalar`]:
//! - `f64`: constructions round; the predicates [`orient`] and [`incircle`] are Shewchuk's
//!   adaptive-precision ones (the `robust` crate), so their *signs* are exact for the given
//!   doubles;
//! - [`Rational`]: exact rationals (arbitrary-precision numerator and denominator); constructions
//!   and predicates are exact.
//!
//! Points are `[S; 2]` ([`Point`]): `Point<f64>` is the crate's `Point2`.
//!
//! [`triangulate_polygon`] cuts a simple polygon into triangles in O(n log n) (`triangulate.rs`).

mod double_double;
mod rational;
mod scalar;
mod simple;
mod tolerances;
mod triangulate;

pub use double_double::DoubleDouble;
pub(crate) use rational::small_literal;
pub use rational::{MAX_INPUT_BITS, ParseRationalError, Rational};
pub use scalar::Scalar;
pub(crate) use simple::crossing_sides;
pub use tolerances::Tolerances;
pub use triangulate::triangulate_polygon;

use std::cmp::Ordering;

/// A point (or vector) of the plane, also read as the complex number `x + iy`.
pub type Point<S> = [S; 2];

/// `a + b`.
#[inline]
pub fn add<S: Scalar>(a: &Point<S>, b: &Point<S>) -> Point<S> {
    [a[0].clone() + b[0].clone(), a[1].clone() + b[1].clone()]
}

/// `a − b`.
#[inline]
pub fn sub<S: Scalar>(a: &Point<S>, b: &Point<S>) -> Point<S> {
    [a[0].clone() - b[0].clone(), a[1].clone() - b[1].clone()]
}

/// `k·a`.
#[inline]
pub fn scale<S: Scalar>(k: &S, a: &Point<S>) -> Point<S> {
    [k.clone() * a[0].clone(), k.clone() * a[1].clone()]
}

/// The dot product `⟨a, b⟩`.
#[inline]
pub fn dot<S: Scalar>(a: &Point<S>, b: &Point<S>) -> S {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone()
}

/// The cross product `a × b` (the z-component), positive when `b` is counter-clockwise of `a`.
#[inline]
pub fn cross<S: Scalar>(a: &Point<S>, b: &Point<S>) -> S {
    a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone()
}

/// `|a|²`, the squared norm (exact in exact mode: compare lengths by their squares).
#[inline]
pub fn norm2<S: Scalar>(a: &Point<S>) -> S {
    dot(a, a)
}

/// `|a − b|²` ([`Scalar::squared_distance`]: exact rationals reduce the result only).
#[inline]
pub fn dist2<S: Scalar>(a: &Point<S>, b: &Point<S>) -> S {
    S::squared_distance(a, b)
}

/// `|a − b|` as a double (a square root: only for reports and f64 geometry).
#[inline]
pub fn dist_f64<S: Scalar>(a: &Point<S>, b: &Point<S>) -> f64 {
    let d = sub(a, b);
    d[0].to_f64().hypot(d[1].to_f64())
}

/// The midpoint `(a + b)/2`.
#[inline]
pub fn midpoint<S: Scalar>(a: &Point<S>, b: &Point<S>) -> Point<S> {
    let s = add(a, b);
    [s[0].half(), s[1].half()]
}

/// The complex product `a·b`.
#[inline]
pub fn complex_mul<S: Scalar>(a: &Point<S>, b: &Point<S>) -> Point<S> {
    [
        a[0].clone() * b[0].clone() - a[1].clone() * b[1].clone(),
        a[0].clone() * b[1].clone() + a[1].clone() * b[0].clone(),
    ]
}

/// The complex quotient `a/b` (`b ≠ 0`): `a·conj(b)/|b|²`.
#[inline]
pub fn complex_div<S: Scalar>(a: &Point<S>, b: &Point<S>) -> Point<S> {
    let n = norm2(b);
    [
        (a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone()) / n.clone(),
        (a[1].clone() * b[0].clone() - a[0].clone() * b[1].clone()) / n,
    ]
}

/// Orientation of `c` relative to the directed line `a → b`: `Greater` when `c` is to the left
/// (`a, b, c` counter-clockwise), `Less` to the right, `Equal` when collinear. Exact sign in both
/// arithmetic modes ([`Scalar::orient2d`]).
#[inline]
pub fn orient<S: Scalar>(a: &Point<S>, b: &Point<S>, c: &Point<S>) -> Ordering {
    S::orient2d(a, b, c)
}

/// In-circle test: `Greater` when `d` is strictly inside the circle through the
/// counter-clockwise triangle `a, b, c`, `Less` outside, `Equal` on it. Exact sign in both modes
/// ([`Scalar::incircle`]).
#[inline]
pub fn incircle<S: Scalar>(a: &Point<S>, b: &Point<S>, c: &Point<S>, d: &Point<S>) -> Ordering {
    S::incircle(a, b, c, d)
}

/// Whether `c` lies on the closed segment `ab` (exact sign of the orientation, then bounds).
pub fn on_segment<S: Scalar>(a: &Point<S>, b: &Point<S>, c: &Point<S>) -> bool {
    let within = |i: usize| {
        let (lo, hi) = if a[i] <= b[i] {
            (&a[i], &b[i])
        } else {
            (&b[i], &a[i])
        };
        *lo <= c[i] && c[i] <= *hi
    };
    orient(a, b, c) == Ordering::Equal && within(0) && within(1)
}

/// Whether the closed segments `pq` and `rs` intersect (touching counts).
pub fn segments_intersect<S: Scalar>(
    p: &Point<S>,
    q: &Point<S>,
    r: &Point<S>,
    s: &Point<S>,
) -> bool {
    let (d1, d2) = (orient(r, s, p), orient(r, s, q));
    let (d3, d4) = (orient(p, q, r), orient(p, q, s));
    let opposite = |x: Ordering, y: Ordering| {
        matches!(
            (x, y),
            (Ordering::Greater, Ordering::Less) | (Ordering::Less, Ordering::Greater)
        )
    };
    if opposite(d1, d2) && opposite(d3, d4) {
        return true;
    }
    on_segment(r, s, p) || on_segment(r, s, q) || on_segment(p, q, r) || on_segment(p, q, s)
}

/// Twice the signed area of a closed polygon (positive when counter-clockwise; exact in exact
/// mode).
pub fn twice_signed_area<S: Scalar>(corners: &[Point<S>]) -> S {
    let k = corners.len();
    let mut sum = S::zero();
    for i in 1..k.saturating_sub(1) {
        sum = sum
            + cross(
                &sub(&corners[i], &corners[0]),
                &sub(&corners[i + 1], &corners[0]),
            );
    }
    sum
}

/// An orientation-preserving similarity `z ↦ ω·z + b` of the complex plane; a rigid motion when
/// `|ω| = 1`, which [`Motion::taking`] guarantees for sides of equal length (exactly in exact
/// mode, up to rounding in f64).
#[derive(Clone, Debug, PartialEq)]
pub struct Motion<S> {
    /// The rotation `ω` (a complex number of modulus 1 for a rigid motion).
    pub rotation: Point<S>,
    /// The translation `b`.
    pub translation: Point<S>,
}

impl<S: Scalar> Motion<S> {
    /// The identity.
    pub fn identity() -> Self {
        Motion {
            rotation: [S::one(), S::zero()],
            translation: [S::zero(), S::zero()],
        }
    }

    /// The translation `z ↦ z + t`.
    pub fn translation(t: Point<S>) -> Self {
        Motion {
            rotation: [S::one(), S::zero()],
            translation: t,
        }
    }

    /// Footnote 2's motion taking `s0` to `t0` and `s1` to `t1`:
    /// `z ↦ (z − s0)(t1 − t0)/(s1 − s0) + t0`, with no square root. `s0 ≠ s1`; rigid when
    /// `|s1 − s0| = |t1 − t0|`.
    pub fn taking(s0: &Point<S>, s1: &Point<S>, t0: &Point<S>, t1: &Point<S>) -> Self {
        let rotation = complex_div(&sub(t1, t0), &sub(s1, s0));
        let translation = sub(t0, &complex_mul(&rotation, s0));
        Motion {
            rotation,
            translation,
        }
    }

    /// The motion gluing side `s0 s1` onto side `t0 t1` (`s0` to `t0`, `s1` to `t1`): footnote 2's
    /// [`Motion::taking`] in exact mode, where matched sides have equal lengths and `|ω| = 1`
    /// exactly; in `f64`, where they agree only up to rounding, `ω` is normalised to modulus 1
    /// (a rigid motion taking `s0` to `t0` and the direction of `s1 − s0` to that of `t1 − t0`).
    /// Footnote 2's quotient would otherwise scale the moved polygon by the ratio of the two
    /// lengths, and a short side with a small absolute error makes that ratio far from 1: every
    /// later side of the polygon inherits the error, and repeated merges compound it.
    pub fn gluing(s0: &Point<S>, s1: &Point<S>, t0: &Point<S>, t1: &Point<S>) -> Self {
        let m = Motion::taking(s0, s1, t0, t1);
        if S::EXACT {
            return m;
        }
        let Some(modulus) = norm2(&m.rotation)
            .approximate_sqrt()
            .filter(|k| !k.is_zero())
        else {
            return m;
        };
        let rotation = [
            m.rotation[0].clone() / modulus.clone(),
            m.rotation[1].clone() / modulus,
        ];
        let translation = sub(t0, &complex_mul(&rotation, s0));
        Motion {
            rotation,
            translation,
        }
    }

    /// The image of `z`.
    #[inline]
    pub fn apply(&self, z: &Point<S>) -> Point<S> {
        add(&complex_mul(&self.rotation, z), &self.translation)
    }

    /// The image of the vector `v` (the rotation alone).
    #[inline]
    pub fn apply_vector(&self, v: &Point<S>) -> Point<S> {
        complex_mul(&self.rotation, v)
    }

    /// `self ∘ other`: first `other`, then `self`.
    pub fn compose(&self, other: &Motion<S>) -> Motion<S> {
        Motion {
            rotation: complex_mul(&self.rotation, &other.rotation),
            translation: self.apply(&other.translation),
        }
    }

    /// The inverse motion `z ↦ (z − b)/ω`.
    pub fn inverse(&self) -> Motion<S> {
        let one = [S::one(), S::zero()];
        let rotation = complex_div(&one, &self.rotation);
        let translation = complex_mul(&rotation, &self.translation);
        Motion {
            rotation,
            translation: [-translation[0].clone(), -translation[1].clone()],
        }
    }

    /// The `k`-th power `self^k` (`k < 0`: of the inverse), by binary powering: O(log |k|)
    /// compositions. In exact mode the sizes of `ω^k`'s numerator and denominator grow linearly
    /// in `|k|`; in f64 the rounding error grows like `log |k|` relative to `|b|·|k|`.
    pub fn power(&self, k: i64) -> Motion<S> {
        let mut base = if k < 0 { self.inverse() } else { self.clone() };
        let mut e = k.unsigned_abs();
        let mut result = Motion::identity();
        while e > 0 {
            if e & 1 == 1 {
                result = result.compose(&base);
            }
            e >>= 1;
            if e > 0 {
                base = base.compose(&base);
            }
        }
        result
    }

    /// Whether this is a translation (`ω = 1` exactly).
    pub fn is_translation(&self) -> bool {
        self.rotation[0] == S::one() && self.rotation[1].is_zero()
    }

    /// Whether this is the identity (exactly).
    pub fn is_identity(&self) -> bool {
        self.is_translation() && self.translation[0].is_zero() && self.translation[1].is_zero()
    }
}

/// Converts a point to another scalar type through `f64` (exact from f64 to [`Rational`] for
/// finite coordinates; rounding the other way). `None` when a coordinate is not finite.
pub fn convert_point<S: Scalar, T: Scalar>(p: &Point<S>) -> Option<Point<T>> {
    Some([T::from_f64(p[0].to_f64())?, T::from_f64(p[1].to_f64())?])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(s: &str) -> Rational {
        s.parse().unwrap()
    }

    #[test]
    fn motion_taking_maps_endpoints_exactly() {
        let (s0, s1) = ([r("1/3"), r("2")], [r("4/3"), r("6")]);
        let (t0, t1) = ([r("-5"), r("0")], [r("-1"), r("-1")]);
        let m = Motion::taking(&s0, &s1, &t0, &t1);
        assert_eq!(m.apply(&s0), t0);
        assert_eq!(m.apply(&s1), t1);
        assert!(m.compose(&m.inverse()).is_identity());
        assert!(m.inverse().compose(&m).is_identity());
        // |s1 - s0|² = |t1 - t0|² = 17: |ω|² = 1 exactly.
        assert_eq!(norm2(&m.rotation), Rational::one());
    }

    #[test]
    fn predicates_agree_between_modes_on_exact_doubles() {
        // Nearly collinear points where a naive f64 determinant gets the sign wrong.
        let a = [0.5, 0.5];
        let b = [12.0, 12.0];
        let c = [24.0, 24.0];
        for i in 0..64 {
            let p = [0.5 + f64::EPSILON * f64::from(i), 0.5];
            let exact = orient(
                &convert_point::<f64, Rational>(&p).unwrap(),
                &convert_point::<f64, Rational>(&b).unwrap(),
                &convert_point::<f64, Rational>(&c).unwrap(),
            );
            assert_eq!(orient(&p, &b, &c), exact, "i = {i}");
        }
        assert_eq!(orient(&a, &b, &c), Ordering::Equal);
        let (p, q, s) = ([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]);
        assert_eq!(incircle(&p, &q, &s, &[1.0, 1.0]), Ordering::Equal);
        assert_eq!(incircle(&p, &q, &s, &[0.5, 0.5]), Ordering::Greater);
        assert_eq!(incircle(&p, &q, &s, &[2.0, 2.0]), Ordering::Less);
        let e = |x: f64, y: f64| {
            [
                Rational::from_f64(x).unwrap(),
                Rational::from_f64(y).unwrap(),
            ]
        };
        assert_eq!(
            incircle(&e(0.0, 0.0), &e(1.0, 0.0), &e(0.0, 1.0), &e(1.0, 1.0)),
            Ordering::Equal
        );
    }

    #[test]
    fn segments_and_area() {
        let sq: Vec<Point<f64>> = vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
        assert_eq!(twice_signed_area(&sq), 8.0);
        assert!(segments_intersect(&sq[0], &sq[2], &sq[1], &sq[3]));
        assert!(segments_intersect(&sq[0], &sq[1], &sq[1], &sq[2]));
        assert!(!segments_intersect(&sq[0], &sq[1], &sq[2], &sq[3]));
        assert_eq!(
            midpoint(&[r("1/3"), r("0")], &[r("1"), r("1")]),
            [r("2/3"), r("1/2")]
        );
    }
}
