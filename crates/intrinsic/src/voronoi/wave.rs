//! The wave algorithm of Dubois, Appendix D.2 (Propositions 11, 13 and 14; Lemmas 40 and 41).
//!
//! For every triangle Δ of a closed triangular portalgon the wave maintains a planar point set
//! X_Δ, in Δ's own frame, initialised with the corners of Δ that are in V. A *candidate event*
//! `(t, Δ, s, x)` is a point `x' ∈ X_Δ'` of the triangle Δ' across side `s` whose closed planar
//! Voronoi cell `Vor(x', X_Δ')` meets the side `s'` matched with `s`, at distance `t` from `x'`;
//! `x` is `x'` carried into Δ's frame by the gluing isometry λ⁻¹ and must not be in X_Δ yet. The
//! algorithm pops a candidate event of smallest date, adds `x` to X_Δ, and repeats; at the end
//! X_Δ is the *constellation* V_Δ (Proposition 13), whose planar Voronoi diagram restricted to Δ is
//! the pre-image of the Voronoi diagram of V (Lemma 34).
//!
//! Lemma 41's structure, per side `s` of every triangle: the cells of X_Δ meeting `s`, as closed
//! parameter intervals `[lo, hi] ⊂ [0, 1]` along `s`, in order. Along a line the Voronoi cells
//! appear in the order of the sites' projections, and `z ↦ |p(u) − z|² − min_j |p(u) − y_j|²` is
//! convex and piecewise linear in `u`, so inserting a site `z` finds the point where that function
//! is least by bisection on the sign of its slope `⟨d, y_j − z⟩` (O(log k)) and then walks the
//! contiguous run of cells that `z` reaches (O(k′), Lemma 40's amortised bound). The run is spliced
//! into a vector (a `memmove`: O(k) bytes, not O(log k) — the deviation from Lemma 41's search
//! trees; the figures in `results/` say what it costs on T_x).
//!
//! Dates are squared distances (exact in exact mode: every cell end is the intersection of a
//! rational bisector with a rational segment). The event list is a binary heap with lazy
//! deletion: a cell carries a stamp, renewed whenever its interval changes, and a popped event
//! whose stamp is stale, or whose point is already in X_Δ, is dropped (Proposition 14's
//! deletions).
//!
//! Deviations and decisions:
//! - In `f64`, "x ∈ X_Δ" is decided up to `point_tolerance · L` ([`Tolerances::point`]) (L the longest side of the
//!   portalgon): the same surface point reached along two routes differs by rounding. In exact
//!   mode it is equality.
//! - In `f64`, two sites tie on a side where their squared distances differ by at most
//!   `4 · point_tolerance · L · (|a − y| + |s|)`: the cells are closed, as the paper's `Vor(x, X)`
//!   is, and a site tied at a single point (a Voronoi vertex on a side, common on meshes with
//!   right triangles) keeps its cell there instead of losing it to rounding, so it still reaches
//!   the neighbouring triangle. Cells may then overlap by that tolerance.
//! - Ties between equal dates are broken by (side, site) ids, so the run is deterministic.
//! - The events are counted ([`Wave::events`]: points added, the paper's iterations) along with
//!   the pops that were dropped ([`Wave::stale_events`]).

use std::cmp::{Ordering, Reverse};
use std::collections::{BinaryHeap, HashMap};

use super::flat::FlatLists;
use crate::geometry::{Motion, Point, Scalar, Tolerances, dist2, dot, sub};
use crate::portalgon::{PolygonId, Portalgon, SideId};

/// Constellations up to this size are searched by a scan; larger ones through a hash grid.
const INDEXED: usize = 48;

/// One cell of a side's diagram: site `site` of the side's triangle is a nearest site for the
/// parameters `lo ..= hi` along the side.
#[derive(Clone, Debug, PartialEq)]
pub struct SideCell<S> {
    /// Index of the site in its triangle's constellation.
    pub site: u32,
    /// First parameter of the cell (`0` = start of the side).
    pub lo: S,
    /// Last parameter of the cell (`1` = end of the side).
    pub hi: S,
    stamp: u64,
}

