//! `surftopo isometric`: whether two closed polyhedral surfaces are isometric (Corollary 2 of the
//! intrinsic-Delaunay paper: their canonical Delaunay tessellations are equal).

use crate::commands::delaunay::load_intrinsic;
use crate::failure::invalid;
use std::path::Path;
use surftopo_intrinsic::{IsometryOptions, isometric};

/// Runs `isometric`; returns whether the surfaces are isometric (exit 0) or not (exit 1).
pub fn run(a: &Path, b: &Path, weld: bool) -> anyhow::Result<bool> {
    let first = load_intrinsic(a, weld)?;
    let second = load_intrinsic(b, weld)?;
    let outcome = crate::progress::step("comparing Delaunay tessellations", || {
        isometric(first, second, &IsometryOptions::default())
    })
    .map_err(|e| invalid(format!("{} / {}: {e}", a.display(), b.display())))?;
    let verdict = if outcome.is_isometric() {
        "isometric"
    } else {
        "not isometric"
    };
    crate::output::emit(&format!("{verdict}\n"))?;
    eprintln!("{outcome}");
    Ok(outcome.is_isometric())
}
