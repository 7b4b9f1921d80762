//! Phase 4 of KS: the guided completion. The deferred nodes still unpaired after the greedy are
//! few but usually far apart (they are left where the greedy's front closed up), so a
//! breadth-first Edmonds search between them reaches much of the graph. They are paired two by
//! two by *guided* searches instead, nearest first (at most [`GUIDED_MAX_HOLES`] left):
//! 1. plain breadth-first waves from all of them, until two waves meet by a path of odd length:
//!    a shortest candidate path between two of them (a plain node costs a fraction of an
//!    Edmonds one: no blossoms, three small arrays);
//! 2. an augmenting path near that path: a depth-first search steered along it, then an Edmonds
//!    search confined to the nodes within [`BAND_WIDTH`] of it, then once more with twice the
//!    width.
//!
//! The waves give up once they have met more than [`GUIDED_EVEN_CONTACTS`] times by even paths
//! (holes of one colour in a bipartite region, where only a blossom joins them). The waves'
//! queue is read ahead like the searches' ([`GuidedCompletion::prefetch_wave_ahead`]).
//!
//! When a guided search fails, the Forest strategy of [`crate::augment`] completes the rest
//! (phase 5 of [`super`]).

use std::time::Instant;

use prefetch_index::prefetch_index;

use super::band::Band;
use super::repair::{DFS_BUDGET, DepthFirst};
use super::{PAIRED, Pairs};
use crate::augment::{Outcome, PREFETCH_AHEAD};
use crate::dual_graph::{DualGraph, NONE};

/// Width of the band around a shortest path between two deferred nodes in which the guided
/// completion searches for an augmenting path (then, once, twice as wide): wide enough that the
/// Edmonds search in the band usually finds the path the first time, in a small fraction of the
/// nodes a Forest completion reaches.
const BAND_WIDTH: u32 = 4;

/// The guided completion runs only while at most this many deferred nodes are left (each guided
/// search starts waves from all of them; many holes are close together, and the Forest
/// completion pairs them in one pass).
const GUIDED_MAX_HOLES: usize = 64;

/// The guided completion gives up (the Forest completion takes the rest) once its waves have met
/// more than this many times by paths of even length (counted over the whole completion). Where
/// two waves touch only at even parity, the region between their holes is bipartite: no path
/// without a blossom joins them there, and the waves (which have no blossoms) would sweep the
/// graph in vain.
pub(super) const GUIDED_EVEN_CONTACTS: usize = 32;

/// The guided depth-first search may visit this many times the nodes of its band.
const GUIDED_DFS_FACTOR: usize = 4;

/// The guided completion's own state: the waves and the band, made at the first guided search.
#[derive(Default)]
pub(super) struct GuidedCompletion {
    /// The nodes labelled by [`GuidedCompletion::waves`].
    queue: Vec<u32>,
    /// Per node slot: 1 + the index of the source whose wave reached the node, shifted left by
    /// one, plus the parity of its distance to the source; 0 when none (between two runs of the
    /// waves, every node: [`GuidedCompletion::check_invariants`]).
    owner: Vec<u16>,
    /// Per node slot: the node its wave came from (`NONE` at a source).
    parent: Vec<u32>,
    band: Band,
}

impl GuidedCompletion {
    /// Pairs the `deferred` nodes still free two by two by guided searches
    /// ([`GuidedCompletion::waves`]), when there are at most [`GUIDED_MAX_HOLES`] of them, and
    /// leaves in `deferred` those still free (for the Forest completion).
    pub(super) fn run<G: DualGraph + ?Sized>(
        &mut self,
        pairs: &mut Pairs<G>,
        depth_first: &mut DepthFirst,
        deferred: &mut Vec<u32>,
    ) {
        let clock = Instant::now();
        let before = pairs.stats.augment.reached;
        deferred.retain(|&v| pairs.is_free(v));
        if (2..=GUIDED_MAX_HOLES).contains(&deferred.len()) {
            if self.owner.is_empty() {
                let slots = pairs.graph.node_slots();
                self.owner = vec![0; slots];
                self.parent = vec![NONE; slots];
                self.band = Band::new(slots);
            }
            self.waves(pairs, depth_first, deferred);
            deferred.retain(|&v| pairs.is_free(v));
        }
        pairs.stats.completion_reached = pairs.stats.augment.reached - before;
        pairs.stats.augmentation_seconds += clock.elapsed().as_secs_f64();
    }

