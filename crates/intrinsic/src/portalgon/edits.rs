//! Portalgon edits for Dubois' Sections 4.1–4.3 and Appendix B, beside the elementary ones of
//! [`crate::portalgon`]:
//! - [`Portalgon::split_side`]: INSERTVERTICES' step (Section 4.1), a new vertex on both copies
//!   of a matched side;
//! - [`Portalgon::vertex_info`]: the vertices of the surface with their degree, whether they are
//!   interior, on a loop edge, and so *weak* or *strong* (Section 4.2);
//! - [`Portalgon::components`]: the connected components of a sub-portalgon with their Euler
//!   characteristic, boundary cycles and interior vertices (Section 4.3's tubes, Appendix B);
//! - [`Portalgon::splice`]: replace a sub-portalgon by another with the same boundary, keeping
//!   the ids of the boundary sides (docs/dubois.md §3.6: cap boundaries and separating loops survive
//!   every replacement).
//!
//! The edits are exact in exact mode; tests check [`Portalgon::check_invariants`] and that the
//! surface is unchanged (area, cone angles, boundary) after each one (`tests/portalgon_edits.rs`).

use std::cmp::Ordering;
use std::collections::HashSet;

use crate::geometry::{Point, Scalar, add, midpoint, scale, sub};
use crate::portalgon::{PolygonId, Portalgon, SideId};
use surftopo_mesh::UnionFind;

/// Why an edit was refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum EditError {
    /// The side is removed or out of range.
    #[error("side {0} does not exist")]
    NoSuchSide(usize),
    /// The polygon is removed, out of range or listed twice.
    #[error("polygon {0} does not exist or is listed twice")]
    NoSuchPolygon(usize),
    /// The split parameter is not strictly between 0 and 1.
    #[error("side {side}: split parameter {value} is not strictly between 0 and 1")]
    SplitParameter {
        /// The side.
        side: usize,
        /// The parameter, as a double.
        value: f64,
    },
    /// The replacement's boundary does not match the replaced sub-portalgon's.
    #[error("splice: {0}")]
    Boundary(String),
}

/// The vertices of a portalgon's surface (Section 4.2), from [`Portalgon::vertex_info`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VertexInfo {
    /// Per side id: the vertex of its start corner (`u32::MAX` for removed sides).
    pub class: Vec<u32>,
    /// Per vertex: the number of edge ends at it (a loop counts twice).
    pub degree: Vec<u32>,
    /// Per vertex: whether it lies in the interior of the surface (no unmatched side at it).
    pub interior: Vec<bool>,
    /// Per vertex: whether a loop edge (both ends at it) is incident to it.
    pub on_loop: Vec<bool>,
    /// Per vertex: one side starting at it (the lowest id).
    pub side: Vec<SideId>,
}

impl VertexInfo {
    /// The number of vertices.
    pub fn count(&self) -> usize {
        self.degree.len()
    }
    /// Section 4.2: *weak* when interior and on no loop edge; *strong* otherwise.
    pub fn is_weak(&self, v: usize) -> bool {
        self.interior[v] && !self.on_loop[v]
    }
}

/// A connected component of a sub-portalgon, from [`Portalgon::components`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Component {
    /// Its polygons, increasing ids.
    pub polygons: Vec<PolygonId>,
    /// Vertices, edges and faces of its tessellation.
    pub vertices: usize,
    /// Edges: pairs of sides matched inside the component, plus boundary sides.
    pub edges: usize,
    /// `vertices − edges + faces`.
    pub euler_characteristic: i64,
    /// The boundary cycles, each the boundary sides in order (the surface on their left), from
    /// its lowest side id; cycles ordered by that id.
    pub boundary_cycles: Vec<Vec<SideId>>,
    /// One side starting at each interior vertex (its lowest id), increasing.
    pub interior_vertices: Vec<SideId>,
}

impl Component {
    /// Whether the component is a topological annulus with exactly one vertex on each boundary
    /// component, each boundary component a single side (Section 3's tube, up to flatness and
    /// triangularity, which the tube test checks).
    pub fn is_annulus_with_single_side_boundaries(&self) -> bool {
        self.euler_characteristic == 0
            && self.boundary_cycles.len() == 2
            && self.boundary_cycles.iter().all(|c| c.len() == 1)
    }
}

