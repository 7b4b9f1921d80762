//! `surftopo isometric`: whether two closed polyhedral surfaces are isometric (Corollary 2 of the
//! intrinsic-Delaunay paper: their canonical Delaunay tessellations are equal), or that double
//! precision cannot decide.

use crate::commands::delaunay::load_intrinsic;
use crate::failure::{invalid, shown};
use std::path::Path;
use surftopo_intrinsic::{IsometryDecision, IsometryOptions, decide_isometry};

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

/// Runs `isometric`: prints `isometric`, `not isometric` or `undecidable in double precision` on
/// stdout and the reason on stderr.
pub fn run(a: &Path, b: &Path, weld: bool) -> anyhow::Result<Verdict> {
    let first = load_intrinsic(a, weld)?;
    let second = load_intrinsic(b, weld)?;
    let decision = crate::progress::step("comparing Delaunay tessellations", || {
        decide_isometry(&first, &second, &IsometryOptions::default())
    })
    .map_err(|e| invalid(format!("{} / {}: {e}", shown(a), shown(b))))?;
    let verdict = match decision {
        IsometryDecision::Isometric(_) => "isometric",
        IsometryDecision::NotIsometric(_) => "not isometric",
        IsometryDecision::Undecidable(_) => "undecidable in double precision",
    };
    crate::output::emit(&format!("{verdict}\n"))?;
    eprintln!("{decision}");
    Ok(Verdict(decision))
}
