//! A perfect pairing by the Karp–Sipser greedy with immediate local repairs (KS): not one of the
//! quadrangulation paper's algorithms, but the fastest way we found to a perfect pairing of a
//! mesh dual, built from the paper's own pieces (a greedy pairing completed by Edmonds'
//! augmenting paths, Section 3.1) and its closing suggestion (Section 5: search for augmenting
//! paths locally, where the unpaired triangles are).
//!
//! # Step 0: the file's quads
//! When the triangles are written two by two as the quads of a quad mesh (every node `2k`
//! adjacent to `2k + 1`), that pairing is perfect and is returned as it is, in O(n), with no
//! greedy ([`crate::file_order`] says why; [`KarpSipserOptions::file_order`] turns it off).
//!
//! # Step 1: the coarser mesh's pairing
//! When the triangles are written four by four as the children of a 1-to-4 subdivision, KS
//! pairs the coarser mesh (recursively, so every level of subdivision is peeled off) and lifts
//! that pairing in O(n), with no greedy ([`crate::subdivision_order`] says how and why;
//! [`KarpSipserOptions::subdivision`] turns it off). A coarse graph with no perfect pairing
//! (possible when the blocks only look like a subdivision) falls back to the greedy.
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
//!   rule of Magun (1998) that keeps few nodes isolated. Measured (nodes reached by the repairs,
//!   `quad_profile`): against the first neighbour in edge order, the bricks of groups A and B go
//!   from 3,000–8,000 isolated triangles to none at all, and the shared meshes of 100k+ faces
//!   reach 8% fewer nodes;
//! - ties go to the side already swept, so the front leaves no gaps behind and, on the
//!   (near-)bipartite duals of regular meshes, pairs coherently, without seams of same-coloured
//!   triangles that only long paths can pair: in id order the neighbour of smallest id (or
//!   largest, once the sweep runs down); in breadth-first order the neighbour the front met
//!   first. Measured (`quad_profile`, nodes reached), breadth-first ties by front against by
//!   smallest id (a random choice when ids are not local): nefertiti 50k to 17k, skull 36k to
//!   24k, gargoyle 57k to 41k, rolling_stage 75k to 66k, koala and igea unchanged, hand1 37k to
//!   41k, brick B5 56 to 2.8k; with the faces shuffled, sketched_brunnen 219k to 74k,
//!   seahorse2_100K 96k to 52k, venus_50k 34k to 4k, icosphere(7) 1.09M to 0.66M, feline 48k
//!   to 60k;
//! - degree-one nodes are paired as soon as they appear (a stack), before the next start;
//! - in breadth-first order the starts ahead on the frontier are loaded into cache early
//!   (`KarpSipser::prefetch_ahead`), since the frontier is known in advance;
//! - in id order, a deferred node (see below) that is the only unpaired one behind the sweep,
//!   met in the last [`REVERSE_TAIL`]th of the ids, reverses the sweep, so that the sweep ends
//!   next to it, where its partner will be isolated (`IdSweep` says why and what was measured).
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
//! A repair that exceeds both budgets is abandoned and the node *deferred*. Once every
//! unpaired node is isolated (the greedy is over), the repairs are skipped and the nodes deferred
//! at once: a path can only end at another isolated node, and those whose repairs failed are far
//! apart. Measured (`quad_profile MESH 1 ks`, nodes reached): icosphere(7) shuffled, whose 50
//! deferred triangles are all isolated at the very end, 481.7k to 427.3k; the shared meshes of
//! 100k+ faces and their shuffled versions 0–1.1k fewer (the last isolated node), the same
//! deferrals and completions.
//!
//! # The completion
//! The deferred nodes still unpaired after the greedy are few (0–16 on the shared meshes of
//! 100k+ faces) but usually far apart (they are left where the greedy's front closed up), so a
//! breadth-first Edmonds search between them reaches much of the graph (45k–65k of the 73k–92k
//! nodes of a 100k-face run). They are paired two by two by *guided* searches instead, nearest
//! first (at most [`GUIDED_MAX_HOLES`] left):
//! 1. plain breadth-first waves from all of them, until two waves meet by a path of odd length:
//!    a shortest candidate path between two of them (a plain node costs a fraction of an
//!    Edmonds one: no blossoms, three small arrays);
//! 2. an augmenting path near that path: a depth-first search steered along it, then an
//!    Edmonds search confined to the nodes within [`BAND_WIDTH`] of it, then once more with
//!    twice the width.
//!
//! The waves give up once they have met more than [`GUIDED_EVEN_CONTACTS`] times by even paths
//! (holes of one colour in a bipartite region, where only a blossom joins them). The waves'
//! queue is read ahead like the searches' (`KarpSipser::prefetch_wave_ahead`): icosphere(7)
//! shuffled, whose waves swept the whole graph, 17.8 to 11.8 ms before the give-up rule; koala
//! 1.87 to 1.60 ms.
//!
//! When a guided search fails, the Forest strategy of [`crate::augment`] completes the rest, as
//! for any greedy pairing, except that the trees retired by a path do not wall the others in:
//! they are reopened ([`crate::augment`] says why and what was measured). So the result is
//! always perfect (or an [`AugmentError`] proves that the graph has no perfect matching).
//!
//! Figures are those of the paper's Table 4.3: the greedy counts as the initial pairing; every
//! repair and the completion count as augmentation (timed separately); "unpaired" is the number
//! of isolated nodes met.
//!
//! Complexity: O(n) for the greedy and the repairs (each bounded); O(n) per guided search
//! (at most one per pair of deferred nodes); plus the Forest completion when a guided search
//! fails (see [`crate::augment`]). On the bricks of groups A and B the greedy isolates at most
//! one triangle.

