//! Random triangulations of a surface (vertex splits and edge flips from a given one) and a
//! randomised reducer: the cross-checks of a census.

use crate::triangulation::Triangulation;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// `t` after `splits` random vertex splits and `flips` random edge flips, interleaved at random
/// (each a topology-preserving move: the result triangulates the same surface). Deterministic in
/// `seed`. A split or flip whose result would not be simplicial is skipped.
pub fn random_retriangulation(
    t: &Triangulation,
    splits: usize,
    flips: usize,
    seed: u64,
) -> Triangulation {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut current = t.clone();
    let (mut splits_left, mut flips_left) = (splits, flips);
    let mut attempts = 0usize;
    while (splits_left > 0 || flips_left > 0) && attempts < 100 * (splits + flips + 1) {
        attempts += 1;
        let split = flips_left == 0
            || (splits_left > 0 && rng.random_range(0..splits_left + flips_left) < splits_left);
        let faces = current.faces();
        if split {
            let v = rng.random_range(0..current.vertex_count()) as u32;
            let neighbours = &current.neighbours()[v as usize];
            let a = neighbours[rng.random_range(0..neighbours.len())];
            let b = neighbours[rng.random_range(0..neighbours.len())];
            let firsts: Vec<usize> = (0..faces.len())
                .filter(|&f| faces[f].contains(&v) && faces[f].contains(&a))
                .collect();
            let first = firsts[rng.random_range(0..firsts.len())];
            if let Some(next) = current.split_vertex(v, a, b, first) {
                current = next;
                splits_left -= 1;
            }
        } else {
            let face = faces[rng.random_range(0..faces.len())];
            let i = rng.random_range(0..3);
            if let Some(next) = current.flip(face[i], face[(i + 1) % 3]) {
                current = next;
                flips_left -= 1;
            }
        }
    }
    current
}

/// An irreducible triangulation of the surface of `t`: contracts a random contractible edge
/// (link condition) until none is left. Deterministic in `seed`.
pub fn random_reduction(t: &Triangulation, seed: u64) -> Triangulation {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut current = t.clone();
    loop {
        let edges = current.contractible_edges();
        if edges.is_empty() {
            return current;
        }
        let [u, v] = edges[rng.random_range(0..edges.len())];
        match current.contract(u, v) {
            Some(next) => current = next,
            None => return current,
        }
    }
}
