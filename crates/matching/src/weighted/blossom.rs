//! Edmonds' primal–dual blossom algorithm for a minimum-cost perfect matching (Edmonds 1965),
//! in the single-tree form of Kolmogorov's Blossom V (2009, Sections 3–4): exact, with the dual
//! solution as certificate ([`Certificate`]).
//!
//! # Formulation
//! The dual of the module [`super::certificate`]: one `y` per node and one `z ≥ 0` per blossom
//! (an odd set), the reduced cost of `e = uv` being `c_e − Σ_{S : |S ∩ {u,v}| = 1} y_S`, where the
//! sum runs over the node duals and the blossoms containing exactly one end (Blossom V's
//! "δ(S)" formulation). The solver keeps, per node `v`, `π(v) = Σ_{S ∋ v} y_S` (its own dual and
//! those of the blossoms around it), so that the reduced cost of an edge between two different
//! outermost blossoms is `c_e − π(u) − π(v)`.
//!
//! # Algorithm
//! 1. *Greedy initialisation* (Blossom V, Section 5.1 "greedy"): `y_v = min_e c_e / 2`, then for
//!    every node in order, `y_v` is raised by its smallest reduced cost and `v` is matched along a
//!    tight edge to a still exposed neighbour, if any.
//! 2. For each exposed node `r` in increasing order: one *alternating tree* rooted at `r` grows
//!    until an augmenting path is found (Edmonds' primal steps: GROW, SHRINK, EXPAND, AUGMENT).
//!    The dual change `δ` of the tree is the time of a Dijkstra-like event queue: each `+` tree
//!    node gains `δ − δ_join`, each `−` node loses it, lazily (a node stores the time at which it
//!    joined; its duals and its nodes' `π` are brought up to date when it leaves the tree, is
//!    shrunk into a blossom or expanded). Events, keyed by the time at which they become possible:
//!    an edge from a `+` node to a free node becomes tight (GROW, or AUGMENT when the free node is
//!    exposed), an edge between two `+` nodes becomes tight (SHRINK: both are in the one tree),
//!    a `−` blossom's dual reaches 0 (EXPAND). Stale events are dropped or re-queued on pop.
//!    Blossoms outlive the search that made them (Blossom V keeps them too) and are expanded only
//!    as `−` nodes whose dual reaches 0.
//!
//! Decision: one tree at a time with a single `δ` (Blossom V's "single" variant), so that all
//! duals stay integers: with every cost doubled (`2c`), all nodes of one tree have `π` of one
//! parity (tight edges join nodes of equal parity, since `2c` is even), so an edge between two
//! `+` nodes has even reduced cost and `δ` = half of it is an integer; GROW and EXPAND times are
//! integers anyway. The certificate is therefore exact.
//!
//! Complexity: O(n m log n) in the worst case (n searches, each O(m log n) with blossom work
//! O(n) per shrink or expand); after the greedy initialisation the searches reach only the
//! neighbourhoods of the few exposed nodes on a mesh dual.
//!
//! Augmenting through blossoms follows the standard rotation of the blossom's cycle (Galil 1986,
//! Section 4), done with an explicit stack so that deeply nested blossoms cannot overflow the
//! call stack.

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::time::Instant;

use super::certificate::{BlossomDual, Certificate};
use super::{MAX_COST, WeightedError};
use crate::dual_graph::{DualGraph, NONE};

/// Labels of outermost nodes (vertices and blossoms).
const FREE: u8 = 0;
const PLUS: u8 = 1;
const MINUS: u8 = 2;

/// Event kinds of the queue.
const EDGE_EVENT: u8 = 0;
const EXPAND_EVENT: u8 = 1;

/// Figures of one [`min_cost_perfect_matching`] run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BlossomStats {
    /// Nodes left exposed by the greedy initialisation (= searches run).
    pub exposed_after_greedy: usize,
    /// Blossoms formed.
    pub shrinks: u64,
    /// Blossoms expanded.
    pub expands: u64,
    /// GROW steps.
    pub grows: u64,
    /// Events popped from the queues, summed over all searches.
    pub events: u64,
    /// Outermost nodes that joined a tree, summed over all searches.
    pub tree_nodes: u64,
    /// Blossoms alive at the end.
    pub blossoms: usize,
    /// Seconds of the greedy initialisation.
    pub greedy_seconds: f64,
    /// Seconds of the searches.
    pub search_seconds: f64,
}

