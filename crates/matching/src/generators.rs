//! Seeded generators of connected, bridgeless, 3-regular multigraphs, for tests, examples and
//! benchmarks. Same seed, same graph (ChaCha8).

use rand::seq::SliceRandom;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::cubic_graph::CubicGraph;

/// A random connected bridgeless cubic multigraph on `node_count` nodes, grown from the theta
/// graph by "handle insertions": subdivide two random edges (possibly the same one) and join the
/// two new nodes by an edge. Every step keeps the graph 3-regular and 2-edge-connected; parallel
/// edges appear (digons). Node and edge ids are shuffled at the end, so ids carry no locality.
/// O(n).
///
/// # Panics
/// If `node_count` is odd or smaller than 2.
pub fn random_bridgeless_cubic(node_count: u32, seed: u64) -> CubicGraph {
    assert!(
        node_count >= 2 && node_count.is_multiple_of(2),
        "a cubic graph has an even number (>= 2) of nodes"
    );
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut edges: Vec<[u32; 2]> = vec![[0, 1]; 3];
    edges.reserve(node_count as usize * 3 / 2);
    let mut nodes = 2u32;
    while nodes < node_count {
        let e1 = rng.random_range(0..edges.len());
        let e2 = rng.random_range(0..edges.len());
        let (s, t) = (nodes, nodes + 1);
        nodes += 2;
        if e1 == e2 {
            let [a, b] = edges[e1];
            edges[e1] = [a, s];
            edges.push([s, t]);
            edges.push([s, t]);
            edges.push([t, b]);
        } else {
            let [a, b] = edges[e1];
            let [c, d] = edges[e2];
            edges[e1] = [a, s];
            edges.push([s, b]);
            edges[e2] = [c, t];
            edges.push([t, d]);
            edges.push([s, t]);
        }
    }
    let mut perm: Vec<u32> = (0..node_count).collect();
    perm.shuffle(&mut rng);
    for e in &mut edges {
        *e = [perm[e[0] as usize], perm[e[1] as usize]];
        if rng.random_bool(0.5) {
            e.swap(0, 1);
        }
    }
    edges.shuffle(&mut rng);
    CubicGraph::new(node_count, edges).expect("handle insertions keep the graph bridgeless")
}

/// A random cubic multigraph from the configuration model (uniform pairing of `3n` half-edges),
/// redrawn until it has no loop and is connected and bridgeless. Parallel edges are kept. Fine for
/// any even `node_count >= 2` (a redraw is needed with probability about `1 - e^{-1}`). O(n)
/// expected.
///
/// # Panics
/// If `node_count` is odd or smaller than 2.
pub fn random_cubic_pairing(node_count: u32, seed: u64) -> CubicGraph {
    assert!(
        node_count >= 2 && node_count.is_multiple_of(2),
        "a cubic graph has an even number (>= 2) of nodes"
    );
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut half: Vec<u32> = (0..node_count).flat_map(|v| [v, v, v]).collect();
    loop {
        half.shuffle(&mut rng);
        let edges: Vec<[u32; 2]> = half.chunks_exact(2).map(|p| [p[0], p[1]]).collect();
        if edges.iter().any(|e| e[0] == e[1]) {
            continue;
        }
        if let Ok(g) = CubicGraph::new(node_count, edges) {
            return g;
        }
    }
}

/// The dual graph of the `w × h` grid torus whose squares are split by one diagonal each: `2wh`
/// nodes (triangles), `3wh` edges (primal edges), with the locality of a mesh (triangles of one
/// square are consecutive, squares in row order). Triangle `2s` is below the diagonal of square
/// `s = j w + i`, `2s + 1` above it.
///
/// # Panics
/// If `w` or `h` is 0 or `2wh` overflows `u32`.
pub fn torus_dual(w: u32, h: u32) -> CubicGraph {
    assert!(w >= 1 && h >= 1, "empty torus");
    let squares = w
        .checked_mul(h)
        .and_then(|s| s.checked_mul(2))
        .expect("torus too large")
        / 2;
    let mut edges = Vec::with_capacity(3 * squares as usize);
    for j in 0..h {
        for i in 0..w {
            let s = j * w + i;
            let below = ((j + h - 1) % h) * w + i;
            let left = j * w + (i + w - 1) % w;
            edges.push([2 * s, 2 * s + 1]); // diagonal
            edges.push([2 * s, 2 * below + 1]); // bottom side
            edges.push([2 * s + 1, 2 * left]); // left side
        }
    }
    CubicGraph::new(2 * squares, edges).expect("torus dual is cubic and bridgeless")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seeded_generators_are_reproducible() {
        assert_eq!(
            random_bridgeless_cubic(100, 7),
            random_bridgeless_cubic(100, 7)
        );
        assert_ne!(
            random_bridgeless_cubic(100, 7),
            random_bridgeless_cubic(100, 8)
        );
        assert_eq!(random_cubic_pairing(50, 3), random_cubic_pairing(50, 3));
        assert_eq!(torus_dual(3, 4).node_count(), 24);
    }
}
