//! Intrinsic Delaunay by method: [`intrinsic_delaunay`], the one function behind the CLI's
//! `delaunay`, the canonical tessellations of `isometric`, the Python package and the benchmarks.
//!
//! It takes a surface in its arithmetic ([`DelaunayInput`]: `f64` lengths, or exact corners) and
//! a [`DelaunayRequest`]: the method ([`DelaunayMethod`]: `auto`, `flip`, `voronoi`, `dubois`),
//! the vertex set `V`, the outputs wanted ([`DelaunayOutputs`]) and the limits, and returns a
//! [`DelaunayOutput`]:
//! - `flip` ([`crate::flip_to_delaunay`]) works on `f64` lengths; the triangulation is the input
//!   flipped, its tessellation [`crate::delaunay_tessellation`];
//! - `voronoi` ([`crate::voronoi::voronoi_delaunay`]) and `dubois`
//!   ([`crate::dubois::delaunay_tessellation_dubois`]) compute the tessellation in the input's
//!   arithmetic; the triangulation is the tessellation cut along shortcuts;
//! - `auto` ([`choice`]) decides from the input alone: flipping unless some triangle is a needle
//!   (the test runs on the half-angle cache of flipping's first pass, so it costs flipping next
//!   to nothing), then `dubois` on a flat surface; on exact input flipping becomes the exact wave.
//!   Asking for the reduced triangulation chooses `dubois`, asking for flipping's limits chooses
//!   `flip`.
//!
//! The Laplacian and the mass matrix are those of the triangulation ([`crate::cotan_laplacian`],
//! [`crate::lumped_mass`]; after flipping, assembled from the half-angle tangents the flips kept
//! up to date, bit for bit the same).

pub(crate) mod choice;

use std::time::Instant;

use crate::covered::CoveredTriangulation;
use crate::dubois::{CapsError, DuboisReport, FlatDelaunayOptions, ReduceOptions};
use crate::error::{DelaunayError, GeometryError, PortalgonError};
use crate::flip::stats::DelaunayStats;
use crate::flip::tessellation::{Tessellation, delaunay_tessellation};
use crate::flip::{DelaunayOptions, FlipReport, flip_unless};
use crate::formats::portalgon_json::PortalgonDoc;
use crate::geometry::{Motion, Rational, Scalar, Tolerances, incircle};
use crate::laplacian::{cotan_laplacian, laplacian_from_tan_half_sq, lumped_mass};
use crate::portalgon::Portalgon;
use crate::sparse::SparseMatrix;
use crate::triangulation::IntrinsicTriangulation;
use crate::voronoi::{
    Sources, VoronoiDelaunay, VoronoiError, VoronoiOptions, WaveOptions, to_f64, voronoi_delaunay,
};
use std::cmp::Ordering;

/// The algorithm computing the Delaunay tessellation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum DelaunayMethod {
    /// The method [`choice`] picks from the input (see the module doc).
    #[default]
    Auto,
    /// Edge flipping (Bobenko–Springborn), on `f64` lengths.
    Flip,
    /// The multi-source Voronoi wave and its dual (Dubois, Appendix D).
    Voronoi,
    /// Dubois' Theorem 1: Proposition 2's reduction (caps around the cone points), then the wave.
    Dubois,
}

impl DelaunayMethod {
    /// Every method, `auto` first.
    pub const ALL: [Self; 4] = [Self::Auto, Self::Flip, Self::Voronoi, Self::Dubois];

    /// The method's name: `auto`, `flip`, `voronoi`, `dubois`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Auto => "auto",
            Self::Flip => "flip",
            Self::Voronoi => "voronoi",
            Self::Dubois => "dubois",
        }
    }
}