impl<S> SideCell<S> {
    /// The cell of `site` over `lo ..= hi`, its event stamped `stamp`.
    fn new(site: u32, lo: S, hi: S, stamp: u64) -> Self {
        Self {
            site,
            lo,
            hi,
            stamp,
        }
    }
}

/// The wave's result: the constellations X_Δ and the side diagrams (Lemma 41's lists at the end).
#[derive(Clone, Debug)]
pub struct Wave<S: Scalar> {
    /// Per polygon id (triangle): the constellation, in the triangle's frame ([`Self::points`]).
    points: FlatLists<Point<S>>,
    /// Per polygon id: the vertex class of each point's source ([`Self::sources`]).
    sources: FlatLists<u32>,
    /// Per side id: the cells meeting the side, in order along it ([`Self::cells`]).
    cells: FlatLists<SideCell<S>>,
    /// Per side id: the gluing isometry λ from its triangle's frame to the frame of its mate's
    /// triangle.
    pub to_mate: Vec<Motion<S>>,
    /// Points added to the constellations after the initialisation (the iterations of the wave).
    pub events: u64,
    /// Events popped and dropped (stale, or their point already present).
    pub stale_events: u64,
    point_tolerance: f64,
    scale: f64,
    /// Per side id: its length as a double ([`Portalgon::side_length`], computed once).
    pub(crate) side_length: Vec<f64>,
    index: HashMap<(u32, i64, i64), Vec<u32>>,
    /// Per stamp: whether a cell still carries it.
    alive: Vec<bool>,
    scratch: Scratch<S>,
}

/// Buffers of [`Wave::update_side`], reused from one side update to the next so that an update
/// allocates nothing.
#[derive(Clone, Debug)]
struct Scratch<S> {
    before: Vec<(SideCell<S>, bool)>,
    after: Vec<(SideCell<S>, bool)>,
    run: Vec<SideCell<S>>,
    changed: Vec<usize>,
}

impl<S> Default for Scratch<S> {
    fn default() -> Self {
        Self {
            before: Vec::new(),
            after: Vec::new(),
            run: Vec::new(),
            changed: Vec::new(),
        }
    }
}

/// Why the wave cannot run.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum WaveError {
    /// The portalgon is not a closed triangular portalgon with dense ids.
    #[error("the wave needs a closed triangular portalgon with dense ids: {0}")]
    Input(String),
    /// The number of events exceeded the budget (an `f64` run that does not settle).
    #[error("the wave exceeded its budget of {0} events")]
    Budget(u64),
    /// The work (the sizes of the constellations the events land in, summed) exceeded
    /// [`MAX_WAVE_WORK`]: the wave's time grows with it, as x² on Dubois' T_x.
    #[error(
        "the wave exceeded its work budget of {0} (the sizes of the constellations its events \
         land in, summed; about x² on the flat torus T_x): on a flat needle, --method dubois \
         (Theorem 1) finishes in time polynomial in the input's size"
    )]
    Work(u64),
}

/// The most work the wave does: the sizes of the constellations its events land in, summed (a
/// mesh near Delaunay needs a few per triangle; T_x about x², so x up to about 30,000; about
/// 20 s in a release build on one core at the limit).
pub const MAX_WAVE_WORK: u64 = 1_000_000_000;

#[derive(Clone, Debug)]
struct Event<S> {
    date2: S,
    side: u32,
    site: u32,
    stamp: u64,
}

