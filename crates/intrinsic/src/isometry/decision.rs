//! A three-way isometry verdict: isometric, not isometric, or undecidable in double precision.
//!
//! [`crate::isometric`] (Dubois, Corollary 2: equal canonical Delaunay tessellations) makes
//! threshold decisions in floating point: which vertices are flat (angle sum within a tolerance of
//! 2π), which triangles are co-circular, which lengths are equal. Near a threshold (a vertex with
//! angle defect 1e-10, a nearly co-circular quad, a nearly degenerate triangle) two triangulations
//! of one surface can fall on different sides of it, and the flat-vertex removal can get stuck
//! ([`crate::RemovalError::Stuck`]) on a valid surface. Such a "not isometric" or failure says
//! nothing about the surfaces. [`decide_isometry`] never reports it as an answer:
//!
//! 1. Robust certificates first: the same mesh with the same lengths bit for bit (a file against
//!    itself) is isometric by the identity; different Euler characteristics, or total areas
//!    differing by more than `1e-6` relative (each area is a sum of Kahan-accurate triangle
//!    areas), prove "not isometric" whatever the rounding.
//! 2. Two flat tori (genus 1, every vertex flat: the flat-vertex removal is most fragile there)
//!    are compared by their period lattices instead ([`crate::isometry::flat_torus_lattice`]): congruent
//!    within the length tolerance is "isometric", different by more than `1e-4` relative is
//!    "not isometric", in between "undecidable".
//! 3. Then the test with the given options. "Isometric" is the answer (a correspondence of the
//!    tessellations within the length tolerance was found).
//! 4. A "not isometric" is re-examined with every tolerance moved by a factor of 1000 (angle and
//!    co-circularity) or 100 (lengths) each way. If every variant still finds them different, the
//!    answer is "not isometric"; if any finds a correspondence, or gets stuck, the verdict is
//!    [`IsometryDecision::Undecidable`]: the surfaces are equal up to rounding-level differences
//!    that double precision cannot settle. It is also undecidable when a surface's intrinsic
//!    Delaunay triangulation has a triangle so thin (local aspect ratio r with `r · ε` above
//!    1/100 of the length tolerance) that the flips' rounding could exceed every tolerance tried
//!    (a vertex moved within 1e-12 of another); r is scale-free, so the verdict is too.
//! 5. A stuck removal or a numerical breakdown (no finding either way) is retried with the angle
//!    and co-circularity variants: a correspondence found by one (with the default length
//!    tolerance) is the answer "isometric"; otherwise the verdict is undecidable.
//!    (Exact arithmetic — the Dubois algorithm on exact input, where the input's lengths allow
//!    it — is the way to settle such cases.)
//!
//! Decision (the paper is silent on floating point): "undecidable" is preferred to a verdict that
//! depends on a tolerance; it is never given when the default test and all its variants agree.

use crate::error::{DelaunayError, IsometryError, RemovalError};
use crate::flip::flip_to_delaunay;
use crate::geometry::Tolerances;
use crate::isometry::flat_torus_lattice::flat_torus_invariants;
use crate::isometry::{IsometryOptions, Outcome, isometric};
use crate::triangulation::IntrinsicTriangulation;
use std::fmt;

/// The verdict of [`decide_isometry`].
#[derive(Clone, Debug, PartialEq)]
pub enum IsometryDecision {
    /// Isometric (the reason says how it was found: identity, period lattices, or the
    /// tessellations' correspondence).
    Isometric(String),
    /// Not isometric: by a robust certificate, or by the test under every tolerance variant.
    NotIsometric(String),
    /// Double precision cannot decide (the reason says which threshold was too close).
    Undecidable(String),
    /// The method cannot decide: a surface with boundary or without orientation has a flat
    /// vertex, which is kept, so its Delaunay tessellation is not canonical and a difference
    /// proves nothing ([`crate::decide_isometry_on_cover`]).
    Undecided(String),
}

impl IsometryDecision {
    /// Whether the verdict is [`IsometryDecision::Isometric`].
    pub fn is_isometric(&self) -> bool {
        matches!(self, IsometryDecision::Isometric(_))
    }
}

impl fmt::Display for IsometryDecision {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            IsometryDecision::Isometric(reason) => write!(f, "isometric: {reason}"),
            IsometryDecision::NotIsometric(reason) => write!(f, "not isometric: {reason}"),
            IsometryDecision::Undecidable(reason) => write!(
                f,
                "undecidable in double precision: {reason} (exact arithmetic on exact input would \
                 settle it)"
            ),
            IsometryDecision::Undecided(reason) => write!(f, "undecided: {reason}"),
        }
    }
}

