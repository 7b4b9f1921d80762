//! Section 8 (proof of Proposition 2): caps around the cone points, ALGORITHM on the flat
//! remainder, the caps put back. Theorem 1 with cone points, Proposition 2 then Proposition 3's
//! wave, is [`super::delaunay_tessellation_dubois`].
//!
//! **The paper's steps and their functions:**
//! - `d`, the minimum height of the triangles of `T`, and the cap points on every directed edge
//!   leaving a cone point (interior singularity): [`cut_caps`], with the radius of docs/dubois.md §3.4
//!   (below);
//! - tracing each cap boundary and cutting the faces along it (`T₀`), then cutting the
//!   remaining polygons along shortcuts (INSERTEDGES' [`Portalgon::triangulate_by_shortcuts`]):
//!   [`cut_caps`] ([`CapCut::t0`]);
//! - removing the cap triangles (`T₁`, flat, with one boundary cycle per cone point):
//!   [`CapCut::remainder`];
//! - Proposition 1 on `T₁` (ALGORITHM with `N = ⌈log₂(2 + L₁/s)⌉`, `s = d/(12r)` below):
//!   [`super::reduce_with_boundary`] with [`CapCut::outer_iterations`];
//! - placing the caps back (Proposition 2's output portalgon `T′`): [`put_caps_back`].
//!
//! **Decisions and deviations:**
//! - **\[reconstruction, docs/dubois.md §3.4\] Cap radius.** The paper's point at distance `d/6` from
//!   the cone point is irrational in general (`d` is a height). Each edge `e` at a cone point gets
//!   the point at distance `ρ_e = 2^{−k}|e|` from it, `k` the least integer with `ρ_e ≤ d/6`
//!   (decided exactly on squares: `36·|e|² ≤ 4^k·d²`, `d² = min 4A²/ℓ²_max`), so
//!   `ρ_e ∈ (d/12, d/6]` and the split parameter is the dyadic rational `2^{−k}`: exact in exact
//!   mode. An edge between two cone points (or a loop at one) gets a point from each end, with
//!   the same `k` (they are distinct: `ρ_e ≤ d/6 < |e|/2`). Every cap point is within `d/6` of its
//!   cone point, as in the paper, so the paper's argument for the happiness bound is unchanged.
//! - **`s` and `N`.** The paper's bound `ℓ(p) ≥ d/(6r)` on a cap boundary segment becomes
//!   `ℓ(p) ≥ (d/12)·sin θ ≥ d/(12r)` (the angle `θ` at the cone point has `sin θ ≥ d/L`; for
//!   `θ ≥ π/2` the segment is longer than either radius), so the systole bound of the first
//!   claim is `s = d/(12r)`, `r = L/d` with `L`, `d` of the input `T`. `N` is the least integer
//!   with `2^N ≥ 2 + L₁/s = 2 + 12·L₁·L/d²`, `L₁` the longest side of `T₁`, decided exactly on
//!   squares in exact mode, with a relative margin of 1e-9 upward in `f64` (never
//!   underestimated).
//! - Cone points are decided by [`crate::voronoi::is_flat_vertex`] (exactly in exact mode, within
//!   the angle tolerance in `f64`); a surface with none goes to
//!   [`super::delaunay_tessellation_flat`] (no caps, `s = d/2`).
//! - **Which vertices get a cap** ([`cut_caps_at`]): in exact mode with [`Sources::Singular`]
//!   the cone points (the paper). With [`Sources::All`] (Section 1's footnote 1: V any vertex
//!   set containing the singularities, here every input vertex, the flip route's) every vertex,
//!   so that ALGORITHM, which deletes flat interior vertices, keeps them; the wave then runs from
//!   the capped vertices of `T′` ([`crate::voronoi::voronoi_delaunay_from`]). In `f64` every
//!   vertex is capped whatever the sources: a vertex flat only within the angle tolerance is not
//!   flat for DELETEVERTICES (its star does not close up), so none of the input's vertices is
//!   left inside `T₁`; every interior vertex of `T₁` is then a midpoint, flat by construction.
//! - **\[`f64` only\] Local radii.** The paper's `d` is global: one thin triangle makes every
//!   cap tiny, and `T₁`'s pieces in fat triangles become needles of aspect `L/d` whose f64 merges
//!   lose `log₁₀(L/d)` digits. In `f64` the radius of an edge comes from the smaller height `h`
//!   of its two faces instead (`ρ_e ∈ (h/12, h/6]`): each cap lies within `h_f/6` of its corner
//!   in each face `f`, and the corners of `f` are at least `h_f` apart, so caps stay disjoint and
//!   inside their faces; radii only grow (`h ≥ d`), and `N` is still computed from the global
//!   `d` (an upper bound).
//! - **\[`f64` only\] Closing tolerance.** Every interior vertex of `T₁` is flat and every
//!   re-glued side keeps its length by construction, so ALGORITHM's checks of them (a deleted
//!   vertex's corners meeting, matched lengths) only measure the rounding accumulated by the
//!   motions of many merges (rigid in `f64`: [`crate::geometry::Motion::gluing`]); on `T₁` they
//!   use a relative tolerance of at least [`Tolerances::closing`] (1e-6) rather than
//!   1e-9. A cap is glued back to its side of `T₁` with that tolerance relative to the longest
//!   side of that side's polygon, in `T₁` or after ALGORITHM, whichever is longer
//!   ([`Portalgon::glue_at_scale`]): cap sides are far shorter than the polygons around them,
//!   whose rounding they carry. The output is checked independently (the tests compare the
//!   Laplacian with the flip route's: to 1e-12 on the smallest shared meshes;
//!   `results/dubois-every-mesh.txt` gives each mesh's deviation).
//! - INSERTEDGES in `f64` skips degenerate shortcut candidates (an arc along a side up to
//!   rounding: [`Portalgon::shortcut`]), which the midpoints and cap points, straight corners
//!   off their line by an ulp, would otherwise produce.
//! - Order: edges in increasing side id (lower id of the pair), corners in increasing id of the
//!   side leaving the cone point; the remaining polygons are cut in increasing polygon id.
//! - The caps are kept as they were cut (triangles of `T₀` with their corners and labels) and
//!   glued back by side id: the boundary sides of `T₁` keep their ids through ALGORITHM
//!   (INSERTVERTICES never splits them, deletions only remove sides at interior vertices, the
//!   splice keeps boundary ids), which [`put_caps_back`] checks (a missing or changed side is a
//!   typed error, never a silent mismatch).
//!
//! **Guarantees.** Proposition 2's and Theorem 1's hold for exact input in exact mode (every
//! step above is exact over the rationals). None is claimed in `f64`: the routines run with the
//! tolerances above, and a failure is a typed [`CapsError`] (an edit's or the wave's), never a
//! silent answer; `tests/caps.rs` compares the result with the flip route on the shared
//! meshes.