impl<S: Scalar> PartialEq for Event<S> {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl<S: Scalar> Eq for Event<S> {}
impl<S: Scalar> PartialOrd for Event<S> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl<S: Scalar> Ord for Event<S> {
    fn cmp(&self, other: &Self) -> Ordering {
        self.date2
            .partial_cmp(&other.date2)
            .unwrap_or(Ordering::Equal)
            .then((self.side, self.site, self.stamp).cmp(&(other.side, other.site, other.stamp)))
    }
}

/// Options of [`run_wave`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct WaveOptions {
    /// Give up after this many events (points added); `None`: `64 n + 4·10⁶` for `n` triangles
    /// (T_x needs about `2x`; a mesh near Delaunay about one per triangle).
    pub max_events: Option<u64>,
    /// Give up once the work exceeds this; `None`: [`MAX_WAVE_WORK`].
    pub max_work: Option<u64>,
}

/// Checks that `p` is a closed triangular portalgon with dense ids.
pub(crate) fn check_input<S: Scalar>(p: &Portalgon<S>) -> Result<(), WaveError> {
    if p.polygon_slots() != p.polygon_count() || p.side_slots() != p.side_count() {
        return Err(WaveError::Input(
            "removed polygons or sides (compact it)".into(),
        ));
    }
    p.check_closed()
        .map_err(|e| WaveError::Input(e.to_string()))?;
    if let Some(q) = p.polygons().find(|&q| p.polygon_sides(q).len() != 3) {
        return Err(WaveError::Input(format!(
            "polygon {} has {} sides",
            q.idx(),
            p.polygon_sides(q).len()
        )));
    }
    Ok(())
}

/// Runs the wave from the vertex classes `sources` (V; see [`super::wave_sources`]) on a closed
/// triangular portalgon with dense ids; `class` gives the vertex class of each side's start. In
/// `f64`, points closer than [`Tolerances::point`] times the longest side are one.
///
/// # Errors
/// [`WaveError::Input`] for another portalgon, [`WaveError::Budget`].
pub fn run_wave<S: Scalar>(
    p: &Portalgon<S>,
    sources: &[u32],
    class: &[u32],
    options: &WaveOptions,
    tolerances: &Tolerances,
) -> Result<Wave<S>, WaveError> {
    check_input(p)?;
    let n = p.polygon_slots();
    // Dense ids (checked above): side `s` is entry `s` of `side_length`.
    let side_length: Vec<f64> = p.sides().map(|s| p.side_length(s)).collect();
    let scale = side_length.iter().copied().fold(0.0f64, f64::max);
    let to_mate = (0..p.side_slots() as u32)
        .map(|s| {
            let s = SideId(s);
            let m = p.mate(s).expect("closed");
            super::singular::gluing(p, s, m)
        })
        .collect();
    // Room for the three corners and one more point per triangle, four cells per side, in
    // three flat vectors (lists that outgrow their room move to the end).
    let origin = [S::zero(), S::zero()];
    let no_cell = SideCell::new(u32::MAX, S::zero(), S::zero(), 0);
    let mut wave = Wave {
        points: FlatLists::new(n, 4, origin),
        sources: FlatLists::new(n, 4, u32::MAX),
        cells: FlatLists::new(p.side_slots(), 4, no_cell),
        to_mate,
        events: 0,
        stale_events: 0,
        point_tolerance: tolerances.point,
        scale,
        side_length,
        index: HashMap::new(),
        alive: Vec::new(),
        scratch: Scratch::default(),
    };
    let mut in_v = vec![false; class.iter().map(|&c| c as usize + 1).max().unwrap_or(0)];
    for &c in sources {
        if let Some(x) = in_v.get_mut(c as usize) {
            *x = true;
        }
    }
    let max_events = options.max_events.unwrap_or(64 * n as u64 + 4_000_000);
    let mut heap = BinaryHeap::new();
    // Every corner in V first, then the side lists: no event is pushed for an image that is
    // already there.
    for q in p.polygons() {
        for &s in p.polygon_sides(q) {
            let c = class[s.idx()];
            if in_v[c as usize] {
                let x = p.start(s);
                if wave.find(q, &x).is_none() {
                    wave.add_point(q, x, c);
                }
            }
        }
    }
    for q in p.polygons() {
        for site in 0..wave.points.len(q.idx()) as u32 {
            wave.update_sides(p, q, site, &mut heap);
        }
    }
    let mut ticker = surftopo_mesh::stop::Ticker::default();
    let (mut work, max_work) = (0u64, options.max_work.unwrap_or(MAX_WAVE_WORK));
    while let Some(Reverse(event)) = heap.pop() {
        ticker.tick();
        let side = SideId(event.side);
        if !wave.alive[event.stamp as usize] {
            wave.stale_events += 1;
            continue;
        }
        let from = p.owner(side);
        let target = p.owner(p.mate(side).expect("closed"));
        let x = wave.to_mate[side.idx()].apply(&wave.points(from)[event.site as usize]);
        if wave.find(target, &x).is_some() {
            wave.stale_events += 1;
            continue;
        }
        if wave.events >= max_events {
            return Err(WaveError::Budget(max_events));
        }
        work += wave.points(target).len() as u64;
        if work > max_work {
            return Err(WaveError::Work(max_work));
        }
        wave.events += 1;
        let source = wave.sources(from)[event.site as usize];
        wave.insert(p, target, x, source, &mut heap);
    }
    Ok(wave)
}

