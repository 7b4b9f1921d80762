//! Fully dynamic connectivity with a mirrored spanning forest supporting path queries: the data
//! structures with which Diks and Stanczyk (SOFSEM 2010, LNCS 5901) replace the fully dynamic
//! 2-edge-connectivity structure of Biedl, Bose, Demaine and Lubiw (J. Algorithms 38(1) 2001) in
//! Frink's reductions.
//!
//! # What it maintains
//! A multigraph on vertices `0..n` whose edges are named by caller-chosen `u32` ids, under edge
//! insertions and deletions, together with a spanning forest `F` of it:
//!
//! * **Connectivity** — Holm, de Lichtenberg and Thorup (J. ACM 48(4) 2001): every edge
//!   has a level `0..=log2 n`; `F_i` (tree edges of level `>= i`) is a spanning forest of the
//!   edges of level `>= i` and its trees have at most `n / 2^i` vertices; each `F_i` is a forest
//!   of Euler-tour trees (splay trees, module `euler_tour`). Deleting a tree edge of level `l` searches
//!   for a replacement from level `l` down to 0 in the smaller half, pushing the tree edges and the
//!   non-replacement edges it visits one level up. Amortized O(log² n) per update, O(log n) per
//!   connectivity query.
//! * **Dynamic trees** — the level-0 forest `F = F_0` is mirrored in link-cut trees
//!   (module `link_cut`; Sleator–Tarjan) with `evert` and LCA, so that questions about tree paths in
//!   `F` cost amortized O(log n).
//! * **Bridges** — [`DynamicConnectivity::is_bridge`] answers whether an edge is a bridge of the
//!   current graph exactly, by deleting it, asking whether its ends are still connected, and
//!   inserting it again: amortized O(log² n).
//!
//! Diks and Stanczyk's observation (reconstructed in [`crate::diks_stanczyk`]) is that these are
//! enough to decide which of Frink's two reduced graphs is bridgeless, so no fully dynamic
//! 2-edge-connectivity structure (HDT's cover levels over top trees, O(log⁴ n) per update) is
//! needed; that is what brings the matching algorithm from O(n log⁴ n) to O(n log² n).
//!
//! The structure is deterministic (splay trees, no random priorities).

mod euler_tour;
mod link_cut;

use euler_tour::{EulerTourForest, NIL, NONTREE, TREE};
use link_cut::LinkCutForest;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum State {
    Absent,
    Loop,
    Tree,
    NonTree,
}

/// Work counters of a [`DynamicConnectivity`] (for benchmarks and tests).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DynamicStats {
    /// Edge insertions (bulk construction included).
    pub insertions: u64,
    /// Edge deletions.
    pub deletions: u64,
    /// Deletions of spanning-forest edges (the ones that search for a replacement).
    pub tree_deletions: u64,
    /// Sum over deleted spanning-forest edges of (level + 1): the number of forests they were
    /// cut from.
    pub tree_deletion_forests: u64,
    /// Replacement edges found.
    pub replacements: u64,
    /// Level increases of tree edges.
    pub tree_promotions: u64,
    /// Level increases of non-tree edges.
    pub nontree_promotions: u64,
    /// Highest edge level reached.
    pub max_level: u8,
}

/// Fully dynamic connectivity (Holm–de Lichtenberg–Thorup) over a multigraph with caller-chosen
/// edge ids, with its spanning forest mirrored in link-cut trees for path queries.
///
/// Complexity (amortized, `n` vertices): [`insert_edge`](Self::insert_edge),
/// [`delete_edge`](Self::delete_edge) and [`is_bridge`](Self::is_bridge) O(log² n);
/// [`connected`](Self::connected) and [`tree_paths_intersect`](Self::tree_paths_intersect)
/// O(log n). Memory O(n + m) plus O(1) per level an edge has reached. Edge ids should be dense
/// (the per-edge arrays are as long as the largest id).
#[derive(Clone, Debug)]
pub struct DynamicConnectivity {
    n: u32,
    et: EulerTourForest,
    lct: LinkCutForest,
    /// Level-0 Euler-tour vertex node of each vertex; higher levels are chained by `up`.
    vbase: Vec<u32>,
    ends: Vec<[u32; 2]>,
    state: Vec<State>,
    level: Vec<u8>,
    /// Level-0 arc nodes of tree edges; higher levels are chained by `up`.
    arcs: Vec<[u32; 2]>,
    /// Doubly-linked lists of non-tree edges per (vertex, level); slot 0/1 = endpoint 0/1.
    nt_next: Vec<[u32; 2]>,
    nt_prev: Vec<[u32; 2]>,
    edge_count: usize,
    stats: DynamicStats,
}

