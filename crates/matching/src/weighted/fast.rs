//! A fast, deterministic, not necessarily optimal low-cost perfect matching: a cost-ordered
//! greedy matching, completed to a perfect one by augmenting paths, then improved along short
//! negative alternating cycles.
//!
//! 1. *Greedy*: the live non-loop edges in increasing `(cost, edge id)` order; an edge whose two
//!    ends are free is matched (the greedy of Remacle et al. 2012, Section 3, before their exact
//!    step).
//! 2. *Completion*: [`crate::augment_to_perfect`] (the blossom searches of `augment`,
//!    Forest strategy) pairs the nodes the greedy left exposed; it ignores costs.
//! 3. *Improvement*: an alternating cycle `C` (matched and unmatched edges in turn) whose unmatched
//!    edges cost less than its matched ones is exchanged (`M ← M △ C`), which keeps the matching
//!    perfect and lowers its cost. Cycles with at most [`MAX_CYCLE_PAIRS`] matched edges are
//!    enumerated by a depth-first search from a matched edge, the first negative cycle found
//!    being exchanged; the matched edges are examined from a worklist (all in id order, then
//!    those near each exchange) until it is empty.
//!    A perfect matching is optimal iff no negative alternating cycle exists (of any length), so
//!    the result is optimal only with respect to these short exchanges.
//!
//! Complexity: O(m log m) for the sort, the completion as in `augment`, and
//! O(2^K) per examined edge for K = [`MAX_CYCLE_PAIRS`] on a cubic graph (each exchange adds O(K)
//! edges to the worklist).

use std::collections::VecDeque;
use std::time::Instant;

use super::{WeightedError, check_costs};
use crate::augment::{AugmentStrategy, augment_to_maximum, augment_to_perfect};
use crate::dual_graph::{DualGraph, NONE, Pairing};

/// Largest number of matched edges on an exchanged cycle (cycles of up to 8 edges).
pub const MAX_CYCLE_PAIRS: usize = 4;

/// Figures of one [`fast_min_cost_perfect_matching`] run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FastStats {
    /// Nodes the greedy left exposed.
    pub exposed_after_greedy: usize,
    /// Cost after the completion, before the improvement.
    pub cost_before_improvement: i64,
    /// Cycles exchanged.
    pub exchanges: u64,
    /// Matched edges examined as a cycle's start.
    pub examined: u64,
    /// Seconds of the greedy, of the completion and of the improvement.
    pub greedy_seconds: f64,
    /// See `greedy_seconds`.
    pub completion_seconds: f64,
    /// See `greedy_seconds`.
    pub improvement_seconds: f64,
}

/// The fast mode's perfect matching.
#[derive(Clone, Debug, PartialEq)]
pub struct FastMatching {
    /// The matched edges, in increasing order.
    pub edges: Vec<u32>,
    /// Their total cost.
    pub cost: i64,
    /// How the run went.
    pub stats: FastStats,
}

/// A low-cost perfect matching of `graph` for `costs` (one per edge slot), by the three steps of
/// the module doc. Deterministic.
///
/// # Errors
/// [`WeightedError::CostCount`] / [`WeightedError::CostOutOfRange`] for bad costs, and
/// [`WeightedError::Augment`] when the completion fails (odd node count, no perfect matching).
pub fn fast_min_cost_perfect_matching<G: DualGraph + ?Sized>(
    graph: &G,
    costs: &[i64],
) -> Result<FastMatching, WeightedError> {
    fast(graph, costs, false)
}

/// The fast mode for a graph without a perfect matching (the dual of a surface with boundary):
/// the steps of [`fast_min_cost_perfect_matching`], the completion by augmenting paths to a
/// *maximum* matching ([`crate::augment_to_maximum`]), so that as few nodes as possible stay
/// unmatched; the exchanges along alternating cycles keep its size. Not of least cost in
/// general (an exchange that moves an unmatched node is not tried).
///
/// # Errors
/// [`WeightedError::CostCount`] / [`WeightedError::CostOutOfRange`] for bad costs.
pub fn fast_min_cost_maximum_matching<G: DualGraph + ?Sized>(
    graph: &G,
    costs: &[i64],
) -> Result<FastMatching, WeightedError> {
    fast(graph, costs, true)
}

