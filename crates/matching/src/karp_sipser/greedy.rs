//! Phase 2 of KS: the Karp–Sipser greedy (Karp and Sipser, "Maximum matchings in sparse random
//! graphs", FOCS 1981): while a free node has exactly one free neighbour, pair the two (such a
//! pair is in some maximum matching, so the rule never loses); otherwise pair a free node with a
//! free neighbour. The *free degree* of an unpaired triangle is its number of unpaired neighbours
//! (a triangle's "free edges" in the paper's Section 3.1). A node whose free degree drops to 0
//! while it is unpaired is *isolated* and goes to the repairs ([`super::repair`]) at once.
//!
//! Decisions:
//! - the start order is deterministic (no seed): when neighbouring nodes have close ids (90% of
//!   the id gaps of a sample at most [`LOCAL_ID_GAP`]: files written along a sweep), increasing
//!   id order; otherwise breadth-first order (the oldest free neighbour of a paired node first,
//!   then the smallest free id). Either way the pairing advances along a front, where the free
//!   nodes needed by the repairs are near; breadth-first order isolates far fewer triangles on
//!   files in strips or in no spatial order, id order reaches fewer nodes on files written
//!   along a sweep;
//! - a started node is paired with its neighbour of smallest free degree, the "minimum degree"
//!   rule of Magun (1998) that keeps few nodes isolated;
//! - ties go to the side already swept, so the front leaves no gaps behind and, on the
//!   (near-)bipartite duals of regular meshes, pairs coherently, without seams of same-coloured
//!   triangles that only long paths can pair: in id order the neighbour of smallest id (or
//!   largest, once the sweep runs down); in breadth-first order the neighbour the front met
//!   first;
//! - degree-one nodes are paired as soon as they appear (a stack), before the next start;
//! - in breadth-first order the starts ahead on the frontier are loaded into cache early
//!   ([`Greedy::prefetch_ahead`]), since the frontier is known in advance;
//! - in id order, a deferred node that is the only unpaired one behind the sweep, met in the last
//!   [`REVERSE_TAIL`]th of the ids, reverses the sweep, so that the sweep ends next to it, where
//!   its partner will be isolated ([`IdSweep`] says why).

use prefetch_index::prefetch_index;

use super::repair::Repairs;
use super::{PAIRED, Pairs};
use crate::augment::PREFETCH_AHEAD;
use crate::dual_graph::DualGraph;

/// Node ids are *local* when 90% of the id distances between neighbours (sampled) are at most
/// this.
const LOCAL_ID_GAP: u32 = 2048;

/// A lone deferred node reverses the id sweep (see [`IdSweep`]) only when less than
/// `1 / REVERSE_TAIL` of the ids are left to sweep.
const REVERSE_TAIL: usize = 4;

/// [`Greedy::seen`] of a node the front has not met.
const UNSEEN: u32 = u32::MAX;

/// Whether neighbouring nodes have close ids: the 90th percentile of `|v - w|` over the
/// neighbours `w` of every 31st node `v` is at most [`LOCAL_ID_GAP`] (a prime stride: a stride of
/// 64 falls in step with periodic face orders and samples one kind of neighbour only).
fn ids_are_local<G: DualGraph + ?Sized>(graph: &G) -> bool {
    let mut gaps: Vec<u32> = (0..graph.node_slots() as u32)
        .step_by(31)
        .filter(|&v| graph.is_node(v))
        .flat_map(|v| graph.adjacent(v).map(|(_, w)| w.abs_diff(v)))
        .collect();
    if gaps.is_empty() {
        return true;
    }
    let p90 = gaps.len() * 9 / 10;
    *gaps.select_nth_unstable(p90).1 <= LOCAL_ID_GAP
}

/// The greedy's own state: the order of its starts and the nodes waiting for it.
pub(super) struct Greedy {
    /// Unpaired nodes of free degree 1 (checked again when popped).
    forced: Vec<u32>,
    /// Unpaired nodes of free degree 0 not yet repaired.
    isolated: Vec<u32>,
    /// Isolated nodes whose repair went over budget (or was skipped).
    deferred: Vec<u32>,
    /// Free neighbours of newly paired nodes, in order (the breadth-first start order).
    frontier: Vec<u32>,
    /// Start from the nodes in id order rather than from the frontier.
    id_order: bool,
    /// In breadth-first order: per node slot, when the front first met it (its first push on
    /// the frontier, or its start), [`UNSEEN`] before; the greedy's tie key. Empty in id order.
    seen: Vec<u32>,
    /// The next `seen` stamp.
    seen_next: u32,
    /// The ids not considered yet as start nodes.
    sweep: IdSweep,
}

