//! The same surface with its triangles listed in a random order: what a mesh written by a tool
//! that does not keep the face order looks like, for measuring how algorithms depend on it.

use crate::Surface;
use rand::SeedableRng;
use rand::seq::SliceRandom;
use rand_chacha::ChaCha8Rng;

/// A copy of `surface` whose triangles are listed in a seeded random order (Fisher–Yates);
/// vertices, positions and each triangle's orientation are unchanged, ids dense. O(F). Same seed,
/// same order.
pub fn shuffle_faces(surface: &Surface, seed: u64) -> Surface {
    let (positions, mut triangles) = surface.to_triangles();
    triangles.shuffle(&mut ChaCha8Rng::seed_from_u64(seed));
    Surface::from_triangles(positions, &triangles)
        .expect("the triangles of a closed surface, reordered, are the same closed surface")
}
