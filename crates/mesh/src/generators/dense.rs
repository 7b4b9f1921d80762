//! Compaction of a [`Surface`]: dense ids for the mesh and its positions together.

use super::Surface;
use crate::compact::Renumbering;

impl Surface {
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
