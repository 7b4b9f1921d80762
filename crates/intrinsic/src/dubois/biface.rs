//! Bifaces and good bifaces (Dubois, Section 3), and the good-biface kernel that stands in for
//! Lemma 25 of Appendix B.
//!
//! A *biface* (Section 3) is a tube of two triangles whose sides `s₀, s₁` are matched with
//! `s′₀, s′₁`: its surface is an annulus with one vertex `b₀`, `b₁` on each boundary component,
//! two *boundary edges* (loops) and two *interior edges*. [`Biface`] holds it in one chart, as the
//! counter-clockwise quadrilateral `A, D, B, C` made of the triangles `(A, B, C)` and `(A, D, B)`
//! side by side along their common interior edge `AB`; the sides `AD` and `CB` are the two copies
//! of the other interior edge, glued by footnote 2's motion `g(z) = C + ω(z − A)`,
//! `ω = (B − C)/(D − A)` (`g(A) = C`, `g(D) = B`). The boundary edges are `CA` (at `b₀`) and `DB`
//! (at `b₁`).
//!
//! **The ladder.** The universal cover of the annulus is the strip of quadrilaterals `gᵏ(ADBC)`;
//! the lifts of `b₀` are `p_k = gᵏ(A)`, those of `b₁` are `q_k = gᵏ(D)`. Every `b₀–b₁` arc is
//! homotopic to exactly one segment `p₀q_m` of the strip (offset `m`), and a shortest `b₀–b₁` path
//! is a straight `p₀q_m` that stays in the strip (a *valid* offset): bending at a vertex would pass
//! through `b₀` or `b₁` again, and cutting there is shorter. The biface's own interior edges are
//! `AD = p₀q₀` (offset 0) and `AB = p₀q₁` (offset 1). The biface with *rung offset* `j` is the
//! chart `p₀, q_j, q_{j+1}, p₁` with the same gluing `g`: its interior edges have offsets `j`
//! and `j + 1`, its boundary sides are `p₁p₀ = CA` (unchanged) and `q_jq_{j+1} = gʲ(DB)`.
//!
//! **Good, thin, thick** (Section 3). The biface is *good* when one interior edge `e` is a
//! shortest path of its surface and the other, `f`, is the shorter diagonal of the quadrilateral
//! obtained by cutting along `e` (when that quadrilateral has two diagonals). With `e` at offset
//! `m`, the quadrilateral is `p₀, q_m, q_{m+1}, p₁`, whose diagonals are `p₀q_{m+1}` and
//! `p₁q_m ≅ p₀q_{m−1}` — each one a diagonal exactly when its offset is valid. A good biface is
//! *thin* when both interior edges are strictly longer than both boundary edges, *thick*
//! otherwise ([`BifaceKind`]). Lengths are compared by their squares.
//!
//! **The kernel ([`Biface::make_good`]).** Lemma 25 delegates to Löffler, Ophelders, Silveira and
//! Staals' Theorem 45, of which there is no public implementation. This module uses instead the
//! closed forms of docs/dubois.md §3.1 — a *reconstruction*, checked by the brute-force ladder oracle
//! of `tests/bifaces.rs` (`kernel_agrees_with_the_ladder_oracle_*`,
//! `validity_criterion_agrees_with_the_walk`):
//! - (a) *translation* (`ω = 1` exactly, `t = C − A`): every offset is valid and `|p₀q_m|²` is
//!   quadratic in `m`, so `m* = ⌊⟨A − D, t⟩/⟨t, t⟩ + ½⌋` (one division and one floor);
//! - (b) *rotation* (`ω ≠ 1`, `θ = Arg ω`, centre `c = (C − ωA)/(1 − ω)`,
//!   `ψ₀ = Arg((D − c)/(A − c))`): offset `m` is valid iff (i) `q_m − p₀` is strictly inside the
//!   angle swept counter-clockwise from `p₋₁ − p₀` to `p₁ − p₀`, (ii) `p₀ − q_m` is strictly inside
//!   the angle from `q_{m+1} − q_m` to `q_{m−1} − q_m`, and (iii) `|ψ₀ + mθ| < π`
//!   ([`Biface::is_valid_offset`]). The valid offsets form an interval containing `{0, 1}` on
//!   which `|p₀q_m|² = |A − c|² + |D − c|² − 2|A − c||D − c| cos(ψ₀ + mθ)` is unimodal, so the
//!   kernel starts at `round(−ψ₀/θ)`, clamps into the interval by bisection on validity, and
//!   descends on exact comparisons of squared lengths.
//!
//! Then `f` is the shorter valid neighbour `p₀q_{m*±1}`.
//!
//! **Ties** go toward the current edges: a good biface is returned unchanged
//! ([`GoodBiface::unchanged`]). Among other good bifaces: when two offsets are both shortest, `e`
//! and `f` are those two; when the two neighbours of `m*` tie (a rectangle), `f = p₀q_{m*+1}`
//! (rung offset `m*`). The other choice, `p₁q_{m*}`, would be as good; this one is taken so
//! that `T_x` cut along its unit loop gives the triangle `(0,0), (1,0), (x − ⌊x⌋, 2)` for integer
//! `x` too (the test `t_x_cut_along_its_unit_loop_gives_d_x`).
//!
//! **Cost.** Offsets are integers held in the scalar type `S`, so the translation quotient is
//! exact however large it is (`T_x` at `x = 10¹⁸`).
//! - Translation: O(1) operations and one floor. In f64 that is a few flops; in exact mode a
//!   handful of rational operations on numbers of the input's size (O(1) big-number operations,
//!   each quasi-linear in the bit size).
//! - Rotation: two `atan2` on doubles, then O(log |m*|) validity tests during the bisection and
//!   O(1) descent steps when the estimate is right; each test computes `g^m` by binary powering
//!   in O(log |m|) operations, so O(log² h) operations in all (h ≥ |m*| is the happiness). In
//!   f64 that is O(log² h) flops; in exact mode `ω^m`'s numerator and denominator have
//!   Θ(|m|·b) bits for `b`-bit input, so the cost is dominated by that size (the real-RAM
//!   O(1 + log h) of Lemma 25 does not carry over to bit complexity). Rotation offsets are
//!   limited to `|m| ≤ 2⁵²` ([`BifaceError::OffsetOutOfRange`]).
//!
//! In exact mode ([`crate::geometry::Rational`]) every predicate is exact: (i) and (ii) are
//! orientation tests, (iii) is decided on doubles when `|ψ₀ + mθ|` is at least 10⁻⁶ away from
//! `π` (the double's error is far below that for `|m| ≤ 2⁵²`) and otherwise by the exact side of
//! `q_m` with respect to the line `cA`. In f64, constructions round; the orientation tests are
//! exact for the rounded points.

