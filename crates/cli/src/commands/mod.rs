//! One module per subcommand.

pub mod census;
pub mod convert;
pub mod delaunay;
pub mod delaunay_args;
pub mod demo;
pub mod generate;
pub mod info;
pub mod irreducible;
pub mod isometric;
pub mod isomorphic;
pub mod quad;
pub mod tufted;