    /// Whether the state is as [`GuidedCompletion::run`] leaves it, with the matching consistent
    /// ([`Pairs::check_invariants`]): no wave labels left, per-node arrays of the graph's size (or
    /// not made yet), the band's marks of no later generation than the current one.
    pub(super) fn check_invariants<G: DualGraph + ?Sized>(
        &self,
        pairs: &Pairs<G>,
    ) -> Result<(), String> {
        pairs.check_invariants()?;
        let slots = pairs.graph.node_slots();
        for (name, len) in [
            ("owner", self.owner.len()),
            ("parent", self.parent.len()),
            ("band", self.band.slots()),
        ] {
            if len != 0 && len != slots {
                return Err(format!("{name} has {len} entries for {slots} node slots"));
            }
        }
        if let Some(v) = self.owner.iter().position(|&o| o != 0) {
            return Err(format!("node {v} keeps the wave label {}", self.owner[v]));
        }
        self.band.check_invariants()
    }

    /// The waves' counterpart of the greedy's read-ahead, on their queue: the adjacency of the
    /// node [`PREFETCH_AHEAD`] places ahead, the owners, parents and free degrees of the
    /// neighbours of the node half as far.
    #[inline]
    fn prefetch_wave_ahead<G: DualGraph + ?Sized>(
        &self,
        pairs: &Pairs<G>,
        queue: &[u32],
        head: usize,
    ) {
        let Some(adjacency) = pairs.graph.flat_adjacency() else {
            return;
        };
        if let Some(&far) = queue.get(head + PREFETCH_AHEAD) {
            prefetch_index(adjacency, far as usize);
        }
        if let Some(&near) = queue.get(head + PREFETCH_AHEAD / 2) {
            for (_, w) in adjacency[near as usize] {
                prefetch_index(&self.owner, w as usize);
                prefetch_index(&pairs.free, w as usize);
                prefetch_index(&self.parent, w as usize);
            }
        }
    }