use std::time::Instant;

use prefetch_index::prefetch_index;

use crate::augment::{
    AugmentError, AugmentStats, OnPath, Outcome, PREFETCH_AHEAD, Search, complete,
};
use crate::dual_graph::{CompactDual, DualGraph, NONE, Pairing};
use crate::file_order::file_order_pairing;
use crate::subdivision_order::coarsen;

/// Nodes a repair's Edmonds search may reach before it is abandoned and its node deferred to the
/// completion. Measured before the guided completion existed (`quad_profile`, nodes reached on
/// seahorse, koala, feline, rolling_stage, sketched_brunnen): 1024 reaches 395k in all, 8192
/// 380k, no limit 423k; with no limit there is nothing to complete, and seahorse, koala and
/// rolling_stage reach 2–7x fewer nodes, but feline and sketched_brunnen 2x more (some repairs
/// must cross most of the graph).
pub const REPAIR_BUDGET: usize = 1024;

/// Nodes the depth-first first try of a repair may visit before the Edmonds search takes over.
/// Measured on the shared meshes of 100k+ faces and on the bricks A5 and B5 (`quad_profile`):
/// with 64, the repairs reach 10% more nodes on the shared meshes but 4x fewer on B5 (5.2M to
/// 1.35M), and a depth-first node costs less than an Edmonds one.
pub const DFS_BUDGET: usize = 64;

/// Node ids are *local* when 90% of the id distances between neighbours (sampled) are at most
/// this.
pub const LOCAL_ID_GAP: u32 = 2048;

/// Width of the band around a shortest path between two deferred nodes in which the guided
/// completion searches for an augmenting path (then, once, twice as wide). Measured
/// (`quad_profile`): with 4, the Edmonds search in the band finds the path on seahorse,
/// koala and rolling_stage the first time, in 1,200–1,900 nodes where the Forest completion
/// reached 45,000–65,000.
pub const BAND_WIDTH: u32 = 4;

/// The guided completion runs only while at most this many deferred nodes are left (each
/// guided search starts waves from all of them; many holes are close together, and the Forest
/// completion pairs them in one pass).
pub const GUIDED_MAX_HOLES: usize = 64;

/// A lone deferred node reverses the id sweep (see `IdSweep`) only when less than
/// `1 / REVERSE_TAIL` of the ids are left to sweep.
pub const REVERSE_TAIL: usize = 4;

/// The guided completion gives up (the Forest completion takes the rest) once its waves have met
/// more than this many times by paths of even length (counted over the whole completion). Where two waves touch only at even parity, the
/// region between their holes is bipartite: no path without a blossom joins them there, and the
/// waves (which have no blossoms) would sweep the graph in vain. Measured (`quad_profile MESH 1
/// ks`): 0–14 even meetings in all on the shared meshes of 100k+ faces and their shuffled
/// versions, whose guided paths save 10–50% of the completion's time; sketched_brunnen shuffled
/// 76 before its first odd one (its third guided search fails after 59k wave nodes), and
/// icosphere(7) shuffled 7,964 and no odd one in 327k wave nodes (the whole graph), where the
/// Forest completion alone is 2x and 4x faster.
pub const GUIDED_EVEN_CONTACTS: usize = 32;

/// The guided depth-first search may visit this many times the nodes of its band.
pub const GUIDED_DFS_FACTOR: usize = 4;

/// Figures of one [`karp_sipser_perfect`] run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct KarpSipserStats {
    /// Whether the pairing is the file's quads ([`crate::file_order`]): no greedy, no search.
    pub file_order: bool,
    /// Levels of 1-to-4 subdivision the pairing was lifted through ([`crate::subdivision_order`]);
    /// the other figures are then those of the coarsest level's run.
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
    /// (false; see the module doc).
    pub id_order: bool,
    /// Times the id sweep was reversed for a lone deferred node (see the module doc).
    pub reversals: usize,
    /// The searches of the repairs and of the completion (nodes reached, paths, ...).
    pub augment: AugmentStats,
}

