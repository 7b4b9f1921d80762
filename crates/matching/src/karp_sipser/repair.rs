//! Phase 3 of KS: the repairs. A node whose free degree drops to 0 while it is unpaired is
//! *isolated*: the greedy alone would leave it unpaired. It is repaired at once, while the part
//! of the graph not yet reached by the greedy is near, so that a short augmenting path to one of
//! its free nodes usually exists:
//! 1. a depth-first alternating search with lookahead (Pothen and Fan's heuristic), blossoms
//!    ignored, at most [`DFS_BUDGET`] nodes: cheap, and enough for most repairs;
//! 2. else an Edmonds search from the node ([`crate::augment`], blossoms included) limited to the
//!    repair budget ([`super::KarpSipserOptions::repair_budget`] reached nodes).
//!
//! A repair that exceeds both budgets is abandoned and the node *deferred* to the completion.
//! Once every unpaired node is isolated (the greedy is over), the searches are skipped and the
//! nodes deferred at once: a path can only end at another isolated node, and those whose repairs
//! failed are far apart.

use super::Pairs;
use super::band::Band;
use crate::augment::Outcome;
use crate::dual_graph::{DualGraph, NONE};

/// Nodes the depth-first first try of a repair may visit before the Edmonds search takes over
/// (a depth-first node costs less than an Edmonds one; with a smaller budget the Edmonds
/// searches of some inputs reach several times more nodes).
pub(super) const DFS_BUDGET: usize = 64;

/// The repairs' own state: the repair budget and the depth-first search.
pub(super) struct Repairs {
    /// Nodes a repair's Edmonds search may reach (0: no repair search at all).
    budget: usize,
    depth_first: DepthFirst,
}

impl Repairs {
    /// Repairs on `node_slots` node ids, whose Edmonds searches may reach `budget` nodes.
    pub(super) fn new(node_slots: usize, budget: usize) -> Self {
        Repairs {
            budget,
            depth_first: DepthFirst::new(node_slots),
        }
    }

    /// The depth-first search, which the guided completion reuses.
    pub(super) fn depth_first(&mut self) -> &mut DepthFirst {
        &mut self.depth_first
    }

    /// Repairs isolated node `u`: the depth-first search, else a bounded Edmonds search. Returns
    /// the free node at the other end of the augmenting path applied, or `None` when `u` is to be
    /// deferred (over both budgets, no path at all, or every unpaired node isolated).
    pub(super) fn repair<G: DualGraph + ?Sized>(
        &mut self,
        pairs: &mut Pairs<G>,
        u: u32,
    ) -> Option<u32> {
        pairs.stats.isolated += 1;
        // Every unpaired node isolated: the greedy is over, and a path from `u` can only end
        // at another isolated node, far away when its own repair failed; the completion pairs
        // them all at once.
        if pairs.unpaired == pairs.stranded {
            pairs.stats.augment.unmatched_before += 1;
            pairs.stats.skipped += 1;
            return None;
        }
        if self.budget > 0
            && let Some(other) = self.depth_first.search(pairs, u, DFS_BUDGET, None)
        {
            pairs.stats.repaired += 1;
            pairs.stats.augment.unmatched_before += 1;
            pairs.stats.augment.searches += 1;
            pairs.stats.augment.augmentations += 1;
            return Some(other);
        }
        pairs.stats.augment.unmatched_before += 1;
        pairs.stats.augment.searches += 1;
        match pairs.edmonds(u, self.budget, |_| true) {
            (Outcome::Augmented, other) => {
                pairs.stats.repaired += 1;
                return Some(other);
            }
            (Outcome::OverBudget, _) => pairs.stats.augment.abandoned += 1,
            // No augmenting path from u at all: the completion reports it.
            (Outcome::Exhausted, _) => {}
        }
        None
    }
}

/// The depth-first alternating search of the repairs and of the guided completion, with its
/// generation stamps and its path.
pub(super) struct DepthFirst {
    /// Generation stamps (nodes visited by the current search).
    stamp: Vec<u32>,
    generation: u32,
    /// The current depth-first path.
    stack: Vec<DfsFrame>,
}