    /// Pairs up the free nodes `sources` (fewer than `u16::MAX / 2`), nearest pairs first:
    /// breadth-first waves (plain, not alternating) grow from all of them; when an edge joins
    /// the waves of two sources by a path of odd length (an augmenting path has odd length; in
    /// a bipartite region, two free nodes at even distance cannot be paired with each other),
    /// or a wave reaches a free node that is not a source at odd distance, an augmenting path
    /// is searched near the path through it ([`GuidedCompletion::search_band`]). The waves of
    /// paired sources stop, and the others may cross the nodes they labelled. Ends at the first
    /// failed search, when fewer than two sources are left, or when the waves fill the graph.
    /// Leaves [`GuidedCompletion::owner`] all 0.
    fn waves<G: DualGraph + ?Sized>(
        &mut self,
        pairs: &mut Pairs<G>,
        depth_first: &mut DepthFirst,
        sources: &[u32],
    ) {
        let mut queue = std::mem::take(&mut self.queue);
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
        // A cooperative stop (Ctrl-C from Python) is read every few thousand nodes scanned.
        let mut ticker = surftopo_mesh::stop::Ticker::default();
        'search: while left >= 2
            && even_contacts <= GUIDED_EVEN_CONTACTS
            && let Some(&x) = queue.get(head)
        {
            ticker.tick();
            self.prefetch_wave_ahead(pairs, &queue, head);
            head += 1;
            let label = self.owner[x as usize];
            if !waiting[usize::from(label >> 1)] {
                continue;
            }
            for (_, y) in pairs.graph.adjacent(x) {
                let other = self.owner[y as usize];
                let meeting = if other == 0 && pairs.is_free(y) {
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
                let Some(end) = self.search_band(pairs, depth_first, &path) else {
                    break 'search;
                };
                pairs.stats.guided += 1;
                pairs.unpaired -= 2;
                for v in [path[0], end] {
                    pairs.free[v as usize] = PAIRED;
                    let source = usize::from(self.owner[v as usize] >> 1);
                    if source > 0 && waiting[source] {
                        waiting[source] = false;
                        left -= 1;
                    }
                }
                break;
            }
        }
        pairs.stats.augment.reached += queue.len() as u64;
        for &x in &queue {
            self.owner[x as usize] = 0;
        }
        self.queue = queue;
    }

    /// The path from the source of `x`'s wave to `x`, then from `y` to the source of its wave
    /// (or to `y` itself when its parent is `NONE`), by [`GuidedCompletion::parent`].
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

    /// An augmenting path from `path[0]` near `path`, a path between two free nodes:
    /// 1. the band of the nodes within [`BAND_WIDTH`] of the path, each keyed by its distance
    ///    to the far end ([`Band::mark`]);
    /// 2. the depth-first search from `path[0]`, trying mates in increasing key order and
    ///    never leaving the band, at most [`GUIDED_DFS_FACTOR`] times the band's nodes; if it
    ///    fails (the depth-first search is incomplete where blossoms matter), an Edmonds search
    ///    confined to the band;
    /// 3. if both fail, once more in a band twice as wide.
    ///
    /// On success augments and returns the other end (any free node, not only the far end of
    /// `path`).
    fn search_band<G: DualGraph + ?Sized>(
        &mut self,
        pairs: &mut Pairs<G>,
        depth_first: &mut DepthFirst,
        path: &[u32],
    ) -> Option<u32> {
        let root = path[0];
        let mut found = None;
        for width in [BAND_WIDTH, 2 * BAND_WIDTH] {
            let band = self.band.mark(pairs.graph, path, width);
            pairs.stats.augment.reached += band as u64;
            pairs.stats.augment.searches += 1;
            found = depth_first.search(
                pairs,
                root,
                GUIDED_DFS_FACTOR * band + DFS_BUDGET,
                Some(&self.band),
            );
            if found.is_some() {
                pairs.stats.augment.augmentations += 1;
            } else {
                found = edmonds_in_band(pairs, &self.band, root);
                pairs.stats.guided_by_edmonds += usize::from(found.is_some());
            }
            if found.is_some() {
                break;
            }
        }
        found
    }
}

/// An Edmonds search from free `root` confined to `band`; on success augments and returns the
/// free end.
fn edmonds_in_band<G: DualGraph + ?Sized>(
    pairs: &mut Pairs<G>,
    band: &Band,
    root: u32,
) -> Option<u32> {
    let (outcome, end) = pairs.edmonds(root, usize::MAX, |w| band.contains(w));
    (outcome == Outcome::Augmented).then_some(end)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dual_graph::CompactDual;
    use crate::karp_sipser::repair::Repairs;
    use crate::karp_sipser::{KarpSipserOptions, karp_sipser_perfect_with};
    use crate::verify::assert_perfect_pairing;
    use surftopo_mesh::generators::icosphere;

    /// A KS matching on `graph` that is perfect except for two free nodes at the ends of an
    /// alternating path of `2 * steps + 1` edges (a perfect matching with the path's edges
    /// switched), with the free degrees as after the greedy; and that path.
    fn two_holes<'g, G: DualGraph + ?Sized>(
        graph: &'g CompactDual<'g, G>,
        steps: usize,
    ) -> (Pairs<'g, CompactDual<'g, G>>, Vec<u32>) {
        // The greedy's pairing (the tests' paths were chosen on it), not the lifted one.
        let greedy = KarpSipserOptions {
            subdivision: false,
            ..KarpSipserOptions::default()
        };
        let (perfect, _) = karp_sipser_perfect_with(graph, &greedy).unwrap();
        let mut pairs = Pairs::new(graph, vec![0; graph.node_slots()]);
        for v in 0..graph.node_slots() as u32 {
            let e = perfect.mate[v as usize];
            pairs.mates[v as usize] = [e, graph.opposite(e, v)];
            pairs.free[v as usize] = PAIRED;
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
        let mut path = vec![0u32, pairs.mates[0][1]];
        while path.len() < 2 * steps + 2 {
            let last = *path.last().unwrap();
            let Some((e, w)) = graph
                .adjacent(last)
                .into_iter()
                .filter(|&(_, w)| !path.contains(&w) && !path.contains(&pairs.mates[w as usize][1]))
                .max_by_key(|&(_, w)| distance[pairs.mates[w as usize][1] as usize])
            else {
                break;
            };
            let m = pairs.mates[w as usize][1];
            path.extend([w, m]);
            pairs.mates[last as usize] = [e, w];
            pairs.mates[w as usize] = [e, last];
        }
        let ends = [path[0], *path.last().unwrap()];
        for end in ends {
            pairs.mates[end as usize] = [NONE, NONE];
            pairs.free[end as usize] = 0;
        }
        pairs.unpaired = 2;
        pairs.stranded = 2;
        assert_eq!(path.len(), 2 * steps + 2, "the walk was not stuck");
        (pairs, path)
    }

    fn assert_perfect<G: DualGraph + ?Sized>(graph: &G, mates: &[[u32; 2]]) {
        let pairing = crate::Pairing {
            mate: mates.iter().map(|&[e, _]| e).collect(),
        };
        assert_perfect_pairing(graph, &pairing);
    }

    /// The completion's state with its per-node arrays made, as at its first guided search.
    fn made(graph: &impl DualGraph) -> GuidedCompletion {
        let slots = graph.node_slots();
        GuidedCompletion {
            owner: vec![0; slots],
            parent: vec![NONE; slots],
            band: Band::new(slots),
            ..GuidedCompletion::default()
        }
    }

    #[test]
    fn band_searches_pair_two_distant_holes() {
        let mesh = icosphere(4).mesh;
        let graph = CompactDual::new(&mesh);
        for steps in [3, 12, 30] {
            let (mut pairs, path) = two_holes(&graph, steps);
            let root = path[0];
            let ends = [root, path[path.len() - 1]];
            let mut guided = made(&graph);
            guided.check_invariants(&pairs).unwrap();
            let band = guided.band.mark(&graph, &path, BAND_WIDTH);
            assert!(band >= path.len());
            // Confined to an empty band, Edmonds finds nothing.
            let holes = pairs.mates.clone();
            let empty = guided.band.emptied();
            assert_eq!(edmonds_in_band(&mut pairs, &empty, root), None);
            assert_eq!(pairs.mates, holes);
            // Each band search alone pairs the holes.
            let other =
                edmonds_in_band(&mut pairs, &guided.band, root).expect("Edmonds in the band");
            assert_eq!(other, ends[1]);
            assert_perfect(&graph, &pairs.mates);
            pairs.mates = holes;
            let mut repairs = Repairs::new(graph.node_slots(), 0);
            let other = repairs
                .depth_first()
                .search(&mut pairs, root, usize::MAX, Some(&guided.band))
                .expect("depth-first in the band");
            assert_eq!(other, ends[1]);
            assert_perfect(&graph, &pairs.mates);
            // And the whole guided completion, which leaves its wave labels cleared.
            let (mut pairs, _) = two_holes(&graph, steps);
            let mut guided = GuidedCompletion::default();
            let mut deferred = ends.to_vec();
            guided.run(&mut pairs, repairs.depth_first(), &mut deferred);
            assert_eq!(pairs.stats.guided, 1);
            assert!(deferred.is_empty());
            assert!(guided.owner.iter().all(|&o| o == 0));
            guided.check_invariants(&pairs).unwrap();
            assert_perfect(&graph, &pairs.mates);
        }
    }

    /// The invariants catch a wave label left behind and a mate edge matched one way only.
    #[test]
    fn check_invariants_finds_broken_states() {
        let mesh = icosphere(2).mesh;
        let graph = CompactDual::new(&mesh);
        let (pairs, _) = two_holes(&graph, 3);
        let mut guided = made(&graph);
        guided.check_invariants(&pairs).unwrap();
        guided.owner[5] = 2;
        assert!(guided.check_invariants(&pairs).is_err());
        let guided = made(&graph);
        let (mut pairs, path) = two_holes(&graph, 3);
        pairs.mates[path[1] as usize] = [NONE, NONE];
        assert!(guided.check_invariants(&pairs).is_err());
        let (mut pairs, _) = two_holes(&graph, 3);
        pairs.unpaired = 0;
        assert!(guided.check_invariants(&pairs).is_err());
    }
}