/// Settings of [`karp_sipser_perfect_with`]; the defaults are [`karp_sipser_perfect`]'s.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct KarpSipserOptions {
    /// Nodes the Edmonds search of a repair may reach (0 skips both repair searches and defers
    /// every isolated node to the completion).
    pub repair_budget: usize,
    /// Whether the deferred nodes are first paired by guided searches (else by the Forest
    /// strategy alone).
    pub guided_completion: bool,
    /// Whether a file written quad by quad is paired as written (step 0 of the module doc).
    pub file_order: bool,
    /// Whether a file written as a 1-to-4 subdivision is paired by lifting the coarser mesh's
    /// pairing (step 1 of the module doc).
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
    let start = Instant::now();
    let nodes = graph.node_count();
    if !nodes.is_multiple_of(2) {
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
        return Ok((pairing, stats));
    }
    // The copy serves the greedy too; the lift reads it rather than the mesh, whose half-edges
    // need not be in face order.
    let (compact, degrees) = CompactDual::with_degrees(graph);
    if options.subdivision
        && let Some(level) = coarsen(&compact)
        && let Ok((coarse, coarse_stats)) = karp_sipser_perfect_with(level.coarse(), options)
    {
        let pairing = level.lift(&compact, &coarse);
        let stats = KarpSipserStats {
            file_order: false,
            subdivision_levels: coarse_stats.subdivision_levels + 1,
            greedy_seconds: start.elapsed().as_secs_f64() - coarse_stats.augmentation_seconds,
            ..coarse_stats
        };
        return Ok((pairing, stats));
    }
    let mut ks = KarpSipser::new(&compact, degrees, options.repair_budget);
    ks.greedy();
    if options.guided_completion {
        ks.complete_guided();
    }
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
        stats.completion_reached += stats.augment.reached - before;
    }
    stats.greedy_seconds = start.elapsed().as_secs_f64() - stats.augmentation_seconds;
    let pairing = Pairing {
        mate: ks.mates.iter().map(|&[e, _]| e).collect(),
    };
    Ok((pairing, stats))
}

/// [`KarpSipser::free`] of a paired node.
const PAIRED: u8 = u8::MAX;

/// [`KarpSipser::seen`] of a node the front has not met.
const UNSEEN: u32 = u32::MAX;

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
    /// Free degree per node slot while the node is unpaired, [`PAIRED`] once it is paired (a
    /// byte per node: the greedy's "is it free" tests stay in cache).
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
    /// In breadth-first order: per node slot, when the front first met it (its first push on
    /// the frontier, or its start), `UNSEEN` before; the greedy's tie key. Empty in id order.
    seen: Vec<u32>,
    /// The next `seen` stamp.
    seen_next: u32,
    /// The ids not considered yet as start nodes.
    sweep: IdSweep,
    /// Nodes a repair search may reach.
    repair_budget: usize,
    /// Unpaired nodes.
    unpaired: usize,
    /// Unpaired nodes whose free degree dropped to 0 (isolated: waiting for their repair, or
    /// deferred); when they are all the unpaired nodes, repairs are skipped.
    stranded: usize,
    /// Generation stamps of the depth-first repairs (nodes visited by the current one).
    dfs_stamp: Vec<u32>,
    dfs_generation: u32,
    /// The current depth-first path.
    dfs_stack: Vec<DfsFrame>,
    /// The nodes labelled by [`KarpSipser::guided_waves`].
    bfs_queue: Vec<u32>,
    /// Per node slot, made at the first guided search: `[generation, key]`, in the band of
    /// [`KarpSipser::band`] when the generation is `band_generation`.
    band: Vec<[u32; 2]>,
    band_generation: u32,
    /// The nodes of the current band.
    band_queue: Vec<u32>,
    /// Per node slot, made at the first guided search: 1 + the index of the source whose wave
    /// reached the node ([`KarpSipser::guided_waves`]), shifted left by one, plus the parity of
    /// its distance to the source; 0 when none.
    owner: Vec<u16>,
    /// Per node slot: the node its wave came from (`NONE` at a source).
    parent: Vec<u32>,
}

/// The ids not considered yet as start nodes, `low..high`, taken from the low end, or from the
/// high end once `descending`.
///
/// Why reverse: in id order, a node deferred near the end of the sweep while no other deferred
/// node is unpaired needs a partner, and by parity the last node isolated by the greedy is one;
/// it appears where the sweep ends. Swept upwards, the rest ends at the top ids, far from the
/// deferred node; swept downwards, it ends next to it, where the sweep is now. Measured
/// (`quad_profile MESH 5 ks`, nodes reached): seahorse2_100K 78,763 to 35,737 (completion 51,319
/// to 9,843); feline, sketched_brunnen and venus unchanged (no lone hole in the tail). Reversing
/// at every deferral, or at any point of the sweep, made feline (6 to 14–20 deferrals) and
/// sketched_brunnen (100k to 124k–138k nodes) worse.
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

/// One even node of the depth-first path of [`KarpSipser::dfs_repair`].
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