/// Whether two closed surfaces are isometric, or that double precision cannot tell (see the
/// module doc). Costs one [`isometric`] call, up to six more when the first does not find a
/// correspondence and no certificate settles it.
///
/// # Errors
/// As [`isometric`] for unusable input (non-positive or non-finite lengths, violated triangle
/// inequalities, a flip budget exceeded); a stuck removal or a numerical breakdown is
/// [`IsometryDecision::Undecidable`] instead.
pub fn decide_isometry(
    a: &IntrinsicTriangulation,
    b: &IntrinsicTriangulation,
    options: &IsometryOptions,
) -> Result<IsometryDecision, IsometryError> {
    if a.mesh() == b.mesh() && a.lengths() == b.lengths() {
        return Ok(IsometryDecision::Isometric(
            "the same triangulation with the same lengths".into(),
        ));
    }
    let (chi_a, chi_b) = (
        a.mesh().euler_characteristic(),
        b.mesh().euler_characteristic(),
    );
    if chi_a != chi_b {
        return Ok(IsometryDecision::NotIsometric(format!(
            "Euler characteristics {chi_a} and {chi_b} differ"
        )));
    }
    let (area_a, area_b) = (a.total_area(), b.total_area());
    if (area_a - area_b).abs() > Tolerances::DEFAULT.area_certificate * area_a.max(area_b) {
        return Ok(IsometryDecision::NotIsometric(format!(
            "total areas {area_a} and {area_b} differ"
        )));
    }
    if let Some(decision) = compare_flat_tori(a, b, options) {
        return Ok(decision);
    }
    let first = match attempt(a, b, options)? {
        Attempt::Isometric(outcome) => return Ok(isometric_by(&outcome)),
        Attempt::Different(outcome) => outcome,
        Attempt::Unsettled(reason) => return retry_unsettled(a, b, options, reason),
    };
    for (what, variant) in variants(options) {
        match attempt(a, b, &variant)? {
            Attempt::Different(_) => {}
            Attempt::Isometric(_) => {
                return Ok(IsometryDecision::Undecidable(format!(
                    "the tessellations differ with the default tolerances ({}) but match \
                     with {what}",
                    first.reason()
                )));
            }
            Attempt::Unsettled(reason) => {
                return Ok(IsometryDecision::Undecidable(format!(
                    "the tessellations differ with the default tolerances ({}); with {what}: \
                     {reason}",
                    first.reason()
                )));
            }
        }
    }
    if let Some(reason) = ill_conditioned(a, b, options)? {
        return Ok(IsometryDecision::Undecidable(format!(
            "the tessellations differ under every tolerance ({}), but {reason}",
            first.reason()
        )));
    }
    Ok(IsometryDecision::NotIsometric(first.reason()))
}

/// How much rounding a flip may amplify, at most, for the tessellations' differences to be a
/// proof: [`ill_conditioned`] asks `aspect ratio · f64::EPSILON <= length tolerance ·`
/// this (the smallest length tolerance the variants of step 4 try).
const CONDITION_MARGIN: f64 = 1e-2;

/// Why a difference of the tessellations proves nothing, if it does not: the intrinsic Delaunay
/// triangulation of a surface has a triangle of local aspect ratio r (longest side over its
/// smallest height) with `r · f64::EPSILON` above the smallest length tolerance tried. A flip in
/// such a triangle computes its new diagonal with a relative error up to about `r · ε`, so the
/// two triangulations' lengths can differ by more than the tolerance although the surfaces are
/// the same (a vertex moved within 1e-12 of another: r ≈ 1e12). The ratio does not depend on
/// the scale, so neither does the verdict.
fn ill_conditioned(
    a: &IntrinsicTriangulation,
    b: &IntrinsicTriangulation,
    options: &IsometryOptions,
) -> Result<Option<String>, IsometryError> {
    let limit = options.length_tolerance * CONDITION_MARGIN / f64::EPSILON;
    for (surface, tri) in [a, b].into_iter().enumerate() {
        let mut flipped = tri.clone();
        match flip_to_delaunay(&mut flipped, &options.delaunay) {
            Ok(_) => {}
            Err(e @ DelaunayError::NumericalBreakdown { .. }) => {
                return Ok(Some(format!("flipping surface {surface} broke down: {e}")));
            }
            Err(source) => return Err(IsometryError::Delaunay { surface, source }),
        }
        let (ratio, face) = flipped
            .mesh()
            .faces()
            .map(|f| {
                let longest = flipped.face_sides(f).into_iter().fold(0.0, f64::max);
                (longest * longest / (2.0 * flipped.face_area(f)), f.0)
            })
            .fold((0.0f64, 0), |m, x| if x.0 > m.0 { x } else { m });
        if ratio > limit || ratio.is_nan() {
            return Ok(Some(format!(
                "face {face} of the Delaunay triangulation of surface {surface} has aspect \
                 ratio {ratio:e} (longest side over height), so rounding in its flips can exceed \
                 the length tolerance"
            )));
        }
    }
    Ok(None)
}

