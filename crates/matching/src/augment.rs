//! Augmenting paths: Edmonds' blossom search as presented by Tarjan, *Data Structures and Network
//! Algorithms* (SIAM 1983), Chapter 9 — breadth-first alternating trees, blossoms shrunk with
//! disjoint sets — used by the quadrangulation paper (`tri-quad-conversion-long.txt`, Sections
//! 3.1 and 3.3) to complete the greedy and LRS pairings into perfect ones.
//!
//! # The search
//! Nodes reached by the search are *even* (roots, and mates of odd nodes) or *odd* (reached from
//! an even node through a non-matching edge). Even nodes are scanned in breadth-first order. An
//! edge from an even node `v` to
//! - an unreached matched node `w`: `w` becomes odd, its mate even (the tree grows);
//! - an unreached unmatched node, or an even node of another tree: an augmenting path is found;
//! - an even node of the same tree in another blossom: the cycle through the nearest common base
//!   is a blossom. Its odd nodes become even (and are scanned), each remembering the *bridge*
//!   `(v, w)` that absorbed it, and the sets of the cycle are united under the common base
//!   (disjoint sets with path halving, linking every set of the cycle under the base's set;
//!   Tarjan uses Gabow and Tarjan's linear special case, which is asymptotically better but not
//!   needed here).
//!
//! The path from an even node `v` to an ancestor `t` is Tarjan's recursive `path(v, t)`: if `v`
//! became even as a mate, `v, mate(v)` then `path(pred(mate(v)), t)`; if `v` was odd and was
//! absorbed through bridge `(x, y)` (`x` on `v`'s side), `v`, `reverse(path(x, mate(v)))`,
//! `path(y, t)`. It is evaluated with an explicit stack (paths can be as long as the graph), and
//! only its non-matching edges are collected: they are exactly the edges matched after the
//! augmentation, so augmenting is "match every collected edge". Edge ids, not node pairs, are
//! recorded, so parallel edges are handled.
//!
//! # Strategies
//! A closed surface's dual is cubic and bridgeless, so it has a perfect matching (Petersen) and,
//! by Berge's theorem and Edmonds' search, a search from any unmatched node finds an augmenting
//! path. A complete search that ends without one is therefore a proof that the graph has no
//! perfect matching ([`AugmentError::NoAugmentingPath`]); for a mesh dual it is a bug, never a
//! partial result.
//! - [`AugmentStrategy::Global`] — the procedure of the paper (Tarjan's): one alternating forest
//!   grown from *all* unmatched nodes at once, stopped at the first augmenting path and restarted,
//!   so invoked `k/2` times for `k` unmatched nodes, each costing up to O(n α(n)): O(k n α).
//! - [`AugmentStrategy::Local`] — the "faster augmenting search exploiting that unmatched triangles
//!   are close together" the paper names as future work (Section 5), taken literally: one
//!   single-root search per unmatched node, bounded by a budget of reached nodes; searches over
//!   budget are abandoned and retried in the next pass with a budget four times larger, until it
//!   exceeds the graph. Nearby augmentations are done first and cost only the region they reach.
//! - [`AugmentStrategy::Forest`] (the default) — the same locality by growing all the regions at
//!   once: the forest of Global, in lock-step breadth-first order, but when two trees meet the
//!   path is augmented, both trees are *retired* (their nodes are ignored for the rest of the pass)
//!   and the other trees keep growing. Every tree stops as soon as it meets a neighbouring one, so
//!   a pass costs at most O(n α) and usually matches almost every node; passes repeat on the nodes
//!   still unmatched (a pass without any augmentation is a complete search: no perfect matching).
//!   The trees of untouched regions keep their structure, since an augmentation only changes mates
//!   inside the two retired trees.
//! - The completion of [`crate::karp_sipser`] runs the Forest passes with the retired trees
//!   *reopened* (`OnPath::Reopen`): a growing tree that meets a node of a retired tree reaches
//!   it anew, as if unreached (the retired trees are matched among themselves, so the forest
//!   stays alternating). Its roots are the few triangles the greedy left far apart, whose
//!   partners often lie beyond other pairs' trees: with walls, the trees shut in by them fill
//!   their pockets and wait for the next pass, and reopening lets them through. After PS or SG
//!   (hundreds to thousands of roots, close together) walls pay: a reopened tree is reached
//!   again by its neighbours; so the Forest strategy keeps them. A reopened pass is not bounded
//!   by O(n α) (a node may be reached again after each retirement of its tree): O(k n α) for k
//!   paths.
//!
//! Forest is the default: every tree stops at its neighbours, so after PS or LRS one pass
//! reaches less than the graph, where each Global forest reaches much of it again (quadratic
//! after SG) and Local's single-root searches overlap; `quad_tables` compares the three
//! (`results/quad.md`).
//!
//! Per-node search state is generation-stamped (never reset), so a search costs only what it
//! reaches; the label is kept in a separate small array, since testing a neighbour's label is the
//! most frequent access.
//!
//! Complexity of one search: O(r α(r)) for the r nodes it reaches (r ≤ n).

use prefetch_index::prefetch_index;
use thiserror::Error;

use crate::dual_graph::{CompactDual, DualGraph, NONE, Pairing};

