//! The Delaunay tessellation from the constellations: the dual of the Voronoi diagram (Dubois,
//! Appendix C, Lemmas 29–31; Appendix D.1, Proposition 12), by the simpler route of docs/dubois.md §3.7.
//!
//! At the end of the wave, the Voronoi diagram of X_Δ restricted to Δ is the pre-image of the
//! Voronoi diagram of V (Proposition 13, Lemma 34). A Voronoi vertex `v` in (closed) Δ is a point
//! with at least three nearest points in X_Δ, and by Lemma 35 those nearest points are φ⁻¹(V) for
//! the maxi-disk of `v`: the Delaunay polygon dual to `v` is their convex hull (Lemma 29), already
//! laid out in Δ's frame, its corners in counter-clockwise order around `v`.
//!
//! Finding the vertices in Δ: every component of the planar Voronoi diagram restricted to Δ
//! reaches Δ's boundary, where it shows in the side diagrams of the wave (Lemma 41's lists) as a
//! boundary between two cells, or a point where three or more cells meet. From each boundary point
//! the bisector is followed into Δ; it ends inside Δ at a vertex unless its exit point is again a
//! boundary between the same two cells (then the segment between them is an edge: the
//! intersection of two convex cells), which a bisection in the exit side's list decides in
//! O(log k). Otherwise the first vertex on the bisector is found by scanning the sites (O(k)),
//! and the vertices found are explored along their edges.
//!
//! Matching the polygons' sides: the side from corner `a` to corner `b` of the polygon of `v` is
//! dual to the Voronoi edge leaving `v` along the bisector of `a b`, away from the polygon. That
//! edge is followed through the triangles (carrying `a`, `b` and the direction by the gluing maps;
//! through a flat vertex of T by walking around its star) until the next Voronoi vertex, whose
//! polygon has the side from `b` to `a`. The edges followed are the Voronoi diagram's edges,
//! recorded as polylines in the triangles of T ([`VoronoiDiagram`]).
//!
//! Deviations from the paper, and decisions:
//! - Proposition 11 refines T into a portalgon T′ having the Voronoi diagram as a subgraph; here
//!   the diagram is output as vertices and polylines inside the triangles of T instead, and T′ is
//!   not built (nothing downstream needs it).
//! - Proposition 12 lays each polygon out by unfolding a spanning tree of its Voronoi face
//!   (Lemmas 32–33); here the polygon is read off the constellation of a triangle holding its
//!   Voronoi vertex (docs/dubois.md §3.7), which Lemma 35 makes equivalent. The tests compare the result
//!   with the flip route's tessellation.
//! - A Voronoi vertex on a side of T belongs to the triangle of the smaller side id of the matched
//!   pair; one at a corner of T (a flat vertex of T not in V) to the corner of the smallest side
//!   id leaving it; every other vertex to the triangle containing it.
//! - In `f64` nearest points, vertices and parameters are compared with a tolerance relative to
//!   the longest side (`point_tolerance`): near-co-circular points are merged into one polygon, as
//!   the flip route merges near-co-circular triangles. In exact mode every comparison is exact.
//! - In `f64` a followed edge continues, in each triangle it enters, from that triangle's own
//!   copies of its two sites (found within the wave's tolerance) and from the point of their
//!   bisector nearest to where it entered: on a portalgon that closes up only to a tolerance
//!   (Dubois' `T′`) the copies carried by the gluings drift off the constellation's.
//! - The traced tessellation must have V's vertices (one vertex class per source) and the
//!   surface's Euler characteristic ([`DualError::Topology`]): in `f64`, edges followed to the
//!   wrong vertex of a near-co-circular cluster can close up into another surface that no
//!   local check sees.
//! - In `f64`, when the dual fails, `wave_and_dual` builds it again with clusters merged
//!   (`merge_clusters`): Voronoi vertices are told apart by their nearest sites, not by their
//!   positions (two that share three sites are one, however far apart the rounding put them;
//!   two with different sites are two, however close: near-co-circular sites put Voronoi
//!   vertices a rounding apart, each seeing some of the sites), and a vertex found again adds
//!   to the recorded one the nearest sites it lacks that lie within the tolerance of its
//!   circle, so a cluster is one polygon. Not the first attempt: the pooled polygon can be off
//!   its circle by a few tolerances, more than the flip route's co-circularity test allows.

use std::cmp::Ordering;

use super::wave::{SideCell, Wave};
use crate::error::PortalgonError;
use crate::geometry::{Motion, Point, Scalar, Tolerances, add, cross, dist2, dot, scale, sub};
use crate::portalgon::{PolygonId, Portalgon, SideId};