impl DynamicConnectivity {
    /// An empty graph on `node_count` vertices. O(n).
    pub fn new(node_count: u32) -> Self {
        let mut et = EulerTourForest::with_capacity(node_count as usize);
        let vbase = (0..node_count).map(|v| et.new_vertex(v)).collect();
        DynamicConnectivity {
            n: node_count,
            et,
            lct: LinkCutForest::new(node_count as usize),
            vbase,
            ends: Vec::new(),
            state: Vec::new(),
            level: Vec::new(),
            arcs: Vec::new(),
            nt_next: Vec::new(),
            nt_prev: Vec::new(),
            edge_count: 0,
            stats: DynamicStats::default(),
        }
    }

    /// The graph with edges `edges` (edge id = index), built in O(n + m) time: a depth-first
    /// spanning forest becomes the level-0 forest, its Euler tours are laid out as balanced splay
    /// trees and its parent pointers seed the link-cut trees. Loops and parallel edges are allowed.
    ///
    /// # Panics
    /// If an edge names a vertex `>= node_count`, or there are `u32::MAX` edges or more.
    pub fn from_edges(node_count: u32, edges: &[[u32; 2]]) -> Self {
        assert!(edges.len() < NIL as usize, "too many edges");
        let n = node_count as usize;
        let m = edges.len();
        let mut dc = DynamicConnectivity::new(node_count);
        dc.ensure_edge_slot(m.saturating_sub(1) as u32);
        // CSR adjacency without loops.
        let mut start = vec![0u32; n + 1];
        for (e, &[a, b]) in edges.iter().enumerate() {
            assert!(
                a < node_count && b < node_count,
                "edge {e}: vertex out of range"
            );
            if a != b {
                start[a as usize + 1] += 1;
                start[b as usize + 1] += 1;
            }
        }
        for v in 0..n {
            start[v + 1] += start[v];
        }
        let mut fill = start.clone();
        let mut adj = vec![0u32; start[n] as usize];
        for (e, &[a, b]) in edges.iter().enumerate() {
            if a != b {
                adj[fill[a as usize] as usize] = e as u32;
                fill[a as usize] += 1;
                adj[fill[b as usize] as usize] = e as u32;
                fill[b as usize] += 1;
            }
        }
        drop(fill);
        for (e, &ab) in edges.iter().enumerate() {
            dc.ends[e] = ab;
            dc.level[e] = 0;
            dc.state[e] = if ab[0] == ab[1] {
                State::Loop
            } else {
                State::NonTree
            };
        }
        dc.edge_count = m;
        dc.stats.insertions = m as u64;
        // Depth-first spanning forest and its Euler tours.
        let mut seen = vec![false; n];
        let mut stack: Vec<(u32, u32, u32)> = Vec::new(); // (vertex, entering edge, next adj index)
        let mut seq: Vec<u32> = Vec::new();
        let mut ticker = surftopo_mesh::stop::Ticker::default();
        for root in 0..node_count {
            if seen[root as usize] {
                continue;
            }
            seen[root as usize] = true;
            if start[root as usize] == start[root as usize + 1] {
                continue; // isolated: its singleton vertex node is already a tree
            }
            seq.clear();
            seq.push(dc.vbase[root as usize]);
            stack.push((root, NIL, start[root as usize]));
            while let Some(top) = stack.last_mut() {
                ticker.tick();
                let (v, via, idx) = *top;
                if idx < start[v as usize + 1] {
                    top.2 += 1;
                    let e = adj[idx as usize];
                    let [a, b] = edges[e as usize];
                    let w = if a == v { b } else { a };
                    if !seen[w as usize] {
                        seen[w as usize] = true;
                        // Tree edge; arc x runs v -> w. The arc ends[0] -> ends[1] carries the flag.
                        dc.state[e as usize] = State::Tree;
                        let x = dc.et.new_arc(e);
                        let y = dc.et.new_arc(e);
                        dc.arcs[e as usize] = if a == v { [x, y] } else { [y, x] };
                        dc.et.set_flag(dc.arcs[e as usize][0], TREE, true);
                        seq.push(x);
                        seq.push(dc.vbase[w as usize]);
                        dc.lct.set_initial_parent(w, v);
                        stack.push((w, e, start[w as usize]));
                    }
                } else {
                    stack.pop();
                    if via != NIL {
                        let arcs = dc.arcs[via as usize];
                        let [a, _] = edges[via as usize];
                        // Arc from the child back to the parent.
                        seq.push(if a == v { arcs[0] } else { arcs[1] });
                    }
                }
            }
            // Non-tree edges of this component into the level-0 lists while its vertex nodes are
            // still singletons (O(1) flag updates), then the balanced build.
            for &x in &seq {
                if dc.et.is_vertex(x) {
                    let v = dc.et.id(x);
                    for k in start[v as usize]..start[v as usize + 1] {
                        let e = adj[k as usize];
                        let [a, _] = edges[e as usize];
                        // Each non-tree edge once, from its first endpoint.
                        if dc.state[e as usize] == State::NonTree && a == v {
                            dc.nt_add(e);
                        }
                    }
                }
            }
            dc.et.build_from_sequence(&seq);
        }
        dc
    }

