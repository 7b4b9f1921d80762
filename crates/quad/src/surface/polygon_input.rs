//! `quad` on a polygon input as the CLI and the Python package run it: a quad-only input gives
//! back its own quads.
//!
//! The surface is built from the polygons cut into triangles (`surftopo_mesh::triangulate_polygons`:
//! a quad is cut into two triangles, face ids `2k` and `2k + 1` for quad `k`). Karp–Sipser's
//! first step pairs triangles written two by two as quads in file order
//! (`surftopo_matching::KarpSipserStats::file_order`); when every face is a quad and that step
//! pairs every quad's two triangles back, the quads are the input's own (ours, no paper: the
//! quad mesh of a quad mesh is itself). Otherwise the quads of the pairing asked for.

use surftopo_mesh::{ClosedCover, CoveredSurface, FaceId, SurfaceKind};

use super::{SurfaceOptions, SurfaceQualityQuads};
use crate::quality::QualityObjective;
use crate::{QuadAlgorithm, QuadError};

/// What became of a quad-only input.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum OwnQuads {
    /// Not every face is a quad: the quads are the pairing's.
    NotQuadOnly,
    /// Every face is a quad and Karp–Sipser paired each one's triangles back: the input's own
    /// quads (input vertex indices), each as listed or reversed as the surface's cover orients
    /// it (building reorients faces against the majority of their piece).
    Kept(Vec<[u32; 4]>),
    /// Every face is a quad, but the triangles cut from them did not pair back in file order:
    /// the quads are Karp–Sipser's.
    NotPairedBack,
}

/// A polygon input's quadrangulation: the pairing's quads and figures, and what became of a
/// quad-only input.
#[derive(Clone, Debug)]
pub struct PolygonQuads {
    /// The quadrangulation of the triangles (Karp–Sipser's, objective `count`, on a quad-only
    /// input).
    pub quads: SurfaceQualityQuads,
    /// The input's own quads, when kept.
    pub own: OwnQuads,
}

impl PolygonQuads {
    /// The objective the figures are of: `count` on a quad-only input, else `objective`.
    pub fn objective_name<'a>(&self, objective: &'a str) -> &'a str {
        match self.own {
            OwnQuads::NotQuadOnly => objective,
            OwnQuads::Kept(_) | OwnQuads::NotPairedBack => "count",
        }
    }
}

/// Quadrangulates the surface built from `faces` (cut into triangles by
/// `surftopo_mesh::triangulate_polygons_as_surface`; `input_vertices` the input index of each
/// surface vertex id, `surftopo_mesh::BuildReport::input_vertices`) by `algorithm` and
/// `objective` (`None`: any maximum pairing; with `all_quads`, the triangles left turned into
/// quads), as the module doc says for a quad-only input (`algorithm` and `objective` then do not
/// apply).
///
/// # Errors
/// Those of [`super::quadrangulate_surface_with_quality`] and
/// [`super::quadrangulate_surface_by_quality`].
pub fn quadrangulate_polygons<'a>(
    surface: &CoveredSurface,
    pieces: &[SurfaceKind],
    faces: impl IntoIterator<Item = &'a [u32]>,
    input_vertices: &[u32],
    algorithm: QuadAlgorithm,
    objective: Option<QualityObjective>,
    all_quads: bool,
) -> Result<PolygonQuads, QuadError> {
    let faces: Vec<&[u32]> = faces.into_iter().collect();
    let own = quads_of_quad_input(&surface.cover, &faces, input_vertices);
    let (algorithm, objective) = match own {
        Some(_) => (QuadAlgorithm::KarpSipser, None),
        None => (algorithm, objective),
    };
    let quads = match objective {
        None => {
            let options = SurfaceOptions {
                all_quads,
                ..SurfaceOptions::default()
            };
            super::quadrangulate_surface_with_quality(surface, pieces, algorithm, &options)
        }
        Some(quality) => {
            super::quadrangulate_surface_by_quality(surface, pieces, quality, all_quads)
        }
    }?;
    let own = match own {
        None => OwnQuads::NotQuadOnly,
        Some(own) if quads.result.stats.file_order => OwnQuads::Kept(own),
        Some(_) => OwnQuads::NotPairedBack,
    };
    Ok(PolygonQuads { quads, own })
}

/// The input's own quads when every face is a quad (surface face ids `2k`, `2k + 1` the two
/// triangles of quad `k`), each as listed or reversed as the cover orients its first triangle.
fn quads_of_quad_input(
    cover: &ClosedCover,
    faces: &[&[u32]],
    input_vertices: &[u32],
) -> Option<Vec<[u32; 4]>> {
    if faces.is_empty() || faces.iter().any(|f| f.len() != 4) {
        return None;
    }
    let quads = faces.iter().enumerate().map(|(k, f)| {
        let quad = [f[0], f[1], f[2], f[3]];
        // The quad's first triangle as the cover orients it: its corners run forward around
        // the quad or backward.
        let corners = cover.mesh.face_vertices(FaceId(2 * k as u32)).map(|v| {
            quad.iter()
                .position(|&q| q == input_vertices[cover.class(v) as usize])
                .unwrap_or(0)
        });
        let steps: usize = (0..3)
            .map(|i| (corners[(i + 1) % 3] + 4 - corners[i]) % 4)
            .sum();
        if steps == 4 {
            quad
        } else {
            [quad[0], quad[3], quad[2], quad[1]]
        }
    });
    Some(quads.collect())
}