/// A minimum-cost perfect matching and its proof.
#[derive(Clone, Debug, PartialEq)]
pub struct MinCostMatching {
    /// The matched edges, in increasing order.
    pub edges: Vec<u32>,
    /// Their total cost (in the input's integer units).
    pub cost: i64,
    /// The dual solution (for the doubled costs) that proves optimality.
    pub certificate: Certificate,
    /// How the run went.
    pub stats: BlossomStats,
}

/// An event of a search: the time (dual change of the tree) at which it becomes possible.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Event {
    time: i64,
    kind: u8,
    /// Edge (EDGE_EVENT) or blossom (EXPAND_EVENT).
    id: u32,
    /// The blossom's join stamp (EXPAND_EVENT), to recognise stale events.
    stamp: u32,
}

/// The solver's state: nodes `0..n` are the graph's node slots (vertices), `n..` blossoms.
struct Solver {
    n: usize,
    adjacency: Vec<[(u32, u32); 3]>,
    ends: Vec<[u32; 2]>,
    /// Doubled costs per edge slot.
    cost: Vec<i64>,
    /// Per vertex: outermost blossom (or itself), `π`, mate edge.
    outer: Vec<u32>,
    pi: Vec<i64>,
    mate: Vec<u32>,
    /// Per node (vertex or blossom).
    parent: Vec<u32>,
    y: Vec<i64>,
    label: Vec<u8>,
    join_time: Vec<i64>,
    join_stamp: Vec<u32>,
    tree_edge: Vec<u32>,
    tree_vertex: Vec<u32>,
    base: Vec<u32>,
    mark: Vec<u32>,
    /// Per blossom (index `node − n`): children in cycle order from the base's child, and the
    /// cycle's edges: `cycle[i] = (edge, a, b)` joins child `i` (at vertex `a`) and child
    /// `i + 1` (at vertex `b`).
    children: Vec<Vec<u32>>,
    cycle: Vec<Vec<(u32, u32, u32)>>,
    live_blossom: Vec<bool>,
    free_slots: Vec<u32>,
    freed_this_search: Vec<u32>,
    /// Search state.
    time: i64,
    stamp: u32,
    mark_stamp: u32,
    heap: BinaryHeap<Reverse<Event>>,
    touched: Vec<u32>,
    scratch: Vec<u32>,
    stats: BlossomStats,
}

/// The minimum-cost perfect matching of `graph` for `costs` (one per edge slot; removed edges'
/// entries are ignored), with its certificate. See the module doc for the algorithm.
///
/// Takes any [`DualGraph`] (loops are never matched). Deterministic.
///
/// # Errors
/// [`WeightedError::CostCount`] / [`WeightedError::CostOutOfRange`] for bad costs,
/// [`WeightedError::OddNodeCount`], and [`WeightedError::NoPerfectMatching`] when the graph has
/// no perfect matching.
pub fn min_cost_perfect_matching<G: DualGraph + ?Sized>(
    graph: &G,
    costs: &[i64],
) -> Result<MinCostMatching, WeightedError> {
    if costs.len() != graph.edge_slots() {
        return Err(WeightedError::CostCount {
            costs: costs.len(),
            edge_slots: graph.edge_slots(),
        });
    }
    for e in 0..graph.edge_slots() as u32 {
        let c = costs[e as usize];
        if graph.is_edge(e) && !(0..=MAX_COST).contains(&c) {
            return Err(WeightedError::CostOutOfRange { edge: e, cost: c });
        }
    }
    let nodes = graph.node_count();
    if !nodes.is_multiple_of(2) {
        return Err(WeightedError::OddNodeCount { nodes });
    }
    let mut solver = Solver::new(graph, costs);
    let start = Instant::now();
    solver.greedy_init();
    solver.stats.greedy_seconds = start.elapsed().as_secs_f64();
    let start = Instant::now();
    for r in 0..solver.n as u32 {
        if graph.is_node(r) && solver.mate[r as usize] == NONE {
            solver.stats.exposed_after_greedy += 1;
            solver.search(r)?;
        }
    }
    solver.stats.search_seconds = start.elapsed().as_secs_f64();
    let mut edges: Vec<u32> = (0..solver.n)
        .filter(|&v| graph.is_node(v as u32))
        .map(|v| solver.mate[v])
        .filter(|&e| e != NONE)
        .collect();
    edges.sort_unstable();
    edges.dedup();
    let cost = edges.iter().map(|&e| costs[e as usize]).sum();
    let certificate = solver.certificate();
    solver.stats.blossoms = certificate.blossoms.len();
    Ok(MinCostMatching {
        edges,
        cost,
        certificate,
        stats: solver.stats,
    })
}

