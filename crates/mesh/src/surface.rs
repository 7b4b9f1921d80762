//! [`Surface`]: a validated mesh together with its vertex positions, the value every generator
//! returns and every command that keeps positions works on.

use crate::build::BuildReport;
use crate::compact::Renumbering;
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
        Self::from_triangles_with_report(positions, triangles).map(|(surface, _)| surface)
    }

    /// [`Self::from_triangles`], also returning what building changed: vertex ids are the input
    /// indices with unreferenced vertices dropped ([`BuildReport::vertex_old_to_new`]), face ids
    /// the input face indices.
    ///
    /// # Errors
    /// As [`Self::from_triangles`].
    pub fn from_triangles_with_report(
        positions: Vec<Point3>,
        triangles: &[[u32; 3]],
    ) -> Result<(Self, BuildReport), BuildError> {
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
        Ok((Self { mesh, positions }, report))
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

    /// Removes the mesh's tombstones ([`crate::SurfaceMesh::compact`]) and permutes the positions
    /// to match, so vertex, edge and face ids are dense. Returns the old-to-new maps. O(n).
    pub fn compact(&mut self) -> Renumbering {
        let map = self.mesh.compact();
        let mut positions = vec![[0.0; 3]; self.mesh.vertex_slots()];
        for (old, new) in map.vertices.iter().enumerate() {
            if new.is_valid() {
                positions[new.idx()] = self.positions[old];
            }
        }
        self.positions = positions;
        map
    }
}
