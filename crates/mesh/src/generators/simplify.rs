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
use crate::cover::{CoveredSurface, Lifting, contract_lifts, satisfies_link_condition};
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
    simplify_covered(&surface.clone().into(), target_faces, seed)
        .into_plain()
        .expect("contractions keep a closed orientable surface so")
}

/// [`simplify`] on any compact surface: the link condition is the surface's
/// ([`satisfies_link_condition`]: Dey et al.'s rule with the boundary coned), edges of the cover
/// that are not the surface's are skipped, a contraction of a non-orientable component is made
/// on both lifts ([`contract_lifts`]), and the face count is the surface's.
pub fn simplify_covered(
    surface: &CoveredSurface,
    target_faces: usize,
    seed: u64,
) -> CoveredSurface {
    let mut out = surface.clone();
    out.compact();
    let cover = &mut out.cover;
    let mut faces = cover.surface_faces().count();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut scratch = LinkScratch::default();
    let mut history = Vec::new();
    let mut order: Vec<EdgeId> = cover.mesh.edges().collect();
    while faces > target_faces {
        for i in (1..order.len()).rev() {
            order.swap(i, rng.random_range(0..=i));
        }
        let mut contracted = false;
        for &e in &order {
            if faces <= target_faces {
                break;
            }
            if !cover.mesh.is_edge_live(e) || cover.sheets.edge_key(e) != e {
                continue;
            }
            let h = if rng.random_bool(0.5) {
                e.halfedge()
            } else {
                e.halfedge().twin()
            };
            if satisfies_link_condition(&cover.mesh, &cover.sheets, h, &mut scratch) {
                let boundary = [h, h.twin()]
                    .iter()
                    .any(|&k| cover.sheets.is_apex(cover.mesh.opposite_vertex(k)));
                history.clear();
                contract_lifts(&mut cover.mesh, &cover.sheets, h, &mut history);
                faces -= if boundary { 1 } else { 2 };
                contracted = true;
            }
        }
        if !contracted {
            break;
        }
        order.retain(|&e| cover.mesh.is_edge_live(e));
    }
    out.compact();
    out
}