impl<'g, G: DualGraph + ?Sized> KarpSipser<'g, G> {
    /// The state before the greedy: `free_degrees` are the non-loop degrees of `graph`'s node
    /// slots.
    fn new(graph: &'g G, free_degrees: Vec<u8>, repair_budget: usize) -> Self {
        let n = graph.node_slots();
        let id_order = ids_are_local(graph);
        KarpSipser {
            graph,
            mates: vec![[NONE, NONE]; n],
            free: free_degrees,
            forced: Vec::new(),
            isolated: Vec::new(),
            deferred: Vec::new(),
            search: None,
            stats: KarpSipserStats::default(),
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
            dfs_stamp: vec![0; n],
            dfs_generation: 0,
            dfs_stack: Vec::new(),
            bfs_queue: Vec::new(),
            owner: Vec::new(),
            parent: Vec::new(),
            band: Vec::new(),
            band_generation: 0,
            band_queue: Vec::new(),
            repair_budget,
            unpaired: graph.node_count(),
            stranded: 0,
        }
    }

    /// A copy of the pairing state (for tests comparing two searches from the same state).
    #[cfg(test)]
    fn clone_state(&self) -> Self {
        let mut copy = KarpSipser::new(self.graph, self.free.clone(), self.repair_budget);
        copy.mates.clone_from(&self.mates);
        copy.owner.clone_from(&self.owner);
        copy.parent.clone_from(&self.parent);
        copy.bfs_queue.clone_from(&self.bfs_queue);
        copy.band.clone_from(&self.band);
        copy.band_generation = self.band_generation;
        copy
    }

    #[inline]
    fn is_free(&self, v: u32) -> bool {
        self.free[v as usize] != PAIRED
    }

    /// An augmenting path from isolated `u` to free `other` was applied: both are paired now.
    fn path_applied(&mut self, u: u32, other: u32) {
        self.unpaired -= 2;
        self.stranded -= 1 + usize::from(self.free[other as usize] == 0);
        self.free[u as usize] = PAIRED;
        self.free[other as usize] = PAIRED;
        self.now_paired(other);
    }

