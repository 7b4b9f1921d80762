//! Intrinsic mollification (Sharp & Crane, "You can find geodesic paths in triangle meshes by just
//! flipping edges", ACM TOG 39(6), 2020, Section 4.5; also geometry-central's
//! `mollifyIntrinsic`).
//!
//! Adds the same small δ ≥ 0 to every edge length so that every triangle satisfies
//! `l_ij + l_jk - l_ki >= ε` for all three permutations, with `ε = epsilon · (mean edge length)`:
//! δ = max(0, max over corners of `ε - (l_ij + l_jk - l_ki)`). Adding a constant to all lengths
//! keeps the triangulation's combinatorics and changes the metric by the least uniform amount that
//! makes every triangle non-degenerate with margin ε. Zero-length edges become `δ > 0` long.

use crate::error::{DelaunayError, GeometryError};
use crate::triangulation::IntrinsicTriangulation;

/// The largest mollification ε accepted: a margin of one mean edge length. Beyond, δ would
/// dwarf the lengths (and at 1e308 overflow them): the metric would no longer be the input's.
pub const MAX_MOLLIFY: f64 = 1.0;

/// Mollifies the lengths in place; returns the δ added to every edge (0 when nothing was needed).
///
/// `epsilon` is relative to the mean edge length (Sharp & Crane use `1e-6`). O(F).
///
/// # Errors
/// [`DelaunayError::InvalidMollify`] unless `0 < epsilon <= MAX_MOLLIFY`;
/// [`GeometryError::NonFiniteLength`] for a non-finite or negative input length (mollification
/// cannot repair those); [`GeometryError::NonPositiveLength`] if every edge has length 0.
pub fn mollify(tri: &mut IntrinsicTriangulation, epsilon: f64) -> Result<f64, DelaunayError> {
    if !(epsilon.is_finite() && epsilon > 0.0 && epsilon <= MAX_MOLLIFY) {
        return Err(DelaunayError::InvalidMollify(epsilon));
    }
    let (mesh, lengths) = tri.parts_mut();
    let mut sum = 0.0;
    for e in mesh.edges() {
        let value = lengths[e.idx()];
        if !value.is_finite() || value < 0.0 {
            return Err(GeometryError::NonFiniteLength { edge: e.0, value }.into());
        }
        sum += value;
    }
    let mean = sum / mesh.edge_count().max(1) as f64;
    if mean <= 0.0 {
        let edge = mesh.edges().next().map_or(0, |e| e.0);
        return Err(GeometryError::NonPositiveLength { edge, value: 0.0 }.into());
    }
    let eps = epsilon * mean;
    let mut delta = 0.0f64;
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_halfedges(f).map(|h| lengths[h.edge().idx()]);
        for (x, y, z) in [(a, b, c), (b, c, a), (c, a, b)] {
            delta = delta.max(eps - (x + y - z));
        }
    }
    if delta > 0.0 {
        for e in mesh.edges() {
            lengths[e.idx()] += delta;
        }
    }
    Ok(delta)
}