use super::delaunay_exit::flip_to_delaunay_within;
use super::{
    DuboisError, DuboisReport, FlatDelaunayOptions, Reduction, reduce_with_boundary_until,
};

use crate::geometry::{DoubleDouble, Scalar, Tolerances};
use crate::portalgon::{PolygonId, Portalgon, SideId};
use crate::voronoi::{Sources, VoronoiError, is_flat_vertex};

/// Why [`cut_caps`], [`put_caps_back`] or [`super::delaunay_tessellation_dubois`] failed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CapsError {
    /// Bad input (not closed, not triangular) or a failure of ALGORITHM on the remainder.
    #[error(transparent)]
    Reduction(#[from] DuboisError),
    /// Proposition 3's wave or its dual failed.
    #[error(transparent)]
    Voronoi(#[from] VoronoiError),
    /// Proposition 3's wave on `T′` exceeded its work budget
    /// ([`crate::voronoi::MAX_WAVE_WORK`]): `T′` is far from Proposition 2's happiness bound, as
    /// rounding can leave it on a very thin input in double precision. (The wave's own message
    /// advises Theorem 1, which is what ran.)
    #[error(
        "Theorem 1's wave on the reduced triangulation T′ exceeded its work budget of {0} (the \
         sizes of the constellations its events land in, summed): T′ is far from Proposition \
         2's happiness bound, as rounding can leave it on a very thin input in double precision"
    )]
    WaveWork(u64),
}