    /// Number of vertices.
    pub fn node_count(&self) -> u32 {
        self.n
    }

    /// Number of edges present.
    pub fn edge_count(&self) -> usize {
        self.edge_count
    }

    /// Work counters so far.
    pub fn stats(&self) -> DynamicStats {
        self.stats
    }

    /// Whether edge `id` is present.
    pub fn contains_edge(&self, id: u32) -> bool {
        self.state
            .get(id as usize)
            .is_some_and(|&s| s != State::Absent)
    }

    /// The two vertices of edge `id`, if present.
    pub fn endpoints(&self, id: u32) -> Option<[u32; 2]> {
        self.contains_edge(id).then(|| self.ends[id as usize])
    }

    /// Whether edge `id` is present and belongs to the maintained spanning forest.
    pub fn is_tree_edge(&self, id: u32) -> bool {
        self.state.get(id as usize) == Some(&State::Tree)
    }

    /// The level of forest edge `id` (`None` for absent and non-forest edges).
    pub fn tree_level(&self, id: u32) -> Option<u8> {
        self.is_tree_edge(id).then(|| self.level[id as usize])
    }

    fn ensure_edge_slot(&mut self, id: u32) {
        let need = id as usize + 1;
        if need > self.ends.len() {
            let len = need.max(self.ends.len() * 2).max(16);
            self.ends.resize(len, [NIL; 2]);
            self.state.resize(len, State::Absent);
            self.level.resize(len, 0);
            self.arcs.resize(len, [NIL; 2]);
            self.nt_next.resize(len, [NIL; 2]);
            self.nt_prev.resize(len, [NIL; 2]);
        }
    }

    /// Inserts edge `id` between `a` and `b` (loops and parallel edges allowed).
    ///
    /// # Panics
    /// If `id` is present already, or `a`/`b` is out of range.
    pub fn insert_edge(&mut self, id: u32, a: u32, b: u32) {
        assert!(
            a < self.n && b < self.n,
            "edge {id}: vertex out of range ({a}, {b})"
        );
        assert!(id != NIL, "edge id u32::MAX is reserved");
        self.ensure_edge_slot(id);
        assert!(!self.contains_edge(id), "edge {id} is present already");
        self.stats.insertions += 1;
        self.edge_count += 1;
        let e = id as usize;
        self.ends[e] = [a, b];
        self.level[e] = 0;
        if a == b {
            self.state[e] = State::Loop;
        } else if self
            .et
            .same_tree(self.vbase[a as usize], self.vbase[b as usize])
        {
            self.state[e] = State::NonTree;
            self.nt_add(id);
        } else {
            self.state[e] = State::Tree;
            self.link_tree_edge(id, 0);
        }
    }