impl Solver {
    fn new<G: DualGraph + ?Sized>(graph: &G, costs: &[i64]) -> Self {
        let n = graph.node_slots();
        let adjacency = graph.adjacency_table().adjacent;
        let mut ends = vec![[NONE, NONE]; graph.edge_slots()];
        for (v, pairs) in adjacency.iter().enumerate() {
            for &(e, w) in pairs {
                if e != NONE {
                    ends[e as usize] = [v as u32, w];
                }
            }
        }
        let cost = costs.iter().map(|&c| 2 * c.max(0)).collect();
        Solver {
            n,
            adjacency,
            ends,
            cost,
            outer: (0..n as u32).collect(),
            pi: vec![0; n],
            mate: vec![NONE; n],
            parent: vec![NONE; n],
            y: vec![0; n],
            label: vec![FREE; n],
            join_time: vec![0; n],
            join_stamp: vec![0; n],
            tree_edge: vec![NONE; n],
            tree_vertex: vec![NONE; n],
            base: (0..n as u32).collect(),
            mark: vec![0; n],
            children: Vec::new(),
            cycle: Vec::new(),
            live_blossom: Vec::new(),
            free_slots: Vec::new(),
            freed_this_search: Vec::new(),
            time: 0,
            stamp: 0,
            mark_stamp: 0,
            heap: BinaryHeap::new(),
            touched: Vec::new(),
            scratch: Vec::new(),
            stats: BlossomStats::default(),
        }
    }

    #[inline]
    fn is_blossom(&self, x: u32) -> bool {
        x as usize >= self.n
    }

    #[inline]
    fn other_end(&self, e: u32, v: u32) -> u32 {
        let [a, b] = self.ends[e as usize];
        if a == v { b } else { a }
    }

    /// The non-loop `(edge, neighbour)` pairs of vertex `v`.
    #[inline]
    fn edges_of(&self, v: u32) -> impl Iterator<Item = (u32, u32)> + use<> {
        let pairs = self.adjacency[v as usize];
        pairs.into_iter().filter(move |&(e, w)| e != NONE && w != v)
    }

    fn greedy_init(&mut self) {
        for v in 0..self.n as u32 {
            let min = self.edges_of(v).map(|(e, _)| self.cost[e as usize]).min();
            if let Some(min) = min {
                self.y[v as usize] = min / 2;
            }
        }
        for v in 0..self.n as u32 {
            if self.mate[v as usize] != NONE {
                continue;
            }
            let slack =
                |s: &Self, e: u32, w: u32| s.cost[e as usize] - s.y[v as usize] - s.y[w as usize];
            let Some(min) = self.edges_of(v).map(|(e, w)| slack(self, e, w)).min() else {
                continue;
            };
            self.y[v as usize] += min;
            let pick = self
                .edges_of(v)
                .find(|&(e, w)| slack(self, e, w) == 0 && self.mate[w as usize] == NONE);
            if let Some((e, w)) = pick {
                self.mate[v as usize] = e;
                self.mate[w as usize] = e;
            }
        }
        self.pi.copy_from_slice(&self.y[..self.n]);
    }

    /// The vertices of node `x` (itself for a vertex), into `out` (cleared first).
    fn collect_vertices(&self, x: u32, out: &mut Vec<u32>) {
        out.clear();
        if !self.is_blossom(x) {
            out.push(x);
            return;
        }
        let mut stack = vec![x];
        while let Some(b) = stack.pop() {
            for &c in &self.children[b as usize - self.n] {
                if self.is_blossom(c) {
                    stack.push(c);
                } else {
                    out.push(c);
                }
            }
        }
    }

    /// The dual change of outermost node `x` since it joined its tree (0 if free).
    #[inline]
    fn offset(&self, x: u32) -> i64 {
        let d = self.time - self.join_time[x as usize];
        match self.label[x as usize] {
            PLUS => d,
            MINUS => -d,
            _ => 0,
        }
    }