impl From<crate::error::PortalgonError> for CapsError {
    fn from(e: crate::error::PortalgonError) -> Self {
        Self::Reduction(e.into())
    }
}

impl From<crate::portalgon::EditError> for CapsError {
    fn from(e: crate::portalgon::EditError) -> Self {
        Self::Reduction(e.into())
    }
}

/// Section 8's cut: `T₀` (the caps traced and cut, the rest cut along shortcuts), its cap
/// triangles, and `T₁` (the flat remainder).
#[derive(Clone, Debug)]
pub struct CapCut<S: Scalar> {
    /// `T₀`: the input's surface, every polygon a triangle, the caps among them.
    pub t0: Portalgon<S>,
    /// The cap triangles of `T₀` (corner 1 of each is not guaranteed: the cone point is the start
    /// of [`Self::apex_sides`]`[k]`), in the order they were cut.
    pub caps: Vec<PolygonId>,
    /// Per cap, its side leaving the cone point.
    pub apex_sides: Vec<SideId>,
    /// `T₁ = T₀` minus the caps, dense ids; the cap boundaries are its boundary.
    pub remainder: Portalgon<S>,
    /// Side ids of `T₀` to those of `T₁` (`INVALID` for cap sides).
    pub to_remainder: Vec<SideId>,
    /// The number of cone points.
    pub cone_points: usize,
    /// The number of vertices capped (the cone points, and in `f64` or for [`Sources::All`]
    /// every vertex: see the module doc).
    pub capped_vertices: usize,
    /// `N = ⌈log₂(2 + L₁/s)⌉` with `s = d/(12r)` (module doc).
    pub outer_iterations: u32,
}

/// The squared smallest height `h²` of a triangle (`4A²/ℓ²_max`).
fn smallest_height2<S: Scalar>(t: &Portalgon<S>, p: PolygonId) -> S {
    let longest = t
        .polygon_sides(p)
        .iter()
        .map(|&s| t.side_length2(s))
        .fold(S::zero(), |m, l| if l > m { l } else { m });
    let a = t.polygon_area(p);
    S::from_i64(4) * a.clone() * a / longest
}

/// The squared smallest height `d²` and squared longest side `L²` of a triangular portalgon.
pub(crate) fn heights_and_lengths<S: Scalar>(t: &Portalgon<S>) -> (S, S) {
    let mut d2: Option<S> = None;
    let mut l2 = S::zero();
    for p in t.polygons() {
        let h2 = smallest_height2(t, p);
        if d2.as_ref().is_none_or(|d| h2 < *d) {
            d2 = Some(h2);
        }
        for &s in t.polygon_sides(p) {
            let l = t.side_length2(s);
            if l > l2 {
                l2 = l;
            }
        }
    }
    (d2.unwrap_or_else(S::zero), l2)
}

/// The least `k ≥ 0` with `36·ℓ² ≤ 4^k·d²` (the radius `2^{−k}ℓ ≤ d/6`), capped at 4096.
fn radius_exponent<S: Scalar>(l2: &S, d2: &S) -> u32 {
    let lhs = S::from_i64(36) * l2.clone();
    let mut rhs = d2.clone();
    let mut k = 0;
    while rhs < lhs && k < 4096 {
        rhs = rhs * S::from_i64(4);
        k += 1;
    }
    k
}

/// `2^{−k}`, exactly.
fn dyadic<S: Scalar>(k: u32) -> S {
    let mut x = S::one();
    for _ in 0..k {
        x = x.half();
    }
    x
}

/// The least `N ≥ 1` with `((2^N − 2)·d²)² ≥ 144·L₁²·L²` (`2^N ≥ 2 + L₁/s`, `s = d²/(12L)`); in
/// `f64` the right side enlarged by a relative 1e-9. Capped at 4096.
fn outer_iterations_with_caps<S: Scalar>(d2: &S, l2: &S, l1_2: &S) -> u32 {
    let margin = S::upward_margin(Tolerances::DEFAULT.bound_margin);
    let rhs = S::from_i64(144) * l1_2.clone() * l2.clone() * margin;
    let mut n = 1u32;
    let mut power = S::from_i64(2);
    loop {
        let lhs = (power.clone() - S::from_i64(2)) * d2.clone();
        if lhs.clone() * lhs >= rhs || n >= 4096 {
            return n;
        }
        n += 1;
        power = power.clone() + power;
    }
}

