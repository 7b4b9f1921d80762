//! The portalgon structure: polygons, sides, the matching, their queries and validation, and the
//! elementary edits ([`Portalgon::cut`], [`Portalgon::merge`], [`Portalgon::delete_vertex`],
//! [`Portalgon::glue`] / [`Portalgon::unglue`], [`Portalgon::sub_portalgon`]); see the module
//! doc of [`crate::portalgon`].

use std::cmp::Ordering;

use crate::error::PortalgonError;
use crate::geometry::{
    Motion, Point, Scalar, Tolerances, crossing_sides, dist_f64, dist2, dot, orient,
    segments_intersect, sub, twice_signed_area,
};

/// [`Tolerances::length`]'s default, the relative tolerance on the lengths of matched sides
/// (`|a - b| <= 1e-9 · max(a, b)`), as a constant for the callers that take one.
pub const DEFAULT_LENGTH_TOLERANCE: f64 = Tolerances::DEFAULT.length;

surftopo_mesh::id_type!(
    /// A side of a polygon of a portalgon.
    SideId,
    "s"
);
surftopo_mesh::id_type!(
    /// A polygon of a portalgon.
    PolygonId,
    "p"
);

/// A 2D point in double precision (`Point<f64>`).
pub type Point2 = [f64; 2];

/// Signed area of a closed polygon (positive when counter-clockwise; exact in exact mode).
pub fn signed_area<S: Scalar>(corners: &[Point<S>]) -> S {
    twice_signed_area(corners).half()
}

/// Whether the direction from corner `cur` towards `target` points strictly into the interior
/// angle of a counter-clockwise polygon at `cur` (neighbours `prev` and `next`). Exact signs
/// ([`orient`]).
pub(crate) fn points_inside<S: Scalar>(
    prev: &Point<S>,
    cur: &Point<S>,
    next: &Point<S>,
    target: &Point<S>,
) -> bool {
    let (less, greater) = (Ordering::Less, Ordering::Greater);
    if orient(cur, next, prev) != less {
        // Convex (or straight) corner: strictly between the two sides counter-clockwise.
        orient(cur, next, target) == greater && orient(cur, target, prev) == greater
    } else {
        // Reflex corner: anywhere but the closed exterior wedge from `prev` to `next`.
        !(orient(cur, prev, target) != less && orient(cur, target, next) != less)
    }
}

/// Whether the segment from corner `i` to corner `j` of `c` makes, at `i` or at `j`, an angle of
/// sine below [`Tolerances::shortcut_sine`] (and positive cosine) with one of the two sides there
/// (evaluated in `f64`; [`Portalgon::shortcut`]).
fn arc_leaves_along_a_side<S: Scalar>(c: &[Point<S>], i: usize, j: usize) -> bool {
    let k = c.len();
    let f = |x: &Point<S>| [x[0].to_f64(), x[1].to_f64()];
    let along = |from: usize, to: usize| {
        let o = f(&c[from]);
        let d = |x: &Point<S>| {
            let x = f(x);
            [x[0] - o[0], x[1] - o[1]]
        };
        let arc = d(&c[to]);
        [&c[(from + 1) % k], &c[(from + k - 1) % k]]
            .iter()
            .any(|&side| {
                let s = d(side);
                let cross = arc[0] * s[1] - arc[1] * s[0];
                let dot = arc[0] * s[0] + arc[1] * s[1];
                let norms = arc[0].hypot(arc[1]) * s[0].hypot(s[1]);
                dot > 0.0 && cross.abs() < Tolerances::DEFAULT.shortcut_sine * norms
            })
    };
    along(i, j) || along(j, i)
}

/// Validates the corners of a polygon: at least three, finite, no zero side, counter-clockwise and
/// simple (no two sides meet except consecutive ones at their common corner). O(k log k) exact
/// predicates: consecutive sides folding back onto each other in one pass, then the sweep of
/// Shamos and Hoey over the other pairs ([`crate::geometry::crossing_sides`]).
///
/// # Errors
/// The first problem, naming `polygon` and the corner or side; for a polygon that is not simple,
/// the first consecutive pair that folds back, else the pair of sides the sweep meets first.
pub fn check_polygon<S: Scalar>(
    polygon: usize,
    corners: &[Point<S>],
) -> Result<(), PortalgonError> {
    let k = corners.len();
    if k < 3 {
        return Err(PortalgonError::TooFewCorners {
            polygon,
            corners: k,
        });
    }
    if let Some(index) = corners
        .iter()
        .position(|c| !(c[0].is_finite() && c[1].is_finite()))
    {
        return Err(PortalgonError::NonFinite { polygon, index });
    }
    for i in 0..k {
        if corners[i] == corners[(i + 1) % k] {
            return Err(PortalgonError::ZeroSide { polygon, side: i });
        }
    }
    let area = twice_signed_area(corners);
    if area.sign() != Ordering::Greater {
        return Err(PortalgonError::NotCounterClockwise {
            polygon,
            area: area.half().to_f64(),
        });
    }
    for a in 0..k {
        let (p, q, r) = (&corners[a], &corners[(a + 1) % k], &corners[(a + 2) % k]);
        // Consecutive sides must not fold back onto each other.
        if orient(p, q, r) == Ordering::Equal
            && dot(&sub(q, p), &sub(r, q)).sign() == Ordering::Less
        {
            return Err(PortalgonError::NotSimple {
                polygon,
                a,
                b: (a + 1) % k,
            });
        }
    }
    match crossing_sides(corners) {
        Some((a, b)) => Err(PortalgonError::NotSimple { polygon, a, b }),
        None => Ok(()),
    }
}