    /// Deletes edge `id`. If it was a spanning-forest edge, a replacement is searched for.
    ///
    /// # Panics
    /// If `id` is not present.
    pub fn delete_edge(&mut self, id: u32) {
        assert!(self.contains_edge(id), "edge {id} is not present");
        self.stats.deletions += 1;
        self.edge_count -= 1;
        let e = id as usize;
        match self.state[e] {
            State::Absent => unreachable!(),
            State::Loop => {}
            State::NonTree => self.nt_remove(id),
            State::Tree => {
                self.stats.tree_deletions += 1;
                let top = self.level[e];
                self.stats.tree_deletion_forests += u64::from(top) + 1;
                let [a, b] = self.ends[e];
                self.cut_tree_edge(id);
                self.state[e] = State::Absent;
                self.find_replacement(a, b, top);
            }
        }
        self.state[e] = State::Absent;
    }

    /// Whether `a` and `b` are connected. Amortized O(log n).
    ///
    /// # Panics
    /// If a vertex is out of range.
    pub fn connected(&mut self, a: u32, b: u32) -> bool {
        self.et
            .same_tree(self.vbase[a as usize], self.vbase[b as usize])
    }

    /// Whether edge `id` is a bridge of the current graph (loops and non-forest edges never are).
    /// Deletes the edge, asks whether its ends are still connected, and inserts it again (at
    /// level 0, possibly now as a non-forest edge). Amortized O(log² n).
    ///
    /// # Panics
    /// If `id` is not present.
    pub fn is_bridge(&mut self, id: u32) -> bool {
        assert!(self.contains_edge(id), "edge {id} is not present");
        if self.state[id as usize] != State::Tree {
            return false;
        }
        let [a, b] = self.ends[id as usize];
        self.delete_edge(id);
        let bridge = !self.connected(a, b);
        self.insert_edge(id, a, b);
        bridge
    }

    /// Whether the paths `a..b` and `c..d` of the maintained spanning forest share a vertex;
    /// `None` if the four vertices are not all in one tree. Amortized O(log n).
    ///
    /// # Panics
    /// If a vertex is out of range.
    pub fn tree_paths_intersect(&mut self, a: u32, b: u32, c: u32, d: u32) -> Option<bool> {
        if !(self.connected(a, b) && self.connected(a, c) && self.connected(a, d)) {
            return None;
        }
        Some(self.lct.paths_intersect(a, b, c, d))
    }

    /// [`tree_paths_intersect`](Self::tree_paths_intersect) for callers that know the four
    /// vertices are connected.
    pub(crate) fn tree_paths_intersect_connected(
        &mut self,
        a: u32,
        b: u32,
        c: u32,
        d: u32,
    ) -> bool {
        debug_assert!(self.connected(a, b) && self.connected(a, c) && self.connected(a, d));
        self.lct.paths_intersect(a, b, c, d)
    }

    // ----- internals -------------------------------------------------------------------------

    /// Euler-tour vertex node of `v` at `level`, or NIL.
    fn vnode(&self, v: u32, level: u8) -> u32 {
        let mut x = self.vbase[v as usize];
        for _ in 0..level {
            if x == NIL {
                break;
            }
            x = self.et.up(x);
        }
        x
    }

    fn ensure_vnode(&mut self, v: u32, level: u8) -> u32 {
        let mut x = self.vbase[v as usize];
        for _ in 0..level {
            let u = self.et.up(x);
            x = if u == NIL {
                let nu = self.et.new_vertex(v);
                self.et.set_up(x, nu);
                nu
            } else {
                u
            };
        }
        x
    }

