//! The pairing of a mesh written as a 1-to-4 subdivision: when the triangles `4k..4k + 4` are
//! always the four children of one coarser triangle (three corners round a centre, as midpoint
//! and Loop subdivision make them, in any order within the four), a perfect pairing of the
//! coarser mesh lifts to one of the finer mesh in O(n), with no search. Not from the
//! quadrangulation paper (which pairs any triangulation, Section 3): a shortcut for inputs that
//! carry their own hierarchy. Phase 1 of KS ([`super`]): after the file's quads
//! ([`super::file_order`]) and before the greedy, level after level down to the coarsest mesh.
//!
//! # The lift
//! Let coarse triangles `p` and `q` be paired, across their shared edge `ab`. Two children of
//! `p` touch `ab` (its corners at `a` and at `b`), and each is adjacent across `ab` to the
//! child of `q` at the same vertex: those are two pairs. The third corner of `p` is adjacent to
//! `p`'s centre: a third pair; likewise in `q`. So the eight children are paired inside the quad
//! `pq`, and the quads of the result lie inside the coarse quads.
//!
//! # What is checked
//! The ids alone say nothing about the mesh, so [`coarsen`] accepts a level only when every
//! block of four is such a star: one node adjacent to the three others (the centre), each other
//! node (a corner) adjacent to the centre and to two nodes of two distinct other blocks, and the
//! six edges leaving the block reaching three distinct blocks, two by two from distinct corners.
//! Then the blocks form a simple cubic graph (the coarse dual) and the lift above pairs every
//! node exactly once, whatever perfect pairing of the coarse graph it starts from. The first
//! block that fails stops the check (on files in any other order, within the first blocks).
//!
//! Why: subdivided meshes are a common input (icospheres, refined meshes; our
//! `subdivide_midpoint` and `icosphere`, and trimesh's `remesh.subdivide`, which its `icosphere`
//! uses, write the four children of each face consecutively), and KS's greedy does badly on
//! their id order (it isolates thousands of triangles on icosphere(7), whose repairs then reach
//! several times the graph); with the lift there is no search at all.

use crate::dual_graph::{DualGraph, NONE, Pairing, flat_adjacency_methods};

/// The blocks of four of a finer graph as the nodes of a coarser one ([`coarsen`]); node `k` is
/// the block `4k..4k + 4`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct CoarseDual {
    /// Per block, its three `(coarse edge, neighbouring block)` pairs.
    adjacency: Vec<[(u32, u32); 3]>,
    /// Per coarse edge, its two blocks.
    ends: Vec<[u32; 2]>,
}

impl DualGraph for CoarseDual {
    flat_adjacency_methods!();
    #[inline]
    fn edge_slots(&self) -> usize {
        self.ends.len()
    }
    #[inline]
    fn is_node(&self, v: u32) -> bool {
        (v as usize) < self.adjacency.len()
    }
    #[inline]
    fn is_edge(&self, e: u32) -> bool {
        (e as usize) < self.ends.len()
    }
    #[inline]
    fn node_count(&self) -> usize {
        self.adjacency.len()
    }
    #[inline]
    fn endpoints(&self, e: u32) -> [u32; 2] {
        self.ends[e as usize]
    }
}

/// One level of 1-to-4 subdivision read from a graph's ids: the coarse graph, and which node of
/// each block is its centre.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct SubdivisionLevel {
    coarse: CoarseDual,
    /// Per block, the index (0–3) of its centre within the block.
    centres: Vec<u8>,
}

/// The coarse graph of `graph` when its nodes `4k..4k + 4` are the children of one coarser
/// triangle for every `k`, as the module doc says what is checked; `None` otherwise (also when
/// there are removed node slots, or fewer than two blocks). O(n) at most.
pub(super) fn coarsen<G: DualGraph + ?Sized>(graph: &G) -> Option<SubdivisionLevel> {
    let slots = graph.node_slots();
    if graph.node_count() != slots || !slots.is_multiple_of(4) || slots < 8 {
        return None;
    }
    let blocks = slots / 4;
    let mut adjacency = vec![[(NONE, NONE); 3]; blocks];
    let mut ends = Vec::with_capacity(blocks * 3 / 2);
    let mut centres = Vec::with_capacity(blocks);
    // A cooperative stop (Ctrl-C from Python) is read every few thousand blocks.
    let mut ticker = surftopo_mesh::stop::Ticker::default();
    for k in 0..blocks as u32 {
        ticker.tick();
        let first = 4 * k;
        let nodes: [[u32; 3]; 4] =
            std::array::from_fn(|i| graph.adjacent(first + i as u32).map(|(_, w)| w));
        let centre = nodes.iter().position(|ws| ws.iter().all(|&w| w / 4 == k))?;
        let centre_node = first + centre as u32;
        // Each corner: the centre, and two other blocks; the six blocks so reached are three,
        // each reached from two corners (the corners and blocks form a 6-cycle).
        let mut leaving = [0u32; 6];
        let mut filled = 0;
        for (i, ws) in nodes.iter().enumerate() {
            if i == centre {
                continue;
            }
            let mut outside = ws.iter().filter(|&&w| w != centre_node).map(|&w| w / 4);
            let (Some(x), Some(y), None) = (outside.next(), outside.next(), outside.next()) else {
                return None;
            };
            if x == k || y == k || x == y {
                return None;
            }
            leaving[filled] = x;
            leaving[filled + 1] = y;
            filled += 2;
        }
        leaving.sort_unstable();
        if !(leaving[0] == leaving[1] && leaving[2] == leaving[3] && leaving[4] == leaving[5])
            || leaving[1] == leaving[2]
            || leaving[3] == leaving[4]
        {
            return None;
        }
        for (slot, j) in [leaving[0], leaving[2], leaving[4]].into_iter().enumerate() {
            let edge = if j > k {
                ends.push([k, j]);
                ends.len() as u32 - 1
            } else {
                // Block j, already seen, met the same two edges to this block.
                adjacency[j as usize].iter().find(|&&(_, b)| b == k)?.0
            };
            adjacency[k as usize][slot] = (edge, j);
        }
        centres.push(centre as u8);
    }
    Some(SubdivisionLevel {
        coarse: CoarseDual { adjacency, ends },
        centres,
    })
}