/// A portalgon: polygons with a partial matching of their sides (see the module doc), corners
/// in the scalar type `S` (`f64` by default; [`crate::geometry::Rational`] for exact mode).
#[derive(Clone, Debug, PartialEq)]
pub struct Portalgon<S: Scalar = f64> {
    /// Per side: its start corner, in its polygon's plane.
    pub(crate) start: Vec<Point<S>>,
    /// Per side: its polygon (`INVALID` for a removed side).
    pub(crate) owner: Vec<PolygonId>,
    /// Per side: the matched side (`INVALID` when unmatched).
    pub(crate) mate: Vec<SideId>,
    /// Per side: the vertex label of its start corner (`u32::MAX` when unknown).
    pub(crate) label: Vec<u32>,
    /// Per side: its index in its polygon's side list.
    pub(crate) slot: Vec<u32>,
    /// Per side: the next side of its polygon (cached from the side lists).
    pub(crate) next: Vec<SideId>,
    /// Per polygon: its sides, counter-clockwise (empty for a removed polygon).
    pub(crate) polygons: Vec<Vec<SideId>>,
    pub(crate) live_polygons: usize,
    pub(crate) live_sides: usize,
}

impl<S: Scalar> Default for Portalgon<S> {
    fn default() -> Self {
        Portalgon {
            start: Vec::new(),
            owner: Vec::new(),
            mate: Vec::new(),
            label: Vec::new(),
            slot: Vec::new(),
            next: Vec::new(),
            polygons: Vec::new(),
            live_polygons: 0,
            live_sides: 0,
        }
    }
}

impl Portalgon {
    /// An empty portalgon in double precision (see [`Portalgon::empty`] for other scalars).
    pub fn new() -> Self {
        Self::default()
    }
}

impl<S: Scalar> Portalgon<S> {
    /// An empty portalgon over any scalar type.
    pub fn empty() -> Self {
        Self::default()
    }

    /// The same portalgon (ids, matching and labels kept) with every corner coordinate mapped by
    /// `f`, e.g. into another scalar type.
    pub fn map_coordinates<T: Scalar>(&self, f: impl Fn(&S) -> T) -> Portalgon<T> {
        Portalgon {
            start: self.start.iter().map(|[x, y]| [f(x), f(y)]).collect(),
            owner: self.owner.clone(),
            mate: self.mate.clone(),
            label: self.label.clone(),
            slot: self.slot.clone(),
            next: self.next.clone(),
            polygons: self.polygons.clone(),
            live_polygons: self.live_polygons,
            live_sides: self.live_sides,
        }
    }

    /// Moves every polygon's chart so that its first corner is the origin (a translation of
    /// each polygon: the surface, the ids and the matching are unchanged, since gluings are
    /// recomputed from the sides). In exact arithmetic the corners are then differences, as
    /// small as the polygon whatever its position: charts that drift (a chart laid out by a
    /// gluing motion far from the origin) stop carrying the drift's digits.
    pub fn translate_to_first_corners(&mut self) {
        for sides in &self.polygons {
            let Some(&first) = sides.first() else {
                continue;
            };
            let origin = self.start[first.idx()].clone();
            if origin[0].is_zero() && origin[1].is_zero() {
                continue;
            }
            for &s in sides {
                let corner = &mut self.start[s.idx()];
                *corner = sub(corner, &origin);
            }
        }
    }

    /// The largest size in bits of a live corner's coordinate ([`Scalar::bits`]; 0 in rounded
    /// arithmetic).
    pub fn max_coordinate_bits(&self) -> u64 {
        if !S::EXACT {
            return 0;
        }
        self.sides()
            .map(|s| {
                let [x, y] = &self.start[s.idx()];
                x.bits().max(y.bits())
            })
            .max()
            .unwrap_or(0)
    }