use std::cmp::Ordering;

use crate::geometry::{
    Motion, Point, Scalar, add, complex_div, dist2, dot, orient, scale, sub, twice_signed_area,
};
use crate::portalgon::points_inside;

/// Largest offset the rotation case handles (`|m| ≤ 2⁵²`: integers exact in a double).
const MAX_ROTATION_OFFSET: i64 = 1 << 52;
/// Descent steps allowed after the estimate (the estimate is within O(1) steps in practice).
const MAX_DESCENT_STEPS: u64 = 1 << 24;
/// Below this `|θ|`, f64 bifaces start from the translation quotient (their centre `c` is too
/// far away to be computed accurately).
const NEAR_TRANSLATION_THETA: f64 = 1e-9;
/// Margin around `±π` within which (iii) is decided exactly.
const ANGLE_MARGIN: f64 = 1e-6;

/// Why a biface could not be built or made good.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum BifaceError {
    /// A corner is not finite (f64 only).
    #[error("biface corner {corner} is not finite")]
    NonFinite {
        /// 0 = A, 1 = D, 2 = B, 3 = C.
        corner: usize,
    },
    /// A triangle is clockwise or degenerate.
    #[error("biface triangle {triangle} ({name}) is not counter-clockwise with positive area")]
    NotCounterClockwise {
        /// 0 = `(A, B, C)`, 1 = `(A, D, B)`.
        triangle: usize,
        /// Its corners by name.
        name: &'static str,
    },
    /// The glued sides `AD` and `CB` have different lengths.
    #[error("biface sides AD and CB are glued but their squared lengths differ: {ad2} and {cb2}")]
    UnequalGluedSides {
        /// `|AD|²` as a double.
        ad2: f64,
        /// `|CB|²` as a double.
        cb2: f64,
    },
    /// A rotation offset beyond `2⁵²` would be needed (or a double estimate was not finite).
    #[error("the shortest path of this rotation biface needs an offset beyond 2^52 ({estimate})")]
    OffsetOutOfRange {
        /// The estimated offset, as a double.
        estimate: f64,
    },
    /// The descent from the estimate took more than 2²⁴ steps (f64 rounding far off).
    #[error("the shortest-offset descent did not settle within 2^24 steps (from offset {start})")]
    DescentLimit {
        /// The offset the descent started from.
        start: i64,
    },
}