    #[inline]
    fn pi_now(&self, v: u32) -> i64 {
        self.pi[v as usize] + self.offset(self.outer[v as usize])
    }

    /// Reduced cost of edge `e` between two different outermost nodes, now.
    #[inline]
    fn slack(&self, e: u32) -> i64 {
        let [u, v] = self.ends[e as usize];
        self.cost[e as usize] - self.pi_now(u) - self.pi_now(v)
    }

    /// Applies the lazy dual change of outermost node `x` to its dual and its vertices' `π`, and
    /// restarts its clock at the current time.
    fn settle(&mut self, x: u32) {
        let d = self.offset(x);
        if d != 0 {
            self.y[x as usize] += d;
            let mut vertices = std::mem::take(&mut self.scratch);
            self.collect_vertices(x, &mut vertices);
            for &v in &vertices {
                self.pi[v as usize] += d;
            }
            self.scratch = vertices;
        }
        self.join_time[x as usize] = self.time;
    }

    fn push_edge(&mut self, e: u32, delay: i64) {
        self.heap.push(Reverse(Event {
            time: self.time + delay,
            kind: EDGE_EVENT,
            id: e,
            stamp: 0,
        }));
    }

    /// Labels outermost node `x` and records it for the cleanup.
    fn join(&mut self, x: u32, label: u8) {
        self.label[x as usize] = label;
        self.join_time[x as usize] = self.time;
        self.stamp = self.stamp.wrapping_add(1);
        self.join_stamp[x as usize] = self.stamp;
        self.touched.push(x);
        self.stats.tree_nodes += 1;
        if label == MINUS && self.is_blossom(x) {
            let y = self.y[x as usize];
            self.heap.push(Reverse(Event {
                time: self.time + y,
                kind: EXPAND_EVENT,
                id: x,
                stamp: self.stamp,
            }));
        }
    }

    /// Queues the events of the edges of `x`'s vertices, `x` having just become `+` (or part of
    /// a `+` blossom): to free nodes (GROW at full reduced cost) and to other `+` nodes (SHRINK at
    /// half of it).
    fn scan_plus(&mut self, x: u32) {
        let mut vertices = std::mem::take(&mut self.scratch);
        self.collect_vertices(x, &mut vertices);
        for &v in &vertices {
            let own = self.outer[v as usize];
            for (e, w) in self.edges_of(v) {
                let other = self.outer[w as usize];
                if other == own {
                    continue;
                }
                match self.label[other as usize] {
                    FREE => self.push_edge(e, self.slack(e)),
                    PLUS => {
                        let s = self.slack(e);
                        debug_assert!(s % 2 == 0, "odd reduced cost {s} between + nodes");
                        self.push_edge(e, s / 2);
                    }
                    _ => {}
                }
            }
        }
        self.scratch = vertices;
    }

    /// Queues GROW events for the edges from `x`'s vertices (`x` free) to `+` nodes.
    fn scan_free(&mut self, x: u32) {
        let mut vertices = std::mem::take(&mut self.scratch);
        self.collect_vertices(x, &mut vertices);
        for &v in &vertices {
            for (e, w) in self.edges_of(v) {
                let other = self.outer[w as usize];
                if other != x && self.label[other as usize] == PLUS {
                    self.push_edge(e, self.slack(e));
                }
            }
        }
        self.scratch = vertices;
    }

    /// One alternating tree from exposed vertex `root`, until it augments.
    fn search(&mut self, root: u32) -> Result<(), WeightedError> {
        self.time = 0;
        let r = self.outer[root as usize];
        self.join(r, PLUS);
        self.scan_plus(r);
        loop {
            let Some(Reverse(event)) = self.heap.pop() else {
                return Err(WeightedError::NoPerfectMatching { node: root });
            };
            self.stats.events += 1;
            debug_assert!(event.time >= self.time, "events go forward in time");
            self.time = event.time;
            if event.kind == EXPAND_EVENT {
                let b = event.id;
                if self.parent[b as usize] != NONE
                    || self.label[b as usize] != MINUS
                    || self.join_stamp[b as usize] != event.stamp
                    || !self.live_blossom[b as usize - self.n]
                {
                    continue;
                }
                self.expand(b);
                continue;
            }
            let e = event.id;
            let [u, v] = self.ends[e as usize];
            let (ou, ov) = (self.outer[u as usize], self.outer[v as usize]);
            if ou == ov {
                continue;
            }
            let (lu, lv) = (self.label[ou as usize], self.label[ov as usize]);
            let s = self.slack(e);
            debug_assert!(s >= 0, "negative reduced cost {s} on edge {e}");
            match (lu, lv) {
                (PLUS, PLUS) => {
                    if s > 0 {
                        self.push_edge(e, s / 2);
                    } else {
                        self.shrink(e);
                    }
                }
                (PLUS, FREE) | (FREE, PLUS) => {
                    if s > 0 {
                        self.push_edge(e, s);
                        continue;
                    }
                    let (inner, outside) = if lu == PLUS { (u, v) } else { (v, u) };
                    let w_outer = self.outer[outside as usize];
                    if self.mate[self.base[w_outer as usize] as usize] == NONE {
                        self.augment(e, inner, outside);
                        self.cleanup();
                        return Ok(());
                    }
                    self.grow(e, outside);
                }
                _ => {}
            }
        }
    }