/// How the unmatched nodes are searched from (see the module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AugmentStrategy {
    /// The paper's procedure: a forest from all unmatched nodes, restarted after each augmentation.
    Global,
    /// Single-root searches with a growing budget of reached nodes, starting at `initial_budget`.
    Local {
        /// Nodes a search may reach in the first pass (multiplied by 4 at each pass).
        initial_budget: u32,
    },
    /// A forest from all unmatched nodes growing in lock-step, in which every pair of trees that
    /// meet is augmented and retired while the other trees keep growing; passes repeat on the
    /// nodes still unmatched.
    Forest,
}

impl Default for AugmentStrategy {
    /// [`AugmentStrategy::Forest`], the fastest in our measurements (see the module doc).
    fn default() -> Self {
        AugmentStrategy::Forest
    }
}

/// Figures of one [`augment_to_perfect`] run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AugmentStats {
    /// Unmatched nodes before.
    pub unmatched_before: usize,
    /// Augmenting paths applied (half of `unmatched_before` on success).
    pub augmentations: usize,
    /// Searches started (including abandoned ones).
    pub searches: usize,
    /// Searches abandoned over budget (local strategy).
    pub abandoned: usize,
    /// Nodes reached, summed over all searches (the work done).
    pub reached: u64,
    /// Edges on the longest augmenting path applied.
    pub longest_path: usize,
    /// The budget of the last pass (local strategy; 0 for global).
    pub final_budget: u64,
}

/// Why a matching could not be made perfect.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum AugmentError {
    /// A complete search from an unmatched node found no augmenting path: the graph has no
    /// perfect matching (for the dual of a simplicial closed surface this is a bug).
    #[error(
        "no augmenting path from node {node}: the search reached {reached} nodes and ended with \
         {unmatched} nodes still unmatched ({augmentations} augmentations done); the graph has no \
         perfect matching"
    )]
    NoAugmentingPath {
        /// The unmatched node searched from (for the global strategy, the first root).
        node: u32,
        /// Nodes reached by that last search.
        reached: usize,
        /// Nodes still unmatched.
        unmatched: usize,
        /// Augmentations done before.
        augmentations: usize,
    },
    /// The pairing does not fit the graph (wrong size, or a mate edge that is not at its node).
    #[error("pairing does not fit the graph: {0}")]
    BadPairing(String),
    /// The graph has an odd number of nodes.
    #[error("{nodes} nodes: a perfect matching needs an even number")]
    OddNodeCount {
        /// Number of live nodes.
        nodes: usize,
    },
}

/// When at least one node in `MATERIALISE_FRACTION` is unmatched, the search first copies the
/// adjacency into a [`CompactDual`] (one sequential pass) instead of reading the graph as given
/// (for a mesh: implicitly, through the half-edges). With many unmatched nodes (SG's) the searches
/// reach every node about twice and the copy pays for itself on meshes whose face order is not
/// spatially coherent; with few (PS's or LRS's) the copy costs as much as it saves, so the
/// implicit dual is read directly.
const MATERIALISE_FRACTION: usize = 64;

/// Augments `pairing` along augmenting paths until it is perfect.
///
/// Takes any [`DualGraph`] and any matching of it; `strategy` chooses the search (see the module
/// doc). Guarantees on success: every live node is matched, and the matched edges of the input
/// that are not on an augmenting path are kept. Complexity: O(k n α(n)) (global) for k unmatched
/// nodes; local: the sum over augmentations of the region searched, times at most a constant;
/// plus O(n) to read the pairing (and to copy the adjacency when at least one node in 64 is
/// unmatched).
///
/// # Errors
/// [`AugmentError::NoAugmentingPath`] when the graph has no perfect matching (the pairing is left
/// as augmented so far, still a matching); [`AugmentError::BadPairing`] /
/// [`AugmentError::OddNodeCount`] on inconsistent input (nothing is changed).
pub fn augment_to_perfect<G: DualGraph + ?Sized>(
    graph: &G,
    pairing: &mut Pairing,
    strategy: AugmentStrategy,
) -> Result<AugmentStats, AugmentError> {
    let nodes = graph.node_count();
    check_fits(graph, pairing)?;
    let unmatched = pairing.unmatched_nodes(graph);
    if unmatched.is_empty() {
        // Still check the pairing: a perfect one is returned as is.
        mates_of(graph, pairing)?;
        return Ok(AugmentStats::default());
    }
    if !nodes.is_multiple_of(2) {
        return Err(AugmentError::OddNodeCount { nodes });
    }
    let done = if unmatched.len() * MATERIALISE_FRACTION >= nodes {
        augment_on(
            &CompactDual::new(graph),
            pairing,
            unmatched,
            strategy,
            Goal::Perfect,
        )
    } else {
        augment_on(graph, pairing, unmatched, strategy, Goal::Perfect)
    };
    done.map(|(stats, _, _)| stats)
}

