//! Dubois' Theorem 1: the intrinsic Delaunay tessellation of a closed polyhedral surface, in time
//! polylogarithmic in its aspect ratio: Proposition 2 (a low-happiness triangulation, Corollary
//! 1) then Proposition 3 (the wave of Appendix D on it, [`crate::voronoi`]).
//!
//! **The folder, by the paper's sections:**
//! - `reduction.rs` (Section 4, Proposition 1): ALGORITHM on a flat surface, the happiness
//!   reduction ([`reduce`], [`reduce_with_boundary`]), with its routines on [`Reduction`];
//! - `tube.rs` and `biface.rs` (Section 3, Proposition 4, Appendix B): tubes replaced by good
//!   bifaces, which SIMPLIFYTUBES and GARDENING call;
//! - [`caps`] (Section 8, Proposition 2): caps around the cone points, ALGORITHM on the flat
//!   remainder, the caps put back ([`proposition_2`]);
//! - [`flat_delaunay`]: Theorem 1 on flat surfaces ([`delaunay_tessellation_flat`]: no caps);
//! - this file: Theorem 1 on any closed surface ([`delaunay_tessellation_dubois`], the CLI's
//!   `delaunay --method dubois`), and on the metric of a mesh in ℝ³, whose happiness is 1, with
//!   the mesh as Proposition 2's output ([`delaunay_tessellation_of_mesh`], the CLI's on a mesh
//!   file; **\[ours\]**, docs/dubois.md §8).
//!
//! **Theorem 1 on flat surfaces** ([`flat_delaunay`]): [`delaunay_tessellation_flat`] runs
//! Proposition 2 (here [`reduce`]: with no cone point there are no caps) and then Proposition 3
//! ([`crate::voronoi::voronoi_delaunay`] from one vertex, the lowest side id's, of the reduced
//! triangulation), reporting both; a cone point is refused with
//! [`FlatDelaunayError::ConePoint`] naming the first one ([`first_cone_point`]).
//!
//! **Theorem 1 with cone points** ([`delaunay_tessellation_dubois`]): [`proposition_2`], then
//! [`crate::voronoi::voronoi_delaunay`] from the singular vertices of `T′`; on a flat surface
//! (no cone point) it is [`delaunay_tessellation_flat`]. Decisions:
//! - **\[`f64` only\] Double-double reduction.** On `f64` input,
//!   [`delaunay_tessellation_dubois`] runs Proposition 2 (caps, ALGORITHM, caps back) in
//!   [`crate::geometry::DoubleDouble`] (about 106 bits), the wave and its dual in `f64`: `T₀` is
//!   laid out again from one length per edge (so matched sides agree to that precision), and
//!   `T′` is rounded back to `f64` in local frames (first corner at the origin). In `f64` the
//!   caps and the pieces of thin triangles give sides thousands of times shorter than the
//!   polygons holding them, whose coordinates (a merged polygon's frame) are larger still;
//!   every motion rounds at the coordinates' scale, so the two copies of a short side come to
//!   disagree in direction by `ulp · |coordinates| / |side|`, and `T′` gets pairs of false cone
//!   points (on `chassis_upright.off`'s `T′`, ±6.8e-5 rad in `f64`), which the cotangents of
//!   the Laplacian amplify. Pieces cut from a polygon are also moved to their own frame
//!   ([`crate::portalgon::Portalgon::cut`]). Measured on `kitten.off` (3 paired runs): 1.3 times the time of
//!   an `f64` reduction. [`caps::proposition_2`] itself runs in the scalar type it is given.
//! - **\[`f64` only\] The wave on `T′`** runs with its own tolerances (points one within 1e-9
//!   of the longest side): the double-double `T′` closes up far below them. (With an `f64`
//!   reduction `T′` closed up only to the closing tolerance, so a site carried around a vertex
//!   came back that far from itself, and the wave had to identify points within 1e-6 of the
//!   longest side; that merged distinct sites of near-co-circular configurations, which broke
//!   the dual on `chassis_upright.off`.) When the traced Voronoi edges do not close up, the dual
//!   is built again pooling the sites of Voronoi vertices taken for one, then at
//!   1e-8 ([`crate::geometry::Tolerances::dual_retry`], set by [`crate::geometry::Tolerances::with_retries`]).
//!   When all three fail, the wave and the dual run again at tolerances
//!   1000 times finer ([`crate::geometry::Tolerances::finer_retry`]: points 1e-12,
//!   the dual 1e-12 and 1e-11). The tolerance
//!   is taken at the scale of the longest side, and a surface with features thousands of times
//!   smaller can have whole clusters of sites within it: on `seahorse2_100K.off`'s `T′`
//!   (longest side 0.07) a cap triangle has a side of 1.9e-6 and 17 sites within 3.2e-5 of a
//!   Voronoi vertex; the side diagrams' ties (about 2e-9 in squared distance, against squared
//!   distances of 1.5e-10 to 1e-9) swallow them all, and the dual misses the vertex. The
//!   coarse tolerance comes first because it merges near-co-circular vertices where the fine
//!   one may not; `results/dubois-every-mesh.txt` shows where each retry is needed.
//! - Output vertex labels: the wave numbers its sources; when every cone point of the input is
//!   labelled (mesh input), the tessellation's corners get the input's labels back, so its
//!   triangulation indexes the Laplacian like the flip route's. A vertex of the input that is
//!   flat (within the tolerance in `f64`) is no vertex of Theorem 1's tessellation.