/// Checks Section 8's input: valid, closed, triangular.
fn check_triangular_closed<S: Scalar>(t: &Portalgon<S>) -> Result<(), CapsError> {
    t.check_invariants()?;
    t.check_closed()?;
    if let Some(p) = t.polygons().find(|&p| t.polygon_sides(p).len() != 3) {
        return Err(DuboisError::NotTriangular {
            polygon: p.idx(),
            sides: t.polygon_sides(p).len(),
        }
        .into());
    }
    Ok(())
}

/// Per vertex class of `t`, whether it is a cone point ([`is_flat_vertex`]).
pub(super) fn cone_points<S: Scalar>(t: &Portalgon<S>, angle_tolerance: f64) -> Vec<bool> {
    let (class, count) = t.vertex_classes();
    let mut first = vec![SideId::INVALID; count];
    for s in t.sides() {
        let c = class[s.idx()] as usize;
        if !first[c].is_valid() {
            first[c] = s;
        }
    }
    first
        .iter()
        .map(|&s| !is_flat_vertex(t, s, angle_tolerance))
        .collect()
}

/// Section 8's first construction on a closed triangular portalgon `t`: a point on every
/// directed edge leaving a cone point at the dyadic radius of the module doc, every corner at a
/// cone point cut off along the segment joining its two points (the cap triangle), the rest of
/// each face cut along shortcuts (`T₀`), and the caps removed (`T₁`). O(n) edits.
///
/// # Errors
/// [`DuboisError::Portalgon`] for an invalid or open input, [`DuboisError::NotTriangular`].
pub fn cut_caps<S: Scalar>(t: &Portalgon<S>, angle_tolerance: f64) -> Result<CapCut<S>, CapsError> {
    check_triangular_closed(t)?;
    let cone = cone_points(t, angle_tolerance);
    cut_caps_at(t, &cone, &cone)
}