/// Augments `pairing` along augmenting paths until none is left: a maximum matching of any
/// [`DualGraph`] (a surface with boundary may have no perfect one). Returns the figures and the
/// proof of maximality, the Tutte–Berge barrier of the last search ([`barrier`]).
///
/// The strategies are [`augment_to_perfect`]'s; a search that finds no augmenting path leaves
/// its roots unmatched instead of failing (a pass of [`AugmentStrategy::Forest`] or
/// [`AugmentStrategy::Global`] without an augmentation ends the run, and that pass, a search
/// from every unmatched node, gives the barrier; a complete single-root search of
/// [`AugmentStrategy::Local`] drops its root, and the barrier takes one more search from the
/// roots left). Complexity: as [`augment_to_perfect`], plus O(n α(n)) for Local's barrier.
///
/// # Errors
/// [`AugmentError::BadPairing`] when the pairing does not fit the graph (nothing is changed).
pub fn augment_to_maximum<G: DualGraph + ?Sized>(
    graph: &G,
    pairing: &mut Pairing,
    strategy: AugmentStrategy,
) -> Result<(AugmentStats, Vec<u32>), AugmentError> {
    check_fits(graph, pairing)?;
    let unmatched = pairing.unmatched_nodes(graph);
    if unmatched.is_empty() {
        mates_of(graph, pairing)?;
        return Ok((AugmentStats::default(), Vec::new()));
    }
    let (stats, mates, barrier) = if unmatched.len() * MATERIALISE_FRACTION >= graph.node_count() {
        maximum_on(&CompactDual::new(graph), pairing, unmatched, strategy)?
    } else {
        maximum_on(graph, pairing, unmatched, strategy)?
    };
    for (m, [e, _]) in pairing.mate.iter_mut().zip(&mates) {
        *m = *e;
    }
    Ok((stats, barrier))
}

/// [`AugmentError::BadPairing`] unless `pairing` has one mate slot per node slot of `graph`.
fn check_fits<G: DualGraph + ?Sized>(graph: &G, pairing: &Pairing) -> Result<(), AugmentError> {
    if pairing.mate.len() != graph.node_slots() {
        return Err(AugmentError::BadPairing(format!(
            "{} mates for {} node slots",
            pairing.mate.len(),
            graph.node_slots()
        )));
    }
    Ok(())
}

/// [`augment_on`] to a maximum, then the barrier: with every node matched, none; after the
/// Forest or Global passes, whose last was a search from every unmatched node that found no
/// augmenting path, its odd nodes; after Local's single-root searches, [`barrier`]'s search.
#[allow(clippy::type_complexity)]
fn maximum_on<G: DualGraph + ?Sized>(
    graph: &G,
    pairing: &mut Pairing,
    pending: Vec<u32>,
    strategy: AugmentStrategy,
) -> Result<(AugmentStats, Vec<[u32; 2]>, Vec<u32>), AugmentError> {
    let (mut stats, mut mates, mut search) =
        augment_on(graph, pairing, pending, strategy, Goal::Maximum)?;
    let perfect =
        (0..graph.node_slots() as u32).all(|v| !graph.is_node(v) || mates[v as usize][0] != NONE);
    let barrier = match strategy {
        _ if perfect => Vec::new(),
        AugmentStrategy::Forest | AugmentStrategy::Global => search.odd_nodes(),
        AugmentStrategy::Local { .. } => barrier(graph, &mut mates, &mut search, &mut stats),
    };
    Ok((stats, mates, barrier))
}

/// Moves the unmatched nodes of a maximum matching to nodes where `prefer` holds, along even
/// alternating paths, and returns the nodes so reached, now unmatched instead of their trees'
/// roots. The barrier's search (see [`augment_to_maximum`]) grows one alternating tree from each
/// unmatched node; every even node of a tree can be left unmatched instead of its root by
/// flipping the even path between them (Tarjan's `path`, through blossoms), which keeps the
/// matching's size. In each tree that holds an even node where `prefer` holds, the first such
/// node in breadth-first order is chosen (the root itself when it qualifies). The trees are
/// disjoint, so the paths of different trees are flipped independently. Augments first if the
/// matching is not maximum. O(n α(n)).
///
/// # Errors
/// [`AugmentError::BadPairing`] when the pairing does not fit the graph (nothing is changed).
pub fn shift_unmatched<G: DualGraph + ?Sized>(
    graph: &G,
    pairing: &mut Pairing,
    prefer: impl Fn(u32) -> bool,
) -> Result<Vec<u32>, AugmentError> {
    check_fits(graph, pairing)?;
    let mut mates = mates_of(graph, pairing)?;
    let mut search = Search::new(graph.node_slots());
    let mut stats = AugmentStats::default();
    let _ = barrier(graph, &mut mates, &mut search, &mut stats);
    // The chosen node of each tree, in the order of the trees' first even nodes.
    let mut chosen: Vec<(u32, u32)> = Vec::new();
    let mut taken = vec![false; graph.node_slots()];
    for &v in &search.queue {
        if search.label(v) != EVEN || !prefer(v) {
            continue;
        }
        let root = search.state[v as usize][ROOT];
        if !std::mem::replace(&mut taken[root as usize], true) {
            chosen.push((v, root));
        }
    }
    for &(v, root) in &chosen {
        if v == root {
            continue;
        }
        search.path.clear();
        search.collect(graph, &mates, v, root);
        for &[f, a, b] in &search.path {
            mates[a as usize] = [f, b];
            mates[b as usize] = [f, a];
        }
        mates[v as usize] = [NONE, NONE];
    }
    for (m, [e, _]) in pairing.mate.iter_mut().zip(&mates) {
        *m = *e;
    }
    Ok(chosen.into_iter().map(|(v, _)| v).collect())
}

