//! Why an input or a census request is refused.

use thiserror::Error;

/// A face list that is not a closed connected simplicial surface, a surface name or census
/// request that cannot be served, or a run that was stopped. Vertices and faces are named by
/// their 0-based index in the input; lines and columns of a text input are 1-based.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum CensusError {
    /// No faces at all.
    #[error("no faces: a closed surface needs at least four triangles")]
    Empty,
    /// A face names the same vertex twice.
    #[error("face {face} names vertex {vertex} twice")]
    DegenerateFace {
        /// The face index.
        face: usize,
        /// The repeated vertex.
        vertex: u32,
    },
    /// A vertex index below the largest one is used by no face.
    #[error("vertex {vertex} is used by no face (vertices must be numbered 0..n without gaps)")]
    UnusedVertex {
        /// The unused vertex.
        vertex: u32,
    },
    /// Two faces have the same three vertices.
    #[error("faces {} and {} have the same three vertices", faces[0], faces[1])]
    DuplicateFace {
        /// The two faces.
        faces: [usize; 2],
    },
    /// An edge lies in a number of faces other than two (1: a boundary; 3 or more: non-manifold).
    #[error(
        "edge ({}, {}) lies in {faces} faces, not 2 (face {face} is one): the surface is not closed{}",
        edge[0], edge[1], if *faces > 2 { " or not a manifold" } else { "" }
    )]
    EdgeFaceCount {
        /// The edge's endpoints.
        edge: [u32; 2],
        /// How many faces contain it.
        faces: usize,
        /// One face containing it.
        face: usize,
    },
    /// The link of a vertex is not a single cycle (a pinched, non-manifold vertex).
    #[error("the link of vertex {vertex} is {cycles} cycles, not one: a non-manifold vertex")]
    PinchedVertex {
        /// The vertex.
        vertex: u32,
        /// How many cycles its link has.
        cycles: usize,
    },
    /// The faces form more than one surface.
    #[error("vertex {vertex} is not connected to vertex 0: the faces form more than one surface")]
    Disconnected {
        /// A vertex of another component than vertex 0's.
        vertex: u32,
    },
    /// A surface name the census does not know.
    #[error(
        "unknown surface `{name}`: expected sphere, torus, projective-plane, klein-bottle, genus-G (G ≥ 0) or nK (K ≥ 1)"
    )]
    UnknownSurface {
        /// The name given.
        name: String,
    },
    /// A census whose search range goes beyond what the vertex labels hold.
    #[error("{vertices} vertices asked: the census search labels at most {limit} vertices")]
    TooManyVertices {
        /// The vertex count asked.
        vertices: usize,
        /// The largest supported.
        limit: usize,
    },
    /// A census whose completion is beyond reach: no proven or published vertex bound that the
    /// search can finish, or an estimated time above the budget.
    #[error("{reason}")]
    BeyondReach {
        /// What is missing and what it would take.
        reason: String,
    },
    /// A text line that is not a triangulation in Lutz's format.
    #[error("line {line}, column {column}: {message}")]
    Parse {
        /// 1-based line.
        line: usize,
        /// 1-based column (in characters).
        column: usize,
        /// What was expected.
        message: String,
    },
    /// A triangulation in a census file is invalid.
    #[error("line {line}: {source}")]
    InvalidLine {
        /// 1-based line.
        line: usize,
        /// Why.
        source: Box<CensusError>,
    },
    /// The run was stopped by its caller (Ctrl-C, a time limit) before it finished.
    #[error("stopped before the census was complete")]
    Cancelled,
}
