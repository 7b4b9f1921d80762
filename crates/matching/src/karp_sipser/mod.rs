//! KS: a perfect pairing by the Karp–Sipser greedy with immediate local repairs. Not one of the
//! quadrangulation paper's algorithms, but built from its own pieces (a greedy pairing completed
//! by Edmonds' augmenting paths, Section 3.1) and its closing suggestion (Section 5: search for
//! augmenting paths locally, where the unpaired triangles are).
//!
//! [`karp_sipser_perfect_with`] tries the phases in order; each has its file and owns its state:
//!
//! | phase | file | state |
//! |---|---|---|
//! | 0. the file's quads: triangles written two by two as quads are paired as written | `file_order.rs` | none |
//! | 1. the coarser mesh's pairing, lifted through every level of a 1-to-4 subdivision the file is written as | `subdivision.rs` | `SubdivisionLevel` |
//! | 2. the greedy: Karp and Sipser's rule (a node with one free neighbour is paired with it), else a start node paired with its neighbour of smallest free degree, in id or breadth-first order | `greedy.rs` | `Greedy` |
//! | 3. the repairs: a node the greedy isolates (free degree 0 while unpaired) is repaired at once by a bounded depth-first search, then a bounded Edmonds search; else it is deferred | `repair.rs` | `Repairs` |
//! | 4. the guided completion: the deferred nodes are paired two by two by searches near the shortest paths between them | `guided.rs` | `GuidedCompletion` |
//! | 5. the rest: the Forest strategy of [`crate::augment`] with the retired trees reopened | `augment.rs` | `Search` |
//!
//! Phases 3 and 4 both search in a band around a path (`band.rs`: `Band`), which neither owns.
//!
//! Phases 0 and 1 need no search at all, on the files they recognise; a coarse graph of phase 1
//! with no perfect pairing falls back to phase 2 on the finer graph. Phases 2 to 5 share the
//! matching ([`Pairs`]: the mates, the free degrees, the counts and the figures). Phase 5 is a
//! complete search, so the result is always perfect, or an [`AugmentError`] proves that the
//! graph has no perfect matching.
//!
//! To a maximum ([`karp_sipser_maximum_with`]), phase 5 starts from every unpaired node and stops
//! as soon as the unpaired nodes are as few as the pieces of odd size, even in the middle of a
//! pass: the Tutte–Berge bound with an empty barrier (Berge, 1958: every matching leaves at least
//! one node of each component of odd size unmatched) proves the matching maximum then, where
//! going on would grow the last root's tree over its whole piece for nothing, twice (the pass
//! that finds no path, and the barrier's search). Otherwise its last pass is a complete search
//! from every unpaired node that found no augmenting path, and the odd nodes of that search are
//! the Gallai–Edmonds barrier (as [`crate::augment_to_maximum`] finds it), taken without
//! searching again.
//!
//! Figures are those of the paper's Table 4.3: the greedy counts as the initial pairing; every
//! repair and the completion count as augmentation (timed separately); "unpaired" is the number
//! of isolated nodes met.
//!
//! Complexity: O(n) for phases 0 to 3 (each repair is bounded); O(n) per guided search (at most
//! one per pair of deferred nodes); plus phase 5 when a guided search fails (see
//! [`crate::augment`]).

mod band;
mod file_order;
mod greedy;
mod guided;
mod repair;
mod subdivision;

use std::time::Instant;

use crate::augment::{AugmentError, AugmentStats, Goal, OnPath, Outcome, Search, complete};
use crate::dual_graph::{CompactDual, DualGraph, NONE, Pairing};
use crate::surface_dual::label_components;
use file_order::file_order_pairing;
use greedy::Greedy;
use guided::GuidedCompletion;
use repair::Repairs;
use subdivision::coarsen;

/// Nodes a repair's Edmonds search may reach before it is abandoned and its node deferred to the
/// completion (the default of [`KarpSipserOptions::repair_budget`]). With no limit there is
/// nothing left to complete, but some repairs then cross most of the graph.
const REPAIR_BUDGET: usize = 1024;