/// The Tutte–Berge barrier of a maximum matching `mates`: one search from all unmatched nodes at
/// once (augmenting along any path it still finds, and searching again), whose odd nodes are the
/// barrier A, in increasing order. With no augmenting path left, every even node lies in a
/// blossom (a single node, or an odd set shrunk together) all of whose neighbours are odd or in
/// the same blossom, and the unreached nodes are matched among themselves; so the components of
/// the graph without A are the outer blossoms (odd: one per tree, plus one per odd node of the
/// tree, the blossom whose base is its mate) and sets of unreached nodes (even), and
/// `odd(G − A) − |A|` is the number of trees, the unmatched nodes: by Tutte and Berge no matching
/// leaves fewer. This is the Gallai–Edmonds set A(G). Empty when nothing is unmatched.
/// O(n α(n)) per search (one, when `mates` is maximum).
pub(crate) fn barrier<G: DualGraph + ?Sized>(
    graph: &G,
    mates: &mut [[u32; 2]],
    search: &mut Search,
    stats: &mut AugmentStats,
) -> Vec<u32> {
    loop {
        let roots: Vec<u32> = (0..graph.node_slots() as u32)
            .filter(|&v| graph.is_node(v) && mates[v as usize][0] == NONE)
            .collect();
        if roots.is_empty() {
            return Vec::new();
        }
        stats.searches += 1;
        let outcome = search.run(
            graph,
            mates,
            &roots,
            usize::MAX,
            OnPath::Stop,
            1,
            stats,
            |_| true,
        );
        stats.reached += search.reached as u64;
        if outcome == Outcome::Exhausted {
            return search.odd_nodes();
        }
    }
}

/// Checks the pairing against the graph and returns `[mate edge, mate node]` per node slot:
/// every mate edge is a live non-loop edge at its node, matched at its other end too. One
/// endpoint lookup per matched node.
fn mates_of<G: DualGraph + ?Sized>(
    graph: &G,
    pairing: &Pairing,
) -> Result<Vec<[u32; 2]>, AugmentError> {
    let mut mates = vec![[NONE, NONE]; pairing.mate.len()];
    for (v, &e) in pairing.mate.iter().enumerate() {
        if e == NONE {
            continue;
        }
        let v = v as u32;
        let ok = (e as usize) < graph.edge_slots() && graph.is_edge(e) && graph.is_node(v) && {
            let [a, b] = graph.endpoints(e);
            let w = if a == v { b } else { a };
            (a == v || b == v) && w != v && pairing.mate[w as usize] == e && {
                mates[v as usize] = [e, w];
                true
            }
        };
        if !ok {
            return Err(AugmentError::BadPairing(format!(
                "node {v} has mate edge {e}, which is not a non-loop edge matched at both ends"
            )));
        }
    }
    Ok(mates)
}

/// What the augmentation aims at: a perfect matching (a search without an augmenting path is an
/// error), or a maximum one (such a search leaves its roots unmatched).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Goal {
    Perfect,
    Maximum,
}

fn augment_on<G: DualGraph + ?Sized>(
    graph: &G,
    pairing: &mut Pairing,
    pending: Vec<u32>,
    strategy: AugmentStrategy,
    goal: Goal,
) -> Result<(AugmentStats, Vec<[u32; 2]>, Search), AugmentError> {
    let mut mates = mates_of(graph, pairing)?;
    let mut stats = AugmentStats {
        unmatched_before: pending.len(),
        ..AugmentStats::default()
    };
    let mut search = Search::new(graph.node_slots());
    let result = match strategy {
        AugmentStrategy::Global => forest(
            graph,
            &mut mates,
            &mut search,
            pending,
            OnPath::Stop,
            goal,
            None,
            &mut stats,
        ),
        AugmentStrategy::Forest => forest(
            graph,
            &mut mates,
            &mut search,
            pending,
            OnPath::Wall,
            goal,
            None,
            &mut stats,
        ),
        AugmentStrategy::Local { initial_budget } => local(
            graph,
            &mut mates,
            &mut search,
            pending,
            initial_budget,
            goal,
            &mut stats,
        ),
    };
    for (m, [e, _]) in pairing.mate.iter_mut().zip(&mates) {
        *m = *e;
    }
    result.map(|()| (stats, mates, search))
}

/// Completes `mates` by the Forest strategy from the unmatched nodes `pending`, reusing `search`
/// (for callers that already hold the mates and the search state, like [`crate::karp_sipser`]).
/// With [`Goal::Maximum`], the roots left when a pass finds no augmenting path stay unmatched.
/// With a `floor` (only with `pending` holding every unmatched node): the completion stops, even
/// inside a pass, once only `floor` nodes are unmatched, where `floor` is a bound no matching
/// betters (see [`forest`]).
pub(crate) fn complete<G: DualGraph + ?Sized>(
    graph: &G,
    mates: &mut [[u32; 2]],
    search: &mut Search,
    pending: Vec<u32>,
    goal: Goal,
    floor: Option<usize>,
    stats: &mut AugmentStats,
) -> Result<(), AugmentError> {
    stats.unmatched_before += pending.len();
    forest(
        graph,
        mates,
        search,
        pending,
        OnPath::Reopen,
        goal,
        floor,
        stats,
    )
}

