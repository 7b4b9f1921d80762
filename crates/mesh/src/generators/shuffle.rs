//! The same surface with its triangles listed in a random order: what a mesh written by a tool
//! that does not keep the face order looks like, for measuring how algorithms depend on it.

use crate::Surface;
use crate::cover::CoveredSurface;
use rand::SeedableRng;
use rand::seq::SliceRandom;
use rand_chacha::ChaCha8Rng;

/// A copy of `surface` whose triangles are listed in a seeded random order (Fisher–Yates);
/// vertices, positions and each triangle's orientation are unchanged, ids dense. O(F). Same seed,
/// same order.
pub fn shuffle_faces(surface: &Surface, seed: u64) -> Surface {
    shuffle_faces_covered(&surface.clone().into(), seed)
        .into_plain()
        .expect("reordered, a closed orientable surface stays so")
}

/// [`shuffle_faces`] on any compact surface.
pub fn shuffle_faces_covered(surface: &CoveredSurface, seed: u64) -> CoveredSurface {
    let (positions, mut triangles) = surface.to_triangles();
    triangles.shuffle(&mut ChaCha8Rng::seed_from_u64(seed));
    CoveredSurface::from_triangles(positions, &triangles)
        .expect("the triangles of a surface, reordered, are the same surface")
        .0
}
