//! Perfect matching of a connected, bridgeless, 3-regular multigraph by Frink's reductions, after
//! Diks and Stanczyk, "Perfect matching for biconnected cubic graphs in O(n log² n) time", SOFSEM
//! 2010 (LNCS 5901) — reference \[23\] of the quadrangulation paper
//! (`tri-quad-conversion-long.txt`, Section 3.2 and Appendix A) — building on Biedl, Bose,
//! Demaine and Lubiw, "Efficient algorithms for Petersen's matching theorem", J. Algorithms 38(1)
//! 2001 (reference \[24\]), and on the dynamic connectivity of Holm, de Lichtenberg and Thorup,
//! J. ACM 48(4) 2001.
//!
//! # Frink's reduction (Appendix A)
//! Let `e = {u, v}` be a simple edge of the current graph `H`, `x1, x2` the other neighbours of
//! `u` (through edges `u x1`, `u x2`) and `x3, x4` those of `v`. Removing `u`, `v` and their five
//! edges gives `H'`; adding `{x1 x3, x2 x4}` gives `H1`, adding `{x1 x4, x2 x3}` gives `H2`. Both
//! are cubic and at least one is connected and bridgeless (Frink 1926). A perfect matching `M'` of
//! the reduced graph lifts to `H` in O(1): if neither new edge is in `M'`, add `e`; if the new
//! edge `x1 x_k` is, replace it by `u x1, v x_k`; if the other one is, likewise. Case (iv), both
//! new edges matched, would need an alternating cycle; Biedl et al. avoid it by carrying an edge
//! `f` that the final matching must avoid and reducing next to it: `f = u x1`, and the new edge at
//! `x1` becomes the next `f`. Since `f ∉ M'` at every level, case (iv) never occurs and the lifted
//! matching never contains `u x1`. The recursion (depth `n/2`) is run as a loop that pushes one
//! 7-word record per reduction; the records are then unwound in reverse to lift the matching.
//!
//! # Which of H1, H2 (Diks–Stanczyk's use of connectivity and dynamic trees)
//! The choice is made on `H'` with [`DynamicConnectivity`]: fully dynamic connectivity (HDT)
//! and its spanning forest `F` mirrored in link-cut trees. The rule, with its proof as
//! reconstructed here (only the outline of Diks and Stanczyk's argument is public):
//!
//! 1. *`H'` disconnected* (`x1`, `x2` not connected). Every component `C` of `H'` has
//!    `|δ_H(C)| >= 2` ports, and a component holding both `x1, x2` would make `e` a bridge; so
//!    `H'` has two components, each with one port of `u` and one of `v`. Take the pairing whose
//!    new edges cross between them (`H2` if `x1` and `x3` are connected, else `H1`); the other
//!    one is disconnected. The chosen one is bridgeless: a bridge of a component that separates
//!    its two ports lies on a cycle through both new edges, and one with both ports on the same
//!    side would leave the other side attached to `H` by that edge alone.
//! 2. *`H'` connected*. A cut of `H1` of size 1 must be a cut of size 1 of `H'` (a bridge `g`)
//!    crossed by no new edge, i.e. `g` separates `{x1, x3}` from `{x2, x4}` (all four on one
//!    side would make `g` a bridge of `H`). Such a bridge lies on every spanning tree, so the
//!    tree paths `x1..x3` and `x2..x4` of `F` are then vertex-disjoint. Hence: if those paths
//!    meet, `H1` is bridgeless; otherwise the four ports are split `{x1,x3} | {x2,x4}` by the
//!    tree, no tree edge separates `{x1,x4}` from `{x2,x3}`, so no bridge of `H'` does and `H2`
//!    is bridgeless. One `evert` and two LCA queries decide it.
//!
//! The same rule also never creates a loop (a loop `x1 x3` makes the pairing that holds it the
//! rejected one). Maintaining `H'` costs five deletions and two insertions per reduction.
//!
//! # Reconstruction decisions (what Appendix A leaves open)
//! * The H1/H2 test above (connectivity, then tree-path intersection) is our reconstruction of
//!   Diks and Stanczyk's "dynamic connectivity plus dynamic trees with evert and LCA".
//! * The initial avoided edge `f` is edge 0 ([`diks_stanczyk`]) or the caller's
//!   ([`diks_stanczyk_avoiding`]). The reduction edge is the first of the two other edges at
//!   `f`'s first endpoint, in incidence order, that is simple; then the same at its second
//!   endpoint.
//! * When both endpoints of `f = a b` have their two other edges forming a digon (`a = c`,
//!   `b = d`), no simple edge touches `f`. We then reduce the simple third edge `c z` of the
//!   digon partner `c` (with `u = c`, `x1 = x2 = a`): `f` is untouched and stays the avoided
//!   edge, and both new edges meet at `a`, so case (iv) cannot occur there either. Counted in
//!   [`DsStats::digon_reductions`].
//! * When both `H1` and `H2` are bridgeless, `H1` is taken.
//! * Base case: the theta graph left on `f`'s two endpoints; the first of its two edges other
//!   than `f` (in incidence order) is matched.
//! * Lifting looks at the new edge holding `x1` first; the two new edges are never both matched
//!   (checked in debug builds).
//! * New edges get ids after the input's (`m, m+1, …`); each node keeps its three incident edge
//!   ids in slots, the new edge taking the slot of the edge it replaces. The result is reported
//!   on the input's edge ids only.
//! * The five edges are deleted non-forest edges first (O(1) each, and they can then never be
//!   picked as replacements only to be deleted next), then the forest edges in the order
//!   `u x1, u x2, v x3, v x4, e`, so that the last deletions isolate `u` and `v` with trivial
//!   searches: fewer forest-edge deletions per reduction (the search work itself is dominated by
//!   HDT's level promotions either way).
//! * The dynamic structure is built in O(n) from a depth-first spanning forest instead of by `m`
//!   insertions.
//! * The result is checked by the independent verifier ([`verify_perfect_pairing`], O(n)) before
//!   it is returned; a failure there is an internal bug and panics.
//!
//! # Complexity
//! `n/2 - 1` reductions, each with O(1) updates (amortized O(log² n), HDT) and O(1) queries
//! (amortized O(log n)), then O(n) lifting: **O(n log² n) amortized total**, deterministic,
//! O(n) memory (plus O(1) per level reached by an edge). This is the bound of Diks and Stanczyk;
//! Biedl et al.'s version with fully dynamic 2-edge-connectivity is O(n log⁴ n).
//! `examples/ds_doubling.rs` measures the growth on doubling sizes (time over `n log² n` and over
//! `n²`, forest deletions and level promotions per reduction); the constant is large (splay-tree
//! cache misses, about a kilobyte per node), which is why the quad pipeline runs DS on the smaller
//! inputs only in its tables.