/// Passes of forest searches from the unmatched nodes until none is left: Global (`OnPath::Stop`,
/// one augmentation per forest), Forest (`OnPath::Wall`) or the KS completion (`OnPath::Reopen`).
/// A pass without an augmentation retired no tree, so it was a complete search from all the
/// roots: none has an augmenting path (Edmonds), an error for [`Goal::Perfect`], the end for
/// [`Goal::Maximum`] (the matching is maximum, by Berge's theorem); the search state then holds
/// that search, whose odd nodes are the Tutte–Berge barrier ([`Search::odd_nodes`], as
/// [`barrier`] finds it) when `pending` held every unmatched node.
///
/// `floor`, when given, is a number of unmatched nodes that no matching of the graph betters
/// (e.g. its pieces of odd size: Tutte–Berge with an empty barrier), and `pending` must hold every
/// unmatched node: the passes then stop, in the middle of one if need be, after the augmentation
/// that leaves `floor` nodes unmatched, which proves the matching maximum without the complete
/// search that would otherwise end the run. Without it a lone root left in the last pass grows
/// its tree over its whole piece, once more in the pass that finds nothing, and once more in the
/// barrier's search.
#[allow(clippy::too_many_arguments)]
fn forest<G: DualGraph + ?Sized>(
    graph: &G,
    mates: &mut [[u32; 2]],
    search: &mut Search,
    mut pending: Vec<u32>,
    on_path: OnPath,
    goal: Goal,
    floor: Option<usize>,
    stats: &mut AugmentStats,
) -> Result<(), AugmentError> {
    while !pending.is_empty() {
        // Each augmentation matches two unmatched nodes.
        let max_paths = floor.map_or(usize::MAX, |f| pending.len().saturating_sub(f) / 2);
        if max_paths == 0 {
            return Ok(());
        }
        stats.searches += 1;
        let before = stats.augmentations;
        search.run(
            graph,
            mates,
            &pending,
            usize::MAX,
            on_path,
            max_paths,
            stats,
            |_| true,
        );
        stats.reached += search.reached as u64;
        if stats.augmentations == before {
            if goal == Goal::Maximum {
                return Ok(());
            }
            return Err(no_path(pending[0], search, pending.len(), stats));
        }
        pending.retain(|&v| mates[v as usize][0] == NONE);
    }
    Ok(())
}

/// Single-root searches with growing budgets. A root whose complete search finds no augmenting
/// path has none after later augmentations either (Edmonds' lemma: a node on no augmenting path
/// stays so), so with [`Goal::Maximum`] it is left unmatched.
fn local<G: DualGraph + ?Sized>(
    graph: &G,
    mates: &mut [[u32; 2]],
    search: &mut Search,
    mut pending: Vec<u32>,
    initial_budget: u32,
    goal: Goal,
    stats: &mut AugmentStats,
) -> Result<(), AugmentError> {
    let nodes = graph.node_count() as u64;
    let mut budget = u64::from(initial_budget.max(2));
    let mut next = Vec::with_capacity(pending.len());
    loop {
        stats.final_budget = budget;
        let limit = if budget >= nodes {
            usize::MAX
        } else {
            budget as usize
        };
        next.clear();
        for i in 0..pending.len() {
            let r = pending[i];
            if mates[r as usize][0] != NONE {
                continue;
            }
            stats.searches += 1;
            let outcome = search.run(graph, mates, &[r], limit, OnPath::Stop, 1, stats, |_| true);
            stats.reached += search.reached as u64;
            match outcome {
                Outcome::Augmented => {}
                Outcome::OverBudget => {
                    stats.abandoned += 1;
                    next.push(r);
                }
                Outcome::Exhausted if goal == Goal::Maximum => {}
                Outcome::Exhausted => {
                    let left = pending[i..]
                        .iter()
                        .chain(next.iter())
                        .filter(|&&v| mates[v as usize][0] == NONE)
                        .count();
                    return Err(no_path(r, search, left, stats));
                }
            }
        }
        if next.is_empty() {
            return Ok(());
        }
        std::mem::swap(&mut pending, &mut next);
        budget = budget.saturating_mul(4);
    }
}

fn no_path(node: u32, search: &Search, unmatched: usize, stats: &AugmentStats) -> AugmentError {
    AugmentError::NoAugmentingPath {
        node,
        reached: search.reached,
        unmatched,
        augmentations: stats.augmentations,
    }
}

/// What [`Search::run`] does after it applies an augmenting path.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum OnPath {
    /// It stops (Global and Local strategies, the repairs of [`crate::karp_sipser`]).
    Stop,
    /// It retires the two trees joined by the path, whose nodes no other tree enters for the rest
    /// of the search (they are walls), and the other trees keep growing (Forest strategy).
    Wall,
    /// As `Wall`, but another tree may reach a retired tree's nodes anew, as if they were
    /// unreached (the completion of [`crate::karp_sipser`]).
    Reopen,
}

/// How a search ended.
#[derive(Debug, PartialEq, Eq)]
pub(crate) enum Outcome {
    /// At least one augmenting path was applied.
    Augmented,
    /// The search ended without finding one (no augmenting path from its roots).
    Exhausted,
    /// The search reached more nodes than its budget and was abandoned.
    OverBudget,
}

/// How far ahead in the queue [`Search::prefetch_ahead`] asks for a node's adjacency.
pub(crate) const PREFETCH_AHEAD: usize = 8;

const EVEN: u32 = 1;
const ODD: u32 = 2;
const LABEL_BITS: u32 = 2;

