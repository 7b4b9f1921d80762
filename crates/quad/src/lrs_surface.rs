//! LRS on every compact surface (placeholder while the expansion through the cover is written).

use surftopo_matching::{Pairing, SurfaceDual};
use surftopo_mesh::ClosedCover;

use crate::QuadError;
use crate::lrs::ExpansionCases;

pub(crate) struct SurfaceExpansion {
    pub cover: ClosedCover,
    pub flipped_edges: usize,
    pub cases: ExpansionCases,
}

impl SurfaceExpansion {
    pub fn pairing_on(&self, dual: &SurfaceDual) -> Result<Pairing, QuadError> {
        Ok(Pairing::empty(surftopo_matching::DualGraph::node_slots(
            dual,
        )))
    }
}

pub(crate) fn pair(cover: &ClosedCover) -> Result<SurfaceExpansion, QuadError> {
    Ok(SurfaceExpansion {
        cover: cover.clone(),
        flipped_edges: 0,
        cases: ExpansionCases::default(),
    })
}
