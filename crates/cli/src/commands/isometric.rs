//! `surftopo isometric`: whether two polyhedral surfaces are isometric (Corollary 2 of the
//! intrinsic-Delaunay paper: their canonical Delaunay tessellations are equal), or that double
//! precision cannot decide. The canonical tessellations come from flipping (`--method flip`),
//! from the Voronoi wave from the singular vertices (`--method voronoi`), or from Dubois'
//! Theorem 1 on flat surfaces (`--method dubois`: the reduction, then the wave); exactly with
//! `--exact`. `--method auto` (the default) takes dubois when both surfaces are flat needles
//! (`surftopo_intrinsic::choose_method` on each), otherwise flip (the exact wave with `--exact`).
//! A mesh with boundary loops, non-orientable pieces or several pieces (on either side) is
//! compared by `surftopo_intrinsic::decide_isometry_on_cover` (flipping on its closed cover);
//! the wave and Theorem 1 are refused there.

use crate::args::{JsonArg, WeldArg};
use crate::commands::delaunay::{
    Method, MethodOptions, is_json_input, load_exact, load_intrinsic, load_json,
};
use crate::failure::{invalid, shown};
use std::path::{Path, PathBuf};
use surftopo_intrinsic::dubois::{FlatDelaunayError, first_cone_point};
use surftopo_intrinsic::geometry::Tolerances;
use surftopo_intrinsic::voronoi::Sources;
use surftopo_intrinsic::{
    CoveredTriangulation, DEFAULT_ANGLE_TOLERANCE, DelaunayInput, DelaunayMethod, DelaunayOutputs,
    DelaunayRequest, IntrinsicTriangulation, IsometryDecision, IsometryOptions, Portalgon,
    choose_method, choose_method_for_triangulation, compare_tessellations, decide_isometry,
    decide_isometry_on_cover, intrinsic_delaunay_reporting,
};

/// The arguments of `isometric`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// First surface (mesh or portalgon JSON).
    pub a: PathBuf,
    /// Second surface (mesh or portalgon JSON).
    pub b: PathBuf,
    #[command(flatten)]
    pub weld: WeldArg,
    /// How the canonical tessellations are computed.
    #[command(flatten)]
    pub method: MethodOptions,
    /// Lengths and polygon corners of the two canonical tessellations agree when they are
    /// within this fraction of the longest side (0 < T < 1; the undecidable check also tries it
    /// 100 times larger and smaller).
    #[arg(long, value_name = "T", default_value_t = Tolerances::DEFAULT.isometry_length)]
    pub tolerance: f64,
    /// Print `isometric` (true, false, or null when undecided), `verdict`, `reason`, `method`
    /// and `tolerance` as JSON instead of the verdict line and the reason on stderr.
    #[command(flatten)]
    pub json: JsonArg,
}

/// What `--json` prints.
#[derive(serde::Serialize)]
struct Report<'a> {
    /// true, false, or null when double precision or the method cannot decide.
    isometric: Option<bool>,
    /// `isometric`, `not isometric`, `undecidable in double precision` or `undecided` (a flat
    /// vertex on a surface with boundary or without orientation).
    verdict: &'static str,
    /// Why, in words.
    reason: &'a str,
    /// The method run (`flip`, `voronoi`, `dubois`; `auto` as asked).
    method: String,
    /// `--tolerance`.
    tolerance: f64,
}

/// The verdict, as an exit code: 0 isometric, 1 not isometric, 3 undecidable in double precision
/// or undecided (2 is invalid input, [`crate::failure::ISOMETRIC_INTERNAL_FAILURE`] an internal failure).
pub struct Verdict(IsometryDecision);

impl Verdict {
    /// The exit code of the verdict.
    pub fn exit_code(&self) -> u8 {
        match self.0 {
            IsometryDecision::Isometric(_) => 0,
            IsometryDecision::NotIsometric(_) => 1,
            IsometryDecision::Undecidable(_) | IsometryDecision::Undecided(_) => 3,
        }
    }
}

