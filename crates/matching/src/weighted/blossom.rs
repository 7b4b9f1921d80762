//! Edmonds' primal–dual blossom algorithm for a minimum-cost perfect matching (Edmonds 1965),
//! with the initialisations of Kolmogorov's Blossom V (2009): exact, with the dual solution as
//! certificate ([`Certificate`]).
//!
//! # Formulation
//! The dual of the module [`super::certificate`]: one `y` per node and one `z ≥ 0` per blossom
//! (an odd set), the reduced cost of `e = uv` being `c_e − Σ_{S : |S ∩ {u,v}| = 1} y_S`, where the
//! sum runs over the node duals and the blossoms containing exactly one end (Blossom V's
//! "δ(S)" formulation, Section 2). The solver keeps, per vertex `v`, `π(v) = Σ_{S ∋ v} y_S`
//! (its own dual and those of the blossoms around it), so that the reduced cost of an edge
//! between two different outermost blossoms is `c_e − π(u) − π(v)`.
//!
//! # Algorithm
//! 1. *Greedy initialisation* (Blossom V, Section 5.1): `y_v = min_e c_e / 2`; then for every
//!    node in order, `y_v` is raised by its smallest reduced cost and `v` is matched along a
//!    tight edge to a still exposed neighbour, if any; then augmenting paths of three tight edges
//!    are taken where they exist.
//! 2. *Fractional initialisation* (Blossom V, Section 5.1, "fractional"): the primal–dual
//!    growth below without blossoms, solving the matching LP without odd-set constraints (its
//!    optimum is half-integral): a tight edge closing an odd cycle in a tree matches the root
//!    and leaves the cycle covered by half-edges; a tree that reaches such a cycle augments into
//!    it. Each cycle left at the end keeps one node exposed. On mesh duals this leaves well under
//!    1% of the nodes exposed.
//! 3. *Blossom phase*: every exposed node roots a `+` tree, and all trees grow together under
//!    one dual change `δ` (the multiple-tree, single-`δ` scheme of Galil's survey, Section 4,
//!    which LEMON also uses), `δ` being the clock of a monotone event queue (a radix heap):
//!    each `+` tree node gains `δ − δ_join`, each `−` node loses it, lazily (a node stores the
//!    time it joined; its dual is brought up to date when it leaves its tree, is shrunk into a
//!    blossom or is expanded). The vertices of each outermost node form a set sharing one
//!    accumulated dual change; a shrink merges the children's sets into the largest (union by
//!    size: only the other children's vertices are relabelled), an expansion splits the set back
//!    into its children's (one of them keeping it: again only the others are relabelled). Events, keyed by the time they become possible: an
//!    edge from a `+` node to a free node becomes tight (GROW), an edge between two `+` nodes
//!    becomes tight (SHRINK in one tree, AUGMENT between two: both trees dissolve), a `−`
//!    blossom's dual reaches 0 (EXPAND). Stale events are dropped or re-queued when popped.
//!    Blossoms outlive their trees (Blossom V keeps them too) and are expanded only as `−` nodes
//!    whose dual reaches 0.
//!
//! Decision: one `δ` for all trees (not Blossom V's per-tree `δ`), so that all duals stay
//! integers: every cost is doubled (`2c`), so a tight edge joins vertices of equal `π` parity;
//! the roots of a phase are all given even `π` (lowering an exposed node's dual keeps the dual
//! feasible), and they all change by the same `δ`, so every `+` vertex of every tree has the
//! same parity and an edge between two `+` nodes has even reduced cost: `δ` = half of it is an
//! integer. GROW and EXPAND times are integers anyway. The certificate is therefore exact.
//!
//! Complexity: O(n m log C) in the worst case (n/2 augmentations, each growth touching O(m)
//! events, blossom work O(n) per shrink or expand); on mesh duals the phases after the greedy
//! reach only neighbourhoods of the exposed nodes.
//!
//! Augmenting through blossoms follows the standard rotation of the blossom's cycle (Galil 1986,
//! Section 4), done with an explicit stack so that deeply nested blossoms cannot overflow the
//! call stack.
//!
//! # Speed (ours, not from the papers)
//! The searches are bound by memory reads: events come out of the queue in time order, far
//! apart in the graph. So the fields a reduced cost needs lie together in one record per id
//! (`Slot`: an outermost vertex's whole `π` in one record), an edge event carries its two ends,
//! the next event's records are read ahead while one is handled, and the event queue moves an
//! item at most 7 times (`radix_heap`). A dissolved tree's former `+` nodes are not scanned again:
//! their edges to other trees' `+` nodes already have events, which come early and are queued
//! again when popped. Measured against LEMON and Gmsh by `crates/quad/examples/quality_bench.rs`.

use std::time::Instant;

use super::certificate::{BlossomDual, Certificate};
use prefetch_index::prefetch_index;

use super::radix_heap::RadixHeap;
use super::{WeightedError, check_costs};
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
    /// Nodes left exposed by the greedy initialisation (the roots of the fractional phase).
    pub exposed_after_greedy: usize,
    /// Nodes left exposed by the fractional phase (the roots of the blossom phase).
    pub exposed_after_fractional: usize,
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
    /// Seconds of the fractional phase (its rounding included).
    pub fractional_seconds: f64,
    /// Seconds of the searches (the fractional phase included).
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