/// [`cut_caps`] with the vertices to cap given: `capped[c]` for each vertex class `c` of `t`
/// ([`Portalgon::vertex_classes`]); `cone[c]` says which of them are cone points (counted in
/// [`CapCut::cone_points`]). Every cone point must be capped (ALGORITHM takes a flat remainder);
/// capping a flat vertex too is Section 1's footnote 1 (V containing the singularities) and, in
/// `f64`, keeps vertices flat only within the tolerance out of DELETEVERTICES (module doc).
///
/// # Errors
/// As [`cut_caps`].
pub fn cut_caps_at<S: Scalar>(
    t: &Portalgon<S>,
    capped: &[bool],
    cone: &[bool],
) -> Result<CapCut<S>, CapsError> {
    check_triangular_closed(t)?;
    let (d2, l2) = heights_and_lengths(t);
    let (class, _) = t.vertex_classes();
    let is_cone = |s: SideId| capped.get(class[s.idx()] as usize) == Some(&true);
    let mut t0 = t.clone();
    // The sides leaving a cone point (one per corner there), before any split.
    let apex_sides: Vec<SideId> = t.sides().filter(|&s| is_cone(s)).collect();
    // One point per edge end at a cone point. The side leaving the cone point keeps its id and
    // its start through `split_side` (it keeps its first half), so `apex_sides` stay valid.
    let edges: Vec<(SideId, SideId)> = t
        .sides()
        .filter_map(|s| t.mate(s).filter(|&m| s < m).map(|m| (s, m)))
        .collect();
    for (s, m) in edges {
        let (at_start, at_end) = (is_cone(s), is_cone(m));
        if !at_start && !at_end {
            continue;
        }
        // Exact mode: the paper's global `d`. `f64`: the smaller height of the edge's two faces
        // (module doc).
        let local;
        let d2_e = if S::EXACT {
            &d2
        } else {
            let (a, b) = (
                smallest_height2(t, t.owner(s)),
                smallest_height2(t, t.owner(m)),
            );
            local = if a < b { a } else { b };
            &local
        };
        let k = radius_exponent(&t.side_length2(s), d2_e);
        let lambda: S = dyadic(k);
        if at_start {
            t0.split_side(s, &lambda)?;
        }
        if at_end {
            // `m` starts at the other end; after a split at `s` it is the part of length
            // `(1 − λ)·|e|`, so the parameter is rescaled to keep the distance `λ·|e|`.
            let mu = if at_start {
                lambda.clone() / (S::one() - lambda)
            } else {
                lambda
            };
            t0.split_side(m, &mu)?;
        }
    }
    let mut caps = Vec::with_capacity(apex_sides.len());
    for &x in &apex_sides {
        let p = t0.owner(x);
        let (i, j) = (
            t0.side_index(t0.prev_side(x)),
            t0.side_index(t0.next_side(x)),
        );
        // `p` keeps corners i..=j: the point before the cone point, the cone point, the point
        // after it — the cap triangle.
        t0.cut(p, i, j)?;
        caps.push(t0.owner(x));
    }
    let mut is_cap = vec![false; t0.polygon_slots()];
    for &c in &caps {
        is_cap[c.idx()] = true;
    }
    let others: Vec<PolygonId> = t0.polygons().filter(|p| !is_cap[p.idx()]).collect();
    for &p in &others {
        if t0.polygon_sides(p).len() > 3 {
            t0.triangulate_by_shortcuts(p)?;
        }
    }
    let is_cap = |p: PolygonId| is_cap.get(p.idx()).copied().unwrap_or(false);
    let remaining: Vec<PolygonId> = t0.polygons().filter(|&p| !is_cap(p)).collect();
    let (remainder, to_remainder) = t0.sub_portalgon(&remaining);
    let remainder = in_local_frames(&remainder, Tolerances::DEFAULT.length)?;
    let l1_2 = remainder
        .sides()
        .map(|s| remainder.side_length2(s))
        .fold(S::zero(), |m, l| if l > m { l } else { m });
    let outer_iterations = outer_iterations_with_caps(&d2, &l2, &l1_2);
    Ok(CapCut {
        t0,
        caps,
        apex_sides,
        remainder,
        to_remainder,
        cone_points: cone.iter().filter(|&&c| c).count(),
        capped_vertices: capped.iter().filter(|&&c| c).count(),
        outer_iterations,
    })
}

/// A copy of a dense portalgon with every polygon translated so that its first corner is the
/// origin (same side ids, labels and matching): the frames ALGORITHM's merges start from are then
/// local, so that in `f64` rounding is relative to the polygons' sizes rather than to the
/// coordinates of the input (cap-sized pieces lie far from the origin). Exact in exact mode.
pub(super) fn in_local_frames<S: Scalar>(
    p: &Portalgon<S>,
    tolerance: f64,
) -> Result<Portalgon<S>, CapsError> {
    let mut out = Portalgon::empty();
    for q in p.polygons() {
        let c = p.corners(q);
        let o = c[0].clone();
        let moved: Vec<_> = c.iter().map(|x| crate::geometry::sub(x, &o)).collect();
        let r = out.add_polygon(&moved)?;
        let labels: Vec<u32> = p
            .polygon_sides(q)
            .iter()
            .map(|&s| p.vertex_label(s).unwrap_or(u32::MAX))
            .collect();
        out.set_vertex_labels(r, &labels)?;
    }
    for s in p.sides() {
        if let Some(t) = p.mate(s).filter(|&t| s < t) {
            // Translations keep lengths (exactly in exact mode, to rounding in `f64`).
            out.glue(s, t, tolerance)?;
        }
    }
    Ok(out)
}