/// The ids not considered yet as start nodes, `low..high`, taken from the low end, or from the
/// high end once `descending`.
///
/// Why reverse: in id order, a node deferred near the end of the sweep while no other deferred
/// node is unpaired needs a partner, and by parity the last node isolated by the greedy is one;
/// it appears where the sweep ends. Swept upwards, the rest ends at the top ids, far from the
/// deferred node; swept downwards, it ends next to it, where the sweep is now. Reversing at
/// every deferral, or at any point of the sweep, makes other files worse (more deferrals, more
/// nodes reached).
#[derive(Clone, Copy, Debug)]
struct IdSweep {
    low: u32,
    high: u32,
    descending: bool,
}

impl IdSweep {
    fn next(&mut self) -> Option<u32> {
        if self.low == self.high {
            None
        } else if self.descending {
            self.high -= 1;
            Some(self.high)
        } else {
            self.low += 1;
            Some(self.low - 1)
        }
    }

    /// How many ids are left.
    fn left(&self) -> u32 {
        self.high - self.low
    }
}

impl Greedy {
    /// Nothing started: the start order is chosen from `graph`'s ids.
    pub(super) fn new<G: DualGraph + ?Sized>(graph: &G) -> Self {
        let n = graph.node_slots();
        let id_order = ids_are_local(graph);
        Greedy {
            forced: Vec::new(),
            isolated: Vec::new(),
            deferred: Vec::new(),
            frontier: Vec::new(),
            id_order,
            seen: if id_order {
                Vec::new()
            } else {
                vec![UNSEEN; n]
            },
            seen_next: 0,
            sweep: IdSweep {
                low: 0,
                high: n as u32,
                descending: false,
            },
        }
    }

    /// The nodes deferred by the repairs (some of them paired since, as the free end of a later
    /// repair).
    pub(super) fn into_deferred(self) -> Vec<u32> {
        self.deferred
    }

    /// Before a run on a graph that is not cubic (the dual of a surface with boundary): the
    /// nodes of free degree 1 are forced from the start (Karp and Sipser's rule), and those of
    /// free degree 0, which no path reaches, count as stranded (never repaired, never deferred:
    /// they stay unpaired).
    pub(super) fn seed_low_degrees<G: DualGraph + ?Sized>(&mut self, pairs: &mut Pairs<G>) {
        // The degree first: most nodes have two or three neighbours, and only the others need
        // the test of a live slot (a removed slot has degree 0).
        for (v, &degree) in pairs.free.iter().enumerate() {
            if degree > 1 || !pairs.graph.is_node(v as u32) {
                continue;
            }
            if degree == 0 {
                pairs.stranded += 1;
            } else {
                self.forced.push(v as u32);
            }
        }
        // The forced stack is taken from its top: the lowest ids first.
        self.forced.reverse();
    }

    /// Pairs every node it can, repairing the isolated ones as they appear; records whether it
    /// swept in id order.
    pub(super) fn run<G: DualGraph + ?Sized>(
        &mut self,
        pairs: &mut Pairs<G>,
        repairs: &mut Repairs,
    ) {
        if !self.forced.is_empty() {
            self.drain(pairs, repairs);
        }
        let mut head = 0;
        // A cooperative stop (Ctrl-C from Python) is read every few thousand starts and pairs.
        let mut ticker = surftopo_mesh::stop::Ticker::default();
        while let Some(s) = self.next_start(pairs, &mut head) {
            ticker.tick();
            let mut best: Option<(u8, u32, u32, u32)> = None;
            // Ties: the side already swept. In id order the smallest id, or the largest once
            // the sweep runs down; in breadth-first order the node the front met first.
            let flip = if self.sweep.descending { u32::MAX } else { 0 };
            for (e, w) in pairs.graph.adjacent(s) {
                if w != s && pairs.is_free(w) {
                    let d = pairs.free[w as usize];
                    let tie = if self.id_order {
                        w ^ flip
                    } else {
                        self.seen[w as usize]
                    };
                    if best.is_none_or(|(b, bt, _, _)| (d, tie) < (b, bt)) {
                        best = Some((d, tie, e, w));
                    }
                }
            }
            // A start node has a free neighbour (a node whose free degree drops to 0 is isolated,
            // never started from).
            debug_assert!(best.is_some(), "start node {s} has no free neighbour");
            if let Some((_, _, e, w)) = best {
                self.join(pairs, e, s, w);
            }
            self.drain(pairs, repairs);
        }
        pairs.stats.id_order = self.id_order;
    }

