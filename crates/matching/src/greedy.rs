//! The simple greedy pairing (SG) of the quadrangulation paper (`tri-quad-conversion-long.txt`,
//! Section 3.1, "the greedy algorithm that uses no heuristic to select edges").
//!
//! Every edge starts *free*. Edges are selected one at a time in a seeded random order (the paper
//! randomises the edge order "to avoid selecting edges in the fixed order they show up in an input
//! file"); a free edge pairs its two triangles, and their other edges become *locked*; a locked
//! edge is discarded.
//!
//! Decision: an edge is locked exactly when one of its two triangles is already paired, so the
//! free/locked mark is read from the per-node mates instead of being stored per edge (same
//! outcome, no second array). A dual loop (a primal edge with the same triangle on both sides,
//! possible only in non-simplicial meshes) is never free.

use rand::SeedableRng;
use rand::seq::SliceRandom;
use rand_chacha::ChaCha8Rng;

use crate::dual_graph::{DualGraph, NONE, Pairing};

/// SG: a maximal (not necessarily perfect) pairing, edges visited in the order of a
/// `ChaCha8Rng::seed_from_u64(seed)` shuffle of the live edge ids. Same seed, same pairing.
///
/// Takes any [`DualGraph`] (the implicit dual of a mesh, or a [`crate::CubicGraph`]).
/// Guarantees: a matching in which no edge has both endpoints unmatched. The paper measured about
/// 87% of the triangles paired. Θ(E) time, one shuffled edge list of memory. No errors.
pub fn simple_greedy<G: DualGraph + ?Sized>(graph: &G, seed: u64) -> Pairing {
    let mut order: Vec<u32> = (0..graph.edge_slots() as u32)
        .filter(|&e| graph.is_edge(e))
        .collect();
    order.shuffle(&mut ChaCha8Rng::seed_from_u64(seed));
    let mut pairing = Pairing::empty(graph.node_slots());
    // A cooperative stop (Ctrl-C from Python) is read every few thousand edges.
    let mut ticker = surftopo_mesh::stop::Ticker::default();
    for e in order {
        ticker.tick();
        let [a, b] = graph.endpoints(e);
        if a != b && pairing.mate[a as usize] == NONE && pairing.mate[b as usize] == NONE {
            pairing.join(e, a, b);
        }
    }
    pairing
}
