//! The Delaunay exit of Proposition 2 in exact mode (docs/dubois.md §3.8): ALGORITHM stops at
//! the first outer iteration whose `T′` (the caps put back on the current portalgon) becomes a
//! Delaunay triangulation within a budget of edge flips.
//!
//! **What the paper gives.** Proposition 3 costs `O(n²h log(nh))` on a triangulation of
//! happiness `h`; Proposition 2 (ALGORITHM run `N` times, then the caps put back) produces
//! `h = O(n log(n) log²(r))`. The paper's Section 1 and Corollary 1 use Löffler, Ophelders,
//! Staals and Silveira's theorem [20, Section 4.2] that Delaunay triangulations have happiness
//! `O(1)`.
//!
//! **What is ours.** Any triangulation of the surface serves the wave (its output is the same
//! Delaunay tessellation); only the happiness bounds its cost. So once `T′` flips to a Delaunay
//! triangulation `T″` (same vertex set: the wave's sources keep their vertices), `T″` has
//! happiness `O(1)`, below Proposition 2's bound, and the remaining outer iterations are not
//! needed. The test costs `O(n′ + budget)` exact operations (`n′` triangles of `T′`, the budget
//! is `n′/2` flips), less than an outer iteration, so Theorem 1's time bound is unchanged; when
//! it never succeeds, ALGORITHM runs its `N` iterations as the paper says. The flips are
//! Lawson's (a non-Delaunay edge of a triangulation is always flippable: its two triangles form
//! a strictly convex quadrilateral), decided by the exact in-circle test.

use crate::geometry::{Scalar, cross, dot, sub};
use crate::portalgon::{Portalgon, SideId};

/// `cot` of the corner opposite side `s` in its triangle, as `(dot, cross)` of the two sides at
/// that corner (`cross > 0`: the polygons are counter-clockwise); `None` when `s`'s polygon is
/// not a triangle.
fn opposite_corner<S: Scalar>(p: &Portalgon<S>, s: SideId) -> Option<(S, S)> {
    if p.polygon_sides(p.owner(s)).len() != 3 {
        return None;
    }
    let c = p.end_ref(p.next_side(s));
    let (u, v) = (sub(p.start_ref(s), c), sub(p.end_ref(s), c));
    Some((dot(&u, &v), cross(&u, &v)))
}

/// Whether the edge of side `s` is locally Delaunay: the two corners opposite it sum to at most
/// π, i.e. `cot α + cot β ≥ 0` (each corner read in its own chart, so no motion is needed; the
/// in-circle test of the quadrilateral laid out across the edge, exact in exact mode).
/// Unmatched sides are; a matched side next to a polygon that is not a triangle is not.
pub fn is_delaunay_side<S: Scalar>(p: &Portalgon<S>, s: SideId) -> bool {
    let Some(t) = p.mate(s) else { return true };
    match (opposite_corner(p, s), opposite_corner(p, t)) {
        (Some((dot_a, cross_a)), Some((dot_b, cross_b))) => {
            dot_a * cross_b + dot_b * cross_a >= S::zero()
        }
        _ => false,
    }
}

/// The number of edges of a triangular portalgon that are not locally Delaunay
/// ([`is_delaunay_side`]).
pub fn non_delaunay_edges<S: Scalar>(p: &Portalgon<S>) -> usize {
    p.sides()
        .filter(|&s| p.mate(s).is_some_and(|t| s < t) && !is_delaunay_side(p, s))
        .count()
}

/// Lawson's flips on a triangular portalgon until every edge is locally Delaunay, at most
/// `budget` of them. Each flip merges the two triangles of an edge ([`Portalgon::merge`]) and
/// cuts the quadrilateral along its other diagonal ([`Portalgon::cut`]). `keep` holds sides
/// whose start vertex the caller follows: a side a flip removes is replaced by another side
/// starting at the same vertex. Returns whether `p` is then Delaunay; on `false` (budget spent, or
/// an edge between two corners of one triangle that is not Delaunay) `p` is left part-flipped
/// (same surface, same vertices).
pub fn flip_to_delaunay_within<S: Scalar>(
    p: &mut Portalgon<S>,
    budget: usize,
    keep: &mut [SideId],
) -> bool {
    let mut stack: Vec<SideId> = p.sides().collect();
    let mut flips = 0;
    while let Some(s) = stack.pop() {
        if !p.is_side_live(s) || is_delaunay_side(p, s) {
            continue;
        }
        let Some(t) = p.mate(s) else { continue };
        let triangles = |x: SideId| p.polygon_sides(p.owner(x)).len() == 3;
        if !triangles(s) || !triangles(t) || p.owner(s) == p.owner(t) || flips == budget {
            return false;
        }
        // The quadrilateral after the merge: corners b, c, a, d from `s`'s next side (`s` from
        // a to b), the new diagonal from c (corner 1) to d (corner 3).
        let (next_s, next_t) = (p.next_side(s), p.next_side(t));
        for k in keep.iter_mut() {
            if *k == s {
                *k = next_t;
            } else if *k == t {
                *k = next_s;
            }
        }
        let Ok(q) = p.merge(s) else { return false };
        if p.cut(q, 1, 3).is_err() {
            return false;
        }
        flips += 1;
        for &x in p.polygon_sides(q) {
            stack.extend(p.mate(x));
        }
        let other = p.owner(p.mate(p.polygon_sides(q)[2]).expect("the new diagonal"));
        for &x in p.polygon_sides(other) {
            stack.extend(p.mate(x));
        }
    }
    non_delaunay_edges(p) == 0
}
