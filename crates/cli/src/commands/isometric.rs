//! `surftopo isometric`: whether two closed polyhedral surfaces are isometric (Corollary 2 of the
//! intrinsic-Delaunay paper: their canonical Delaunay tessellations are equal), or that double
//! precision cannot decide. The canonical tessellations come from flipping (`--method flip`) or
//! from the Voronoi wave from the singular vertices (`--method voronoi`, exactly with `--exact`).

use crate::commands::delaunay::{Method, MethodOptions, load_exact, load_intrinsic};
use crate::failure::{invalid, shown};
use std::path::Path;
use surftopo_intrinsic::voronoi::{Sources, VoronoiOptions, to_f64, voronoi_delaunay};
use surftopo_intrinsic::{
    IsometryDecision, IsometryOptions, Portalgon, compare_tessellations, decide_isometry,
};

/// Exit code of `isometric` for an internal failure (1 means "not isometric" there).
pub const INTERNAL_FAILURE: u8 = 4;

/// The verdict, as an exit code: 0 isometric, 1 not isometric, 3 undecidable in double precision
/// (2 is invalid input, [`INTERNAL_FAILURE`] an internal failure).
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

/// The canonical tessellation of one input by the Voronoi wave (V = the singular vertices).
fn canonical_by_wave(path: &Path, weld: bool, exact: bool) -> anyhow::Result<Portalgon> {
    let fail = |e: &dyn std::fmt::Display| invalid(format!("{}: {e}", shown(path)));
    let options = VoronoiOptions {
        sources: Sources::Singular,
        ..VoronoiOptions::default()
    };
    if exact {
        let p = load_exact(path)?;
        let v = voronoi_delaunay(&p, &options).map_err(|e| fail(&e))?;
        Ok(to_f64(&v.tessellation))
    } else {
        let tri = load_intrinsic(path, weld)?;
        tri.validate().map_err(|e| fail(&e))?;
        let (p, _) = tri.to_portalgon();
        let v = voronoi_delaunay(&p, &options).map_err(|e| fail(&e))?;
        Ok(v.tessellation)
    }
}

/// The verdict of `--method voronoi`. In exact mode the tessellations are exact and the
/// comparison decides. In f64 a correspondence proves isometry up to the tolerance, but its
/// absence proves nothing: the flip route's three-way decision ([`decide_isometry`]) settles it.
fn decide_by_wave(a: &Path, b: &Path, weld: bool, exact: bool) -> anyhow::Result<IsometryDecision> {
    let ta = canonical_by_wave(a, weld, exact)?;
    let tb = canonical_by_wave(b, weld, exact)?;
    let options = IsometryOptions::default();
    let outcome = crate::progress::step("comparing Delaunay tessellations", || {
        compare_tessellations(&ta, &tb, options.length_tolerance, options.allow_reflection)
    })
    .map_err(|(surface, e)| invalid(format!("surface {surface}: {e}")))?;
    if outcome.is_isometric() {
        return Ok(IsometryDecision::Isometric(format!(
            "Voronoi-wave tessellations correspond: {outcome}"
        )));
    }
    if exact {
        return Ok(IsometryDecision::NotIsometric(format!(
            "exact Voronoi-wave tessellations differ: {outcome}"
        )));
    }
    decide_by_flips(a, b, weld)
}

fn decide_by_flips(a: &Path, b: &Path, weld: bool) -> anyhow::Result<IsometryDecision> {
    let first = load_intrinsic(a, weld)?;
    let second = load_intrinsic(b, weld)?;
    crate::progress::step("comparing Delaunay tessellations", || {
        decide_isometry(&first, &second, &IsometryOptions::default())
    })
    .map_err(|e| invalid(format!("{} / {}: {e}", shown(a), shown(b))))
}

/// Runs `isometric`: prints `isometric`, `not isometric` or `undecidable in double precision` on
/// stdout and the reason on stderr.
pub fn run(a: &Path, b: &Path, weld: bool, method: &MethodOptions) -> anyhow::Result<Verdict> {
    method.check()?;
    if method.method == Method::Dubois {
        return Err(crate::failure::invalid(
            "--method dubois applies to delaunay only (isometric: use --method flip or voronoi)",
        ));
    }
    let decision = if method.method == Method::Voronoi {
        decide_by_wave(a, b, weld, method.exact)?
    } else {
        decide_by_flips(a, b, weld)?
    };
    let verdict = match decision {
        IsometryDecision::Isometric(_) => "isometric",
        IsometryDecision::NotIsometric(_) => "not isometric",
        IsometryDecision::Undecidable(_) => "undecidable in double precision",
    };
    crate::output::emit(&format!("{verdict}\n"))?;
    eprintln!("{decision}");
    Ok(Verdict(decision))
}