/// Where a Voronoi vertex lies in its triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Place {
    Interior,
    /// On the relative interior of a side.
    Side(SideId),
    /// At the corner where this side starts.
    Corner(SideId),
}

/// A Voronoi vertex found in a triangle: its position, its nearest sites counter-clockwise around
/// it, where it lies, and the polygon it gives when the triangle owns it.
#[derive(Clone, Debug)]
struct Instance<S> {
    at: Point<S>,
    sites: Vec<u32>,
    place: Place,
    polygon: Option<u32>,
}

/// A piece of a Voronoi edge: a segment in the frame of the triangle of T that holds it.
pub type Segment<S> = (PolygonId, Point<S>, Point<S>);

/// Where a followed edge ends: the triangle, the instance there, the polygon side, the segments.
type Followed<S> = (PolygonId, usize, usize, Vec<Segment<S>>);

/// The Voronoi diagram of (S(T), V) as found by the dual: its vertices (one per polygon of the
/// tessellation, in the frame of the triangle owning it) and its edges as polylines through the
/// triangles of T.
#[derive(Clone, Debug)]
pub struct VoronoiDiagram<S> {
    /// Per polygon of the tessellation: the triangle holding its Voronoi vertex and the vertex.
    pub vertices: Vec<(PolygonId, Point<S>)>,
    /// Per matched pair of tessellation sides: the segments of the dual Voronoi edge, each in the
    /// frame of the triangle it crosses.
    pub edges: Vec<Vec<Segment<S>>>,
}

/// Why the dual could not be built (an inconsistency of the `f64` geometry).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum DualError {
    /// A Voronoi edge could not be followed to its other end.
    #[error("a Voronoi edge leaving polygon {polygon} (side {side}) could not be followed: {why}")]
    Trace {
        /// The polygon.
        polygon: usize,
        /// Its side.
        side: usize,
        /// What went wrong.
        why: String,
    },
    /// The traced polygons and gluings close up, but not into a tessellation of the surface
    /// with V as its vertex set (an `f64` failure that no local check saw).
    #[error(
        "the traced tessellation has {vertices} vertices and Euler characteristic {euler}, where \
         V has {sources} vertices and the surface Euler characteristic {expected}"
    )]
    Topology {
        /// Vertices of the traced tessellation.
        vertices: usize,
        /// Vertices in V.
        sources: usize,
        /// Its Euler characteristic.
        euler: i64,
        /// The surface's.
        expected: i64,
    },
    /// A polygon or a gluing of the tessellation was refused.
    #[error(transparent)]
    Portalgon(#[from] PortalgonError),
}

struct Dual<'a, S: Scalar> {
    p: &'a Portalgon<S>,
    wave: &'a Wave<S>,
    eps: f64,
    /// Whether Voronoi vertices taken for the same one pool their sites ([`Self::absorb`]).
    merge_clusters: bool,
    instances: Vec<Vec<Instance<S>>>,
    /// The most triangles a followed edge may cross (a guard against an `f64` loop).
    step_budget: usize,
    scratch: Scratch<S>,
}

/// Buffers of [`Dual::find_vertices`], reused from one triangle to the next.
struct Scratch<S> {
    /// Instances to explore.
    todo: Vec<usize>,
    /// Parameters of the boundary points of a side.
    params: Vec<S>,
    /// The sites at a boundary point.
    sites: Vec<u32>,
    /// The sites around the instance being explored.
    around: Vec<u32>,
}

impl<S> Default for Scratch<S> {
    fn default() -> Self {
        Self {
            todo: Vec::new(),
            params: Vec::new(),
            sites: Vec::new(),
            around: Vec::new(),
        }
    }
}

/// The result of [`build_dual`].
pub(crate) struct DualOutput<S: Scalar> {
    pub portalgon: Portalgon<S>,
    pub diagram: VoronoiDiagram<S>,
}

fn rot_left<S: Scalar>(v: &Point<S>) -> Point<S> {
    [-v[1].clone(), v[0].clone()]
}
fn rot_right<S: Scalar>(v: &Point<S>) -> Point<S> {
    [v[1].clone(), -v[0].clone()]
}

/// The point of the bisector of `a` and `b` reached from `x` along `b − a`.
fn onto_bisector<S: Scalar>(x: &Point<S>, a: &Point<S>, b: &Point<S>) -> Point<S> {
    let w = sub(b, a);
    let ww = dot(&w, &w);
    if ww.is_zero() {
        return x.clone();
    }
    let excess = dist2(x, a) - dist2(x, b);
    sub(x, &scale(&(excess / (ww.clone() + ww)), &w))
}

