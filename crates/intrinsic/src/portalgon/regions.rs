//! The regions of Dubois' Section 4.4: a partition of a portalgon's polygons with one active
//! region.

use crate::geometry::Scalar;
use crate::portalgon::{PolygonId, Portalgon, SideId};

/// The partition of a portalgon's polygons into regions, one of them active (Dubois,
/// Section 4.4, Figure 4): the data structure of the paper's ALGORITHM. A side matched to a side
/// of a polygon in another region lies on a *separating* edge. Regions are plain labels per
/// polygon id; after [`Portalgon::cut`] the caller assigns the new polygon (usually to the region
/// of the cut one), and [`Regions::sub_portalgon`] extracts a region with its border as boundary.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Regions {
    region: Vec<u32>,
    active: u32,
    count: u32,
}

impl Regions {
    /// Every polygon of `portalgon` in region 0, which is active.
    pub fn new<S: Scalar>(portalgon: &Portalgon<S>) -> Self {
        Self {
            region: vec![0; portalgon.polygon_slots()],
            active: 0,
            count: 1,
        }
    }
    /// The region of a polygon (polygons created after [`Regions::new`] and never assigned are
    /// in the active region).
    pub fn region(&self, p: PolygonId) -> u32 {
        self.region.get(p.idx()).copied().unwrap_or(self.active)
    }
    /// Puts polygon `p` in region `r`.
    pub fn assign(&mut self, p: PolygonId, r: u32) {
        if self.region.len() <= p.idx() {
            self.region.resize(p.idx() + 1, self.active);
        }
        self.region[p.idx()] = r;
        self.count = self.count.max(r + 1);
    }
    /// Follows [`Portalgon::compact_in_place`]: each live polygon keeps its region under its new
    /// id (`polygon_map` is the map that returned).
    pub fn renumber(&mut self, polygon_map: &[PolygonId]) {
        let live = polygon_map.iter().filter(|p| p.is_valid()).count();
        let mut region = vec![self.active; live];
        for (old, new) in polygon_map.iter().enumerate() {
            if new.is_valid() {
                region[new.idx()] = self.region(PolygonId(old as u32));
            }
        }
        self.region = region;
    }
    /// A fresh region label.
    pub fn new_region(&mut self) -> u32 {
        self.count += 1;
        self.count - 1
    }
    /// The active region.
    pub fn active(&self) -> u32 {
        self.active
    }
    /// Makes region `r` the active one.
    pub fn set_active(&mut self, r: u32) {
        self.active = r;
        self.count = self.count.max(r + 1);
    }
    /// The live polygons of region `r`, increasing ids.
    pub fn polygons_in<S: Scalar>(&self, portalgon: &Portalgon<S>, r: u32) -> Vec<PolygonId> {
        portalgon
            .polygons()
            .filter(|&p| self.region(p) == r)
            .collect()
    }
    /// Whether side `s` is matched to a side of a polygon in another region.
    pub fn is_separating<S: Scalar>(&self, portalgon: &Portalgon<S>, s: SideId) -> bool {
        portalgon
            .mate(s)
            .is_some_and(|t| self.region(portalgon.owner(s)) != self.region(portalgon.owner(t)))
    }
    /// The sub-portalgon of region `r` (see [`Portalgon::sub_portalgon`]).
    pub fn sub_portalgon<S: Scalar>(
        &self,
        portalgon: &Portalgon<S>,
        r: u32,
    ) -> (Portalgon<S>, Vec<SideId>) {
        portalgon.sub_portalgon(&self.polygons_in(portalgon, r))
    }
}