pub(crate) mod biface;
pub mod caps;
pub mod delaunay_exit;
pub mod flat_delaunay;
mod reduction;
pub(crate) mod tube;

pub use caps::{CapCut, CapsError, cut_caps, cut_caps_at, proposition_2, put_caps_back};
pub use flat_delaunay::{
    FlatDelaunay, FlatDelaunayError, FlatDelaunayOptions, delaunay_tessellation_flat,
    first_cone_point,
};
pub use reduction::{
    DELETE_MAX_DEGREE, DuboisError, DuboisReport, INNER_REPETITIONS, MAX_WORKING_BITS,
    OUTER_PERIOD_MAX, ReduceOptions, Reduction, outer_iterations, reduce, reduce_with_boundary,
    reduce_with_boundary_until,
};

use crate::geometry::Scalar;
use crate::portalgon::{PolygonId, Portalgon};
use crate::voronoi::{
    Sources, VoronoiDelaunay, VoronoiError, VoronoiOptions, WaveError, voronoi_delaunay,
    voronoi_delaunay_from,
};
use caps::{in_local_frames, laid_out_in_double_double, proposition_2_with_apexes};

/// Theorem 1's output on a closed surface: the tessellation (with the wave's data), ALGORITHM's
/// report, and the caps.
#[derive(Clone, Debug)]
pub struct ConeDelaunay<S: Scalar> {
    /// Proposition 3 on Proposition 2's `T′`: `.tessellation`, `.wave`, `.sources`.
    pub delaunay: VoronoiDelaunay<S>,
    /// ALGORITHM's report (on `T₁`; `triangles_after_reduction` counts `T′`, caps included).
    pub reduction: DuboisReport,
    /// Cone points, each with a cap (0 for a flat surface).
    pub cone_points: usize,
    /// Cap triangles cut off and put back.
    pub cap_triangles: usize,
    /// Corollary 1: the low-happiness triangulation the wave ran on (Proposition 2's `T′`, caps
    /// included; ALGORITHM's output on a flat surface).
    pub reduced: Portalgon<S>,
}

/// Theorem 1 on a closed triangular portalgon, with or without cone points: without, it is
/// [`delaunay_tessellation_flat`]; with, [`proposition_2`] then
/// [`crate::voronoi::voronoi_delaunay`] from the singular vertices of `T′` (its cone points are
/// the input's), or with [`Sources::All`] from every input vertex
/// ([`crate::voronoi::voronoi_delaunay_from`] on the capped vertices). Labels: see the module
/// doc. Exact on rational input in exact mode; on `f64` input Proposition 2 runs in
/// double-double and the wave in `f64` (module doc).
///
/// # Errors
/// [`CapsError`]: bad input, ALGORITHM's or the wave's errors.
pub fn delaunay_tessellation_dubois<S: Scalar>(
    t: &Portalgon<S>,
    options: &FlatDelaunayOptions,
) -> Result<ConeDelaunay<S>, CapsError> {
    theorem_1(t, options).map_err(|e| match e {
        CapsError::Voronoi(VoronoiError::Wave(WaveError::Work(work))) => CapsError::WaveWork(work),
        e => e,
    })
}

