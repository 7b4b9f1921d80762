//! Triangulation of a simple polygon in O(n log n) with exact predicates: the sweep of de Berg,
//! Cheong, van Kreveld and Overmars, "Computational Geometry" (3rd ed., Section 3.2, algorithm
//! MAKEMONOTONE) cuts the polygon into y-monotone pieces, and each piece is cut into triangles
//! by the stack walk of Section 3.3 (TRIANGULATEMONOTONEPOLYGON).
//!
//! Decisions where the book assumes general position: corners are ordered by `y`, then by
//! decreasing `x` (the book's rule, a sweep line turned by an infinitesimal angle), so no two
//! corners are level; the stack walk cuts a corner off only when the triangle is strictly
//! counter-clockwise, so a straight corner (angle π) is never the middle of a triangle; every
//! triangle is made counter-clockwise by its orientation sign. The sweep status is a vector
//! sorted left to right, searched by bisection (O(log n) orientation tests per event); its
//! insertions and removals move O(n) words, a memory move that stays below the tests' cost at
//! the sizes a portalgon file holds.

use super::{Point, Scalar, orient};
use std::cmp::Ordering;
use std::collections::HashMap;

/// Whether corner `a` comes before corner `b` in the sweep (higher, or level and to the left).
fn above<S: Scalar>(c: &[Point<S>], a: usize, b: usize) -> bool {
    match c[a][1].partial_cmp(&c[b][1]) {
        Some(Ordering::Greater) => true,
        Some(Ordering::Less) => false,
        _ => c[a][0] < c[b][0],
    }
}

/// The sweep order of two corners: `Less` when `a` comes first ([`above`]); two equal corners
/// (only in a polygon that is not simple) in index order, so the order is total.
pub(super) fn sweep_order<S: Scalar>(c: &[Point<S>], a: usize, b: usize) -> Ordering {
    if above(c, a, b) {
        Ordering::Less
    } else if above(c, b, a) {
        Ordering::Greater
    } else {
        a.cmp(&b)
    }
}

/// The ends of side `e` (from corner `e` to corner `e + 1` of a polygon of `c.len()` corners) in
/// sweep order: (the one the sweep meets first, the other).
pub(super) fn side_ends<S: Scalar>(c: &[Point<S>], e: usize) -> (usize, usize) {
    let next = (e + 1) % c.len();
    if above(c, e, next) {
        (e, next)
    } else {
        (next, e)
    }
}

#[derive(Clone, Copy, PartialEq)]
enum Kind {
    Start,
    End,
    Split,
    Merge,
    Regular,
}

