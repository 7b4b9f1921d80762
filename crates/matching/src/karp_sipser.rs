//! A perfect pairing by the Karp–Sipser greedy with immediate local repairs (KS): not one of the
//! quadrangulation paper's algorithms, but the fastest way we found to a perfect pairing of a
//! mesh dual, built from the paper's own pieces (a greedy pairing completed by Edmonds'
//! augmenting paths, Section 3.1) and its closing suggestion (Section 5: search for augmenting
//! paths locally, where the unpaired triangles are).
//!
//! # The greedy
//! Karp and Sipser, "Maximum matchings in sparse random graphs" (FOCS 1981): while a free node
//! has exactly one free neighbour, pair the two (such a pair is in some maximum matching, so the
//! rule never loses); otherwise pair a free node with a free neighbour. The *free degree* of an
//! unpaired triangle is its number of unpaired neighbours (a triangle's "free edges" in the
//! paper's Section 3.1). Decisions:
//! - the start order is deterministic (no seed): when neighbouring nodes have close ids (90% of
//!   the id gaps of a sample at most [`LOCAL_ID_GAP`]: files written along a sweep, like venus,
//!   seahorse, sketched_brunnen, feline), increasing id order; otherwise breadth-first order
//!   (the oldest free neighbour of a paired node first, then the smallest free id). Either way
//!   the pairing advances along a front, where the free nodes needed by the repairs are near.
//!   Measured
//!   (`quad_profile`; the nodes reached by the repairs dominate the time): breadth-first order
//!   isolates 5–20x fewer triangles on files in strips (igea, nefertiti: median gap 1–60, 90th
//!   percentile 2,600–5,000) or in no spatial order (koala, hand1, skull, rolling_stage), and
//!   reaches 5–13x more nodes on venus and seahorse; on the bricks both orders isolate (almost)
//!   nothing;
//! - a started node is paired with its neighbour of smallest free degree, the "minimum degree"
//!   rule of Magun (1998) that keeps few nodes isolated; ties go to the neighbour of smallest
//!   id (in id order: the one on the side already swept, so the front leaves no gaps behind).
//!   Measured (nodes reached by the repairs, `quad_profile`): against the first neighbour in
//!   edge order, the bricks of groups A and B go from 3,000–8,000 isolated triangles to none at
//!   all, and the shared meshes of 100k+ faces reach 8% fewer nodes;
//! - degree-one nodes are paired as soon as they appear (a stack), before the next start.
//!
//! # The repairs
//! A node whose free degree drops to 0 while it is unpaired is *isolated*: the greedy alone would
//! leave it unpaired. It is repaired at once, while the part of the graph not yet reached by the
//! greedy is near, so that a short augmenting path to one of its free nodes usually exists:
//! 1. a depth-first alternating search with lookahead (Pothen and Fan's heuristic), blossoms
//!    ignored, at most [`DFS_BUDGET`] nodes: cheap, and enough for most repairs;
//! 2. else an Edmonds search from the node ([`crate::augment`], blossoms included) limited to
//!    the repair budget ([`REPAIR_BUDGET`] reached nodes by default).
//!
//! A repair that exceeds both budgets is abandoned and the node *deferred*; after the greedy,
//! the deferred nodes still unpaired are completed by the Forest strategy of [`crate::augment`],
//! as any greedy pairing is. So the result is always perfect (or an [`AugmentError`] proves
//! that the graph has no perfect matching).
//!
//! Figures are those of the paper's Table 4.3: the greedy counts as the initial pairing; every
//! repair and the final completion count as augmentation (timed separately); "unpaired" is the
//! number of isolated nodes met.
//!
//! Complexity: O(n) for the greedy and the repairs (each bounded), plus the completion (see
//! [`crate::augment`]). On the shared 100k–270k-face meshes the repairs leave 0–16 nodes, but
//! those are usually far apart, and their completion can reach two thirds of the graph (see
//! [`REPAIR_BUDGET`]): it is most of the time of KS on seahorse2_100K and koala. On the bricks
//! of groups A and B the greedy isolates at most one triangle.

use std::time::Instant;

use crate::augment::{AugmentError, AugmentStats, Outcome, Search, complete};
use crate::dual_graph::{CompactDual, DualGraph, NONE, Pairing, non_loop_degrees};

/// Nodes a repair's Edmonds search may reach before it is abandoned and its node deferred to the
/// final completion. Measured (`quad_profile`, nodes reached on seahorse, koala, feline,
/// rolling_stage, sketched_brunnen): 1024 reaches 395k in all, 8192 380k, no limit 423k. The
/// deferred nodes are few (0–16) but usually far apart, so the completion that pairs them reaches
/// most of the graph (45k–65k of the 73k–92k nodes of a 100k-face run); with no limit there is
/// nothing to complete, and seahorse, koala and rolling_stage reach 2–7x fewer nodes, but feline
/// and sketched_brunnen 2x more (some repairs must cross most of the graph).
pub const REPAIR_BUDGET: usize = 1024;