/// The canonical tessellation (V = the singular vertices) of a surface by the wave
/// (`--method voronoi`) or by Theorem 1 on a flat surface (`--method dubois`), in f64 for the
/// comparison. Errors (an invalid surface, a tolerance the f64 dual cannot settle) name `path`.
fn canonical(
    path: &Path,
    input: DelaunayInput,
    method: Method,
    options: &MethodOptions,
) -> anyhow::Result<Portalgon> {
    let request = DelaunayRequest {
        method: method.into(),
        vertices: Sources::Singular,
        outputs: DelaunayOutputs {
            tessellation: true,
            ..DelaunayOutputs::default()
        },
        ..options.request()
    };
    let out =
        crate::progress::steps(|progress| intrinsic_delaunay_reporting(input, &request, progress))
            .map_err(|e| invalid(format!("{}: {e}", shown(path))))?;
    Ok(out
        .tessellation
        .expect("the tessellation is asked for")
        .to_f64())
}

/// Refuses a cone point for `--method dubois`, which takes flat surfaces only here (Corollary
/// 2's canonical tessellations of flat surfaces; cone points go to flip or voronoi).
fn refuse_cone_point(
    path: &Path,
    p: &surftopo_intrinsic::Portalgon<impl surftopo_intrinsic::geometry::Scalar>,
    exact: bool,
) -> anyhow::Result<()> {
    let Some((label, class, side)) = first_cone_point(p, DEFAULT_ANGLE_TOLERANCE) else {
        return Ok(());
    };
    Err(invalid(if exact {
        let e = FlatDelaunayError::ConePoint {
            label,
            class,
            side: side.idx(),
        };
        format!("{}: {e}", shown(path))
    } else {
        format!(
            "{}: a cone point: --method dubois takes flat surfaces only; use --method flip or voronoi",
            shown(path)
        )
    }))
}

/// Whether two canonical tessellations correspond.
fn correspond(
    ta: &Portalgon,
    tb: &Portalgon,
    options: &IsometryOptions,
) -> anyhow::Result<surftopo_intrinsic::Outcome> {
    crate::progress::step("comparing Delaunay tessellations", || {
        compare_tessellations(ta, tb, options.length_tolerance, options.allow_reflection)
    })
    .map_err(|(surface, e)| invalid(format!("surface {surface}: {e}")))
}

/// The verdict of `--method voronoi` and `--method dubois`. In exact mode the tessellations are
/// exact and the comparison decides. In f64 a correspondence proves isometry up to the
/// tolerance, but its absence, or a surface the f64 dual refuses, proves nothing: the flip
/// route's three-way decision ([`decide_isometry`]) settles it, on the triangulations already
/// read. Dubois refuses cone points (exit 2) when asked for by name.
fn decide_by_tessellations(
    a: &Path,
    b: &Path,
    weld: bool,
    method: MethodOptions,
    options: &IsometryOptions,
) -> anyhow::Result<IsometryDecision> {
    let isometric = |method: Method, outcome: surftopo_intrinsic::Outcome| {
        IsometryDecision::Isometric(format!("by the {}, {}", what(method), outcome.reason()))
    };
    if method.exact {
        let (pa, pb) = (load_exact(a)?, load_exact(b)?);
        let resolved = match method.method {
            Method::Auto
                if choose_method(&pa) == DelaunayMethod::Dubois
                    && choose_method(&pb) == DelaunayMethod::Dubois =>
            {
                Method::Dubois
            }
            Method::Auto => Method::Voronoi,
            m => m,
        };
        if resolved == Method::Dubois {
            refuse_cone_point(a, &pa, true)?;
        }
        let ta = canonical(a, DelaunayInput::Exact(pa), resolved, &method)?;
        if resolved == Method::Dubois {
            refuse_cone_point(b, &pb, true)?;
        }
        let tb = canonical(b, DelaunayInput::Exact(pb), resolved, &method)?;
        let outcome = correspond(&ta, &tb, options)?;
        return Ok(if outcome.is_isometric() {
            isometric(resolved, outcome)
        } else {
            IsometryDecision::NotIsometric(format!(
                "by the exact {}, {}",
                what(resolved),
                outcome.reason()
            ))
        });
    }
    let (first, second) = (load_valid(a, weld)?, load_valid(b, weld)?);
    decide_closed(a, b, first, second, method, options)
}

