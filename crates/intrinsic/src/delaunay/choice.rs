//! The automatic choice of the Delaunay method ([`DelaunayMethod::Auto`], `--method auto`): flipping where it is safe and
//! fast, Dubois' Theorem 1 where flipping would take too many flips or lose precision.
//!
//! **The rule** ([`choose_method`]), read off one O(n) pass over the triangles:
//! - Let `a` be the largest triangle aspect ratio `ℓ²/(2A)` (longest side over the height on it;
//!   `A` the area). Flipping a needle of aspect `a` takes about `√(2a)` flips (Section 9's `T_x`:
//!   aspect `(x² + 4)/2`, `x − 1` flips) and, in double precision, loses about `log₁₀ a` digits.
//!   `results/papers/intrinsic.md` measures the flip route on `T_x`: lengths right to 2e-9 up to
//!   `x = 10³` (aspect 5·10⁵), wrong from `x = 3·10³` (aspect 4.5·10⁶). [`crate::AUTO_ASPECT_LIMIT`]
//!   = 10⁵ leaves a margin of 45 below the first failure.
//! - Aspect at most the limit: [`DelaunayMethod::Flip`] (on the shared meshes flipping is the fastest
//!   method). [`super::intrinsic_delaunay`] runs the test on the half-angle cache flipping's first pass fills
//!   ([`crate::flip::flip_to_delaunay_unless_needle`], leaving before any flip when there
//!   is a needle), so on the inputs it flips `auto` adds nothing but the test itself.
//! - Above the limit, no cone point: [`DelaunayMethod::Dubois`] (Theorem 1: time polylogarithmic in the
//!   aspect ratio, exact in exact mode).
//! - Above the limit with a cone point: [`DelaunayMethod::Dubois`] when [`DUBOIS_TAKES_CONE_POINTS`]
//!   (Section 8's caps are built), otherwise [`DelaunayMethod::Flip`] — the wave alone on a raw needle
//!   does as much work as flipping (its constellations grow like the flip count), so it is no
//!   better a fallback.
//!
//! Decision where the issue is silent: the rule looks at the input only (no flip budget that
//! restarts another method half-way), so that the method, hence the output bytes, depends on
//! the input alone.

use super::DelaunayMethod;
use crate::flip::needle::{AUTO_ASPECT_LIMIT, is_needle};
use crate::geometry::{Scalar, Tolerances};
use crate::portalgon::Portalgon;
use crate::triangulation::IntrinsicTriangulation;

/// Whether [`choose_method`] sends needles with cone points to [`crate::dubois`]. Section 8's
/// caps run in both arithmetics ([`crate::dubois::delaunay_tessellation_dubois`]), but on meshes
/// they cost orders of magnitude more than flipping (every vertex capped, `T₁` ten times the
/// input's triangles, ALGORITHM's passes over all of it) and in `f64` not every shared mesh
/// finishes in reasonable time (`tests/caps.rs`' release sweep; `results/dubois_bench.md`), so
/// `auto` keeps flipping them: `false`.
pub const DUBOIS_TAKES_CONE_POINTS: bool = false;

/// The largest triangle aspect ratio `ℓ²/(2A)` of the polygons (longest side `ℓ`, area `A`; for
/// a polygon that is not a triangle the same formula), as a double; infinite for a polygon of
/// zero area. O(n).
pub fn largest_aspect_ratio<S: Scalar>(p: &Portalgon<S>) -> f64 {
    p.polygons()
        .map(|q| {
            let longest2 = p
                .polygon_sides(q)
                .iter()
                .map(|&s| p.side_length2(s).to_f64())
                .fold(0.0, f64::max);
            let area = p.polygon_area(q).to_f64();
            if area > 0.0 {
                longest2 / (2.0 * area)
            } else {
                f64::INFINITY
            }
        })
        .fold(0.0, f64::max)
}

/// The rule of the module doc on its two inputs: whether some triangle's aspect ratio exceeds
/// [`crate::AUTO_ASPECT_LIMIT`], and whether the surface has no cone point (asked only for a needle).
pub(crate) fn method_for(needle: bool, flat: impl FnOnce() -> bool) -> DelaunayMethod {
    if !needle {
        return DelaunayMethod::Flip;
    }
    if DUBOIS_TAKES_CONE_POINTS || flat() {
        DelaunayMethod::Dubois
    } else {
        DelaunayMethod::Flip
    }
}

/// `--method auto` on a portalgon (see the module doc): [`method_for`] on its
/// [`largest_aspect_ratio`] and whether it has a cone point (decided with the default angle
/// tolerance in `f64`, exactly in exact mode). O(n).
pub fn choose_method<S: Scalar>(p: &Portalgon<S>) -> DelaunayMethod {
    method_for(largest_aspect_ratio(p) > AUTO_ASPECT_LIMIT, || {
        crate::dubois::first_cone_point(p, Tolerances::DEFAULT.angle).is_none()
    })
}

/// `--method auto` on an intrinsic triangulation: the needle test from its edge lengths (stopping
/// at the first needle), and only then flatness from its angle sums (within the default angle
/// tolerance, stopping at the first cone point). At most one pass over the faces and one over
/// the corners.
pub fn choose_method_for_triangulation(tri: &IntrinsicTriangulation) -> DelaunayMethod {
    let needle = tri.mesh().faces().any(|f| {
        let [a, b, c] = tri.face_sides(f);
        is_needle(a, b, c)
    });
    method_for(needle, || is_flat(tri))
}

/// [`method_for`] a triangulation known to have a needle (e.g. from
/// [`crate::flip::flip_to_delaunay_unless_needle`]): flatness decided from its angle sums as
/// in [`choose_method_for_triangulation`].
pub(crate) fn choose_method_for_needle(tri: &IntrinsicTriangulation) -> DelaunayMethod {
    method_for(true, || is_flat(tri))
}

/// Whether every vertex's angle sum is 2π within the default angle tolerance (stopping at the
/// first cone point).
fn is_flat(tri: &IntrinsicTriangulation) -> bool {
    tri.mesh()
        .vertices()
        .all(|v| (tri.angle_sum(v) - std::f64::consts::TAU).abs() <= Tolerances::DEFAULT.angle)
}
