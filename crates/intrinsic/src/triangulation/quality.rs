//! Aspect ratios and singular vertices (Dubois, Sections 2.1–2.2).
//!
//! - The **aspect ratio** of a triangular portalgon is the maximum side length of a triangle
//!   divided by the smallest height of a triangle, possibly another one (always `>= √3/2`).
//! - The **local aspect ratio** is the maximum over triangles of the triangle's longest side over
//!   its own smallest height (Lemma 1: `r_local <= r <= r_local^n` on a connected surface).
//! - A vertex is **singular** when the angles around it do not sum to 2π (closed surfaces have no
//!   boundary vertices). Numerically: `|Θ_v - 2π| > angle_tolerance` radians, with
//!   [`DEFAULT_ANGLE_TOLERANCE`] unless told otherwise.

use crate::geometry::Tolerances;
use crate::triangulation::IntrinsicTriangulation;
use serde::Serialize;
use std::f64::consts::TAU;
use surftopo_mesh::VertexId;

/// [`Tolerances::angle`]'s default, the absolute tolerance (radians) on `|Θ_v - 2π|` below which a
/// vertex is flat, as a constant for the callers that take one.
pub const DEFAULT_ANGLE_TOLERANCE: f64 = Tolerances::DEFAULT.angle;

/// Shape figures of an intrinsic triangulation.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Quality {
    /// Longest side over smallest height, over all triangles (Section 2.2).
    pub aspect_ratio: f64,
    /// Maximum over triangles of longest side over smallest height of the same triangle.
    pub local_aspect_ratio: f64,
    /// Longest side of all triangles.
    pub max_side: f64,
    /// Smallest height of all triangles (`2 · area / longest side`).
    pub min_height: f64,
    /// Total area.
    pub area: f64,
    /// Genus of the (closed orientable) surface.
    pub genus: i64,
    /// Vertices whose angle sum differs from 2π by more than the tolerance, increasing ids.
    pub singular_vertices: Vec<u32>,
    /// Number of flat (non-singular) vertices.
    pub flat_vertices: usize,
    /// Number of loop edges.
    pub loops: usize,
}

/// Measures `tri` (lengths assumed valid: see [`IntrinsicTriangulation::validate`]). O(n).
pub fn quality(tri: &IntrinsicTriangulation, angle_tolerance: f64) -> Quality {
    let mesh = tri.mesh();
    let (mut max_side, mut min_height, mut local, mut area) =
        (0.0f64, f64::INFINITY, 0.0f64, 0.0f64);
    for f in mesh.faces() {
        let sides = tri.face_sides(f);
        let longest = sides.iter().copied().fold(0.0, f64::max);
        let a = tri.face_area(f);
        let height = 2.0 * a / longest;
        max_side = max_side.max(longest);
        min_height = min_height.min(height);
        local = local.max(longest / height);
        area += a;
    }
    let sums = tri.angle_sums();
    let singular_vertices: Vec<u32> = mesh
        .vertices()
        .filter(|v| is_singular(sums[v.idx()], angle_tolerance))
        .map(|v| v.0)
        .collect();
    let loops = mesh
        .edges()
        .filter(|&e| {
            let [a, b] = mesh.edge_vertices(e);
            a == b
        })
        .count();
    Quality {
        aspect_ratio: max_side / min_height,
        local_aspect_ratio: local,
        max_side,
        min_height,
        area,
        genus: mesh.genus(),
        flat_vertices: mesh.vertex_count() - singular_vertices.len(),
        singular_vertices,
        loops,
    }
}

/// Whether an angle sum is singular: `|sum - 2π| > tolerance`.
#[inline]
pub fn is_singular(angle_sum: f64, tolerance: f64) -> bool {
    (angle_sum - TAU).abs() > tolerance
}

/// The flat vertices of `tri` (angle sum within `tolerance` of 2π), increasing ids.
pub fn flat_vertices(tri: &IntrinsicTriangulation, tolerance: f64) -> Vec<VertexId> {
    let sums = tri.angle_sums();
    tri.mesh()
        .vertices()
        .filter(|v| !is_singular(sums[v.idx()], tolerance))
        .collect()
}
