//! Building a [`SurfaceMesh`] from a triangle soup, with validation, and inspecting a soup.
//!
//! The directed corner edges are paired after two counting sorts (by larger, then by smaller
//! vertex: O(n), no comparison sort); a walk around each vertex checks its fan, a union-find counts
//! components, and a breadth-first search over faces orients them when needed ([`pairing`]).
//!
//! Two kinds of findings are kept apart:
//! - **problems**: what makes the faces something other than a triangulated surface (a
//!   non-manifold edge or vertex, a degenerate or duplicate face, a bad index, no face at all)
//!   and the geometric ones (non-finite coordinates, zero-area faces). [`inspect`] lists them.
//! - **facts** of a surface that is fine as such: a boundary, no consistent orientation, several
//!   pieces. [`inspect`] classifies each piece ([`SurfaceKind`]); [`build`], whose
//!   [`SurfaceMesh`] is a closed oriented surface, refuses them; [`crate::ClosedCover`] takes them.

pub(crate) mod classify;
pub(crate) mod pairing;

pub use classify::SurfaceKind;

use crate::error::BuildError;
use crate::ids::VertexId;
use crate::topology::SurfaceMesh;
use pairing::CornerPairing;

/// At most this many problems are listed by [`inspect`] (counts are always complete).
pub const MAX_LISTED_PROBLEMS: usize = 100;

/// What building a mesh changed about its input.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct BuildReport {
    /// Faces whose orientation was reversed to make the orientation consistent.
    pub reoriented_faces: usize,
    /// Input vertices that no face uses; they were dropped.
    pub dropped_vertices: Vec<u32>,
    /// Input vertex index -> mesh vertex id (`INVALID` for dropped vertices).
    pub vertex_old_to_new: Vec<VertexId>,
    /// The classification of each piece of the input, in the order of their first face
    /// ([`crate::ClosedCover::from_triangles`] gives it; [`build()`] leaves it empty).
    pub surfaces: Vec<SurfaceKind>,
}

impl BuildReport {
    /// The input index of each vertex id of the input's vertices (the inverse of
    /// [`Self::vertex_old_to_new`] on the referenced vertices, in id order): how an output on
    /// the mesh's ids is put back in the input's vertex numbering.
    pub fn input_vertices(&self) -> Vec<u32> {
        let mut index =
            Vec::with_capacity(self.vertex_old_to_new.len() - self.dropped_vertices.len());
        for (old, new) in self.vertex_old_to_new.iter().enumerate() {
            if new.is_valid() {
                debug_assert_eq!(new.idx(), index.len());
                index.push(old as u32);
            }
        }
        index
    }
}

/// Everything [`inspect`] finds out about a triangle soup, valid or not.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Inspection {
    /// Referenced vertices.
    pub vertices: usize,
    /// Distinct undirected edges.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// Connected components (faces joined through shared edges).
    pub components: usize,
    /// Edges in exactly one face (a fact of a surface with boundary, not a problem).
    pub boundary_edges: usize,
    /// Boundary loops (cycles of boundary edges), summed over [`Self::surfaces`]; 0 when the
    /// faces do not form a surface.
    pub boundary_loops: usize,
    /// Edges in more than two faces.
    pub non_manifold_edges: usize,
    /// Vertices whose faces form more than one fan (not checked at vertices of non-manifold
    /// edges, which are reported as such).
    pub non_manifold_vertices: usize,
    /// Whether a consistent orientation exists (of every component; over the manifold part).
    pub orientable: bool,
    /// Faces that would be reversed to orient the surface consistently (when orientable).
    pub reoriented_faces: usize,
    /// Unreferenced vertices.
    pub dropped_vertices: usize,
    /// One classification per connected component, in the order of their first face, when the
    /// faces form a surface (every face valid, no non-manifold edge or vertex); empty otherwise.
    pub surfaces: Vec<SurfaceKind>,
    /// The problems found, at most [`MAX_LISTED_PROBLEMS`], in input order of discovery.
    pub problems: Vec<BuildError>,
    /// Total number of problems found.
    pub problem_count: usize,
    /// The problems found, counted by class (they sum to `problem_count`).
    pub counts: ProblemCounts,
}