    /// GROW: free matched node of vertex `w` joins as `−` through tight edge `e`, its mate as `+`.
    fn grow(&mut self, e: u32, w: u32) {
        self.stats.grows += 1;
        let x = self.outer[w as usize];
        self.tree_edge[x as usize] = e;
        self.tree_vertex[x as usize] = w;
        self.join(x, MINUS);
        let b = self.base[x as usize];
        let m = self.mate[b as usize];
        let partner = self.outer[self.other_end(m, b) as usize];
        debug_assert_eq!(self.label[partner as usize], FREE);
        self.join(partner, PLUS);
        self.scan_plus(partner);
    }

    /// The `+` parent of `+` node `x` in the tree (`NONE` for the root).
    fn plus_parent(&self, x: u32) -> u32 {
        let b = self.base[x as usize];
        let m = self.mate[b as usize];
        if m == NONE {
            return NONE;
        }
        let minus = self.outer[self.other_end(m, b) as usize];
        let tv = self.tree_vertex[minus as usize];
        self.outer[self.other_end(self.tree_edge[minus as usize], tv) as usize]
    }

    /// The edge from node `x` to its tree parent, as `(edge, vertex in x, vertex in parent)`.
    fn parent_link(&self, x: u32) -> (u32, u32, u32) {
        if self.label[x as usize] == PLUS {
            let b = self.base[x as usize];
            let m = self.mate[b as usize];
            (m, b, self.other_end(m, b))
        } else {
            let e = self.tree_edge[x as usize];
            let v = self.tree_vertex[x as usize];
            (e, v, self.other_end(e, v))
        }
    }

    /// SHRINK: tight edge `e` joins two `+` nodes of the tree; the cycle through their lowest
    /// common ancestor becomes a `+` blossom with dual 0.
    fn shrink(&mut self, e: u32) {
        self.stats.shrinks += 1;
        let [u, v] = self.ends[e as usize];
        let (ou, ov) = (self.outer[u as usize], self.outer[v as usize]);
        // Lowest common ancestor, stepping up alternately from both sides.
        self.mark_stamp = self.mark_stamp.wrapping_add(2);
        let (tag_u, tag_v) = (self.mark_stamp, self.mark_stamp + 1);
        let (mut a, mut b) = (ou, ov);
        let lca = loop {
            if a != NONE {
                if self.mark[a as usize] == tag_v {
                    break a;
                }
                self.mark[a as usize] = tag_u;
                a = self.plus_parent(a);
            }
            if b != NONE {
                if self.mark[b as usize] == tag_u {
                    break b;
                }
                self.mark[b as usize] = tag_v;
                b = self.plus_parent(b);
            }
        };
        // The two paths up to the LCA, through the `−` nodes.
        let path_to = |s: &Self, from: u32| {
            let mut path = vec![from];
            let mut x = from;
            while x != lca {
                let (_, _, up) = s.parent_link(x);
                x = s.outer[up as usize];
                path.push(x);
            }
            path
        };
        let path_u = path_to(self, ou);
        let path_v = path_to(self, ov);
        let mut children = Vec::with_capacity(path_u.len() + path_v.len() - 1);
        let mut cycle = Vec::with_capacity(children.capacity());
        for i in (0..path_u.len()).rev() {
            children.push(path_u[i]);
            if i > 0 {
                let (edge, below, above) = self.parent_link(path_u[i - 1]);
                cycle.push((edge, above, below));
            }
        }
        cycle.push((e, u, v));
        for &x in &path_v[..path_v.len() - 1] {
            children.push(x);
            let (edge, here, up) = self.parent_link(x);
            cycle.push((edge, here, up));
        }
        let blossom = self.new_blossom();
        for &c in &children {
            self.settle(c);
            self.parent[c as usize] = blossom;
        }
        let bi = blossom as usize;
        self.base[bi] = self.base[lca as usize];
        self.y[bi] = 0;
        self.parent[bi] = NONE;
        let minus_children: Vec<u32> = children
            .iter()
            .copied()
            .filter(|&c| self.label[c as usize] == MINUS)
            .collect();
        self.children[bi - self.n] = children;
        self.cycle[bi - self.n] = cycle;
        let mut vertices = std::mem::take(&mut self.scratch);
        self.collect_vertices(blossom, &mut vertices);
        for &w in &vertices {
            self.outer[w as usize] = blossom;
        }
        self.scratch = vertices;
        self.join(blossom, PLUS);
        for c in minus_children {
            self.scan_plus(c);
        }
    }