/// One even node of the depth-first path of [`DepthFirst::search`].
#[derive(Clone, Copy)]
struct DfsFrame {
    node: u32,
    /// Its neighbour slots in the order to try them.
    order: [u8; 3],
    /// How many of `order` to try (guided: those whose mate has a label).
    len: u8,
    /// How many of `order` were tried.
    tried: u8,
    /// The edge into the odd node before it (`NONE` at the root).
    edge_in: u32,
}

impl DepthFirst {
    fn new(node_slots: usize) -> Self {
        DepthFirst {
            stamp: vec![0; node_slots],
            generation: 0,
            stack: Vec::new(),
        }
    }

    /// Depth-first alternating search from free `u` with lookahead (Pothen and Fan's heuristic
    /// for bipartite matching), without blossoms, visiting at most `budget` nodes; on success
    /// augments and returns the free end. Each node is visited at most once, so the path found
    /// is simple and a valid augmenting path even though blossoms are ignored; a path that only
    /// a blossom would reveal is left to the Edmonds search. With a `band`, only mates inside it
    /// are entered, in increasing key order (towards the far end of the band's path); otherwise
    /// every neighbour slot, in slot order.
    pub(super) fn search<G: DualGraph + ?Sized>(
        &mut self,
        pairs: &mut Pairs<G>,
        u: u32,
        budget: usize,
        band: Option<&Band>,
    ) -> Option<u32> {
        self.generation += 1;
        let generation = self.generation;
        self.stamp[u as usize] = generation;
        self.stack.clear();
        let root = frame(pairs, u, NONE, band);
        self.stack.push(root);
        let mut visited = 1usize;
        let found = 'search: loop {
            let &DfsFrame {
                node: v,
                order,
                len,
                tried,
                ..
            } = self.stack.last()?;
            let adjacent = pairs.graph.adjacent(v);
            if tried == 0 {
                // Lookahead: a free neighbour ends the path at once.
                for (e, w) in adjacent {
                    if w != v && w != u && pairs.is_free(w) {
                        break 'search (e, w);
                    }
                }
            }
            if tried == len {
                self.stack.pop();
                continue;
            }
            self.stack.last_mut().expect("not empty").tried += 1;
            let (e, w) = adjacent[usize::from(order[usize::from(tried)])];
            if w == v || self.stamp[w as usize] == generation || pairs.is_free(w) {
                continue;
            }
            let m = pairs.mates[w as usize][1];
            if self.stamp[m as usize] == generation {
                continue;
            }
            self.stamp[w as usize] = generation;
            self.stamp[m as usize] = generation;
            visited += 2;
            pairs.stats.augment.reached += 2;
            if visited > budget {
                return None;
            }
            self.stack.push(frame(pairs, m, e, band));
        };
        // Augment along the stack: v_k - found, then each v_{i-1} - w_i.
        let (mut e, mut x) = found;
        let end = x;
        while let Some(frame) = self.stack.pop() {
            let v = frame.node;
            let old_mate = pairs.mates[v as usize][1];
            pairs.mates[v as usize] = [e, x];
            pairs.mates[x as usize] = [e, v];
            if v == u {
                break;
            }
            // The odd node before v is its old mate; it pairs with the previous even node.
            e = frame.edge_in;
            x = old_mate;
        }
        Some(end)
    }
}

/// The depth-first frame of even node `v` entered through `edge_in`.
fn frame<G: DualGraph + ?Sized>(
    pairs: &Pairs<G>,
    v: u32,
    edge_in: u32,
    band: Option<&Band>,
) -> DfsFrame {
    let mut order = [0, 1, 2];
    let mut len = 3;
    if let Some(band) = band {
        let adjacent = pairs.graph.adjacent(v);
        let key = |slot: u8| {
            let w = adjacent[usize::from(slot)].1;
            if w == v || pairs.is_free(w) {
                return u32::MAX;
            }
            band.key(pairs.mates[w as usize][1]).unwrap_or(u32::MAX)
        };
        let keys = order.map(key);
        order.sort_unstable_by_key(|&slot| keys[usize::from(slot)]);
        len = keys.iter().filter(|&&k| k != u32::MAX).count() as u8;
    }
    DfsFrame {
        node: v,
        order,
        len,
        tried: 0,
        edge_in,
    }
}