/// Figures of one [`karp_sipser_perfect`] run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct KarpSipserStats {
    /// Whether the pairing is the file's quads (the triangles `2k` and `2k + 1` adjacent for
    /// every `k`): no greedy, no search.
    pub file_order: bool,
    /// Levels of 1-to-4 subdivision the pairing was lifted through (the triangles `4k..4k + 4`
    /// the children of one coarser triangle, level after level); the other figures are then
    /// those of the coarsest level's run.
    pub subdivision_levels: u32,
    /// Seconds of the greedy itself, copying the adjacency included, repairs excluded (with
    /// `file_order`: of the file-order check).
    pub greedy_seconds: f64,
    /// Seconds of the repairs and of the final completion.
    pub augmentation_seconds: f64,
    /// Isolated nodes met by the greedy (what the greedy alone would leave unpaired).
    pub isolated: usize,
    /// Isolated nodes paired by a repair search within its budget.
    pub repaired: usize,
    /// Isolated nodes whose repair went over budget, or was skipped (deferred).
    pub deferred: usize,
    /// Of these, the nodes deferred without a search, every unpaired node being isolated.
    pub skipped: usize,
    /// Deferred nodes still unpaired after the greedy, paired two by two by the completion (the
    /// others were reached as the free end of a later repair).
    pub completed: usize,
    /// Augmenting paths found by the guided completion (each pairs two deferred nodes).
    pub guided: usize,
    /// Of these, the paths found by the Edmonds search in the band (the depth-first search
    /// failed).
    pub guided_by_edmonds: usize,
    /// Nodes reached by the completion (included in `augment.reached`).
    pub completion_reached: u64,
    /// Whether the greedy started from the nodes in id order (true) or in breadth-first order
    /// (false): id order when neighbouring nodes have close ids (files written along a sweep).
    pub id_order: bool,
    /// Times the id sweep was reversed for a lone deferred node in its last quarter.
    pub reversals: usize,
    /// The searches of the repairs and of the completion (nodes reached, paths, ...).
    pub augment: AugmentStats,
}

/// Settings of [`karp_sipser_perfect_with`]; the defaults are [`karp_sipser_perfect`]'s.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct KarpSipserOptions {
    /// Nodes the Edmonds search of a repair may reach (0 skips both repair searches and defers
    /// every isolated node to the completion). Default 1024.
    pub repair_budget: usize,
    /// Whether the deferred nodes are first paired by guided searches (else by the Forest
    /// strategy alone).
    pub guided_completion: bool,
    /// Whether a file written quad by quad is paired as written (phase 0 of the module doc).
    pub file_order: bool,
    /// Whether a file written as a 1-to-4 subdivision is paired by lifting the coarser mesh's
    /// pairing (phase 1).
    pub subdivision: bool,
}

impl Default for KarpSipserOptions {
    fn default() -> Self {
        KarpSipserOptions {
            repair_budget: REPAIR_BUDGET,
            guided_completion: true,
            file_order: true,
            subdivision: true,
        }
    }
}

/// KS: a perfect pairing of `graph` by the Karp–Sipser greedy (Karp and Sipser, "Maximum
/// matchings in sparse random graphs", FOCS 1981) with immediate local repairs, completed by
/// augmenting paths; files written quad by quad or as a 1-to-4 subdivision are paired from their
/// face order without a search ([`KarpSipserStats::file_order`],
/// [`KarpSipserStats::subdivision_levels`]). Not from the quadrangulation paper: built from its
/// Section 3.1 (a greedy completed by Edmonds' augmenting paths) and its Section 5 (local
/// searches where the unpaired triangles are). Deterministic.
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
    karp_sipser_perfect_with(graph, &KarpSipserOptions::default())
}

/// [`karp_sipser_perfect`] with other settings.
///
/// # Errors
/// See [`karp_sipser_perfect`].
pub fn karp_sipser_perfect_with<G: DualGraph + ?Sized>(
    graph: &G,
    options: &KarpSipserOptions,
) -> Result<(Pairing, KarpSipserStats), AugmentError> {
    run(graph, options, Goal::Perfect).map(|(pairing, stats, _)| (pairing, stats))
}

/// KS to a maximum matching, on any [`DualGraph`] (the dual of a surface with boundary, whose
/// triangles may not all pair): the phases of [`karp_sipser_perfect_with`], with three changes.
/// The nodes of free degree 1 at the start (triangles with two boundary sides) are paired first,
/// by Karp and Sipser's rule; nodes of free degree 0 at the start (a lone triangle) are left
/// unpaired at once; and the completion, from every unpaired node, stops once one node per
/// piece of odd size is left unpaired (which no matching betters: the barrier A = ∅), or at its
/// first pass without an augmenting path (a complete search: the matching is then maximum).
/// Returns the pairing, the figures and the Tutte–Berge barrier proving maximality (see
/// [`crate::augment_to_maximum`]): empty in the first case (no search at all when the greedy
/// leaves exactly that many), the odd nodes of that last search in the second. On a graph with
/// a perfect matching the result is perfect. Deterministic.
pub fn karp_sipser_maximum_with<G: DualGraph + ?Sized>(
    graph: &G,
    options: &KarpSipserOptions,
) -> (Pairing, KarpSipserStats, Vec<u32>) {
    run(graph, options, Goal::Maximum).expect("a maximum matching always exists")
}