/// The cuts of a simple counter-clockwise polygon into y-monotone pieces (MAKEMONOTONE), as
/// pairs of corner indices; `None` if the sweep finds the polygon is not simple.
fn monotone_diagonals<S: Scalar>(c: &[Point<S>], order: &[usize]) -> Option<Vec<(usize, usize)>> {
    let k = c.len();
    let prev = |i: usize| (i + k - 1) % k;
    let next = |i: usize| (i + 1) % k;
    let kind: Vec<Kind> = (0..k)
        .map(|i| {
            let convex = orient(&c[prev(i)], &c[i], &c[next(i)]) == Ordering::Greater;
            match (above(c, prev(i), i), above(c, next(i), i)) {
                (false, false) if convex => Kind::Start,
                (false, false) => Kind::Split,
                (true, true) if convex => Kind::End,
                (true, true) => Kind::Merge,
                _ => Kind::Regular,
            }
        })
        .collect();
    // Edge `e` runs from corner `e` to corner `e + 1`; the status holds the edges with the
    // interior on their right that cross the sweep line, left to right.
    let ends = |e: usize| side_ends(c, e);
    // Whether edge `e` passes left of corner `v` (`v` strictly on its east side).
    let left_of = |e: usize, v: usize| {
        let (top, bottom) = ends(e);
        orient(&c[top], &c[bottom], &c[v]) == Ordering::Greater
    };
    let mut status: Vec<usize> = Vec::new();
    let mut helper = vec![usize::MAX; k];
    let mut diagonals = Vec::new();
    let insert = |status: &mut Vec<usize>, e: usize, v: usize| {
        let at = status.partition_point(|&f| left_of(f, v));
        status.insert(at, e);
    };
    let remove = |status: &mut Vec<usize>, e: usize, v: usize| -> Option<()> {
        let at = status.partition_point(|&f| left_of(f, v));
        let at = if status.get(at) == Some(&e) {
            at
        } else {
            status.iter().position(|&f| f == e)?
        };
        status.remove(at);
        Some(())
    };
    let left_edge = |status: &[usize], v: usize| -> Option<usize> {
        let at = status.partition_point(|&f| left_of(f, v));
        at.checked_sub(1).map(|a| status[a])
    };
    for &v in order {
        let before = prev(v); // the edge ending at v
        let merge_helper = |helper: &[usize], e: usize| {
            let h = helper[e];
            (h != usize::MAX && kind[h] == Kind::Merge).then_some(h)
        };
        match kind[v] {
            Kind::Start => {
                insert(&mut status, v, v);
                helper[v] = v;
            }
            Kind::End => {
                if let Some(h) = merge_helper(&helper, before) {
                    diagonals.push((v, h));
                }
                remove(&mut status, before, v)?;
            }
            Kind::Split => {
                let e = left_edge(&status, v)?;
                diagonals.push((v, helper[e]));
                helper[e] = v;
                insert(&mut status, v, v);
                helper[v] = v;
            }
            Kind::Merge => {
                if let Some(h) = merge_helper(&helper, before) {
                    diagonals.push((v, h));
                }
                remove(&mut status, before, v)?;
                let e = left_edge(&status, v)?;
                if let Some(h) = merge_helper(&helper, e) {
                    diagonals.push((v, h));
                }
                helper[e] = v;
            }
            Kind::Regular if above(c, before, v) => {
                // On the left chain: the interior is to the right of v.
                if let Some(h) = merge_helper(&helper, before) {
                    diagonals.push((v, h));
                }
                remove(&mut status, before, v)?;
                insert(&mut status, v, v);
                helper[v] = v;
            }
            Kind::Regular => {
                let e = left_edge(&status, v)?;
                if let Some(h) = merge_helper(&helper, e) {
                    diagonals.push((v, h));
                }
                helper[e] = v;
            }
        }
    }
    Some(diagonals)
}

/// Whether direction `a` comes before direction `b` counter-clockwise from direction `r`.
fn ccw_before<S: Scalar>(r: &Point<S>, a: &Point<S>, b: &Point<S>) -> bool {
    let cross = |u: &Point<S>, w: &Point<S>| {
        let z = [S::zero(), S::zero()];
        orient(&z, u, w)
    };
    let dot = |u: &Point<S>, w: &Point<S>| {
        (u[0].clone() * w[0].clone() + u[1].clone() * w[1].clone()).sign()
    };
    // 0 for angles in [0, π) from r, 1 for [π, 2π).
    let half = |u: &Point<S>| match cross(r, u) {
        Ordering::Greater => 0,
        Ordering::Equal if dot(r, u) == Ordering::Greater => 0,
        _ => 1,
    };
    match half(a).cmp(&half(b)) {
        Ordering::Less => true,
        Ordering::Greater => false,
        Ordering::Equal => cross(a, b) == Ordering::Greater,
    }
}

/// The pieces of the polygon cut along `diagonals`, each as its corner indices counter-clockwise;
/// `None` if the walk around a piece does not close (diagonals that cross: not a simple polygon).
fn pieces<S: Scalar>(c: &[Point<S>], diagonals: &[(usize, usize)]) -> Option<Vec<Vec<usize>>> {
    let k = c.len();
    let dir = |from: usize, to: usize| super::sub(&c[to], &c[from]);
    // Neighbours of each corner counter-clockwise inside the polygon: next, diagonals, prev.
    let mut extra: Vec<Vec<usize>> = vec![Vec::new(); k];
    for &(a, b) in diagonals {
        extra[a].push(b);
        extra[b].push(a);
    }
    let mut around: Vec<Vec<usize>> = Vec::with_capacity(k);
    for (v, mut d) in extra.into_iter().enumerate() {
        let r = dir(v, (v + 1) % k);
        d.sort_by(|&a, &b| {
            if a == b {
                Ordering::Equal
            } else if ccw_before(&r, &dir(v, a), &dir(v, b)) {
                Ordering::Less
            } else {
                Ordering::Greater
            }
        });
        let mut list = vec![(v + 1) % k];
        list.extend(d);
        list.push((v + k - 1) % k);
        around.push(list);
    }
    let mut index: HashMap<(usize, usize), usize> = HashMap::new();
    for (v, list) in around.iter().enumerate() {
        for (n, &w) in list.iter().enumerate() {
            index.insert((v, w), n);
        }
    }
    // Half-edge u → w (interior on its left) continues with w → the neighbour of w just
    // clockwise of u.
    let half_edges = k + 2 * diagonals.len();
    let mut used: HashMap<(usize, usize), ()> = HashMap::new();
    let mut out = Vec::new();
    let starts = (0..k)
        .map(|v| (v, (v + 1) % k))
        .chain(diagonals.iter().flat_map(|&(a, b)| [(a, b), (b, a)]));
    for (u0, w0) in starts {
        if used.contains_key(&(u0, w0)) {
            continue;
        }
        let mut piece = Vec::new();
        let (mut u, mut w) = (u0, w0);
        loop {
            if used.insert((u, w), ()).is_some() || piece.len() > half_edges {
                return None;
            }
            piece.push(u);
            let at = index.get(&(w, u))?.checked_sub(1)?;
            (u, w) = (w, around[w][at]);
            if (u, w) == (u0, w0) {
                break;
            }
        }
        out.push(piece);
    }
    Some(out)
}

