//! Minimum-cost perfect matchings of a [`DualGraph`]: the exact primal–dual blossom algorithm
//! with its optimality certificate, an independent verifier of that certificate, and a fast
//! heuristic.
//!
//! * [`blossom`] — Edmonds' weighted blossom algorithm (Edmonds 1965) after Blossom V's greedy
//!   and fractional initialisations (Kolmogorov 2009), all alternating trees grown together
//!   under one dual change with a monotone event queue (Galil 1986). Returns the matched edges
//!   and the dual solution ([`Certificate`]).
//! * [`certificate`] — the dual solution and [`verify_min_cost_perfect_matching`], which checks a
//!   matching and a certificate without any of the solver's code: primal perfection, dual
//!   feasibility and complementary slackness, hence optimality.
//! * [`maximum`] — the minimum-cost *maximum* matching of a graph without a perfect matching
//!   (the dual of a surface with boundary): the exact solver on an auxiliary graph with dummy
//!   nodes, its certificate and verifier ([`min_cost_maximum_matching`],
//!   [`verify_min_cost_maximum_matching`]).
//! * [`fast`] — a cost-ordered greedy matching completed by augmenting paths
//!   ([`crate::augment_to_perfect`]), then improved along short negative alternating cycles:
//!   deterministic, not optimal in general.
//!
//! # Costs
//! Costs are integers (`i64`, one per edge slot, in `0..=MAX_COST`), so that the duals are exact and
//! the certificate is checked exactly. A real-valued cost `c` is given as `round(c · R)` for a
//! fixed resolution `R` chosen by the caller (the quad quality costs use `R = 10⁹`,
//! `surftopo_quad::quality::COST_RESOLUTION`). For any perfect matching `M`, the rounded total
//! differs from `R ·` the real total by at most `|M| / 2`; hence the matching that is optimal for
//! the rounded costs is within `|M| / R` of the real-valued optimum (absolute, in cost units).
//!
//! Internally every cost is doubled, so that all duals stay integers (see [`blossom`]); the
//! certificate's duals are for the doubled costs `2c`.
//!
//! # References
//! * J. Edmonds, "Maximum matching and a polyhedron with 0,1-vertices", *Journal of Research of
//!   the National Bureau of Standards* 69B (1965), 125–130.
//! * V. Kolmogorov, "Blossom V: a new implementation of a minimum cost perfect matching
//!   algorithm", *Mathematical Programming Computation* 1(1) (2009), 43–67.
//! * Z. Galil, "Efficient algorithms for finding maximum matching in graphs", *ACM Computing
//!   Surveys* 18(1) (1986), 23–38.

pub mod blossom;
pub mod certificate;
pub mod fast;
pub mod maximum;
mod radix_heap;

use thiserror::Error;

use crate::augment::AugmentError;
use crate::dual_graph::DualGraph;

pub use blossom::{BlossomStats, MinCostMatching, min_cost_perfect_matching};
pub use certificate::{
    BlossomDual, Certificate, CertificateError, verify_min_cost_perfect_matching,
};
pub use fast::{
    FastMatching, FastStats, fast_min_cost_maximum_matching, fast_min_cost_perfect_matching,
};
pub use maximum::{
    MaximumCertificate, MinCostMaximumMatching, min_cost_maximum_matching,
    verify_min_cost_maximum_matching,
};

/// Largest cost accepted (2³¹ − 1): with doubled costs and at most 2³² nodes every dual and every
/// sum the solver forms stays far inside `i64`.
pub const MAX_COST: i64 = (1 << 31) - 1;

/// Checks one cost per edge slot, each live edge's in `0..=MAX_COST`.
fn check_costs<G: DualGraph + ?Sized>(graph: &G, costs: &[i64]) -> Result<(), WeightedError> {
    if costs.len() != graph.edge_slots() {
        return Err(WeightedError::CostCount {
            costs: costs.len(),
            edge_slots: graph.edge_slots(),
        });
    }
    match (0..graph.edge_slots() as u32)
        .find(|&e| graph.is_edge(e) && !(0..=MAX_COST).contains(&costs[e as usize]))
    {
        Some(edge) => Err(WeightedError::CostOutOfRange {
            edge,
            cost: costs[edge as usize],
        }),
        None => Ok(()),
    }
}

/// Why a minimum-cost perfect matching could not be computed.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum WeightedError {
    /// The cost array does not have one entry per edge slot.
    #[error("{costs} costs for {edge_slots} edge slots")]
    CostCount {
        /// Entries given.
        costs: usize,
        /// Edge slots of the graph.
        edge_slots: usize,
    },
    /// A live edge's cost is negative or above [`MAX_COST`].
    #[error("edge {edge}: cost {cost} outside 0..={MAX_COST}")]
    CostOutOfRange {
        /// The edge.
        edge: u32,
        /// Its cost.
        cost: i64,
    },
    /// The graph has an odd number of live nodes.
    #[error("{nodes} nodes: a perfect matching needs an even number")]
    OddNodeCount {
        /// Live nodes.
        nodes: usize,
    },
    /// The graph has no perfect matching: the search from `node` exhausted its alternating tree.
    #[error("no perfect matching: the alternating tree from node {node} can grow no further")]
    NoPerfectMatching {
        /// The exposed node searched from.
        node: u32,
    },
    /// The auxiliary graph of a minimum-cost maximum matching would be too large: a piece with
    /// a large deficiency and many nodes that a maximum matching may leave unmatched.
    #[error(
        "the exact pairing of least cost would need {dummies} dummy nodes with {dummy_edges} \
         edges (pieces where many triangles must stay unpaired); use the fast objective"
    )]
    AuxiliaryTooLarge {
        /// Dummy nodes (the unmatched nodes of a maximum matching).
        dummies: usize,
        /// Their edges.
        dummy_edges: usize,
    },
    /// The fast mode's completion by augmenting paths failed.
    #[error("completion by augmenting paths: {0}")]
    Augment(AugmentError),
}
