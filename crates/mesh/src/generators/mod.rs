//! Deterministic generators of closed surfaces (positions + triangles), for tests and benchmarks.
//!
//! Every generator returns a [`Surface`]: a validated mesh with its positions. Randomised
//! generators take a seed and give the same surface for the same seed (`ChaCha8Rng`).

mod basic;

pub use basic::{icosphere, tetrahedron, torus};

use crate::error::BuildError;
use crate::geometry::Point3;
use crate::topology::SurfaceMesh;

/// A mesh together with its vertex positions (indexed by vertex id).
#[derive(Clone, Debug, PartialEq)]
pub struct Surface {
    /// The topology.
    pub mesh: SurfaceMesh,
    /// Position of each vertex slot.
    pub positions: Vec<Point3>,
}

impl Surface {
    /// Builds and validates a surface from positions and triangles.
    ///
    /// # Errors
    /// Any [`BuildError`] of [`crate::build()`], or non-finite positions.
    pub fn from_triangles(
        positions: Vec<Point3>,
        triangles: &[[u32; 3]],
    ) -> Result<Self, BuildError> {
        crate::geometry::check_finite(&positions)?;
        let (mesh, report) = crate::build(positions.len(), triangles)?;
        let positions = if report.dropped_vertices.is_empty() {
            positions
        } else {
            let mut kept = vec![[0.0; 3]; mesh.vertex_slots()];
            for (old, new) in report.vertex_old_to_new.iter().enumerate() {
                if new.is_valid() {
                    kept[new.idx()] = positions[old];
                }
            }
            kept
        };
        Ok(Self { mesh, positions })
    }

    /// The triangles of the live faces (in face order) with vertices renumbered densely, and the
    /// matching dense positions: a soup ready to write.
    pub fn to_triangles(&self) -> (Vec<Point3>, Vec<[u32; 3]>) {
        let mut dense = vec![u32::MAX; self.mesh.vertex_slots()];
        let mut positions = Vec::with_capacity(self.mesh.vertex_count());
        for v in self.mesh.vertices() {
            dense[v.idx()] = positions.len() as u32;
            positions.push(self.positions[v.idx()]);
        }
        let triangles = self
            .mesh
            .faces()
            .map(|f| self.mesh.face_vertices(f).map(|v| dense[v.idx()]))
            .collect();
        (positions, triangles)
    }
}
