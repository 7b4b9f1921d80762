//! Theorem 1 on flat closed surfaces: the Delaunay tessellation of a flat torus (or any closed
//! portalgon without cone points) by Proposition 2's reduction followed by Proposition 3's wave.
//!
//! The paper's steps and their functions:
//! - Proposition 2 (a triangulation of size O(n) whose edges are short, computed by ALGORITHM of
//!   Section 4 plus Section 8's caps): [`super::reduce`]. With no cone point there are no caps,
//!   so Proposition 2 is ALGORITHM alone; a cone point is refused
//!   ([`FlatDelaunayError::ConePoint`]), naming the first one by lowest side id.
//! - Proposition 3 (the wave from V and its dual): [`crate::voronoi::voronoi_delaunay`] with
//!   [`Sources::Singular`] on the reduced portalgon (compacted to dense ids first). With no
//!   singular vertex V is one vertex — Section 1's footnote and Theorem 1's statement: the
//!   Delaunay tessellation of a flat torus is taken with respect to one chosen vertex — chosen as
//!   the class of the lowest side id of the *reduced* triangulation (the reduction may delete
//!   the input's vertices; on a flat torus every choice gives the same tessellation up to a
//!   translation).

use super::{DuboisError, DuboisReport, ReduceOptions, reduce};
use crate::geometry::{Scalar, Tolerances};
use crate::portalgon::{Portalgon, SideId};
use crate::voronoi::{
    Sources, VoronoiDelaunay, VoronoiError, VoronoiOptions, WaveOptions, is_flat_vertex,
    voronoi_delaunay,
};

/// Options of [`delaunay_tessellation_flat`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlatDelaunayOptions {
    /// Proposition 2's reduction (ALGORITHM).
    pub reduce: ReduceOptions,
    /// Proposition 3's wave.
    pub wave: WaveOptions,
    /// In `f64` (exact mode decides exactly): a vertex is a cone point when its angle sum is more
    /// than [`Tolerances::angle`] from 2π; the wave's and the dual's tolerances; on a surface with
    /// cone points, the least tolerance of the closing checks on `T₁`
    /// ([`Tolerances::closing`]). The wave on `T′` adds [`Tolerances::with_retries`].
    pub tolerances: Tolerances,
    /// V of Proposition 3 on a surface with cone points ([`super::delaunay_tessellation_dubois`]):
    /// [`Sources::Singular`] (the default: Theorem 1's canonical tessellation) or
    /// [`Sources::All`], every vertex of the input (Section 1's footnote 1: the flip route's
    /// vertex set, so that the Laplacian has a row per input vertex). A flat surface always gets
    /// Theorem 1's one vertex.
    pub sources: Sources,
}

impl Default for FlatDelaunayOptions {
    fn default() -> Self {
        Self {
            reduce: ReduceOptions::default(),
            wave: WaveOptions::default(),
            tolerances: Tolerances::DEFAULT,
            sources: Sources::Singular,
        }
    }
}

/// Why [`delaunay_tessellation_flat`] failed or refused its input.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FlatDelaunayError {
    /// The input has a cone point: Section 8's caps would be needed, and they are not built.
    #[error(
        "vertex {} (at the start of side {side}) is a cone point (angle sum not 2π): the Dubois \
         pipeline takes flat surfaces only",
        label.map_or_else(|| format!("class {class}"), |l| l.to_string())
    )]
    ConePoint {
        /// The vertex's label (a mesh vertex id), when the input is labelled.
        label: Option<u32>,
        /// Its vertex class ([`Portalgon::vertex_classes`]).
        class: u32,
        /// Its lowest side id.
        side: usize,
    },
    /// Proposition 2's reduction failed or refused the input.
    #[error(transparent)]
    Reduction(#[from] DuboisError),
    /// Proposition 3's wave or its dual failed.
    #[error(transparent)]
    Voronoi(#[from] VoronoiError),
}

/// Theorem 1's output on a flat surface: the tessellation (with the wave's data) and the
/// reduction's report.
#[derive(Clone, Debug)]
pub struct FlatDelaunay<S: Scalar> {
    /// Proposition 3 on the reduced triangulation: `.tessellation`, `.wave`, `.sources`.
    pub delaunay: VoronoiDelaunay<S>,
    /// Proposition 2's (ALGORITHM's) report.
    pub reduction: DuboisReport,
    /// Corollary 1: the low-happiness triangulation ALGORITHM produced (dense ids), on which the
    /// wave ran.
    pub reduced: Portalgon<S>,
}

/// The first cone point of a closed portalgon, by lowest side id: `(label, class, side)`.
pub fn first_cone_point<S: Scalar>(
    p: &Portalgon<S>,
    angle_tolerance: f64,
) -> Option<(Option<u32>, u32, SideId)> {
    let (class, count) = p.vertex_classes();
    let mut seen = vec![false; count];
    p.sides().find_map(|s| {
        let c = class[s.idx()];
        if std::mem::replace(&mut seen[c as usize], true) {
            return None;
        }
        (!is_flat_vertex(p, s, angle_tolerance)).then(|| (p.vertex_label(s), c, s))
    })
}

/// Theorem 1 for a closed portalgon without cone points (see the module doc): [`reduce`]
/// (Proposition 2) then [`voronoi_delaunay`] from one vertex (Proposition 3). Exact on rational
/// input in exact mode.
///
/// # Errors
/// [`FlatDelaunayError::ConePoint`] for a cone point; the reduction's errors (bad input, not
/// triangular) and the wave's.
pub fn delaunay_tessellation_flat<S: Scalar>(
    p: &Portalgon<S>,
    options: &FlatDelaunayOptions,
) -> Result<FlatDelaunay<S>, FlatDelaunayError> {
    p.check_invariants().map_err(DuboisError::from)?;
    p.check_closed().map_err(DuboisError::from)?;
    if let Some((label, class, side)) = first_cone_point(p, options.tolerances.angle) {
        return Err(FlatDelaunayError::ConePoint {
            label,
            class,
            side: side.idx(),
        });
    }
    let r = reduce(p, &options.reduce)?;
    let (reduced, _) = r.portalgon.compacted();
    let delaunay = voronoi_delaunay(
        &reduced,
        &VoronoiOptions {
            sources: Sources::Singular,
            wave: options.wave,
            tolerances: options.tolerances,
        },
    )?;
    Ok(FlatDelaunay {
        delaunay,
        reduction: r.report,
        reduced,
    })
}