    fn greedy(&mut self) {
        let mut head = 0;
        while let Some(s) = self.next_start(&mut head) {
            let mut best: Option<(u8, u32, u32, u32)> = None;
            // Ties: the side already swept. In id order the smallest id, or the largest once
            // the sweep runs down; in breadth-first order the node the front met first.
            let flip = if self.sweep.descending { u32::MAX } else { 0 };
            for (e, w) in self.graph.adjacent(s) {
                if w != s && self.is_free(w) {
                    let d = self.free[w as usize];
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
                self.join(e, s, w);
            }
            self.drain();
        }
    }

    /// The next node to start from, free and with a free neighbour: the oldest such frontier
    /// node (breadth-first order; the frontier stays empty in id order), else the next such id
    /// of the [`IdSweep`].
    fn next_start(&mut self, head: &mut usize) -> Option<u32> {
        while let Some(&x) = self.frontier.get(*head) {
            self.prefetch_ahead(*head);
            *head += 1;
            if self.is_free(x) && self.free[x as usize] > 0 {
                return Some(x);
            }
        }
        // A removed node slot has free degree 0.
        while let Some(v) = self.sweep.next() {
            if self.is_free(v) && self.free[v as usize] > 0 {
                self.mark_seen(v);
                return Some(v);
            }
        }
        None
    }

    /// The waves' counterpart of [`KarpSipser::prefetch_ahead`], on their queue: the adjacency
    /// of the node [`PREFETCH_AHEAD`] places ahead, the owners, parents and free degrees of the
    /// neighbours of the node half as far.
    #[inline]
    fn prefetch_wave_ahead(&self, queue: &[u32], head: usize) {
        let Some(adjacency) = self.graph.flat_adjacency() else {
            return;
        };
        if let Some(&far) = queue.get(head + PREFETCH_AHEAD) {
            prefetch_index(adjacency, far as usize);
        }
        if let Some(&near) = queue.get(head + PREFETCH_AHEAD / 2) {
            for (_, w) in adjacency[near as usize] {
                prefetch_index(&self.owner, w as usize);
                prefetch_index(&self.free, w as usize);
                prefetch_index(&self.parent, w as usize);
            }
        }
    }

    /// Starts loading what the starts ahead of frontier position `head` will read (breadth-first
    /// order, on a flat graph), as the augmenting searches do with their queue
    /// ([`PREFETCH_AHEAD`]): the adjacency and free degree of the node that many places ahead,
    /// the free degrees and front stamps of the neighbours of the node half as far. Measured
    /// (`quad_profile MESH 11 ks`, the greedy's time, minimum of the medians of alternating
    /// runs): sketched_brunnen shuffled 3.44 to 3.06 ms, icosphere(7) shuffled 29.4 to 20.3
    /// ms, feline shuffled 3.25 to 2.89 ms, koala 3.19 to 2.87 ms, skull 2.96 to 2.71 ms; 16
    /// and 8 places ahead instead of 8 and 4: no difference.
    #[inline]
    fn prefetch_ahead(&self, head: usize) {
        let Some(adjacency) = self.graph.flat_adjacency() else {
            return;
        };
        if let Some(&far) = self.frontier.get(head + PREFETCH_AHEAD) {
            prefetch_index(adjacency, far as usize);
            prefetch_index(&self.free, far as usize);
        }
        if let Some(&near) = self.frontier.get(head + PREFETCH_AHEAD / 2) {
            for (_, w) in adjacency[near as usize] {
                prefetch_index(&self.free, w as usize);
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
    /// other direction (see `IdSweep`).
    fn reverse_for_lone_hole(&mut self) {
        let left = self.sweep.left() as usize;
        if self.id_order
            && left * REVERSE_TAIL < self.graph.node_slots()
            && self
                .deferred
                .iter()
                .filter(|&&v| self.is_free(v))
                .take(2)
                .count()
                == 1
        {
            self.sweep.descending = !self.sweep.descending;
            self.stats.reversals += 1;
        }
    }

    /// Pairs the forced nodes and repairs the isolated ones until neither is left.
    fn drain(&mut self) {
        loop {
            if let Some(a) = self.forced.pop() {
                if self.free[a as usize] != 1 {
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
        self.unpaired -= 2;
        self.mates[a as usize] = [e, b];
        self.mates[b as usize] = [e, a];
        self.free[a as usize] = PAIRED;
        self.free[b as usize] = PAIRED;
        self.now_paired(a);
        self.now_paired(b);
    }

    /// `x` was free and is now paired: its free neighbours lose a free edge.
    fn now_paired(&mut self, x: u32) {
        for (_, y) in self.graph.adjacent(x) {
            if y != x && self.is_free(y) {
                if !self.id_order {
                    self.frontier.push(y);
                    self.mark_seen(y);
                }
                let f = &mut self.free[y as usize];
                *f -= 1;
                match *f {
                    1 => self.forced.push(y),
                    0 => {
                        self.stranded += 1;
                        self.isolated.push(y);
                    }
                    _ => {}
                }
            }
        }
    }

    /// Depth-first alternating search from isolated `u` with lookahead (Pothen and Fan's
    /// heuristic for bipartite matching), without blossoms, visiting at most `budget` nodes; on
    /// success augments and returns the free end. Each node is visited at most once, so the path
    /// found is simple and a valid augmenting path even though blossoms are ignored; a path that
    /// only a blossom would reveal is left to the Edmonds search. With `guided`, only mates
    /// inside the band of [`KarpSipser::band`] are entered, in increasing key order (towards
    /// the far end of the band's path); otherwise every neighbour slot, in slot order.
    fn dfs_repair(&mut self, u: u32, budget: usize, guided: bool) -> Option<u32> {
        self.dfs_generation += 1;
        let generation = self.dfs_generation;
        self.dfs_stamp[u as usize] = generation;
        self.dfs_stack.clear();
        let root = self.frame(u, NONE, guided);
        self.dfs_stack.push(root);
        let mut visited = 1usize;
        let found = 'search: loop {
            let &DfsFrame {
                node: v,
                order,
                len,
                tried,
                ..
            } = self.dfs_stack.last()?;
            let adjacent = self.graph.adjacent(v);
            if tried == 0 {
                // Lookahead: a free neighbour ends the path at once.
                for (e, w) in adjacent {
                    if w != v && w != u && self.is_free(w) {
                        break 'search (e, w);
                    }
                }
            }
            if tried == len {
                self.dfs_stack.pop();
                continue;
            }
            self.dfs_stack.last_mut().expect("not empty").tried += 1;
            let (e, w) = adjacent[usize::from(order[usize::from(tried)])];
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
            if visited > budget {
                return None;
            }
            let frame = self.frame(m, e, guided);
            self.dfs_stack.push(frame);
        };
        // Augment along the stack: v_k - found, then each v_{i-1} - w_i.
        let (mut e, mut x) = found;
        let end = x;
        while let Some(frame) = self.dfs_stack.pop() {
            let v = frame.node;
            let old_mate = self.mates[v as usize][1];
            self.mates[v as usize] = [e, x];
            self.mates[x as usize] = [e, v];
            if v == u {
                break;
            }
            // The odd node before v is its old mate; it pairs with the previous even node.
            e = frame.edge_in;
            x = old_mate;
        }
        Some(end)
    }

    /// The depth-first frame of even node `v` entered through `edge_in`.
    fn frame(&self, v: u32, edge_in: u32, guided: bool) -> DfsFrame {
        let mut order = [0, 1, 2];
        let mut len = 3;
        if guided {
            let adjacent = self.graph.adjacent(v);
            let key = |slot: u8| {
                let w = adjacent[usize::from(slot)].1;
                if w == v || self.is_free(w) {
                    return u32::MAX;
                }
                match self.band[self.mates[w as usize][1] as usize] {
                    [g, key] if g == self.band_generation => key,
                    _ => u32::MAX,
                }
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

    /// Pairs the deferred nodes still free two by two by guided searches
    /// ([`KarpSipser::guided_waves`]), when there are at most [`GUIDED_MAX_HOLES`] of them. The
    /// Forest completion takes the rest.
    fn complete_guided(&mut self) {
        let clock = Instant::now();
        let before = self.stats.augment.reached;
        let mut holes = std::mem::take(&mut self.deferred);
        holes.retain(|&v| self.is_free(v));
        if (2..=GUIDED_MAX_HOLES).contains(&holes.len()) {
            if self.owner.is_empty() {
                self.owner = vec![0; self.graph.node_slots()];
                self.parent = vec![NONE; self.graph.node_slots()];
                self.band = vec![[0, 0]; self.graph.node_slots()];
            }
            self.guided_waves(&holes);
            holes.retain(|&v| self.is_free(v));
        }
        self.deferred = holes;
        self.stats.completion_reached = self.stats.augment.reached - before;
        self.stats.augmentation_seconds += clock.elapsed().as_secs_f64();
    }

    /// An augmenting path from `path[0]` near `path`, a path between two free nodes:
    /// 1. the band of the nodes within [`BAND_WIDTH`] of the path, each keyed by its distance
    ///    to the far end ([`KarpSipser::band`]);
    /// 2. the depth-first search from `path[0]`, trying mates in increasing key order and
    ///    never leaving the band, at most [`GUIDED_DFS_FACTOR`] times the band's nodes; if it
    ///    fails (the depth-first search is incomplete where blossoms matter), an Edmonds search
    ///    confined to the band;
    /// 3. if both fail, once more in a band twice as wide.
    ///
    /// On success augments and returns the other end (any free node, not only the far end of
    /// `path`).
    fn search_band(&mut self, path: &[u32]) -> Option<u32> {
        let root = path[0];
        let mut found = None;
        for width in [BAND_WIDTH, 2 * BAND_WIDTH] {
            let band = self.band(path, width);
            self.stats.augment.searches += 1;
            found = self.dfs_repair(root, GUIDED_DFS_FACTOR * band + DFS_BUDGET, true);
            if found.is_some() {
                self.stats.augment.augmentations += 1;
            } else {
                found = self.edmonds_in_band(root);
                self.stats.guided_by_edmonds += usize::from(found.is_some());
            }
            if found.is_some() {
                break;
            }
        }
        found
    }

    /// An Edmonds search from free `root` confined to the band of [`KarpSipser::band`]; on
    /// success augments and returns the free end.
    fn edmonds_in_band(&mut self, root: u32) -> Option<u32> {
        let search = self
            .search
            .get_or_insert_with(|| Search::new(self.graph.node_slots()));
        let (band, generation) = (&self.band, self.band_generation);
        let outcome = search.run(
            self.graph,
            &mut self.mates,
            &[root],
            usize::MAX,
            OnPath::Stop,
            &mut self.stats.augment,
            |w| band[w as usize][0] == generation,
        );
        self.stats.augment.reached += search.reached as u64;
        (outcome == Outcome::Augmented).then_some(search.last_end)
    }

    /// Pairs up the free nodes `sources` (fewer than `u16::MAX / 2`), nearest pairs first:
    /// breadth-first waves (plain, not alternating) grow from all of them; when an edge joins
    /// the waves of two sources by a path of odd length (an augmenting path has odd length; in
    /// a bipartite region, two free nodes at even distance cannot be paired with each other),
    /// or a wave reaches a free node that is not a source at odd distance, an augmenting path
    /// is searched near the path through it ([`KarpSipser::search_band`]). The waves of paired
    /// sources stop, and the others may cross the nodes they labelled. Ends at the first failed
    /// search, when fewer than two sources are left, or when the waves fill the graph. Leaves
    /// [`KarpSipser::owner`] all 0.
    fn guided_waves(&mut self, sources: &[u32]) {
        let mut queue = std::mem::take(&mut self.bfs_queue);
        queue.clear();
        for (i, &s) in sources.iter().enumerate() {
            self.owner[s as usize] = (i as u16 + 1) << 1;
            self.parent[s as usize] = NONE;
            queue.push(s);
        }
        // Per source (`owner >> 1`): still free.
        let mut waiting = vec![true; sources.len() + 1];
        let mut left = sources.len();
        let mut head = 0;
        let mut even_contacts = 0;
        'search: while left >= 2
            && even_contacts <= GUIDED_EVEN_CONTACTS
            && let Some(&x) = queue.get(head)
        {
            self.prefetch_wave_ahead(&queue, head);
            head += 1;
            let label = self.owner[x as usize];
            if !waiting[usize::from(label >> 1)] {
                continue;
            }
            for (_, y) in self.graph.adjacent(x) {
                let other = self.owner[y as usize];
                let meeting = if other == 0 && self.is_free(y) {
                    // A free node that is not a source, at distance d(x) + 1.
                    self.parent[y as usize] = NONE;
                    label & 1 == 0
                } else if other == 0 || !waiting[usize::from(other >> 1)] {
                    self.owner[y as usize] = label ^ 1;
                    self.parent[y as usize] = x;
                    queue.push(y);
                    false
                } else if other >> 1 == label >> 1 {
                    false
                } else if other & 1 == label & 1 {
                    // Two waves, and a path of odd length d(x) + 1 + d(y).
                    true
                } else {
                    even_contacts += 1;
                    false
                };
                if !meeting {
                    continue;
                }
                let path = self.path_between(x, y);
                let Some(end) = self.search_band(&path) else {
                    break 'search;
                };
                self.stats.guided += 1;
                for v in [path[0], end] {
                    self.free[v as usize] = PAIRED;
                    let source = usize::from(self.owner[v as usize] >> 1);
                    if source > 0 && waiting[source] {
                        waiting[source] = false;
                        left -= 1;
                    }
                }
                break;
            }
        }
        self.stats.augment.reached += queue.len() as u64;
        for &x in &queue {
            self.owner[x as usize] = 0;
        }
        self.bfs_queue = queue;
    }

    /// The path from the source of `x`'s wave to `x`, then from `y` to the source of its wave
    /// (or to `y` itself when its parent is `NONE`), by [`KarpSipser::parent`].
    fn path_between(&self, x: u32, y: u32) -> Vec<u32> {
        let mut path = Vec::new();
        for end in [x, y] {
            let mut z = end;
            while z != NONE {
                path.push(z);
                z = self.parent[z as usize];
            }
            if end == x {
                path.reverse();
            }
        }
        path
    }

    /// Marks the nodes within `width` of `path` as the band (a new [`KarpSipser::band`]
    /// generation) and keys each by its distance to the path's far end: along the path from the
    /// path node it was reached from, plus its depth. Returns the number of nodes in the band.
    fn band(&mut self, path: &[u32], width: u32) -> usize {
        self.band_generation += 1;
        let generation = self.band_generation;
        let mut queue = std::mem::take(&mut self.band_queue);
        queue.clear();
        let last = path.len() - 1;
        for (i, &p) in path.iter().enumerate() {
            self.band[p as usize] = [generation, (last - i) as u32];
            queue.push(p);
        }
        let mut head = 0;
        for _ in 0..width {
            let layer_end = queue.len();
            while head < layer_end {
                let x = queue[head];
                head += 1;
                let key = self.band[x as usize][1] + 1;
                for (_, y) in self.graph.adjacent(x) {
                    if self.band[y as usize][0] != generation {
                        self.band[y as usize] = [generation, key];
                        queue.push(y);
                    }
                }
            }
        }
        let labelled = queue.len();
        self.stats.augment.reached += labelled as u64;
        self.band_queue = queue;
        labelled
    }

    /// Repairs isolated node `u`: the depth-first search, else a bounded Edmonds search, else
    /// defers it. On success the free node at the other end of the path is now paired too (the
    /// nodes inside the path stay paired).
    fn repair(&mut self, u: u32) {
        let clock = Instant::now();
        self.stats.isolated += 1;
        // Every unpaired node isolated: the greedy is over, and a path from `u` can only end
        // at another isolated node, far away when its own repair failed; the completion pairs
        // them all at once.
        if self.unpaired == self.stranded {
            self.stats.augment.unmatched_before += 1;
            self.stats.skipped += 1;
            self.defer(u, clock);
            return;
        }
        if self.repair_budget > 0
            && let Some(other) = self.dfs_repair(u, DFS_BUDGET, false)
        {
            self.stats.repaired += 1;
            self.stats.augment.unmatched_before += 1;
            self.stats.augment.searches += 1;
            self.stats.augment.augmentations += 1;
            self.stats.augmentation_seconds += clock.elapsed().as_secs_f64();
            self.path_applied(u, other);
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
            OnPath::Stop,
            stats,
            |_| true,
        );
        stats.reached += search.reached as u64;
        match outcome {
            Outcome::Augmented => {
                self.stats.repaired += 1;
                let other = search.last_end;
                self.stats.augmentation_seconds += clock.elapsed().as_secs_f64();
                self.path_applied(u, other);
                return;
            }
            Outcome::OverBudget => stats.abandoned += 1,
            // No augmenting path from u at all: the completion reports it.
            Outcome::Exhausted => {}
        }
        self.defer(u, clock);
    }

    /// Leaves isolated `u` to the completion (its repair started at `clock`).
    fn defer(&mut self, u: u32, clock: Instant) {
        self.deferred.push(u);
        self.stats.deferred += 1;
        self.reverse_for_lone_hole();
        self.stats.augmentation_seconds += clock.elapsed().as_secs_f64();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::verify::verify_perfect_matching_on;
    use surftopo_mesh::generators::icosphere;

    /// A KS state on `graph` whose matching is perfect except for two free nodes at the ends of
    /// an alternating path of `2 * steps + 1` edges (a perfect matching with the path's edges
    /// switched), with the free degrees as after the greedy; and that path.
    fn two_holes<'g, G: DualGraph + ?Sized>(
        graph: &'g CompactDual<'g, G>,
        steps: usize,
    ) -> (KarpSipser<'g, CompactDual<'g, G>>, Vec<u32>) {
        // The greedy's pairing (the tests' paths were chosen on it), not the lifted one.
        let greedy = KarpSipserOptions {
            subdivision: false,
            ..KarpSipserOptions::default()
        };
        let (perfect, _) = karp_sipser_perfect_with(graph, &greedy).unwrap();
        let mut ks = KarpSipser::new(graph, vec![0; graph.node_slots()], 0);
        for v in 0..graph.node_slots() as u32 {
            let e = perfect.mate[v as usize];
            ks.mates[v as usize] = [e, graph.opposite(e, v)];
            ks.free[v as usize] = PAIRED;
        }
        // Hop distances from node 0, so that the walk can head away from it.
        let mut distance = vec![u32::MAX; graph.node_slots()];
        let mut queue = std::collections::VecDeque::from([0u32]);
        distance[0] = 0;
        while let Some(x) = queue.pop_front() {
            for (_, y) in graph.adjacent(x) {
                if distance[y as usize] == u32::MAX {
                    distance[y as usize] = distance[x as usize] + 1;
                    queue.push_back(y);
                }
            }
        }
        // Walk p0 -M- p1 - p2 -M- p3 ... outwards on unvisited nodes, switching the edges.
        let mut path = vec![0u32, ks.mates[0][1]];
        while path.len() < 2 * steps + 2 {
            let last = *path.last().unwrap();
            let Some((e, w)) = graph
                .adjacent(last)
                .into_iter()
                .filter(|&(_, w)| !path.contains(&w) && !path.contains(&ks.mates[w as usize][1]))
                .max_by_key(|&(_, w)| distance[ks.mates[w as usize][1] as usize])
            else {
                break;
            };
            let m = ks.mates[w as usize][1];
            path.extend([w, m]);
            ks.mates[last as usize] = [e, w];
            ks.mates[w as usize] = [e, last];
        }
        let ends = [path[0], *path.last().unwrap()];
        for end in ends {
            ks.mates[end as usize] = [NONE, NONE];
            ks.free[end as usize] = 0;
        }
        assert_eq!(path.len(), 2 * steps + 2, "the walk was not stuck");
        (ks, path)
    }

    fn assert_perfect<G: DualGraph + ?Sized>(graph: &G, mates: &[[u32; 2]]) {
        let edges: Vec<[u32; 2]> = (0..graph.edge_slots() as u32)
            .map(|e| graph.endpoints(e))
            .collect();
        let mut matched = vec![false; edges.len()];
        for &[e, _] in mates {
            matched[e as usize] = true;
        }
        verify_perfect_matching_on(graph.node_count() as u32, &edges, &matched).unwrap();
    }

    #[test]
    fn band_searches_pair_two_distant_holes() {
        let mesh = icosphere(4).mesh;
        let graph = CompactDual::new(&mesh);
        for steps in [3, 12, 30] {
            let (mut ks, path) = two_holes(&graph, steps);
            let root = path[0];
            let ends = [root, path[path.len() - 1]];
            ks.band = vec![[0, 0]; graph.node_slots()];
            let band = ks.band(&path, BAND_WIDTH);
            assert!(band >= path.len());
            // Confined to an empty band, Edmonds finds nothing.
            let mut confined = ks.clone_state();
            confined.band_generation += 1;
            assert_eq!(confined.edmonds_in_band(root), None);
            assert_eq!(confined.mates, ks.mates);
            // Each band search alone pairs the holes.
            let mut by_edmonds = ks.clone_state();
            let other = by_edmonds
                .edmonds_in_band(root)
                .expect("Edmonds in the band");
            assert_eq!(other, ends[1]);
            assert_perfect(&graph, &by_edmonds.mates);
            let other = ks
                .dfs_repair(root, usize::MAX, true)
                .expect("depth-first in the band");
            assert_eq!(other, ends[1]);
            assert_perfect(&graph, &ks.mates);
            // And the whole guided completion, which leaves its wave labels cleared.
            let (mut ks, _) = two_holes(&graph, steps);
            ks.deferred = ends.to_vec();
            ks.complete_guided();
            assert_eq!(ks.stats.guided, 1);
            assert!(ks.deferred.is_empty());
            assert!(ks.owner.iter().all(|&o| o == 0));
            assert_perfect(&graph, &ks.mates);
        }
    }

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
            let mut ks = KarpSipser::new(&graph, vec![3; n as usize], REPAIR_BUDGET);
            ks.id_order = id_order;
            ks.sweep.low = n - left;
            for v in 0..n {
                if !holes.contains(&v) {
                    ks.free[v as usize] = PAIRED;
                }
            }
            ks.deferred = holes.to_vec();
            ks.reverse_for_lone_hole();
            (ks.sweep.descending, ks.stats.reversals)
        };
        let tail = n / (2 * REVERSE_TAIL as u32);
        assert_eq!(state(true, tail, &[7]), (true, 1));
        assert_eq!(state(true, tail, &[7, 9]), (false, 0));
        assert_eq!(state(true, n / 2, &[7]), (false, 0));
        assert_eq!(state(false, tail, &[7]), (false, 0));
        // A deferred node paired since does not count.
        let mut ks = KarpSipser::new(&graph, vec![3; n as usize], REPAIR_BUDGET);
        ks.id_order = true;
        ks.sweep.low = n - tail;
        ks.deferred = vec![7, 9];
        ks.free.fill(PAIRED);
        ks.free[9] = 0;
        ks.reverse_for_lone_hole();
        assert!(ks.sweep.descending);
    }
}