/// Builds the Delaunay tessellation (and the Voronoi diagram) from a finished wave; `labels` has
/// an entry per vertex class `c` of `p`: the output vertex label of `c` (`u32::MAX` off V).
pub(crate) fn build_dual<S: Scalar>(
    p: &Portalgon<S>,
    wave: &Wave<S>,
    labels: &[u32],
    point_tolerance: f64,
    merge_clusters: bool,
    sources: usize,
) -> Result<DualOutput<S>, DualError> {
    let scale = wave.side_length.iter().copied().fold(0.0f64, f64::max);
    let mut dual = Dual {
        p,
        wave,
        eps: point_tolerance * scale,
        merge_clusters,
        instances: vec![Vec::new(); p.polygon_slots()],
        step_budget: 4 * (p.polygon_slots() + wave.total_points()) + 16,
        scratch: Scratch::default(),
    };
    for q in p.polygons() {
        dual.find_vertices(q);
    }
    // Ownership and polygons.
    let mut out = Portalgon::empty();
    let mut diagram = VoronoiDiagram {
        vertices: Vec::new(),
        edges: Vec::new(),
    };
    let mut owner_of: Vec<(PolygonId, usize)> = Vec::new();
    let (mut corners, mut polygon_labels): (Vec<Point<S>>, Vec<u32>) = (Vec::new(), Vec::new());
    for q in p.polygons() {
        for k in 0..dual.instances[q.idx()].len() {
            let inst = &dual.instances[q.idx()][k];
            let owned = match inst.place {
                Place::Interior => true,
                Place::Side(s) => s < p.mate(s).expect("closed"),
                Place::Corner(s) => p.star(s).is_some_and(|c| c.iter().min() == Some(&s)),
            };
            if !owned {
                continue;
            }
            corners.clear();
            corners.extend(
                inst.sites
                    .iter()
                    .map(|&i| wave.points(q)[i as usize].clone()),
            );
            polygon_labels.clear();
            polygon_labels.extend(
                inst.sites
                    .iter()
                    .map(|&i| labels[wave.sources(q)[i as usize] as usize]),
            );
            let id = out.add_polygon(&corners)?;
            out.set_vertex_labels(id, &polygon_labels)?;
            diagram.vertices.push((q, inst.at.clone()));
            owner_of.push((q, k));
            dual.instances[q.idx()][k].polygon = Some(id.0);
        }
    }
    // Matching, by following each Voronoi edge.
    for (polygon, &(q, k)) in owner_of.iter().enumerate() {
        let m = dual.instances[q.idx()][k].sites.len();
        for side in 0..m {
            let s = out.side(PolygonId(polygon as u32), side);
            if out.mate(s).is_some() {
                continue;
            }
            let fail = |why: String| DualError::Trace { polygon, side, why };
            let (q2, k2, side2, segments) = dual.follow(q, k, side).map_err(fail)?;
            let polygon2 = dual.instances[q2.idx()][k2]
                .polygon
                .ok_or_else(|| fail("the edge ends at a vertex nobody owns".into()))?;
            let t = out.side(PolygonId(polygon2), side2);
            if t == s || out.mate(t).is_some() {
                return Err(fail(format!(
                    "the edge ends at side {side2} of polygon {polygon2}, already matched"
                )));
            }
            out.glue(s, t, S::slack(|| 1e3 * Tolerances::DEFAULT.length))?;
            diagram.edges.push(segments);
        }
    }
    let vertices = out.vertex_classes().1;
    // `labels` has one entry per vertex class of `p`.
    let (euler, expected) = (euler(&out, vertices), euler(p, labels.len()));
    if vertices != sources || euler != expected {
        return Err(DualError::Topology {
            vertices,
            sources,
            euler,
            expected,
        });
    }
    Ok(DualOutput {
        portalgon: out,
        diagram,
    })
}

/// `V − E + F` of a closed portalgon with `vertices` vertex classes.
fn euler<S: Scalar>(p: &Portalgon<S>, vertices: usize) -> i64 {
    vertices as i64 - (p.side_count() / 2) as i64 + p.polygon_count() as i64
}

/// Where a ray leaves a triangle.
enum Exit<S> {
    /// Through the relative interior of a side, at this parameter.
    Side(SideId, S),
    /// Through the corner at the start of this side.
    Corner(SideId),
    /// It does not leave (degenerate direction).
    None,
}