    /// Adds tree edge `id` to the forests `F_0..=F_top` (its level is `top`).
    fn link_tree_edge(&mut self, id: u32, top: u8) {
        let [a, b] = self.ends[id as usize];
        let mut xa = self.vbase[a as usize];
        let mut xb = self.vbase[b as usize];
        let mut prev = [NIL; 2];
        for j in 0..=top {
            if j > 0 {
                xa = self.et.up(xa);
                xb = self.et.up(xb);
                debug_assert!(xa != NIL && xb != NIL);
            }
            let p = self.et.new_arc(id);
            let q = self.et.new_arc(id);
            if j == 0 {
                self.arcs[id as usize] = [p, q];
            } else {
                self.et.set_up(prev[0], p);
                self.et.set_up(prev[1], q);
            }
            self.et.link(xa, xb, p, q);
            prev = [p, q];
        }
        self.et.set_flag(prev[0], TREE, true);
        self.level[id as usize] = top;
        self.lct.link(a, b);
    }

    /// Removes tree edge `id` from all its forests and from the link-cut trees.
    fn cut_tree_edge(&mut self, id: u32) {
        let [mut p, mut q] = self.arcs[id as usize];
        while p != NIL {
            let (np, nq) = (self.et.up(p), self.et.up(q));
            self.et.cut(p, q);
            self.et.release(p);
            self.et.release(q);
            p = np;
            q = nq;
        }
        self.arcs[id as usize] = [NIL; 2];
        let [a, b] = self.ends[id as usize];
        self.lct.cut(a, b);
    }

    /// Raises tree edge `id` from level `i` to `i + 1`.
    fn promote_tree_edge(&mut self, id: u32, i: u8) {
        debug_assert_eq!(self.level[id as usize], i);
        self.stats.tree_promotions += 1;
        let [mut p, mut q] = self.arcs[id as usize];
        for _ in 0..i {
            p = self.et.up(p);
            q = self.et.up(q);
        }
        self.et.set_flag(p, TREE, false);
        let [a, b] = self.ends[id as usize];
        let xa = self.ensure_vnode(a, i + 1);
        let xb = self.ensure_vnode(b, i + 1);
        let np = self.et.new_arc(id);
        let nq = self.et.new_arc(id);
        self.et.set_up(p, np);
        self.et.set_up(q, nq);
        self.et.link(xa, xb, np, nq);
        self.et.set_flag(np, TREE, true);
        self.level[id as usize] = i + 1;
        self.stats.max_level = self.stats.max_level.max(i + 1);
    }

    fn slot(&self, e: u32, v: u32) -> usize {
        usize::from(self.ends[e as usize][0] != v)
    }

    fn nt_add(&mut self, e: u32) {
        let level = self.level[e as usize];
        for s in 0..2 {
            let v = self.ends[e as usize][s];
            let x = self.vnode(v, level);
            debug_assert!(x != NIL, "non-tree edge {e} above its vertex's forests");
            let head = self.et.nt_head(x);
            self.nt_next[e as usize][s] = head;
            self.nt_prev[e as usize][s] = NIL;
            if head != NIL {
                let hs = self.slot(head, v);
                self.nt_prev[head as usize][hs] = e;
            }
            self.et.set_nt_head(x, e);
        }
    }

    fn nt_remove(&mut self, e: u32) {
        let level = self.level[e as usize];
        for s in 0..2 {
            let v = self.ends[e as usize][s];
            let prev = self.nt_prev[e as usize][s];
            let next = self.nt_next[e as usize][s];
            if next != NIL {
                let ns = self.slot(next, v);
                self.nt_prev[next as usize][ns] = prev;
            }
            if prev != NIL {
                let ps = self.slot(prev, v);
                self.nt_next[prev as usize][ps] = next;
            } else {
                let x = self.vnode(v, level);
                self.et.set_nt_head(x, next);
            }
            self.nt_next[e as usize][s] = NIL;
            self.nt_prev[e as usize][s] = NIL;
        }
    }