/// Cuts a y-monotone counter-clockwise polygon (corner indices `piece` into `c`) into triangles
/// (TRIANGULATEMONOTONEPOLYGON), appended to `out` counter-clockwise. Returns false if a
/// triangle would be flat (the piece is not monotone or not simple).
fn triangulate_monotone<S: Scalar>(
    c: &[Point<S>],
    piece: &[usize],
    out: &mut Vec<[usize; 3]>,
) -> bool {
    let m = piece.len();
    let mut order: Vec<usize> = (0..m).collect();
    order.sort_by(|&a, &b| sweep_order(c, piece[a], piece[b]));
    let (top, bottom) = (order[0], order[m - 1]);
    // Counter-clockwise from the top runs down the left chain to the bottom.
    let mut left = vec![false; m];
    let mut i = top;
    while i != bottom {
        left[i] = true;
        i = (i + 1) % m;
    }
    let mut flat = false;
    let mut emit = |a: usize, b: usize, d: usize, out: &mut Vec<[usize; 3]>| {
        let (a, b, d) = (piece[a], piece[b], piece[d]);
        match orient(&c[a], &c[b], &c[d]) {
            Ordering::Greater => out.push([a, b, d]),
            Ordering::Less => out.push([a, d, b]),
            Ordering::Equal => flat = true,
        }
    };
    let mut stack = vec![order[0], order[1]];
    for &u in &order[2..m - 1] {
        let top_of_stack = *stack.last().unwrap_or(&order[0]);
        if left[u] != left[top_of_stack] {
            for w in stack.windows(2) {
                emit(u, w[0], w[1], out);
            }
            stack = vec![top_of_stack, u];
        } else {
            let mut last = stack.pop().unwrap_or(top_of_stack);
            while let Some(&t) = stack.last() {
                // Cut the triangle (t, last, u) off only if it is strictly counter-clockwise in
                // the polygon's order (the diagonal u–t then lies inside).
                let (a, b, d) = if left[u] { (t, last, u) } else { (u, last, t) };
                if orient(&c[piece[a]], &c[piece[b]], &c[piece[d]]) != Ordering::Greater {
                    break;
                }
                emit(a, b, d, out);
                last = t;
                stack.pop();
            }
            stack.push(last);
            stack.push(u);
        }
    }
    let u = order[m - 1];
    for w in stack.windows(2) {
        emit(u, w[0], w[1], out);
    }
    !flat
}

/// The triangles of a simple counter-clockwise polygon (corners in order, no two equal), as
/// counter-clockwise triples of corner indices, `n − 2` of them, none flat; `None` if the polygon
/// is not simple (the sweep or a piece fails). O(n log n) exact predicates (module doc).
pub fn triangulate_polygon<S: Scalar>(c: &[Point<S>]) -> Option<Vec<[usize; 3]>> {
    let k = c.len();
    if k < 3 {
        return None;
    }
    let mut order: Vec<usize> = (0..k).collect();
    order.sort_by(|&a, &b| sweep_order(c, a, b));
    let diagonals = monotone_diagonals(c, &order)?;
    let mut out = Vec::with_capacity(k - 2);
    for piece in pieces(c, &diagonals)? {
        if piece.len() < 3 || !triangulate_monotone(c, &piece, &mut out) {
            return None;
        }
    }
    (out.len() == k - 2).then_some(out)
}