impl<S: Scalar> Portalgon<S> {
    /// INSERTVERTICES' step (Section 4.1): a new vertex at parameter `λ ∈ (0, 1)` of side `s`
    /// (the point `start + λ(end − start)`), on both copies when `s` is matched (at `1 − λ` of
    /// its mate). `s` keeps its first half and its mate `t` its first half; the new sides are the
    /// second halves, and the halves are cross-matched (`s`'s first half with `t`'s second).
    /// `λ = ½` uses [`midpoint`], exact in both arithmetic modes. The new corners have no vertex
    /// label. Returns the new side after `s` and, when matched, the new side after `t`. O(k).
    ///
    /// # Errors
    /// [`EditError::NoSuchSide`], [`EditError::SplitParameter`].
    pub fn split_side(
        &mut self,
        s: SideId,
        lambda: &S,
    ) -> Result<(SideId, Option<SideId>), EditError> {
        if !self.is_side_live(s) {
            return Err(EditError::NoSuchSide(s.idx()));
        }
        let one = S::one();
        if lambda.sign() != Ordering::Greater || *lambda >= one {
            return Err(EditError::SplitParameter {
                side: s.idx(),
                value: lambda.to_f64(),
            });
        }
        let half = one.half();
        let point_at = |me: &Self, x: SideId, l: &S| -> Point<S> {
            let (a, b) = (me.start_ref(x), me.end_ref(x));
            if *l == half {
                midpoint(a, b)
            } else {
                add(a, &scale(l, &sub(b, a)))
            }
        };
        let mate = self.mate(s);
        let x = point_at(self, s, lambda);
        let y = mate.map(|t| point_at(self, t, &(S::one() - lambda.clone())));
        let s2 = self.insert_side_after(s, x);
        let Some(t) = mate else {
            return Ok((s2, None));
        };
        let t2 = self.insert_side_after(t, y.expect("mate point"));
        self.mate[s.idx()] = t2;
        self.mate[t2.idx()] = s;
        self.mate[s2.idx()] = t;
        self.mate[t.idx()] = s2;
        Ok((s2, Some(t2)))
    }

    /// A fresh unmatched side starting at `start`, inserted after `s` in its polygon.
    fn insert_side_after(&mut self, s: SideId, start: Point<S>) -> SideId {
        let p = self.owner(s);
        let new = self.fresh_side(start, u32::MAX);
        let mut sides = std::mem::take(&mut self.polygons[p.idx()]);
        sides.insert(self.side_index(s) + 1, new);
        self.set_polygon(p, sides);
        self.live_sides += 1;
        new
    }

    /// A new side id (not yet in a polygon, unmatched).
    fn fresh_side(&mut self, start: Point<S>, label: u32) -> SideId {
        let s = SideId(self.start.len() as u32);
        self.start.push(start);
        self.owner.push(PolygonId::INVALID);
        self.mate.push(SideId::INVALID);
        self.label.push(label);
        self.slot.push(0);
        self.next.push(SideId::INVALID);
        s
    }

    /// Vertex classes of the surface of the polygons with `in_set[p]`: start corners identified
    /// through sides matched inside the set. Returns the class per side id (`u32::MAX` outside)
    /// and the count; classes are numbered by their lowest side id.
    pub(crate) fn classes_within(&self, in_set: &[bool]) -> (Vec<u32>, usize) {
        let n = self.side_slots();
        let mut uf = UnionFind::new(n);
        let inside = |s: SideId| in_set[self.owner(s).idx()];
        for s in self.sides().filter(|&s| inside(s)) {
            if let Some(t) = self.mate(s).filter(|&t| inside(t)) {
                uf.union(s.0, self.next_side(t).0);
            }
        }
        let mut class = vec![u32::MAX; n];
        let mut root_class = vec![u32::MAX; n];
        let mut count = 0u32;
        for s in self.sides().filter(|&s| inside(s)) {
            let r = uf.find(s.0) as usize;
            if root_class[r] == u32::MAX {
                root_class[r] = count;
                count += 1;
            }
            class[s.idx()] = root_class[r];
        }
        (class, count as usize)
    }

