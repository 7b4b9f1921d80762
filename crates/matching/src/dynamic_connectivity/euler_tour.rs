//! Euler-tour trees kept in splay trees (Henzinger and King; as used by Holm, de Lichtenberg and
//! Thorup, J. ACM 48(4) 2001), one pool of nodes shared by all levels.
//!
//! A tree of a spanning forest is stored as the cyclic sequence of its Euler tour in which every
//! vertex appears once (its *vertex node*) and every tree edge twice (its two *arc nodes*, one per
//! direction). The sequence is the in-order of a splay tree. Each node aggregates over its subtree
//! the number of vertex nodes (tree sizes for HDT's "smaller side" rule) and two flags used to find
//! what HDT must visit: arcs of tree edges whose level equals this forest's level, and vertices
//! with non-tree edges of this level. A vertex node also heads the list of those non-tree edges.
//!
//! All operations are amortized O(log s) for trees of s nodes (splay trees), deterministic.

pub(crate) const NIL: u32 = u32::MAX;

/// Own flag: the node is a vertex node (counted by `size`).
pub(crate) const VERTEX: u8 = 1;
/// Own/aggregate flag: the arc's tree edge has exactly this forest's level.
pub(crate) const TREE: u8 = 2;
/// Own/aggregate flag: the vertex has non-tree edges of this forest's level.
pub(crate) const NONTREE: u8 = 4;

#[derive(Clone, Copy, Debug)]
struct Node {
    left: u32,
    right: u32,
    parent: u32,
    /// The same vertex, or the same arc, in the forest one level up (or NIL).
    up: u32,
    /// Number of vertex nodes in this subtree.
    size: u32,
    /// Vertex id for a vertex node, edge id for an arc node.
    id: u32,
    /// Vertex nodes: first non-tree edge of this level at the vertex (or NIL).
    nt_head: u32,
    own: u8,
    agg: u8,
}

/// A pool of splay-tree nodes representing Euler tours.
#[derive(Clone, Debug, Default)]
pub(crate) struct EulerTourForest {
    nodes: Vec<Node>,
    free: Vec<u32>,
}

impl EulerTourForest {
    pub(crate) fn with_capacity(capacity: usize) -> Self {
        EulerTourForest {
            nodes: Vec::with_capacity(capacity),
            free: Vec::new(),
        }
    }

    /// A new singleton vertex node (a one-vertex tree).
    pub(crate) fn new_vertex(&mut self, vertex: u32) -> u32 {
        self.alloc(Node {
            left: NIL,
            right: NIL,
            parent: NIL,
            up: NIL,
            size: 1,
            id: vertex,
            nt_head: NIL,
            own: VERTEX,
            agg: 0,
        })
    }

    /// A new singleton arc node for tree edge `edge`.
    pub(crate) fn new_arc(&mut self, edge: u32) -> u32 {
        self.alloc(Node {
            left: NIL,
            right: NIL,
            parent: NIL,
            up: NIL,
            size: 0,
            id: edge,
            nt_head: NIL,
            own: 0,
            agg: 0,
        })
    }

    fn alloc(&mut self, node: Node) -> u32 {
        if let Some(x) = self.free.pop() {
            self.nodes[x as usize] = node;
            x
        } else {
            let x = self.nodes.len();
            assert!(x < NIL as usize, "Euler-tour node pool exhausted");
            self.nodes.push(node);
            x as u32
        }
    }

    /// Returns a detached singleton arc node to the pool.
    pub(crate) fn release(&mut self, x: u32) {
        debug_assert!(self.nodes[x as usize].own & VERTEX == 0);
        debug_assert!(
            self.nodes[x as usize].parent == NIL
                && self.nodes[x as usize].left == NIL
                && self.nodes[x as usize].right == NIL
        );
        self.free.push(x);
    }

    /// Number of node slots (live or released).
    pub(crate) fn pool_len(&self) -> usize {
        self.nodes.len()
    }

    /// Number of live nodes (allocated minus released).
    pub(crate) fn live_nodes(&self) -> usize {
        self.nodes.len() - self.free.len()
    }

    pub(crate) fn id(&self, x: u32) -> u32 {
        self.nodes[x as usize].id
    }

    pub(crate) fn up(&self, x: u32) -> u32 {
        self.nodes[x as usize].up
    }

    pub(crate) fn set_up(&mut self, x: u32, up: u32) {
        self.nodes[x as usize].up = up;
    }

    pub(crate) fn nt_head(&self, x: u32) -> u32 {
        self.nodes[x as usize].nt_head
    }

    /// Sets the non-tree list head of vertex node `x`, keeping the NONTREE flag in step.
    pub(crate) fn set_nt_head(&mut self, x: u32, head: u32) {
        let had = self.nodes[x as usize].nt_head != NIL;
        self.nodes[x as usize].nt_head = head;
        if had != (head != NIL) {
            self.set_flag(x, NONTREE, head != NIL);
        }
    }