    /// HDT's `Replace`: after the tree edge `a - b` of level `top` was cut, look for a non-tree
    /// edge reconnecting the two halves, from level `top` down to 0, in the smaller half.
    fn find_replacement(&mut self, a: u32, b: u32, top: u8) {
        for i in (0..=top).rev() {
            let xa = self.vnode(a, i);
            let xb = self.vnode(b, i);
            let sa = self.et.tree_size(xa);
            let sb = self.et.tree_size(xb);
            let small = if sa <= sb { xa } else { xb };
            debug_assert!(
                u64::from(sa.min(sb)) << (i + 1) <= u64::from(self.n),
                "HDT size invariant violated at level {i}"
            );
            while let Some(arc) = self.et.find_flag(small, TREE) {
                let e = self.et.id(arc);
                self.promote_tree_edge(e, i);
            }
            while let Some(vx) = self.et.find_flag(small, NONTREE) {
                let v = self.et.id(vx);
                loop {
                    let g = self.et.nt_head(vx);
                    if g == NIL {
                        break;
                    }
                    let [p, q] = self.ends[g as usize];
                    let w = if p == v { q } else { p };
                    let wx = self.vnode(w, i);
                    if self.et.same_tree(vx, wx) {
                        self.nt_remove(g);
                        self.level[g as usize] = i + 1;
                        self.stats.max_level = self.stats.max_level.max(i + 1);
                        self.stats.nontree_promotions += 1;
                        self.nt_add(g);
                    } else {
                        self.nt_remove(g);
                        self.state[g as usize] = State::Tree;
                        self.stats.replacements += 1;
                        self.link_tree_edge(g, i);
                        return;
                    }
                }
            }
        }
    }

    /// Checks every invariant of the structure against a recomputation from scratch; returns a
    /// description of the first violation. O((n + m) log n); meant for tests. The checks, in
    /// order: the edges against union-find recomputations of the graph's and the forest's
    /// components (`check_edges`); each vertex's node per level and its non-tree lists
    /// (`check_vertex_levels`); each tree edge's arcs per level
    /// (`check_tree_edges`); the node count; each tour as a closed walk
    /// (`check_tours`); the link-cut trees against `F_0` (`check_link_cut`).
    ///
    /// # Errors
    /// A message naming the violated invariant.
    pub fn check_invariants(&mut self) -> Result<(), String> {
        let (mut all, mut forest) = self.check_edges()?;
        let mut comp_size = vec![0u32; self.n as usize];
        for v in 0..self.n {
            let (ra, rf) = (find(&mut all, v), find(&mut forest, v));
            if find(&mut all, rf) != ra {
                return Err(format!("vertex {v}: forest component differs"));
            }
            comp_size[ra as usize] += 1;
        }
        let expected_nodes =
            self.check_vertex_levels(&mut all, &comp_size)? + self.check_tree_edges()?;
        if expected_nodes != self.et.live_nodes() {
            return Err(format!(
                "{} live Euler-tour nodes, {expected_nodes} expected",
                self.et.live_nodes()
            ));
        }
        self.check_tours()?;
        self.check_link_cut(&mut forest)
    }

    /// [`Self::check_invariants`]' first phase: forest edges close no cycle, loops are loops,
    /// the edge count is right. Returns the union-find parents over all present edges and over
    /// the forest edges.
    fn check_edges(&self) -> Result<(Vec<u32>, Vec<u32>), String> {
        let mut all: Vec<u32> = (0..self.n).collect();
        let mut forest: Vec<u32> = (0..self.n).collect();
        let mut present = 0usize;
        for e in 0..self.state.len() {
            let [a, b] = self.ends[e];
            match self.state[e] {
                State::Absent => continue,
                State::Tree => {
                    let (ra, rb) = (find(&mut forest, a), find(&mut forest, b));
                    if ra == rb {
                        return Err(format!("forest edge {e} closes a cycle"));
                    }
                    forest[ra as usize] = rb;
                }
                State::Loop if a != b => return Err(format!("edge {e} marked loop")),
                _ => {}
            }
            present += 1;
            let (ra, rb) = (find(&mut all, a), find(&mut all, b));
            all[ra as usize] = rb;
        }
        if present != self.edge_count {
            return Err(format!("edge count {} != {present}", self.edge_count));
        }
        Ok((all, forest))
    }

