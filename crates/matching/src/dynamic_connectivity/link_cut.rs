//! Link-cut trees (Sleator and Tarjan, "A data structure for dynamic trees", JCSS 26(3) 1983) with
//! `evert` (change of root) and lowest common ancestors: the "dynamic trees" that Diks and Stanczyk
//! use beside dynamic connectivity. Vertices only; an edge is a parent pointer. All operations are
//! amortized O(log n).

use super::euler_tour::NIL;

/// A forest of rooted trees on vertices `0..n`, with lazy subtree reversal for `evert`.
#[derive(Clone, Debug, Default)]
pub(crate) struct LinkCutForest {
    child: Vec<[u32; 2]>,
    parent: Vec<u32>,
    flip: Vec<bool>,
    scratch: Vec<u32>,
}

impl LinkCutForest {
    /// `n` isolated vertices.
    pub(crate) fn new(n: usize) -> Self {
        LinkCutForest {
            child: vec![[NIL; 2]; n],
            parent: vec![NIL; n],
            flip: vec![false; n],
            scratch: Vec::new(),
        }
    }

    /// Sets `x`'s tree parent to `p` during a bulk build (every vertex must still be a singleton
    /// of its auxiliary tree). O(1).
    pub(crate) fn set_initial_parent(&mut self, x: u32, p: u32) {
        debug_assert!(self.parent[x as usize] == NIL);
        self.parent[x as usize] = p;
    }

    #[inline]
    fn is_aux_root(&self, x: u32) -> bool {
        let p = self.parent[x as usize];
        p == NIL || (self.child[p as usize][0] != x && self.child[p as usize][1] != x)
    }

    #[inline]
    fn push(&mut self, x: u32) {
        if self.flip[x as usize] {
            self.flip[x as usize] = false;
            self.child[x as usize].swap(0, 1);
            for c in self.child[x as usize] {
                if c != NIL {
                    self.flip[c as usize] ^= true;
                }
            }
        }
    }

    fn rotate(&mut self, x: u32) {
        let p = self.parent[x as usize];
        let g = self.parent[p as usize];
        let dir = usize::from(self.child[p as usize][1] == x);
        let b = self.child[x as usize][dir ^ 1];
        if !self.is_aux_root(p) {
            let gd = usize::from(self.child[g as usize][1] == p);
            self.child[g as usize][gd] = x;
        }
        self.parent[x as usize] = g;
        self.child[x as usize][dir ^ 1] = p;
        self.parent[p as usize] = x;
        self.child[p as usize][dir] = b;
        if b != NIL {
            self.parent[b as usize] = p;
        }
    }

    fn splay(&mut self, x: u32) {
        // Push pending flips from the auxiliary root down to x.
        let mut path = std::mem::take(&mut self.scratch);
        path.clear();
        let mut y = x;
        path.push(y);
        while !self.is_aux_root(y) {
            y = self.parent[y as usize];
            path.push(y);
        }
        for &z in path.iter().rev() {
            self.push(z);
        }
        self.scratch = path;
        while !self.is_aux_root(x) {
            let p = self.parent[x as usize];
            if !self.is_aux_root(p) {
                let g = self.parent[p as usize];
                let zigzig = (self.child[g as usize][1] == p) == (self.child[p as usize][1] == x);
                if zigzig {
                    self.rotate(p);
                } else {
                    self.rotate(x);
                }
            }
            self.rotate(x);
        }
    }

    /// Makes the root-to-`x` path preferred; returns the last vertex where the walk joined the
    /// previous preferred path of the root (the LCA trick).
    fn access(&mut self, x: u32) -> u32 {
        let mut last = NIL;
        let mut y = x;
        while y != NIL {
            self.splay(y);
            self.child[y as usize][1] = last;
            last = y;
            y = self.parent[y as usize];
        }
        self.splay(x);
        last
    }

    /// Makes `x` the root of its tree.
    pub(crate) fn evert(&mut self, x: u32) {
        self.access(x);
        self.flip[x as usize] ^= true;
        self.push(x);
    }

    /// Links `x` and `y`, which must be in different trees.
    pub(crate) fn link(&mut self, x: u32, y: u32) {
        self.evert(x);
        debug_assert!(self.find_root(y) != x, "link inside one tree");
        self.parent[x as usize] = y;
    }

    /// Cuts the tree edge `x - y`, which must exist.
    pub(crate) fn cut(&mut self, x: u32, y: u32) {
        self.evert(x);
        self.access(y);
        // The auxiliary tree of y holds exactly the path x..y = {x, y}; x is y's left child.
        debug_assert_eq!(self.child[y as usize][0], x, "cut of a non-edge");
        debug_assert_eq!(self.child[x as usize], [NIL; 2], "cut of a non-edge");
        self.child[y as usize][0] = NIL;
        self.parent[x as usize] = NIL;
    }

    /// Root of the tree of `x` (for checks).
    pub(crate) fn find_root(&mut self, x: u32) -> u32 {
        self.access(x);
        let mut r = x;
        loop {
            self.push(r);
            let l = self.child[r as usize][0];
            if l == NIL {
                break;
            }
            r = l;
        }
        self.splay(r);
        r
    }

    /// LCA of `x` and `y` in the current rooting (same tree required).
    pub(crate) fn lca(&mut self, x: u32, y: u32) -> u32 {
        self.access(x);
        self.access(y)
    }

    /// Whether the tree paths `a..b` and `c..d` share a vertex (all four in one tree).
    ///
    /// Root at `a`: the path `a..b` is the set of ancestors of `b`, and the path `c..d` lies in
    /// the subtree of `w = lca(c, d)` and contains `w`; so they meet iff `w` is an ancestor of `b`.
    pub(crate) fn paths_intersect(&mut self, a: u32, b: u32, c: u32, d: u32) -> bool {
        self.evert(a);
        let w = self.lca(c, d);
        self.lca(w, b) == w
    }
}