    /// Sets or clears an own flag of `x` and repairs the aggregates (splays `x`).
    pub(crate) fn set_flag(&mut self, x: u32, flag: u8, on: bool) {
        self.splay(x);
        let n = &mut self.nodes[x as usize];
        if on {
            n.own |= flag;
        } else {
            n.own &= !flag;
        }
        self.pull(x);
    }

    pub(crate) fn has_own_flag(&self, x: u32, flag: u8) -> bool {
        self.nodes[x as usize].own & flag != 0
    }

    #[inline]
    fn pull(&mut self, x: u32) {
        let (l, r) = {
            let n = &self.nodes[x as usize];
            (n.left, n.right)
        };
        let mut size = u32::from(self.nodes[x as usize].own & VERTEX);
        let mut agg = self.nodes[x as usize].own & !VERTEX;
        if l != NIL {
            let ln = &self.nodes[l as usize];
            size += ln.size;
            agg |= ln.agg;
        }
        if r != NIL {
            let rn = &self.nodes[r as usize];
            size += rn.size;
            agg |= rn.agg;
        }
        let n = &mut self.nodes[x as usize];
        n.size = size;
        n.agg = agg;
    }

    fn rotate(&mut self, x: u32) {
        let p = self.nodes[x as usize].parent;
        let g = self.nodes[p as usize].parent;
        if self.nodes[p as usize].left == x {
            let b = self.nodes[x as usize].right;
            self.nodes[p as usize].left = b;
            if b != NIL {
                self.nodes[b as usize].parent = p;
            }
            self.nodes[x as usize].right = p;
        } else {
            let b = self.nodes[x as usize].left;
            self.nodes[p as usize].right = b;
            if b != NIL {
                self.nodes[b as usize].parent = p;
            }
            self.nodes[x as usize].left = p;
        }
        self.nodes[p as usize].parent = x;
        self.nodes[x as usize].parent = g;
        if g != NIL {
            if self.nodes[g as usize].left == p {
                self.nodes[g as usize].left = x;
            } else {
                self.nodes[g as usize].right = x;
            }
        }
        self.pull(p);
    }

    /// Makes `x` the root of its splay tree.
    pub(crate) fn splay(&mut self, x: u32) {
        loop {
            let p = self.nodes[x as usize].parent;
            if p == NIL {
                break;
            }
            let g = self.nodes[p as usize].parent;
            if g != NIL {
                let zigzig =
                    (self.nodes[g as usize].left == p) == (self.nodes[p as usize].left == x);
                if zigzig {
                    self.rotate(p);
                } else {
                    self.rotate(x);
                }
            }
            self.rotate(x);
        }
        self.pull(x);
    }

    /// Whether `a` and `b` are in the same tree. Splays both.
    pub(crate) fn same_tree(&mut self, a: u32, b: u32) -> bool {
        if a == b {
            return true;
        }
        self.splay(a);
        self.splay(b);
        // If they share a splay tree, splaying b moved a below the root.
        self.nodes[a as usize].parent != NIL
    }

    /// Number of vertices of the tree of `x`. Splays `x`.
    pub(crate) fn tree_size(&mut self, x: u32) -> u32 {
        self.splay(x);
        self.nodes[x as usize].size
    }

    /// Finds a node with own `flag` in the tree of `x` (splaying it), if any.
    pub(crate) fn find_flag(&mut self, x: u32, flag: u8) -> Option<u32> {
        self.splay(x);
        if self.nodes[x as usize].agg & flag == 0 {
            return None;
        }
        let mut cur = x;
        loop {
            let n = self.nodes[cur as usize];
            if n.own & flag != 0 {
                break;
            }
            if n.left != NIL && self.nodes[n.left as usize].agg & flag != 0 {
                cur = n.left;
            } else {
                debug_assert!(n.right != NIL && self.nodes[n.right as usize].agg & flag != 0);
                cur = n.right;
            }
        }
        self.splay(cur);
        Some(cur)
    }

    /// Splits the sequence of `x` just before `x`; returns the roots (left part or NIL, `x`).
    fn split_before(&mut self, x: u32) -> (u32, u32) {
        self.splay(x);
        let l = self.nodes[x as usize].left;
        if l != NIL {
            self.nodes[l as usize].parent = NIL;
            self.nodes[x as usize].left = NIL;
            self.pull(x);
        }
        (l, x)
    }

    /// Concatenates two sequences given by their roots (either may be NIL); returns the root.
    fn join(&mut self, a: u32, b: u32) -> u32 {
        if a == NIL {
            return b;
        }
        if b == NIL {
            return a;
        }
        debug_assert!(self.nodes[a as usize].parent == NIL && self.nodes[b as usize].parent == NIL);
        let mut m = a;
        while self.nodes[m as usize].right != NIL {
            m = self.nodes[m as usize].right;
        }
        self.splay(m);
        self.nodes[m as usize].right = b;
        self.nodes[b as usize].parent = m;
        self.pull(m);
        m
    }