    /// [`Self::check_invariants`]' second phase: each vertex's node at each level (the level-0
    /// tour spans its component of `comp_size`, a level-i tree has at most n / 2^i vertices) and
    /// its non-tree list (entries of its level, linked both ways, within one tree; two entries
    /// per non-tree edge in all). `all` is [`Self::check_edges`]' union-find of the graph.
    /// Returns the number of vertex nodes.
    fn check_vertex_levels(&mut self, all: &mut [u32], comp_size: &[u32]) -> Result<usize, String> {
        // Non-tree edges connect vertices of one forest component: implied by the checks below.
        let mut nt_count_by_level: Vec<usize> = Vec::new();
        let mut expected_nodes = 0usize;
        for v in 0..self.n {
            // Level-0 tree size equals the component size; size invariant at each level.
            let mut x = self.vbase[v as usize];
            let mut lvl = 0u32;
            while x != NIL {
                expected_nodes += 1;
                let s = self.et.tree_size(x);
                if lvl == 0 {
                    let c = comp_size[find(all, v) as usize];
                    if s != c {
                        return Err(format!(
                            "vertex {v}: level-0 tour has {s} vertices, component {c}"
                        ));
                    }
                } else if u64::from(s) << lvl > u64::from(self.n) {
                    return Err(format!("vertex {v}: level-{lvl} tree of {s} vertices"));
                }
                if self.et.id(x) != v || !self.et.is_vertex(x) {
                    return Err(format!("vertex {v}: wrong vertex node at level {lvl}"));
                }
                // Walk its non-tree list.
                let mut g = self.et.nt_head(x);
                if (g != NIL) != self.et.has_own_flag(x, NONTREE) {
                    return Err(format!(
                        "vertex {v}: NONTREE flag out of step at level {lvl}"
                    ));
                }
                let mut prev = NIL;
                while g != NIL {
                    let s = self.slot(g, v);
                    if self.state[g as usize] != State::NonTree
                        || u32::from(self.level[g as usize]) != lvl
                        || self.ends[g as usize][s] != v
                        || self.nt_prev[g as usize][s] != prev
                    {
                        return Err(format!(
                            "vertex {v}: bad non-tree list entry {g} at level {lvl}"
                        ));
                    }
                    let w = self.ends[g as usize][1 - s];
                    let wx = self.vnode(w, lvl as u8);
                    if wx == NIL || !self.et.same_tree(x, wx) {
                        return Err(format!("non-tree edge {g} of level {lvl} spans two trees"));
                    }
                    if nt_count_by_level.len() <= lvl as usize {
                        nt_count_by_level.resize(lvl as usize + 1, 0);
                    }
                    nt_count_by_level[lvl as usize] += 1;
                    prev = g;
                    g = self.nt_next[g as usize][s];
                }
                x = self.et.up(x);
                lvl += 1;
            }
        }
        let listed: usize = nt_count_by_level.iter().sum();
        let nontree = self.state.iter().filter(|&&s| s == State::NonTree).count();
        if listed != 2 * nontree {
            return Err(format!(
                "{listed} list entries for {nontree} non-tree edges"
            ));
        }
        Ok(expected_nodes)
    }

    /// [`Self::check_invariants`]' third phase: each tree edge has an arc pair at every level up
    /// to its own, in the trees of its endpoints, with the TREE flag at its level only. Returns
    /// the number of arc nodes.
    fn check_tree_edges(&mut self) -> Result<usize, String> {
        let mut expected_nodes = 0usize;
        for e in 0..self.state.len() as u32 {
            if self.state[e as usize] != State::Tree {
                continue;
            }
            let [a, b] = self.ends[e as usize];
            let top = u32::from(self.level[e as usize]);
            let [mut p, mut q] = self.arcs[e as usize];
            let mut lvl = 0u32;
            while p != NIL {
                expected_nodes += 2;
                let (xa, xb) = (self.vnode(a, lvl as u8), self.vnode(b, lvl as u8));
                if xa == NIL || xb == NIL {
                    return Err(format!("tree edge {e}: endpoint missing at level {lvl}"));
                }
                if !(self.et.same_tree(p, xa)
                    && self.et.same_tree(q, xb)
                    && self.et.same_tree(p, q))
                {
                    return Err(format!(
                        "tree edge {e}: arcs not in its tree at level {lvl}"
                    ));
                }
                if self.et.id(p) != e || self.et.id(q) != e {
                    return Err(format!("tree edge {e}: foreign arc at level {lvl}"));
                }
                if self.et.has_own_flag(p, TREE) != (lvl == top) || self.et.has_own_flag(q, TREE) {
                    return Err(format!("tree edge {e}: TREE flag wrong at level {lvl}"));
                }
                p = self.et.up(p);
                q = self.et.up(q);
                lvl += 1;
            }
            if lvl != top + 1 {
                return Err(format!("tree edge {e}: {lvl} forests for level {top}"));
            }
        }
        Ok(expected_nodes)
    }