use std::time::Instant;

use crate::cubic_graph::{CubicGraph, GraphError};
use crate::dual_graph::Pairing;
use crate::dynamic_connectivity::{DynamicConnectivity, DynamicStats};
use crate::verify::{PerfectPairing, verify_perfect_pairing};

/// Figures of one run of the Diks–Stanczyk algorithm.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DsStats {
    /// Frink reductions performed (`n/2 - 1`).
    pub reductions: u64,
    /// Reductions made beside a digon because no simple edge touched the avoided edge.
    pub digon_reductions: u64,
    /// Reductions where `H'` was disconnected.
    pub disconnected_cases: u64,
    /// Reductions that took `H2` (`x1 x4`, `x2 x3`).
    pub chose_h2: u64,
    /// Seconds to build the dynamic structure.
    pub build_seconds: f64,
    /// Seconds spent reducing.
    pub reduce_seconds: f64,
    /// Seconds spent lifting the matching back (and verifying it).
    pub lift_seconds: f64,
    /// Total seconds.
    pub seconds: f64,
    /// Work counters of the dynamic connectivity structure.
    pub dynamic: DynamicStats,
}

/// A perfect matching of `graph` by Frink's reductions (Diks–Stanczyk; see the module docs).
///
/// Takes any [`CubicGraph`] (connected, bridgeless, 3-regular, parallel edges allowed); returns a
/// verified perfect matching that avoids edge 0. Deterministic. O(n log² n) amortized time, O(n)
/// memory. No errors: the input type guarantees that a perfect matching exists (Petersen); a
/// panic would mean an internal bug.
pub fn diks_stanczyk(graph: &CubicGraph) -> PerfectPairing {
    diks_stanczyk_with_stats(graph).0
}