/// The verdict on two closed orientable surfaces read in double precision: the flip route's
/// three-way decision ([`decide`]) for `--method flip`, otherwise the tessellations of the
/// method asked for (see [`decide_by_tessellations`]).
fn decide_closed(
    a: &Path,
    b: &Path,
    first: IntrinsicTriangulation,
    second: IntrinsicTriangulation,
    method: MethodOptions,
    options: &IsometryOptions,
) -> anyhow::Result<IsometryDecision> {
    let isometric = |method: Method, outcome: surftopo_intrinsic::Outcome| {
        IsometryDecision::Isometric(format!("by the {}, {}", what(method), outcome.reason()))
    };
    if method.method == Method::Flip {
        return decide(a, b, &first, &second, options);
    }
    let resolved = match method.method {
        Method::Auto
            if choose_method_for_triangulation(&first) == DelaunayMethod::Dubois
                && choose_method_for_triangulation(&second) == DelaunayMethod::Dubois =>
        {
            Method::Dubois
        }
        Method::Auto => return decide(a, b, &first, &second, options),
        m => m,
    };
    if resolved == Method::Dubois {
        // Asked for by name (or chosen), a cone point is refused rather than decided otherwise.
        for (path, tri) in [(a, &first), (b, &second)] {
            refuse_cone_point(path, &tri.to_portalgon().0, false)?;
        }
    }
    let of = |path: &Path, tri: &IntrinsicTriangulation| {
        canonical(path, DelaunayInput::Lengths(tri.clone()), resolved, &method)
    };
    let tessellations = of(a, &first).and_then(|ta| Ok((ta, of(b, &second)?)));
    if let Ok((ta, tb)) = tessellations {
        let outcome = correspond(&ta, &tb, options)?;
        if outcome.is_isometric() {
            return Ok(isometric(resolved, outcome));
        }
    }
    decide(a, b, &first, &second, options)
}

/// What a method's canonical tessellation is called in a reason.
fn what(method: Method) -> &'static str {
    if method == Method::Dubois {
        "Theorem 1 (Dubois) tessellation"
    } else {
        "Voronoi wave"
    }
}

/// An input of `isometric` read in double precision.
enum Input {
    /// One closed orientable piece (a mesh, or a portalgon file): every method.
    Closed(IntrinsicTriangulation),
    /// Any other surface (boundary loops, non-orientable pieces, several pieces): flipping.
    Any(CoveredTriangulation),
}

impl Input {
    fn into_covered(self) -> CoveredTriangulation {
        match self {
            Input::Closed(tri) => CoveredTriangulation::from_closed(tri),
            Input::Any(tri) => tri,
        }
    }
}

/// Reads an input: a portalgon file of one closed oriented piece as its triangulation, of any
/// other kind (format version 2, boundary sides, several pieces) on its closed cover
/// ([`load_json`]); a mesh file of any kind on its closed cover unless it is one closed
/// orientable piece.
fn load_input(path: &Path, weld: bool) -> anyhow::Result<Input> {
    if is_json_input(path)? {
        return match load_json(path)? {
            DelaunayInput::Covered(tri) => {
                crate::commands::delaunay::validated(path, tri.cover())?;
                Ok(Input::Any(tri))
            }
            DelaunayInput::Lengths(tri) => {
                crate::commands::delaunay::validated(path, &tri)?;
                Ok(Input::Closed(tri))
            }
            DelaunayInput::Exact(_) => Err(anyhow::anyhow!(
                "{}: read in double precision, but given as exact",
                shown(path)
            )),
        };
    }
    let name = crate::input::name(path);
    let loaded = crate::input::read_covered(path, weld)?;
    let fail = |e: surftopo_intrinsic::GeometryError| invalid(format!("{name}: {e}"));
    let surface = loaded.surface;
    if surface.cover.is_plain() && loaded.report.surfaces.len() <= 1 {
        let s = surface
            .into_plain()
            .expect("a plain cover is a closed orientable surface");
        let tri = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).map_err(fail)?;
        crate::commands::delaunay::validated(path, &tri)?;
        return Ok(Input::Closed(tri));
    }
    let tri = CoveredTriangulation::from_cover(&surface.cover, &surface.positions).map_err(fail)?;
    crate::commands::delaunay::validated(path, tri.cover())?;
    Ok(Input::Any(tri))
}