/// The problems of an [`Inspection`] counted by class, one count per kind of [`BuildError`]
/// that [`inspect`] and the geometric checks ([`crate::geometry::problems`]) report. The field
/// names are the keys of `surftopo info --json` and, read with spaces for `_`, its text labels.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ProblemCounts {
    /// Coordinates that are NaN or infinite, one per coordinate (a vertex `nan nan nan` counts
    /// three): [`BuildError::NonFinite`].
    pub non_finite_coordinates: usize,
    /// Faces of exactly zero area (collinear vertices): [`BuildError::ZeroArea`].
    pub zero_area_faces: usize,
    /// Faces repeating a vertex: [`BuildError::RepeatedVertex`].
    pub degenerate_faces: usize,
    /// Faces on the same vertices as an earlier face: [`BuildError::DuplicateFace`].
    pub duplicate_faces: usize,
    /// Edges in more than two faces: [`BuildError::NonManifoldEdge`].
    pub non_manifold_edges: usize,
    /// Vertices whose faces form several fans: [`BuildError::NonManifoldVertex`].
    pub non_manifold_vertices: usize,
    /// Any other problem: a vertex index out of range, no face at all, more elements than
    /// `u32` ids address (none of which comes from a file: the readers refuse such files, and
    /// `surftopo info` with them).
    pub other_problems: usize,
}

impl ProblemCounts {
    /// Counts one problem in its class.
    pub fn add(&mut self, problem: &BuildError) {
        let count = match problem {
            BuildError::NonFinite { .. } => &mut self.non_finite_coordinates,
            BuildError::ZeroArea { .. } => &mut self.zero_area_faces,
            BuildError::RepeatedVertex { .. } => &mut self.degenerate_faces,
            BuildError::DuplicateFace { .. } => &mut self.duplicate_faces,
            BuildError::NonManifoldEdge { .. } => &mut self.non_manifold_edges,
            BuildError::NonManifoldVertex { .. } => &mut self.non_manifold_vertices,
            BuildError::IndexOutOfRange { .. }
            | BuildError::Empty
            | BuildError::TooLarge { .. }
            | BuildError::SideUnglued { .. }
            | BuildError::SideGluedTwice { .. }
            | BuildError::NotAsGiven { .. }
            | BuildError::NotTriangle { .. }
            | BuildError::BoundaryEdge { .. }
            | BuildError::NonOrientable { .. }
            | BuildError::Disconnected { .. } => &mut self.other_problems,
        };
        *count += 1;
    }