/// `a + u·d`.
fn along<S: Scalar>(a: &Point<S>, d: &Point<S>, u: &S) -> Point<S> {
    [
        a[0].clone() + u.clone() * d[0].clone(),
        a[1].clone() + u.clone() * d[1].clone(),
    ]
}

impl<S: Scalar> Wave<S> {
    /// The constellation X_q of triangle `q`, in the triangle's frame.
    pub fn points(&self, q: PolygonId) -> &[Point<S>] {
        self.points.get(q.idx())
    }

    /// The vertex class (of [`Portalgon::vertex_classes`]) of the source of each point of X_q.
    pub fn sources(&self, q: PolygonId) -> &[u32] {
        self.sources.get(q.idx())
    }

    /// The cells meeting side `s`, in order along it.
    pub fn cells(&self, s: SideId) -> &[SideCell<S>] {
        self.cells.get(s.idx())
    }

    /// The largest constellation size, max |X_Δ|.
    pub fn max_constellation(&self) -> usize {
        self.points.lens().max().unwrap_or(0)
    }

    /// The total size of the constellations, Σ |X_Δ|.
    pub fn total_points(&self) -> usize {
        self.points.lens().sum()
    }

    fn eps(&self) -> f64 {
        self.point_tolerance * self.scale
    }

    fn bucket(&self, x: &Point<S>) -> (i64, i64) {
        let e = if S::EXACT {
            1e-9 * self.scale
        } else {
            self.eps()
        }
        .max(f64::MIN_POSITIVE);
        (
            (x[0].to_f64() / e).floor() as i64,
            (x[1].to_f64() / e).floor() as i64,
        )
    }

    /// Whether two points are the same point of a constellation (exactly, or within the tolerance
    /// in `f64`).
    pub fn same_point(&self, a: &Point<S>, b: &Point<S>) -> bool {
        S::same_point(a, b, || self.eps() * self.eps())
    }

    /// The index of point `x` in the constellation of triangle `q`, if present.
    pub fn find(&self, q: PolygonId, x: &Point<S>) -> Option<u32> {
        let points = self.points(q);
        if points.len() <= INDEXED {
            return (0..points.len() as u32).find(|&i| self.same_point(&points[i as usize], x));
        }
        let (bx, by) = self.bucket(x);
        for dx in -1..=1 {
            for dy in -1..=1 {
                if let Some(list) = self.index.get(&(q.0, bx + dx, by + dy)) {
                    for &i in list {
                        if self.same_point(&points[i as usize], x) {
                            return Some(i);
                        }
                    }
                }
            }
        }
        None
    }

