//! `surftopo isometric`: whether two closed polyhedral surfaces are isometric (Corollary 2 of the
//! intrinsic-Delaunay paper: their canonical Delaunay tessellations are equal). The canonical
//! tessellations come from flipping (`--method flip`) or from the Voronoi wave from the singular
//! vertices (`--method voronoi`, exactly with `--exact`).

use crate::commands::delaunay::{Method, MethodOptions, load_exact, load_intrinsic};
use crate::failure::invalid;
use std::path::Path;
use surftopo_intrinsic::voronoi::{Sources, VoronoiOptions, to_f64, voronoi_delaunay};
use surftopo_intrinsic::{IsometryOptions, Portalgon, compare_tessellations, isometric};

/// The canonical tessellation of one input by the Voronoi wave (V = the singular vertices).
fn canonical_by_wave(path: &Path, weld: bool, exact: bool) -> anyhow::Result<Portalgon> {
    let fail = |e: &dyn std::fmt::Display| invalid(format!("{}: {e}", path.display()));
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

/// Runs `isometric`; returns whether the surfaces are isometric (exit 0) or not (exit 1).
pub fn run(a: &Path, b: &Path, weld: bool, method: &MethodOptions) -> anyhow::Result<bool> {
    method.check()?;
    let outcome = if method.method == Method::Voronoi {
        let ta = canonical_by_wave(a, weld, method.exact)?;
        let tb = canonical_by_wave(b, weld, method.exact)?;
        let options = IsometryOptions::default();
        crate::progress::step("comparing Delaunay tessellations", || {
            compare_tessellations(&ta, &tb, options.length_tolerance, options.allow_reflection)
        })
        .map_err(|(surface, e)| invalid(format!("surface {surface}: {e}")))?
    } else {
        let first = load_intrinsic(a, weld)?;
        let second = load_intrinsic(b, weld)?;
        crate::progress::step("comparing Delaunay tessellations", || {
            isometric(first, second, &IsometryOptions::default())
        })
        .map_err(|e| invalid(format!("{} / {}: {e}", a.display(), b.display())))?
    };
    let verdict = if outcome.is_isometric() {
        "isometric"
    } else {
        "not isometric"
    };
    crate::output::emit(&format!("{verdict}\n"))?;
    eprintln!("{outcome}");
    Ok(outcome.is_isometric())
}