    /// The next node to start from, free and with a free neighbour: the oldest such frontier
    /// node (breadth-first order; the frontier stays empty in id order), else the next such id
    /// of the [`IdSweep`].
    fn next_start<G: DualGraph + ?Sized>(
        &mut self,
        pairs: &Pairs<G>,
        head: &mut usize,
    ) -> Option<u32> {
        while let Some(&x) = self.frontier.get(*head) {
            self.prefetch_ahead(pairs, *head);
            *head += 1;
            if pairs.is_free(x) && pairs.free[x as usize] > 0 {
                return Some(x);
            }
        }
        // A removed node slot has free degree 0.
        while let Some(v) = self.sweep.next() {
            if pairs.is_free(v) && pairs.free[v as usize] > 0 {
                self.mark_seen(v);
                return Some(v);
            }
        }
        None
    }

    /// Starts loading what the starts ahead of frontier position `head` will read (breadth-first
    /// order, on a flat graph), as the augmenting searches do with their queue
    /// ([`PREFETCH_AHEAD`]): the adjacency and free degree of the node that many places ahead,
    /// the free degrees and front stamps of the neighbours of the node half as far. Without it
    /// each start waits for its neighbours' reads when the ids are not spatially ordered.
    #[inline]
    fn prefetch_ahead<G: DualGraph + ?Sized>(&self, pairs: &Pairs<G>, head: usize) {
        let Some(adjacency) = pairs.graph.flat_adjacency() else {
            return;
        };
        if let Some(&far) = self.frontier.get(head + PREFETCH_AHEAD) {
            prefetch_index(adjacency, far as usize);
            prefetch_index(&pairs.free, far as usize);
        }
        if let Some(&near) = self.frontier.get(head + PREFETCH_AHEAD / 2) {
            for (_, w) in adjacency[near as usize] {
                prefetch_index(&pairs.free, w as usize);
                prefetch_index(&self.seen, w as usize);
            }
        }
    }

    /// Stamps `v` as met by the front now, unless it was met before (breadth-first order only).
    #[inline]
    fn mark_seen(&mut self, v: u32) {
        if let Some(stamp) = self.seen.get_mut(v as usize)
            && *stamp == UNSEEN
        {
            *stamp = self.seen_next;
            self.seen_next += 1;
        }
    }

    /// After a deferral in id order: when the deferred node is the only unpaired one behind
    /// the sweep and less than `1 / REVERSE_TAIL` of the ids are left, the rest is swept in the
    /// other direction (see [`IdSweep`]).
    fn reverse_for_lone_hole<G: DualGraph + ?Sized>(&mut self, pairs: &mut Pairs<G>) {
        let left = self.sweep.left() as usize;
        if self.id_order
            && left * REVERSE_TAIL < pairs.graph.node_slots()
            && self
                .deferred
                .iter()
                .filter(|&&v| pairs.is_free(v))
                .take(2)
                .count()
                == 1
        {
            self.sweep.descending = !self.sweep.descending;
            pairs.stats.reversals += 1;
        }
    }

    /// Pairs the forced nodes and repairs the isolated ones until neither is left.
    fn drain<G: DualGraph + ?Sized>(&mut self, pairs: &mut Pairs<G>, repairs: &mut Repairs) {
        let mut ticker = surftopo_mesh::stop::Ticker::default();
        loop {
            ticker.tick();
            if let Some(a) = self.forced.pop() {
                if pairs.free[a as usize] != 1 {
                    continue;
                }
                let (e, b) = pairs
                    .graph
                    .adjacent(a)
                    .into_iter()
                    .find(|&(_, b)| b != a && pairs.is_free(b))
                    .expect("a node of free degree 1 has a free neighbour");
                self.join(pairs, e, a, b);
            } else if let Some(u) = self.isolated.pop() {
                if pairs.is_free(u) {
                    self.repair(pairs, repairs, u);
                }
            } else {
                return;
            }
        }
    }

    /// Repairs isolated node `u` ([`Repairs::repair`]): on success the free node at the other end
    /// of the path is now paired too (the nodes inside the path stay paired), else `u` is
    /// deferred to the completion.
    fn repair<G: DualGraph + ?Sized>(
        &mut self,
        pairs: &mut Pairs<G>,
        repairs: &mut Repairs,
        u: u32,
    ) {
        let clock = std::time::Instant::now();
        if let Some(other) = repairs.repair(pairs, u) {
            pairs.stats.augmentation_seconds += clock.elapsed().as_secs_f64();
            self.path_applied(pairs, u, other);
        } else {
            self.deferred.push(u);
            pairs.stats.deferred += 1;
            self.reverse_for_lone_hole(pairs);
            pairs.stats.augmentation_seconds += clock.elapsed().as_secs_f64();
        }
    }

    /// An augmenting path from isolated `u` to free `other` was applied: both are paired now.
    fn path_applied<G: DualGraph + ?Sized>(&mut self, pairs: &mut Pairs<G>, u: u32, other: u32) {
        pairs.unpaired -= 2;
        pairs.stranded -= 1 + usize::from(pairs.free[other as usize] == 0);
        pairs.free[u as usize] = PAIRED;
        pairs.free[other as usize] = PAIRED;
        self.now_paired(pairs, other);
    }

