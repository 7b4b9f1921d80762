//! Whether a polygon is simple, in O(k log k) exact predicates: the sweep of M. I. Shamos and
//! D. Hoey, "Geometric intersection problems" (FOCS 1976), which decides whether any two of `k`
//! segments intersect by testing only the pairs that become neighbours on the sweep line (the
//! sweep of de Berg, Cheong, van Kreveld and Overmars, "Computational Geometry", 3rd ed.,
//! Section 2.1, stopped at the first intersection).
//!
//! The corners are met in the order of the polygon triangulation's sweep (`y` down, level corners
//! left to right: [`super::triangulate`]), so no two distinct corners are level. Where the paper
//! assumes general position: two sides of the polygon that are consecutive share a corner and are
//! not tested (the caller has refused consecutive sides folding back onto each other); two equal
//! corners are refused before the sweep (the sides starting at them meet there); at a corner `v`
//! the status splits into the sides passing strictly west of `v`, those through `v`, and those
//! strictly east (exact [`orient`] signs), and a side through `v` that does not end at `v` is an
//! intersection at once (a corner touching a side, or a collinear overlap). The status is a treap
//! (random priorities from the side index: deterministic) split and joined at the corner, so each
//! corner costs O(log k) orientation tests.

use super::triangulate::{side_ends, sweep_order};
use super::{Point, Scalar, orient, segments_intersect};
use std::cmp::Ordering;

const NIL: u32 = u32::MAX;

/// The sweep status: a sequence of sides, as a treap over the side indices (a node per side).
struct Status {
    left: Vec<u32>,
    right: Vec<u32>,
    priority: Vec<u64>,
}

impl Status {
    fn new(k: usize) -> Self {
        let priority = (0..k as u64)
            .map(|i| {
                // SplitMix64 of the index.
                let mut z = i.wrapping_add(1).wrapping_mul(0x9E37_79B9_7F4A_7C15);
                z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
                z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
                z ^ (z >> 31)
            })
            .collect();
        Status {
            left: vec![NIL; k],
            right: vec![NIL; k],
            priority,
        }
    }

    /// Splits the sequence `t` into the longest prefix whose sides satisfy `before` (which must
    /// hold on a prefix) and the rest.
    fn split(&mut self, t: u32, before: &impl Fn(usize) -> bool) -> (u32, u32) {
        if t == NIL {
            return (NIL, NIL);
        }
        let i = t as usize;
        if before(i) {
            let (a, b) = self.split(self.right[i], before);
            self.right[i] = a;
            (t, b)
        } else {
            let (a, b) = self.split(self.left[i], before);
            self.left[i] = b;
            (a, t)
        }
    }

    /// The sequence `a` followed by the sequence `b`.
    fn join(&mut self, a: u32, b: u32) -> u32 {
        if a == NIL {
            return b;
        }
        if b == NIL {
            return a;
        }
        if self.priority[a as usize] > self.priority[b as usize] {
            let r = self.join(self.right[a as usize], b);
            self.right[a as usize] = r;
            a
        } else {
            let l = self.join(a, self.left[b as usize]);
            self.left[b as usize] = l;
            b
        }
    }

    /// The first (`west`) or last side of the sequence `t`.
    fn end(&self, mut t: u32, west: bool) -> Option<usize> {
        if t == NIL {
            return None;
        }
        loop {
            let child = if west {
                self.left[t as usize]
            } else {
                self.right[t as usize]
            };
            if child == NIL {
                return Some(t as usize);
            }
            t = child;
        }
    }

    /// Appends the sides of the sequence `t` to `out`.
    fn collect(&self, t: u32, out: &mut Vec<usize>) {
        if t != NIL {
            self.collect(self.left[t as usize], out);
            out.push(t as usize);
            self.collect(self.right[t as usize], out);
        }
    }
}