impl SubdivisionLevel {
    /// The coarse graph: node `k` is the block of nodes `4k..4k + 4`.
    pub(super) fn coarse(&self) -> &CoarseDual {
        &self.coarse
    }

    /// The perfect pairing of `graph` (the graph this level was read from) lifted from a perfect
    /// pairing of [`SubdivisionLevel::coarse`], as the module doc says. O(n).
    ///
    /// # Panics
    /// If `coarse_pairing` is not a perfect pairing of the coarse graph, or `graph` is not the
    /// graph this level was read from.
    pub(super) fn lift<G: DualGraph + ?Sized>(
        &self,
        graph: &G,
        coarse_pairing: &Pairing,
    ) -> Pairing {
        let mut mate = vec![NONE; graph.node_slots()];
        let mut ticker = surftopo_mesh::stop::Ticker::default();
        for (k, &centre) in self.centres.iter().enumerate() {
            ticker.tick();
            let k = k as u32;
            let partner = self.coarse.opposite(coarse_pairing.mate[k as usize], k);
            let centre = 4 * k + u32::from(centre);
            let mut spare = NONE;
            for corner in (4 * k..4 * k + 4).filter(|&v| v != centre) {
                match graph
                    .adjacent(corner)
                    .into_iter()
                    .find(|&(_, w)| w / 4 == partner)
                {
                    Some((e, _)) => mate[corner as usize] = e,
                    None => spare = corner,
                }
            }
            let (e, _) = graph
                .adjacent(centre)
                .into_iter()
                .find(|&(_, w)| w == spare)
                .expect("the corner not facing the partner block is adjacent to the centre");
            mate[centre as usize] = e;
            mate[spare as usize] = e;
        }
        Pairing { mate }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::augment::{AugmentStrategy, augment_to_perfect};
    use crate::greedy::simple_greedy;
    use crate::verify::assert_perfect_pairing;
    use surftopo_mesh::Surface;
    use surftopo_mesh::generators::{icosphere, shuffle_faces, torus};

    #[test]
    fn an_icosphere_coarsens_level_by_level_to_the_icosahedron() {
        let mesh = icosphere(3).mesh;
        let one = coarsen(&mesh).expect("icosphere(3) is icosphere(2) subdivided");
        assert_eq!(one.coarse().node_count(), 320);
        let two = coarsen(one.coarse()).unwrap();
        let three = coarsen(two.coarse()).unwrap();
        assert_eq!(three.coarse().node_count(), 20);
        assert_eq!(three.coarse().edge_slots(), 30);
        // The icosahedron is not itself a subdivision.
        assert!(coarsen(three.coarse()).is_none());
        // The coarse graph of icosphere(3) is icosphere(2)'s dual, node for node.
        let coarser = icosphere(2).mesh;
        for k in 0..320 {
            let mut expected: Vec<u32> = coarser.adjacent(k).map(|(_, w)| w).into();
            let mut found: Vec<u32> = one.coarse().adjacent(k).map(|(_, w)| w).into();
            expected.sort_unstable();
            found.sort_unstable();
            assert_eq!(found, expected, "block {k}");
        }
    }

    #[test]
    fn every_perfect_pairing_of_the_coarse_graph_lifts_to_a_perfect_pairing() {
        let mesh = icosphere(4).mesh;
        let level = coarsen(&mesh).unwrap();
        // Different coarse pairings: seeded simple greedies completed by augmenting paths.
        for seed in 0..4 {
            let mut coarse = simple_greedy(level.coarse(), seed);
            augment_to_perfect(level.coarse(), &mut coarse, AugmentStrategy::Forest).unwrap();
            assert_perfect_pairing(level.coarse(), &coarse);
            let lifted = level.lift(&mesh, &coarse);
            assert_perfect_pairing(&mesh, &lifted);
            // Each pair lies inside one block or in two blocks the coarse pairing joined.
            for v in 0..mesh.node_slots() as u32 {
                let w = mesh.opposite(lifted.mate[v as usize], v);
                let (b, c) = (v / 4, w / 4);
                assert!(b == c || level.coarse().opposite(coarse.mate[b as usize], b) == c);
            }
        }
    }

    #[test]
    fn files_in_another_order_are_not_taken_for_subdivisions() {
        // Tori are written quad by quad, not as subdivisions.
        assert!(coarsen(&torus(12, 8).mesh).is_none());
        // The same icosphere with its faces shuffled.
        assert!(coarsen(&shuffle_faces(&icosphere(3), 1).mesh).is_none());
        // Two faces of different blocks swapped.
        let (positions, mut triangles) = icosphere(3).to_triangles();
        triangles.swap(5, 900);
        let swapped = Surface::from_triangles(positions, &triangles).unwrap();
        assert!(coarsen(&swapped.mesh).is_none());
        // Within a block, any order is a subdivision.
        let (positions, mut triangles) = icosphere(3).to_triangles();
        triangles.swap(4, 7);
        triangles.swap(9, 10);
        let reordered = Surface::from_triangles(positions, &triangles).unwrap();
        let level = coarsen(&reordered.mesh).expect("children in another order");
        assert_eq!(level.centres[1], 0);
    }
}
