//! The needle test of `--method auto` ([`crate::choose_method`]), beside flipping, which runs it on
//! the half-angle cache of its first pass ([`super::flip_to_delaunay_unless_needle`]): a needle
//! is a triangle whose aspect ratio `ℓ²/(2A)` exceeds [`AUTO_ASPECT_LIMIT`].

use crate::triangulation::IntrinsicTriangulation;

/// Above this largest triangle aspect ratio `ℓ²/(2A)`, `--method auto` leaves flipping
/// ([`crate::choose_method`]'s module gives the measurement behind it).
pub const AUTO_ASPECT_LIMIT: f64 = 1e5;

/// Whether the triangle of sides `a, b, c` has aspect ratio `ℓ²/(2A)` above
/// [`AUTO_ASPECT_LIMIT`] (a degenerate one counts): `4ℓ⁴ > K²·16A²` with Heron's
/// `16A² = (a+b+c)(−a+b+c)(a−b+c)(a+b−c)`, no square root.
pub(crate) fn is_needle(a: f64, b: f64, c: f64) -> bool {
    let longest = a.max(b).max(c);
    let sixteen_area2 = (a + b + c) * (-a + b + c) * (a - b + c) * (a + b - c);
    let l4 = longest * longest * longest * longest;
    // NaN (overflowing lengths) counts as a needle, like a degenerate triangle.
    (4.0 * l4)
        .partial_cmp(&(AUTO_ASPECT_LIMIT * AUTO_ASPECT_LIMIT * sixteen_area2))
        .is_none_or(|o| o == std::cmp::Ordering::Greater)
}

/// Below this `tan²(θ/2)` an angle may belong to a needle: the aspect ratio is
/// `sin α/(sin β sin γ) ≤ 2/sin γ` (`γ` the smallest angle), so a needle (aspect above
/// `K` = [`AUTO_ASPECT_LIMIT`]) has `tan²(γ/2) < 1/K²` up to rounding; `4/K²` leaves a margin.
const SURELY_NOT_NEEDLE_TAN_HALF_SQ: f64 = 4.0 / (AUTO_ASPECT_LIMIT * AUTO_ASPECT_LIMIT);

/// Whether some face of `tri` is a needle ([`is_needle`]), given `tan²` of the half angle opposite
/// every half-edge (flipping's cache after its first pass, by half-edge id, `NaN` in unused
/// slots): one scan of the cache, and [`is_needle`] only on the faces of the angles below
/// [`SURELY_NOT_NEEDLE_TAN_HALF_SQ`] (thin triangles that are no needle are not rare: a full
/// pass over the faces would cost as much as the scan again). Same answer as testing every face.
pub(crate) fn has_needle_given_half_angles(
    tri: &IntrinsicTriangulation,
    tan_half_sq: &[f64],
) -> bool {
    let faces = tri.mesh().halfedge_faces();
    tan_half_sq
        .iter()
        .zip(faces)
        .filter(|(t, _)| **t < SURELY_NOT_NEEDLE_TAN_HALF_SQ)
        .any(|(_, &f)| {
            let [a, b, c] = tri.face_sides(f);
            is_needle(a, b, c)
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::triangulation::trig::tan_half_sq_all;

    /// The bound behind the half-angle shortcut: no triangle with every `tan²(θ/2)` at least
    /// [`SURELY_NOT_NEEDLE_TAN_HALF_SQ`] is a needle, on triangles of every shape (aspect ratios
    /// 1 to 1e9 on both sides of the limit, needles with a short side, flat caps with an angle
    /// near π).
    #[test]
    fn no_needle_has_only_wide_half_angles() {
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut uniform = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut needles = [0, 0];
        for _ in 0..200_000 {
            // Apex at (x, h) over the base (0, 0)–(1, 0): h spans aspect ratios 1 to 1e9.
            let x = 3.0 * uniform() - 1.0;
            let h = 10f64.powf(-9.0 * uniform());
            let sides = [
                1.0,
                (x * x + h * h).sqrt(),
                ((1.0 - x) * (1.0 - x) + h * h).sqrt(),
            ];
            for k in 0..3 {
                let s = [sides[k], sides[(k + 1) % 3], sides[(k + 2) % 3]];
                let (half, _) = tan_half_sq_all(s);
                let wide = half.iter().all(|&t| t >= SURELY_NOT_NEEDLE_TAN_HALF_SQ);
                let needle = is_needle(s[0], s[1], s[2]);
                assert!(!(wide && needle), "{s:?}: {half:?}");
                needles[usize::from(needle)] += 1;
            }
        }
        assert!(needles[0] > 10_000 && needles[1] > 10_000, "{needles:?}");
    }
}