/// After a stuck removal or a breakdown with the default options (no finding either way): the
/// angle and co-circularity variants, which move the flat and co-circular decisions away from the
/// values that got stuck; the first that finds a correspondence (with the default length
/// tolerance) is the answer, otherwise the verdict is undecidable.
fn retry_unsettled(
    a: &IntrinsicTriangulation,
    b: &IntrinsicTriangulation,
    options: &IsometryOptions,
    reason: String,
) -> Result<IsometryDecision, IsometryError> {
    for (_, variant) in variants(options) {
        if variant.length_tolerance != options.length_tolerance {
            continue;
        }
        if let Attempt::Isometric(outcome) = attempt(a, b, &variant)? {
            return Ok(isometric_by(&outcome));
        }
    }
    Ok(IsometryDecision::Undecidable(reason))
}

/// The verdict of a correspondence found by [`isometric`].
fn isometric_by(outcome: &Outcome) -> IsometryDecision {
    IsometryDecision::Isometric(outcome.reason())
}

/// Relative difference of the lattice invariants beyond which two flat tori are certainly not
/// congruent (far above the development's rounding).
const LATTICE_CERTIFICATE: f64 = 1e-4;

/// Two flat tori (genus 1, all vertices flat) compared by their period lattices
/// ([`flat_torus_invariants`]): congruent within the length tolerance is isometric, different by
/// more than [`LATTICE_CERTIFICATE`] is not, in between undecidable. `None` unless both are flat
/// tori whose lattices could be read.
fn compare_flat_tori(
    a: &IntrinsicTriangulation,
    b: &IntrinsicTriangulation,
    options: &IsometryOptions,
) -> Option<IsometryDecision> {
    let la = flat_torus_invariants(a, options.angle_tolerance)?;
    let lb = flat_torus_invariants(b, options.angle_tolerance)?;
    let scale = la[1].max(lb[1]);
    let difference = ((la[0] - lb[0]).abs() / scale)
        .max((la[1] - lb[1]).abs() / scale)
        .max((la[2] - lb[2]).abs() / (scale * scale));
    let shown = |l: [f64; 3]| format!("|b1| {}, |b2| {}, |b1·b2| {}", l[0], l[1], l[2]);
    Some(if difference <= options.length_tolerance {
        IsometryDecision::Isometric(format!(
            "flat tori with congruent period lattices ({})",
            shown(la)
        ))
    } else if difference > LATTICE_CERTIFICATE {
        IsometryDecision::NotIsometric(format!(
            "flat tori with different period lattices ({} vs {})",
            shown(la),
            shown(lb)
        ))
    } else {
        IsometryDecision::Undecidable(format!(
            "flat tori whose period lattices differ by {difference:e} relative ({} vs {})",
            shown(la),
            shown(lb)
        ))
    })
}

/// One run of the test.
enum Attempt {
    Isometric(Outcome),
    Different(Outcome),
    /// A failure of the method, not of the input.
    Unsettled(String),
}

fn attempt(
    a: &IntrinsicTriangulation,
    b: &IntrinsicTriangulation,
    options: &IsometryOptions,
) -> Result<Attempt, IsometryError> {
    match isometric(a.clone(), b.clone(), options) {
        Ok(outcome) if outcome.is_isometric() => Ok(Attempt::Isometric(outcome)),
        Ok(outcome) => Ok(Attempt::Different(outcome)),
        Err(e) if is_precision_failure(&e) => Ok(Attempt::Unsettled(e.to_string())),
        Err(e) => Err(e),
    }
}

/// Whether an error of [`isometric`] comes from rounding rather than from the input.
fn is_precision_failure(e: &IsometryError) -> bool {
    match e {
        IsometryError::Removal { source, .. } => matches!(
            source,
            RemovalError::Stuck { .. }
                | RemovalError::Delaunay(DelaunayError::NumericalBreakdown { .. })
        ),
        IsometryError::Delaunay { source, .. } => {
            matches!(source, DelaunayError::NumericalBreakdown { .. })
        }
        IsometryError::Portalgon { .. } => true,
    }
}

/// The tolerance variants of steps 4 and 5, each with a description.
fn variants(options: &IsometryOptions) -> Vec<(String, IsometryOptions)> {
    type Field = fn(&mut IsometryOptions) -> &mut f64;
    let fields: [(&str, Field, [f64; 2]); 3] = [
        ("angle", |o| &mut o.angle_tolerance, [1e3, 1e-3]),
        (
            "co-circularity",
            |o| &mut o.cocircular_tolerance,
            [1e3, 1e-3],
        ),
        ("length", |o| &mut o.length_tolerance, [1e2, 1e-2]),
    ];
    let mut out = Vec::new();
    for (name, field, factors) in fields {
        for factor in factors {
            let mut variant = *options;
            *field(&mut variant) *= factor;
            let value = *field(&mut variant);
            out.push((format!("{name} tolerance {value:e}"), variant));
        }
    }
    out
}