/// An event of a search, queued under the time (the dual change since the search began) at
/// which it becomes possible.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Event {
    /// Edge (EDGE_EVENT) or blossom (EXPAND_EVENT).
    id: u32,
    /// The edge's two ends (EDGE_EVENT), carried so that the event's vertices are read without
    /// the edge's record first; or the blossom's join stamp and `NONE` (EXPAND_EVENT), to
    /// recognise stale events.
    a: u32,
    b: u32,
    kind: u8,
}

/// The hot state of one id of the node range, read together when a reduced cost is evaluated or
/// a vertex is scanned: for a vertex id, the vertex's own fields and neighbours; for any id, the
/// fields of the vertex set and of the node of that id. An outermost vertex is its own set and
/// node, so its reduced-cost terms and its neighbours lie in one record of one cache line.
#[derive(Clone, Copy, Debug)]
#[repr(align(64))]
struct Slot {
    /// Vertex: its stored `π` (see `Solver::pi_now`).
    pi: i64,
    /// Set: the dual change its vertices' `π` owe it (`set_acc` of the `Solver` doc).
    acc: i64,
    /// Node: the time it joined its tree (or was last settled).
    join_time: i64,
    /// Vertex: its three `(edge, neighbour)` pairs (`NONE` pairs for a removed node), read by
    /// every scan of the vertex right after its record.
    adjacent: [(u32, u32); 3],
    /// Vertex: its set.
    set: u32,
    /// Vertex: its matched edge (`NONE` if exposed).
    mate: u32,
    /// Set: its outermost node (`set_outer` of the `Solver` doc).
    outer: u32,
    /// Node: `FREE`, `PLUS` or `MINUS`.
    label: u8,
}

impl Slot {
    /// The record of id `i` before any search: its own set and node, free, exposed, no
    /// neighbours.
    fn new(i: u32) -> Self {
        Slot {
            pi: 0,
            acc: 0,
            join_time: 0,
            adjacent: [(NONE, NONE); 3],
            set: i,
            mate: NONE,
            outer: i,
            label: FREE,
        }
    }
}

/// An edge slot: its ends and doubled cost.
#[derive(Clone, Copy, Debug)]
struct EdgeSlot {
    ends: [u32; 2],
    cost: i64,
}

/// The solver's state: nodes `0..n` are the graph's node slots (vertices), `n..` blossoms.
/// The per-id fields read on every reduced cost live together in `slots` ([`Slot`]); the
/// vertex-set scheme is described at `node_set`, with `set_of`, `set_outer` and `set_acc`
/// standing for the `set`, `outer` and `acc` fields of the slots.
struct Solver<X: Extra = NoExtra> {
    n: usize,
    /// The edges beyond a vertex's three slots (none on a mesh dual; see [`Extra`]).
    extra: X,
    /// Per node: its tree (an index into `trees`) while it is an outermost tree node.
    tree: Vec<u32>,
    edges: Vec<EdgeSlot>,
    slots: Vec<Slot>,
    /// Per vertex: liveness.
    is_live: Vec<bool>,
    /// Per vertex: its vertex set (see `set_*`) and the next vertex of that set's list.
    set_next: Vec<u32>,
    /// Vertex sets, one per outermost node, ids in the node range: the vertices of an outermost
    /// node form one set (`node_set`), a list (`set_head` … `set_tail` through `set_next`,
    /// `set_size` long) whose node is `set_outer`. A vertex's `π` is `pi + set_acc[its set] +
    /// the running tree offset of its node`: `set_acc` gathers the dual changes of the
    /// outermost nodes the set has stood for. A shrink merges the children's sets into the
    /// largest (relabelling only the others' vertices, so a vertex is relabelled O(log n) times
    /// between expansions); an expansion splits the blossom's list back into its children's
    /// (`segment`), one child keeping the blossom's set, so that it too relabels only the
    /// others' vertices.
    node_set: Vec<u32>,
    /// Per node nested in a blossom: its list (`[head, tail, size]`) when the blossom was made,
    /// a contiguous segment of the blossom's list (the lists are joined end to end), restored
    /// as the node's list when the blossom is expanded.
    segment: Vec<[u32; 3]>,
    set_head: Vec<u32>,
    set_tail: Vec<u32>,
    set_size: Vec<u32>,
    /// Per node (vertex or blossom).
    parent: Vec<u32>,
    y: Vec<i64>,
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
    /// Fractional phase: per vertex its half-edge cycle (`NONE` if none), and per cycle its
    /// vertices in order with the edge to the next.
    half_cycle_of: Vec<u32>,
    half_cycles: Vec<Vec<(u32, u32)>>,
    /// Per tree: the first entry of the list of the nodes that joined it (some since nested or
    /// expanded) in `members`; and how many trees are still growing.
    trees: Vec<u32>,
    active_trees: usize,
    /// The lists of `trees`, all in one arena: entry `i` is a node and the index of the next
    /// entry of its tree's list (`NONE` at the end); `trees[t]` is the first entry of tree `t`.
    members: Vec<(u32, u32)>,
    /// The `−` nodes freed by a dissolve (a buffer kept between calls).
    freed: Vec<u32>,
    /// Search state.
    time: i64,
    stamp: u32,
    mark_stamp: u32,
    heap: RadixHeap<Event>,
    scratch: Vec<u32>,
    /// Buffers of `odd_cycle`'s two tree paths.
    paths: [Vec<u32>; 2],
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
    check_costs(graph, costs)?;
    let nodes = graph.node_count();
    if !nodes.is_multiple_of(2) {
        return Err(WeightedError::OddNodeCount { nodes });
    }
    let (edges, certificate, stats) = Solver::new(graph, costs).solve()?;
    let cost = edges.iter().map(|&e| costs[e as usize]).sum();
    Ok(MinCostMatching {
        edges,
        cost,
        certificate,
        stats,
    })
}