    /// Adds `z` to X_q and updates the three side diagrams of `q`, pushing the events of the cells
    /// that changed or appeared (Proposition 14).
    fn insert(
        &mut self,
        p: &Portalgon<S>,
        q: PolygonId,
        z: Point<S>,
        source: u32,
        heap: &mut BinaryHeap<Reverse<Event<S>>>,
    ) {
        let site = self.add_point(q, z, source);
        self.update_sides(p, q, site, heap);
    }

    /// Adds `z` to X_q (and to the grid of a large constellation); returns its index.
    fn add_point(&mut self, q: PolygonId, z: Point<S>, source: u32) -> u32 {
        let site = self.points.len(q.idx()) as u32;
        self.points.push(q.idx(), z);
        self.sources.push(q.idx(), source);
        // Large constellations are found through a grid of buckets, small ones by a scan.
        let count = self.points.len(q.idx());
        let newly_indexed = if count == INDEXED + 1 {
            0..count
        } else {
            count - 1..count
        };
        if count > INDEXED {
            for i in newly_indexed {
                let key = self.bucket(&self.points(q)[i]);
                self.index
                    .entry((q.0, key.0, key.1))
                    .or_default()
                    .push(i as u32);
            }
        }
        site
    }

    /// Inserts site `site` of X_q into the three side lists of `q`, pushing the events of the
    /// cells that changed or appeared (Proposition 14).
    fn update_sides(
        &mut self,
        p: &Portalgon<S>,
        q: PolygonId,
        site: u32,
        heap: &mut BinaryHeap<Reverse<Event<S>>>,
    ) {
        for &s in p.polygon_sides(q) {
            let changed = self.insert_on_side(p, s, site);
            let target = p.owner(p.mate(s).expect("closed"));
            for &k in &changed {
                let cell = &self.cells(s)[k];
                let y = &self.points(q)[cell.site as usize];
                // Points are never removed: an image already in the target's constellation can
                // never be a candidate event again (Proposition 14's deletions, done early).
                if self.find(target, &self.to_mate[s.idx()].apply(y)).is_some() {
                    continue;
                }
                let date2 = date2(p.start_ref(s), p.end_ref(s), y, &cell.lo, &cell.hi);
                heap.push(Reverse(Event {
                    date2,
                    side: s.0,
                    site: cell.site,
                    stamp: cell.stamp,
                }));
            }
            self.scratch.changed = changed;
        }
    }

    /// Lemma 41's update of side `s`'s diagram for the new site `site` of its triangle; returns
    /// the positions (after the update) of the cells whose interval changed or appeared.
    fn insert_on_side(&mut self, p: &Portalgon<S>, s: SideId, site: u32) -> Vec<usize> {
        let mut alive = std::mem::take(&mut self.alive);
        let changed = self.update_side(p, s, site, &mut alive);
        self.alive = alive;
        changed
    }

