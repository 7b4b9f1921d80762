//! Perfect matchings of the dual graphs of closed triangle meshes: connected, bridgeless, 3-regular
//! multigraphs ([`CubicGraph`]), paired by the algorithms of the quadrangulation paper
//! (`tri-quad-conversion-long.txt`, Section 3), each result checked by an independent verifier
//! ([`verify`]).
//!
//! * [`diks_stanczyk`] — Frink's reductions with Diks and Stanczyk's dynamic connectivity,
//!   O(n log² n) amortized, always perfect.
//! * [`dynamic_connectivity`] — the fully dynamic connectivity / spanning-forest structure it uses.
//! * [`karp_sipser`] — the Karp–Sipser greedy with immediate local repairs: a perfect pairing,
//!   the fastest on most meshes (not from the paper; see its module doc).
//! * [`file_order`] — the pairing a triangulated quad mesh is written in (its quads), when the
//!   file lists them two triangles at a time; KS's first step.
//! * [`subdivision_order`] — the pairing of a mesh written as a 1-to-4 subdivision, lifted from
//!   the coarser mesh's; KS's second step.
//! * [`generators`] — seeded random bridgeless cubic multigraphs and mesh duals, for tests and
//!   benchmarks.

pub mod cubic_graph;
pub mod diks_stanczyk;
pub mod dynamic_connectivity;
pub mod generators;
pub mod verify;
pub mod weighted;

pub use cubic_graph::{CubicGraph, GraphError};
pub use diks_stanczyk::DsStats;
pub use dynamic_connectivity::{DynamicConnectivity, DynamicStats};
pub use verify::{
    MatchingError, PerfectMatching, verify_perfect_matching, verify_perfect_matching_edges,
    verify_perfect_matching_on,
};

// Pairing on the (implicit) dual graph: greedy, Pulli–Segal, augmenting paths.
pub mod augment;
pub mod dual_graph;
pub mod file_order;
pub mod greedy;
pub mod karp_sipser;
pub mod pulli_segal;
pub mod subdivision_order;

pub use augment::{AugmentError, AugmentStats, AugmentStrategy, augment_to_perfect};
pub use dual_graph::{
    AdjacencyTable, CompactDual, DualGraph, Pairing, PairingError, mesh_dual_graph,
};
pub use file_order::file_order_pairing;
pub use greedy::simple_greedy;
pub use karp_sipser::{
    KarpSipserOptions, KarpSipserStats, karp_sipser_perfect, karp_sipser_perfect_with,
};
pub use pulli_segal::pulli_segal;
pub use weighted::{
    Certificate, MinCostMatching, WeightedError, fast_min_cost_perfect_matching,
    min_cost_perfect_matching, verify_min_cost_perfect_matching,
};