/// Good or not, and thin or thick (Section 3).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BifaceKind {
    /// Not good: an interior edge could be replaced by a shorter one.
    NotGood,
    /// Good, both interior edges strictly longer than both boundary edges.
    Thin,
    /// Good, and not thin.
    Thick,
}

/// A biface in one chart: the counter-clockwise quadrilateral `A, D, B, C` of the triangles
/// `(A, B, C)` and `(A, D, B)`, with `AD` glued to `CB` by `g(A) = C`, `g(D) = B` (see the
/// module documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct Biface<S: Scalar = f64> {
    a: Point<S>,
    d: Point<S>,
    b: Point<S>,
    c: Point<S>,
}

/// The result of [`Biface::make_good`].
#[derive(Clone, Debug, PartialEq)]
pub struct GoodBiface<S: Scalar = f64> {
    /// The good biface: the input's chart at rung offset [`GoodBiface::rung_offset`].
    pub biface: Biface<S>,
    /// `j`: the new interior edges are the input's offsets `j` (the new `AD`) and `j + 1` (the
    /// new `AB`); an integer.
    pub rung_offset: S,
    /// `m*`: the offset of the shortest path used (`j` or `j + 1`); an integer.
    pub shortest_offset: S,
    /// The squared length of a shortest `b₀–b₁` path.
    pub shortest_length2: S,
    /// Whether the input was already good (and is returned as it is, `j = 0`).
    pub unchanged: bool,
}

/// The ladder's geometry that the offsets need, computed once per biface.
enum Ladder<S: Scalar> {
    /// `ω = 1`: `q_m = D + m·t`.
    Translation { t: Point<S> },
    /// `ω ≠ 1`.
    Rotation(Box<Rotation<S>>),
}

struct Rotation<S: Scalar> {
    g: Motion<S>,
    /// `p₋₁ = g⁻¹(A)` and `q₋₁ = g⁻¹(D)`.
    p_prev: Point<S>,
    q_prev: Point<S>,
    /// The fixed point `c` of `g`.
    centre: Point<S>,
    /// `θ = Arg ω` and `ψ₀ = Arg((D − c)/(A − c))`, as doubles.
    theta: f64,
    psi0: f64,
}

impl<S: Scalar> Biface<S> {
    /// The biface of the quadrilateral `A, D, B, C` (see [`Biface`]). Errors: a corner not
    /// finite, a triangle `(A, B, C)` or `(A, D, B)` not strictly counter-clockwise (exact
    /// orientation tests), or `|AD|² ≠ |CB|²` (exactly in exact mode; up to the relative
    /// `tolerance` in f64, [`Scalar::lengths_match`]).
    pub fn new(
        a: Point<S>,
        d: Point<S>,
        b: Point<S>,
        c: Point<S>,
        tolerance: f64,
    ) -> Result<Self, BifaceError> {
        for (corner, p) in [&a, &d, &b, &c].into_iter().enumerate() {
            if !(p[0].is_finite() && p[1].is_finite()) {
                return Err(BifaceError::NonFinite { corner });
            }
        }
        if orient(&a, &b, &c) != Ordering::Greater {
            return Err(BifaceError::NotCounterClockwise {
                triangle: 0,
                name: "(A, B, C)",
            });
        }
        if orient(&a, &d, &b) != Ordering::Greater {
            return Err(BifaceError::NotCounterClockwise {
                triangle: 1,
                name: "(A, D, B)",
            });
        }
        let (ad2, cb2) = (dist2(&a, &d), dist2(&c, &b));
        if !S::lengths_match(&ad2, &cb2, tolerance) {
            return Err(BifaceError::UnequalGluedSides {
                ad2: ad2.to_f64(),
                cb2: cb2.to_f64(),
            });
        }
        Ok(Biface { a, d, b, c })
    }

    /// Corner `A = p₀` (a lift of `b₀`).
    pub fn a(&self) -> &Point<S> {
        &self.a
    }
    /// Corner `D = q₀` (a lift of `b₁`).
    pub fn d(&self) -> &Point<S> {
        &self.d
    }
    /// Corner `B = q₁` (a lift of `b₁`).
    pub fn b(&self) -> &Point<S> {
        &self.b
    }
    /// Corner `C = p₁` (a lift of `b₀`).
    pub fn c(&self) -> &Point<S> {
        &self.c
    }