/// The surface, in the arithmetic the run computes in.
#[derive(Clone, Debug)]
pub enum DelaunayInput {
    /// Edge lengths in `f64` (a mesh, a portalgon read in `f64`): every method, in `f64`.
    Lengths(IntrinsicTriangulation),
    /// A closed triangular portalgon given by exact corners: the wave and Theorem 1, exactly.
    Exact(Portalgon<Rational>),
    /// Any compact surface (boundary loops, non-orientable pieces) on its closed cover, `f64`
    /// lengths: flipping ([`CoveredTriangulation::flip_to_delaunay`]) and its tessellation
    /// ([`CoveredTriangulation::tessellation`]); the wave and Theorem 1 are refused
    /// ([`IntrinsicDelaunayError::NotClosedOrientable`]).
    Covered(CoveredTriangulation),
}

/// The outputs wanted; what is not asked for is not computed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DelaunayOutputs {
    /// The Delaunay triangulation ([`DelaunayOutput::triangulation`], and in exact mode
    /// [`DelaunayOutput::exact_triangulation`]).
    pub triangulation: bool,
    /// The Delaunay tessellation (co-circular triangles merged).
    pub tessellation: bool,
    /// The reduced triangulation of Dubois' Proposition 2 (Corollary 1); asks for `dubois`.
    pub reduced: bool,
    /// The cotan Laplacian of the triangulation.
    pub laplacian: bool,
    /// The lumped mass matrix of the triangulation.
    pub mass: bool,
    /// The figures of the run ([`DelaunayOutput::stats`]).
    pub figures: bool,
}

/// What [`intrinsic_delaunay`] is asked to do.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DelaunayRequest {
    /// The algorithm.
    pub method: DelaunayMethod,
    /// V, the vertices of the tessellation: every vertex of the input (the default, the flip
    /// route's: the Laplacian has a row per input vertex), or the singular ones (Theorem 1's
    /// canonical tessellation, one vertex on a flat torus). Flipping keeps every vertex.
    pub vertices: Sources,
    /// The outputs wanted.
    pub outputs: DelaunayOutputs,
    /// Flipping: stop with [`DelaunayError::MaxFlips`] after this many flips (`None`:
    /// [`crate::default_max_flips`]); asks for `flip`.
    pub max_flips: Option<u64>,
    /// Flipping: mollify degenerate input with this ε relative to the mean edge length; asks for
    /// `flip`.
    pub mollify: Option<f64>,
    /// The wave: give up after this many events (`None`: the wave's default budget).
    pub max_wave_events: Option<u64>,
    /// `dubois`: run all 350 inner repetitions of ALGORITHM (Section 4.5), not stopping at the
    /// first that changes nothing (the same output; slower).
    pub faithful: bool,
    /// The input's lengths are those of a mesh in ℝ³ (each triangle a face in space, as a mesh
    /// file gives them): `dubois` then keeps it as Proposition 2's `T′`, whose happiness is 1
    /// ([`crate::dubois::delaunay_tessellation_of_mesh`], docs/dubois.md §8), unless `faithful`
    /// asks for the paper's Proposition 2.
    pub mesh_metric: bool,
}

/// A request that cannot be run, whatever the input.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum RequestError {
    /// Flipping works on lengths, which are square roots: it has no exact mode.
    #[error("flipping works on lengths: it has no exact mode")]
    ExactFlip,
    /// `faithful` is a property of Dubois' ALGORITHM.
    #[error("the faithful repetitions belong to the dubois method")]
    FaithfulWithoutDubois,
    /// The reduced triangulation is Dubois' Proposition 2's.
    #[error("the reduced triangulation belongs to the dubois method")]
    ReducedWithoutDubois,
    /// `max_flips` and `mollify` limit flipping.
    #[error("the flip budget and mollification belong to the flip method")]
    FlipLimitsWithoutFlip,
}