/// The closed triangular portalgon `t` (in `f64`) laid out again in double-double: one length
/// per edge (its lower side id's, from the corners), each triangle placed from its three
/// lengths, so that matched sides agree to double-double rounding instead of differing by the
/// rounding of two independent `f64` layouts (which a short piece cut from the edge, a cap
/// side, would carry as a large relative error). A triangle the new lengths make degenerate
/// keeps its corners. Ids, matching and labels are kept.
pub(super) fn laid_out_in_double_double<S: Scalar>(t: &Portalgon<S>) -> Portalgon<DoubleDouble> {
    let mut out = t.map_coordinates(|x| DoubleDouble::from_f64_exact(x.to_f64()));
    let length2 = |p: &Portalgon<DoubleDouble>, s: SideId| {
        let s = p.mate(s).map_or(s, |m| m.min(s));
        p.side_length2(s)
    };
    for q in t.polygons() {
        let &[s0, s1, s2] = t.polygon_sides(q) else {
            continue;
        };
        let [a2, b2, c2] = [s0, s1, s2].map(|s| length2(&out, s));
        let a = a2.sqrt();
        // Corner 0 at the origin, corner 1 at (a, 0), corner 2 at (x, y): |2 − 0| = c, |2 − 1| = b.
        let x = (a2 + c2 - b2) / (a + a);
        let y2 = c2 - x * x;
        if y2.sign() != std::cmp::Ordering::Greater {
            continue;
        }
        let zero = DoubleDouble::zero();
        out.start[s0.idx()] = [zero, zero];
        out.start[s1.idx()] = [a, zero];
        out.start[s2.idx()] = [x, y2.sqrt()];
    }
    out
}

/// Section 8's last step (Proposition 2's output `T′`): the cap triangles of `cut` added to
/// `reduced` (ALGORITHM's output on [`CapCut::remainder`], whose boundary sides all survive:
/// [`Reduction::side_of_input`]) and glued back: to each other as in `T₀`, and to the boundary
/// sides. Lengths are checked by [`Portalgon::glue`] (exactly in exact mode,
/// within `tolerance` in `f64`).
///
/// # Errors
/// [`DuboisError::Portalgon`] when a boundary side is missing, already matched or of another
/// length.
pub fn put_caps_back<S: Scalar>(
    reduced: &Reduction<S>,
    cut: &CapCut<S>,
    tolerance: f64,
) -> Result<Portalgon<S>, CapsError> {
    Ok(put_caps_back_mapped(reduced, cut, tolerance)?.0)
}

/// [`put_caps_back`], with the map from `T₀`'s cap side ids to the output's.
fn put_caps_back_mapped<S: Scalar>(
    reduced: &Reduction<S>,
    cut: &CapCut<S>,
    tolerance: f64,
) -> Result<(Portalgon<S>, Vec<SideId>), CapsError> {
    let t0 = &cut.t0;
    let mut out = reduced.portalgon.clone();
    let mut new_side = vec![SideId::INVALID; t0.side_slots()];
    for &c in &cut.caps {
        let q = out.add_polygon(&t0.corners(c))?;
        let labels: Vec<u32> = t0
            .polygon_sides(c)
            .iter()
            .map(|&s| t0.vertex_label(s).unwrap_or(u32::MAX))
            .collect();
        out.set_vertex_labels(q, &labels)?;
        for (i, &s) in t0.polygon_sides(c).iter().enumerate() {
            new_side[s.idx()] = out.side(q, i);
        }
    }
    for &c in &cut.caps {
        for &x in t0.polygon_sides(c) {
            let y = t0.mate(x).expect("T₀ is closed");
            if new_side[y.idx()].is_valid() {
                if x < y {
                    out.glue(new_side[x.idx()], new_side[y.idx()], tolerance)?;
                }
            } else {
                let boundary = cut.to_remainder[y.idx()];
                let now = reduced.side_of_input(boundary).ok_or_else(|| {
                    DuboisError::Invariant(format!(
                        "boundary side {} of T₁ did not survive ALGORITHM",
                        boundary.idx()
                    ))
                })?;
                // In f64, `now` comes out of ALGORITHM with the rounding of the polygons it
                // was merged with: its length is compared at the scale of its polygon, before
                // ALGORITHM (in T₁) and after.
                let longest = |p: &Portalgon<S>, s: SideId| {
                    p.polygon_sides(p.owner(s))
                        .iter()
                        .map(|&z| p.side_length(z))
                        .fold(0.0, f64::max)
                };
                let scale = longest(&out, now).max(longest(&cut.remainder, boundary));
                out.glue_at_scale(new_side[x.idx()], now, tolerance, scale)?;
            }
        }
    }
    Ok((out, new_side))
}