    /// A blossom slot, reused or new.
    fn new_blossom(&mut self) -> u32 {
        if let Some(b) = self.free_slots.pop() {
            self.live_blossom[b as usize - self.n] = true;
            return b;
        }
        let b = self.parent.len() as u32;
        self.parent.push(NONE);
        self.y.push(0);
        self.label.push(FREE);
        self.join_time.push(0);
        self.join_stamp.push(0);
        self.tree_edge.push(NONE);
        self.tree_vertex.push(NONE);
        self.base.push(NONE);
        self.mark.push(0);
        self.children.push(Vec::new());
        self.cycle.push(Vec::new());
        self.live_blossom.push(true);
        b
    }

    /// EXPAND: `−` blossom `b`, whose dual reached 0, is replaced by its children; the even
    /// path of the cycle from the child the tree enters by to the base's child stays in the tree
    /// (alternately `−` and `+`), the other children become free.
    fn expand(&mut self, b: u32) {
        self.stats.expands += 1;
        self.settle(b);
        debug_assert_eq!(self.y[b as usize], 0);
        let bi = b as usize - self.n;
        let entry = self.tree_vertex[b as usize];
        let entry_edge = self.tree_edge[b as usize];
        let mut child = entry;
        while self.parent[child as usize] != b {
            child = self.parent[child as usize];
        }
        let children = std::mem::take(&mut self.children[bi]);
        let cycle = std::mem::take(&mut self.cycle[bi]);
        let k = children.len();
        let j = children
            .iter()
            .position(|&c| c == child)
            .expect("the entry vertex lies in a child");
        let mut vertices = std::mem::take(&mut self.scratch);
        for &c in &children {
            self.parent[c as usize] = NONE;
            self.label[c as usize] = FREE;
            self.collect_vertices(c, &mut vertices);
            for &w in &vertices {
                self.outer[w as usize] = c;
            }
        }
        self.scratch = vertices;
        self.live_blossom[bi] = false;
        self.label[b as usize] = FREE;
        self.freed_this_search.push(b);
        // The even path j -> 0 along the cycle: backward if j is even, forward otherwise.
        let mut on_path = vec![false; k];
        let mut path = Vec::with_capacity(k);
        let mut i = j;
        on_path[i] = true;
        path.push((children[i], entry_edge, entry));
        while i != 0 {
            let (next, edge, vertex_in_next) = if j % 2 == 0 {
                let (edge, a, _) = cycle[i - 1];
                (i - 1, edge, a)
            } else {
                let (edge, _, bb) = cycle[i];
                ((i + 1) % k, edge, bb)
            };
            on_path[next] = true;
            path.push((children[next], edge, vertex_in_next));
            i = next;
        }
        for (pos, &(c, edge, vertex)) in path.iter().enumerate() {
            if pos % 2 == 0 {
                self.tree_edge[c as usize] = edge;
                self.tree_vertex[c as usize] = vertex;
                self.join(c, MINUS);
            } else {
                self.join(c, PLUS);
            }
        }
        for (pos, &(c, _, _)) in path.iter().enumerate() {
            if pos % 2 == 1 {
                self.scan_plus(c);
            }
        }
        for (idx, &c) in children.iter().enumerate() {
            if !on_path[idx] {
                self.scan_free(c);
            }
        }
    }