/// Edges of a vertex beyond the three of its record: none on a mesh dual ([`NoExtra`]); lists
/// on the auxiliary graph of a maximum-cardinality matching ([`ExtraLists`], see
/// [`super::maximum`]), whose dummy nodes are joined to many vertices. Its
/// [`Extra::edges_of`] gives all of a vertex's non-loop edges, without borrowing the solver.
pub(super) trait Extra {
    /// The vertex's non-loop `(edge, neighbour)` pairs: the live ones of `adjacent` (its record's
    /// three), then its extra ones.
    fn edges_of(
        &self,
        adjacent: [(u32, u32); 3],
        v: u32,
    ) -> impl Iterator<Item = (u32, u32)> + use<Self>;
}

/// No edge beyond the three of a vertex's record.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct NoExtra;

impl Extra for NoExtra {
    #[inline]
    fn edges_of(
        &self,
        adjacent: [(u32, u32); 3],
        v: u32,
    ) -> impl Iterator<Item = (u32, u32)> + use<> {
        adjacent
            .into_iter()
            .filter(move |&(e, w)| e != NONE && w != v)
    }
}

/// Extra `(edge, neighbour)` pairs per vertex, as one shared list with offsets (shared, so that
/// an iterator over a vertex's pairs holds no borrow of the solver).
#[derive(Clone, Debug)]
pub(super) struct ExtraLists {
    /// Per vertex, the start of its pairs in `pairs` (one more entry at the end).
    pub start: std::rc::Rc<[u32]>,
    pub pairs: std::rc::Rc<[(u32, u32)]>,
}

/// A vertex's pairs of an [`ExtraLists`].
pub(super) struct ExtraIter {
    pairs: std::rc::Rc<[(u32, u32)]>,
    next: usize,
    end: usize,
}

impl Iterator for ExtraIter {
    type Item = (u32, u32);
    #[inline]
    fn next(&mut self) -> Option<(u32, u32)> {
        (self.next < self.end).then(|| {
            self.next += 1;
            self.pairs[self.next - 1]
        })
    }
}

impl Extra for ExtraLists {
    #[inline]
    fn edges_of(
        &self,
        adjacent: [(u32, u32); 3],
        v: u32,
    ) -> impl Iterator<Item = (u32, u32)> + use<> {
        let (next, end) = match self.start.get(v as usize + 1) {
            Some(&end) => (self.start[v as usize] as usize, end as usize),
            None => (0, 0),
        };
        NoExtra.edges_of(adjacent, v).chain(ExtraIter {
            pairs: self.pairs.clone(),
            next,
            end,
        })
    }
}

/// The solver on a graph given as vertex records (three `(edge, neighbour)` pairs each, `NONE`
/// pairs unused), extra pairs per vertex, edge ends with their (undoubled) costs, and the live
/// vertices: the auxiliary graph of [`super::maximum`]. Returns the matched edges in increasing
/// order, the certificate (for the doubled costs) and the figures.
pub(super) fn solve_with_extra(
    adjacency: Vec<[(u32, u32); 3]>,
    extra: ExtraLists,
    edges: &[([u32; 2], i64)],
    is_live: Vec<bool>,
) -> Result<(Vec<u32>, Certificate, BlossomStats), WeightedError> {
    let edges = edges
        .iter()
        .map(|&(ends, cost)| EdgeSlot {
            ends,
            cost: 2 * cost,
        })
        .collect();
    Solver::from_parts(adjacency, edges, is_live, extra).solve()
}

impl Solver {
    fn new<G: DualGraph + ?Sized>(graph: &G, costs: &[i64]) -> Self {
        let n = graph.node_slots();
        let adjacency = graph.adjacency_table().adjacent;
        let mut edges: Vec<EdgeSlot> = costs
            .iter()
            .map(|&c| EdgeSlot {
                ends: [NONE, NONE],
                cost: 2 * c.max(0),
            })
            .collect();
        for (v, pairs) in adjacency.iter().enumerate() {
            for &(e, w) in pairs {
                if e != NONE {
                    edges[e as usize].ends = [v as u32, w];
                }
            }
        }
        let is_live = (0..n as u32).map(|v| graph.is_node(v)).collect();
        Solver::from_parts(adjacency, edges, is_live, NoExtra)
    }
}

impl<X: Extra> Solver<X> {
    /// A solver for the graph of these vertex records (three pairs each), edges (ends and
    /// doubled costs), live vertices and extra edges.
    fn from_parts(
        adjacency: Vec<[(u32, u32); 3]>,
        edges: Vec<EdgeSlot>,
        is_live: Vec<bool>,
        extra: X,
    ) -> Self {
        let n = adjacency.len();
        let slots = (0..n as u32)
            .map(|v| Slot {
                adjacent: adjacency[v as usize],
                ..Slot::new(v)
            })
            .collect();
        Solver {
            n,
            extra,
            tree: vec![NONE; n],
            edges,
            slots,
            is_live,
            set_next: vec![NONE; n],
            node_set: (0..n as u32).collect(),
            segment: (0..n as u32).map(|v| [v, v, 1]).collect(),
            set_head: (0..n as u32).collect(),
            set_tail: (0..n as u32).collect(),
            set_size: vec![1; n],
            parent: vec![NONE; n],
            y: vec![0; n],
            join_stamp: vec![0; n],
            tree_edge: vec![NONE; n],
            tree_vertex: vec![NONE; n],
            base: (0..n as u32).collect(),
            mark: vec![0; n],
            children: Vec::new(),
            cycle: Vec::new(),
            live_blossom: Vec::new(),
            half_cycle_of: vec![NONE; n],
            half_cycles: Vec::new(),
            trees: Vec::new(),
            active_trees: 0,
            members: Vec::new(),
            freed: Vec::new(),
            time: 0,
            stamp: 0,
            mark_stamp: 0,
            heap: RadixHeap::new(),
            scratch: Vec::new(),
            paths: [Vec::new(), Vec::new()],
            stats: BlossomStats::default(),
        }
    }

