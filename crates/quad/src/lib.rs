//! surftopo-quad: quadrangulations of closed triangle meshes by triangle pairing.
//!
//! Paper: T. Lemos, S. Ramaswami and M. Siqueira, "An experimental comparison of algorithms
//! for converting triangulations of closed surfaces into quadrangulations", 24th International
//! Meshing Roundtable (IMR24), research note, Elsevier, 2015, and its long version (2015,
//! <http://clam.rutgers.edu/~rsuneeta/hpc/research/imr15_long.pdf>, as the note cites it; no
//! DOI or arXiv identifier could be verified for either).
//!
//! - [`quadrangulate`] / [`quadrangulate_with`]: the pipeline for every algorithm ([`QuadAlgorithm`]:
//!   SG, PS, LRS, DS): initial pairing, augmenting paths until the pairing is perfect, one quad per
//!   pair, with the figures of Table 4.3 ([`QuadStats`]).
//! - [`quadrangulate_polygons`]: the same on a surface read as polygons, a quad-only input
//!   giving back its own quads (as `surftopo quad` and the Python package run it).
//! - [`expand`]: the expansion step of LRS (Algorithms 3.1–3.4), which pairs the triangles of a
//!   triangulation K obtained from the input by edge flips.
//!
//! Every pairing reaches the quads as a [`PerfectPairing`], which only the independent verifier
//! of `surftopo-matching` builds.
//!
//! The pairing algorithms themselves (SG, PS, augmenting paths, DS) live in `surftopo-matching`
//! and work on the dual graph read implicitly from the half-edge mesh.

mod error;
mod lrs;
mod lrs_surface;
mod quadrangulate;
pub mod quality;
mod surface;

pub use error::QuadError;
pub use lrs::{Expansion, ExpansionCases, expand};
pub use quadrangulate::{
    QuadAlgorithm, QuadOptions, QuadResult, QuadStats, quadrangulate, quadrangulate_with,
};
pub use quality::{
    QuadFigures, QualityMeasured, QualityObjective, QualityQuads, QualityReport, QualitySummary,
    pair_costs, quadrangulate_by_quality, quadrangulate_with_quality, quality_report,
};
pub use surface::{
    AllQuads, ComponentQuads, OwnQuads, PolygonQuads, SurfaceOptions, SurfaceQuads,
    SurfaceQualityQuads, all_quads, positions_with_added, quadrangulate_polygons,
    quadrangulate_surface, quadrangulate_surface_by_quality, quadrangulate_surface_with_quality,
    surface_pair_costs, surface_vertex_count,
};
pub use surftopo_matching::{
    AugmentStats, AugmentStrategy, KarpSipserOptions, KarpSipserStats, PerfectPairing,
};
