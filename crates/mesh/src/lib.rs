//! surftopo-mesh: index-based half-edge triangulations of closed surfaces.
//!
//! - [`SurfaceMesh`]: the topology (struct of arrays, `twin(h) = h ^ 1`, tombstones).
//! - [`build()`] / [`inspect`]: from a triangle soup, with typed validation errors ([`BuildError`]).
//! - Edits with their checks: [`SurfaceMesh::flip`], [`SurfaceMesh::contract`] /
//!   [`SurfaceMesh::split_vertex`], [`SurfaceMesh::compact`], [`geometry::reorder_morton`].
//! - [`geometry`]: positions and edge lengths beside the topology; [`Surface`]: a mesh with its
//!   positions.
//! - [`generators`]: deterministic test and benchmark surfaces.
//!

mod build;
mod compact;
mod contract;
pub mod decimal;
mod error;
mod flip;
pub mod generators;
pub mod geometry;
mod gluing;
mod ids;
mod invariants;
mod printable;
mod surface;
mod topology;
mod union_find;

pub use build::{
    BuildReport, Inspection, MAX_LISTED_PROBLEMS, ProblemCounts, build, build_topology, inspect,
};
pub use compact::Renumbering;
pub use contract::{Contraction, LinkScratch};
pub use error::{BuildError, EditError, InvariantError};
pub use gluing::Side;
pub use ids::{EdgeId, FaceId, HalfedgeId, VertexId};
pub use printable::printable;
pub use surface::Surface;
pub use topology::{Outgoing, SurfaceMesh};
pub use union_find::UnionFind;