    /// Number of live polygons.
    pub fn polygon_count(&self) -> usize {
        self.live_polygons
    }
    /// Number of live sides.
    pub fn side_count(&self) -> usize {
        self.live_sides
    }
    /// Size of the polygon id range (live and removed).
    pub fn polygon_slots(&self) -> usize {
        self.polygons.len()
    }
    /// Size of the side id range (live and removed).
    pub fn side_slots(&self) -> usize {
        self.start.len()
    }
    /// Whether a polygon id is live.
    pub fn is_polygon_live(&self, p: PolygonId) -> bool {
        self.polygons.get(p.idx()).is_some_and(|s| !s.is_empty())
    }
    /// Whether a side id is live.
    pub fn is_side_live(&self, s: SideId) -> bool {
        self.owner.get(s.idx()).is_some_and(|p| p.is_valid())
    }
    /// Live polygon ids.
    pub fn polygons(&self) -> impl Iterator<Item = PolygonId> + '_ {
        (0..self.polygons.len() as u32)
            .map(PolygonId)
            .filter(|&p| self.is_polygon_live(p))
    }
    /// Live side ids.
    pub fn sides(&self) -> impl Iterator<Item = SideId> + '_ {
        (0..self.start.len() as u32)
            .map(SideId)
            .filter(|&s| self.is_side_live(s))
    }

    /// The sides of a polygon, counter-clockwise.
    pub fn polygon_sides(&self, p: PolygonId) -> &[SideId] {
        &self.polygons[p.idx()]
    }
    /// Side `i` of polygon `p`.
    pub fn side(&self, p: PolygonId, i: usize) -> SideId {
        self.polygons[p.idx()][i]
    }
    /// The polygon of a side.
    pub fn owner(&self, s: SideId) -> PolygonId {
        self.owner[s.idx()]
    }
    /// The index of a side in its polygon.
    pub fn side_index(&self, s: SideId) -> usize {
        self.slot[s.idx()] as usize
    }
    /// The next side counter-clockwise in the same polygon.
    #[inline]
    pub fn next_side(&self, s: SideId) -> SideId {
        self.next[s.idx()]
    }
    /// The previous side in the same polygon.
    pub fn prev_side(&self, s: SideId) -> SideId {
        let sides = &self.polygons[self.owner(s).idx()];
        sides[(self.side_index(s) + sides.len() - 1) % sides.len()]
    }
    /// Start corner of a side (a copy; [`Self::start_ref`] borrows it).
    pub fn start(&self, s: SideId) -> Point<S> {
        self.start[s.idx()].clone()
    }
    /// End corner of a side (the start of the next side).
    pub fn end(&self, s: SideId) -> Point<S> {
        self.start(self.next_side(s))
    }
    /// Start corner of a side, borrowed.
    #[inline]
    pub fn start_ref(&self, s: SideId) -> &Point<S> {
        &self.start[s.idx()]
    }
    /// End corner of a side, borrowed.
    #[inline]
    pub fn end_ref(&self, s: SideId) -> &Point<S> {
        &self.start[self.next_side(s).idx()]
    }
    /// Squared length of a side (exact in exact mode).
    pub fn side_length2(&self, s: SideId) -> S {
        dist2(self.start_ref(s), self.end_ref(s))
    }
    /// Length of a side, as a double (a square root in exact mode).
    pub fn side_length(&self, s: SideId) -> f64 {
        dist_f64(self.start_ref(s), self.end_ref(s))
    }
    /// The side matched with `s`, if any.
    pub fn mate(&self, s: SideId) -> Option<SideId> {
        let m = self.mate[s.idx()];
        m.is_valid().then_some(m)
    }
    /// The vertex label of the start corner of `s`, if known.
    pub fn vertex_label(&self, s: SideId) -> Option<u32> {
        let l = self.label[s.idx()];
        (l != u32::MAX).then_some(l)
    }
    /// The corners of a polygon, counter-clockwise.
    pub fn corners(&self, p: PolygonId) -> Vec<Point<S>> {
        self.polygons[p.idx()]
            .iter()
            .map(|&s| self.start(s))
            .collect()
    }
    /// Signed area of a polygon.
    pub fn polygon_area(&self, p: PolygonId) -> S {
        signed_area(&self.corners(p))
    }
    /// Total area of the live polygons.
    pub fn area(&self) -> S {
        self.polygons()
            .fold(S::zero(), |sum, p| sum + self.polygon_area(p))
    }

    /// Adds a validated polygon ([`check_polygon`]) with unmatched sides and no vertex labels.
    ///
    /// # Errors
    /// As [`check_polygon`], naming the new polygon's id.
    pub fn add_polygon(&mut self, corners: &[Point<S>]) -> Result<PolygonId, PortalgonError> {
        check_polygon(self.polygons.len(), corners)?;
        Ok(self.push_polygon(corners, None))
    }

    /// Adds a polygon without validation (crate-internal: shapes known to be valid).
    pub(crate) fn push_polygon(
        &mut self,
        corners: &[Point<S>],
        labels: Option<&[u32]>,
    ) -> PolygonId {
        let p = PolygonId(self.polygons.len() as u32);
        let mut sides = Vec::with_capacity(corners.len());
        for (i, c) in corners.iter().enumerate() {
            let s = SideId(self.start.len() as u32);
            self.start.push(c.clone());
            self.owner.push(p);
            self.mate.push(SideId::INVALID);
            self.label.push(labels.map_or(u32::MAX, |l| l[i]));
            self.slot.push(i as u32);
            self.next.push(SideId(s.0 + 1));
            sides.push(s);
        }
        let last = sides[sides.len() - 1];
        self.next[last.idx()] = sides[0];
        self.polygons.push(sides);
        self.live_polygons += 1;
        self.live_sides += corners.len();
        p
    }

    /// Sets the vertex labels of a polygon's corners (`labels[i]` for corner `i`).
    ///
    /// # Errors
    /// [`PortalgonError::NoSuchPolygon`], or [`PortalgonError::VertexLabels`] when the count is wrong.
    pub fn set_vertex_labels(
        &mut self,
        p: PolygonId,
        labels: &[u32],
    ) -> Result<(), PortalgonError> {
        if !self.is_polygon_live(p) {
            return Err(PortalgonError::NoSuchPolygon(p.idx()));
        }
        let sides = &self.polygons[p.idx()];
        if labels.len() != sides.len() {
            return Err(PortalgonError::VertexLabels {
                polygon: p.idx(),
                detail: format!("{} labels for {} corners", labels.len(), sides.len()),
            });
        }
        for (&s, &l) in sides.iter().zip(labels) {
            self.label[s.idx()] = l;
        }
        Ok(())
    }

    fn side_ref(&self, s: SideId) -> (usize, usize) {
        if self.is_side_live(s) {
            (self.owner(s).idx(), self.side_index(s))
        } else {
            (usize::MAX, s.idx())
        }
    }

    /// Matches sides `s` and `t` (of the same or different polygons); their lengths must agree up to
    /// `tolerance` relative to the longer one (exactly in exact mode, [`Scalar::lengths_match`]).
    /// The squared lengths are compared: `|a − b| ≤ tol · max(a, b)` iff
    /// `|a² − b²| ≤ tol(2 − tol) · max(a, b)²`, so the tolerance means what it meant on lengths.
    ///
    /// # Errors
    /// [`PortalgonError::NoSuchSide`], [`PortalgonError::MatchedTwice`] (already matched, or
    /// `s == t`), [`PortalgonError::UnequalSides`].
    pub fn glue(&mut self, s: SideId, t: SideId, tolerance: f64) -> Result<(), PortalgonError> {
        self.glue_at_scale(s, t, tolerance, 0.0)
    }

    /// [`Self::glue`], where in `f64` the lengths may also differ by up to `tolerance · scale`:
    /// for a short side whose corners carry rounding errors of the size of a larger polygon
    /// around it (`scale` its longest side), as when a side comes back from a long computation.
    /// Exact mode ignores `scale`.
    ///
    /// # Errors
    /// As [`Self::glue`].
    pub fn glue_at_scale(
        &mut self,
        s: SideId,
        t: SideId,
        tolerance: f64,
        scale: f64,
    ) -> Result<(), PortalgonError> {
        for x in [s, t] {
            if !self.is_side_live(x) {
                return Err(PortalgonError::NoSuchSide {
                    polygon: usize::MAX,
                    side: x.idx(),
                });
            }
            if self.mate[x.idx()].is_valid() || s == t {
                let (polygon, side) = self.side_ref(x);
                return Err(PortalgonError::MatchedTwice { polygon, side });
            }
        }
        let (la, lb) = (self.side_length2(s), self.side_length2(t));
        let within_scale =
            || !S::EXACT && (self.side_length(s) - self.side_length(t)).abs() <= tolerance * scale;
        if !S::lengths_match(&la, &lb, tolerance * (2.0 - tolerance)) && !within_scale() {
            let (la, lb) = (self.side_length(s), self.side_length(t));
            let (polygon_a, side_a) = self.side_ref(s);
            let (polygon_b, side_b) = self.side_ref(t);
            return Err(PortalgonError::UnequalSides {
                polygon_a,
                side_a,
                polygon_b,
                side_b,
                length_a: la,
                length_b: lb,
                tolerance,
            });
        }
        self.mate[s.idx()] = t;
        self.mate[t.idx()] = s;
        Ok(())
    }

    /// Unmatches `s` from its mate (cutting the surface along that side); returns the former mate.
    pub fn unglue(&mut self, s: SideId) -> Option<SideId> {
        let m = self.mate(s)?;
        self.mate[s.idx()] = SideId::INVALID;
        self.mate[m.idx()] = SideId::INVALID;
        Some(m)
    }

    /// Checks the invariants every edit keeps: the per-side arrays have one entry per side id;
    /// every live polygon has at least three sides, each owned by it, at its index, its cached
    /// next side the following one; no side is in two polygons, and every side in no polygon is
    /// a tombstone (no owner, no mate, no next); mates are live and symmetric, never the side
    /// itself; the live counts are right; every polygon is valid ([`check_polygon`]: finite, no
    /// zero side, counter-clockwise, simple). O(Σ k²). Merging the polygons around a vertex whose
    /// angle exceeds 2π makes a polygon that overlaps itself in the plane ([`Self::merge`]):
    /// this check reports it as not simple.
    ///
    /// # Errors
    /// [`PortalgonError::Invariant`] saying what is wrong where, or the polygon's
    /// [`check_polygon`] error.
    pub fn check_invariants(&self) -> Result<(), PortalgonError> {
        let fail = |what: String| Err(PortalgonError::Invariant(what));
        let n = self.start.len();
        if [
            self.owner.len(),
            self.mate.len(),
            self.label.len(),
            self.slot.len(),
            self.next.len(),
        ]
        .iter()
        .any(|&l| l != n)
        {
            return fail(format!("per-side arrays differ in length ({n} corners)"));
        }
        let mut seen = vec![false; n];
        let (mut live_polygons, mut live_sides) = (0usize, 0usize);
        for (pi, sides) in self.polygons.iter().enumerate() {
            if sides.is_empty() {
                continue;
            }
            live_polygons += 1;
            live_sides += sides.len();
            let k = sides.len();
            if k < 3 {
                return fail(format!("polygon {pi} has {k} sides"));
            }
            for (i, &s) in sides.iter().enumerate() {
                if s.idx() >= n || std::mem::replace(&mut seen[s.idx()], true) {
                    return fail(format!(
                        "side {} of polygon {pi} is out of range or shared",
                        s.0
                    ));
                }
                if self.owner[s.idx()] != PolygonId(pi as u32)
                    || self.slot[s.idx()] as usize != i
                    || self.next[s.idx()] != sides[(i + 1) % k]
                {
                    return fail(format!(
                        "side {} (index {i} of polygon {pi}): cached owner {:?}, index {}, next {:?}",
                        s.0,
                        self.owner[s.idx()],
                        self.slot[s.idx()],
                        self.next[s.idx()]
                    ));
                }
            }
            check_polygon(pi, &self.corners(PolygonId(pi as u32)))?;
        }
        for s in 0..n {
            let m = self.mate[s];
            if !seen[s] {
                if self.owner[s].is_valid() || m.is_valid() || self.next[s].is_valid() {
                    return fail(format!("side {s} is in no polygon but not a tombstone"));
                }
                continue;
            }
            if m.is_valid()
                && (m.idx() >= n || !seen[m.idx()] || self.mate[m.idx()].idx() != s || m.idx() == s)
            {
                return fail(format!(
                    "side {s} is matched to {} which is not matched back",
                    m.0
                ));
            }
        }
        if (live_polygons, live_sides) != (self.live_polygons, self.live_sides) {
            return fail(format!(
                "live counts {} polygons, {} sides cached; {live_polygons} and {live_sides} found",
                self.live_polygons, self.live_sides
            ));
        }
        Ok(())
    }

    /// The unmatched live sides (the boundary of the surface).
    pub fn unmatched_sides(&self) -> impl Iterator<Item = SideId> + '_ {
        self.sides().filter(|&s| self.mate(s).is_none())
    }

    /// Checks that the portalgon is non-empty and every side is matched.
    ///
    /// # Errors
    /// [`PortalgonError::Empty`] or [`PortalgonError::Unmatched`] naming the first unmatched side.
    pub fn check_closed(&self) -> Result<(), PortalgonError> {
        if self.live_polygons == 0 {
            return Err(PortalgonError::Empty);
        }
        match self.unmatched_sides().next() {
            Some(s) => {
                let (polygon, side) = self.side_ref(s);
                Err(PortalgonError::Unmatched { polygon, side })
            }
            None => Ok(()),
        }
    }

    /// The corners around the vertex at the start of `s`, counter-clockwise: the sides leaving the
    /// vertex, `s` first (`s`, `mate(prev(s))`, ...). `None` when a side on the way is unmatched.
    pub fn star(&self, s: SideId) -> Option<Vec<SideId>> {
        let mut out = vec![s];
        let mut cur = s;
        loop {
            let next = self.mate(self.prev_side(cur))?;
            if next == s {
                return Some(out);
            }
            if out.len() > self.side_slots() {
                return None;
            }
            out.push(next);
            cur = next;
        }
    }

    /// The vertices of the surface: the class of each side's start corner under the gluing
    /// (indexed by side id, `u32::MAX` for removed sides; classes numbered by first side), and the
    /// number of classes. O(n α(n)).
    pub fn vertex_classes(&self) -> (Vec<u32>, usize) {
        self.classes_within(&vec![true; self.polygon_slots()])
    }

    /// Whether the segment between corners `i` and `j` of polygon `p` is a vertex-to-vertex arc
    /// (Section 4.1): distinct, non-consecutive corners whose open segment lies in the interior of
    /// the polygon. O(k).
    pub fn is_arc(&self, p: PolygonId, i: usize, j: usize) -> bool {
        let c = self.corners(p);
        let k = c.len();
        if i >= k || j >= k || i == j || (i + 1) % k == j || (j + 1) % k == i {
            return false;
        }
        let (a, b) = (&c[i], &c[j]);
        if a == b {
            return false;
        }
        if !points_inside(&c[(i + k - 1) % k], a, &c[(i + 1) % k], b)
            || !points_inside(&c[(j + k - 1) % k], b, &c[(j + 1) % k], a)
        {
            return false;
        }
        for s in 0..k {
            let e = (s + 1) % k;
            if s == i || e == i || s == j || e == j {
                continue;
            }
            if segments_intersect(a, b, &c[s], &c[e]) {
                return false;
            }
        }
        // Sides through an endpoint may still run along the segment; the wedge tests at both
        // endpoints exclude that for the sides at them, and the other sides were tested above.
        true
    }

    /// A shortcut of polygon `p` (Section 4.1): a shortest vertex-to-vertex arc, as its two corner
    /// indices `(i, j)` with `i < j`; `None` for triangles. Ties (of the squared lengths) go to the
    /// smallest `(i, j)`. O(k³).
    ///
    /// **\[decision, `f64` only\] Degenerate candidates.** In exact mode a corner of angle π (a
    /// midpoint of INSERTVERTICES, a cap point of Section 8) is straight, and the segment across
    /// it lies on the boundary: no arc. In `f64` the rounded corner is off the line by an ulp and
    /// [`Self::is_arc`] (exact signs on the rounded values) accepts that segment, whose piece is a
    /// triangle of area ~1e-16 relative to its sides (zero when evaluated in `f64`). So in `f64`
    /// an arc that leaves one of its endpoints within [`Tolerances::shortcut_sine`] of a side there
    /// (the angle's sine below it, cosine positive: a sharp piece corner) is skipped when a
    /// non-degenerate arc exists; only when every arc is degenerate is the shortest of them
    /// taken (a polygon that is itself a needle of aspect ratio beyond 1e9). Exact mode is the
    /// paper's rule verbatim.
    pub fn shortcut(&self, p: PolygonId) -> Option<(usize, usize)> {
        let c = self.corners(p);
        let k = c.len();
        let mut pairs: Vec<(S, usize, usize)> = Vec::new();
        for i in 0..k {
            for j in i + 2..k {
                if !(i == 0 && j == k - 1) {
                    pairs.push((dist2(&c[i], &c[j]), i, j));
                }
            }
        }
        pairs.sort_by(|x, y| {
            x.0.partial_cmp(&y.0)
                .unwrap_or(Ordering::Equal)
                .then((x.1, x.2).cmp(&(y.1, y.2)))
        });
        let mut degenerate = None;
        for (_, i, j) in pairs {
            if !self.is_arc(p, i, j) {
                continue;
            }
            if S::EXACT || !arc_leaves_along_a_side(&c, i, j) {
                return Some((i, j));
            }
            degenerate.get_or_insert((i, j));
        }
        degenerate
    }

    /// Cuts polygon `p` along the arc between its corners `i` and `j` (INSERTEDGES' elementary
    /// step, Section 4.1): `p` keeps corners `i..=j` and a new polygon gets corners `j..=i`; the two
    /// new sides (from j to i in `p`, from i to j in the new polygon) are matched to each other
    /// and returned in that order. In rounded arithmetic both pieces are then translated so
    /// that their first corner is the origin (exact mode keeps the corners). O(k).
    ///
    /// # Errors
    /// [`PortalgonError::NoSuchPolygon`], [`PortalgonError::NotAnArc`].
    pub fn cut(
        &mut self,
        p: PolygonId,
        i: usize,
        j: usize,
    ) -> Result<(SideId, SideId), PortalgonError> {
        if !self.is_polygon_live(p) {
            return Err(PortalgonError::NoSuchPolygon(p.idx()));
        }
        if !self.is_arc(p, i, j) {
            return Err(PortalgonError::NotAnArc {
                polygon: p.idx(),
                i,
                j,
            });
        }
        Ok(self.cut_along_arc(p, i, j))
    }

    /// [`Self::cut`] of a live polygon along corners `i, j` known to bound an arc (as
    /// [`Self::shortcut`] returns them: its test is not repeated).
    fn cut_along_arc(&mut self, p: PolygonId, i: usize, j: usize) -> (SideId, SideId) {
        let sides = std::mem::take(&mut self.polygons[p.idx()]);
        let k = sides.len();
        let q = PolygonId(self.polygons.len() as u32);
        self.polygons.push(Vec::new());
        let (corner_i, corner_j) = (self.start(sides[i]), self.start(sides[j]));
        let (label_i, label_j) = (self.label[sides[i].idx()], self.label[sides[j].idx()]);
        let new_side = |me: &mut Self, start: Point<S>, label: u32, owner: PolygonId| {
            let s = SideId(me.start.len() as u32);
            me.start.push(start);
            me.owner.push(owner);
            me.mate.push(SideId::INVALID);
            me.label.push(label);
            me.slot.push(0);
            me.next.push(SideId::INVALID);
            s
        };
        let in_p = new_side(self, corner_j, label_j, p);
        let in_q = new_side(self, corner_i, label_i, q);
        self.mate[in_p.idx()] = in_q;
        self.mate[in_q.idx()] = in_p;
        let j_after = if j > i { j } else { j + k };
        let i_after = if i > j { i } else { i + k };
        let mut first: Vec<SideId> = (i..j_after).map(|m| sides[m % k]).collect();
        first.push(in_p);
        let mut second: Vec<SideId> = (j..i_after).map(|m| sides[m % k]).collect();
        second.push(in_q);
        self.set_polygon(p, first);
        self.set_polygon(q, second);
        self.live_polygons += 1;
        self.live_sides += 2;
        if !S::EXACT {
            self.recenter(p);
            self.recenter(q);
        }
        (in_p, in_q)
    }

    /// In rounded arithmetic, translates polygon `p` so that its first corner is the origin: a
    /// piece cut from a large polygon keeps that polygon's frame, where its coordinates can be
    /// many times its own size (thousands of times in `T′` of a mesh), and every later rounding
    /// (motions of merges, gluings) is relative to the coordinates, not to the piece.
    fn recenter(&mut self, p: PolygonId) {
        let origin = self.start(self.polygons[p.idx()][0]);
        for &x in &self.polygons[p.idx()] {
            self.start[x.idx()] = sub(&self.start[x.idx()], &origin);
        }
    }

    pub(crate) fn set_polygon(&mut self, p: PolygonId, sides: Vec<SideId>) {
        let k = sides.len();
        for (n, &s) in sides.iter().enumerate() {
            self.owner[s.idx()] = p;
            self.slot[s.idx()] = n as u32;
            self.next[s.idx()] = sides[(n + 1) % k];
        }
        self.polygons[p.idx()] = sides;
    }

    /// Matches two fresh sides without checks (crate-internal: built from a closed triangulation).
    pub(crate) fn set_mates(&mut self, s: SideId, t: SideId) {
        self.mate[s.idx()] = t;
        self.mate[t.idx()] = s;
    }

    /// Merges the polygon across side `s` into the polygon of `s` (the inverse of [`Self::cut`]):
    /// the other polygon is displaced rigidly so that the mate of `s` lies on `s`, the two sides
    /// disappear, and the merged polygon keeps the id of `s`'s polygon (returned). Other side ids
    /// are kept. O(k).
    ///
    /// # Errors
    /// [`PortalgonError::NoSuchSide`]; [`PortalgonError::CannotMerge`] when `s` is unmatched or
    /// matched to a side of its own polygon.
    pub fn merge(&mut self, s: SideId) -> Result<PolygonId, PortalgonError> {
        if !self.is_side_live(s) {
            return Err(PortalgonError::NoSuchSide {
                polygon: usize::MAX,
                side: s.idx(),
            });
        }
        let (p, side) = (self.owner(s), self.side_index(s));
        let t = match self.mate(s) {
            Some(t) if self.owner(t) != p => t,
            _ => {
                return Err(PortalgonError::CannotMerge {
                    polygon: p.idx(),
                    side,
                });
            }
        };
        let q = self.owner(t);
        // Footnote 2's rigid motion taking start(t) to end(s) and end(t) to start(s).
        let motion = Motion::gluing(
            self.start_ref(t),
            self.end_ref(t),
            self.end_ref(s),
            self.start_ref(s),
        );
        let q_sides = std::mem::take(&mut self.polygons[q.idx()]);
        for &x in &q_sides {
            self.start[x.idx()] = motion.apply(&self.start[x.idx()]);
        }
        let p_sides = std::mem::take(&mut self.polygons[p.idx()]);
        let (kp, kq) = (p_sides.len(), q_sides.len());
        let tq = q_sides
            .iter()
            .position(|&x| x == t)
            .expect("t is a side of q");
        let mut merged: Vec<SideId> = (1..kp).map(|m| p_sides[(side + m) % kp]).collect();
        merged.extend((1..kq).map(|m| q_sides[(tq + m) % kq]));
        for x in [s, t] {
            self.owner[x.idx()] = PolygonId::INVALID;
            self.mate[x.idx()] = SideId::INVALID;
            self.next[x.idx()] = SideId::INVALID;
        }
        self.set_polygon(p, merged);
        self.live_polygons -= 1;
        self.live_sides -= 2;
        Ok(p)
    }

    /// Deletes the vertex at the start corner of side `s` (DELETEVERTICES' elementary step,
    /// Section 4.2): the polygons around it are merged one by one across its incident sides
    /// ([`Self::merge`]) until the last two sides at it are matched to each other; those two are
    /// removed, and the vertex with them. The vertex must be weak (interior, not on a loop: every
    /// side at it matched, to a side of another polygon until the end) and flat (angle 2π, so the
    /// two corners beside the slit coincide: exactly in exact mode, within `tolerance` relative to
    /// the polygon's longest side in `f64`). Returns the polygon that replaces the star (it is usually not a triangle:
    /// [`Self::triangulate_by_shortcuts`] is INSERTEDGES). O(size of the star).
    ///
    /// # Errors
    /// [`PortalgonError::NoSuchSide`]; [`PortalgonError::CannotMerge`] naming an unmatched side or
    /// a side matched within its own polygon before the end (the vertex is on the boundary or on a
    /// loop); [`PortalgonError::NotFlat`]. The merges done before an error stay done (they do not
    /// change the surface).
    pub fn delete_vertex(
        &mut self,
        s: SideId,
        tolerance: f64,
    ) -> Result<PolygonId, PortalgonError> {
        if !self.is_side_live(s) {
            return Err(PortalgonError::NoSuchSide {
                polygon: usize::MAX,
                side: s.idx(),
            });
        }
        let mut out = s;
        loop {
            let into = self.prev_side(out);
            if self.mate(out) == Some(into) {
                break;
            }
            let t = match self.mate(out) {
                Some(t) if self.owner(t) != self.owner(out) => t,
                _ => {
                    return Err(PortalgonError::CannotMerge {
                        polygon: self.owner(out).idx(),
                        side: self.side_index(out),
                    });
                }
            };
            // After merging across `out`, the side leaving the vertex is the one after t.
            let next_out = self.next_side(t);
            self.merge(out)?;
            out = next_out;
        }
        // `into` ends at the vertex and `out` leaves it, glued to each other: a slit. The corners
        // at its two ends (start of `into`, end of `out`) must coincide.
        let into = self.prev_side(out);
        let p = self.owner(out);
        let (a, b) = (self.start(into), self.end(out));
        // Rounded: the gap within tolerance · longest side, squared (no square root per side).
        let apart = !S::same_point(&a, &b, || {
            let longest2 = self.polygons[p.idx()]
                .iter()
                .map(|&x| self.side_length2(x).to_f64())
                .fold(0.0, f64::max);
            tolerance * tolerance * longest2
        });
        if apart || self.polygons[p.idx()].len() < 5 {
            return Err(PortalgonError::NotFlat {
                polygon: p.idx(),
                gap: dist_f64(&a, &b),
            });
        }
        let after = self.next_side(out);
        let sides: Vec<SideId> = self.polygons[p.idx()]
            .iter()
            .copied()
            .filter(|&x| x != into && x != out)
            .collect();
        // The corner kept is the start of `into` (its label), now the start of `after`.
        self.label[after.idx()] = self.label[into.idx()];
        self.start[after.idx()] = a;
        for x in [into, out] {
            self.owner[x.idx()] = PolygonId::INVALID;
            self.mate[x.idx()] = SideId::INVALID;
            self.next[x.idx()] = SideId::INVALID;
        }
        self.live_sides -= 2;
        self.set_polygon(p, sides);
        Ok(p)
    }

    /// A copy with every polygon cut into triangles ([`Self::triangulate_polygon`], O(k log k)
    /// for a polygon of k corners), dense ids, labels kept: e.g. a Delaunay tessellation as a
    /// Delaunay triangulation, or a portalgon file's polygons.
    ///
    /// # Errors
    /// As [`Self::triangulate_polygon`].
    pub fn triangulated(&self) -> Result<Portalgon<S>, PortalgonError> {
        let mut t = self.clone();
        let polygons: Vec<_> = t.polygons().collect();
        for q in polygons {
            t.triangulate_polygon(q)?;
        }
        Ok(t.compacted().0)
    }

    /// Cuts polygon `p` (simple, counter-clockwise) into triangles by
    /// [`crate::geometry::triangulate_polygon`] (monotone pieces, O(k log k) exact predicates,
    /// no flat triangle); the new sides are matched in pairs. Returns the triangles (the first
    /// is `p`). Any triangulation, where [`Self::triangulate_by_shortcuts`] is INSERTEDGES' rule.
    ///
    /// # Errors
    /// [`PortalgonError::NoSuchPolygon`]; [`PortalgonError::NotAnArc`] (naming the polygon) if
    /// the sweep finds the polygon is not simple.
    pub fn triangulate_polygon(&mut self, p: PolygonId) -> Result<Vec<PolygonId>, PortalgonError> {
        if !self.is_polygon_live(p) {
            return Err(PortalgonError::NoSuchPolygon(p.idx()));
        }
        let sides = self.polygons[p.idx()].clone();
        let k = sides.len();
        if k == 3 {
            return Ok(vec![p]);
        }
        let corners = self.corners(p);
        let triangles =
            crate::geometry::triangulate_polygon(&corners).ok_or(PortalgonError::NotAnArc {
                polygon: p.idx(),
                i: 0,
                j: 0,
            })?;
        // The side of each diagonal made so far, by its (from, to) corners.
        let mut diagonal: std::collections::HashMap<(usize, usize), SideId> =
            std::collections::HashMap::new();
        let mut out = Vec::with_capacity(triangles.len());
        for (n, t) in triangles.iter().enumerate() {
            let q = if n == 0 {
                p
            } else {
                self.polygons.push(Vec::new());
                self.live_polygons += 1;
                PolygonId(self.polygons.len() as u32 - 1)
            };
            let mut own = Vec::with_capacity(3);
            for m in 0..3 {
                let (a, b) = (t[m], t[(m + 1) % 3]);
                if b == (a + 1) % k {
                    own.push(sides[a]);
                    continue;
                }
                let s = SideId(self.start.len() as u32);
                self.start.push(corners[a].clone());
                self.owner.push(q);
                self.mate.push(SideId::INVALID);
                self.label.push(self.label[sides[a].idx()]);
                self.slot.push(0);
                self.next.push(SideId::INVALID);
                self.live_sides += 1;
                if let Some(other) = diagonal.remove(&(b, a)) {
                    self.mate[s.idx()] = other;
                    self.mate[other.idx()] = s;
                } else {
                    diagonal.insert((a, b), s);
                }
                own.push(s);
            }
            self.set_polygon(q, own);
            if !S::EXACT {
                self.recenter(q);
            }
            out.push(q);
        }
        Ok(out)
    }

    /// INSERTEDGES (Section 4.1) on one polygon: as long as a piece is not a triangle, cut it along
    /// a shortcut. Returns the resulting triangles (the first is `p`). O(k⁴) in the worst case.
    ///
    /// # Errors
    /// [`PortalgonError::NoSuchPolygon`]; [`PortalgonError::NotAnArc`] if a piece has no arc at all
    /// (only possible for a polygon that overlaps itself).
    pub fn triangulate_by_shortcuts(
        &mut self,
        p: PolygonId,
    ) -> Result<Vec<PolygonId>, PortalgonError> {
        if !self.is_polygon_live(p) {
            return Err(PortalgonError::NoSuchPolygon(p.idx()));
        }
        let mut todo = vec![p];
        let mut done = Vec::new();
        while let Some(x) = todo.pop() {
            if self.polygon_sides(x).len() == 3 {
                done.push(x);
                continue;
            }
            let (i, j) = self.shortcut(x).ok_or(PortalgonError::NotAnArc {
                polygon: x.idx(),
                i: 0,
                j: 0,
            })?;
            let (_, in_q) = self.cut_along_arc(x, i, j);
            todo.push(self.owner(in_q));
            todo.push(x);
        }
        done.sort();
        Ok(done)
    }

    /// The sub-portalgon of the given polygons (Section 2.1): a copy with their corners and labels,
    /// two sides matched iff they are matched here and both belong to the subset (so sides matched
    /// across the subset's border become boundary). Returns it and the old-to-new side map
    /// (`INVALID` for sides not copied). Polygon `k` of the copy is `polygons[k]`.
    pub fn sub_portalgon(&self, polygons: &[PolygonId]) -> (Portalgon<S>, Vec<SideId>) {
        let mut sub_p = Portalgon::empty();
        let mut map = vec![SideId::INVALID; self.start.len()];
        for &p in polygons {
            if !self.is_polygon_live(p) {
                continue;
            }
            let labels: Vec<u32> = self
                .polygon_sides(p)
                .iter()
                .map(|s| self.label[s.idx()])
                .collect();
            let np = sub_p.push_polygon(&self.corners(p), Some(&labels));
            for (i, &s) in self.polygon_sides(p).iter().enumerate() {
                map[s.idx()] = sub_p.side(np, i);
            }
        }
        for s in self.sides() {
            if let Some(t) = self.mate(s)
                && map[s.idx()].is_valid()
                && map[t.idx()].is_valid()
            {
                sub_p.mate[map[s.idx()].idx()] = map[t.idx()];
            }
        }
        (sub_p, map)
    }

    /// A copy with dense ids (live polygons and sides in id order), and the old-to-new side map.
    pub fn compacted(&self) -> (Portalgon<S>, Vec<SideId>) {
        let live: Vec<PolygonId> = self.polygons().collect();
        self.sub_portalgon(&live)
    }

    /// Drops the removed polygons and sides in place, renumbering the live ones densely **in
    /// their id order** (side `s` becomes the number of live sides below `s`, likewise for
    /// polygons), so every rule that breaks ties by lowest id decides as before; new ids still
    /// come after every live one. Returns the old-to-new side and polygon maps (`INVALID` for
    /// removed ids). O(slots). Edits leave tombstones, so a long run of edits (Dubois'
    /// ALGORITHM) compacts from time to time to keep whole-portalgon passes proportional to the
    /// live size.
    pub fn compact_in_place(&mut self) -> (Vec<SideId>, Vec<PolygonId>) {
        let mut side_map = vec![SideId::INVALID; self.start.len()];
        let mut next_id = 0u32;
        for (s, m) in side_map.iter_mut().enumerate() {
            if self.owner[s].is_valid() {
                *m = SideId(next_id);
                next_id += 1;
            }
        }
        let mut polygon_map = vec![PolygonId::INVALID; self.polygons.len()];
        next_id = 0;
        for (p, m) in polygon_map.iter_mut().enumerate() {
            if !self.polygons[p].is_empty() {
                *m = PolygonId(next_id);
                next_id += 1;
            }
        }
        let keep = |old: usize| side_map[old].is_valid();
        let map_side = |s: SideId| {
            if s.is_valid() { side_map[s.idx()] } else { s }
        };
        let mut k = 0;
        for old in 0..self.start.len() {
            if !keep(old) {
                continue;
            }
            self.start.swap(k, old);
            self.owner[k] = polygon_map[self.owner[old].idx()];
            self.mate[k] = map_side(self.mate[old]);
            self.label[k] = self.label[old];
            self.slot[k] = self.slot[old];
            self.next[k] = map_side(self.next[old]);
            k += 1;
        }
        self.start.truncate(k);
        self.owner.truncate(k);
        self.mate.truncate(k);
        self.label.truncate(k);
        self.slot.truncate(k);
        self.next.truncate(k);
        self.polygons.retain(|sides| !sides.is_empty());
        for sides in &mut self.polygons {
            for s in sides.iter_mut() {
                *s = side_map[s.idx()];
            }
        }
        (side_map, polygon_map)
    }

    /// The mirror image (every polygon reflected across the x axis, orientations kept
    /// counter-clockwise by reversing the corner order; the matching carried over): the surface
    /// with the opposite orientation. Side `i` of a `k`-gon becomes side `k - 1 - i`.
    pub fn mirrored(&self) -> Portalgon<S> {
        let (dense, _) = self.compacted();
        let mut out = Portalgon::empty();
        for p in dense.polygons() {
            let sides = dense.polygon_sides(p);
            let k = sides.len();
            // New side m is old side k-1-m reversed; it starts at the old end corner.
            let corners: Vec<Point<S>> = (0..k)
                .map(|m| {
                    let [x, y] = dense.end(sides[k - 1 - m]);
                    [x, -y]
                })
                .collect();
            let labels: Vec<u32> = (0..k)
                .map(|m| dense.label[dense.next_side(sides[k - 1 - m]).idx()])
                .collect();
            out.push_polygon(&corners, Some(&labels));
        }
        let image = |s: SideId| {
            let p = dense.owner(s);
            let k = dense.polygon_sides(p).len();
            out.side(p, k - 1 - dense.side_index(s))
        };
        let pairs: Vec<(SideId, SideId)> = dense
            .sides()
            .filter_map(|s| dense.mate(s).map(|t| (image(s), image(t))))
            .collect();
        for (a, b) in pairs {
            out.mate[a.idx()] = b;
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square_cut() -> Portalgon {
        let mut p = Portalgon::new();
        let q = p
            .add_polygon(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])
            .unwrap();
        p.cut(q, 0, 2).unwrap();
        p.check_invariants().unwrap();
        p
    }

    #[test]
    fn check_invariants_finds_each_broken_cache() {
        let broken = |edit: &dyn Fn(&mut Portalgon)| {
            let mut p = square_cut();
            edit(&mut p);
            p.check_invariants().is_err()
        };
        assert!(broken(&|p| p.mate[0] = SideId(1)));
        assert!(broken(&|p| p.mate[4] = SideId::INVALID));
        assert!(broken(&|p| p.slot[1] = 0));
        assert!(broken(&|p| p.next[0] = SideId(2)));
        assert!(broken(&|p| p.owner[0] = PolygonId(1)));
        assert!(broken(&|p| p.live_sides += 1));
        assert!(broken(&|p| p.live_polygons -= 1));
        assert!(broken(&|p| p.start[1] = [3.0, 3.0]));
        assert!(broken(&|p| p.start[2] = [-2.0, -2.0]));
        assert!(broken(&|p| {
            p.label.pop();
        }));
        assert!(!broken(&|_| ()));
    }
}