    /// [`Self::check_invariants`]' fourth phase: each tour is a closed walk (consecutive arcs
    /// chain up, cyclically) and every vertex node sits where the walk is at its vertex.
    fn check_tours(&mut self) -> Result<(), String> {
        let mut arc_dir = vec![[NIL; 2]; self.et.pool_len()]; // node -> [tail, head]
        for e in 0..self.state.len() {
            if self.state[e] != State::Tree {
                continue;
            }
            let [a, b] = self.ends[e];
            let [mut p, mut q] = self.arcs[e];
            while p != NIL {
                arc_dir[p as usize] = [a, b];
                arc_dir[q as usize] = [b, a];
                p = self.et.up(p);
                q = self.et.up(q);
            }
        }
        let mut visited = vec![false; self.et.pool_len()];
        for v in 0..self.n {
            let mut x = self.vbase[v as usize];
            while x != NIL {
                if !visited[x as usize] {
                    let seq = self.et.sequence(x);
                    for &y in &seq {
                        visited[y as usize] = true;
                    }
                    let arcs: Vec<usize> = (0..seq.len())
                        .filter(|&k| !self.et.is_vertex(seq[k]))
                        .collect();
                    if arcs.is_empty() {
                        if seq.len() != 1 {
                            return Err(format!(
                                "tour of vertex {v} without arcs has {} nodes",
                                seq.len()
                            ));
                        }
                    } else {
                        for (j, &k) in arcs.iter().enumerate() {
                            let next = arcs[(j + 1) % arcs.len()];
                            let at = arc_dir[seq[k] as usize][1];
                            if at == NIL || arc_dir[seq[next] as usize][0] != at {
                                return Err(format!("tour of vertex {v}: arcs do not chain"));
                            }
                            let mut t = (k + 1) % seq.len();
                            while t != next {
                                if self.et.id(seq[t]) != at {
                                    return Err(format!(
                                        "tour of vertex {v}: vertex node misplaced"
                                    ));
                                }
                                t = (t + 1) % seq.len();
                            }
                        }
                    }
                }
                x = self.et.up(x);
            }
        }
        Ok(())
    }

    /// [`Self::check_invariants`]' last phase: the link-cut trees mirror `F_0` (one root per
    /// forest component of `forest`, [`Self::check_edges`]' union-find, and no root shared).
    fn check_link_cut(&mut self, forest: &mut [u32]) -> Result<(), String> {
        let n = self.n as usize;
        let mut rep = vec![NIL; n];
        for v in 0..self.n {
            let r = self.lct.find_root(v);
            let c = find(forest, v);
            if rep[c as usize] == NIL {
                rep[c as usize] = r;
            } else if rep[c as usize] != r {
                return Err(format!(
                    "vertex {v}: link-cut root differs within a component"
                ));
            }
        }
        let mut roots_seen = vec![false; n];
        for c in 0..n {
            if rep[c] != NIL {
                if roots_seen[rep[c] as usize] {
                    return Err("two components share a link-cut root".into());
                }
                roots_seen[rep[c] as usize] = true;
            }
        }
        Ok(())
    }
}

/// Union-find's root of `x` in the parent array `p`, halving the path (for
/// [`DynamicConnectivity::check_invariants`]' recomputations).
fn find(p: &mut [u32], mut x: u32) -> u32 {
    while p[x as usize] != x {
        p[x as usize] = p[p[x as usize] as usize];
        x = p[x as usize];
    }
    x
}
