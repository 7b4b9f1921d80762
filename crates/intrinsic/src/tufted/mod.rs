//! The Laplacian of a non-manifold triangle mesh or a triangle soup through its tufted cover:
//! N. Sharp and K. Crane, "A Laplacian for Nonmanifold Triangle Meshes", Computer Graphics Forum
//! 39(5) (SGP 2020), Section 4.
//!
//! The pipeline is the paper's:
//! 1. **Mollification** (Section 4.5): with `δ = mollify_factor × (mean length of the input's
//!    distinct edges)`, every edge is lengthened by the least `ε ≥ 0` that makes every triangle
//!    satisfy the strict triangle inequality with margin δ (`l_ij + l_jk - l_ki >= δ` at every
//!    corner). A factor of 0 skips it; degenerate triangles are then an error naming the face.
//! 2. **The tufted cover** (Section 4.2, [`cover`]): two sides per face, glued around each edge
//!    in the faces' cyclic order in space; a closed oriented surface (several pieces for several
//!    pieces of input), pinched vertices split into one cover vertex per fan.
//! 3. **Intrinsic Delaunay flipping** of the cover ([`crate::flip_to_delaunay`]; Section 4.3).
//! 4. **The cotan Laplacian and lumped (barycentric) mass matrix of the cover, folded** to the
//!    input vertices with the factor 1/2 (Section 4.4: the cover covers each face twice): entry
//!    `(i, j)` of the result is half the sum of the cover's entries over the cover vertices of
//!    input vertices `i` and `j`.
//!
//! On a closed oriented manifold the cover is two copies of the surface, so the result is the
//! intrinsic Delaunay Laplacian and mass matrix of the surface itself. Rows and columns are the
//! input's vertex indices; an unreferenced vertex has a zero row and column and zero mass (where
//! `robust_laplacian` puts 1 on the Laplacian's diagonal and a small negative mass: an
//! arbitrary choice we do not copy).
//!
//! What is ours: the defaults and the choices the paper leaves to the implementation follow
//! geometry-central's `buildTuftedLaplacian` (what `robust_laplacian.mesh_laplacian` runs):
//! mollification before the cover, over the input's distinct edges, default factor 1e-5; the
//! geometric order around edges. The Delaunay test is this crate's ([`crate::DEFAULT_TOLERANCE`]
//! on `tan(γ/2) tan(δ/2)`), where geometry-central flips while the edge's cotan weight is below
//! `-1e-6`; the two Delaunay triangulations then give Laplacians that differ by at most about
//! that weight on the few edges in between.

pub(crate) mod cover;

use crate::error::TuftedError;
use crate::flip::{DelaunayOptions, flip_keeping_tan_half_sq};
use crate::laplacian::{assemble_laplacian, lumped_mass_on_rows, weights_from_tan_half_sq};
use crate::sparse::SparseMatrix;
use crate::triangulation::mollify::{MAX_MOLLIFY, margin_delta};
use crate::triangulation::{IntrinsicTriangulation, check_triangle};
use surftopo_mesh::geometry::{Point3, check_finite, distance};
use surftopo_mesh::{BuildError, FaceId};

/// `robust_laplacian`'s default `mollify_factor`.
pub const DEFAULT_MOLLIFY_FACTOR: f64 = 1e-5;

/// Options of [`tufted_laplacian`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TuftedOptions {
    /// The mollification margin relative to the mean input edge length, in `[0, MAX_MOLLIFY]`
    /// (0: none).
    pub mollify_factor: f64,
    /// The flip budget (`None`: [`crate::default_max_flips`] of the cover's edges).
    pub max_flips: Option<u64>,
}

impl Default for TuftedOptions {
    fn default() -> Self {
        Self {
            mollify_factor: DEFAULT_MOLLIFY_FACTOR,
            max_flips: None,
        }
    }
}

/// What [`tufted_laplacian`] built and did.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TuftedReport {
    /// Input vertices (rows), referenced or not.
    pub vertices: usize,
    /// Input faces.
    pub faces: usize,
    /// Distinct input edges.
    pub edges: usize,
    /// Input edges with one face (fins, boundary edges).
    pub fin_edges: usize,
    /// Input edges with three faces or more.
    pub book_edges: usize,
    /// Vertices of the cover (one per fan of each input vertex on the cover).
    pub cover_vertices: usize,
    /// Edges of the cover.
    pub cover_edges: usize,
    /// Faces of the cover (twice the input's).
    pub cover_faces: usize,
    /// The length added to every edge by mollification (0 when none was needed or asked).
    pub mollify_delta: f64,
    /// Intrinsic flips on the cover.
    pub flips: u64,
}

/// The tufted Laplacian and mass matrix of a soup, with its report.
#[derive(Clone, Debug, PartialEq)]
pub struct TuftedLaplacian {
    /// The cotan Laplacian, positive semidefinite convention ([`crate::cotan_laplacian`]'s),
    /// `vertices x vertices`.
    pub laplacian: SparseMatrix,
    /// The lumped (barycentric) mass matrix, diagonal.
    pub mass: SparseMatrix,
    /// The figures.
    pub report: TuftedReport,
    /// The tufted cover, flipped to intrinsic Delaunay (a closed oriented surface: each input
    /// face twice, once per side).
    pub cover: IntrinsicTriangulation,
    /// The input vertex of each vertex of [`Self::cover`] (by vertex id).
    pub cover_input_vertex: Vec<u32>,
}

