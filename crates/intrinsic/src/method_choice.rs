//! The automatic choice of the Delaunay method (`--method auto`): flipping where it is safe and
//! fast, Dubois' Theorem 1 where flipping would take too many flips or lose precision.
//!
//! **The rule** ([`choose_method`]), read off one O(n) pass over the triangles:
//! - Let `a` be the largest triangle aspect ratio `ℓ²/(2A)` (longest side over the height on it;
//!   `A` the area). Flipping a needle of aspect `a` takes about `√(2a)` flips (Section 9's `T_x`:
//!   aspect `(x² + 4)/2`, `x − 1` flips) and, in double precision, loses about `log₁₀ a` digits.
//!   `results/papers/intrinsic.md` measures the flip route on `T_x`: lengths right to 2e-9 up to
//!   `x = 10³` (aspect 5·10⁵), wrong from `x = 3·10³` (aspect 4.5·10⁶). [`AUTO_ASPECT_LIMIT`]
//!   = 10⁵ leaves a margin of 45 below the first failure.
//! - Aspect at most the limit: [`Method::Flip`] (on the shared meshes flipping is the fastest
//!   method, and this pass is all `auto` adds to it).
//! - Above the limit, no cone point: [`Method::Dubois`] (Theorem 1: time polylogarithmic in the
//!   aspect ratio, exact in exact mode).
//! - Above the limit with a cone point: [`Method::Dubois`] when [`DUBOIS_TAKES_CONE_POINTS`]
//!   (Section 8's caps are built), otherwise [`Method::Flip`] — the wave alone on a raw needle
//!   does as much work as flipping (its constellations grow like the flip count), so it is no
//!   better a fallback.
//!
//! Decision where the issue is silent: the rule looks at the input only (no flip budget that
//! restarts another method half-way), so that the method, hence the output bytes, depends on
//! the input alone.

use crate::geometry::Scalar;
use crate::portalgon::Portalgon;
use crate::quality::DEFAULT_ANGLE_TOLERANCE;
use crate::triangulation::IntrinsicTriangulation;

/// The Delaunay methods [`choose_method`] chooses between.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Edge flipping (Bobenko–Springborn).
    Flip,
    /// The multi-source Voronoi wave and its dual (Dubois, Appendix D).
    Voronoi,
    /// Dubois' Theorem 1: the happiness reduction, then the wave.
    Dubois,
}

/// Above this largest triangle aspect ratio `ℓ²/(2A)`, [`choose_method`] leaves flipping (see the
/// module doc for the measurement behind it).
pub const AUTO_ASPECT_LIMIT: f64 = 1e5;

/// Whether [`crate::dubois`] takes surfaces with cone points (Section 8's caps). While it does
/// not, [`choose_method`] keeps flipping for them.
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

/// The rule of the module doc on its two inputs: the largest aspect ratio, and whether the
/// surface has no cone point (asked only above [`AUTO_ASPECT_LIMIT`]).
pub fn method_for(largest_aspect: f64, flat: impl FnOnce() -> bool) -> Method {
    if largest_aspect <= AUTO_ASPECT_LIMIT {
        return Method::Flip;
    }
    if DUBOIS_TAKES_CONE_POINTS || flat() {
        Method::Dubois
    } else {
        Method::Flip
    }
}

/// `--method auto` on a portalgon (see the module doc): [`method_for`] its
/// [`largest_aspect_ratio`] and whether it has a cone point (decided with the default angle
/// tolerance in `f64`, exactly in exact mode). O(n).
pub fn choose_method<S: Scalar>(p: &Portalgon<S>) -> Method {
    method_for(largest_aspect_ratio(p), || {
        crate::dubois::first_cone_point(p, DEFAULT_ANGLE_TOLERANCE).is_none()
    })
}

/// `--method auto` on an intrinsic triangulation: the aspect ratios from its edge lengths
/// (`ℓ²/(2A)`, Heron's area), flatness from its angle sums (within the default angle
/// tolerance); no portalgon is built unless needed. O(n).
pub fn choose_method_for_triangulation(tri: &IntrinsicTriangulation) -> Method {
    let largest = tri
        .mesh()
        .faces()
        .map(|f| {
            let longest = tri.face_sides(f).into_iter().fold(0.0, f64::max);
            let area = tri.face_area(f);
            if area > 0.0 {
                longest * longest / (2.0 * area)
            } else {
                f64::INFINITY
            }
        })
        .fold(0.0, f64::max);
    method_for(largest, || {
        tri.angle_sums()
            .iter()
            .all(|a| (a - std::f64::consts::TAU).abs() <= DEFAULT_ANGLE_TOLERANCE)
    })
}