/// Two sides of the counter-clockwise polygon `c` that intersect (closed segments) and are not
/// consecutive, as `(a, b)` with `a < b`; `None` if there are none. The caller guarantees at
/// least three corners, finite, no zero side, and no two consecutive sides folding back onto
/// each other, so `None` means the polygon is simple. O(k log k) exact predicates (module doc).
pub(crate) fn crossing_sides<S: Scalar>(c: &[Point<S>]) -> Option<(usize, usize)> {
    let k = c.len();
    let prev = |i: usize| (i + k - 1) % k;
    let pair = |a: usize, b: usize| (a.min(b), a.max(b));
    let consecutive = |a: usize, b: usize| a == (b + 1) % k || b == (a + 1) % k;
    let mut order: Vec<usize> = (0..k).collect();
    order.sort_by(|&a, &b| sweep_order(c, a, b));
    // Equal corners are neighbours in the order; the sides starting there meet at them (and are
    // not consecutive: no side is zero).
    if let Some(w) = order.windows(2).find(|w| c[w[0]] == c[w[1]]) {
        return Some(pair(w[0], w[1]));
    }
    let crossing = |a: Option<usize>, b: Option<usize>| match (a, b) {
        (Some(a), Some(b)) if !consecutive(a, b) => {
            let (p, q) = (&c[a], &c[(a + 1) % k]);
            segments_intersect(p, q, &c[b], &c[(b + 1) % k]).then(|| pair(a, b))
        }
        _ => None,
    };
    let mut status = Status::new(k);
    let mut root = NIL;
    let mut through = Vec::new();
    for &v in &order {
        // Where side `e` passes corner `v`: `Greater` strictly west of it.
        let side_of = |e: usize| {
            let (first, last) = side_ends(c, e);
            orient(&c[first], &c[last], &c[v])
        };
        let (west, rest) = status.split(root, &|e| side_of(e) == Ordering::Greater);
        let (at, east) = status.split(rest, &|e| side_of(e) == Ordering::Equal);
        through.clear();
        status.collect(at, &mut through);
        let sides = [prev(v), v];
        for &e in &through {
            if !sides.contains(&e) {
                // Corner `v` lies on side `e`, as on the sides at `v`.
                let s = if consecutive(e, v) { prev(v) } else { v };
                return Some(pair(e, s));
            }
        }
        let ending = |e: &usize| side_ends(c, *e).1 == v;
        if sides.iter().filter(|e| ending(e)).count() != through.len() {
            // A side ending at `v` not met at `v`: only after an intersection the sweep missed,
            // which the theorem excludes; named by the quadratic scan rather than trusted.
            return quadratic_crossing(c);
        }
        // The sides starting at `v` (one or two), west to east.
        let mut starting: Vec<usize> = sides.iter().copied().filter(|e| !ending(e)).collect();
        if let [a, b] = starting[..] {
            let ends = |e: usize| side_ends(c, e).1;
            if orient(&c[v], &c[ends(a)], &c[ends(b)]) == Ordering::Less {
                starting.swap(0, 1);
            }
        }
        let mut middle = NIL;
        for &e in &starting {
            middle = status.join(middle, e as u32);
        }
        let (w, e) = (status.end(west, false), status.end(east, true));
        let found = if middle == NIL {
            crossing(w, e)
        } else {
            crossing(w, status.end(middle, true)).or(crossing(status.end(middle, false), e))
        };
        if found.is_some() {
            return found;
        }
        let joined = status.join(west, middle);
        root = status.join(joined, east);
    }
    None
}

/// Every pair of non-consecutive sides, in index order: the first that intersect (the fallback
/// of [`crossing_sides`]).
fn quadratic_crossing<S: Scalar>(c: &[Point<S>]) -> Option<(usize, usize)> {
    let k = c.len();
    (0..k).find_map(|a| {
        (a + 2..k)
            .filter(|&b| !(a == 0 && b == k - 1))
            .find(|&b| segments_intersect(&c[a], &c[(a + 1) % k], &c[b], &c[(b + 1) % k]))
            .map(|b| (a, b))
    })
}