    /// The two triangles, counter-clockwise: `[(A, B, C), (A, D, B)]`. In the first, side 0
    /// (`AB`) is matched with side 2 (`BA`) of the second, and side 1 (`BC`) with side 0 (`AD`)
    /// of the second; side 2 (`CA`) and side 1 (`DB`) are the boundary edges at `b₀` and `b₁`.
    pub fn triangles(&self) -> [[Point<S>; 3]; 2] {
        [
            [self.a.clone(), self.b.clone(), self.c.clone()],
            [self.a.clone(), self.d.clone(), self.b.clone()],
        ]
    }

    /// The gluing `g` of `AD` onto `CB` (footnote 2: `g(A) = C`, `g(D) = B`).
    pub fn gluing(&self) -> Motion<S> {
        Motion::gluing(&self.a, &self.d, &self.c, &self.b)
    }

    /// Whether the gluing is a translation (`ω = 1` exactly): a flat cylinder,
    /// docs/dubois.md §3.1(a).
    pub fn is_translation(&self) -> bool {
        self.gluing().is_translation()
    }

    /// Twice the area of the surface (exact in exact mode).
    pub fn twice_area(&self) -> S {
        twice_signed_area(&[
            self.a.clone(),
            self.d.clone(),
            self.b.clone(),
            self.c.clone(),
        ])
    }

    /// The squared lengths of the boundary edges `[|CA|², |DB|²]` (at `b₀`, at `b₁`).
    pub fn boundary_lengths2(&self) -> [S; 2] {
        [dist2(&self.c, &self.a), dist2(&self.d, &self.b)]
    }

    /// The squared lengths of the interior edges `[|AD|², |AB|²]` (offsets 0 and 1).
    pub fn interior_lengths2(&self) -> [S; 2] {
        [dist2(&self.a, &self.d), dist2(&self.a, &self.b)]
    }

    /// Whether both interior edges are strictly longer than both boundary edges (Section 3's
    /// *thin*, without the goodness that the definition presupposes; see [`Biface::kind`]).
    pub fn interior_longer_than_boundary(&self) -> bool {
        let [b0, b1] = self.boundary_lengths2();
        let longest = if b0 >= b1 { b0 } else { b1 };
        self.interior_lengths2().iter().all(|e| *e > longest)
    }

    fn ladder(&self) -> Ladder<S> {
        self.ladder_with_winding(None)
    }

    /// The ladder, with `ψ₀` given (a tube's chart, [`good_biface_of_ladder`]) or the principal
    /// argument (a biface: `AD` is a segment of the strip, so its angle seen from `c` is below π).
    fn ladder_with_winding(&self, psi0: Option<f64>) -> Ladder<S> {
        let g = self.gluing();
        if g.is_translation() {
            return Ladder::Translation {
                t: sub(&self.c, &self.a),
            };
        }
        let g_inv = g.inverse();
        let one_minus_omega = [S::one() - g.rotation[0].clone(), -g.rotation[1].clone()];
        let centre = complex_div(&g.translation, &one_minus_omega);
        let ratio = complex_div(&sub(&self.d, &centre), &sub(&self.a, &centre));
        Ladder::Rotation(Box::new(Rotation {
            p_prev: g_inv.apply(&self.a),
            q_prev: g_inv.apply(&self.d),
            theta: g.rotation[1].to_f64().atan2(g.rotation[0].to_f64()),
            psi0: psi0.unwrap_or_else(|| ratio[1].to_f64().atan2(ratio[0].to_f64())),
            centre,
            g,
        }))
    }

    /// `q_m = gᵐ(D)`, the lift of `b₁` at offset `m` (an integer). Errors: a rotation offset
    /// beyond `2⁵²`.
    pub fn lift_b1(&self, m: &S) -> Result<Point<S>, BifaceError> {
        match self.ladder() {
            Ladder::Translation { t } => Ok(add(&self.d, &scale(m, &t))),
            Ladder::Rotation(r) => Ok(r.g.power(offset_i64(m)?).apply(&self.d)),
        }
    }