/// Nodes the depth-first first try of a repair may visit before the Edmonds search takes over.
/// Measured on the shared meshes of 100k+ faces and on the bricks A5 and B5 (`quad_profile`):
/// with 64, the repairs reach 10% more nodes on the shared meshes but 4x fewer on B5 (5.2M to
/// 1.35M), and a depth-first node costs less than an Edmonds one.
pub const DFS_BUDGET: usize = 64;

/// Node ids are *local* when 90% of the id distances between neighbours (sampled) are at most
/// this.
pub const LOCAL_ID_GAP: u32 = 2048;

/// Figures of one [`karp_sipser_perfect`] run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct KarpSipserStats {
    /// Seconds of the greedy itself (copying the adjacency included; repairs excluded).
    pub greedy_seconds: f64,
    /// Seconds of the repairs and of the final completion.
    pub augmentation_seconds: f64,
    /// Isolated nodes met by the greedy (what the greedy alone would leave unpaired).
    pub isolated: usize,
    /// Isolated nodes paired by a repair search within its budget.
    pub repaired: usize,
    /// Isolated nodes whose repair went over budget (deferred).
    pub deferred: usize,
    /// Deferred nodes still unpaired after the greedy, paired two by two by the completion (the
    /// others were reached as the free end of a later repair).
    pub completed: usize,
    /// Nodes reached by the completion (included in `augment.reached`).
    pub completion_reached: u64,
    /// Whether the greedy started from the nodes in id order (true) or in breadth-first order
    /// (false; see the module doc).
    pub id_order: bool,
    /// The searches of the repairs and of the completion (nodes reached, paths, ...).
    pub augment: AugmentStats,
}

/// KS: a perfect pairing of `graph` by the Karp–Sipser greedy with local repairs, completed by
/// augmenting paths (see the module doc). Deterministic.
///
/// Takes any [`DualGraph`] with an even number of nodes. Guarantees on success: a perfect
/// matching. O(n) plus the completion.
///
/// # Errors
/// [`AugmentError::NoAugmentingPath`] when the graph has no perfect matching;
/// [`AugmentError::OddNodeCount`] for an odd number of nodes.
pub fn karp_sipser_perfect<G: DualGraph + ?Sized>(
    graph: &G,
) -> Result<(Pairing, KarpSipserStats), AugmentError> {
    karp_sipser_perfect_with(graph, REPAIR_BUDGET)
}

/// [`karp_sipser_perfect`] with another repair budget (nodes the Edmonds search of a repair may
/// reach; 0 skips both searches and defers every isolated node to the completion).
///
/// # Errors
/// See [`karp_sipser_perfect`].
pub fn karp_sipser_perfect_with<G: DualGraph + ?Sized>(
    graph: &G,
    repair_budget: usize,
) -> Result<(Pairing, KarpSipserStats), AugmentError> {
    let start = Instant::now();
    let nodes = graph.node_count();
    if !nodes.is_multiple_of(2) {
        return Err(AugmentError::OddNodeCount { nodes });
    }
    let compact = CompactDual::new(graph);
    let mut ks = KarpSipser::new(&compact, repair_budget);
    ks.greedy();
    let mut stats = ks.stats;
    stats.id_order = ks.id_order;
    let deferred: Vec<u32> = ks
        .deferred
        .iter()
        .copied()
        .filter(|&v| ks.mates[v as usize][0] == NONE)
        .collect();
    stats.completed = deferred.len();
    if !deferred.is_empty() {
        let complete_start = Instant::now();
        let before = stats.augment.reached;
        complete(
            &compact,
            &mut ks.mates,
            ks.search
                .get_or_insert_with(|| Search::new(graph.node_slots())),
            deferred,
            &mut stats.augment,
        )?;
        stats.augmentation_seconds += complete_start.elapsed().as_secs_f64();
        stats.completion_reached = stats.augment.reached - before;
    }
    stats.greedy_seconds = start.elapsed().as_secs_f64() - stats.augmentation_seconds;
    let pairing = Pairing {
        mate: ks.mates.iter().map(|&[e, _]| e).collect(),
    };
    Ok((pairing, stats))
}

/// Whether neighbouring nodes have close ids: the 90th percentile of `|v - w|` over the
/// neighbours `w` of every 31st node `v` is at most [`LOCAL_ID_GAP`] (a prime stride: with 64,
/// the periodic face order of sketched_brunnen gave a 90th percentile of 6,272 instead of 15).
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

