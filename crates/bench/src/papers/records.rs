//! The rows each paper's experiment measures (one `.jsonl` line each), read by its report and by
//! [`super::differences`]: below both, so that neither imports the other's module.

use serde::{Deserialize, Serialize};

use super::inputs::Described;

/// Intrinsic-Delaunay paper: one measured surface.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct IntrinsicRecord {
    /// `flat_torus`, `sheared_torus` or `mesh`.
    pub kind: String,
    /// x, the shear, or the model name.
    pub input: String,
    /// x (flat torus), the shear (sheared torus), 0 for meshes.
    pub parameter: f64,
    /// Edges.
    pub edges: usize,
    /// Flips made.
    pub flips: u64,
    /// Expected flips (flat torus: x − 1).
    pub expected_flips: Option<u64>,
    /// Flat torus: max |ℓ − exact| over the three final lengths (1, 2, √5).
    pub length_error: Option<f64>,
    /// Edges not Delaunay at the end (0 on success).
    pub non_delaunay_edges: usize,
    /// Wall-clock seconds of the flips.
    pub seconds: f64,
    /// `ok` or the error.
    pub status: String,
}

/// Quadrangulation paper: one algorithm on one input, means over the runs.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct QuadRecord {
    /// The input (group, name, how it was made, sizes).
    #[serde(flatten)]
    pub about: Described,
    /// `SG`, `PS`, `DS` or `LRS`.
    pub algorithm: String,
    /// Augmenting search: `forest` (the library's default) or `global` (the paper's procedure,
    /// [`surftopo_quad::AugmentStrategy::Global`]).
    pub augment: String,
    /// Runs (seeds 1..=runs for SG and PS).
    pub runs: u64,
    /// (a) initial pairing seconds (wall-clock, mean).
    pub initial_pairing_seconds: f64,
    /// (b) percentage paired by the initial pairing.
    pub paired_percent: f64,
    /// (c) unpaired triangles after the initial pairing.
    pub unpaired: f64,
    /// (d) augmentation seconds.
    pub augmentation_seconds: f64,
    /// (e) total seconds.
    pub total_seconds: f64,
    /// Mean CPU seconds of the whole call.
    pub cpu_seconds: f64,
    /// LRS: edges of the input whose flip is in K.
    pub flipped_edges: f64,
    /// Nodes reached by the augmenting searches.
    pub augment_reached: f64,
    /// Augmenting searches started.
    pub augment_searches: f64,
}

/// Irreducible-triangulations paper: one algorithm on one input; counts are means over the runs
/// (BF: its seeds).
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct AlgorithmRun {
    /// ℓ: link-condition tests.
    pub link_tests: f64,
    /// ε: edges tested more than once.
    pub edges_tested_more_than_once: f64,
    /// Vertices of the irreducible output.
    pub output_vertices: f64,
    /// Mean CPU seconds of the algorithm alone (the input check that `reduce` makes is measured
    /// apart and subtracted).
    pub cpu_seconds: f64,
    /// Least wall-clock seconds (`Counters::seconds`, as the paper's `run()`).
    pub wall_seconds: f64,
    /// Timed calls.
    pub calls: u32,
    /// Seeded runs averaged (BF: `irreducible::BF_RUNS`, or fewer on large inputs,
    /// `measure::seeds_for`; RS and S: 1).
    #[serde(default = "one")]
    pub seeds: u64,
}

fn one() -> u64 {
    1
}

/// Irreducible-triangulations paper: one input's row.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct IrreducibleRow {
    /// The input (group, name, how it was made, sizes).
    #[serde(flatten)]
    pub about: Described,
    /// RS.
    pub rs: AlgorithmRun,
    /// Schipper.
    pub s: AlgorithmRun,
    /// Brute force (means over its seeds, [`AlgorithmRun::seeds`]).
    pub bf: AlgorithmRun,
}

/// Our six ratios of Tables 7, 9 and 11 (CPU times).
pub fn ratios(r: &IrreducibleRow) -> [f64; 6] {
    let q = |a: f64, b: f64| if b > 0.0 { a / b } else { f64::NAN };
    [
        q(r.s.link_tests, r.rs.link_tests),
        q(r.bf.link_tests, r.rs.link_tests),
        q(r.s.link_tests, r.bf.link_tests),
        q(r.s.cpu_seconds, r.rs.cpu_seconds),
        q(r.bf.cpu_seconds, r.rs.cpu_seconds),
        q(r.s.cpu_seconds, r.bf.cpu_seconds),
    ]
}

impl std::ops::Deref for IrreducibleRow {
    type Target = Described;

    /// The input's description, so that `row.faces` reads as a field of the row.
    fn deref(&self) -> &Described {
        &self.about
    }
}