    /// Whether the segment `p₀q_m` lies in the ladder: docs/dubois.md §3.1(b)'s criterion (i)–(iii)
    /// for a rotation, always for a translation (§2.1(a)). A *reconstruction*, checked against
    /// the walk of the segment through the strip by `validity_criterion_agrees_with_the_walk`.
    pub fn is_valid_offset(&self, m: &S) -> Result<bool, BifaceError> {
        match self.ladder() {
            Ladder::Translation { .. } => Ok(true),
            Ladder::Rotation(r) => Ok(self.rotation_valid(&r, offset_i64(m)?)),
        }
    }

    /// The biface with rung offset `j` (an integer): the chart `p₀, q_j, q_{j+1}, p₁` with the
    /// same gluing. It is a biface of the same surface when `j` and `j + 1` are valid offsets
    /// whose segments bound a quadrilateral with `p₁`, as [`Biface::make_good`]'s are.
    pub fn with_rung_offset(&self, j: &S) -> Result<Biface<S>, BifaceError> {
        let (d, b) = match self.ladder() {
            Ladder::Translation { t } => (add(&self.d, &scale(j, &t)), add(&self.b, &scale(j, &t))),
            Ladder::Rotation(r) => {
                let gj = r.g.power(offset_i64(j)?);
                (gj.apply(&self.d), gj.apply(&self.b))
            }
        };
        Ok(Biface {
            a: self.a.clone(),
            d,
            b,
            c: self.c.clone(),
        })
    }

    /// Section 3's classification: not good, thin or thick.
    pub fn kind(&self) -> Result<BifaceKind, BifaceError> {
        Ok(if !self.make_good()?.unchanged {
            BifaceKind::NotGood
        } else if self.interior_longer_than_boundary() {
            BifaceKind::Thin
        } else {
            BifaceKind::Thick
        })
    }

    /// Whether the biface is good (Section 3).
    pub fn is_good(&self) -> Result<bool, BifaceError> {
        Ok(self.make_good()?.unchanged)
    }

    /// The good-biface kernel (Lemma 25 of Appendix B, by docs/dubois.md §3.1's closed forms — a
    /// reconstruction, see the module documentation for the method, its cost and its tests): a
    /// good biface of the same surface, with the same gluing, the same boundary side `CA` and
    /// `DB` replaced by its image `gʲ(DB)`. A good input is returned unchanged.
    pub fn make_good(&self) -> Result<GoodBiface<S>, BifaceError> {
        self.make_good_with_winding(None)
    }

    fn make_good_with_winding(&self, psi0: Option<f64>) -> Result<GoodBiface<S>, BifaceError> {
        let ladder = self.ladder_with_winding(psi0);
        match &ladder {
            Ladder::Translation { t } => {
                let a_minus_d = sub(&self.a, &self.d);
                let half = S::one().half();
                let m_star = (dot(&a_minus_d, t) / dot(t, t) + half).floor();
                let q = |m: &S| add(&self.d, &scale(m, t));
                let d = |m: &S| dist2(&self.a, &q(m));
                self.select(m_star, |_: &S| true, d)
            }
            Ladder::Rotation(r) => {
                let m_star = self.rotation_shortest(r)?;
                let valid = |m: &S| self.rotation_valid(r, exact_i64(m));
                let d = |m: &S| dist2(&self.a, &r.g.power(exact_i64(m)).apply(&self.d));
                self.select(S::from_i64(m_star), valid, d)
            }
        }
    }

    /// Given a shortest offset `m*`, the good biface with the tie rules of the module
    /// documentation.
    fn select(
        &self,
        m_star: S,
        valid: impl Fn(&S) -> bool,
        d: impl Fn(&S) -> S,
    ) -> Result<GoodBiface<S>, BifaceError> {
        let one = S::one();
        let plus = |m: &S, k: i64| m.clone() + S::from_i64(k);
        let d_min = d(&m_star);
        // Section 3's definition for rung offset j, given the shortest length.
        let good_at = |j: &S| {
            let (j1, j2, jm1) = (plus(j, 1), plus(j, 2), plus(j, -1));
            let (dj, dj1) = (d(j), d(&j1));
            (dj1 == d_min && (!valid(&j2) || dj <= d(&j2)))
                || (dj == d_min && (!valid(&jm1) || dj1 <= d(&jm1)))
        };
        let zero = S::zero();
        if good_at(&zero) {
            let shortest_offset = if d(&zero) == d_min { S::zero() } else { one };
            return Ok(GoodBiface {
                biface: self.clone(),
                rung_offset: zero,
                shortest_offset,
                shortest_length2: d_min,
                unchanged: true,
            });
        }
        let (next, prev) = (plus(&m_star, 1), plus(&m_star, -1));
        let (next_valid, prev_valid) = (valid(&next), valid(&prev));
        let j = if next_valid && d(&next) == d_min {
            m_star.clone()
        } else if prev_valid && d(&prev) == d_min {
            prev
        } else {
            match (prev_valid, next_valid) {
                (true, true) if d(&next) <= d(&prev) => m_star.clone(),
                (true, _) => prev,
                // The valid offsets form an interval containing 0 and 1, so m* has a valid
                // neighbour; without one this falls back to f = p₀q_{m*+1}.
                (false, _) => m_star.clone(),
            }
        };
        Ok(GoodBiface {
            biface: self.with_rung_offset(&j)?,
            rung_offset: j,
            shortest_offset: m_star,
            shortest_length2: d_min,
            unchanged: false,
        })
    }