    /// Section 4.2's vertex classification of the whole surface (boundary = unmatched sides):
    /// degree, interior, on a loop edge, hence weak or strong ([`VertexInfo::is_weak`]). O(n α(n)).
    pub fn vertex_info(&self) -> VertexInfo {
        let in_set = vec![true; self.polygon_slots()];
        self.vertex_info_of_set(&in_set)
    }

    /// Section 4.2's classification on the surface of the sub-portalgon of `polygons` (Section
    /// 2.1: sides matched to polygons outside the set are boundary), e.g. the active region `R_A`
    /// of Section 4.4. Sides outside the set get class `u32::MAX`. O(n α(n)).
    ///
    /// # Errors
    /// [`EditError::NoSuchPolygon`] for a removed or repeated polygon.
    pub fn vertex_info_within(&self, polygons: &[PolygonId]) -> Result<VertexInfo, EditError> {
        let in_set = self.polygon_set(polygons)?;
        Ok(self.vertex_info_of_set(&in_set))
    }

    fn vertex_info_of_set(&self, in_set: &[bool]) -> VertexInfo {
        let (class, count) = self.classes_within(in_set);
        let mut info = VertexInfo {
            degree: vec![0; count],
            interior: vec![true; count],
            on_loop: vec![false; count],
            side: vec![SideId::INVALID; count],
            class,
        };
        let inside = |s: SideId| in_set[self.owner(s).idx()];
        for s in self.sides().filter(|&s| inside(s)) {
            let (v, w) = (
                info.class[s.idx()] as usize,
                info.class[self.next_side(s).idx()] as usize,
            );
            info.degree[v] += 1;
            if !info.side[v].is_valid() {
                info.side[v] = s;
            }
            if !self.mate(s).is_some_and(inside) {
                info.degree[w] += 1;
                info.interior[v] = false;
                info.interior[w] = false;
            }
            if v == w {
                info.on_loop[v] = true;
            }
        }
        info
    }

    /// The connected components of the sub-portalgon of `polygons` (Section 2.1: sides matched
    /// to polygons outside the set are boundary), each with its Euler characteristic, boundary
    /// cycles and interior vertices, ordered by lowest polygon id. O(k log k) in the size `k` of
    /// the set, whatever the size of the portalgon (Dubois' routines ask for every tube
    /// component of the active region).
    ///
    /// # Errors
    /// [`EditError::NoSuchPolygon`] for a removed or repeated polygon.
    pub fn components(&self, polygons: &[PolygonId]) -> Result<Vec<Component>, EditError> {
        let set = LocalSet::new(self, polygons)?;
        let inside = |s: SideId| set.polygon(self.owner(s)).is_some();
        let internal = |s: SideId| self.mate(s).is_some_and(inside);
        // Vertex classes of the sides (start corners identified through internal sides), on
        // set-local side indices.
        let mut vertex_uf = UnionFind::new(set.side_count());
        for &p in &set.polygons {
            for &s in self.polygon_sides(p) {
                if let Some(t) = self.mate(s).filter(|&t| inside(t)) {
                    let (a, b) = (set.side(self, s), set.side(self, self.next_side(t)));
                    vertex_uf.union(a.expect("inside") as u32, b.expect("inside") as u32);
                }
            }
        }
        let mut out: Vec<Component> = set
            .polygon_components(self)
            .into_iter()
            .map(|members| Component {
                polygons: members.into_iter().map(|i| set.polygons[i]).collect(),
                vertices: 0,
                edges: 0,
                euler_characteristic: 0,
                boundary_cycles: Vec::new(),
                interior_vertices: Vec::new(),
            })
            .collect();
        // Per vertex class (a root of `vertex_uf`) its lowest side and whether it is on the
        // boundary.
        let mut lowest = vec![SideId::INVALID; set.side_count()];
        let mut on_boundary = vec![false; set.side_count()];
        for c in &mut out {
            let mut roots: Vec<u32> = Vec::new();
            let mut boundary: Vec<SideId> = Vec::new();
            let mut sides = 0;
            for &p in &c.polygons {
                for &s in self.polygon_sides(p) {
                    sides += 1;
                    let r = vertex_uf.find(set.side(self, s).expect("inside") as u32);
                    let l = &mut lowest[r as usize];
                    if !l.is_valid() {
                        roots.push(r);
                        *l = s;
                    } else if s < *l {
                        *l = s;
                    }
                    if !internal(s) {
                        boundary.push(s);
                        on_boundary[r as usize] = true;
                    }
                }
            }
            c.vertices = roots.len();
            c.edges = (sides - boundary.len()) / 2 + boundary.len();
            c.euler_characteristic = c.vertices as i64 - c.edges as i64 + c.polygons.len() as i64;
            let mut interior: Vec<SideId> = roots
                .iter()
                .filter(|&&r| !on_boundary[r as usize])
                .map(|&r| lowest[r as usize])
                .collect();
            interior.sort_unstable();
            c.interior_vertices = interior;
            boundary.sort_unstable();
            let mut seen: HashSet<SideId> = HashSet::new();
            for &b in &boundary {
                if seen.contains(&b) {
                    continue;
                }
                let mut cycle = vec![b];
                let mut x = self.next_boundary_side(b, &internal);
                while x != b {
                    cycle.push(x);
                    x = self.next_boundary_side(x, &internal);
                }
                seen.extend(&cycle);
                c.boundary_cycles.push(cycle);
            }
        }
        Ok(out)
    }