    /// Pairs free nodes `a` and `b` along edge `e`.
    fn join<G: DualGraph + ?Sized>(&mut self, pairs: &mut Pairs<G>, e: u32, a: u32, b: u32) {
        pairs.unpaired -= 2;
        pairs.mates[a as usize] = [e, b];
        pairs.mates[b as usize] = [e, a];
        pairs.free[a as usize] = PAIRED;
        pairs.free[b as usize] = PAIRED;
        self.now_paired(pairs, a);
        self.now_paired(pairs, b);
    }

    /// `x` was free and is now paired: its free neighbours lose a free edge.
    fn now_paired<G: DualGraph + ?Sized>(&mut self, pairs: &mut Pairs<G>, x: u32) {
        for (_, y) in pairs.graph.adjacent(x) {
            if y != x && pairs.is_free(y) {
                if !self.id_order {
                    self.frontier.push(y);
                    self.mark_seen(y);
                }
                let f = &mut pairs.free[y as usize];
                *f -= 1;
                match *f {
                    1 => self.forced.push(y),
                    0 => {
                        pairs.stranded += 1;
                        self.isolated.push(y);
                    }
                    _ => {}
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dual_graph::CompactDual;
    use surftopo_mesh::generators::icosphere;

    #[test]
    fn id_sweep_takes_ids_from_either_end() {
        let mut sweep = IdSweep {
            low: 0,
            high: 6,
            descending: false,
        };
        let mut taken = vec![sweep.next(), sweep.next()];
        sweep.descending = true;
        taken.extend([sweep.next(), sweep.next()]);
        assert_eq!(sweep.left(), 2);
        sweep.descending = false;
        taken.extend([sweep.next(), sweep.next(), sweep.next()]);
        let expected = [0, 1, 5, 4, 2, 3].map(Some).to_vec();
        assert_eq!(taken, [expected, vec![None]].concat());
    }

    /// The sweep reverses for a deferred node only in id order, in the tail of the sweep, and
    /// when no other deferred node is unpaired.
    #[test]
    fn a_lone_hole_in_the_tail_reverses_the_sweep() {
        let mesh = icosphere(3).mesh;
        let graph = CompactDual::new(&mesh);
        let n = graph.node_slots() as u32;
        let state = |id_order: bool, left: u32, holes: &[u32]| {
            let mut pairs = Pairs::new(&graph, vec![3; n as usize]);
            let mut greedy = Greedy::new(&graph);
            greedy.id_order = id_order;
            greedy.sweep.low = n - left;
            for v in 0..n {
                if !holes.contains(&v) {
                    pairs.free[v as usize] = PAIRED;
                }
            }
            greedy.deferred = holes.to_vec();
            greedy.reverse_for_lone_hole(&mut pairs);
            (greedy.sweep.descending, pairs.stats.reversals)
        };
        let tail = n / (2 * REVERSE_TAIL as u32);
        assert_eq!(state(true, tail, &[7]), (true, 1));
        assert_eq!(state(true, tail, &[7, 9]), (false, 0));
        assert_eq!(state(true, n / 2, &[7]), (false, 0));
        assert_eq!(state(false, tail, &[7]), (false, 0));
        // A deferred node paired since does not count.
        let mut pairs = Pairs::new(&graph, vec![3; n as usize]);
        let mut greedy = Greedy::new(&graph);
        greedy.id_order = true;
        greedy.sweep.low = n - tail;
        greedy.deferred = vec![7, 9];
        pairs.free.fill(PAIRED);
        pairs.free[9] = 0;
        greedy.reverse_for_lone_hole(&mut pairs);
        assert!(greedy.sweep.descending);
    }

    /// After the greedy and its repairs, the matching is consistent with the free degrees and
    /// the count of unpaired nodes, and every unpaired node was deferred.
    #[test]
    fn the_greedy_leaves_a_consistent_matching() {
        for subdivisions in [2, 3] {
            let mesh = icosphere(subdivisions).mesh;
            let (graph, degrees) = CompactDual::with_degrees(&mesh);
            for budget in [0, super::super::REPAIR_BUDGET] {
                let mut pairs = Pairs::new(&graph, degrees.clone());
                let mut greedy = Greedy::new(&graph);
                let mut repairs = Repairs::new(graph.node_slots(), budget);
                greedy.run(&mut pairs, &mut repairs);
                pairs.check_invariants().unwrap();
                let deferred = greedy.into_deferred();
                for v in 0..graph.node_slots() as u32 {
                    assert!(!pairs.is_free(v) || deferred.contains(&v), "node {v}");
                }
            }
        }
    }
}