    /// (i)–(iii) of docs/dubois.md §3.1(b) at offset `m` (|m| ≤ 2⁵²).
    fn rotation_valid(&self, r: &Rotation<S>, m: i64) -> bool {
        if m == 0 || m == 1 {
            return true;
        }
        let gm = r.g.power(m);
        let q = gm.apply(&self.d);
        let q_next = gm.apply(&self.b);
        let q_prev = gm.apply(&r.q_prev);
        strictly_inside_sweep(&self.a, &r.p_prev, &q, &self.c)
            && strictly_inside_sweep(&q, &q_next, &self.a, &q_prev)
            && self.winding_below_half_turn(r, m, &q)
    }

    /// (iii): `|ψ₀ + mθ| < π`, on doubles away from `±π`, by the exact side of `q_m` with respect
    /// to the line from `c` through `A` near it.
    fn winding_below_half_turn(&self, r: &Rotation<S>, m: i64, q: &Point<S>) -> bool {
        let alpha = r.psi0 + m as f64 * r.theta;
        let pi = std::f64::consts::PI;
        if alpha.abs() < pi - ANGLE_MARGIN {
            return true;
        }
        if alpha.abs() > pi + ANGLE_MARGIN {
            return false;
        }
        let side = orient(&r.centre, &self.a, q);
        if alpha > 0.0 {
            side == Ordering::Greater
        } else {
            side == Ordering::Less
        }
    }

    /// A shortest valid offset in the rotation case: the estimate `round(−ψ₀/θ)` (or, for f64
    /// bifaces with `|θ| < 10⁻⁹`, the translation quotient), clamped into the valid interval by
    /// bisection, then a descent on exact comparisons of squared lengths.
    fn rotation_shortest(&self, r: &Rotation<S>) -> Result<i64, BifaceError> {
        let estimate = if r.theta.abs() >= NEAR_TRANSLATION_THETA || (S::EXACT && r.theta != 0.0) {
            (-r.psi0 / r.theta).round()
        } else {
            let t = sub(&self.c, &self.a);
            let a_minus_d = sub(&self.a, &self.d);
            (dot(&a_minus_d, &t).to_f64() / dot(&t, &t).to_f64()).round()
        };
        if !estimate.is_finite() || estimate.abs() > MAX_ROTATION_OFFSET as f64 {
            return Err(BifaceError::OffsetOutOfRange { estimate });
        }
        let estimate = estimate as i64;
        let valid = |m: i64| m.abs() <= MAX_ROTATION_OFFSET && self.rotation_valid(r, m);
        let mut m = estimate;
        if !valid(m) {
            // Bisect between a valid anchor (0 or 1) and the invalid estimate.
            let (mut inside, mut outside) = if m > 1 { (1, m) } else { (0, m) };
            while (outside - inside).abs() > 1 {
                let mid = inside + (outside - inside) / 2;
                if valid(mid) {
                    inside = mid;
                } else {
                    outside = mid;
                }
            }
            m = inside;
        }
        let d = |m: i64| dist2(&self.a, &r.g.power(m).apply(&self.d));
        let start = m;
        let mut steps = 0u64;
        let mut here = d(m);
        for dir in [1i64, -1] {
            loop {
                let n = m + dir;
                if !valid(n) {
                    break;
                }
                let there = d(n);
                if there >= here {
                    break;
                }
                (m, here) = (n, there);
                steps += 1;
                if steps > MAX_DESCENT_STEPS {
                    return Err(BifaceError::DescentLimit { start });
                }
            }
        }
        Ok(m)
    }
}

