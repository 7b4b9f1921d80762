//! Diks–Stanczyk on any compact surface, through the coned closure.
//!
//! Diks and Stanczyk's algorithm (Section 3.2 of the quadrangulation paper) finds a perfect
//! matching of a connected bridgeless cubic graph by Frink's reductions; on a surface with
//! boundary the dual is neither cubic (boundary triangles have fewer neighbours) nor, in general,
//! bridgeless, and may have no perfect matching. Decision (ours): each piece is closed by a cone
//! over every boundary loop (the cover's own construction), whose dual is cubic and bridgeless
//! (`surftopo_matching::SurfaceDual::coned`); DS pairs it perfectly, the pairs that hold a cone
//! triangle are dropped, and the caller completes the rest by augmenting paths to a maximum.
//! A closed piece, orientable or not, is its own closure: DS pairs it perfectly, as in the paper.
//! Each piece is a separate connected graph for DS.

use surftopo_matching::{CubicGraph, DualGraph, Pairing, SurfaceDual, diks_stanczyk};
use surftopo_mesh::ClosedCover;

use crate::QuadError;

/// DS on the coned closure of every piece (see the module doc), its pairs of two surface
/// triangles as a pairing of `dual` (the surface's dual, of the same cover).
pub(super) fn diks_stanczyk_on_closure(
    cover: &ClosedCover,
    dual: &SurfaceDual,
) -> Result<Pairing, QuadError> {
    let closure = SurfaceDual::coned(cover);
    let (component, count) = closure.components();
    // Each piece's nodes and edges numbered densely.
    let mut local = vec![u32::MAX; closure.node_slots()];
    let mut sizes = vec![0u32; count];
    for v in 0..closure.node_slots() {
        if closure.is_node(v as u32) {
            let c = component[v] as usize;
            local[v] = sizes[c];
            sizes[c] += 1;
        }
    }
    let mut edges: Vec<Vec<[u32; 2]>> = vec![Vec::new(); count];
    let mut global_edges: Vec<Vec<u32>> = vec![Vec::new(); count];
    for e in 0..closure.edge_slots() as u32 {
        let [a, b] = closure.endpoints(e);
        let c = component[a as usize] as usize;
        edges[c].push([local[a as usize], local[b as usize]]);
        global_edges[c].push(e);
    }
    let mut matched = Vec::new();
    for c in 0..count {
        let graph = CubicGraph::new(sizes[c], std::mem::take(&mut edges[c])).map_err(|err| {
            QuadError::Internal(format!(
                "the coned closure's dual of piece {c} is not cubic and bridgeless: {err}"
            ))
        })?;
        let pairing = diks_stanczyk(&graph);
        let flags = pairing.matched_flags();
        matched.extend(
            global_edges[c]
                .iter()
                .enumerate()
                .filter(|&(local_edge, _)| flags[local_edge])
                .map(|(_, &e)| e),
        );
    }
    // A pair of two surface triangles is the edge of `dual` between them (two triangles of a
    // simplicial surface share at most one edge).
    let pairs = matched.into_iter().filter_map(|e| {
        let [f, g] = closure.endpoints(e);
        (dual.is_node(f) && dual.is_node(g))
            .then(|| dual.adjacent(f).into_iter().find(|&(_, w)| w == g))
            .flatten()
            .map(|(edge, _)| edge)
    });
    Pairing::from_edges(dual, pairs)
        .map_err(|err| QuadError::Internal(format!("DS on the coned closure: {err}")))
}