/// Why [`intrinsic_delaunay`] failed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum IntrinsicDelaunayError {
    /// The request cannot run.
    #[error(transparent)]
    Request(#[from] RequestError),
    /// Flipping failed (bad lengths, the flip budget, or a numerical breakdown).
    #[error(transparent)]
    Flip(#[from] DelaunayError),
    /// The `f64` input is not a valid triangulation (for the wave and Theorem 1).
    #[error(transparent)]
    Geometry(#[from] GeometryError),
    /// The wave or its dual failed; `numerical` when it is a refusal of double precision on
    /// valid input ([`VoronoiError::is_numerical`] in `f64`).
    #[error("{error}")]
    Wave {
        /// The wave's error.
        error: VoronoiError,
        /// Whether double precision, not the input, is at fault.
        numerical: bool,
    },
    /// Theorem 1 failed; `numerical` in `f64` (the input was validated: rounding broke a check).
    #[error("{error}")]
    Dubois {
        /// Theorem 1's error.
        error: CapsError,
        /// Whether double precision, not the input, is at fault.
        numerical: bool,
    },
    /// The tessellation could not be cut into triangles.
    #[error(transparent)]
    Portalgon(#[from] PortalgonError),
    /// The method asked for is defined on closed orientable surfaces only (the wave and Theorem
    /// 1: Dubois treats closed surfaces), and the input has boundary or is non-orientable.
    #[error(
        "{what} takes closed orientable surfaces only, and this surface has boundary or is \
         non-orientable: {instead}"
    )]
    NotClosedOrientable {
        /// What was asked: "the voronoi method (Dubois, Appendix D)", ...
        what: &'static str,
        /// What works instead.
        instead: &'static str,
    },
}

impl IntrinsicDelaunayError {
    /// Whether double precision could not finish on valid input (another arithmetic or method
    /// can): the `f64` wave's numerical refusals and Theorem 1's failures in `f64`. (Flipping's
    /// numerical breakdown is [`DelaunayError::NumericalBreakdown`].)
    pub fn is_numerical(&self) -> bool {
        matches!(
            self,
            Self::Wave {
                numerical: true,
                ..
            } | Self::Dubois {
                numerical: true,
                ..
            }
        )
    }
}

/// A portalgon in the arithmetic of the run.
#[derive(Clone, Debug, PartialEq)]
pub enum AnyPortalgon {
    /// `f64` corners.
    F64(Portalgon),
    /// Exact corners.
    Exact(Portalgon<Rational>),
}

impl AnyPortalgon {
    /// Its portalgon JSON document (exact corners as fractions).
    pub fn to_doc(&self) -> PortalgonDoc {
        match self {
            Self::F64(p) => PortalgonDoc::from_portalgon(p),
            Self::Exact(p) => PortalgonDoc::from_portalgon(p),
        }
    }

    /// The portalgon with its corners rounded to doubles, compacted.
    pub fn to_f64(&self) -> Portalgon {
        match self {
            Self::F64(p) => to_f64(p),
            Self::Exact(p) => to_f64(p),
        }
    }
}

/// The wave's figures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WaveFigures {
    /// Events (points added to the constellations).
    pub events: u64,
    /// The largest constellation `|X_Δ|`.
    pub max_constellation: usize,
}