fn fast<G: DualGraph + ?Sized>(
    graph: &G,
    costs: &[i64],
    maximum: bool,
) -> Result<FastMatching, WeightedError> {
    check_costs(graph, costs)?;
    let mut order: Vec<u32> = Vec::with_capacity(graph.edge_slots());
    for e in 0..graph.edge_slots() as u32 {
        if !graph.is_edge(e) {
            continue;
        }
        let [a, b] = graph.endpoints(e);
        if a != b {
            order.push(e);
        }
    }
    let mut stats = FastStats::default();
    let start = Instant::now();
    order.sort_unstable_by_key(|&e| (costs[e as usize], e));
    let mut mate = vec![NONE; graph.node_slots()];
    // A cooperative stop (Ctrl-C from Python) is read every few thousand edges examined.
    let mut ticker = surftopo_mesh::stop::Ticker::default();
    for &e in &order {
        ticker.tick();
        let [a, b] = graph.endpoints(e);
        if mate[a as usize] == NONE && mate[b as usize] == NONE {
            mate[a as usize] = e;
            mate[b as usize] = e;
        }
    }
    let greedy: Vec<u32> = order
        .iter()
        .copied()
        .filter(|&e| mate[graph.endpoints(e)[0] as usize] == e)
        .collect();
    let mut pairing = Pairing::from_edges(graph, greedy).expect("the greedy builds a matching");
    stats.exposed_after_greedy = pairing.unmatched_count(graph);
    stats.greedy_seconds = start.elapsed().as_secs_f64();
    let start = Instant::now();
    if maximum {
        augment_to_maximum(graph, &mut pairing, AugmentStrategy::Forest)
            .map_err(WeightedError::Augment)?;
    } else {
        augment_to_perfect(graph, &mut pairing, AugmentStrategy::Forest)
            .map_err(WeightedError::Augment)?;
    }
    stats.completion_seconds = start.elapsed().as_secs_f64();
    let mut mate = pairing.mates().to_vec();
    stats.cost_before_improvement = total_cost(graph, &mate, costs);
    let start = Instant::now();
    improve(graph, costs, &mut mate, &mut stats);
    stats.improvement_seconds = start.elapsed().as_secs_f64();
    let mut edges: Vec<u32> = (0..mate.len() as u32)
        .filter(|&v| mate[v as usize] != NONE && graph.endpoints(mate[v as usize])[0] == v)
        .map(|v| mate[v as usize])
        .collect();
    edges.sort_unstable();
    let cost = edges.iter().map(|&e| costs[e as usize]).sum();
    Ok(FastMatching { edges, cost, stats })
}

fn total_cost<G: DualGraph + ?Sized>(graph: &G, mate: &[u32], costs: &[i64]) -> i64 {
    (0..mate.len() as u32)
        .filter(|&v| mate[v as usize] != NONE && graph.endpoints(mate[v as usize])[0] == v)
        .map(|v| costs[mate[v as usize] as usize])
        .sum()
}

/// Negative alternating cycle exchanges (step 3 of the module doc), from a first-in first-out
/// worklist of matched edges: all of them in id order at first, then, after each exchange, the
/// matched edges at and next to the exchanged cycle's nodes. Ends when the worklist is empty:
/// every matched edge was examined since the last exchange near it. Each exchange lowers the
/// integer cost, so it ends.
fn improve<G: DualGraph + ?Sized>(
    graph: &G,
    costs: &[i64],
    mate: &mut [u32],
    stats: &mut FastStats,
) {
    let mut queue: VecDeque<u32> = VecDeque::new();
    let mut queued = vec![false; graph.edge_slots()];
    for v in 0..mate.len() as u32 {
        let e = mate[v as usize];
        if e != NONE && graph.endpoints(e)[0] == v {
            queued[e as usize] = true;
            queue.push_back(e);
        }
    }
    let mut cycle: Vec<u32> = Vec::with_capacity(2 * MAX_CYCLE_PAIRS);
    while let Some(e) = queue.pop_front() {
        queued[e as usize] = false;
        let [a, b] = graph.endpoints(e);
        if mate[a as usize] != e {
            continue;
        }
        stats.examined += 1;
        cycle.clear();
        let mut path = [NONE; 2 * MAX_CYCLE_PAIRS];
        path[0] = a;
        path[1] = b;
        if !find_cycle(
            graph,
            costs,
            mate,
            &mut path,
            2,
            costs[e as usize],
            &mut cycle,
        ) {
            continue;
        }
        // `cycle` holds the unmatched edges of the cycle; its matched ones are the mates of
        // their ends.
        let nodes: Vec<u32> = cycle.iter().flat_map(|&f| graph.endpoints(f)).collect();
        for &x in &nodes {
            mate[x as usize] = NONE;
        }
        for &f in &cycle {
            let [x, y] = graph.endpoints(f);
            mate[x as usize] = f;
            mate[y as usize] = f;
        }
        stats.exchanges += 1;
        for &x in &nodes {
            for (_, w) in graph.adjacent(x) {
                if w == NONE {
                    continue;
                }
                let f = mate[w as usize];
                if f != NONE && !queued[f as usize] {
                    queued[f as usize] = true;
                    queue.push_back(f);
                }
            }
        }
    }
}

/// Depth-first search for a negative alternating cycle through the path `path[..len]` (matched
/// pairs `path[2i], path[2i + 1]`, consecutive pairs joined by unmatched edges), whose matched
/// edges cost `gain` minus the unmatched ones so far. Fills `cycle` with the cycle's unmatched
/// edges on success.
fn find_cycle<G: DualGraph + ?Sized>(
    graph: &G,
    costs: &[i64],
    mate: &[u32],
    path: &mut [u32; 2 * MAX_CYCLE_PAIRS],
    len: usize,
    gain: i64,
    cycle: &mut Vec<u32>,
) -> bool {
    let last = path[len - 1];
    for (f, c) in graph.adjacent(last) {
        if f == NONE || c == last || mate[last as usize] == f {
            continue;
        }
        let after = gain - costs[f as usize];
        if c == path[0] {
            if len >= 4 && after > 0 {
                cycle.push(f);
                return true;
            }
            continue;
        }
        if len == path.len() || path[..len].contains(&c) {
            continue;
        }
        let m = mate[c as usize];
        if m == NONE {
            // An unmatched node (a maximum matching): no cycle through it.
            continue;
        }
        let d = graph.opposite(m, c);
        if path[..len].contains(&d) {
            continue;
        }
        path[len] = c;
        path[len + 1] = d;
        if find_cycle(
            graph,
            costs,
            mate,
            path,
            len + 2,
            after + costs[m as usize],
            cycle,
        ) {
            cycle.push(f);
            return true;
        }
    }
    false
}