/// The tufted-cover Laplacian and mass matrix of any triangle soup (module doc): non-manifold
/// edges and vertices, boundary, duplicate faces, several pieces, unreferenced vertices.
/// Work: O(F log d) for the cover, then flipping (finite, input dependent), then O(E) assembly.
///
/// # Errors
/// [`TuftedError::Input`] (no face, an index out of range, a face repeating a vertex, a
/// non-finite coordinate: each naming the face or vertex); [`TuftedError::InvalidMollifyFactor`];
/// [`TuftedError::Degenerate`] for a zero-area triangle (naming the input face) when the factor is
/// 0 or all the points coincide; [`TuftedError::Flip`] when flipping fails (budget, numerical
/// breakdown).
pub fn tufted_laplacian(
    positions: &[Point3],
    triangles: &[[u32; 3]],
    options: &TuftedOptions,
) -> Result<TuftedLaplacian, TuftedError> {
    let factor = options.mollify_factor;
    if !(factor.is_finite() && (0.0..=MAX_MOLLIFY).contains(&factor)) {
        return Err(TuftedError::InvalidMollifyFactor(factor));
    }
    check_soup(positions, triangles)?;
    let cover = cover::tufted_cover(positions, triangles)?;
    let mut report = TuftedReport {
        vertices: positions.len(),
        faces: triangles.len(),
        edges: cover.input_edges,
        fin_edges: cover.fin_edges,
        book_edges: cover.book_edges,
        cover_vertices: cover.mesh.vertex_count(),
        cover_edges: cover.mesh.edge_count(),
        cover_faces: cover.mesh.face_count(),
        ..TuftedReport::default()
    };
    let side_lengths = |t: &[u32; 3]| {
        [0, 1, 2].map(|i| distance(positions[t[i] as usize], positions[t[(i + 1) % 3] as usize]))
    };
    let mut lengths = cover.lengths;
    if factor > 0.0 {
        let margin = factor * cover.input_length_sum / cover.input_edges as f64;
        report.mollify_delta = margin_delta(triangles.iter().map(side_lengths), margin);
        lengths.iter_mut().for_each(|l| *l += report.mollify_delta);
    }
    for (f, t) in triangles.iter().enumerate() {
        let sides = side_lengths(t).map(|l| l + report.mollify_delta);
        check_triangle(FaceId::new(f), sides).map_err(TuftedError::Degenerate)?;
    }
    let mut tri =
        IntrinsicTriangulation::from_parts(cover.mesh, lengths).map_err(TuftedError::Degenerate)?;
    let flip_options = DelaunayOptions {
        max_flips: options.max_flips,
        ..DelaunayOptions::default()
    };
    let (flipped, t2) = flip_keeping_tan_half_sq(&mut tri, &flip_options)?;
    report.flips = flipped.flips;
    // Halving the weights and areas is exact: the fold's factor 1/2.
    let mut weights = weights_from_tan_half_sq(&tri, &t2);
    weights.iter_mut().for_each(|w| *w *= 0.5);
    let n = positions.len();
    let (mesh, rows) = (tri.mesh(), &cover.input_vertex);
    let laplacian = assemble_laplacian(n, || {
        mesh.edges().map(|e| {
            let [a, b] = mesh.edge_vertices(e).map(|v| rows[v.idx()] as usize);
            (a, b, weights[e.idx()])
        })
    });
    let mut mass = lumped_mass_on_rows(&tri, &cover.input_vertex, n);
    mass.iter_mut().for_each(|m| *m *= 0.5);
    Ok(TuftedLaplacian {
        laplacian,
        mass: SparseMatrix::diagonal(mass),
        report,
        cover: tri,
        cover_input_vertex: cover.input_vertex,
    })
}

/// Refuses what no cover can be built from: no face, an index out of range, a face repeating a
/// vertex, a non-finite coordinate.
fn check_soup(positions: &[Point3], triangles: &[[u32; 3]]) -> Result<(), BuildError> {
    if triangles.is_empty() {
        return Err(BuildError::Empty);
    }
    if positions.len() >= u32::MAX as usize {
        return Err(BuildError::TooLarge { what: "vertices" });
    }
    for (face, t) in triangles.iter().enumerate() {
        if let Some(&index) = t.iter().find(|&&v| v as usize >= positions.len()) {
            return Err(BuildError::IndexOutOfRange {
                face,
                index,
                vertex_count: positions.len(),
            });
        }
        let [a, b, c] = *t;
        if a == b || a == c || b == c {
            let vertex = if a == b || a == c { a } else { b };
            return Err(BuildError::RepeatedVertex { face, vertex });
        }
    }
    check_finite(positions)
}