/// [`delaunay_tessellation_dubois`], the wave's work budget reported as the wave's.
fn theorem_1<S: Scalar>(
    t: &Portalgon<S>,
    options: &FlatDelaunayOptions,
) -> Result<ConeDelaunay<S>, CapsError> {
    t.check_invariants()?;
    t.check_closed()?;
    if first_cone_point(t, options.tolerances.angle).is_none() {
        let flat = delaunay_tessellation_flat(t, options).map_err(|e| match e {
            FlatDelaunayError::Reduction(e) => CapsError::Reduction(e),
            FlatDelaunayError::Voronoi(e) => CapsError::Voronoi(e),
            FlatDelaunayError::ConePoint { .. } => CapsError::Reduction(DuboisError::Invariant(
                "a cone point appeared on a flat surface".into(),
            )),
        })?;
        return Ok(ConeDelaunay {
            delaunay: flat.delaunay,
            reduction: flat.reduction,
            cone_points: 0,
            cap_triangles: 0,
            reduced: flat.reduced,
        });
    }
    let (t_prime, reduction, cut, apexes) = if S::REDUCES_IN_DOUBLE_DOUBLE {
        resolvable_in_double(t, options)?;
        // The reduction in double-double, `T′` rounded back in local frames (module doc).
        let t_dd = laid_out_in_double_double(t);
        let (t_prime, reduction, cut, apexes) = proposition_2_with_apexes(&t_dd, options)?;
        let t_prime = in_local_frames(&t_prime, options.tolerances.closing)?
            .map_coordinates(|x| S::from_f64(x.to_f64()).unwrap_or_else(S::zero));
        let cut = (cut.cone_points, cut.caps.len());
        (t_prime, reduction, cut, apexes)
    } else {
        let (t_prime, reduction, cut, apexes) = proposition_2_with_apexes(t, options)?;
        (
            t_prime,
            reduction,
            (cut.cone_points, cut.caps.len()),
            apexes,
        )
    };
    let wave_options = wave_options(options, Sources::Singular);
    let mut delaunay = match options.sources {
        Sources::Singular => voronoi_delaunay(&t_prime, &wave_options)?,
        Sources::All => voronoi_delaunay_from(&t_prime, apexes, &wave_options)?,
    };
    relabel_with_input_labels(&t_prime, &mut delaunay)?;
    Ok(ConeDelaunay {
        delaunay,
        reduction,
        cone_points: cut.0,
        cap_triangles: cut.1,
        reduced: t_prime,
    })
}

/// In double precision, whether Section 8's caps can be told from their cone points by the
/// rounded wave: their radius is above `d/12` (`d` the smallest height, §3.4 of docs/dubois.md),
/// and the wave takes points within [`Tolerances::point`](crate::geometry::Tolerances::point)
/// of the longest side for one, [`Tolerances::finer_retry`](crate::geometry::Tolerances::finer_retry)
/// times that on its last retry. Below it (a pillowcase of a right triangle of height 10⁻¹²:
/// `d/(12L)` about 10⁻¹³) the wave could not resolve `T′` and ran on for minutes; refused at once
/// instead.
///
/// # Errors
/// [`DuboisError::Unresolvable`].
fn resolvable_in_double<S: Scalar>(
    t: &Portalgon<S>,
    options: &FlatDelaunayOptions,
) -> Result<(), CapsError> {
    let (d2, l2) = caps::heights_and_lengths(t);
    let cap = (d2.to_f64() / l2.to_f64()).sqrt() / 12.0;
    let tolerances = options.tolerances.with_retries();
    let tolerance = tolerances.point * tolerances.finer_retry.unwrap_or(1.0);
    if cap >= tolerance {
        Ok(())
    } else {
        Err(CapsError::Reduction(DuboisError::Unresolvable {
            cap,
            tolerance,
        }))
    }
}

