//! Why an input is refused.

use surftopo_mesh::{EdgeId, FaceId, VertexId};
use thiserror::Error;

/// An input that is not a closed orientable simplicial surface. (Boundary, non-manifold,
/// disconnected and non-orientable inputs cannot be a `SurfaceMesh`: `surftopo_mesh::build` refuses
/// them with a `BuildError`.) Elements are named by their mesh ids.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum IrreducibleError {
    /// The mesh has no faces.
    #[error("empty mesh: no faces")]
    Empty,
    /// An edge joins a vertex to itself.
    #[error("loop: edge {edge} joins vertex {vertex} to itself (a simplicial surface is needed)")]
    Loop {
        /// The loop edge.
        edge: EdgeId,
        /// Its vertex.
        vertex: VertexId,
    },
    /// Two edges join the same two vertices.
    #[error(
        "multi-edge: edges {} and {} both join vertices {} and {} (a simplicial surface is needed)",
        edges[0], edges[1], vertices[0], vertices[1]
    )]
    MultiEdge {
        /// The two parallel edges.
        edges: [EdgeId; 2],
        /// Their common endpoints.
        vertices: [VertexId; 2],
    },
    /// Two faces have the same three vertices (the two-triangle sphere).
    #[error(
        "faces {} and {} have the same three vertices (a simplicial surface is needed)",
        faces[0], faces[1]
    )]
    DuplicateFace {
        /// The two faces.
        faces: [FaceId; 2],
    },
}
