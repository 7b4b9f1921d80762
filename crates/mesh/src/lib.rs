//! surftopo-mesh: index-based half-edge triangulations of compact surfaces.
//!
//! - [`SurfaceMesh`]: the topology (struct of arrays, `twin(h) = h ^ 1`, tombstones).
//! - [`build()`] / [`inspect`]: from a triangle soup, with typed validation errors ([`BuildError`]);
//!   [`inspect`] classifies each component ([`SurfaceKind`]).
//! - [`ClosedCover`]: any compact surface (boundary loops, non-orientable, several components) as
//!   a closed oriented mesh that covers it, with its [`Lifting`]; edits of the surface on every
//!   lift ([`contract_lifts`], [`flip_lifts`], [`split_lifts`], [`satisfies_link_condition`]).
//! - Edits with their checks: [`SurfaceMesh::flip`], [`SurfaceMesh::contract`] /
//!   [`SurfaceMesh::split_vertex`], [`SurfaceMesh::compact`], [`geometry::reorder_morton`].
//! - [`geometry`]: positions and edge lengths beside the topology; [`Surface`]: a mesh with its
//!   positions.
//! - [`generators`]: deterministic test and benchmark surfaces.
//! - [`triangulate_polygons`]: polygon faces cut into triangles by ear clipping in their plane
//!   (exact predicates; no degenerate triangle for a polygon simple in its plane);
//!   [`inspect_polygons`]: a polygon soup inspected through those triangles.
//!

mod build;
mod compact;
mod contract;
mod cover;
pub mod decimal;
mod error;
mod flip;
pub mod generators;
pub mod geometry;
mod gluing;
mod ids;
mod invariants;
mod polygons;
mod printable;
pub mod stop;
mod surface;
mod topology;
mod union_find;

pub use build::{
    BuildReport, Inspection, MAX_LISTED_PROBLEMS, ProblemCounts, SurfaceKind, build,
    build_topology, face_components, inspect,
};
pub use compact::Renumbering;
pub use contract::{Contraction, LinkScratch};
pub use cover::{
    ClosedCover, CoveredSurface, Lifting, Plain, Sheets, contract_lifts, flip_lifts,
    satisfies_link_condition, split_lifts,
};
pub use error::{BuildError, EditError, InvariantError};
pub use gluing::Side;
pub use ids::{EdgeId, FaceId, HalfedgeId, VertexId};
pub use polygons::{
    PolygonInspection, PolygonTriangulation, inspect_polygons, triangulate_polygon,
    triangulate_polygons, triangulate_polygons_as_surface,
};
pub use printable::printable;
pub use surface::Surface;
pub use topology::{Outgoing, SurfaceMesh};
pub use union_find::UnionFind;