struct KarpSipser<'g, G: ?Sized> {
    graph: &'g G,
    /// `[mate edge, mate node]` per node slot (`NONE` when unpaired), as [`Search`] wants them.
    mates: Vec<[u32; 2]>,
    /// Free degree per node slot (valid while the node is unpaired).
    free: Vec<u8>,
    /// Unpaired nodes of free degree 1 (checked again when popped).
    forced: Vec<u32>,
    /// Unpaired nodes of free degree 0 not yet repaired.
    isolated: Vec<u32>,
    /// Isolated nodes whose repair went over budget.
    deferred: Vec<u32>,
    /// The Edmonds search state (O(n) memory), made at the first Edmonds repair: most runs
    /// never need it.
    search: Option<Search>,
    stats: KarpSipserStats,
    /// Free neighbours of newly paired nodes, in order (the breadth-first start order).
    frontier: Vec<u32>,
    /// Start from the nodes in id order rather than from the frontier.
    id_order: bool,
    /// Nodes a repair search may reach.
    repair_budget: usize,
    /// Generation stamps of the depth-first repairs (nodes visited by the current one).
    dfs_stamp: Vec<u32>,
    dfs_generation: u32,
    /// The current depth-first path: (even node, next neighbour slot, edge into the odd node
    /// before it).
    dfs_stack: Vec<(u32, u8, u32)>,
}

impl<'g, G: DualGraph + ?Sized> KarpSipser<'g, G> {
    fn new(graph: &'g G, repair_budget: usize) -> Self {
        let n = graph.node_slots();
        KarpSipser {
            graph,
            mates: vec![[NONE, NONE]; n],
            free: non_loop_degrees(graph),
            forced: Vec::new(),
            isolated: Vec::new(),
            deferred: Vec::new(),
            search: None,
            stats: KarpSipserStats::default(),
            frontier: Vec::new(),
            id_order: ids_are_local(graph),
            dfs_stamp: vec![0; n],
            dfs_generation: 0,
            dfs_stack: Vec::new(),
            repair_budget,
        }
    }

    #[inline]
    fn is_free(&self, v: u32) -> bool {
        self.mates[v as usize][0] == NONE
    }

    fn greedy(&mut self) {
        let mut head = 0;
        let mut next_id = 0;
        while let Some(s) = self.next_start(&mut head, &mut next_id) {
            let mut best: Option<(u8, u32, u32)> = None;
            for (e, w) in self.graph.adjacent(s) {
                if w != s && self.is_free(w) {
                    let d = self.free[w as usize];
                    if best.is_none_or(|(b, _, bw)| (d, w) < (b, bw)) {
                        best = Some((d, e, w));
                    }
                }
            }
            // A start node has a free neighbour (a node whose free degree drops to 0 is isolated,
            // never started from).
            debug_assert!(best.is_some(), "start node {s} has no free neighbour");
            if let Some((_, e, w)) = best {
                self.join(e, s, w);
            }
            self.drain();
        }
    }

    /// The next node to start from, free and with a free neighbour: the oldest such frontier
    /// node (breadth-first order; the frontier stays empty in id order), else the smallest such
    /// id not considered yet.
    fn next_start(&mut self, head: &mut usize, next_id: &mut u32) -> Option<u32> {
        while let Some(&x) = self.frontier.get(*head) {
            *head += 1;
            if self.is_free(x) && self.free[x as usize] > 0 {
                return Some(x);
            }
        }
        let n = self.graph.node_slots() as u32;
        while *next_id < n {
            let v = *next_id;
            *next_id += 1;
            if self.graph.is_node(v) && self.is_free(v) && self.free[v as usize] > 0 {
                return Some(v);
            }
        }
        None
    }

    /// Pairs the forced nodes and repairs the isolated ones until neither is left.
    fn drain(&mut self) {
        loop {
            if let Some(a) = self.forced.pop() {
                if !self.is_free(a) || self.free[a as usize] != 1 {
                    continue;
                }
                let (e, b) = self
                    .graph
                    .adjacent(a)
                    .into_iter()
                    .find(|&(_, b)| b != a && self.is_free(b))
                    .expect("a node of free degree 1 has a free neighbour");
                self.join(e, a, b);
            } else if let Some(u) = self.isolated.pop() {
                if self.is_free(u) {
                    self.repair(u);
                }
            } else {
                return;
            }
        }
    }

    /// Pairs free nodes `a` and `b` along edge `e`.
    fn join(&mut self, e: u32, a: u32, b: u32) {
        self.mates[a as usize] = [e, b];
        self.mates[b as usize] = [e, a];
        self.now_paired(a);
        self.now_paired(b);
    }

