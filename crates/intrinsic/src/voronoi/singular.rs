//! The vertex set V of the wave: the singular vertices (Dubois, Section 2.2: angle sum different
//! from 2π), or one vertex when there is none (a flat torus, Proof of Proposition 3).
//!
//! Exact mode decides flatness exactly (docs/dubois.md §3.5): the star of the vertex is unfolded into
//! the plane of its first corner by composing the gluing maps ([`Motion::gluing`], exact on rationals), and
//! the vertex is flat iff the composed map around the star is the identity and the corners wind
//! exactly once around the vertex (the number of corner wedges, half-open, that contain the
//! direction of the first side). In `f64` the angle sum is summed with `atan2` and compared with 2π
//! up to the angle tolerance ([`crate::DEFAULT_ANGLE_TOLERANCE`] = 1e-9 radians by
//! default).

use std::cmp::Ordering;
use std::f64::consts::TAU;

use crate::geometry::{Motion, Point, Scalar, cross, dot, sub};
use crate::portalgon::{Portalgon, SideId};

/// The gluing map from the frame of the polygon of `q` to the frame of the polygon of `s` that
/// puts `q` onto its mate `s` (footnote 2: `start(q) ↦ end(s)`, `end(q) ↦ start(s)`).
pub(crate) fn gluing<S: Scalar>(p: &Portalgon<S>, q: SideId, s: SideId) -> Motion<S> {
    Motion::gluing(p.start_ref(q), p.end_ref(q), p.end_ref(s), p.start_ref(s))
}

/// Whether direction `r` lies in the half-open wedge from `a` (included) counter-clockwise to `b`
/// (excluded), the wedge being less than a half-turn. Exact signs.
fn in_wedge<S: Scalar>(a: &Point<S>, b: &Point<S>, r: &Point<S>) -> bool {
    let ar = cross(a, r).sign();
    let rb = cross(r, b).sign();
    match ar {
        Ordering::Less => false,
        Ordering::Equal => dot(a, r).sign() == Ordering::Greater,
        Ordering::Greater => rb == Ordering::Greater,
    }
}

/// Whether the vertex at the start of side `s` is flat: exactly in exact mode (unfolding, see the
/// module doc), within `angle_tolerance` of 2π in `f64`. A vertex with an unmatched side around it
/// (boundary) counts as singular.
pub fn is_flat_vertex<S: Scalar>(p: &Portalgon<S>, s: SideId, angle_tolerance: f64) -> bool {
    let Some(corners) = p.star(s) else {
        return false;
    };
    if !S::EXACT {
        let sum: f64 = corners
            .iter()
            .map(|&c| {
                let v = p.start_ref(c);
                let e1 = sub(p.end_ref(c), v);
                let e2 = sub(p.start_ref(p.prev_side(c)), v);
                let (x, y) = (dot(&e1, &e2).to_f64(), cross(&e1, &e2).to_f64());
                y.atan2(x)
            })
            .sum();
        return (sum - TAU).abs() <= angle_tolerance;
    }
    // Unfold: `to_first` maps the frame of the current corner's polygon to that of corner 0.
    let mut to_first = Motion::identity();
    let v0 = p.start(s);
    let r = sub(p.end_ref(s), &v0);
    let mut windings = 0usize;
    let mut cur = s;
    for k in 0..=corners.len() {
        if k > 0 {
            let into = p.prev_side(corners[k - 1]);
            let next = if k == corners.len() { s } else { corners[k] };
            to_first = to_first.compose(&gluing(p, next, into));
            cur = next;
        }
        if k == corners.len() {
            break;
        }
        let v = to_first.apply(p.start_ref(cur));
        let e1 = sub(&to_first.apply(p.end_ref(cur)), &v);
        let e2 = sub(&to_first.apply(p.start_ref(p.prev_side(cur))), &v);
        if in_wedge(&e1, &e2, &r) {
            windings += 1;
        }
    }
    to_first.is_identity() && windings == 1
}

/// The singular vertices of a closed portalgon, as vertex classes of
/// [`Portalgon::vertex_classes`] (increasing), and the classes themselves (per side id). When no
/// vertex is singular (a flat torus) the set is `{0}`: Proposition 3's single arbitrary vertex,
/// chosen as the class of the lowest side id.
pub fn wave_sources<S: Scalar>(p: &Portalgon<S>, angle_tolerance: f64) -> (Vec<u32>, Vec<u32>) {
    let (class, count) = p.vertex_classes();
    let mut first = vec![SideId::INVALID; count];
    for s in p.sides() {
        let c = class[s.idx()] as usize;
        if !first[c].is_valid() {
            first[c] = s;
        }
    }
    let mut singular: Vec<u32> = (0..count as u32)
        .filter(|&c| !is_flat_vertex(p, first[c as usize], angle_tolerance))
        .collect();
    if singular.is_empty() && count > 0 {
        singular.push(0);
    }
    (singular, class)
}