/// Per-node state of a search: eight `u32` fields in one 32-byte record (an array, so that the
/// vector is allocated zeroed, without an O(n) initialisation), touched only for reached nodes;
/// the label lives in the smaller stamp array, which is what the scan of a neighbour reads.
type NodeState = [u32; 8];
/// Root of the node's tree.
const ROOT: usize = 0;
/// For odd (or once-odd) nodes: the non-matching edge by which the node was reached, and the even
/// node at its other end. For a node that was never odd (a root, or a node that became even as a
/// mate), `PRED` is its grandparent in the tree (the odd mate's `PRED`; `NONE` at a root) and
/// `MARK` (the same field as `PRED_EDGE`) marks it in the walk of [`Search::shrink_blossom`]:
/// only such nodes are blossom bases, and the walk reads nothing but their own records.
const PRED_EDGE: usize = 1;
const MARK: usize = PRED_EDGE;
const PRED: usize = 2;
/// For once-odd nodes absorbed by a blossom: the bridge edge (else `NONE`) and its endpoint on the
/// absorbed node's side.
const BRIDGE_EDGE: usize = 3;
const BRIDGE_SIDE: usize = 4;
/// For a node that became even as a mate (so `BRIDGE_EDGE` is `NONE`): that odd mate, so that
/// [`Search::absorb_path`] reads only the records of the bases it walks.
const ODD_MATE: usize = BRIDGE_SIDE;
/// Disjoint-set parent (blossoms), and the base of the set when the node is a set root.
const PARENT: usize = 5;
const BASE: usize = 6;
/// Generation in which this node, as a root, had its tree retired (Forest strategy).
const RETIRED: usize = 7;

/// The state of Edmonds' search, generation-stamped so that a search costs only what it reaches.
pub(crate) struct Search {
    /// `generation << 2 | label` of the search that last reached each node.
    stamp: Vec<u32>,
    state: Vec<NodeState>,
    /// Current generation, in `1 .. 2^30`.
    generation: u32,
    /// Stamp of the current nearest-common-base walk (in the bases' `MARK`; never `NONE`, the
    /// value a node gets when reached).
    mark_generation: u32,
    queue: Vec<u32>,
    /// (node, target) tasks of the path evaluation, and the collected (edge, end, end) triples.
    tasks: Vec<(u32, u32)>,
    path: Vec<[u32; 3]>,
    /// Nodes reached by the last search.
    pub(crate) reached: usize,
    /// The end of the last augmenting path applied that was not `root(v)` of [`Search::augment`]:
    /// the unreached free node, or the root of the other tree.
    pub(crate) last_end: u32,
}

impl Search {
    pub(crate) fn new(n: usize) -> Self {
        Search {
            stamp: vec![0; n],
            state: vec![[0; 8]; n],
            generation: 0,
            mark_generation: 0,
            queue: Vec::new(),
            tasks: Vec::new(),
            path: Vec::new(),
            reached: 0,
            last_end: NONE,
        }
    }

    #[inline]
    fn label(&self, v: u32) -> u32 {
        let s = self.stamp[v as usize];
        if s >> LABEL_BITS == self.generation {
            s & ((1 << LABEL_BITS) - 1)
        } else {
            0
        }
    }

    #[inline]
    fn set_label(&mut self, v: u32, label: u32) {
        self.stamp[v as usize] = self.generation << LABEL_BITS | label;
    }

    /// Whether the tree of reached node `v` was retired in this search.
    #[inline]
    fn is_retired(&self, v: u32) -> bool {
        let root = self.state[v as usize][ROOT];
        self.state[root as usize][RETIRED] == self.generation
    }

    /// Labels an unreached node and makes it a singleton blossom.
    #[inline]
    fn reach(&mut self, v: u32, label: u32, root: u32, pred_edge: u32, pred: u32) {
        self.set_label(v, label);
        let s = &mut self.state[v as usize];
        s[ROOT] = root;
        s[PRED_EDGE] = pred_edge;
        s[PRED] = pred;
        s[BRIDGE_EDGE] = NONE;
        s[PARENT] = v;
        s[BASE] = v;
        self.reached += 1;
    }

    #[inline]
    fn find(&mut self, mut v: u32) -> u32 {
        loop {
            let p = self.state[v as usize][PARENT];
            if p == v {
                return v;
            }
            let gp = self.state[p as usize][PARENT];
            self.state[v as usize][PARENT] = gp;
            v = gp;
        }
    }

    #[inline]
    fn base_of(&mut self, v: u32) -> u32 {
        let r = self.find(v);
        self.state[r as usize][BASE]
    }

    /// Puts the set of `v` under the set root `common_root` (whose base is kept).
    #[inline]
    fn absorb(&mut self, common_root: u32, v: u32) {
        let r = self.find(v);
        if r != common_root {
            self.state[r as usize][PARENT] = common_root;
        }
    }

    /// The base of the blossom above base `x` in its tree, or `NONE` at the root. A base is a
    /// root or a node that became even as a mate, whose `PRED` is its grandparent.
    #[inline]
    fn parent_base(&mut self, x: u32) -> u32 {
        match self.state[x as usize][PRED] {
            NONE => NONE,
            p => self.base_of(p),
        }
    }

