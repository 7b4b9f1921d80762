//! The pairing a triangulated quad mesh is written in: when every triangle `2k` is adjacent to
//! triangle `2k + 1`, the pairs `{2k, 2k + 1}` are a perfect pairing, and they are the quads the
//! file came from (quad-to-triangle converters write the two triangles of each quad one after the
//! other). Not from the quadrangulation paper: a shortcut for such files, phase 0 of KS
//! ([`super`]), taken before any greedy when it exists.
//!
//! Why: such files are common, their quads are the pairing a user expects back, and a greedy can
//! do badly on them (on a file whose quads are listed in reverse order, KS's greedy spends most of
//! its time in augmenting paths, where this check takes one pass).
//!
//! The check stops at the first pair that is not adjacent, so other files pay for a few
//! adjacency reads only (on the shared meshes that are not quad by quad, the first failure is
//! among the first pairs: half or fewer of their consecutive pairs are adjacent).

use crate::dual_graph::{DualGraph, Pairing};

/// The pairing `{2k, 2k + 1}` for every `k` when each such pair is adjacent (through the first
/// of their shared edges); `None` when one is not, when the graph has removed node slots, or when
/// its node count is odd. O(n) at most. Guarantees on `Some`: a perfect matching.
pub(super) fn file_order_pairing<G: DualGraph + ?Sized>(graph: &G) -> Option<Pairing> {
    let slots = graph.node_slots();
    if graph.node_count() != slots || !slots.is_multiple_of(2) {
        return None;
    }
    let mut mate = Vec::with_capacity(slots);
    // A cooperative stop (Ctrl-C from Python) is read every few thousand pairs.
    let mut ticker = surftopo_mesh::stop::Ticker::default();
    for first in (0..slots as u32).step_by(2) {
        ticker.tick();
        let (e, _) = graph
            .adjacent(first)
            .into_iter()
            .find(|&(_, w)| w == first + 1)?;
        mate.extend([e, e]);
    }
    Some(Pairing { mate })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::verify::assert_perfect_pairing;
    use surftopo_mesh::Surface;
    use surftopo_mesh::generators::{icosphere, torus};

    /// Checks `pairing` independently: perfect on `graph`, and each pair is `{2k, 2k + 1}`.
    fn check_file_order<G: DualGraph + ?Sized>(graph: &G, pairing: &Pairing) {
        assert_perfect_pairing(graph, pairing);
        for (v, &e) in pairing.mate.iter().enumerate() {
            let mut ends = graph.endpoints(e);
            ends.sort_unstable();
            assert_eq!(ends, [v as u32 & !1, v as u32 | 1]);
        }
    }

    #[test]
    fn a_torus_written_quad_by_quad_is_paired_as_written() {
        let grid = torus(12, 9);
        let pairing = file_order_pairing(&grid.mesh).expect("the torus is written quad by quad");
        check_file_order(&grid.mesh, &pairing);
    }

    #[test]
    fn one_quad_out_of_order_or_no_quad_order_gives_none() {
        let grid = torus(12, 9);
        let (positions, mut triangles) = grid.to_triangles();
        // Swapping triangles 1 and 2 separates the first two quads' halves.
        triangles.swap(1, 2);
        let swapped = Surface::from_triangles(positions, &triangles).unwrap();
        assert!(file_order_pairing(&swapped.mesh).is_none());
        // Subdivided icosahedra: a quarter of the consecutive pairs are not adjacent.
        assert!(file_order_pairing(&icosphere(3).mesh).is_none());
    }

    #[test]
    fn removed_node_slots_give_none() {
        let mut mesh = torus(12, 9).mesh;
        let mut scratch = surftopo_mesh::LinkScratch::default();
        mesh.contract(surftopo_mesh::EdgeId(40).halfedge(), &mut scratch)
            .unwrap();
        assert!(mesh.face_slots() > mesh.face_count());
        assert!(file_order_pairing(&mesh).is_none());
    }
}
