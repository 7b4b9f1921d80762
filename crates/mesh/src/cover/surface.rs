//! [`CoveredSurface`]: a [`ClosedCover`] with the positions of the surface's vertices.

use super::{ClosedCover, Lifting};
use crate::Surface;
use crate::build::BuildReport;
use crate::compact::Renumbering;
use crate::error::BuildError;
use crate::geometry::Point3;

/// A compact triangulated surface with positions: its [`ClosedCover`] and the position of each
/// vertex class (the apex class's entry is unused).
#[derive(Clone, Debug, PartialEq)]
pub struct CoveredSurface {
    /// The topology.
    pub cover: ClosedCover,
    /// Position of each vertex class.
    pub positions: Vec<Point3>,
}

impl CoveredSurface {
    /// Builds the cover of the surface a triangle soup forms ([`ClosedCover::from_triangles`])
    /// and keeps the positions of its vertices.
    ///
    /// # Errors
    /// Non-finite positions, and the errors of [`ClosedCover::from_triangles`].
    pub fn from_triangles(
        positions: Vec<Point3>,
        triangles: &[[u32; 3]],
    ) -> Result<(Self, BuildReport), BuildError> {
        crate::geometry::check_finite(&positions)?;
        let (cover, report) = ClosedCover::from_triangles(positions.len(), triangles)?;
        let mut kept = vec![[0.0; 3]; cover.sheets.class_count()];
        for (old, new) in report.vertex_old_to_new.iter().enumerate() {
            if new.is_valid() {
                kept[new.idx()] = positions[old];
            }
        }
        Ok((
            Self {
                cover,
                positions: kept,
            },
            report,
        ))
    }

    /// The surface's triangles (in face id order) and the positions of the vertices they use,
    /// renumbered densely in class order: a soup ready to write.
    pub fn to_triangles(&self) -> (Vec<Point3>, Vec<[u32; 3]>) {
        let triangles = self.cover.surface_triangles();
        let mut dense = vec![u32::MAX; self.cover.sheets.class_count()];
        for &c in triangles.iter().flatten() {
            dense[c as usize] = 0;
        }
        let mut positions = Vec::new();
        for (c, d) in dense.iter_mut().enumerate() {
            if *d == 0 {
                *d = positions.len() as u32;
                positions.push(self.positions[c]);
            }
        }
        let triangles = triangles
            .into_iter()
            .map(|t| t.map(|c| dense[c as usize]))
            .collect();
        (positions, triangles)
    }

    /// Removes the cover's tombstones ([`ClosedCover::compact`]) and renumbers the classes
    /// densely ([`ClosedCover::compact_classes`]), the positions with them. O(n).
    pub fn compact(&mut self) -> Renumbering {
        let plain = self.cover.is_plain();
        let map = self.cover.compact();
        let classes = if plain {
            map.vertices.iter().map(|v| v.0).collect()
        } else {
            self.cover.compact_classes()
        };
        let mut positions = vec![[0.0; 3]; self.cover.sheets.class_count()];
        for (old, &new) in classes.iter().enumerate() {
            if new != u32::MAX {
                positions[new as usize] = self.positions[old];
            }
        }
        self.positions = positions;
        map
    }

    /// The surface as a closed orientable [`Surface`] when it is one ([`ClosedCover::is_plain`]:
    /// classes are then vertex ids).
    pub fn into_plain(self) -> Option<Surface> {
        if !self.cover.is_plain() {
            return None;
        }
        Some(Surface {
            mesh: self.cover.mesh,
            positions: self.positions,
        })
    }
}

impl From<Surface> for CoveredSurface {
    /// A closed orientable surface as its own cover.
    fn from(surface: Surface) -> Self {
        CoveredSurface {
            cover: ClosedCover::plain(surface.mesh),
            positions: surface.positions,
        }
    }
}
