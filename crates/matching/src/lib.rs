//! Perfect matchings of the dual graphs of closed triangle meshes: connected, bridgeless, 3-regular
//! multigraphs, paired by the algorithms of the quadrangulation paper (Section 3 of its long
//! version), each result checked by an independent verifier ([`verify_perfect_pairing`], the only
//! way to a [`PerfectPairing`]).
//!
//! Paper: T. Lemos, S. Ramaswami and M. Siqueira, "An experimental comparison of algorithms
//! for converting triangulations of closed surfaces into quadrangulations", 24th International
//! Meshing Roundtable (IMR24), research note, Elsevier, 2015, and its long version (2015,
//! <http://clam.rutgers.edu/~rsuneeta/hpc/research/imr15_long.pdf>, as the note cites it; no
//! DOI or arXiv identifier could be verified for either).
//! Diks–Stanczyk: K. Diks and P. Stanczyk, "Perfect matching for biconnected cubic graphs in
//! O(n log² n) time", SOFSEM 2010, LNCS 5901, Springer, pp. 321–333,
//! doi:10.1007/978-3-642-11266-9_27.
//!
//! * Graphs: the [`DualGraph`] interface every pairing algorithm is generic over, implemented by
//!   the implicit dual of a [`surftopo_mesh::SurfaceMesh`], by [`CubicGraph`] (a validated edge
//!   list) and by [`CompactDual`] (a flat copy of either); pairings as [`Pairing`] (one mate edge
//!   per node).
//! * Initial pairings (Section 3.1): [`simple_greedy`], [`pulli_segal`].
//! * Completion by augmenting paths (Edmonds' blossoms, Sections 3.1 and 3.3):
//!   [`augment_to_perfect`], with the strategies of [`AugmentStrategy`].
//! * [`diks_stanczyk`] — Frink's reductions with Diks and Stanczyk's dynamic connectivity
//!   ([`DynamicConnectivity`]), O(n log² n) amortized, always perfect (Section 3.2).
//! * [`karp_sipser_perfect`] — the Karp–Sipser greedy with immediate local repairs and a guided
//!   completion: a perfect pairing, the fastest on most meshes (not from the paper).
//! * [`generators`] — seeded random bridgeless cubic multigraphs and mesh duals, for tests and
//!   benchmarks.

mod augment;
mod cubic_graph;
mod diks_stanczyk;
mod dual_graph;
mod dynamic_connectivity;
pub mod generators;
mod greedy;
mod karp_sipser;
mod pulli_segal;
mod surface_dual;
mod verify;
mod verify_maximum;
pub mod weighted;

pub use augment::{
    AugmentError, AugmentStats, AugmentStrategy, augment_to_maximum, augment_to_perfect,
    shift_unmatched,
};
pub use cubic_graph::{CubicGraph, GraphError};
pub use diks_stanczyk::{DsStats, diks_stanczyk, diks_stanczyk_avoiding, diks_stanczyk_with_stats};
pub use dual_graph::{
    AdjacencyTable, CompactDual, DualGraph, Pairing, PairingError, mesh_dual_graph,
};
pub use dynamic_connectivity::{DynamicConnectivity, DynamicStats};
pub use greedy::simple_greedy;
pub use karp_sipser::{
    KarpSipserOptions, KarpSipserStats, karp_sipser_maximum_with, karp_sipser_perfect,
    karp_sipser_perfect_with,
};
pub use pulli_segal::pulli_segal;
pub use surface_dual::{SurfaceDual, components_of};
pub use verify::{
    MatchingError, PerfectPairing, verify_perfect_matching, verify_perfect_matching_edges,
    verify_perfect_matching_on, verify_perfect_pairing,
};
pub use verify_maximum::{ComponentPairing, MaximumPairing, verify_maximum_pairing};
pub use weighted::{
    Certificate, MaximumCertificate, MinCostMatching, MinCostMaximumMatching, WeightedError,
    fast_min_cost_maximum_matching, fast_min_cost_perfect_matching, min_cost_maximum_matching,
    min_cost_perfect_matching, verify_min_cost_maximum_matching, verify_min_cost_perfect_matching,
};