    /// `(key, count)` per class, in the order `surftopo info` prints them; the key is the
    /// field's name.
    pub fn entries(&self) -> [(&'static str, usize); 7] {
        [
            ("non_finite_coordinates", self.non_finite_coordinates),
            ("zero_area_faces", self.zero_area_faces),
            ("degenerate_faces", self.degenerate_faces),
            ("duplicate_faces", self.duplicate_faces),
            ("non_manifold_edges", self.non_manifold_edges),
            ("non_manifold_vertices", self.non_manifold_vertices),
            ("other_problems", self.other_problems),
        ]
    }

    /// The problems of the geometry (non-finite coordinates, zero-area faces); the others are
    /// of the combinatorics.
    pub fn geometric(&self) -> usize {
        self.non_finite_coordinates + self.zero_area_faces
    }

    /// All problems, every class.
    pub fn total(&self) -> usize {
        self.entries().iter().map(|&(_, n)| n).sum()
    }
}

impl Inspection {
    /// Whether every edge has exactly two faces.
    pub fn is_closed(&self) -> bool {
        self.boundary_edges == 0 && self.non_manifold_edges == 0
    }
    /// Euler characteristic `V - E + F`.
    pub fn euler_characteristic(&self) -> i64 {
        self.vertices as i64 - self.edges as i64 + self.faces as i64
    }
    /// Whether no problem was found: the soup is a triangulated compact surface (boundary,
    /// non-orientable pieces and several components allowed) with finite coordinates and no
    /// zero-area face.
    pub fn is_valid(&self) -> bool {
        self.problem_count == 0
    }
    /// Whether the combinatorics are those of a triangulated surface: no problem but the
    /// geometric ones ([`ProblemCounts::geometric`]: non-finite coordinates, zero-area faces),
    /// which leave the topology defined.
    pub fn is_combinatorially_valid(&self) -> bool {
        self.problem_count == self.counts.geometric()
    }
    /// Whether the faces form a closed, connected, orientable surface without combinatorial
    /// problems: what [`build()`] accepts (geometric problems aside).
    pub fn is_closed_connected_orientable(&self) -> bool {
        self.is_combinatorially_valid()
            && self.is_closed()
            && self.components == 1
            && self.orientable
    }
    /// The genus when the faces form one connected orientable surface (closed or not, genus `g`
    /// with `χ = 2 − 2g − b`), `None` otherwise.
    pub fn genus(&self) -> Option<i64> {
        match self.surfaces.as_slice() {
            [one] => one.genus.map(|g| g as i64),
            _ => None,
        }
    }
    /// Whether a problem makes the faces a non-simplicial complex: a face repeating a vertex, or
    /// two faces on the same three vertices.
    pub fn has_degenerate_faces(&self) -> bool {
        self.problems.iter().any(|p| {
            matches!(
                p,
                BuildError::RepeatedVertex { .. } | BuildError::DuplicateFace { .. }
            )
        })
    }
    /// Whether more problems were found than [`Self::problems`] lists (at most
    /// [`MAX_LISTED_PROBLEMS`]).
    pub fn is_truncated(&self) -> bool {
        self.problem_count > self.problems.len()
    }
    /// Counts problems found outside the soup's combinatorics (non-finite coordinates, zero-area
    /// faces: [`crate::geometry::problems`]) and lists them before the others, the list still
    /// cut at [`MAX_LISTED_PROBLEMS`].
    pub fn add_problems_first(&mut self, problems: impl IntoIterator<Item = BuildError>) {
        let later = std::mem::take(&mut self.problems);
        for e in problems {
            self.push(e);
        }
        let room = MAX_LISTED_PROBLEMS - self.problems.len();
        self.problems.extend(later.into_iter().take(room));
    }
    pub(crate) fn push(&mut self, e: BuildError) {
        self.problem_count += 1;
        self.counts.add(&e);
        if self.problems.len() < MAX_LISTED_PROBLEMS {
            self.problems.push(e);
        }
    }
}

/// Inspects a triangle soup without building anything: counts, the classification of each
/// connected component, and every problem found.
pub fn inspect(vertex_count: usize, triangles: &[[u32; 3]]) -> Inspection {
    let mut p = CornerPairing::run(vertex_count, triangles);
    if p.is_surface() {
        p.inspection.surfaces = classify::classify(&p);
        p.inspection.boundary_loops = p.inspection.surfaces.iter().map(|s| s.boundary_loops).sum();
    }
    p.inspection
}

/// The connected component of each face (numbered in the order of their first face, as
/// [`Inspection::surfaces`]) when the soup forms a surface, `None` otherwise. O(n).
pub fn face_components(vertex_count: usize, triangles: &[[u32; 3]]) -> Option<Vec<u32>> {
    let p = CornerPairing::run(vertex_count, triangles);
    p.is_surface().then(|| classify::components(&p).0)
}

/// Builds a closed, connected, orientable surface from a triangle soup.
///
/// Unreferenced vertices are dropped (see [`BuildReport::vertex_old_to_new`]); faces are reoriented
/// to agree with the majority orientation when needed. Face ids equal input face indices.
///
/// # Errors
/// The first problem found, naming the input face, vertex or edge (see [`BuildError`]); absent
/// problems, the first boundary edge ([`BuildError::BoundaryEdge`]), the components
/// ([`BuildError::Disconnected`]) or an orientation conflict ([`BuildError::NonOrientable`]):
/// [`crate::ClosedCover`] takes those.
pub fn build(
    vertex_count: usize,
    triangles: &[[u32; 3]],
) -> Result<(SurfaceMesh, BuildReport), BuildError> {
    build_closed(vertex_count, triangles, false)
}

/// [`build()`], allowing several connected components when `components` is set.
pub(crate) fn build_closed(
    vertex_count: usize,
    triangles: &[[u32; 3]],
    components: bool,
) -> Result<(SurfaceMesh, BuildReport), BuildError> {
    let mut p = CornerPairing::run(vertex_count, triangles);
    if let Some(e) = p.first_refusal(components) {
        return Err(e);
    }
    let mut report = BuildReport {
        reoriented_faces: p.inspection.reoriented_faces,
        dropped_vertices: std::mem::take(&mut p.dropped),
        vertex_old_to_new: std::mem::take(&mut p.old_to_new),
        surfaces: Vec::new(),
    };
    let mesh = if report.reoriented_faces > 0 {
        let oriented = p.oriented_triangles();
        let again = CornerPairing::run(p.inspection.vertices, &oriented);
        debug_assert_eq!(again.inspection.reoriented_faces, 0);
        if let Some(e) = again.first_refusal(components) {
            return Err(e);
        }
        again.into_mesh()
    } else {
        p.into_mesh()
    };
    report.reoriented_faces = report.reoriented_faces.min(triangles.len());
    Ok((mesh, report))
}

/// Builds the topology of a soup that is known to be valid and consistently oriented, with no
/// unreferenced vertices, so that vertex and face ids are the soup's as given.
///
/// # Errors
/// As [`build`]; [`BuildError::NotAsGiven`] if faces would need reorienting or vertices
/// dropping.
pub fn build_topology(
    vertex_count: usize,
    triangles: &[[u32; 3]],
) -> Result<SurfaceMesh, BuildError> {
    build_topology_closed(vertex_count, triangles, false)
}

/// The topology of a soup this crate made as a closed oriented surface (every edge in two
/// faces that run it opposite ways, every vertex one fan, every vertex `0..vertex_count` used),
/// with the soup's vertex and face ids: [`build_topology_closed`]'s mesh (components allowed)
/// without the checks that the soup is one (debug builds run them and compare).
pub(crate) fn closed_topology_of_trusted(
    vertex_count: usize,
    triangles: &[[u32; 3]],
) -> SurfaceMesh {
    let p = CornerPairing::pair_only(vertex_count, triangles);
    debug_assert!(p.inspection.problems.is_empty() && p.dropped.is_empty());
    debug_assert!(p.edges.same_direction.iter().all(|&same| !same));
    let mesh = p.into_mesh();
    debug_assert_eq!(
        Ok(&mesh),
        build_topology_closed(vertex_count, triangles, true).as_ref()
    );
    mesh
}

/// [`build_topology`], allowing several connected components when `components` is set.
pub(crate) fn build_topology_closed(
    vertex_count: usize,
    triangles: &[[u32; 3]],
    components: bool,
) -> Result<SurfaceMesh, BuildError> {
    let (mesh, report) = build_closed(vertex_count, triangles, components)?;
    if report.reoriented_faces > 0 || !report.dropped_vertices.is_empty() {
        return Err(BuildError::NotAsGiven {
            reoriented_faces: report.reoriented_faces,
            dropped_vertices: report.dropped_vertices.len(),
        });
    }
    Ok(mesh)
}

impl SurfaceMesh {
    /// The tetrahedron boundary as a mesh (the smallest simplicial closed surface).
    pub fn tetrahedron() -> Self {
        build_topology(4, &[[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]])
            .expect("the tetrahedron is a valid closed surface")
    }
}