    /// One search from `roots` (all unmatched), reaching at most `budget` nodes; after each
    /// augmenting path it does what `on_path` says ([`OnPath`]), and it stops after `max_paths`
    /// of them (at least 1).
    /// Confined to the nodes for which `allowed` holds (and the roots, and the mates of allowed
    /// nodes): a node outside is never reached through a non-matching edge.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn run<G: DualGraph + ?Sized>(
        &mut self,
        graph: &G,
        mates: &mut [[u32; 2]],
        roots: &[u32],
        budget: usize,
        on_path: OnPath,
        max_paths: usize,
        stats: &mut AugmentStats,
        allowed: impl Fn(u32) -> bool,
    ) -> Outcome {
        self.generation += 1;
        if self.generation >= 1 << (32 - LABEL_BITS) {
            self.stamp.fill(0);
            self.state.iter_mut().for_each(|s| s[RETIRED] = 0);
            self.generation = 1;
        }
        self.reached = 0;
        self.queue.clear();
        for &r in roots {
            self.reach(r, EVEN, r, NONE, NONE);
            self.queue.push(r);
        }
        let keep_going = on_path != OnPath::Stop;
        let mut paths = 0;
        let mut head = 0;
        // A cooperative stop (Ctrl-C from Python) is read every few thousand nodes scanned.
        let mut ticker = surftopo_mesh::stop::Ticker::default();
        'scan: while head < self.queue.len() {
            ticker.tick();
            self.prefetch_ahead(graph, mates, head);
            let v = self.queue[head];
            head += 1;
            // Skip the nodes of retired trees, and (OnPath::Reopen) queued nodes re-reached as
            // odd by another tree.
            if keep_going && (self.is_retired(v) || self.label(v) != EVEN) {
                continue;
            }
            let mate_v = mates[v as usize][0];
            for (e, w) in graph.adjacent(v) {
                if w == v || e == mate_v {
                    continue;
                }
                let mut label = self.label(w);
                if label != 0 && keep_going && self.is_retired(w) {
                    if on_path == OnPath::Wall {
                        continue;
                    }
                    // A retired tree's nodes are matched among themselves, so `w` is matched
                    // and its mate is retired too: both are reached anew, as if unreached.
                    label = 0;
                }
                if label == 0 {
                    if !allowed(w) {
                        continue;
                    }
                    let [_, m] = mates[w as usize];
                    if m == NONE {
                        self.augment(graph, mates, v, e, w, false, stats);
                        paths += 1;
                        if !keep_going || paths == max_paths {
                            break 'scan;
                        }
                        continue 'scan;
                    }
                    debug_assert!(self.label(m) == 0 || self.is_retired(m));
                    let root = self.state[v as usize][ROOT];
                    self.reach(w, ODD, root, e, v);
                    self.reach(m, EVEN, root, NONE, v);
                    self.state[m as usize][ODD_MATE] = w;
                    self.queue.push(m);
                    if self.reached > budget {
                        return Outcome::OverBudget;
                    }
                } else if label == EVEN {
                    if self.state[v as usize][ROOT] != self.state[w as usize][ROOT] {
                        self.augment(graph, mates, v, e, w, true, stats);
                        paths += 1;
                        if !keep_going || paths == max_paths {
                            break 'scan;
                        }
                        continue 'scan;
                    }
                    if self.find(v) != self.find(w) {
                        self.shrink_blossom(mates, v, e, w);
                    }
                } // odd: nothing to do
            }
        }
        if paths > 0 {
            Outcome::Augmented
        } else {
            Outcome::Exhausted
        }
    }

    /// The nodes labelled odd by the last search, in increasing order: after a search from every
    /// unmatched node that found no augmenting path, the Tutte–Berge barrier (see [`barrier`]).
    pub(crate) fn odd_nodes(&self) -> Vec<u32> {
        (0..self.stamp.len() as u32)
            .filter(|&v| self.label(v) == ODD)
            .collect()
    }

    /// Starts loading what the scans of the queued nodes ahead of `head` will read: the
    /// adjacency, mate and state of the node [`PREFETCH_AHEAD`] places ahead, and the labels,
    /// mates and states of the neighbours of the node half as far ahead (whose adjacency was
    /// asked for then); only on a flat graph ([`DualGraph::flat_adjacency`]), where reading an
    /// adjacency early costs one load. The queue is known in advance, so the random reads of a
    /// large graph overlap instead of stalling one after the other (`quad_profile` on a shuffled
    /// mesh shows the difference; `COLD=1` with cold caches).
    #[inline]
    fn prefetch_ahead<G: DualGraph + ?Sized>(&self, graph: &G, mates: &[[u32; 2]], head: usize) {
        let Some(adjacency) = graph.flat_adjacency() else {
            return;
        };
        if let Some(&far) = self.queue.get(head + PREFETCH_AHEAD) {
            prefetch_index(adjacency, far as usize);
            prefetch_index(mates, far as usize);
            prefetch_index(&self.state, far as usize);
        }
        if let Some(&near) = self.queue.get(head + PREFETCH_AHEAD / 2) {
            for (_, w) in adjacency[near as usize] {
                prefetch_index(&self.stamp, w as usize);
                prefetch_index(mates, w as usize);
                prefetch_index(&self.state, w as usize);
            }
        }
    }

    /// Shrinks the blossom closed by edge `e = (v, w)` between two even nodes of one tree.
    /// The walk up to the nearest common base and [`Search::absorb_path`] read only the records
    /// of the bases (grandparent, mark and odd mate are kept there), and the queue's nodes ahead
    /// have their mates and states loaded early too: a separate mark array, or reading the mates
    /// on the walk, would add a random read per base on inputs with many blossoms.
    fn shrink_blossom(&mut self, mates: &[[u32; 2]], v: u32, e: u32, w: u32) {
        // A base's MARK is reset to NONE when it is reached, so a stamp of an earlier walk can
        // only be one of this search's (fewer than n of them): wrapping around is harmless.
        self.mark_generation = self.mark_generation.wrapping_add(1);
        if self.mark_generation == NONE {
            self.mark_generation = 0;
        }
        let (mut x, mut y) = (self.base_of(v), self.base_of(w));
        let common = loop {
            if x != NONE {
                if self.state[x as usize][MARK] == self.mark_generation {
                    break x;
                }
                self.state[x as usize][MARK] = self.mark_generation;
                x = self.parent_base(x);
            }
            std::mem::swap(&mut x, &mut y);
        };
        let common_root = self.find(common);
        self.absorb_path(mates, v, e, common, common_root);
        self.absorb_path(mates, w, e, common, common_root);
    }

    /// Walks from `side`'s base up to `common`, making the odd nodes even with bridge `e`
    /// (entered from `side`) and uniting everything under `common`'s set.
    fn absorb_path(&mut self, mates: &[[u32; 2]], side: u32, e: u32, common: u32, root: u32) {
        let mut x = self.base_of(side);
        while x != common {
            let (grandparent, m) = (
                self.state[x as usize][PRED],
                self.state[x as usize][ODD_MATE],
            );
            debug_assert_eq!(m, mates[x as usize][1]);
            debug_assert_eq!(self.label(m), ODD);
            self.set_label(m, EVEN);
            let s = &mut self.state[m as usize];
            s[BRIDGE_EDGE] = e;
            s[BRIDGE_SIDE] = side;
            // An odd node is a singleton set until a blossom absorbs it.
            s[PARENT] = root;
            self.queue.push(m);
            self.absorb(root, x);
            x = self.base_of(grandparent);
        }
    }

    /// Collects the non-matching edges of `path(v, target)` (with their ends) into `self.path`.
    fn collect<G: DualGraph + ?Sized>(
        &mut self,
        graph: &G,
        mates: &[[u32; 2]],
        v: u32,
        target: u32,
    ) {
        self.tasks.push((v, target));
        while let Some((v, t)) = self.tasks.pop() {
            if v == t {
                continue;
            }
            let s = self.state[v as usize];
            if s[BRIDGE_EDGE] == NONE {
                let m = mates[v as usize][1];
                let ms = self.state[m as usize];
                self.path.push([ms[PRED_EDGE], m, ms[PRED]]);
                self.tasks.push((ms[PRED], t));
            } else {
                let x = s[BRIDGE_SIDE];
                let y = graph.opposite(s[BRIDGE_EDGE], x);
                self.path.push([s[BRIDGE_EDGE], x, y]);
                self.tasks.push((x, mates[v as usize][1]));
                self.tasks.push((y, t));
            }
        }
    }

    /// Applies the augmenting path `root(v) .. v, e, w .. root(w)` (`w` unreached and unmatched
    /// unless `w_in_tree`) and retires the trees involved.
    #[allow(clippy::too_many_arguments)]
    fn augment<G: DualGraph + ?Sized>(
        &mut self,
        graph: &G,
        mates: &mut [[u32; 2]],
        v: u32,
        e: u32,
        w: u32,
        w_in_tree: bool,
        stats: &mut AugmentStats,
    ) {
        self.path.clear();
        self.path.push([e, v, w]);
        let root_v = self.state[v as usize][ROOT];
        self.collect(graph, mates, v, root_v);
        self.state[root_v as usize][RETIRED] = self.generation;
        if w_in_tree {
            let root_w = self.state[w as usize][ROOT];
            self.collect(graph, mates, w, root_w);
            self.state[root_w as usize][RETIRED] = self.generation;
            self.last_end = root_w;
        } else {
            self.last_end = w;
            // w joins v's retired tree, so that no other tree grows through it (or, reopened,
            // reaches it as a matched node).
            self.reach(w, EVEN, root_v, NONE, NONE);
        }
        for &[f, a, b] in &self.path {
            mates[a as usize] = [f, b];
            mates[b as usize] = [f, a];
        }
        stats.augmentations += 1;
        stats.longest_path = stats.longest_path.max(2 * self.path.len() - 1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generators::{random_bridgeless_cubic, random_cubic_pairing};
    use crate::verify::verify_perfect_matching;

    /// The completion of [`crate::karp_sipser`] (`OnPath::Reopen`) from an empty matching:
    /// every node a root, so trees retire everywhere and the others re-reach their nodes. The
    /// result is checked by the independent verifier, and the work by the counts.
    #[test]
    fn reopen_completion_from_every_node_unmatched() {
        for seed in 0..8u64 {
            let n = 500 + 250 * seed as u32;
            for graph in [
                random_bridgeless_cubic(n, seed),
                random_cubic_pairing(n, seed),
            ] {
                let mut mates = vec![[NONE, NONE]; n as usize];
                let mut search = Search::new(n as usize);
                let mut stats = AugmentStats::default();
                complete(
                    &graph,
                    &mut mates,
                    &mut search,
                    (0..n).collect(),
                    Goal::Perfect,
                    None,
                    &mut stats,
                )
                .unwrap();
                assert_eq!(stats.augmentations, n as usize / 2);
                // Reached more than once: trees grew through retired ones.
                assert!(stats.reached > n as u64, "{stats:?}");
                let mut matched = vec![false; graph.edge_count() as usize];
                for (v, &[e, w]) in mates.iter().enumerate() {
                    assert_eq!(mates[w as usize], [e, v as u32]);
                    matched[e as usize] = true;
                }
                verify_perfect_matching(&graph, &matched).unwrap();
            }
        }
    }
}