fn run<G: DualGraph + ?Sized>(
    graph: &G,
    options: &KarpSipserOptions,
    goal: Goal,
) -> Result<(Pairing, KarpSipserStats, Vec<u32>), AugmentError> {
    let start = Instant::now();
    let nodes = graph.node_count();
    if goal == Goal::Perfect && !nodes.is_multiple_of(2) {
        return Err(AugmentError::OddNodeCount { nodes });
    }
    if options.file_order
        && let Some(pairing) = file_order_pairing(graph)
    {
        let stats = KarpSipserStats {
            file_order: true,
            greedy_seconds: start.elapsed().as_secs_f64(),
            ..KarpSipserStats::default()
        };
        return Ok((pairing, stats, Vec::new()));
    }
    // The copy serves the greedy too; the lift reads it rather than the mesh, whose half-edges
    // need not be in face order.
    let (compact, degrees) = CompactDual::with_degrees(graph);
    if options.subdivision
        && let Some(level) = coarsen(&compact)
        && let Ok((coarse, coarse_stats, coarse_barrier)) = run(level.coarse(), options, goal)
        && (goal == Goal::Perfect
            || (coarse_barrier.is_empty() && coarse.unmatched_count(level.coarse()) == 0))
    {
        let pairing = level.lift(&compact, &coarse);
        let stats = KarpSipserStats {
            file_order: false,
            subdivision_levels: coarse_stats.subdivision_levels + 1,
            greedy_seconds: start.elapsed().as_secs_f64() - coarse_stats.augmentation_seconds,
            ..coarse_stats
        };
        return Ok((pairing, stats, Vec::new()));
    }
    let mut pairs = Pairs::new(&compact, degrees);
    let mut greedy = Greedy::new(&compact);
    if goal == Goal::Maximum {
        greedy.seed_low_degrees(&mut pairs);
    }
    // The nodes without a neighbour, each a piece of one node (stranded by the seeding).
    let lone = pairs.stranded;
    let mut repairs = Repairs::new(compact.node_slots(), options.repair_budget);
    greedy.run(&mut pairs, &mut repairs);
    let mut deferred = greedy.into_deferred();
    if options.guided_completion {
        let mut guided = GuidedCompletion::default();
        guided.run(&mut pairs, repairs.depth_first(), &mut deferred);
        debug_assert_eq!(guided.check_invariants(&pairs), Ok(()));
    }
    let mut stats = pairs.stats;
    deferred.retain(|&v| pairs.mates[v as usize][0] == NONE);
    stats.completed = deferred.len();
    let mut barrier_nodes = Vec::new();
    // To a maximum: from every unpaired node, down to the floor of Tutte–Berge with an empty
    // barrier (a maximum matching leaves at least one node of every odd piece unpaired); when KS
    // leaves exactly that many, it is maximum without a search. The pieces are counted only when
    // KS leaves more than the lone nodes plus the parity of the others: that many odd pieces
    // there are at least, so leaving no more, KS has left exactly one node per odd piece (the
    // same floor, without a pass over the graph).
    let pending = match goal {
        Goal::Maximum if pairs.unpaired > lone + (nodes - lone) % 2 => {
            let floor = odd_pieces(&compact);
            let unpaired = unpaired_nodes(&compact, &pairs.mates);
            (unpaired.len() > floor).then_some((unpaired, Some(floor)))
        }
        Goal::Maximum => None,
        Goal::Perfect => (!deferred.is_empty()).then_some((deferred, None)),
    };
    if let Some((pending, floor)) = pending {
        let complete_start = Instant::now();
        let (before, paths_before, pending_count) = (
            stats.augment.reached,
            stats.augment.augmentations,
            pending.len(),
        );
        let search = pairs
            .search
            .get_or_insert_with(|| Search::new(graph.node_slots()));
        complete(
            &compact,
            &mut pairs.mates,
            search,
            pending,
            goal,
            floor,
            &mut stats.augment,
        )?;
        // Above the floor, the completion ended with a search from every unpaired node that
        // found no augmenting path: its odd nodes are the barrier. (With a floor the pending
        // nodes were every unpaired node, and each path paired two of them.)
        let paths = stats.augment.augmentations - paths_before;
        if floor.is_some_and(|f| pending_count - 2 * paths > f) {
            barrier_nodes = search.odd_nodes();
        }
        stats.augmentation_seconds += complete_start.elapsed().as_secs_f64();
        stats.completion_reached += stats.augment.reached - before;
    }
    stats.greedy_seconds = start.elapsed().as_secs_f64() - stats.augmentation_seconds;
    let pairing = Pairing {
        mate: pairs.mates.iter().map(|&[e, _]| e).collect(),
    };
    Ok((pairing, stats, barrier_nodes))
}

