//! `surftopo isometric`: whether two closed polyhedral surfaces are isometric (Corollary 2 of the
//! intrinsic-Delaunay paper: their canonical Delaunay tessellations are equal), or that double
//! precision cannot decide. The canonical tessellations come from flipping (`--method flip`) or
//! from the Voronoi wave from the singular vertices (`--method voronoi`, exactly with `--exact`).

use crate::args::{JsonArg, WeldArg};
use crate::commands::delaunay::{Method, MethodOptions, load_exact, load_intrinsic};
use crate::failure::{invalid, shown};
use std::path::{Path, PathBuf};
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
    /// `flip` or `voronoi`.
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

/// The canonical tessellation of an exact portalgon file by the exact Voronoi wave.
fn canonical_by_exact_wave(path: &Path) -> anyhow::Result<Portalgon> {
    let p = load_exact(path)?;
    let v = voronoi_delaunay(&p, &singular_wave())
        .map_err(|e| invalid(format!("{}: {e}", shown(path))))?;
    Ok(to_f64(&v.tessellation))
}

/// The canonical tessellation of an intrinsic triangulation by the f64 Voronoi wave.
fn canonical_by_wave(path: &Path, tri: &IntrinsicTriangulation) -> anyhow::Result<Portalgon> {
    let fail = |e: &dyn std::fmt::Display| invalid(format!("{}: {e}", shown(path)));
    tri.validate().map_err(|e| fail(&e))?;
    let (p, _) = tri.to_portalgon();
    let v = voronoi_delaunay(&p, &singular_wave()).map_err(|e| fail(&e))?;
    Ok(v.tessellation)
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

/// The verdict of `--method voronoi`. In exact mode the tessellations are exact and the
/// comparison decides. In f64 a correspondence proves isometry up to the tolerance, but its
/// absence, or a surface the f64 dual refuses, proves nothing: the flip route's three-way
/// decision ([`decide_isometry`]) settles it, on the triangulations already read.
fn decide_by_wave(
    a: &Path,
    b: &Path,
    weld: bool,
    exact: bool,
    options: &IsometryOptions,
) -> anyhow::Result<IsometryDecision> {
    let isometric = |outcome: surftopo_intrinsic::Outcome| {
        IsometryDecision::Isometric(format!("by the Voronoi wave, {}", outcome.reason()))
    };
    if exact {
        let (ta, tb) = (canonical_by_exact_wave(a)?, canonical_by_exact_wave(b)?);
        let outcome = correspond(&ta, &tb, options)?;
        return Ok(if outcome.is_isometric() {
            isometric(outcome)
        } else {
            IsometryDecision::NotIsometric(format!(
                "by the exact Voronoi wave, {}",
                outcome.reason()
            ))
        });
    }
    let (first, second) = (load_intrinsic(a, weld)?, load_intrinsic(b, weld)?);
    // The f64 wave's dual may refuse a surface (a tolerance it cannot settle): the flip route
    // then decides, as it does when no correspondence is found.
    let waves =
        canonical_by_wave(a, &first).and_then(|ta| Ok((ta, canonical_by_wave(b, &second)?)));
    if let Ok((ta, tb)) = waves {
        let outcome = correspond(&ta, &tb, options)?;
        if outcome.is_isometric() {
            return Ok(isometric(outcome));
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
    let (a, b, weld, method) = (&args.a, &args.b, args.weld.weld, &args.method);
    method.check()?;
    if method.method == Method::Dubois {
        return Err(crate::failure::invalid(
            "--method dubois applies to delaunay only (isometric: use --method flip or voronoi)",
        ));
    }
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
    let decision = if method.method == Method::Voronoi {
        decide_by_wave(a, b, weld, method.exact, &options)?
    } else {
        let (first, second) = (load_intrinsic(a, weld)?, load_intrinsic(b, weld)?);
        decide(a, b, &first, &second, &options)?
    };
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
            method: crate::args::value_name(&method.method),
            tolerance: args.tolerance,
        })?;
    } else {
        crate::output::emit(&format!("{verdict}\n"))?;
        eprintln!("{decision}");
    }
    Ok(Verdict(decision))
}
