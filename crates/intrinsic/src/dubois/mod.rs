//! Dubois' Theorem 1: the intrinsic Delaunay tessellation of a closed polyhedral surface in time
//! polylogarithmic in its aspect ratio.
//!
//! - [`reduction`] (Section 4, Proposition 1): ALGORITHM, the happiness reduction of a flat surface;
//! - [`tube`] and [`biface`] (Section 3, Proposition 4 and Appendix B): tubes replaced by good
//!   bifaces, which SIMPLIFYTUBES and GARDENING call;
//! - [`caps`] (Section 8, Proposition 2): caps around the cone points, ALGORITHM on the flat
//!   remainder, the caps put back; Theorem 1 with cone points ([`delaunay_tessellation_dubois`]);
//! - [`flat_delaunay`]: Theorem 1 on flat surfaces ([`delaunay_tessellation_flat`]).

pub(crate) mod biface;
pub mod caps;
pub mod flat_delaunay;
mod reduction;
pub(crate) mod tube;

pub use caps::{
    CapCut, CapsError, ConeDelaunay, cut_caps, cut_caps_at, delaunay_tessellation_dubois,
    proposition_2, put_caps_back,
};
pub use flat_delaunay::{
    FlatDelaunay, FlatDelaunayError, FlatDelaunayOptions, delaunay_tessellation_flat,
    first_cone_point,
};
pub use reduction::{
    DELETE_MAX_DEGREE, DuboisError, DuboisReport, INNER_REPETITIONS, ReduceOptions, Reduction,
    outer_iterations, reduce, reduce_with_boundary,
};
