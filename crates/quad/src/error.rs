//! Errors of the quadrangulation pipeline.

use surftopo_irreducible::IrreducibleError;
use surftopo_matching::AugmentError;
use thiserror::Error;

/// Why a mesh could not be quadrangulated. No variant ever comes with a partial result.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum QuadError {
    /// The mesh has no live face.
    #[error("the mesh has no faces")]
    Empty,
    /// LRS (through Ramaswami–Siqueira) needs a simplicial surface; the error names the element.
    #[error("LRS needs a simplicial triangulation: {0}")]
    NotSimplicial(#[from] IrreducibleError),
    /// The dual graph has no perfect matching. Only possible when the mesh is not simplicial (a
    /// primal loop whose dual edge is a bridge); the search that proves it is described.
    #[error("the triangles cannot all be paired (the mesh is not simplicial): {0}")]
    NoPerfectPairing(AugmentError),
    /// The algorithm does not take this kind of surface (the message names the piece and what
    /// to use instead).
    #[error("{0}")]
    Unsupported(String),
    /// The exact quality pairing of a surface whose pieces must leave many triangles unpaired
    /// would need an auxiliary graph beyond its bound (see
    /// `surftopo_matching::weighted::maximum`); the fast objective pairs it.
    #[error("{0}")]
    QualityTooLarge(String),
    /// A broken invariant: a bug, reported with diagnostics instead of a wrong result.
    #[error("internal error (a bug, please report): {0}")]
    Internal(String),
}