/// Proposition 2 on a closed triangular portalgon: [`cut_caps_at`] (the vertices capped: see
/// the module doc), ALGORITHM on `T₁` ([`super::reduce_with_boundary`] with `N` of the module doc, in exact mode
/// with the Delaunay exit of [`super::delaunay_exit`]),
/// [`put_caps_back`]. Returns `T′` (compacted: dense ids), ALGORITHM's report and the cut.
///
/// # Errors
/// As the three steps.
pub fn proposition_2<S: Scalar>(
    t: &Portalgon<S>,
    options: &FlatDelaunayOptions,
) -> Result<(Portalgon<S>, DuboisReport, CapCut<S>), CapsError> {
    let (t_prime, report, cut, _) = proposition_2_with_apexes(t, options)?;
    Ok((t_prime, report, cut))
}

/// [`proposition_2`]'s output and the vertex classes of `T′` that are capped vertices of the
/// input (increasing, each once).
pub(super) type WithApexes<S> = (Portalgon<S>, DuboisReport, CapCut<S>, Vec<u32>);

/// [`proposition_2`], with the vertex classes of `T′` that are capped vertices of `t`.
pub(super) fn proposition_2_with_apexes<S: Scalar>(
    t: &Portalgon<S>,
    options: &FlatDelaunayOptions,
) -> Result<WithApexes<S>, CapsError> {
    check_triangular_closed(t)?;
    let cone = cone_points(t, options.tolerances.angle);
    let capped = if S::EXACT && options.sources == Sources::Singular {
        cone.clone()
    } else {
        vec![true; cone.len()]
    };
    let cut = cut_caps_at(t, &capped, &cone)?;
    let mut reduce = options.reduce;
    reduce.outer_iterations = reduce.outer_iterations.or(Some(cut.outer_iterations));
    reduce.tolerances.length = reduce
        .tolerances
        .length
        .max(S::slack(|| options.tolerances.closing));
    // Exact mode: the Delaunay exit (`delaunay_exit`), `T″` and its apex sides once found.
    let mut flipped: Option<(Portalgon<S>, Vec<SideId>)> = None;
    let tolerance = reduce.tolerances.length;
    let mut delaunay_exit = |r: &Reduction<S>| -> Result<bool, DuboisError> {
        let (mut t2, new_side) = put_caps_back_mapped(r, &cut, tolerance).map_err(|e| match e {
            CapsError::Reduction(e) => e,
            e @ (CapsError::Voronoi(_) | CapsError::WaveWork(_)) => {
                DuboisError::Invariant(e.to_string())
            }
        })?;
        let mut apex_sides: Vec<SideId> =
            cut.apex_sides.iter().map(|&x| new_side[x.idx()]).collect();
        // One flip per two triangles (an edge in three): the test costs less than an outer
        // iteration (results/exact_growth.md measured n′ and 2n′ too: slower overall).
        let budget = t2.polygon_count() / 2;
        if flip_to_delaunay_within(&mut t2, budget, &mut apex_sides) {
            flipped = Some((t2, apex_sides));
            return Ok(true);
        }
        Ok(false)
    };
    let r = reduce_with_boundary_until(&cut.remainder, &reduce, &mut delaunay_exit)?;
    let (t_prime, apex_sides) = match flipped {
        Some(found) => found,
        None => {
            let (t_prime, new_side) = put_caps_back_mapped(&r, &cut, reduce.tolerances.length)?;
            let apex_sides = cut.apex_sides.iter().map(|&x| new_side[x.idx()]).collect();
            (t_prime, apex_sides)
        }
    };
    let mut report = r.report;
    report.triangles_after_reduction = t_prime.polygon_count();
    let (t_prime, dense) = t_prime.compacted();
    let (class, _) = t_prime.vertex_classes();
    let mut apexes: Vec<u32> = apex_sides
        .iter()
        .map(|&x| class[dense[x.idx()].idx()])
        .collect();
    apexes.sort_unstable();
    apexes.dedup();
    Ok((t_prime, report, cut, apexes))
}
