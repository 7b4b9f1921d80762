//! The randomised brute force (BF) of Section 5 of the irreducible-triangulations paper.
//!
//! All edges are shuffled into an array; each pass visits the array, tests every live edge against
//! the link condition (the mesh's generic test, O(d_u + d_v)) and contracts it if it passes, else
//! keeps it in an auxiliary array for the next pass. The algorithm stops after a pass that contracts
//! nothing; then every remaining edge has just failed the test, so the result is irreducible.
//!
//! Decisions: the shuffle is a `ChaCha8Rng` seeded with the caller's seed (same seed, same result);
//! edges removed by a contraction are skipped without a test; the auxiliary array keeps the order
//! of the failures (no reshuffle between passes, as the paper describes); a contracted edge
//! `e` identifies the destination of its half-edge `2e` with its origin.

use rand::SeedableRng;
use rand::seq::SliceRandom;
use rand_chacha::ChaCha8Rng;
use surftopo_mesh::{
    Contraction, EdgeId, Lifting, LinkScratch, SurfaceMesh, contract_lifts,
    satisfies_link_condition,
};

use crate::tally::TestTally;
use crate::{IrreducibleError, Reduction};

/// The randomised brute force of Section 5: passes over the shuffled edges, contracting every edge
/// that passes the link condition, until a pass contracts nothing.
///
/// Takes a closed orientable simplicial surface (checked first) and the shuffle's seed.
/// Guarantees: the result is irreducible and simplicial with the input's genus; surviving vertices
/// keep their ids; the history replays back to the input; same seed, same result. Time O(n²) link
/// tests in the worst case (Figure 6 of the paper), each O(degree); memory O(n).
///
/// # Errors
/// [`IrreducibleError`] if the mesh is not simplicial (nothing is done then).
pub fn brute_force(mesh: SurfaceMesh, seed: u64) -> Result<Reduction, IrreducibleError> {
    Reduction::of_plain_run(mesh, |mesh, plain| run(mesh, plain, seed))
}

/// BF on the surface a mesh covers (see [`crate::reduce_surface`]): the edges of the surface
/// (not the cones', one per mirror pair) are shuffled, the link condition is the surface's
/// ([`satisfies_link_condition`]), contractions are made on every lift.
pub(crate) fn run<L: Lifting>(
    mesh: &mut SurfaceMesh,
    lifting: &L,
    seed: u64,
) -> (Vec<Contraction>, TestTally, u64) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut edges: Vec<EdgeId> = mesh
        .edges()
        .filter(|&e| {
            lifting.edge_key(e) == e && !mesh.edge_vertices(e).iter().any(|&v| lifting.is_apex(v))
        })
        .collect();
    edges.shuffle(&mut rng);
    let mut failed = Vec::with_capacity(edges.len());
    let mut scratch = LinkScratch::default();
    let mut tally = TestTally::new(mesh.edge_slots());
    let mut history = Vec::with_capacity(mesh.vertex_count().saturating_sub(4));
    let mut contractions = 0;
    let mut ticker = surftopo_mesh::stop::Ticker::default();
    loop {
        let before = contractions;
        for e in edges.drain(..) {
            ticker.tick();
            if !mesh.is_edge_live(e) {
                continue;
            }
            tally.record(e);
            let h = e.halfedge();
            if satisfies_link_condition(mesh, lifting, h, &mut scratch) {
                contract_lifts(mesh, lifting, h, &mut history);
                contractions += 1;
            } else {
                failed.push(e);
            }
        }
        std::mem::swap(&mut edges, &mut failed);
        if contractions == before {
            break;
        }
    }
    (history, tally, contractions)
}