    /// Runs the algorithm of the module doc: the matched edges in increasing order, the
    /// certificate and the figures.
    fn solve(mut self) -> Result<(Vec<u32>, Certificate, BlossomStats), WeightedError> {
        let start = Instant::now();
        self.greedy_init();
        self.stats.greedy_seconds = start.elapsed().as_secs_f64();
        let start = Instant::now();
        self.grow_forest(true)?;
        self.round_half_cycles();
        self.stats.fractional_seconds = start.elapsed().as_secs_f64();
        self.stats.exposed_after_fractional = (0..self.n)
            .filter(|&v| self.is_live[v] && self.slots[v].mate == NONE)
            .count();
        self.grow_forest(false)?;
        self.stats.search_seconds = start.elapsed().as_secs_f64();
        // In increasing order: each matched edge from the mate of its first end.
        let edges: Vec<u32> = (0..self.edges.len() as u32)
            .filter(|&e| {
                let [u, _] = self.edges[e as usize].ends;
                u != NONE && self.slots[u as usize].mate == e
            })
            .collect();
        let certificate = self.certificate();
        self.stats.blossoms = certificate.blossoms.len();
        Ok((edges, certificate, self.stats))
    }

    #[inline]
    fn is_blossom(&self, x: u32) -> bool {
        x as usize >= self.n
    }

    #[inline]
    fn other_end(&self, e: u32, v: u32) -> u32 {
        let [a, b] = self.edges[e as usize].ends;
        if a == v { b } else { a }
    }

    /// The non-loop `(edge, neighbour)` pairs of vertex `v` (its record's, then its extra ones).
    #[inline]
    fn edges_of(&self, v: u32) -> impl Iterator<Item = (u32, u32)> + use<X> {
        self.extra.edges_of(self.slots[v as usize].adjacent, v)
    }