/// The live nodes of `graph` that `mates` leaves unpaired, in increasing order.
fn unpaired_nodes<G: DualGraph + ?Sized>(graph: &G, mates: &[[u32; 2]]) -> Vec<u32> {
    (0..graph.node_slots() as u32)
        .filter(|&v| mates[v as usize][0] == NONE && graph.is_node(v))
        .collect()
}

/// The connected components of `graph` with an odd number of nodes: every matching leaves at
/// least this many nodes unmatched. Counted as the components are found
/// ([`label_components`]), without a pass over their labels.
fn odd_pieces<G: DualGraph + ?Sized>(graph: &G) -> usize {
    let mut component = vec![NONE; graph.node_slots()];
    let mut odd = 0;
    label_components(graph, &mut component, |size| odd += size % 2);
    odd
}

/// [`Pairs::free`] of a paired node.
const PAIRED: u8 = u8::MAX;

/// The matching that phases 2 to 5 build together, and their figures.
struct Pairs<'g, G: ?Sized> {
    graph: &'g G,
    /// `[mate edge, mate node]` per node slot (`NONE` when unpaired), as [`Search`] wants them.
    mates: Vec<[u32; 2]>,
    /// Free degree per node slot while the node is unpaired, [`PAIRED`] once it is paired (a
    /// byte per node: the greedy's "is it free" tests stay in cache).
    free: Vec<u8>,
    /// Unpaired nodes.
    unpaired: usize,
    /// Unpaired nodes whose free degree dropped to 0 (isolated: waiting for their repair, or
    /// deferred); when they are all the unpaired nodes, repairs are skipped.
    stranded: usize,
    /// The Edmonds search state (O(n) memory), made at the first Edmonds search: most runs never
    /// need it.
    search: Option<Search>,
    stats: KarpSipserStats,
}

impl<'g, G: DualGraph + ?Sized> Pairs<'g, G> {
    /// Nothing paired: `free_degrees` are the non-loop degrees of `graph`'s node slots.
    fn new(graph: &'g G, free_degrees: Vec<u8>) -> Self {
        Pairs {
            graph,
            mates: vec![[NONE, NONE]; graph.node_slots()],
            free: free_degrees,
            unpaired: graph.node_count(),
            stranded: 0,
            search: None,
            stats: KarpSipserStats::default(),
        }
    }

    #[inline]
    fn is_free(&self, v: u32) -> bool {
        self.free[v as usize] != PAIRED
    }

    /// One Edmonds search from free `root` ([`Search::run`], made on first use), stopped at the
    /// first augmenting path, which it applies; at most `budget` nodes reached, none outside
    /// `allowed`. Returns how it ended and, when it augmented, the path's other end.
    fn edmonds(
        &mut self,
        root: u32,
        budget: usize,
        allowed: impl Fn(u32) -> bool,
    ) -> (Outcome, u32) {
        let slots = self.graph.node_slots();
        let search = self.search.get_or_insert_with(|| Search::new(slots));
        let outcome = search.run(
            self.graph,
            &mut self.mates,
            &[root],
            budget,
            OnPath::Stop,
            1,
            &mut self.stats.augment,
            allowed,
        );
        self.stats.augment.reached += search.reached as u64;
        (outcome, search.last_end)
    }

    /// Whether the mates are a matching that [`Pairs::free`] and [`Pairs::unpaired`] agree with:
    /// a mate edge is at its node and its mate's mate edge too, a node is [`PAIRED`] exactly
    /// when it has a mate. For tests and debug assertions.
    fn check_invariants(&self) -> Result<(), String> {
        let mut unpaired = 0;
        for v in 0..self.graph.node_slots() as u32 {
            if !self.graph.is_node(v) {
                continue;
            }
            let [e, w] = self.mates[v as usize];
            if e == NONE {
                unpaired += 1;
                if !self.is_free(v) {
                    return Err(format!("node {v} is unpaired but marked paired"));
                }
                continue;
            }
            if self.is_free(v) {
                return Err(format!("node {v} is paired but marked free"));
            }
            let ends = self.graph.endpoints(e);
            if w == v
                || !ends.contains(&v)
                || !ends.contains(&w)
                || self.mates[w as usize] != [e, v]
            {
                return Err(format!(
                    "node {v}: mate edge {e} to node {w} is not matched both ways"
                ));
            }
        }
        if unpaired != self.unpaired {
            return Err(format!(
                "{unpaired} unpaired nodes, {} counted",
                self.unpaired
            ));
        }
        Ok(())
    }
}