    /// The body of [`Self::insert_on_side`] (Lemma 41): the new site's interval on the side is
    /// found from the least point of the convex function h (below), the run of cells it reaches
    /// is split cell by cell ([`split_cell`]), and the run is replaced by the kept parts before
    /// it, the new site's cell, and the kept parts after it.
    fn update_side(
        &mut self,
        p: &Portalgon<S>,
        s: SideId,
        site: u32,
        alive: &mut Vec<bool>,
    ) -> Vec<usize> {
        let q = p.owner(s);
        let (a, b) = (p.start_ref(s), p.end_ref(s));
        let d = sub(b, a);
        let pts = self.points.get(q.idx());
        let z = &pts[site as usize];
        let cells = self.cells.get(s.idx());
        let mut changed = std::mem::take(&mut self.scratch.changed);
        changed.clear();
        let fresh = |alive: &mut Vec<bool>| {
            alive.push(true);
            alive.len() as u64 - 1
        };
        if cells.is_empty() {
            let stamp = fresh(alive);
            self.cells
                .push(s.idx(), SideCell::new(site, S::zero(), S::one(), stamp));
            changed.push(0);
            return changed;
        }
        let az = dist2(a, z);
        // h_j(u) = |p(u) − z|² − |p(u) − y_j|² = c_j + 2u·e_j: negative where z is closer.
        let coeffs = |j: u32| {
            let y = &pts[j as usize];
            let c = az.clone() - dist2(a, y);
            let e = dot(&d, &sub(y, z));
            (c, e)
        };
        // Ties: exact in exact mode; in f64 a difference of squared distances within
        // `4 eps (|a − y| + |d|)` (distances within about 2 eps) counts as a tie, so that a site
        // tied at a point keeps (or gets) its closed cell there despite rounding.
        let side_len = self.side_length[s.idx()];
        let eps = self.eps();
        let tie = |j: u32| -> S {
            S::tie(|| 4.0 * eps * (dist2(a, &pts[j as usize]).to_f64().sqrt() + side_len))
        };
        // The least point of the convex function: first cell with a non-negative slope.
        let first = cells.partition_point(|cell| coeffs(cell.site).1.sign() == Ordering::Less);
        let (u_min, j_min) = if first < cells.len() {
            (cells[first].lo.clone(), cells[first].site)
        } else {
            (S::one(), cells[cells.len() - 1].site)
        };
        let (c0, e0) = coeffs(j_min);
        if sgn(&h(&c0, &e0, &u_min), &tie(j_min)) == Ordering::Greater {
            return changed;
        }
        let reaches = |cell: &SideCell<S>| {
            let (c, e) = coeffs(cell.site);
            let t = tie(cell.site);
            sgn(&h(&c, &e, &cell.lo), &t) != Ordering::Greater
                || sgn(&h(&c, &e, &cell.hi), &t) != Ordering::Greater
        };
        let (mut l, mut r) = (first.min(cells.len() - 1), first.min(cells.len() - 1));
        if !reaches(&cells[l]) {
            // u_min is the left end of cell `first`, shared with cell `first − 1`.
            l = first - 1;
            r = first - 1;
        }
        while l > 0 && reaches(&cells[l - 1]) {
            l -= 1;
        }
        r += 1;
        while r < cells.len() && reaches(&cells[r]) {
            r += 1;
        }
        let mut before = std::mem::take(&mut self.scratch.before);
        let mut after = std::mem::take(&mut self.scratch.after);
        let mut run = std::mem::take(&mut self.scratch.run);
        before.clear();
        after.clear();
        run.clear();
        let (mut z_lo, mut z_hi): (Option<S>, Option<S>) = (None, None);
        let mut widen = |lo: S, hi: S| {
            if z_lo.as_ref().is_none_or(|x| lo < *x) {
                z_lo = Some(lo);
            }
            if z_hi.as_ref().is_none_or(|x| hi > *x) {
                z_hi = Some(hi);
            }
        };
        for cell in &cells[l..r] {
            // Every cell of the run is replaced, kept as it is, or removed.
            alive[cell.stamp as usize] = false;
            let (c, e) = coeffs(cell.site);
            let t = tie(cell.site);
            let (lo, hi) = (&cell.lo, &cell.hi);
            let (take, keep) = split_cell(&c, &e, &t, lo, hi);
            if let Some((take_lo, take_hi)) = take {
                widen(take_lo, take_hi);
            }
            if let Some((klo, khi)) = keep {
                let same = klo == *lo && khi == *hi;
                let kept = SideCell::new(cell.site, klo, khi, cell.stamp);
                if e.sign() == Ordering::Greater {
                    after.push((kept, same));
                } else {
                    before.push((kept, same));
                }
            }
        }
        let (z_lo, z_hi) = (
            z_lo.expect("z reaches the side"),
            z_hi.expect("z reaches the side"),
        );

        // A kept cell keeps its stamp (its event stays valid); a shrunk one gets a fresh stamp.
        let mut push = |run: &mut Vec<SideCell<S>>, mut cell: SideCell<S>, same: bool| {
            if same {
                alive[cell.stamp as usize] = true;
            } else {
                cell.stamp = fresh(alive);
                changed.push(l + run.len());
            }
            run.push(cell);
        };
        for (cell, same) in before.drain(..) {
            push(&mut run, cell, same);
        }
        let new_cell = SideCell::new(site, z_lo, z_hi, 0);
        push(&mut run, new_cell, false);
        for (cell, same) in after.drain(..) {
            push(&mut run, cell, same);
        }
        self.cells.splice(s.idx(), l, r, &mut run);
        self.scratch = Scratch {
            before,
            after,
            run,
            changed: Vec::new(),
        };
        changed
    }
}