/// The kernel on the ladder of any tube (docs/dubois.md §3.1(c), a *reconstruction* checked by
/// `tests/bifaces.rs`' random tubes): `a = p₀` and `c = p₁ = g(p₀)` are the ends of the `b₀`
/// boundary side (it runs `p₁ → p₀`), `d = q₀` a lift of `b₁` with `g(q₀)` the end of the `b₁`
/// side, all in one chart of the tube's universal cover, and `psi0` the angle `ψ₀` swept around
/// `g`'s centre from `p₀` to `q₀` along a path in that chart (ignored for translations). The
/// segment `p₀q₀` need not lie in the strip; the result, the chart `p₀, q_j, q_{j+1}, p₁`, is a
/// good biface of the tube's surface, with the same boundary sides.
pub fn good_biface_of_ladder<S: Scalar>(
    a: Point<S>,
    d: Point<S>,
    c: Point<S>,
    g: &Motion<S>,
    psi0: f64,
) -> Result<GoodBiface<S>, BifaceError> {
    let b = g.apply(&d);
    let ladder = Biface { a, d, b, c };
    let mut good = ladder.make_good_with_winding(Some(psi0))?;
    if good.unchanged {
        // Rung offset 0 is good here, but the chart was not checked to be a biface: rebuild it
        // as the kernel's output (the same corners).
        good.biface = ladder.with_rung_offset(&S::zero())?;
    }
    Ok(good)
}

/// Whether the direction `v − o` is strictly inside the angle swept counter-clockwise at `o`
/// from `u − o` to `w − o` (an angle in `(0, 2π)`): a polygon's interior angle at `o` with next
/// corner `u` and previous corner `w` ([`points_inside`], exact orientation tests).
fn strictly_inside_sweep<S: Scalar>(
    o: &Point<S>,
    u: &Point<S>,
    v: &Point<S>,
    w: &Point<S>,
) -> bool {
    points_inside(w, o, u, v)
}

/// An integer offset held in `S` as an `i64`, refusing `|m| > 2⁵²`.
fn offset_i64<S: Scalar>(m: &S) -> Result<i64, BifaceError> {
    let x = m.to_f64();
    if x.is_finite() && x.abs() <= MAX_ROTATION_OFFSET as f64 {
        Ok(x as i64)
    } else {
        Err(BifaceError::OffsetOutOfRange { estimate: x })
    }
}

/// An offset already known to be within `2⁵²` (built from an `i64`).
fn exact_i64<S: Scalar>(m: &S) -> i64 {
    m.to_f64() as i64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_square_cylinder_is_good_and_thick() {
        // Unit square cylinder: A=(1,0), D=(1,1), B=(0,1), C=(0,0); g is the translation by −1.
        let b = Biface::new([1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0], 1e-12).unwrap();
        assert!(b.is_translation());
        let good = b.make_good().unwrap();
        assert!(good.unchanged);
        assert_eq!(good.shortest_length2, 1.0);
        assert_eq!(b.kind().unwrap(), BifaceKind::Thick);
    }

    #[test]
    fn sweep_handles_reflex_and_half_turn_angles() {
        let o = [0.0, 0.0];
        let (e, n, w, s) = ([1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]);
        assert!(strictly_inside_sweep(&o, &e, &[1.0, 1.0], &n));
        assert!(!strictly_inside_sweep(&o, &e, &s, &n));
        assert!(strictly_inside_sweep(&o, &n, &s, &e)); // reflex: 270°
        assert!(strictly_inside_sweep(&o, &e, &n, &w)); // half-turn
        assert!(!strictly_inside_sweep(&o, &e, &s, &w));
        assert!(!strictly_inside_sweep(&o, &e, &e, &w));
    }

    #[test]
    fn bad_input_is_refused_with_the_reason() {
        let err = Biface::new([0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0], 1e-12);
        assert!(matches!(err, Err(BifaceError::NotCounterClockwise { .. })));
        let err = Biface::new([1.0, 0.0], [1.0, 2.0], [0.0, 1.0], [0.0, 0.0], 1e-12);
        assert!(matches!(err, Err(BifaceError::UnequalGluedSides { .. })));
        let err = Biface::new([f64::NAN, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0], 1e-12);
        assert!(matches!(err, Err(BifaceError::NonFinite { corner: 0 })));
    }
}