/// Proposition 3's options on `T′`: the sources, `options`' angle tolerance and wave budget, and
/// in `f64` the dual's retries (module doc).
fn wave_options(options: &FlatDelaunayOptions, sources: Sources) -> VoronoiOptions {
    // `T′` from the double-double reduction closes up to far below the wave's own point
    // tolerance (module doc), which is kept; its features can be far below it: the rounded
    // wave's retries (exact arithmetic has none).
    VoronoiOptions {
        sources,
        wave: options.wave,
        tolerances: options.tolerances.with_retries(),
    }
}

/// Theorem 1 on the metric of a mesh in ℝ³ (every triangle of `t` a face with those side
/// lengths, as `surftopo delaunay` reads a mesh file): `t` has happiness 1 (a shortest path
/// meets each face in one segment, docs/dubois.md §8), within Proposition 2's bound, so `T′ = t`
/// and Proposition 3's wave runs on `t` from `options.sources` (the wave's options of
/// [`delaunay_tessellation_dubois`]). The report has no outer iteration
/// ([`DuboisReport::mesh_metric`] set); `reduced` is `t`. In `f64`, when the wave fails on `t`
/// (its dual refusing rounding, as on near-co-circular sites of a regular grid), it is
/// [`delaunay_tessellation_dubois`] (Proposition 2 with caps, whose `T′` the wave resolves). The tessellation is the one
/// [`delaunay_tessellation_dubois`] computes, up to the choice of diagonals in co-circular
/// polygons and rounding in `f64`; that `t` is a mesh's metric is the caller's word (nothing here
/// can check it).
///
/// # Errors
/// [`CapsError`]: bad input or the wave's errors.
pub fn delaunay_tessellation_of_mesh<S: Scalar>(
    t: &Portalgon<S>,
    options: &FlatDelaunayOptions,
) -> Result<ConeDelaunay<S>, CapsError> {
    t.check_invariants()?;
    t.check_closed()?;
    let cone_points = caps::cone_points(t, options.tolerances.angle)
        .iter()
        .filter(|&&c| c)
        .count();
    let wave_options = wave_options(options, options.sources);
    let mut delaunay = match voronoi_delaunay(t, &wave_options) {
        Ok(delaunay) => delaunay,
        // In `f64` the wave's dual can refuse a mesh whose rounding makes the traced Voronoi
        // edges inconsistent (near-co-circular grids), or the wave run out of its budget; `T′`
        // with caps resolves the former (and bad input is refused there again).
        Err(_) if !S::EXACT => {
            return delaunay_tessellation_dubois(t, options);
        }
        Err(e) => return Err(e.into()),
    };
    if options.sources == Sources::Singular {
        relabel_with_input_labels(t, &mut delaunay)?;
    }
    let reduction = DuboisReport {
        triangles_after_reduction: t.polygon_count(),
        arithmetic: S::ARITHMETIC,
        mesh_metric: true,
        ..DuboisReport::default()
    };
    Ok(ConeDelaunay {
        delaunay,
        reduction,
        cone_points,
        cap_triangles: 0,
        reduced: t.clone(),
    })
}

/// Gives the tessellation's corners (labelled with the index of their source) the label of their
/// source in `t_prime`, when every source has one.
fn relabel_with_input_labels<S: Scalar>(
    t_prime: &Portalgon<S>,
    delaunay: &mut VoronoiDelaunay<S>,
) -> Result<(), CapsError> {
    let (class, _) = t_prime.vertex_classes();
    let mut label_of_class: Vec<Option<u32>> = vec![None; class.len()];
    for s in t_prime.sides() {
        let c = class[s.idx()] as usize;
        if label_of_class[c].is_none() {
            label_of_class[c] = t_prime.vertex_label(s);
        }
    }
    let labels: Option<Vec<u32>> = delaunay
        .sources
        .iter()
        .map(|&c| label_of_class[c as usize])
        .collect();
    let Some(labels) = labels else {
        return Ok(());
    };
    let tess = &mut delaunay.tessellation;
    let polygons: Vec<PolygonId> = tess.polygons().collect();
    for p in polygons {
        let new: Vec<u32> = tess
            .polygon_sides(p)
            .iter()
            .map(|&s| {
                tess.vertex_label(s)
                    .and_then(|k| labels.get(k as usize).copied())
                    .unwrap_or(u32::MAX)
            })
            .collect();
        tess.set_vertex_labels(p, &new)?;
    }
    Ok(())
}