impl<S: Scalar> Dual<'_, S> {
    fn pts(&self, q: PolygonId) -> &[Point<S>] {
        self.wave.points(q)
    }

    fn zero_or_less(&self, x: &S, scale2: f64) -> bool {
        S::at_most_zero(x, || self.eps * scale2.sqrt())
    }

    /// The sites nearest to `x` among X_q, and their squared distance.
    fn nearest(&self, q: PolygonId, x: &Point<S>) -> Vec<u32> {
        let mut out = Vec::new();
        self.nearest_into(q, x, &mut out);
        out
    }

    /// [`Self::nearest`] into `out` (cleared first): the dual asks this at every boundary point
    /// and vertex, so the hot paths reuse one buffer instead of allocating a list each time.
    fn nearest_into(&self, q: PolygonId, x: &Point<S>, out: &mut Vec<u32>) {
        out.clear();
        let (best, tol) = self.nearest_distance(q, x);
        let pts = self.pts(q);
        out.extend(
            (0..pts.len() as u32)
                .filter(|&i| S::same_value(&dist2(x, &pts[i as usize]), &best, || tol)),
        );
    }

    /// The least squared distance from `x` to X_q, and the tolerance within which another
    /// squared distance is the same ([`Self::nearest`]).
    fn nearest_distance(&self, q: PolygonId, x: &Point<S>) -> (S, f64) {
        // Two passes instead of a buffer of distances: constellations are small.
        let best = self
            .pts(q)
            .iter()
            .map(|y| dist2(x, y))
            .fold(None::<S>, |m, v| match m {
                Some(m) if m <= v => Some(m),
                _ => Some(v),
            })
            .unwrap_or_else(S::zero);
        let tol = 4.0 * self.eps * best.to_f64().sqrt().max(self.eps);
        (best, tol)
    }

    /// Sorts sites counter-clockwise around `v` (exact angular order).
    fn sort_around(&self, q: PolygonId, v: &Point<S>, sites: &mut [u32]) {
        let pts = self.pts(q);
        let half = |w: &Point<S>| {
            // 0 for angles in [0, π), 1 for [π, 2π).
            let up = w[1].sign();
            u8::from(
                !(up == Ordering::Greater
                    || (up == Ordering::Equal && w[0].sign() != Ordering::Less)),
            )
        };
        sites.sort_by(|&i, &j| {
            let (a, b) = (sub(&pts[i as usize], v), sub(&pts[j as usize], v));
            half(&a).cmp(&half(&b)).then_with(|| cross(&b, &a).sign())
        });
    }

    /// Where the ray `x + t·dir` (t > 0) leaves triangle `q`, and at which `t`.
    fn exit(&self, q: PolygonId, x: &Point<S>, dir: &Point<S>) -> (Exit<S>, S) {
        let p = self.p;
        let mut best: Option<(S, SideId)> = None;
        for &s in p.polygon_sides(q) {
            let (a, b) = (p.start_ref(s), p.end_ref(s));
            let e = sub(b, a);
            let den = cross(&e, dir);
            if den.sign() != Ordering::Less {
                continue;
            }
            let t = cross(&e, &sub(a, x)) / den;
            if best.as_ref().is_none_or(|(bt, _)| t < *bt) {
                best = Some((t, s));
            }
        }
        let Some((t, s)) = best else {
            return (Exit::None, S::zero());
        };
        let (a, b) = (p.start_ref(s), p.end_ref(s));
        let e = sub(b, a);
        let point = add(x, &scale(&t, dir));
        let u = dot(&sub(&point, a), &e) / dot(&e, &e);
        let tol = self.eps / self.wave.side_length[s.idx()].max(f64::MIN_POSITIVE);
        if S::same_value(&u, &S::zero(), || tol) {
            (Exit::Corner(s), t)
        } else if S::same_value(&u, &S::one(), || tol) {
            (Exit::Corner(p.next_side(s)), t)
        } else {
            (Exit::Side(s, u), t)
        }
    }

    /// The sites whose cells on side `s` contain parameter `u`, sorted, into `out` (exact mode:
    /// from the side's list, O(log k); `f64`: the nearest sites of the point, by a scan with the
    /// tolerance, so that all the `f64` decisions agree with [`Self::nearest`]).
    fn sites_at_into(&self, s: SideId, u: &S, out: &mut Vec<u32>) {
        if !S::EXACT {
            let x = self.point_on(s, u);
            self.nearest_into(self.p.owner(s), &x, out);
            out.sort_unstable();
            return;
        }
        out.clear();
        out.extend(self.cells_at(s, u).map(|c| c.site));
        out.sort_unstable();
        out.dedup();
    }

    /// Whether the sites at parameter `u` of side `s` ([`Self::sites_at_into`]) are two, `i`
    /// and `j` among them, without listing them.
    fn sites_at_are(&self, s: SideId, u: &S, i: u32, j: u32) -> bool {
        let mut found = [u32::MAX; 2];
        let mut count = 0;
        let mut two_at_most = |k: u32| {
            if found[..count].contains(&k) {
                return true;
            }
            if count == 2 {
                return false;
            }
            found[count] = k;
            count += 1;
            true
        };
        let at_most_two = if S::EXACT {
            self.cells_at(s, u).all(|c| two_at_most(c.site))
        } else {
            let (q, x) = (self.p.owner(s), self.point_on(s, u));
            let (best, tol) = self.nearest_distance(q, &x);
            let pts = self.pts(q);
            (0..pts.len() as u32)
                .filter(|&k| S::same_value(&dist2(&x, &pts[k as usize]), &best, || tol))
                .all(two_at_most)
        };
        at_most_two && count == 2 && found.contains(&i) && found.contains(&j)
    }

    /// The point at parameter `u` of side `s`.
    fn point_on(&self, s: SideId, u: &S) -> Point<S> {
        let p = self.p;
        let d = sub(p.end_ref(s), p.start_ref(s));
        add(p.start_ref(s), &scale(u, &d))
    }

    /// Exact mode: the cells of side `s`'s list containing parameter `u`, in order.
    fn cells_at<'w>(&'w self, s: SideId, u: &'w S) -> impl Iterator<Item = &'w SideCell<S>> {
        let cells = self.wave.cells(s);
        let start = cells.partition_point(|c| *u > c.hi);
        cells[start..].iter().take_while(move |c| c.lo <= *u)
    }

    /// The first point `x + t·dir`, `0 < t ≤ t_max`, equidistant from site `i` and another site
    /// closer than `i` beyond it, in neither list of `skip`: the next Voronoi vertex on the
    /// edge of `i` (and its partner).
    fn first_vertex(
        &self,
        q: PolygonId,
        x: &Point<S>,
        dir: &Point<S>,
        i: u32,
        skip: [&[u32]; 2],
        t_max: &S,
    ) -> Option<Point<S>> {
        let pts = self.pts(q);
        let yi = &pts[i as usize];
        let xi = dist2(x, yi);
        let mut best: Option<S> = None;
        let dir2 = dot(dir, dir).to_f64();
        for (k, yk) in pts.iter().enumerate() {
            if k as u32 == i || skip.iter().any(|list| list.contains(&(k as u32))) {
                continue;
            }
            let den = dot(dir, &sub(yk, yi));
            if den.sign() != Ordering::Greater {
                continue;
            }
            let num = dist2(x, yk) - xi.clone();
            let t = num / (den.clone() + den);
            // t > 0 (the vertex at the start is not the next one).
            if self.zero_or_less(&t, dir2.recip()) {
                continue;
            }
            if best.as_ref().is_none_or(|b| t < *b) {
                best = Some(t);
            }
        }
        let t = best?;
        let slack = S::tie(|| self.eps / dir2.sqrt());
        (t <= t_max.clone() + slack).then(|| add(x, &scale(&t, dir)))
    }

    /// Where a point of triangle `q` lies: a corner, a side, or the interior.
    fn place(&self, q: PolygonId, v: &Point<S>) -> Place {
        let p = self.p;
        for &s in p.polygon_sides(q) {
            if self.same_point(p.start_ref(s), v) {
                return Place::Corner(s);
            }
        }
        for &s in p.polygon_sides(q) {
            let (a, b) = (p.start_ref(s), p.end_ref(s));
            let c = cross(&sub(b, a), &sub(v, a));
            if S::negligible(&c, || self.eps * self.wave.side_length[s.idx()]) {
                return Place::Side(s);
            }
        }
        Place::Interior
    }

    fn same_point(&self, a: &Point<S>, b: &Point<S>) -> bool {
        S::same_point(a, b, || 16.0 * self.eps * self.eps)
    }

    /// Records the vertex at `v` in triangle `q` unless known; returns its index and whether it
    /// is to be explored (new, or in `f64` known with sites added by [`Self::absorb`]).
    fn record(&mut self, q: PolygonId, v: Point<S>) -> Option<(usize, bool)> {
        if let Some(k) = self.instance_at(q, &v) {
            return Some((k, self.absorb(q, k, &v)));
        }
        let mut sites = self.nearest(q, &v);
        if sites.len() < 3 {
            // Not a vertex after all (an `f64` near-miss).
            return None;
        }
        self.sort_around(q, &v, &mut sites);
        let place = self.place(q, &v);
        self.instances[q.idx()].push(Instance {
            at: v,
            sites,
            place,
            polygon: None,
        });
        Some((self.instances[q.idx()].len() - 1, true))
    }

    /// When merging clusters (`f64`), adds to instance `k` of `q` the nearest sites of `v`, a
    /// point taken for the same vertex ([`Self::instance_at`]: three sites shared), that it
    /// lacks and that lie within the tolerance of its circle, kept counter-clockwise around the
    /// instance; returns whether any was added. Near-co-circular sites give Voronoi vertices a
    /// rounding apart, each with only some of the sites: they are one vertex of the merged
    /// (near-co-circular) polygon, as the flip route merges near-co-circular triangles; the
    /// Voronoi edges between them are not followed.
    fn absorb(&mut self, q: PolygonId, k: usize, v: &Point<S>) -> bool {
        if S::EXACT || !self.merge_clusters {
            return false;
        }
        let at = self.instances[q.idx()][k].at.clone();
        let mut sites = self.instances[q.idx()][k].sites.clone();
        let pts = self.pts(q);
        let radius = dist2(&at, &pts[sites[0] as usize]).to_f64().sqrt();
        let before = sites.len();
        for i in self.nearest(q, v) {
            let off = dist2(&at, &pts[i as usize]).to_f64().sqrt() - radius;
            if !sites.contains(&i) && off.abs() <= 4.0 * self.eps {
                sites.push(i);
            }
        }
        if sites.len() == before {
            return false;
        }
        self.sort_around(q, &at, &mut sites);
        self.instances[q.idx()][k].sites = sites;
        true
    }

    /// Whether the segment from a point on the edge of sites `i`, `j` to the exit is all on that
    /// edge (the exit is again a boundary of exactly those two cells).
    fn edge_runs_through(&self, exit: &Exit<S>, i: u32, j: u32) -> bool {
        match exit {
            Exit::Side(s, u) => self.sites_at_are(*s, u, i, j),
            _ => false,
        }
    }

    /// All Voronoi vertices in the closed triangle `q`.
    fn find_vertices(&mut self, q: PolygonId) {
        let p = self.p;
        // The buffers live in `self.scratch` between calls: nothing is allocated per triangle.
        let mut scratch = std::mem::take(&mut self.scratch);
        let Scratch {
            todo,
            params,
            sites,
            around,
        } = &mut scratch;
        todo.clear();
        for &s in p.polygon_sides(q) {
            let (a, b) = (p.start(s), p.end(s));
            let d = sub(&b, &a);
            let inward = rot_left(&d);
            // Boundary points: where consecutive cells meet (the bisector of their sites; in
            // exact mode that is where the cells end), and the start corner.
            let cells = self.wave.cells(s);
            let pts = self.pts(q);
            params.clear();
            params.push(S::zero());
            for w in cells.windows(2) {
                let (yi, yj) = (&pts[w[0].site as usize], &pts[w[1].site as usize]);
                let den = dot(&d, &sub(yj, yi));
                if den.is_zero() {
                    continue;
                }
                let u = (dist2(&a, yj) - dist2(&a, yi)) / (den.clone() + den);
                if u.sign() == Ordering::Greater && u < S::one() {
                    params.push(u);
                }
            }
            params.sort_by(|x, y| x.partial_cmp(y).unwrap_or(Ordering::Equal));
            params.dedup();
            for u in params.drain(..) {
                let x = add(&a, &scale(&u, &d));
                let corner = u.is_zero();
                if corner {
                    self.nearest_into(q, &x, sites);
                } else {
                    self.sites_at_into(s, &u, sites);
                }
                if sites.len() >= 3 {
                    if let Some((k, true)) = self.record(q, x) {
                        todo.push(k);
                    }
                    continue;
                }
                if sites.len() != 2 {
                    continue;
                }
                let pts = self.pts(q);
                let (i, j) = (sites[0], sites[1]);
                let mut dir = rot_left(&sub(&pts[j as usize], &pts[i as usize]));
                if corner {
                    // Into the corner's wedge, or not at all.
                    let prev = sub(p.start_ref(p.prev_side(s)), &a);
                    let inside = |w: &Point<S>| {
                        cross(&d, w).sign() == Ordering::Greater
                            && cross(w, &prev).sign() == Ordering::Greater
                    };
                    if !inside(&dir) {
                        dir = [-dir[0].clone(), -dir[1].clone()];
                        if !inside(&dir) {
                            continue;
                        }
                    }
                } else {
                    match dot(&dir, &inward).sign() {
                        Ordering::Less => dir = [-dir[0].clone(), -dir[1].clone()],
                        Ordering::Equal => continue,
                        Ordering::Greater => {}
                    }
                }
                let (exit, t_exit) = self.exit(q, &x, &dir);
                if self.edge_runs_through(&exit, i, j) {
                    continue;
                }
                if let Some(v) = self.first_vertex(q, &x, &dir, i, [&[j], &[]], &t_exit)
                    && let Some((k, true)) = self.record(q, v)
                {
                    todo.push(k);
                }
            }
        }
        // Explore from the vertices found along their edges.
        while let Some(k) = todo.pop() {
            let inst = &self.instances[q.idx()][k];
            let at = inst.at.clone();
            around.clear();
            around.extend_from_slice(&inst.sites);
            let m = around.len();
            for e in 0..m {
                let (a, b) = (around[e], around[(e + 1) % m]);
                let pts = self.pts(q);
                let dir = rot_right(&sub(&pts[b as usize], &pts[a as usize]));
                let (exit, t_exit) = self.exit(q, &at, &dir);
                if matches!(exit, Exit::None) || self.edge_runs_through(&exit, a, b) {
                    continue;
                }
                if let Some(v) = self.first_vertex(q, &at, &dir, a, [around, &[]], &t_exit)
                    && let Some((k2, true)) = self.record(q, v)
                {
                    todo.push(k2);
                }
            }
        }
        self.scratch = scratch;
    }

    /// The instance of the vertex at `v` in triangle `q`: at the same point, or (in `f64`, for
    /// near-co-circular sites) one with the same nearest sites as `v`. When merging clusters
    /// (`f64`), one sharing three of the nearest sites of `v` (if it has three), whatever
    /// the distance.
    fn instance_at(&self, q: PolygonId, v: &Point<S>) -> Option<usize> {
        let list = &self.instances[q.idx()];
        if !S::EXACT && self.merge_clusters {
            let sites = self.nearest(q, v);
            if sites.len() >= 3 {
                // Three sites fix a circle: vertices sharing three are one (pooled) vertex,
                // however close two others are.
                return list
                    .iter()
                    .position(|inst| sites.iter().filter(|i| inst.sites.contains(i)).count() >= 3);
            }
        }
        if let Some(k) = list.iter().position(|inst| self.same_point(&inst.at, v)) {
            return Some(k);
        }
        if S::EXACT {
            return None;
        }
        let sites = self.nearest(q, v);
        if sites.len() < 3 {
            return None;
        }
        // The same set of sites (each list has distinct sites).
        list.iter().position(|inst| {
            inst.sites.len() == sites.len() && inst.sites.iter().all(|i| sites.contains(i))
        })
    }

    /// Carries points around the corner at the start of `s` (counter-clockwise, one corner) into
    /// the next corner's triangle; returns the next corner's side.
    fn turn_corner(&self, s: SideId, points: &mut [Point<S>], dirs: &mut [Point<S>]) -> SideId {
        let into = self.p.prev_side(s);
        let motion: &Motion<S> = &self.wave.to_mate[into.idx()];
        for x in points.iter_mut() {
            *x = motion.apply(x);
        }
        for d in dirs.iter_mut() {
            *d = motion.apply_vector(d);
        }
        self.p.mate(into).expect("closed")
    }

    /// Follows the Voronoi edge dual to side `side` of the polygon of instance `k` of triangle
    /// `q` to its other end: returns the triangle, instance and polygon side there, and the
    /// segments crossed.
    fn follow(&self, q: PolygonId, k: usize, side: usize) -> Result<Followed<S>, String> {
        let p = self.p;
        let inst = &self.instances[q.idx()][k];
        let m = inst.sites.len();
        let pts = self.pts(q);
        let mut ya = pts[inst.sites[side] as usize].clone();
        let mut yb = pts[inst.sites[(side + 1) % m] as usize].clone();
        let mut dir = rot_right(&sub(&yb, &ya));
        let mut x = inst.at.clone();
        let mut tri = q;
        // Sites that cannot end the edge: the vertex's own in the first triangle, none after.
        let mut skip: &[u32] = &inst.sites;
        let mut segments = Vec::new();
        for step in 0..self.step_budget {
            let missing = |y: &Point<S>| {
                let best = self
                    .pts(tri)
                    .iter()
                    .map(|z| dist2(z, y).to_f64().sqrt())
                    .fold(f64::INFINITY, f64::min);
                format!(
                    "a site of the edge is missing from the constellation of triangle {} (nearest at {best:e}, eps {:e}, step {step})",
                    tri.idx(),
                    self.eps
                )
            };
            let ia = self.wave.find(tri, &ya).ok_or_else(|| missing(&ya))?;
            let ib = self.wave.find(tri, &yb).ok_or_else(|| missing(&yb))?;
            if !S::EXACT && step > 0 {
                // The sites are found in this triangle's constellation within the wave's
                // tolerance, not where the gluings carried them (`T′` closes up only to that
                // tolerance): continue from this triangle's copies, on their bisector.
                let pts = self.pts(tri);
                (ya, yb) = (pts[ia as usize].clone(), pts[ib as usize].clone());
                dir = rot_right(&sub(&yb, &ya));
                x = onto_bisector(&x, &ya, &yb);
            }
            let (exit, t_exit) = self.exit(tri, &x, &dir);
            if matches!(exit, Exit::None) {
                return Err("the edge does not leave a triangle".into());
            }
            let through = self.edge_runs_through(&exit, ia, ib);
            let vertex = if through {
                None
            } else {
                self.first_vertex(tri, &x, &dir, ia, [&[ib], skip], &t_exit)
            };
            if let Some(v) = vertex {
                segments.push((tri, x.clone(), v.clone()));
                let k2 = self.instance_at(tri, &v).ok_or_else(|| {
                    format!(
                        "the edge ends at a point of triangle {} with nearest sites {:?} that \
                         was not found as a vertex (step {step})",
                        tri.idx(),
                        self.nearest(tri, &v)
                    )
                })?;
                return self.resolve(tri, k2, ya, yb, segments);
            }
            let end = add(&x, &scale(&t_exit, &dir));
            segments.push((tri, x.clone(), end.clone()));
            skip = &[];
            match exit {
                Exit::Side(s, _) => {
                    let motion = &self.wave.to_mate[s.idx()];
                    x = motion.apply(&end);
                    ya = motion.apply(&ya);
                    yb = motion.apply(&yb);
                    dir = motion.apply_vector(&dir);
                    tri = p.owner(p.mate(s).expect("closed"));
                }
                Exit::Corner(s) => {
                    // Through a flat vertex of T: turn around it until the wedge holds `dir`.
                    let mut cur = s;
                    let mut pts = [end, ya, yb];
                    let mut dirs = [dir];
                    let corners = p.star(s).ok_or("an open star")?.len();
                    let mut found = false;
                    for _ in 0..=corners {
                        let c = &pts[0];
                        let e1 = sub(p.end_ref(cur), c);
                        let e2 = sub(p.start_ref(p.prev_side(cur)), c);
                        let w = &dirs[0];
                        let along_e1 = cross(&e1, w).sign() == Ordering::Equal
                            && dot(&e1, w).sign() == Ordering::Greater;
                        if along_e1
                            || (cross(&e1, w).sign() == Ordering::Greater
                                && cross(w, &e2).sign() == Ordering::Greater)
                        {
                            found = true;
                            break;
                        }
                        cur = self.turn_corner(cur, &mut pts, &mut dirs);
                    }
                    if !found {
                        return Err("no triangle around a vertex of T holds the edge".into());
                    }
                    let [c, a2, b2] = pts;
                    x = p.start(cur);
                    debug_assert!(!S::EXACT || c == x);
                    ya = a2;
                    yb = b2;
                    dir = dirs[0].clone();
                    tri = p.owner(cur);
                }
                Exit::None => unreachable!("handled above"),
            }
        }
        Err("too many steps".into())
    }

    /// From the instance `k` of triangle `q` reached along the edge of sites `ya`, `yb` (in
    /// `q`'s frame), the owning instance and the index of its side from `yb` to `ya`.
    fn resolve(
        &self,
        q: PolygonId,
        k: usize,
        mut ya: Point<S>,
        mut yb: Point<S>,
        segments: Vec<Segment<S>>,
    ) -> Result<Followed<S>, String> {
        let p = self.p;
        let inst = &self.instances[q.idx()][k];
        let (mut tri, mut kk) = (q, k);
        if inst.polygon.is_none() {
            let mut at = inst.at.clone();
            match inst.place {
                Place::Side(s) => {
                    let motion = &self.wave.to_mate[s.idx()];
                    at = motion.apply(&at);
                    ya = motion.apply(&ya);
                    yb = motion.apply(&yb);
                    tri = p.owner(p.mate(s).expect("closed"));
                }
                Place::Corner(s) => {
                    let corners = p.star(s).ok_or("an open star")?;
                    let target = *corners.iter().min().expect("a corner");
                    let mut cur = s;
                    let mut pts = [at, ya, yb];
                    while cur != target {
                        cur = self.turn_corner(cur, &mut pts, &mut []);
                    }
                    [at, ya, yb] = pts;
                    tri = p.owner(cur);
                }
                Place::Interior => return Err("an interior vertex without a polygon".into()),
            }
            kk = self
                .instance_at(tri, &at)
                .ok_or("the owner of a vertex on the boundary of a triangle did not find it")?;
        }
        let owner = &self.instances[tri.idx()][kk];
        let pts = self.pts(tri);
        let m = owner.sites.len();
        for j in 0..m {
            let (from, to) = (
                &pts[owner.sites[j] as usize],
                &pts[owner.sites[(j + 1) % m] as usize],
            );
            if self.same_point(from, &yb) && self.same_point(to, &ya) {
                return Ok((tri, kk, j, segments));
            }
        }
        Err("the vertex reached has no side between the edge's two sites".into())
    }
}