    /// Rotates the cyclic tour of `v` so that it starts at `v`; returns the root.
    fn reroot(&mut self, v: u32) -> u32 {
        let (l, r) = self.split_before(v);
        self.join(r, l)
    }

    /// Links the trees of vertex nodes `u` and `v` (different trees) by a tree edge whose arc nodes
    /// are the fresh singletons `arc_uv` and `arc_vu`: the new tour is `tour(u) arc_uv tour(v)
    /// arc_vu`, assembled in O(1) under the two arc nodes after rerooting both tours.
    pub(crate) fn link(&mut self, u: u32, v: u32, arc_uv: u32, arc_vu: u32) {
        debug_assert!(!self.same_tree(u, v));
        let ru = self.reroot(u);
        let rv = self.reroot(v);
        self.nodes[arc_vu as usize].left = rv;
        self.nodes[rv as usize].parent = arc_vu;
        self.pull(arc_vu);
        self.nodes[arc_uv as usize].left = ru;
        self.nodes[ru as usize].parent = arc_uv;
        self.nodes[arc_uv as usize].right = arc_vu;
        self.nodes[arc_vu as usize].parent = arc_uv;
        self.pull(arc_uv);
    }

    /// Cuts the tree edge whose arc nodes are `a1` and `a2`, leaving both arcs as detached
    /// singletons (to be released by the caller).
    pub(crate) fn cut(&mut self, a1: u32, a2: u32) {
        // Order the two arcs: is a2 left of a1?
        self.splay(a1);
        let mut cur = a2;
        let mut from_left = false;
        while cur != a1 {
            let p = self.nodes[cur as usize].parent;
            debug_assert!(p != NIL, "arcs of one edge must share a tree");
            from_left = self.nodes[p as usize].left == cur;
            cur = p;
        }
        let (first, second) = if from_left { (a2, a1) } else { (a1, a2) };
        // Sequence: A first B second C  ->  B  and  C A.
        self.splay(first);
        let a = self.detach(first, true);
        let rest = self.detach(first, false);
        debug_assert!(rest != NIL);
        self.splay(second); // in `rest`; also pays for the walk above
        let _b = self.detach(second, true);
        let c = self.detach(second, false);
        self.join(c, a);
    }

    /// Detaches the left (or right) subtree of the root `x`; returns it (or NIL).
    fn detach(&mut self, x: u32, left: bool) -> u32 {
        let n = &mut self.nodes[x as usize];
        let child = if left {
            std::mem::replace(&mut n.left, NIL)
        } else {
            std::mem::replace(&mut n.right, NIL)
        };
        if child != NIL {
            self.nodes[child as usize].parent = NIL;
            self.pull(x);
        }
        child
    }

    /// Builds one tree directly from its Euler-tour sequence of nodes (all singletons), in O(len).
    pub(crate) fn build_from_sequence(&mut self, seq: &[u32]) -> u32 {
        if seq.is_empty() {
            return NIL;
        }
        // Iterative midpoint construction: (lo, hi, parent, is_left)
        let mut stack: Vec<(usize, usize, u32, bool)> = vec![(0, seq.len(), NIL, false)];
        let mut order: Vec<u32> = Vec::with_capacity(seq.len());
        let mut root = NIL;
        while let Some((lo, hi, parent, is_left)) = stack.pop() {
            if lo >= hi {
                continue;
            }
            let mid = lo + (hi - lo) / 2;
            let x = seq[mid];
            self.nodes[x as usize].parent = parent;
            if parent == NIL {
                root = x;
            } else if is_left {
                self.nodes[parent as usize].left = x;
            } else {
                self.nodes[parent as usize].right = x;
            }
            order.push(x);
            stack.push((lo, mid, x, true));
            stack.push((mid + 1, hi, x, false));
        }
        // Children come after parents in `order`: pull in reverse.
        for &x in order.iter().rev() {
            self.pull(x);
        }
        root
    }

    /// In-order node sequence of the tree of `x` (for invariant checks; O(s)).
    pub(crate) fn sequence(&mut self, x: u32) -> Vec<u32> {
        self.splay(x);
        let mut out = Vec::new();
        let mut stack = Vec::new();
        let mut cur = x;
        loop {
            while cur != NIL {
                stack.push(cur);
                cur = self.nodes[cur as usize].left;
            }
            let Some(top) = stack.pop() else { break };
            out.push(top);
            cur = self.nodes[top as usize].right;
        }
        out
    }

    /// Whether `x` is a vertex node.
    pub(crate) fn is_vertex(&self, x: u32) -> bool {
        self.nodes[x as usize].own & VERTEX != 0
    }
}