/// What [`intrinsic_delaunay`] computed; the fields not asked for are `None`.
#[derive(Clone, Debug)]
pub struct DelaunayOutput {
    /// The method run (`auto` resolved).
    pub method: DelaunayMethod,
    /// `"f64"` or `"exact"`.
    pub arithmetic: &'static str,
    /// The Delaunay triangulation in `f64` (flipping: the input flipped; the wave and Theorem 1:
    /// the tessellation cut along shortcuts, vertex ids the input's dense vertex indices).
    pub triangulation: Option<IntrinsicTriangulation>,
    /// The Delaunay triangulation of a [`DelaunayInput::Covered`] surface (the input flipped).
    pub covered: Option<CoveredTriangulation>,
    /// Exact mode: the tessellation cut along shortcuts, by exact corners.
    pub exact_triangulation: Option<Portalgon<Rational>>,
    /// The Delaunay tessellation (of a closed orientable surface).
    pub tessellation: Option<AnyPortalgon>,
    /// The Delaunay tessellation of a [`DelaunayInput::Covered`] surface
    /// ([`CoveredTriangulation::tessellation`]: boundary sides unmatched, orientation-reversing
    /// gluings flagged).
    pub covered_tessellation: Option<Tessellation<PortalgonDoc>>,
    /// `dubois`: Corollary 1's low-happiness triangulation the wave ran on.
    pub reduced: Option<AnyPortalgon>,
    /// The cotan Laplacian of the triangulation (positive semidefinite).
    pub laplacian: Option<SparseMatrix>,
    /// The lumped mass matrix of the triangulation.
    pub mass: Option<SparseMatrix>,
    /// The figures (vertices, edges, faces, flips, non-Delaunay edges, seconds, ...).
    pub stats: Option<DelaunayStats>,
    /// `dubois`: ALGORITHM's report.
    pub reduction: Option<DuboisReport>,
    /// `voronoi` and `dubois`: the wave's figures.
    pub wave: Option<WaveFigures>,
}

impl DelaunayRequest {
    /// Refuses what no input can run: flipping on exact input, `faithful` without `dubois`.
    ///
    /// # Errors
    /// [`RequestError::ExactFlip`], [`RequestError::FaithfulWithoutDubois`].
    pub fn check(&self, exact: bool) -> Result<(), RequestError> {
        if self.faithful && self.method != DelaunayMethod::Dubois {
            return Err(RequestError::FaithfulWithoutDubois);
        }
        if exact && self.method == DelaunayMethod::Flip {
            return Err(RequestError::ExactFlip);
        }
        Ok(())
    }

    /// Whether flipping's limits are given (they ask `auto` for flipping).
    fn flip_limits(&self) -> bool {
        self.max_flips.is_some() || self.mollify.is_some()
    }

    /// Flipping's options.
    fn flip_options(&self) -> DelaunayOptions {
        DelaunayOptions {
            max_flips: self.max_flips,
            mollify: self.mollify,
            ..DelaunayOptions::default()
        }
    }

    /// Refuses the options of another method than `method` (resolved).
    fn check_resolved(&self, method: DelaunayMethod) -> Result<(), RequestError> {
        if method != DelaunayMethod::Flip && self.flip_limits() {
            return Err(RequestError::FlipLimitsWithoutFlip);
        }
        if method != DelaunayMethod::Dubois && self.outputs.reduced {
            return Err(RequestError::ReducedWithoutDubois);
        }
        Ok(())
    }
}

/// The intrinsic Delaunay triangulation and tessellation of a closed surface by the requested
/// method (see the module doc), with the outputs asked for. Takes the input by value: flipping
/// works in place.
///
/// # Errors
/// [`IntrinsicDelaunayError`]: the request, the input, or the method's failure.
pub fn intrinsic_delaunay(
    input: DelaunayInput,
    request: &DelaunayRequest,
) -> Result<DelaunayOutput, IntrinsicDelaunayError> {
    intrinsic_delaunay_reporting(input, request, &mut |_| {})
}

