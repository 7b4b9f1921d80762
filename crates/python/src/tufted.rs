//! The tufted-cover Laplacian (Sharp & Crane, "A Laplacian for Nonmanifold Triangle Meshes",
//! 2020) behind `laplacian(V, F, tufted=True)`, and the rule that takes it for non-manifold
//! input.

use crate::errors::{Failure, invalid};
use crate::intrinsic::Csr;
use surftopo_intrinsic::{TuftedError, TuftedLaplacian, TuftedOptions, tufted_laplacian};
use surftopo_mesh::BuildError;

/// Whether a build error says the soup is not a manifold (a non-manifold edge or vertex, a
/// duplicate face): what the tufted cover takes and the closed-surface path refuses.
pub fn is_non_manifold(failure: &Failure) -> bool {
    matches!(
        failure,
        Failure::Build(
            BuildError::NonManifoldEdge { .. }
                | BuildError::NonManifoldVertex { .. }
                | BuildError::DuplicateFace { .. }
        )
    )
}

/// The failure of a tufted error: the soup's problem, the face's geometry, the flips, or the
/// factor.
fn failure(e: TuftedError) -> Failure {
    match e {
        TuftedError::Input(b) => Failure::Build(b),
        TuftedError::Degenerate(g) => Failure::Geometry(g),
        TuftedError::Flip(d) => Failure::Delaunay(d),
        e @ TuftedError::InvalidMollifyFactor(_) => invalid(e.to_string()),
    }
}

/// `surftopo_intrinsic::tufted_laplacian` with its errors as failures (call without the GIL).
pub fn tufted(
    positions: &[[f64; 3]],
    triangles: &[[u32; 3]],
    options: &TuftedOptions,
) -> Result<TuftedLaplacian, Failure> {
    tufted_laplacian(positions, triangles, options).map_err(failure)
}

/// The tufted Laplacian and mass matrix of `(positions, triangles)` as CSR matrices with one row
/// per input vertex (call without the GIL).
pub fn tufted_csr(
    positions: &[[f64; 3]],
    triangles: &[[u32; 3]],
    options: &TuftedOptions,
) -> Result<(Csr, Csr), Failure> {
    let TuftedLaplacian {
        laplacian, mass, ..
    } = tufted(positions, triangles, options)?;
    let rows: Vec<u32> = (0..positions.len() as u32).collect();
    Ok((
        Csr::new(laplacian, &rows, positions.len()),
        Csr::new(mass, &rows, positions.len()),
    ))
}