/// The verdict on two inputs of which one at least is not one closed orientable piece
/// ([`decide_isometry_on_cover`]); the wave and Theorem 1 are refused (Dubois' paper treats
/// closed surfaces).
fn decide_any(
    a: &Path,
    b: &Path,
    first: Input,
    second: Input,
    method: MethodOptions,
    options: &IsometryOptions,
) -> anyhow::Result<IsometryDecision> {
    if matches!(method.method, Method::Voronoi | Method::Dubois) {
        let path = if matches!(first, Input::Any(_)) { a } else { b };
        return Err(invalid(format!(
            "{}: --method {} takes closed orientable surfaces of one piece; this one has \
             boundary loops, no orientation or several pieces: use --method flip (auto takes it)",
            shown(path),
            crate::args::value_name(&method.method)
        )));
    }
    let (first, second) = (first.into_covered(), second.into_covered());
    crate::progress::step("comparing Delaunay tessellations", || {
        decide_isometry_on_cover(&first, &second, options)
    })
    .map_err(|e| invalid(format!("{} / {}: {e}", shown(a), shown(b))))
}

/// The flip route's three-way decision.
fn decide(
    a: &Path,
    b: &Path,
    first: &IntrinsicTriangulation,
    second: &IntrinsicTriangulation,
    options: &IsometryOptions,
) -> anyhow::Result<IsometryDecision> {
    crate::progress::step("comparing Delaunay tessellations", || {
        decide_isometry(first, second, options)
    })
    .map_err(|e| invalid(format!("{} / {}: {e}", shown(a), shown(b))))
}

/// Runs `isometric`: prints `isometric`, `not isometric` or `undecidable in double precision` on
/// stdout and the reason on stderr (`--json`: both as JSON on stdout).
pub fn run(args: &Args) -> anyhow::Result<Verdict> {
    let decision = decide_args(args)?;
    let (isometric, verdict, reason) = match &decision {
        IsometryDecision::Isometric(reason) => (Some(true), "isometric", reason),
        IsometryDecision::NotIsometric(reason) => (Some(false), "not isometric", reason),
        IsometryDecision::Undecidable(reason) => (None, "undecidable in double precision", reason),
        IsometryDecision::Undecided(reason) => (None, "undecided", reason),
    };
    if args.json.json {
        crate::output::print_json(&Report {
            isometric,
            verdict,
            reason,
            method: crate::args::value_name(&args.method.method),
            tolerance: args.tolerance,
        })?;
    } else {
        crate::output::emit(&format!("{verdict}\n"))?;
        stderr_println!("{decision}");
    }
    Ok(Verdict(decision))
}

/// The decision of `isometric` on `args`, printing nothing.
///
/// # Errors
/// Invalid input or options (exit 2), an internal failure.
pub fn decide_args(args: &Args) -> anyhow::Result<IsometryDecision> {
    let (a, b, weld, method) = (&args.a, &args.b, args.weld.weld, &args.method);
    method.check()?;
    if !(args.tolerance > 0.0 && args.tolerance < 1.0) {
        return Err(invalid(format!(
            "--tolerance {}: a fraction of the longest side, above 0 and below 1",
            args.tolerance
        )));
    }
    let options = IsometryOptions {
        length_tolerance: args.tolerance,
        ..IsometryOptions::default()
    };
    let decision = if method.exact {
        decide_by_tessellations(a, b, weld, *method, &options)
    } else {
        load_input(a, weld)
            .and_then(|first| Ok((first, load_input(b, weld)?)))
            .and_then(|inputs| match inputs {
                (Input::Closed(first), Input::Closed(second)) => {
                    decide_closed(a, b, first, second, *method, &options)
                }
                (first, second) => decide_any(a, b, first, second, *method, &options),
            })
    };
    match decision {
        Err(e) if crate::failure::exit_code(&e) == crate::failure::NUMERICAL_FAILURE => {
            Ok(IsometryDecision::Undecidable(crate::failure::message(&e)))
        }
        other => other,
    }
}

/// An input read in double precision whose lengths make valid triangles, as `delaunay` asks
/// ([`crate::commands::delaunay::validated`]): degenerate input is refused (exit 2), or, when
/// only double precision makes it degenerate (exact corners), a numerical failure that
/// [`decide_args`] reports as undecidable in double precision (exit 3).
fn load_valid(path: &Path, weld: bool) -> anyhow::Result<IntrinsicTriangulation> {
    let tri = load_intrinsic(path, weld)?;
    crate::commands::delaunay::validated(path, &tri)?;
    Ok(tri)
}
