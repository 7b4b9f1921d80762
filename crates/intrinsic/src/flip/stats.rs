//! The figures of one Delaunay run, for the CLI's `--json` and the benchmark.

use crate::error::DelaunayError;
use crate::flip::{DelaunayOptions, FlipReport, flip_to_delaunay};
use crate::triangulation::IntrinsicTriangulation;
use serde::Serialize;
use std::time::Instant;

/// Figures of a Delaunay run. Serialises to JSON with at least the keys `vertices`, `edges`,
/// `faces`, `flips`, `non_delaunay_edges`, `seconds` (in that order).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DelaunayStats {
    /// Vertices of the triangulation.
    pub vertices: usize,
    /// Edges.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// Flips made.
    pub flips: u64,
    /// Edges not Delaunay at the end (0 on success).
    pub non_delaunay_edges: usize,
    /// Wall-clock seconds of the flipping (including validation and mollification).
    pub seconds: f64,
    /// δ added to every length by mollification, if asked.
    pub mollify_delta: Option<f64>,
    /// Loop edges in the result.
    pub loops: usize,
    /// Edges sharing both endpoints with another edge, in the result.
    pub multi_edges: usize,
}

impl DelaunayStats {
    /// The figures of `tri` after a run that made `report` in `seconds`.
    pub fn new(tri: &IntrinsicTriangulation, report: &FlipReport, seconds: f64) -> Self {
        let mesh = tri.mesh();
        let pairs: Vec<(u32, u32)> = mesh
            .edges()
            .map(|e| {
                let [a, b] = mesh.edge_vertices(e);
                (a.0.min(b.0), a.0.max(b.0))
            })
            .collect();
        let counts = [mesh.vertex_count(), mesh.edge_count(), mesh.face_count()];
        Self::from_pairs(counts, pairs, report, seconds)
    }

    /// The figures from the vertex, edge and face counts and the edges' end pairs.
    pub(crate) fn from_pairs(
        [vertices, edges, faces]: [usize; 3],
        mut pairs: Vec<(u32, u32)>,
        report: &FlipReport,
        seconds: f64,
    ) -> Self {
        let loops = pairs.iter().filter(|(a, b)| a == b).count();
        pairs.sort_unstable();
        let multi_edges = pairs
            .chunk_by(|x, y| x == y)
            .filter(|run| run.len() > 1)
            .map(<[_]>::len)
            .sum();
        Self {
            vertices,
            edges,
            faces,
            flips: report.flips,
            non_delaunay_edges: report.non_delaunay_edges,
            seconds,
            mollify_delta: report.mollify_delta,
            loops,
            multi_edges,
        }
    }
}

/// Runs [`flip_to_delaunay`] and times it.
///
/// # Errors
/// As [`flip_to_delaunay`].
pub fn delaunay_with_stats(
    tri: &mut IntrinsicTriangulation,
    options: &DelaunayOptions,
) -> Result<DelaunayStats, DelaunayError> {
    let start = Instant::now();
    let report = flip_to_delaunay(tri, options)?;
    let seconds = start.elapsed().as_secs_f64();
    Ok(DelaunayStats::new(tri, &report, seconds))
}