    /// `x` was free and is now paired: its free neighbours lose a free edge.
    fn now_paired(&mut self, x: u32) {
        for (_, y) in self.graph.adjacent(x) {
            if y != x && self.is_free(y) {
                if !self.id_order {
                    self.frontier.push(y);
                }
                let f = &mut self.free[y as usize];
                *f -= 1;
                match *f {
                    1 => self.forced.push(y),
                    0 => self.isolated.push(y),
                    _ => {}
                }
            }
        }
    }

    /// Depth-first alternating search from isolated `u` with lookahead (Pothen and Fan's
    /// heuristic for bipartite matching), without blossoms, visiting at most [`DFS_BUDGET`]
    /// nodes; on success augments and returns the free end. Each node is visited at most once,
    /// so the path found is simple and a valid augmenting path even though blossoms are ignored;
    /// a path that only a blossom would reveal is left to the Edmonds search.
    fn dfs_repair(&mut self, u: u32) -> Option<u32> {
        self.dfs_generation += 1;
        let generation = self.dfs_generation;
        self.dfs_stamp[u as usize] = generation;
        self.dfs_stack.clear();
        // (even node, next neighbour slot, edge into the odd node before it)
        self.dfs_stack.push((u, 0, NONE));
        let mut visited = 1usize;
        let found = 'search: loop {
            let &(v, slot, _) = self.dfs_stack.last()?;
            let adjacent = self.graph.adjacent(v);
            if slot == 0 {
                // Lookahead: a free neighbour ends the path at once.
                for (e, w) in adjacent {
                    if w != v && w != u && self.is_free(w) {
                        break 'search (e, w);
                    }
                }
            }
            if slot == 3 {
                self.dfs_stack.pop();
                continue;
            }
            self.dfs_stack.last_mut().expect("not empty").1 += 1;
            let (e, w) = adjacent[slot as usize];
            if w == v || self.dfs_stamp[w as usize] == generation || self.is_free(w) {
                continue;
            }
            let m = self.mates[w as usize][1];
            if self.dfs_stamp[m as usize] == generation {
                continue;
            }
            self.dfs_stamp[w as usize] = generation;
            self.dfs_stamp[m as usize] = generation;
            visited += 2;
            self.stats.augment.reached += 2;
            if visited > DFS_BUDGET {
                return None;
            }
            self.dfs_stack.push((m, 0, e));
        };
        // Augment along the stack: v_k - found, then each v_{i-1} - w_i.
        let (mut e, mut x) = found;
        let end = x;
        while let Some((v, _, e_in)) = self.dfs_stack.pop() {
            let old_mate = self.mates[v as usize][1];
            self.mates[v as usize] = [e, x];
            self.mates[x as usize] = [e, v];
            if v == u {
                break;
            }
            // The odd node before v is its old mate; it pairs with the previous even node.
            e = e_in;
            x = old_mate;
        }
        Some(end)
    }

    /// Repairs isolated node `u`: the depth-first search, else a bounded Edmonds search, else
    /// defers it. On success the free node at the other end of the path is now paired too (the
    /// nodes inside the path stay paired).
    fn repair(&mut self, u: u32) {
        let clock = Instant::now();
        self.stats.isolated += 1;
        if self.repair_budget > 0
            && let Some(other) = self.dfs_repair(u)
        {
            self.stats.repaired += 1;
            self.stats.augment.unmatched_before += 1;
            self.stats.augment.searches += 1;
            self.stats.augment.augmentations += 1;
            self.stats.augmentation_seconds += clock.elapsed().as_secs_f64();
            self.now_paired(other);
            return;
        }
        let stats = &mut self.stats.augment;
        stats.unmatched_before += 1;
        stats.searches += 1;
        let search = self
            .search
            .get_or_insert_with(|| Search::new(self.graph.node_slots()));
        let outcome = search.run(
            self.graph,
            &mut self.mates,
            &[u],
            self.repair_budget,
            false,
            stats,
        );
        stats.reached += search.reached as u64;
        match outcome {
            Outcome::Augmented => {
                self.stats.repaired += 1;
                let other = search.last_end;
                self.stats.augmentation_seconds += clock.elapsed().as_secs_f64();
                self.now_paired(other);
                return;
            }
            Outcome::OverBudget => stats.abandoned += 1,
            // No augmenting path from u at all: the completion reports it.
            Outcome::Exhausted => {}
        }
        self.deferred.push(u);
        self.stats.deferred += 1;
        self.stats.augmentation_seconds += clock.elapsed().as_secs_f64();
    }
}
