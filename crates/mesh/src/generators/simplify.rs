//! Simplification by random edge contractions: coarser meshes of the same surface.
//!
//! The irreducible-triangulations paper (Section 5.1, Tables 3 and 4) obtains its smallest inputs
//! B7..B9 and C7 "from B_{i-1} by a simplification process that approximately halved the number
//! of triangles", without naming the process. We use the simplest process that keeps the
//! topology: random contractions of edges that satisfy the link condition. Decision (the paper is
//! silent): the kept vertex keeps its position, so every output position is an input position;
//! the geometry is not optimised (no error metric) and may fold over, only the topology is
//! guaranteed.

use crate::Surface;
use crate::contract::LinkScratch;
use crate::ids::EdgeId;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A copy of `surface` simplified by random edge contractions until it has at most
/// `target_faces` faces, or no edge satisfies the link condition.
///
/// The edges are visited in passes, each over the live edges in a random order (Fisher-Yates with
/// `ChaCha8Rng::seed_from_u64(seed)`); a visited edge, taken in a random direction `u -> v`, is
/// contracted into `u` ([`crate::SurfaceMesh::contract_unchecked`]) when it satisfies
/// [`crate::SurfaceMesh::satisfies_link_condition`]; a pass that contracts nothing ends the
/// process. Each contraction removes 1 vertex, 3 edges and 2 faces and keeps the surface (so the
/// genus, and a simplicial input stays simplicial): a closed input with more than `target_faces`
/// faces ends with `target_faces` or `target_faces - 1` faces unless it becomes irreducible first.
/// The kept vertex keeps its position. Ids are dense ([`Surface::compact`]). Expected
/// O(n * degree) time when a constant fraction of the edges is contractible in every pass. Same
/// seed, same result.
pub fn simplify(surface: &Surface, target_faces: usize, seed: u64) -> Surface {
    let mut out = surface.clone();
    out.compact();
    let mesh = &mut out.mesh;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut scratch = LinkScratch::default();
    let mut order: Vec<EdgeId> = mesh.edges().collect();
    while mesh.face_count() > target_faces {
        for i in (1..order.len()).rev() {
            order.swap(i, rng.random_range(0..=i));
        }
        let mut contracted = false;
        for &e in &order {
            if mesh.face_count() <= target_faces {
                break;
            }
            if !mesh.is_edge_live(e) {
                continue;
            }
            let h = if rng.random_bool(0.5) {
                e.halfedge()
            } else {
                e.halfedge().twin()
            };
            if mesh.satisfies_link_condition(h, &mut scratch) {
                mesh.contract_unchecked(h);
                contracted = true;
            }
        }
        if !contracted {
            break;
        }
        order.retain(|&e| mesh.is_edge_live(e));
    }
    out.compact();
    out
}
