//! Random simplicial edge flips: irregular connectivity on a fixed vertex set.

use super::Surface;
use crate::ids::EdgeId;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A copy of `surface` after `flips` random edge flips, each keeping the mesh simplicial
/// ([`crate::SurfaceMesh::can_flip_simplicial`]); positions are unchanged, ids dense.
///
/// Edges are drawn uniformly among the live edges; a drawn edge that cannot be flipped is skipped
/// (not counted). When `E` draws in a row fail, all edges are scanned: if none can be flipped
/// (e.g. the tetrahedron), the flips stop early, so the call always ends. Expected
/// O(flips * degree) time when a constant fraction of the edges is flippable. Same seed, same
/// result.
pub fn random_flips(surface: &Surface, flips: usize, seed: u64) -> Surface {
    let mut out = surface.clone();
    out.compact();
    let mesh = &mut out.mesh;
    let edges = mesh.edge_count();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (mut done, mut failures) = (0usize, 0usize);
    while done < flips && edges > 0 {
        let e = EdgeId::new(rng.random_range(0..edges));
        if mesh.can_flip_simplicial(e) {
            mesh.flip(e).expect("checked by can_flip_simplicial");
            done += 1;
            failures = 0;
        } else {
            failures += 1;
            if failures >= edges {
                if !mesh.edges().any(|e| mesh.can_flip_simplicial(e)) {
                    break;
                }
                failures = 0;
            }
        }
    }
    out
}