    /// AUGMENT along tight edge `e` from `inner` (in the tree) to `outside` (in an exposed free
    /// node): the path to the root alternates, every blossom on it rotated to its new base.
    fn augment(&mut self, e: u32, inner: u32, outside: u32) {
        let w = self.outer[outside as usize];
        self.rotate(w, outside);
        self.mate[outside as usize] = e;
        let (mut x, mut entry, mut edge) = (self.outer[inner as usize], inner, e);
        loop {
            let old_base = self.base[x as usize];
            let old_mate = self.mate[old_base as usize];
            self.rotate(x, entry);
            self.mate[entry as usize] = edge;
            if old_mate == NONE {
                break;
            }
            let minus = self.outer[self.other_end(old_mate, old_base) as usize];
            let p = self.tree_edge[minus as usize];
            let pv = self.tree_vertex[minus as usize];
            self.rotate(minus, pv);
            self.mate[pv as usize] = p;
            entry = self.other_end(p, pv);
            x = self.outer[entry as usize];
            edge = p;
        }
    }

    /// Makes vertex `v` the base of node `x` (a no-op for a vertex), rematching inside: in each
    /// blossom, the child holding `v` is matched outside, and the cycle is re-paired from it to
    /// the old base's child along the even side; nested blossoms are rotated in turn.
    fn rotate(&mut self, x: u32, v: u32) {
        if !self.is_blossom(x) {
            return;
        }
        let mut stack = vec![(x, v)];
        while let Some((b, v)) = stack.pop() {
            let bi = b as usize - self.n;
            let mut t = v;
            while self.parent[t as usize] != b {
                t = self.parent[t as usize];
            }
            if self.is_blossom(t) {
                stack.push((t, v));
            }
            let k = self.children[bi].len();
            let i = self.children[bi]
                .iter()
                .position(|&c| c == t)
                .expect("v lies in a child");
            // Cycle edges to match: i+1, i+3, ..., k-1 (i odd) or i-2, i-4, ..., 0 (i even).
            let mut pick = |m: usize, s: &mut Self| {
                let (edge, a, bb) = s.cycle[bi][m];
                let (ca, cb) = (s.children[bi][m], s.children[bi][(m + 1) % k]);
                if s.is_blossom(ca) {
                    stack.push((ca, a));
                }
                if s.is_blossom(cb) {
                    stack.push((cb, bb));
                }
                s.mate[a as usize] = edge;
                s.mate[bb as usize] = edge;
            };
            if i % 2 == 1 {
                let mut m = i + 1;
                while m < k {
                    pick(m, self);
                    m += 2;
                }
            } else {
                let mut m = i;
                while m >= 2 {
                    m -= 2;
                    pick(m, self);
                }
            }
            self.children[bi].rotate_left(i);
            self.cycle[bi].rotate_left(i);
            self.base[b as usize] = v;
        }
    }

    /// After an augmentation: every tree node's duals brought up to date and its label cleared.
    fn cleanup(&mut self) {
        let touched = std::mem::take(&mut self.touched);
        for &x in &touched {
            if self.parent[x as usize] == NONE && self.label[x as usize] != FREE {
                self.settle(x);
            }
        }
        for &x in &touched {
            self.label[x as usize] = FREE;
        }
        self.touched = touched;
        self.touched.clear();
        self.heap.clear();
        self.free_slots.append(&mut self.freed_this_search);
    }

    /// The duals and the laminar family of live blossoms.
    fn certificate(&self) -> Certificate {
        let mut index = vec![NONE; self.parent.len() - self.n];
        let mut blossoms = Vec::new();
        for (bi, &live) in self.live_blossom.iter().enumerate() {
            if live {
                index[bi] = blossoms.len() as u32;
                blossoms.push(BlossomDual {
                    parent: NONE,
                    dual: self.y[self.n + bi],
                });
            }
        }
        let map = |p: u32| {
            if p == NONE {
                NONE
            } else {
                index[p as usize - self.n]
            }
        };
        for (bi, &live) in self.live_blossom.iter().enumerate() {
            if live {
                blossoms[index[bi] as usize].parent = map(self.parent[self.n + bi]);
            }
        }
        Certificate {
            node_duals: self.y[..self.n].to_vec(),
            node_blossom: (0..self.n).map(|v| map(self.parent[v])).collect(),
            blossoms,
        }
    }
}