    /// The components of the sub-portalgon of `polygons` bounded by exactly two sides, as
    /// [`Self::components`] gives them and in its order: the only components that can be tubes
    /// (Section 3: an annulus whose two boundary components are single sides). The connectivity
    /// of the whole set costs O(k α(k)); only these components are analysed further.
    ///
    /// # Errors
    /// [`EditError::NoSuchPolygon`] for a removed or repeated polygon.
    pub fn two_sided_components(
        &self,
        polygons: &[PolygonId],
    ) -> Result<Vec<Component>, EditError> {
        let set = LocalSet::new(self, polygons)?;
        let mut out = Vec::new();
        for members in set.polygon_components_where(self, |boundary_sides| boundary_sides == 2) {
            let group: Vec<PolygonId> = members.into_iter().map(|i| set.polygons[i]).collect();
            out.extend(self.components(&group)?);
        }
        Ok(out)
    }

    /// The boundary side after boundary side `b` along its boundary cycle: around the vertex at
    /// the end of `b`, across internal sides until a boundary side leaves it.
    fn next_boundary_side(&self, b: SideId, internal: &impl Fn(SideId) -> bool) -> SideId {
        let mut x = self.next_side(b);
        while internal(x) {
            x = self.next_side(self.mate(x).expect("internal sides are matched"));
        }
        x
    }

    /// Per polygon slot: whether it is in `polygons` (all live, none twice).
    fn polygon_set(&self, polygons: &[PolygonId]) -> Result<Vec<bool>, EditError> {
        let mut in_set = vec![false; self.polygon_slots()];
        for &p in polygons {
            if !self.is_polygon_live(p) || std::mem::replace(&mut in_set[p.idx()], true) {
                return Err(EditError::NoSuchPolygon(p.idx()));
            }
        }
        Ok(in_set)
    }