/// [`diks_stanczyk`] with its [`DsStats`].
pub fn diks_stanczyk_with_stats(graph: &CubicGraph) -> (PerfectPairing, DsStats) {
    run(graph, 0)
}

/// A perfect matching of `graph` that does not contain edge `avoid` (Biedl et al.: one always
/// exists), with its [`DsStats`]. Same algorithm and bounds as [`diks_stanczyk`].
///
/// # Errors
/// [`GraphError::EdgeOutOfRange`] if `avoid` is not an edge of `graph`.
pub fn diks_stanczyk_avoiding(
    graph: &CubicGraph,
    avoid: u32,
) -> Result<(PerfectPairing, DsStats), GraphError> {
    if avoid >= graph.edge_count() {
        return Err(GraphError::EdgeOutOfRange {
            edge: avoid,
            edge_count: graph.edge_count(),
        });
    }
    Ok(run(graph, avoid))
}

/// One reduction, enough to lift a matching: `[e, u x1, v x_k, x1 x_k, u x2, v x_l, x2 x_l]`.
type Record = [u32; 7];

struct Reducer {
    ends: Vec<[u32; 2]>,
    inc: Vec<[u32; 3]>,
    dc: DynamicConnectivity,
    records: Vec<Record>,
    stats: DsStats,
}

impl Reducer {
    #[inline]
    fn other(&self, e: u32, v: u32) -> u32 {
        let [a, b] = self.ends[e as usize];
        debug_assert!(a == v || b == v);
        if a == v { b } else { a }
    }

    /// The two edges at `v` other than `e` (by id).
    #[inline]
    fn others_at(&self, v: u32, e: u32) -> [u32; 2] {
        let s = self.inc[v as usize];
        if s[0] == e {
            [s[1], s[2]]
        } else if s[1] == e {
            [s[0], s[2]]
        } else {
            debug_assert_eq!(s[2], e, "edge {e} not at node {v}");
            [s[0], s[1]]
        }
    }

    /// A simple edge `e = u w` at endpoint `u` of `f`, other than `f`, with the remaining edge `h`.
    fn simple_edge_beside(&self, f: u32, u: u32) -> Option<(u32, u32)> {
        let x1 = self.other(f, u);
        let [g1, g2] = self.others_at(u, f);
        for (g, h) in [(g1, g2), (g2, g1)] {
            let w = self.other(g, u);
            if w != x1 && w != self.other(h, u) {
                return Some((g, h));
            }
        }
        None
    }

    fn replace_incidence(&mut self, x: u32, old: u32, new: u32) {
        let slots = &mut self.inc[x as usize];
        let k = slots
            .iter()
            .position(|&s| s == old)
            .expect("edge missing from its node's incidence");
        slots[k] = new;
    }

