//! Deterministic generators of closed surfaces (positions + triangles), for tests and benchmarks.
//!
//! Every generator returns a [`Surface`]: a validated mesh with its positions. Randomised
//! generators take a seed and give the same surface for the same seed (`ChaCha8Rng`). Every result
//! has dense ids (see [`Surface::compact`]).
//!
//! | generator | what it gives |
//! |---|---|
//! | [`tetrahedron()`] | the boundary of a tetrahedron (4 vertices, genus 0) |
//! | [`icosphere`]`(s)` | an icosahedron refined `s` times, on the unit sphere |
//! | [`torus`]`(m, n)` | an `m x n` grid torus of revolution (genus 1) |
//! | [`genus_surface`]`(g, size)` | a slab with `g` square through-holes (genus `g`), resolution `size` |
//! | [`cavity_box`]`(c, h, target)` / [`CavityBox`] | the papers' brick with `c` cavities and `h` through-holes (genus `h`) at about `target` triangles |
//! | [`random_flips`]`(surface, k, seed)` | `k` random simplicial edge flips (irregular connectivity) |
//! | [`subdivide_midpoint`]`(surface, levels)` | 1-to-4 midpoint subdivision, `levels` times |
//! | [`random_vertex_splits`]`(surface, k, seed)` | `k` random vertex splits (the inverse of contractions) |
//! | [`simplify`]`(surface, faces, seed)` | random link-condition edge contractions down to `faces` faces (same genus) |
//! | [`shuffle_faces`]`(surface, seed)` | the same triangles listed in a seeded random order |

mod basic;
mod cavity_box;
mod dense;
mod flips;
mod genus;
mod polycube;
mod shuffle;
mod simplify;
mod subdivide;
mod vertex_splits;

pub use basic::{icosphere, sheared_torus, tetrahedron, torus};
pub use cavity_box::{CavityBox, cavity_box};
pub use flips::random_flips;
pub use genus::genus_surface;
pub use shuffle::shuffle_faces;
pub use simplify::simplify;
pub use subdivide::subdivide_midpoint;
pub use vertex_splits::random_vertex_splits;

use crate::build::BuildReport;
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
}