/// [`intrinsic_delaunay`], calling `progress` with the name of each step as it starts
/// ("flipping to Delaunay", "running the Voronoi wave", "building the Laplacian", ...).
///
/// # Errors
/// As [`intrinsic_delaunay`].
pub fn intrinsic_delaunay_reporting(
    input: DelaunayInput,
    request: &DelaunayRequest,
    progress: &mut dyn FnMut(&'static str),
) -> Result<DelaunayOutput, IntrinsicDelaunayError> {
    let exact = matches!(input, DelaunayInput::Exact(_));
    request.check(exact)?;
    match input {
        DelaunayInput::Covered(tri) => covered(tri, request, progress),
        DelaunayInput::Exact(p) => {
            let method = match request.method {
                DelaunayMethod::Auto if request.outputs.reduced => DelaunayMethod::Dubois,
                DelaunayMethod::Auto => match choice::choose_method(&p) {
                    DelaunayMethod::Dubois => DelaunayMethod::Dubois,
                    _ => DelaunayMethod::Voronoi,
                },
                m => m,
            };
            request.check_resolved(method)?;
            by_wave(&p, method, request, Instant::now(), progress)
        }
        DelaunayInput::Lengths(mut tri) => {
            let method = match request.method {
                DelaunayMethod::Auto if request.outputs.reduced => DelaunayMethod::Dubois,
                DelaunayMethod::Auto if request.flip_limits() => DelaunayMethod::Flip,
                DelaunayMethod::Auto => {
                    progress("flipping to Delaunay");
                    let start = Instant::now();
                    let options = request.flip_options();
                    if let Some(flipped) = flip_unless(&mut tri, &options, true)? {
                        return Ok(flipped_output(tri, flipped, start, request, progress));
                    }
                    choice::choose_method_for_needle(&tri)
                }
                m => m,
            };
            request.check_resolved(method)?;
            if method == DelaunayMethod::Flip {
                progress("flipping to Delaunay");
                let start = Instant::now();
                let flipped = flip_unless(&mut tri, &request.flip_options(), false)?
                    .expect("flipping without the needle test always finishes");
                return Ok(flipped_output(tri, flipped, start, request, progress));
            }
            let start = Instant::now();
            tri.validate()?;
            let (p, _) = tri.to_portalgon();
            by_wave(&p, method, request, start, progress)
        }
    }
}

/// The outputs of a flipped triangulation; `flipped` is flipping's report and its half-angle
/// cache.
fn flipped_output(
    tri: IntrinsicTriangulation,
    (report, tan_half_sq): (FlipReport, Vec<f64>),
    start: Instant,
    request: &DelaunayRequest,
    progress: &mut dyn FnMut(&'static str),
) -> DelaunayOutput {
    let seconds = start.elapsed().as_secs_f64();
    let wanted = request.outputs;
    let stats = wanted
        .figures
        .then(|| DelaunayStats::new(&tri, &report, seconds));
    let tessellation = wanted.tessellation.then(|| {
        progress("merging co-circular triangles");
        let t = delaunay_tessellation(&tri, Tolerances::DEFAULT.cocircular);
        AnyPortalgon::F64(t.portalgon)
    });
    let laplacian = wanted.laplacian.then(|| {
        progress("building the Laplacian");
        laplacian_from_tan_half_sq(&tri, &tan_half_sq)
    });
    let mass = wanted.mass.then(|| {
        progress("building the mass matrix");
        lumped_mass(&tri)
    });
    DelaunayOutput {
        method: DelaunayMethod::Flip,
        arithmetic: f64::ARITHMETIC,
        triangulation: wanted.triangulation.then_some(tri),
        covered: None,
        exact_triangulation: None,
        tessellation,
        covered_tessellation: None,
        reduced: None,
        laplacian,
        mass,
        stats,
        reduction: None,
        wave: None,
    }
}

/// Flipping on a surface of any kind ([`DelaunayInput::Covered`]): `auto` is `flip`; the wave
/// and Theorem 1 are refused; the tessellation is [`CoveredTriangulation::tessellation`].
fn covered(
    mut tri: CoveredTriangulation,
    request: &DelaunayRequest,
    progress: &mut dyn FnMut(&'static str),
) -> Result<DelaunayOutput, IntrinsicDelaunayError> {
    let refuse = |what, instead| Err(IntrinsicDelaunayError::NotClosedOrientable { what, instead });
    // Dubois' paper (the wave of Appendix D, Theorem 1) treats closed surfaces.
    let flip = "use the flip method (--method flip; auto takes it)";
    match request.method {
        DelaunayMethod::Voronoi => return refuse("the voronoi method (Dubois, Appendix D)", flip),
        DelaunayMethod::Dubois => return refuse("the dubois method (Dubois, Theorem 1)", flip),
        DelaunayMethod::Auto | DelaunayMethod::Flip => {}
    }
    request.check_resolved(DelaunayMethod::Flip)?;
    let wanted = request.outputs;
    progress("flipping to Delaunay");
    let start = Instant::now();
    let (report, tan_half_sq) = tri.flip_keeping_tan_half_sq(&request.flip_options())?;
    let seconds = start.elapsed().as_secs_f64();
    let stats = wanted.figures.then(|| tri.stats(&report, seconds));
    let covered_tessellation = wanted.tessellation.then(|| {
        progress("merging co-circular triangles");
        tri.tessellation(Tolerances::DEFAULT.cocircular)
    });
    let laplacian = wanted.laplacian.then(|| {
        progress("building the Laplacian");
        tri.laplacian_from_tan_half_sq(&tan_half_sq)
    });
    let mass = wanted.mass.then(|| {
        progress("building the mass matrix");
        tri.mass()
    });
    Ok(DelaunayOutput {
        method: DelaunayMethod::Flip,
        arithmetic: f64::ARITHMETIC,
        triangulation: None,
        covered: wanted.triangulation.then_some(tri),
        exact_triangulation: None,
        tessellation: None,
        covered_tessellation,
        reduced: None,
        laplacian,
        mass,
        stats,
        reduction: None,
        wave: None,
    })
}

/// The tessellation by the wave (`voronoi`) or by Theorem 1 (`dubois`) in the arithmetic of `p`,
/// then the outputs; `start` is when the run began (for the figures).
fn by_wave<S: Scalar>(
    p: &Portalgon<S>,
    method: DelaunayMethod,
    request: &DelaunayRequest,
    start: Instant,
    progress: &mut dyn FnMut(&'static str),
) -> Result<DelaunayOutput, IntrinsicDelaunayError>
where
    AnyPortalgon: From<Portalgon<S>>,
{
    let wave_options = WaveOptions {
        max_events: request.max_wave_events,
        ..WaveOptions::default()
    };
    let (v, reduction, reduced) = if method == DelaunayMethod::Dubois {
        progress("reducing (Dubois, Sections 8 and 4) and running the wave");
        let options = FlatDelaunayOptions {
            reduce: ReduceOptions {
                faithful: request.faithful,
                ..ReduceOptions::default()
            },
            sources: request.vertices,
            wave: wave_options,
            ..FlatDelaunayOptions::default()
        };
        let out = if request.mesh_metric && !request.faithful {
            crate::dubois::delaunay_tessellation_of_mesh(p, &options)
        } else {
            crate::dubois::delaunay_tessellation_dubois(p, &options)
        }
        .map_err(|error| IntrinsicDelaunayError::Dubois {
            error,
            numerical: !S::EXACT,
        })?;
        (out.delaunay, Some(out.reduction), Some(out.reduced))
    } else {
        progress("running the Voronoi wave");
        let options = VoronoiOptions {
            sources: request.vertices,
            wave: wave_options,
            ..VoronoiOptions::default()
        };
        let v = voronoi_delaunay(p, &options).map_err(|error| IntrinsicDelaunayError::Wave {
            numerical: !S::EXACT && error.is_numerical(),
            error,
        })?;
        (v, None, None)
    };
    wave_output(v, method, reduction, reduced, request, start, progress)
}

/// The outputs of a tessellation computed by the wave (after the reduction for `dubois`).
fn wave_output<S: Scalar>(
    v: VoronoiDelaunay<S>,
    method: DelaunayMethod,
    reduction: Option<DuboisReport>,
    reduced: Option<Portalgon<S>>,
    request: &DelaunayRequest,
    start: Instant,
    progress: &mut dyn FnMut(&'static str),
) -> Result<DelaunayOutput, IntrinsicDelaunayError>
where
    AnyPortalgon: From<Portalgon<S>>,
{
    let wanted = request.outputs;
    let exact_triangulation = match wanted.triangulation {
        true if S::EXACT => match AnyPortalgon::from(v.triangulated()?) {
            AnyPortalgon::Exact(p) => Some(p),
            AnyPortalgon::F64(_) => None,
        },
        _ => None,
    };
    let needs_triangulation = wanted.triangulation || wanted.laplacian || wanted.mass;
    let triangulation = if needs_triangulation || wanted.figures {
        Some(v.triangulation()?)
    } else {
        None
    };
    // In exact mode the count is decided on the exact triangles (the rounded lengths of a
    // needle can fail the f64 test on a triangulation that is exactly Delaunay).
    let exact_count = match (wanted.figures, S::EXACT) {
        (true, true) => Some(non_delaunay_sides(&v.triangulated()?)),
        _ => None,
    };
    let stats = triangulation
        .as_ref()
        .filter(|_| wanted.figures)
        .map(|tri| {
            let report = FlipReport {
                flips: 0,
                mollify_delta: None,
                non_delaunay_edges: exact_count
                    .unwrap_or_else(|| tri.non_delaunay_edges(Tolerances::DEFAULT.delaunay)),
            };
            DelaunayStats::new(tri, &report, start.elapsed().as_secs_f64())
        });
    let laplacian = triangulation
        .as_ref()
        .filter(|_| wanted.laplacian)
        .map(|tri| {
            progress("building the Laplacian");
            cotan_laplacian(tri)
        });
    let mass = triangulation.as_ref().filter(|_| wanted.mass).map(|tri| {
        progress("building the mass matrix");
        lumped_mass(tri)
    });
    let wave = Some(WaveFigures {
        events: v.wave.events,
        max_constellation: v.wave.max_constellation(),
    });
    Ok(DelaunayOutput {
        method,
        arithmetic: S::ARITHMETIC,
        triangulation: triangulation.filter(|_| wanted.triangulation),
        covered: None,
        exact_triangulation,
        tessellation: wanted
            .tessellation
            .then(|| AnyPortalgon::from(v.tessellation)),
        covered_tessellation: None,
        reduced: reduced.filter(|_| wanted.reduced).map(AnyPortalgon::from),
        laplacian,
        mass,
        stats,
        reduction,
        wave,
    })
}

/// The glued sides of a portalgon of triangles whose two triangles fail the empty-circle test:
/// the corner opposite the mate, carried into the side's plane by the gluing, lies strictly
/// inside the circle through the side's triangle ([`incircle`]: the exact sign in exact mode,
/// no tolerance). Each glued pair counted once; polygons of more than three sides are skipped.
pub(crate) fn non_delaunay_sides<S: Scalar>(p: &Portalgon<S>) -> usize {
    let is_triangle = |s| p.polygon_sides(p.owner(s)).len() == 3;
    p.sides()
        .filter(|&s| {
            let Some(t) = p.mate(s) else {
                return false;
            };
            if t.0 < s.0 || !is_triangle(s) || !is_triangle(t) {
                return false;
            }
            // The mate runs the other way: its start goes to the side's end.
            let motion = Motion::gluing(p.start_ref(t), p.end_ref(t), p.end_ref(s), p.start_ref(s));
            let apex = motion.apply(p.start_ref(p.prev_side(t)));
            let [a, b, c] = [s, p.next_side(s), p.prev_side(s)].map(|x| p.start_ref(x));
            incircle(a, b, c, &apex) == Ordering::Greater
        })
        .count()
}

impl From<Portalgon> for AnyPortalgon {
    fn from(p: Portalgon) -> Self {
        Self::F64(p)
    }
}

impl From<Portalgon<Rational>> for AnyPortalgon {
    fn from(p: Portalgon<Rational>) -> Self {
        Self::Exact(p)
    }
}
