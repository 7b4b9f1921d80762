//! Typed errors of mesh construction, validation and edits. Every variant names the offending element
//! by its index in the input (face index, vertex index, or an edge as its two input vertex indices).

use thiserror::Error;

/// A problem found while building a surface from a triangle soup.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum BuildError {
    /// The soup has no faces.
    #[error("empty mesh: no faces")]
    Empty,
    /// A face refers to a vertex index that does not exist.
    #[error("face {face}: vertex index {index} out of range ({vertex_count} vertices)")]
    IndexOutOfRange {
        /// Input face index.
        face: usize,
        /// The offending vertex index.
        index: u32,
        /// Number of vertices in the input.
        vertex_count: usize,
    },
    /// A face uses the same vertex twice (combinatorially degenerate).
    #[error("face {face}: vertex {vertex} repeated (degenerate face)")]
    RepeatedVertex {
        /// Input face index.
        face: usize,
        /// The repeated vertex.
        vertex: u32,
    },
    /// Two faces have the same three vertices.
    #[error("face {face}: duplicate of face {duplicate_of} (same three vertices)")]
    DuplicateFace {
        /// Input face index of the later face.
        face: usize,
        /// Input face index of the earlier face.
        duplicate_of: usize,
    },
    /// An edge belongs to one face only: the surface has a boundary.
    #[error("boundary edge ({}, {}) of face {face}: the surface is not closed", edge[0], edge[1])]
    BoundaryEdge {
        /// The edge as two input vertex indices.
        edge: [u32; 2],
        /// The one face containing it.
        face: usize,
    },
    /// An edge belongs to more than two faces.
    #[error("non-manifold edge ({}, {}): in {face_count} faces (first: face {face})", edge[0], edge[1])]
    NonManifoldEdge {
        /// The edge as two input vertex indices.
        edge: [u32; 2],
        /// How many faces contain it.
        face_count: usize,
        /// One face containing it.
        face: usize,
    },
    /// The faces around a vertex do not form a single fan.
    #[error(
        "non-manifold vertex {vertex}: its {faces} faces do not form one fan (the first fan has {first_fan})"
    )]
    NonManifoldVertex {
        /// Input vertex index.
        vertex: u32,
        /// Number of faces around it.
        faces: usize,
        /// Number of faces in the fan found first.
        first_fan: usize,
    },
    /// No consistent orientation exists (e.g. a Möbius strip or Klein bottle).
    #[error("non-orientable surface: orientation conflict across edge ({}, {}) at face {face}", edge[0], edge[1])]
    NonOrientable {
        /// The edge where the conflict was found, as input vertex indices.
        edge: [u32; 2],
        /// A face next to it.
        face: usize,
    },
    /// The faces form more than one connected component.
    #[error("{components} connected components (face {face} is not connected to face 0)")]
    Disconnected {
        /// Number of components.
        components: usize,
        /// First face (input index) outside the component of the first face.
        face: usize,
    },
    /// A vertex coordinate is NaN or infinite.
    #[error("vertex {vertex}: non-finite coordinate {value} on axis {axis}")]
    NonFinite {
        /// Input vertex index.
        vertex: u32,
        /// 0, 1 or 2 for x, y, z.
        axis: usize,
        /// The value, as text (`NaN`, `inf`, `-inf`).
        value: String,
    },
    /// A face of exactly zero area: its vertices lie on one line
    /// ([`crate::geometry::is_zero_area_face`]).
    #[error("face {face}: zero area (its vertices are collinear)")]
    ZeroArea {
        /// Input face index.
        face: usize,
    },
    /// More elements than `u32` ids can address.
    #[error("too large: {what} exceeds the u32 id range")]
    TooLarge {
        /// What overflowed.
        what: &'static str,
    },
    /// A triangle side is not glued to any other side.
    #[error("face {face}: side {side} is not glued to any side")]
    SideUnglued {
        /// Face index.
        face: usize,
        /// Side 0, 1 or 2 (from corner i to corner i + 1).
        side: usize,
    },
    /// A triangle side is glued more than once, or to itself.
    #[error("face {face}: side {side} is glued more than once or to itself")]
    SideGluedTwice {
        /// Face index.
        face: usize,
        /// Side 0, 1 or 2.
        side: usize,
    },
    /// [`crate::build_topology`] takes a soup only as it is, and this one needs faces reoriented
    /// or unreferenced vertices dropped ([`crate::build`] does both).
    #[error(
        "the soup is not usable as given: {reoriented_faces} faces would be reoriented and \
         {dropped_vertices} unreferenced vertices dropped"
    )]
    NotAsGiven {
        /// Faces whose orientation disagrees with the majority of their component.
        reoriented_faces: usize,
        /// Vertices that no face uses.
        dropped_vertices: usize,
    },
    /// A face is not a triangle.
    #[error("face {face}: has {sides} sides, a triangle is needed")]
    NotTriangle {
        /// Input face index.
        face: usize,
        /// Its number of sides.
        sides: usize,
    },
}

impl BuildError {
    /// The input face the error names, if any (mutable, to renumber it).
    pub fn face_mut(&mut self) -> Option<&mut usize> {
        match self {
            BuildError::IndexOutOfRange { face, .. }
            | BuildError::RepeatedVertex { face, .. }
            | BuildError::DuplicateFace { face, .. }
            | BuildError::BoundaryEdge { face, .. }
            | BuildError::NonManifoldEdge { face, .. }
            | BuildError::NonOrientable { face, .. }
            | BuildError::Disconnected { face, .. }
            | BuildError::NotTriangle { face, .. }
            | BuildError::ZeroArea { face } => Some(face),
            _ => None,
        }
    }

    /// The error with the faces it names renumbered through `map` (a triangle's index to its
    /// polygon's, [`crate::PolygonTriangulation::face_of`]).
    pub fn on_faces(mut self, map: &[u32]) -> Self {
        if let BuildError::DuplicateFace { duplicate_of, .. } = &mut self {
            *duplicate_of = map[*duplicate_of] as usize;
        }
        if let Some(face) = self.face_mut() {
            *face = map[*face] as usize;
        }
        self
    }
}

/// A violated structural invariant, found by [`crate::SurfaceMesh::check_invariants`].
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[error("invariant violated: {0}")]
pub struct InvariantError(pub String);

/// Why an edit was refused.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum EditError {
    /// The element id is removed or out of range.
    #[error("{0} is not a live element")]
    NotLive(String),
    /// The edge cannot be flipped (its two sides are the same face, or the flip would break simpliciality).
    #[error("edge {0:?} cannot be flipped")]
    NotFlippable(crate::EdgeId),
    /// The edge fails the link condition: contracting it would change the topology.
    #[error("edge {0:?} fails the link condition")]
    NotContractible(crate::EdgeId),
}