    fn greedy_init(&mut self) {
        for v in 0..self.n as u32 {
            let min = self
                .edges_of(v)
                .map(|(e, _)| self.edges[e as usize].cost)
                .min();
            if let Some(min) = min {
                self.y[v as usize] = min / 2;
            }
        }
        for v in 0..self.n as u32 {
            if self.slots[v as usize].mate != NONE {
                continue;
            }
            let slack = |s: &Self, e: u32, w: u32| {
                s.edges[e as usize].cost - s.y[v as usize] - s.y[w as usize]
            };
            let Some(min) = self.edges_of(v).map(|(e, w)| slack(self, e, w)).min() else {
                continue;
            };
            self.y[v as usize] += min;
            let pick = self
                .edges_of(v)
                .find(|&(e, w)| slack(self, e, w) == 0 && self.slots[w as usize].mate == NONE);
            if let Some((e, w)) = pick {
                self.slots[v as usize].mate = e;
                self.slots[w as usize].mate = e;
            }
        }
        // Augmenting paths of three tight edges: exposed v, w = x matched, z exposed.
        for v in 0..self.n as u32 {
            if self.slots[v as usize].mate != NONE {
                continue;
            }
            let tight = |s: &Self, e: u32, a: u32, b: u32| {
                s.edges[e as usize].cost == s.y[a as usize] + s.y[b as usize]
            };
            'paths: for (e, w) in self.edges_of(v) {
                let m = self.slots[w as usize].mate;
                if m == NONE || !tight(self, e, v, w) {
                    continue;
                }
                let x = self.other_end(m, w);
                for (f, z) in self.edges_of(x) {
                    if z != w
                        && z != v
                        && self.slots[z as usize].mate == NONE
                        && tight(self, f, x, z)
                    {
                        self.slots[v as usize].mate = e;
                        self.slots[w as usize].mate = e;
                        self.slots[x as usize].mate = f;
                        self.slots[z as usize].mate = f;
                        break 'paths;
                    }
                }
            }
        }
        for (slot, &y) in self.slots.iter_mut().zip(&self.y) {
            slot.pi = y;
        }
    }

    /// The vertices of outermost node `x`, from its set's list, into `out` (cleared first).
    fn collect_vertices(&self, x: u32, out: &mut Vec<u32>) {
        out.clear();
        if !self.is_blossom(x) {
            // An outermost vertex is alone in its set.
            out.push(x);
            return;
        }
        let mut v = self.set_head[self.node_set[x as usize] as usize];
        while v != NONE {
            out.push(v);
            v = self.set_next[v as usize];
        }
    }

    /// The outermost node holding vertex `v`.
    #[inline]
    fn outer_of(&self, v: u32) -> u32 {
        self.slots[self.slots[v as usize].set as usize].outer
    }

    /// The dual change of outermost node `x` since it joined its tree (0 if free).
    #[inline]
    fn offset(&self, x: u32) -> i64 {
        let d = self.time - self.slots[x as usize].join_time;
        match self.slots[x as usize].label {
            PLUS => d,
            MINUS => -d,
            _ => 0,
        }
    }

    #[inline]
    fn pi_now(&self, v: u32) -> i64 {
        let set = self.slots[v as usize].set as usize;
        self.slots[v as usize].pi + self.slots[set].acc + self.offset(self.slots[set].outer)
    }

    /// Reduced cost of edge `e` between two different outermost nodes, now.
    #[inline]
    /// (`u` and `v` are its ends, in either order.)
    fn slack(&self, e: u32, u: u32, v: u32) -> i64 {
        self.edges[e as usize].cost - self.pi_now(u) - self.pi_now(v)
    }

    /// Applies the lazy dual change of outermost node `x` to its dual and to its `acc` (the
    /// change its vertices' `π` owe it), and restarts its clock at the current time. O(1).
    fn settle(&mut self, x: u32) {
        let d = self.offset(x);
        self.y[x as usize] += d;
        self.slots[self.node_set[x as usize] as usize].acc += d;
        self.slots[x as usize].join_time = self.time;
    }

    /// Queues an event for edge `e` between vertices `u` and `v`, `delay` after now.
    #[inline]
    fn push_edge(&mut self, e: u32, u: u32, v: u32, delay: i64) {
        let event = Event {
            id: e,
            a: u,
            b: v,
            kind: EDGE_EVENT,
        };
        self.heap.push((self.time + delay) as u64, event);
    }

    /// Labels outermost node `x` as a node of `tree`.
    fn join(&mut self, x: u32, label: u8, tree: u32) {
        self.slots[x as usize].label = label;
        self.slots[x as usize].join_time = self.time;
        self.stamp = self.stamp.wrapping_add(1);
        self.join_stamp[x as usize] = self.stamp;
        self.tree[x as usize] = tree;
        let first = self.trees[tree as usize];
        self.trees[tree as usize] = self.members.len() as u32;
        self.members.push((x, first));
        self.stats.tree_nodes += 1;
        if label == MINUS && self.is_blossom(x) {
            let event = Event {
                id: x,
                a: self.stamp,
                b: NONE,
                kind: EXPAND_EVENT,
            };
            self.heap
                .push((self.time + self.y[x as usize]) as u64, event);
        }
    }

    /// Queues the events of the edges of `x`'s vertices, `x` having just become `+` (or part of
    /// a `+` blossom): to free nodes (GROW at full reduced cost) and to other `+` nodes (SHRINK at
    /// half of it).
    fn scan_plus(&mut self, x: u32) {
        let mut vertices = std::mem::take(&mut self.scratch);
        self.collect_vertices(x, &mut vertices);
        self.scan_plus_vertices(&vertices);
        self.scratch = vertices;
    }

    /// [`Solver::scan_plus`] for the given vertices (of `+` nodes).
    fn scan_plus_vertices(&mut self, vertices: &[u32]) {
        for &v in vertices {
            let own = self.outer_of(v);
            for (e, w) in self.edges_of(v) {
                let other = self.outer_of(w);
                if other == own {
                    continue;
                }
                match self.slots[other as usize].label {
                    FREE => self.push_edge(e, v, w, self.slack(e, v, w)),
                    PLUS => {
                        let s = self.slack(e, v, w);
                        debug_assert!(s % 2 == 0, "odd reduced cost {s} between + nodes");
                        self.push_edge(e, v, w, s / 2);
                    }
                    _ => {}
                }
            }
        }
    }

    /// Queues GROW events for the edges from `x`'s vertices (`x` free) to `+` nodes.
    fn scan_free(&mut self, x: u32) {
        let mut vertices = std::mem::take(&mut self.scratch);
        self.collect_vertices(x, &mut vertices);
        for &v in &vertices {
            for (e, w) in self.edges_of(v) {
                let other = self.outer_of(w);
                if other != x && self.slots[other as usize].label == PLUS {
                    self.push_edge(e, v, w, self.slack(e, v, w));
                }
            }
        }
        self.scratch = vertices;
    }

    /// Every exposed vertex roots a `+` tree; all trees grow under one clock until every tree
    /// has augmented.
    ///
    /// With `fractional` (Blossom V's fractional initialisation, Kolmogorov 2009, Section 5.1),
    /// no blossom is made: a tight edge closing an odd cycle in a tree augments the tree's root
    /// path up to the cycle, whose nodes are then covered by half-edges (the fractional optimum
    /// without odd-set constraints is half-integral); a tree reaching such a cycle augments into
    /// it (the rest of the cycle is then matched along it). At the end one node per remaining
    /// cycle is left exposed, the others matched along it: the duals are still feasible and every
    /// matched edge tight, and few nodes are exposed.
    fn grow_forest(&mut self, fractional: bool) -> Result<(), WeightedError> {
        self.time = 0;
        self.heap.clear();
        // Every tree of a previous phase has dissolved.
        self.trees.clear();
        self.members.clear();
        self.members.reserve(2 * self.n);
        let roots: Vec<u32> = (0..self.n as u32)
            .filter(|&v| self.is_live[v as usize] && self.slots[v as usize].mate == NONE)
            .collect();
        if fractional {
            self.stats.exposed_after_greedy = roots.len();
        }
        for &r in &roots {
            // All roots of one parity (see the module doc): lowering a dual keeps feasibility.
            if (self.slots[r as usize].pi + self.slots[self.slots[r as usize].set as usize].acc) % 2
                != 0
            {
                self.slots[r as usize].pi -= 1;
                self.y[r as usize] -= 1;
            }
            let tree = self.trees.len() as u32;
            self.trees.push(NONE);
            self.join(r, PLUS, tree);
        }
        self.active_trees = roots.len();
        for &r in &roots {
            self.scan_plus(r);
        }
        // A cooperative stop (Ctrl-C from Python) is read every few thousand events.
        let mut ticker = surftopo_mesh::stop::Ticker::default();
        while self.active_trees > 0 {
            ticker.tick();
            let Some((time, event)) = self.heap.pop() else {
                let node = (0..self.n as u32)
                    .find(|&v| self.is_live[v as usize] && self.slots[v as usize].mate == NONE)
                    .unwrap_or(0);
                return Err(WeightedError::NoPerfectMatching { node });
            };
            self.stats.events += 1;
            debug_assert!(time as i64 >= self.time, "events go forward in time");
            self.time = time as i64;
            if let Some(next) = self.heap.peek() {
                // The next event's records, read ahead (an event's vertices are far apart).
                if next.kind == EDGE_EVENT {
                    prefetch_index(&self.slots, next.a as usize);
                    prefetch_index(&self.slots, next.b as usize);
                    prefetch_index(&self.edges, next.id as usize);
                }
            }
            if event.kind == EXPAND_EVENT {
                let b = event.id;
                if self.parent[b as usize] != NONE
                    || self.slots[b as usize].label != MINUS
                    || self.join_stamp[b as usize] != event.a
                    || !self.live_blossom[b as usize - self.n]
                {
                    continue;
                }
                self.expand(b);
                continue;
            }
            let (e, u, v) = (event.id, event.a, event.b);
            let (ou, ov) = (self.outer_of(u), self.outer_of(v));
            if ou == ov {
                continue;
            }
            let (lu, lv) = (self.slots[ou as usize].label, self.slots[ov as usize].label);
            let s = self.slack(e, u, v);
            debug_assert!(s >= 0, "negative reduced cost {s} on edge {e}");
            match (lu, lv) {
                (PLUS, PLUS) => {
                    if s > 0 {
                        self.push_edge(e, u, v, s / 2);
                    } else if self.tree[ou as usize] == self.tree[ov as usize] {
                        if fractional {
                            self.half_cycle(e);
                        } else {
                            self.shrink(e);
                        }
                    } else {
                        self.augment(e);
                    }
                }
                (PLUS, FREE) | (FREE, PLUS) => {
                    if s > 0 {
                        self.push_edge(e, u, v, s);
                        continue;
                    }
                    let (inner, outside) = if lu == PLUS { (u, v) } else { (v, u) };
                    if self.half_cycle_of[outside as usize] != NONE {
                        self.augment_into_half_cycle(e, inner, outside);
                    } else {
                        self.grow(e, inner, outside);
                    }
                }
                _ => {}
            }
        }
        Ok(())
    }

    /// GROW: the free (matched) node of vertex `w` joins the tree of vertex `inner` as `−`
    /// through tight edge `e`, its mate as `+`.
    fn grow(&mut self, e: u32, inner: u32, w: u32) {
        self.stats.grows += 1;
        let tree = self.tree[self.outer_of(inner) as usize];
        let x = self.outer_of(w);
        self.tree_edge[x as usize] = e;
        self.tree_vertex[x as usize] = w;
        self.join(x, MINUS, tree);
        let b = self.base[x as usize];
        let m = self.slots[b as usize].mate;
        let partner = self.outer_of(self.other_end(m, b));
        debug_assert_eq!(self.slots[partner as usize].label, FREE);
        self.join(partner, PLUS, tree);
        self.scan_plus(partner);
    }

    /// The `+` parent of `+` node `x` in the tree (`NONE` for the root).
    fn plus_parent(&self, x: u32) -> u32 {
        let b = self.base[x as usize];
        let m = self.slots[b as usize].mate;
        if m == NONE {
            return NONE;
        }
        let minus = self.outer_of(self.other_end(m, b));
        let tv = self.tree_vertex[minus as usize];
        self.outer_of(self.other_end(self.tree_edge[minus as usize], tv))
    }

    /// The outermost nodes from `from` up its tree to `top` (both included), into `out`.
    fn path_up(&self, from: u32, top: u32, out: &mut Vec<u32>) {
        out.clear();
        out.push(from);
        let mut x = from;
        while x != top {
            let (_, _, up) = self.parent_link(x);
            x = self.outer_of(up);
            out.push(x);
        }
    }

    /// The edge from node `x` to its tree parent, as `(edge, vertex in x, vertex in parent)`.
    fn parent_link(&self, x: u32) -> (u32, u32, u32) {
        if self.slots[x as usize].label == PLUS {
            let b = self.base[x as usize];
            let m = self.slots[b as usize].mate;
            (m, b, self.other_end(m, b))
        } else {
            let e = self.tree_edge[x as usize];
            let v = self.tree_vertex[x as usize];
            (e, v, self.other_end(e, v))
        }
    }

    /// SHRINK: tight edge `e` joins two `+` nodes of the tree; the cycle through their lowest
    /// common ancestor becomes a `+` blossom with dual 0.
    /// The odd cycle closed by tight edge `e` between two `+` nodes of one tree: its lowest
    /// common ancestor, the cycle's nodes from the LCA (the cycle order of a blossom's children)
    /// and its edges as `(edge, vertex in node i, vertex in node i + 1)`.
    #[allow(clippy::type_complexity)]
    fn odd_cycle(&mut self, e: u32) -> (u32, Vec<u32>, Vec<(u32, u32, u32)>) {
        let [u, v] = self.edges[e as usize].ends;
        let (ou, ov) = (self.outer_of(u), self.outer_of(v));
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
        // The two paths up to the LCA, through the `−` nodes (buffers kept between calls).
        let [mut path_u, mut path_v] = std::mem::take(&mut self.paths);
        self.path_up(ou, lca, &mut path_u);
        self.path_up(ov, lca, &mut path_v);
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
        self.paths = [path_u, path_v];
        (lca, children, cycle)
    }

    fn shrink(&mut self, e: u32) {
        self.stats.shrinks += 1;
        let (lca, children, cycle) = self.odd_cycle(e);
        let blossom = self.new_blossom();
        for &c in &children {
            self.settle(c);
            self.parent[c as usize] = blossom;
        }
        let bi = blossom as usize;
        self.base[bi] = self.base[lca as usize];
        self.y[bi] = 0;
        self.parent[bi] = NONE;
        // The `−` children's vertices, to scan as `+` once merged.
        let mut minus_vertices = Vec::new();
        let mut vertices = std::mem::take(&mut self.scratch);
        for &c in &children {
            if self.slots[c as usize].label == MINUS {
                self.collect_vertices(c, &mut vertices);
                minus_vertices.extend_from_slice(&vertices);
            }
        }
        self.scratch = vertices;
        // Merge the children's sets into the largest one: its list, then the others' in turn, each
        // child's list kept as its segment of the blossom's.
        for &c in &children {
            let set = self.node_set[c as usize] as usize;
            self.segment[c as usize] = [self.set_head[set], self.set_tail[set], self.set_size[set]];
        }
        let big = children
            .iter()
            .map(|&c| self.node_set[c as usize])
            .max_by_key(|&set| (self.set_size[set as usize], std::cmp::Reverse(set)))
            .expect("a blossom has children");
        for &c in &children {
            let set = self.node_set[c as usize];
            if set == big {
                continue;
            }
            let delta = self.slots[set as usize].acc - self.slots[big as usize].acc;
            let mut w = self.set_head[set as usize];
            while w != NONE {
                self.slots[w as usize].pi += delta;
                self.slots[w as usize].set = big;
                w = self.set_next[w as usize];
            }
            let tail = self.set_tail[big as usize];
            self.set_next[tail as usize] = self.set_head[set as usize];
            self.set_tail[big as usize] = self.set_tail[set as usize];
            self.set_size[big as usize] += self.set_size[set as usize];
        }
        self.node_set[bi] = big;
        self.slots[big as usize].outer = blossom;
        self.children[bi - self.n] = children;
        self.cycle[bi - self.n] = cycle;
        let tree = self.tree[lca as usize];
        self.join(blossom, PLUS, tree);
        self.scan_plus_vertices(&minus_vertices);
    }

    /// A new blossom slot (slots are never reused, so that the trees' node lists stay valid).
    fn new_blossom(&mut self) -> u32 {
        let b = self.parent.len() as u32;
        self.slots.push(Slot::new(b));
        self.tree.push(NONE);
        self.segment.push([NONE, NONE, 0]);
        self.slots[b as usize].outer = NONE;
        self.parent.push(NONE);
        self.y.push(0);
        self.join_stamp.push(0);
        self.tree_edge.push(NONE);
        self.tree_vertex.push(NONE);
        self.base.push(NONE);
        self.mark.push(0);
        self.children.push(Vec::new());
        self.cycle.push(Vec::new());
        self.live_blossom.push(true);
        self.node_set.push(NONE);
        self.set_head.push(NONE);
        self.set_tail.push(NONE);
        self.set_size.push(0);
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
        // The children's lists are their segments of the blossom's list (see `segment`). The
        // child holding the node whose id names the blossom's set keeps that set (a dead blossom's
        // id, or the blossom's own, may go to any child: the largest); the others get sets of
        // their own (id: their node id), owing what the blossom's set owed. So only the other
        // children's vertices are relabelled, and no `π` changes.
        let set = self.node_set[b as usize];
        let owed = self.slots[set as usize].acc;
        let holder =
            if set == b || (self.is_blossom(set) && !self.live_blossom[set as usize - self.n]) {
                None
            } else {
                let mut x = set;
                while self.parent[x as usize] != b {
                    x = self.parent[x as usize];
                }
                Some(x)
            };
        let keep = holder.unwrap_or_else(|| {
            *children
                .iter()
                .max_by_key(|&&c| (self.segment[c as usize][2], std::cmp::Reverse(c)))
                .expect("a blossom has children")
        });
        for &c in &children {
            self.parent[c as usize] = NONE;
            self.slots[c as usize].label = FREE;
            let [head, tail, size] = self.segment[c as usize];
            self.set_next[tail as usize] = NONE;
            let own = if c == keep { set } else { c };
            self.node_set[c as usize] = own;
            self.set_head[own as usize] = head;
            self.set_tail[own as usize] = tail;
            self.set_size[own as usize] = size;
            self.slots[own as usize].outer = c;
            if own != set {
                self.slots[own as usize].acc = owed;
                let mut w = head;
                while w != NONE {
                    self.slots[w as usize].set = own;
                    w = self.set_next[w as usize];
                }
            }
        }
        self.live_blossom[bi] = false;
        self.slots[b as usize].label = FREE;
        let tree = self.tree[b as usize];
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
                self.join(c, MINUS, tree);
            } else {
                self.join(c, PLUS, tree);
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

    /// AUGMENT along tight edge `e` between the `+` nodes of two trees: the paths from its ends
    /// to the two roots alternate (every blossom on them rotated to its new base), and both trees
    /// dissolve.
    fn augment(&mut self, e: u32) {
        let [u, v] = self.edges[e as usize].ends;
        let trees = [
            self.tree[self.outer_of(u) as usize],
            self.tree[self.outer_of(v) as usize],
        ];
        for end in [u, v] {
            self.augment_to_root(end, e);
        }
        self.dissolve(&trees);
    }

    /// Fractional phase: tight edge `e` closes an odd cycle in its tree. The path from the
    /// cycle's top node to the root alternates (the root is matched, the top node exposed), the
    /// cycle's nodes become a half-edge cycle, and the tree dissolves.
    fn half_cycle(&mut self, e: u32) {
        let tree = self.tree[self.outer_of(self.edges[e as usize].ends[0]) as usize];
        let (lca, nodes, edges) = self.odd_cycle(e);
        let old_mate = self.slots[lca as usize].mate;
        if old_mate != NONE {
            let z = self.other_end(old_mate, lca);
            let p = self.tree_edge[z as usize];
            let entry = self.other_end(p, z);
            self.augment_to_root(entry, p);
            self.slots[z as usize].mate = p;
        }
        let id = self.half_cycles.len() as u32;
        for &c in &nodes {
            self.slots[c as usize].mate = NONE;
            self.half_cycle_of[c as usize] = id;
        }
        self.half_cycles.push(
            nodes
                .iter()
                .zip(&edges)
                .map(|(&c, &(f, _, _))| (c, f))
                .collect(),
        );
        self.dissolve(&[tree]);
    }

    /// Fractional phase: tight edge `e` from `inner` (in a tree) reaches `w` on a half-edge
    /// cycle. The tree path augments, `w` is matched along `e`, the rest of the cycle along it.
    fn augment_into_half_cycle(&mut self, e: u32, inner: u32, w: u32) {
        let tree = self.tree[self.outer_of(inner) as usize];
        self.augment_to_root(inner, e);
        self.slots[w as usize].mate = e;
        let id = self.half_cycle_of[w as usize];
        self.match_half_cycle(id, w);
        self.dissolve(&[tree]);
    }

    /// Matches half-edge cycle `id` along itself, all but vertex `exposed` (left as it is).
    fn match_half_cycle(&mut self, id: u32, exposed: u32) {
        let cycle = std::mem::take(&mut self.half_cycles[id as usize]);
        let k = cycle.len();
        let i = cycle
            .iter()
            .position(|&(c, _)| c == exposed)
            .expect("on the cycle");
        for j in 0..k / 2 {
            let (a, edge) = cycle[(i + 1 + 2 * j) % k];
            let (b, _) = cycle[(i + 2 + 2 * j) % k];
            self.slots[a as usize].mate = edge;
            self.slots[b as usize].mate = edge;
        }
        for &(c, _) in &cycle {
            self.half_cycle_of[c as usize] = NONE;
        }
    }

    /// Ends the growth of `trees`: their nodes' duals settled and labels cleared. The edges from
    /// the other trees' `+` nodes to the freed nodes now shrink at rate 1: those to a former `+`
    /// node already have an event (queued when the second of their ends became `+`), which comes
    /// early and is queued again when popped; those to a former `−` node had none, so the `−`
    /// nodes are scanned.
    fn dissolve(&mut self, trees: &[u32]) {
        let mut freed = std::mem::take(&mut self.freed);
        for &tree in trees {
            let mut entry = std::mem::replace(&mut self.trees[tree as usize], NONE);
            while entry != NONE {
                let (x, next) = self.members[entry as usize];
                entry = next;
                let live = !self.is_blossom(x) || self.live_blossom[x as usize - self.n];
                if live
                    && self.parent[x as usize] == NONE
                    && self.slots[x as usize].label != FREE
                    && self.tree[x as usize] == tree
                {
                    self.settle(x);
                    self.tree[x as usize] = NONE;
                    let slot = &mut self.slots[x as usize];
                    let was_minus = slot.label == MINUS;
                    slot.label = FREE;
                    if was_minus {
                        freed.push(x);
                    }
                }
            }
        }
        self.active_trees -= trees.len();
        for &x in &freed {
            self.scan_free(x);
        }
        freed.clear();
        self.freed = freed;
    }

    /// Flips the tree path from vertex `entry` (matched along `edge` from now on) up to its root.
    fn augment_to_root(&mut self, mut entry: u32, mut edge: u32) {
        let mut x = self.outer_of(entry);
        loop {
            let old_base = self.base[x as usize];
            let old_mate = self.slots[old_base as usize].mate;
            self.rotate(x, entry);
            self.slots[entry as usize].mate = edge;
            if old_mate == NONE {
                break;
            }
            let minus = self.outer_of(self.other_end(old_mate, old_base));
            let p = self.tree_edge[minus as usize];
            let pv = self.tree_vertex[minus as usize];
            self.rotate(minus, pv);
            self.slots[pv as usize].mate = p;
            entry = self.other_end(p, pv);
            x = self.outer_of(entry);
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
                s.slots[a as usize].mate = edge;
                s.slots[bb as usize].mate = edge;
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

    /// After the fractional phase: each remaining half-edge cycle matched along itself but for its
    /// first node, left exposed.
    fn round_half_cycles(&mut self) {
        for id in 0..self.half_cycles.len() as u32 {
            if let Some(&(first, _)) = self.half_cycles[id as usize].first() {
                self.match_half_cycle(id, first);
            }
        }
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