    /// Replaces the sub-portalgon of `old` by the portalgon `new` (docs/dubois.md §3.6; Section 4.3's
    /// "replace X by a good biface"), keeping the ids of the boundary sides. `boundary` pairs each
    /// unmatched side of `new` with a boundary side of the sub-portalgon (a side of `old` not
    /// matched inside it), one to one, with equal lengths (exactly in exact mode, up to the relative
    /// `tolerance` on lengths in f64) and the same cyclic order along the boundary cycles. Each
    /// boundary side id then lives on in the new polygon, with its mate outside and its vertex
    /// label; the other sides of `old` and the polygons of `old` are removed (tombstones), the
    /// polygons of `new` get fresh ids (returned, in `new`'s order) and its internal sides fresh
    /// ids. The caller vouches for the geometry (the same surface); the combinatorics are checked.
    /// O(size of old + new).
    ///
    /// # Errors
    /// [`EditError::NoSuchPolygon`], [`EditError::NoSuchSide`] (a side of `new` out of range),
    /// [`EditError::Boundary`] saying which pair or side breaks the correspondence.
    pub fn splice(
        &mut self,
        old: &[PolygonId],
        new: &Portalgon<S>,
        boundary: &[(SideId, SideId)],
        tolerance: f64,
    ) -> Result<Vec<PolygonId>, EditError> {
        // Hash sets, not per-id arrays: a splice costs the size of `old` and `new`, not of `self`.
        let mut in_set: HashSet<PolygonId> = HashSet::with_capacity(old.len());
        for &p in old {
            if !self.is_polygon_live(p) || !in_set.insert(p) {
                return Err(EditError::NoSuchPolygon(p.idx()));
            }
        }
        let inside = |me: &Self, s: SideId| me.is_side_live(s) && in_set.contains(&me.owner(s));
        let internal_old = |s: SideId| self.mate(s).is_some_and(|t| inside(self, t));
        let old_boundary: Vec<SideId> = old
            .iter()
            .flat_map(|&p| self.polygon_sides(p).iter().copied())
            .filter(|&s| !internal_old(s))
            .collect();
        let new_boundary: Vec<SideId> = new.unmatched_sides().collect();
        if boundary.len() != old_boundary.len() || boundary.len() != new_boundary.len() {
            return Err(EditError::Boundary(format!(
                "{} pairs for {} boundary sides replaced by {}",
                boundary.len(),
                old_boundary.len(),
                new_boundary.len()
            )));
        }
        let mut to_old = vec![SideId::INVALID; new.side_slots()];
        let mut used: HashSet<SideId> = HashSet::with_capacity(boundary.len());
        for &(n, o) in boundary {
            if !new.is_side_live(n) {
                return Err(EditError::NoSuchSide(n.idx()));
            }
            if new.mate(n).is_some() || to_old[n.idx()].is_valid() {
                return Err(EditError::Boundary(format!(
                    "side {} of the replacement is matched or paired twice",
                    n.0
                )));
            }
            if !inside(self, o) || internal_old(o) || !used.insert(o) {
                return Err(EditError::Boundary(format!(
                    "side {} is not a boundary side of the replaced polygons, or paired twice",
                    o.0
                )));
            }
            let (ln, lo) = (new.side_length2(n), self.side_length2(o));
            if !S::lengths_match(&ln, &lo, tolerance * (2.0 - tolerance)) {
                return Err(EditError::Boundary(format!(
                    "side {} (length {}) paired with side {} (length {})",
                    n.0,
                    new.side_length(n),
                    o.0,
                    self.side_length(o)
                )));
            }
            to_old[n.idx()] = o;
        }
        let internal_new = |s: SideId| new.mate(s).is_some();
        for &(n, o) in boundary {
            let (n2, o2) = (
                new.next_boundary_side(n, &internal_new),
                self.next_boundary_side(o, &internal_old),
            );
            if to_old[n2.idx()] != o2 {
                return Err(EditError::Boundary(format!(
                    "after side {} comes {} in the replacement, but after side {} comes {}",
                    n.0, n2.0, o.0, o2.0
                )));
            }
        }
        // Remove the old polygons; their boundary sides wait for their new polygons.
        for &p in old {
            let sides = std::mem::take(&mut self.polygons[p.idx()]);
            self.live_polygons -= 1;
            self.live_sides -= sides.len();
            for s in sides {
                self.owner[s.idx()] = PolygonId::INVALID;
                self.next[s.idx()] = SideId::INVALID;
                if !used.contains(&s) {
                    self.mate[s.idx()] = SideId::INVALID;
                }
            }
        }
        let mut image = vec![SideId::INVALID; new.side_slots()];
        let mut created = Vec::new();
        for q in new.polygons() {
            let p = PolygonId(self.polygons.len() as u32);
            self.polygons.push(Vec::new());
            let sides: Vec<SideId> = new
                .polygon_sides(q)
                .iter()
                .map(|&n| {
                    let s = if to_old[n.idx()].is_valid() {
                        let o = to_old[n.idx()];
                        self.start[o.idx()] = new.start(n);
                        o
                    } else {
                        self.fresh_side(new.start(n), new.label[n.idx()])
                    };
                    image[n.idx()] = s;
                    s
                })
                .collect();
            self.live_sides += sides.len();
            self.live_polygons += 1;
            self.set_polygon(p, sides);
            created.push(p);
        }
        for n in new.sides() {
            if let Some(m) = new.mate(n) {
                self.mate[image[n.idx()].idx()] = image[m.idx()];
            }
        }
        Ok(created)
    }
}