    /// Performs one reduction beside the avoided edge `f`; returns the next avoided edge.
    fn reduce(&mut self, f: u32) -> u32 {
        let [a, b] = self.ends[f as usize];
        let (u, e, ux1, ux2, f_moves) = if let Some((e, h)) = self.simple_edge_beside(f, a) {
            (a, e, f, h, true)
        } else if let Some((e, h)) = self.simple_edge_beside(f, b) {
            (b, e, f, h, true)
        } else {
            // Digons on both sides of f: reduce the third edge of a's digon partner c.
            let [g1, g2] = self.others_at(a, f);
            let c = self.other(g1, a);
            debug_assert_eq!(c, self.other(g2, a));
            let s = self.inc[c as usize];
            let h = *s
                .iter()
                .find(|&&x| x != g1 && x != g2)
                .expect("digon partner has a third edge");
            self.stats.digon_reductions += 1;
            (c, h, g1, g2, false)
        };
        let v = self.other(e, u);
        let [vx3, vx4] = self.others_at(v, e);
        let x1 = self.other(ux1, u);
        let x2 = self.other(ux2, u);
        let x3 = self.other(vx3, v);
        let x4 = self.other(vx4, v);
        debug_assert!(u != v && ![x1, x2, x3, x4].contains(&u) && ![x1, x2, x3, x4].contains(&v));

        let doomed = [ux1, ux2, vx3, vx4, e];
        for g in doomed {
            if !self.dc.is_tree_edge(g) {
                self.dc.delete_edge(g);
            }
        }
        for g in doomed {
            if self.dc.contains_edge(g) {
                self.dc.delete_edge(g);
            }
        }
        let take_h1 = if !self.dc.connected(x1, x2) {
            self.stats.disconnected_cases += 1;
            // Two components, {x1, x3 or x4} and {x2, the other}: pair across them.
            !self.dc.connected(x1, x3)
        } else {
            self.dc.tree_paths_intersect_connected(x1, x3, x2, x4)
        };
        let (vk, xk, vl, xl) = if take_h1 {
            (vx3, x3, vx4, x4)
        } else {
            self.stats.chose_h2 += 1;
            (vx4, x4, vx3, x3)
        };
        debug_assert!(x1 != xk && x2 != xl, "Frink's choice created a loop");
        let n1 = self.ends.len() as u32;
        let n2 = n1 + 1;
        self.ends.push([x1, xk]);
        self.ends.push([x2, xl]);
        self.replace_incidence(x1, ux1, n1);
        self.replace_incidence(xk, vk, n1);
        self.replace_incidence(x2, ux2, n2);
        self.replace_incidence(xl, vl, n2);
        self.dc.insert_edge(n1, x1, xk);
        self.dc.insert_edge(n2, x2, xl);
        self.records.push([e, ux1, vk, n1, ux2, vl, n2]);
        self.stats.reductions += 1;
        if f_moves { n1 } else { f }
    }
}

fn run(graph: &CubicGraph, avoid: u32) -> (PerfectPairing, DsStats) {
    let t0 = Instant::now();
    let n = graph.node_count() as usize;
    let m = graph.edge_count() as usize;
    let mut ends = Vec::with_capacity(m + n);
    ends.extend_from_slice(graph.edges());
    let inc: Vec<[u32; 3]> = (0..graph.node_count())
        .map(|v| graph.incident_edges(v))
        .collect();
    let dc = DynamicConnectivity::from_edges(graph.node_count(), graph.edges());
    let mut r = Reducer {
        ends,
        inc,
        dc,
        records: Vec::with_capacity(n / 2),
        stats: DsStats::default(),
    };
    r.stats.build_seconds = t0.elapsed().as_secs_f64();

    let t1 = Instant::now();
    let mut f = avoid;
    let mut alive = n;
    let mut ticker = surftopo_mesh::stop::Ticker::default();
    while alive > 2 {
        ticker.tick();
        f = r.reduce(f);
        alive -= 2;
    }
    r.stats.reduce_seconds = t1.elapsed().as_secs_f64();

    let t2 = Instant::now();
    // Base case: the theta graph on f's two endpoints; match one of the two edges other than f.
    let [p, _] = r.ends[f as usize];
    let base = r.others_at(p, f)[0];
    let mut matched = vec![false; r.ends.len()];
    matched[base as usize] = true;
    for &[e, a1, bk, n1, a2, bl, n2] in r.records.iter().rev() {
        if matched[n1 as usize] {
            debug_assert!(!matched[n2 as usize], "case (iv) of Frink's proof");
            matched[n1 as usize] = false;
            matched[a1 as usize] = true;
            matched[bk as usize] = true;
        } else if matched[n2 as usize] {
            matched[n2 as usize] = false;
            matched[a2 as usize] = true;
            matched[bl as usize] = true;
        } else {
            matched[e as usize] = true;
        }
    }
    debug_assert!(matched[m..].iter().all(|&x| !x));
    matched.truncate(m);
    debug_assert!(!matched[avoid as usize]);
    let matching = Pairing::from_edge_flags(graph, &matched)
        .map_err(|err| err.to_string())
        .and_then(|pairing| verify_perfect_pairing(graph, pairing).map_err(|err| err.to_string()))
        .expect("Diks–Stanczyk produced an invalid matching (internal bug)");
    r.stats.lift_seconds = t2.elapsed().as_secs_f64();
    r.stats.dynamic = r.dc.stats();
    r.stats.seconds = t0.elapsed().as_secs_f64();
    (matching, r.stats)
}
