//! `surftopo isometric`: whether two closed polyhedral surfaces are isometric (Corollary 2 of the
//! intrinsic-Delaunay paper: their canonical Delaunay tessellations are equal), or that double
//! precision cannot decide. The canonical tessellations come from flipping (`--method flip`),
//! from the Voronoi wave from the singular vertices (`--method voronoi`), or from Dubois'
//! Theorem 1 on flat surfaces (`--method dubois`: the reduction, then the wave); exactly with
//! `--exact`. `--method auto` (the default) takes dubois when both surfaces are flat needles
//! (`surftopo_intrinsic::method_choice` on each), otherwise flip (the exact wave with `--exact`).

use crate::args::{JsonArg, WeldArg};
use crate::commands::delaunay::{Method, MethodOptions, load_exact, load_intrinsic};
use crate::failure::{invalid, shown};
use std::path::{Path, PathBuf};
use surftopo_intrinsic::dubois::{FlatDelaunayOptions, ReduceOptions, delaunay_tessellation_flat};
use surftopo_intrinsic::geometry::Scalar;
use surftopo_intrinsic::method_choice::{
    Method as Choice, choose_method, choose_method_for_triangulation,
};
use surftopo_intrinsic::voronoi::{Sources, VoronoiOptions, to_f64, voronoi_delaunay};
use surftopo_intrinsic::{
    ISOMETRY_LENGTH_TOLERANCE, IntrinsicTriangulation, IsometryDecision, IsometryOptions,
    Portalgon, compare_tessellations, decide_isometry,
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
    #[arg(long, value_name = "T", default_value_t = ISOMETRY_LENGTH_TOLERANCE)]
    pub tolerance: f64,
    /// Print `isometric` (true, false, or null when undecidable), `verdict`, `reason`, `method`
    /// and `tolerance` as JSON instead of the verdict line and the reason on stderr.
    #[command(flatten)]
    pub json: JsonArg,
}

/// What `--json` prints.
#[derive(serde::Serialize)]
struct Report<'a> {
    /// true, false, or null when double precision cannot decide.
    isometric: Option<bool>,
    /// `isometric`, `not isometric` or `undecidable in double precision`.
    verdict: &'static str,
    /// Why, in words.
    reason: &'a str,
    /// The method run (`flip`, `voronoi`, `dubois`; `auto` as asked).
    method: String,
    /// `--tolerance`.
    tolerance: f64,
}

/// The verdict, as an exit code: 0 isometric, 1 not isometric, 3 undecidable in double precision
/// (2 is invalid input, [`crate::failure::ISOMETRIC_INTERNAL_FAILURE`] an internal failure).
pub struct Verdict(IsometryDecision);

impl Verdict {
    /// The exit code of the verdict.
    pub fn exit_code(&self) -> u8 {
        match self.0 {
            IsometryDecision::Isometric(_) => 0,
            IsometryDecision::NotIsometric(_) => 1,
            IsometryDecision::Undecidable(_) => 3,
        }
    }
}

/// The options of the wave for a canonical tessellation (V = the singular vertices).
fn singular_wave() -> VoronoiOptions {
    VoronoiOptions {
        sources: Sources::Singular,
        ..VoronoiOptions::default()
    }
}

/// The canonical tessellation of a portalgon by the wave from its singular vertices
/// (`--method voronoi`) or by Theorem 1 on a flat surface (`--method dubois`), in f64 for the
/// comparison. Errors (a cone point for dubois, a tolerance the f64 dual cannot settle) name
/// `path`.
fn canonical<S: Scalar>(
    path: &Path,
    p: &surftopo_intrinsic::Portalgon<S>,
    method: Method,
    reduce: ReduceOptions,
) -> anyhow::Result<Portalgon> {
    let fail = |e: &dyn std::fmt::Display| invalid(format!("{}: {e}", shown(path)));
    let tessellation = if method == Method::Dubois {
        crate::progress::step("reducing (Dubois, Section 4) and running the wave", || {
            let options = FlatDelaunayOptions {
                reduce,
                ..FlatDelaunayOptions::default()
            };
            delaunay_tessellation_flat(p, &options)
        })
        .map_err(|e| fail(&e))?
        .delaunay
        .tessellation
    } else {
        voronoi_delaunay(p, &singular_wave())
            .map_err(|e| fail(&e))?
            .tessellation
    };
    Ok(to_f64(&tessellation))
}

/// The canonical tessellation of an intrinsic triangulation in f64 (see [`canonical`]).
fn canonical_of_triangulation(
    path: &Path,
    tri: &IntrinsicTriangulation,
    method: Method,
    reduce: ReduceOptions,
) -> anyhow::Result<Portalgon> {
    let (p, _) = tri.to_portalgon();
    canonical(path, &p, method, reduce)
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
    let (exact, reduce, method) = (method.exact, method.reduce_options(), method.method);
    let what = |method: Method| {
        if method == Method::Dubois {
            "Theorem 1 (Dubois) tessellation"
        } else {
            "Voronoi wave"
        }
    };
    let isometric = |method: Method, outcome: surftopo_intrinsic::Outcome| {
        IsometryDecision::Isometric(format!("by the {}, {}", what(method), outcome.reason()))
    };
    if exact {
        let (pa, pb) = (load_exact(a)?, load_exact(b)?);
        let method = match method {
            Method::Auto
                if choose_method(&pa) == Choice::Dubois && choose_method(&pb) == Choice::Dubois =>
            {
                Method::Dubois
            }
            Method::Auto => Method::Voronoi,
            m => m,
        };
        let (ta, tb) = (
            canonical(a, &pa, method, reduce)?,
            canonical(b, &pb, method, reduce)?,
        );
        let outcome = correspond(&ta, &tb, options)?;
        return Ok(if outcome.is_isometric() {
            isometric(method, outcome)
        } else {
            IsometryDecision::NotIsometric(format!(
                "by the exact {}, {}",
                what(method),
                outcome.reason()
            ))
        });
    }
    let (first, second) = (load_valid(a, weld)?, load_valid(b, weld)?);
    let method = match method {
        Method::Auto
            if choose_method_for_triangulation(&first) == Choice::Dubois
                && choose_method_for_triangulation(&second) == Choice::Dubois =>
        {
            Method::Dubois
        }
        Method::Auto => return decide(a, b, &first, &second, options),
        m => m,
    };
    if method == Method::Dubois {
        // Asked for by name (or chosen), a cone point is refused rather than decided otherwise.
        for (path, tri) in [(a, &first), (b, &second)] {
            let (p, _) = tri.to_portalgon();
            if surftopo_intrinsic::dubois::first_cone_point(
                &p,
                surftopo_intrinsic::DEFAULT_ANGLE_TOLERANCE,
            )
            .is_some()
            {
                return Err(invalid(format!(
                    "{}: a cone point: --method dubois takes flat surfaces only; use --method flip or voronoi",
                    shown(path)
                )));
            }
        }
    }
    let tessellations = canonical_of_triangulation(a, &first, method, reduce)
        .and_then(|ta| Ok((ta, canonical_of_triangulation(b, &second, method, reduce)?)));
    if let Ok((ta, tb)) = tessellations {
        let outcome = correspond(&ta, &tb, options)?;
        if outcome.is_isometric() {
            return Ok(isometric(method, outcome));
        }
    }
    decide(a, b, &first, &second, options)
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
    let decision = if method.method == Method::Flip {
        load_valid(a, weld)
            .and_then(|first| Ok((first, load_valid(b, weld)?)))
            .and_then(|(first, second)| decide(a, b, &first, &second, &options))
    } else {
        decide_by_tessellations(a, b, weld, *method, &options)
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