/// A set of live polygons with set-local indices for them and their sides (polygon `i` of the
/// sorted set owns the side indices `offset[i]..offset[i + 1]`, in side order), so that work on
/// a small set costs its size, not the portalgon's.
struct LocalSet {
    /// The polygons, increasing ids.
    polygons: Vec<PolygonId>,
    offset: Vec<usize>,
    /// Per polygon slot, its index in the set (`u32::MAX` outside) when the set is a large
    /// part of the portalgon; else lookups search `polygons`.
    dense: Option<Vec<u32>>,
}

impl LocalSet {
    fn new<S: Scalar>(p: &Portalgon<S>, polygons: &[PolygonId]) -> Result<Self, EditError> {
        let mut sorted = polygons.to_vec();
        sorted.sort_unstable();
        if let Some(&q) = sorted.iter().find(|&&q| !p.is_polygon_live(q)) {
            return Err(EditError::NoSuchPolygon(q.idx()));
        }
        if let Some(w) = sorted.windows(2).find(|w| w[0] == w[1]) {
            return Err(EditError::NoSuchPolygon(w[0].idx()));
        }
        let mut offset = Vec::with_capacity(sorted.len() + 1);
        offset.push(0);
        for &q in &sorted {
            offset.push(offset.last().copied().unwrap_or(0) + p.polygon_sides(q).len());
        }
        let dense = (4 * sorted.len() >= p.polygon_slots()).then(|| {
            let mut index = vec![u32::MAX; p.polygon_slots()];
            for (i, &q) in sorted.iter().enumerate() {
                index[q.idx()] = i as u32;
            }
            index
        });
        Ok(Self {
            polygons: sorted,
            offset,
            dense,
        })
    }

    /// The set-local index of polygon `q`, when in the set.
    fn polygon(&self, q: PolygonId) -> Option<usize> {
        match &self.dense {
            Some(index) => index
                .get(q.idx())
                .filter(|&&i| i != u32::MAX)
                .map(|&i| i as usize),
            None => self.polygons.binary_search(&q).ok(),
        }
    }

    /// The set-local index of side `s`, when its polygon is in the set.
    fn side<S: Scalar>(&self, p: &Portalgon<S>, s: SideId) -> Option<usize> {
        self.polygon(p.owner(s))
            .map(|i| self.offset[i] + p.side_index(s))
    }

    /// The number of sides of the set.
    fn side_count(&self) -> usize {
        self.offset.last().copied().unwrap_or(0)
    }

    /// The connected components of the set through the sides matched inside it: per component
    /// the set-local indices of its polygons, increasing; components by their lowest polygon.
    fn polygon_components<S: Scalar>(&self, p: &Portalgon<S>) -> Vec<Vec<usize>> {
        self.polygon_components_where(p, |_| true)
    }

    /// [`Self::polygon_components`], keeping only the components whose number of boundary sides
    /// (sides not matched inside the set) satisfies `keep`; the others are never listed.
    fn polygon_components_where<S: Scalar>(
        &self,
        p: &Portalgon<S>,
        keep: impl Fn(usize) -> bool,
    ) -> Vec<Vec<usize>> {
        let n = self.polygons.len();
        let mut uf = UnionFind::new(n);
        let mut boundary_sides = vec![0usize; n];
        for (i, &q) in self.polygons.iter().enumerate() {
            for &s in p.polygon_sides(q) {
                match p.mate(s).and_then(|t| self.polygon(p.owner(t))) {
                    // Each matched pair is seen from both polygons: unite once.
                    Some(j) if j > i => {
                        uf.union(i as u32, j as u32);
                    }
                    Some(_) => {}
                    None => boundary_sides[i] += 1,
                }
            }
        }
        let mut boundary_of_root = vec![0usize; n];
        let roots: Vec<usize> = (0..n).map(|i| uf.find(i as u32) as usize).collect();
        for (i, &r) in roots.iter().enumerate() {
            boundary_of_root[r] += boundary_sides[i];
        }
        let mut component_of_root = vec![usize::MAX; n];
        let mut out: Vec<Vec<usize>> = Vec::new();
        for (i, &r) in roots.iter().enumerate() {
            if !keep(boundary_of_root[r]) {
                continue;
            }
            if component_of_root[r] == usize::MAX {
                component_of_root[r] = out.len();
                out.push(Vec::new());
            }
            out[component_of_root[r]].push(i);
        }
        out
    }
}