/// `h(u) = c + 2u·e`: on a side, the squared distance to the new site minus the squared distance
/// to a cell's site (negative where the new site is closer; Lemma 41).
fn h<S: Scalar>(c: &S, e: &S, u: &S) -> S {
    c.clone() + (e.clone() + e.clone()) * u.clone()
}

/// The sign of `x` with `-tol ..= tol` counting as zero (`tol` is zero in exact arithmetic).
fn sgn<S: Scalar>(x: &S, tol: &S) -> Ordering {
    if *x > *tol {
        Ordering::Greater
    } else if *x < -tol.clone() {
        Ordering::Less
    } else {
        Ordering::Equal
    }
}

/// One cell `lo ..= hi` of the run the new site reaches (Lemma 41): within it h (of [`h`], with
/// coefficients `c`, `e`) is linear, the new site takes `{h ≤ 0}` and the cell's site keeps
/// `{h ≥ 0}` (each with the tie tolerance `t` of f64, zero when exact). Returns the part taken
/// and the part kept, each `None` when empty.
#[allow(clippy::type_complexity)]
fn split_cell<S: Scalar>(c: &S, e: &S, t: &S, lo: &S, hi: &S) -> (Option<(S, S)>, Option<(S, S)>) {
    let clamp = |u: S| {
        if u < *lo {
            lo.clone()
        } else if u > *hi {
            hi.clone()
        } else {
            u
        }
    };
    match e.sign() {
        Ordering::Equal => match sgn(c, t) {
            Ordering::Less => (Some((lo.clone(), hi.clone())), None),
            // A tie everywhere (z mirrors the site across the side's line).
            _ => (
                Some((lo.clone(), hi.clone())),
                Some((lo.clone(), hi.clone())),
            ),
        },
        sign => {
            let two_e = e.clone() + e.clone();
            let take_end = clamp((t.clone() - c.clone()) / two_e.clone());
            let keep_end = clamp((-t.clone() - c.clone()) / two_e);
            let (h_lo, h_hi) = (sgn(&h(c, e, lo), t), sgn(&h(c, e, hi), t));
            if sign == Ordering::Greater {
                // h increasing: z on the left part.
                let take = (h_lo != Ordering::Greater).then(|| (lo.clone(), take_end));
                (
                    take,
                    (h_hi != Ordering::Less).then(|| (keep_end, hi.clone())),
                )
            } else {
                let take = (h_hi != Ordering::Greater).then(|| (take_end, hi.clone()));
                (
                    take,
                    (h_lo != Ordering::Less).then(|| (lo.clone(), keep_end)),
                )
            }
        }
    }
}

/// The squared distance from `y` to the part `lo ..= hi` of the segment `a b` (a date squared).
pub(crate) fn date2<S: Scalar>(a: &Point<S>, b: &Point<S>, y: &Point<S>, lo: &S, hi: &S) -> S {
    let d = sub(b, a);
    let u = dot(&sub(y, a), &d) / dot(&d, &d);
    let u = if u < *lo {
        lo.clone()
    } else if u > *hi {
        hi.clone()
    } else {
        u
    };
    dist2(&along(a, &d, &u), y)
}
