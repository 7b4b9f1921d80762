//! The backtracking search of one job: every labelled irreducible triangulation with n vertices,
//! Euler characteristic χ, the given orientability and maximum degree d whose vertex 0 has
//! degree d and link 1, 2, …, d.
//!
//! Vertices get labels in the order the search first meets them. The search repeatedly takes the
//! open vertex v of least label (open: its link is not yet a closed cycle), the least-labelled
//! neighbour p such that the edge vp lies in one face so far, and branches over the apex q of the
//! second face on vp: every labelled vertex that can take it, and the next new label. Every
//! triangulation of the job is found: label it by running this very procedure on it (at each step
//! its own second face on vp), and every partial face set along the way passes the tests below,
//! which are all necessary conditions.
//!
//! Tests on adding a face (each necessary for a closed simplicial surface of the job):
//! - each of its edges lies in at most two faces, the face is new, degrees stay at most d, edges
//!   at most 3(n − χ), faces at most 2(n − χ), labels at most n;
//! - the link of each corner stays a set of disjoint paths, or closes into one cycle through all
//!   the corner's neighbours (a link cycle that leaves out a neighbour would pinch the vertex);
//! - a vertex whose link closes has degree at least 4 (n ≥ 5: a degree-3 vertex's edges are
//!   contractible), and for each edge xy whose two ends are closed, x and y have at least three
//!   common neighbours (the link condition fails: the edge is not contractible) — the
//!   irreducibility test, final once both ends are closed since closed vertices get no new
//!   neighbour;
//! - for an orientable job the faces are oriented: the second face on an edge traverses it in the
//!   direction opposite to the first.
//!
//! At a leaf (no open vertex) the labels must number n and the faces 2(n − χ) (so χ is right);
//! a non-orientable job also rejects an orientable leaf.

/// The most vertices a job can label (one bit each in a `u64`).
pub const MAX_VERTICES: usize = 64;

const NONE: u8 = u8::MAX;

/// What adding a face changed, to undo it.
#[derive(Clone, Copy)]
struct Added {
    face: [u8; 3],
    newly_closed: u64,
    new_label: bool,
}

/// The state of one job's search.
pub struct Enumerator {
    n: usize,
    max_degree: usize,
    orientable: bool,
    max_edges: usize,
    max_faces: usize,
    used: usize,
    adjacency: [u64; MAX_VERTICES],
    /// Orientable jobs: bit w of `directed[u]` when a face traverses u → w.
    directed: [u64; MAX_VERTICES],
    /// The apexes of the (up to two) faces on each edge, `apexes[u * 64 + w]`.
    apexes: Vec<[u8; 2]>,
    closed: u64,
    edges: usize,
    history: Vec<Added>,
    /// Search nodes visited.
    pub nodes: u64,
    /// Leaves reached (labelled irreducible triangulations, before isomorph rejection).
    pub leaves: u64,
}

fn bit(v: usize) -> u64 {
    1u64 << v
}

impl Enumerator {
    /// The job (n, χ, orientability, d) with vertex 0 of degree d and link 1..d placed.
    /// `None` when the start itself fails a test (d < 3, d ≥ n).
    pub fn new(n: usize, chi: i64, orientable: bool, max_degree: usize) -> Option<Self> {
        if n > MAX_VERTICES || max_degree < 3 || max_degree >= n {
            return None;
        }
        let max_edges = 3 * (n as i64 - chi);
        if max_edges <= 0 {
            return None;
        }
        let mut e = Self {
            n,
            max_degree,
            orientable,
            max_edges: max_edges as usize,
            max_faces: 2 * (n as i64 - chi) as usize,
            used: max_degree + 1,
            adjacency: [0; MAX_VERTICES],
            directed: [0; MAX_VERTICES],
            apexes: vec![[NONE; 2]; MAX_VERTICES * MAX_VERTICES],
            closed: 0,
            edges: 0,
            history: Vec::with_capacity(4 * n),
            nodes: 0,
            leaves: 0,
        };
        for i in 1..=max_degree {
            let j = if i == max_degree { 1 } else { i + 1 };
            if !e.try_add([0, i as u8, j as u8]) {
                return None;
            }
        }
        if e.closed & 1 == 0 {
            return None;
        }
        Some(e)
    }

    fn faces_on(&self, a: usize, b: usize) -> usize {
        let [x, y] = self.apexes[a * MAX_VERTICES + b];
        (x != NONE) as usize + (y != NONE) as usize
    }

    fn push_apex(&mut self, a: usize, b: usize, apex: u8) {
        for key in [a * MAX_VERTICES + b, b * MAX_VERTICES + a] {
            let slot = &mut self.apexes[key];
            if slot[0] == NONE {
                slot[0] = apex;
            } else {
                slot[1] = apex;
            }
        }
    }

    fn pop_apex(&mut self, a: usize, b: usize) {
        for key in [a * MAX_VERTICES + b, b * MAX_VERTICES + a] {
            let slot = &mut self.apexes[key];
            if slot[1] != NONE {
                slot[1] = NONE;
            } else {
                slot[0] = NONE;
            }
        }
    }

    fn degree(&self, v: usize) -> usize {
        self.adjacency[v].count_ones() as usize
    }

    /// After the face is in place: whether corner x's link, which just got the edge yz, closes
    /// (`Some(true)`), stays paths (`Some(false)`) or closes a cycle that leaves out a
    /// neighbour (`None`).
    fn link_closes(&self, x: usize, y: usize, z: usize) -> Option<bool> {
        if self.faces_on(x, y) < 2 || self.faces_on(x, z) < 2 {
            return Some(false);
        }
        let (mut previous, mut current) = (z, y);
        let mut length = 1;
        loop {
            let [a, b] = self.apexes[x * MAX_VERTICES + current];
            let next = if a as usize == previous { b } else { a };
            if next == NONE {
                return Some(false);
            }
            let next = next as usize;
            length += 1;
            if next == z {
                return if length == self.degree(x) {
                    Some(true)
                } else {
                    None
                };
            }
            previous = current;
            current = next;
            if length > MAX_VERTICES {
                return None;
            }
        }
    }

    /// Adds the face if every test passes (and records it); otherwise changes nothing.
    fn try_add(&mut self, face: [u8; 3]) -> bool {
        let [a, b, c] = face.map(usize::from);
        let corners = [a, b, c];
        for &x in &corners {
            if self.closed & bit(x) != 0 {
                return false;
            }
        }
        let pairs = [(a, b), (b, c), (c, a)];
        let mut new_edges = 0u8;
        for (i, &(x, y)) in pairs.iter().enumerate() {
            match self.faces_on(x, y) {
                0 => new_edges |= 1 << i,
                1 => {
                    let third = corners[(i + 2) % 3];
                    if self.apexes[x * MAX_VERTICES + y][0] as usize == third {
                        return false; // the same face again
                    }
                }
                _ => return false,
            }
        }
        if self.history.len() + 1 > self.max_faces
            || self.edges + new_edges.count_ones() as usize > self.max_edges
        {
            return false;
        }
        let mut extra = [0usize; 3];
        for (i, &(x, y)) in pairs.iter().enumerate() {
            if new_edges & (1 << i) != 0 {
                extra[corners.iter().position(|&v| v == x).unwrap_or(0)] += 1;
                extra[corners.iter().position(|&v| v == y).unwrap_or(0)] += 1;
            }
        }
        for (i, &x) in corners.iter().enumerate() {
            if self.degree(x) + extra[i] > self.max_degree {
                return false;
            }
        }
        // Orientation: an edge already in a face fixes the face's order (the second face on an
        // edge traverses it the other way), so at most one order has its three directed edges
        // free; the very first face is taken as given.
        let mut oriented = face;
        if self.orientable && !self.history.is_empty() {
            let free =
                |o: [usize; 3]| (0..3).all(|i| self.directed[o[i]] & bit(o[(i + 1) % 3]) == 0);
            if free([a, b, c]) {
                oriented = face;
            } else if free([a, c, b]) {
                oriented = [face[0], face[2], face[1]];
            } else {
                return false;
            }
        }
        // Place the face.
        for (i, &(x, y)) in pairs.iter().enumerate() {
            self.push_apex(x, y, corners[(i + 2) % 3] as u8);
            if new_edges & (1 << i) != 0 {
                self.adjacency[x] |= bit(y);
                self.adjacency[y] |= bit(x);
                self.edges += 1;
            }
        }
        if self.orientable {
            let o = oriented.map(usize::from);
            for i in 0..3 {
                self.directed[o[i]] |= bit(o[(i + 1) % 3]);
            }
        }
        let mut newly_closed = 0u64;
        let mut ok = true;
        for i in 0..3 {
            let (x, y, z) = (corners[i], corners[(i + 1) % 3], corners[(i + 2) % 3]);
            match self.link_closes(x, y, z) {
                Some(true) => newly_closed |= bit(x),
                Some(false) => {}
                None => ok = false,
            }
        }
        let record = Added {
            face: oriented,
            newly_closed,
            new_label: false,
        };
        self.history.push(record);
        self.closed |= newly_closed;
        if ok && newly_closed != 0 {
            ok = self.closures_irreducible(newly_closed);
        }
        if !ok {
            self.undo();
        }
        ok
    }

    /// The tests on vertices that just closed: degree at least 4 (n ≥ 5), and at least three
    /// common neighbours with every closed neighbour.
    fn closures_irreducible(&self, newly_closed: u64) -> bool {
        if self.n == 4 {
            return true; // the tetrahedron
        }
        let mut rest = newly_closed;
        while rest != 0 {
            let x = rest.trailing_zeros() as usize;
            rest &= rest - 1;
            if self.degree(x) < 4 {
                return false;
            }
            let mut closed_neighbours = self.adjacency[x] & self.closed;
            while closed_neighbours != 0 {
                let y = closed_neighbours.trailing_zeros() as usize;
                closed_neighbours &= closed_neighbours - 1;
                if (self.adjacency[x] & self.adjacency[y]).count_ones() < 3 {
                    return false;
                }
            }
        }
        true
    }

    /// Removes the last face added.
    fn undo(&mut self) {
        let Some(added) = self.history.pop() else {
            return;
        };
        let [a, b, c] = added.face.map(usize::from);
        let pairs = [(a, b), (b, c), (c, a)];
        // An edge that lost its last face goes too.
        for &(x, y) in &pairs {
            self.pop_apex(x, y);
            if self.faces_on(x, y) == 0 && self.adjacency[x] & bit(y) != 0 {
                self.adjacency[x] &= !bit(y);
                self.adjacency[y] &= !bit(x);
                self.edges -= 1;
            }
        }
        if self.orientable {
            for &(x, y) in &pairs {
                self.directed[x] &= !bit(y);
            }
        }
        self.closed &= !added.newly_closed;
        if added.new_label {
            self.used -= 1;
        }
    }

    /// The open vertex of least label and the edge to extend: (v, p, apex of vp's one face).
    fn next_edge(&self) -> Option<(usize, usize)> {
        let labelled = if self.used == 64 {
            u64::MAX
        } else {
            bit(self.used) - 1
        };
        let open = labelled & !self.closed;
        if open == 0 {
            return None;
        }
        let v = open.trailing_zeros() as usize;
        let mut neighbours = self.adjacency[v];
        while neighbours != 0 {
            let p = neighbours.trailing_zeros() as usize;
            neighbours &= neighbours - 1;
            if self.faces_on(v, p) == 1 {
                return Some((v, p));
            }
        }
        None
    }

    /// Tries the apex q on the edge vp; q == used means a new label.
    fn try_apex(&mut self, v: usize, p: usize, q: usize) -> bool {
        if q == v || q == p || q > self.used || q >= self.n {
            return false;
        }
        let fresh = q == self.used;
        if fresh {
            self.used += 1;
        }
        if self.try_add([v as u8, p as u8, q as u8]) {
            if fresh && let Some(last) = self.history.last_mut() {
                last.new_label = true;
            }
            true
        } else {
            if fresh {
                self.used -= 1;
            }
            false
        }
    }

    /// Whether the leaf reached (no open vertex) is a triangulation of the job.
    fn leaf_is_complete(&self) -> bool {
        self.used == self.n
            && self.history.len() == self.max_faces
            && (self.orientable || !self.current_is_orientable())
    }

    fn current_is_orientable(&self) -> bool {
        let faces: Vec<[u32; 3]> = self.faces().collect();
        crate::triangulation::Triangulation::new(faces)
            .map(|t| t.is_orientable())
            .unwrap_or(true)
    }

    /// The faces placed so far.
    pub fn faces(&self) -> impl Iterator<Item = [u32; 3]> + '_ {
        self.history.iter().map(|a| a.face.map(u32::from))
    }

    /// At a leaf: whether its labelling is the canonical one of its class, i.e. its root flag
    /// (vertex 0, then 1, then 2: the first face placed) has the least code among the flags at the
    /// vertices of maximum degree d ([`crate::canonical`]); each class then passes exactly once
    /// per job.
    pub fn is_canonical_leaf(&self) -> bool {
        let faces: Vec<[u32; 3]> = self.faces().collect();
        let mut face_of = vec![[u32::MAX; 2]; MAX_VERTICES * MAX_VERTICES];
        for (f, face) in faces.iter().enumerate() {
            for i in 0..3 {
                let (x, y) = (face[i] as usize, face[(i + 1) % 3] as usize);
                let slot = &mut face_of[x.min(y) * MAX_VERTICES + x.max(y)];
                if slot[0] == u32::MAX {
                    slot[0] = f as u32;
                } else {
                    slot[1] = f as u32;
                }
            }
        }
        let across: Vec<[u32; 3]> = faces
            .iter()
            .enumerate()
            .map(|(f, face)| {
                [0, 1, 2].map(|i| {
                    let (x, y) = (face[(i + 1) % 3] as usize, face[(i + 2) % 3] as usize);
                    let [g, h] = face_of[x.min(y) * MAX_VERTICES + x.max(y)];
                    if g == f as u32 { h } else { g }
                })
            })
            .collect();
        let top = self.max_degree;
        crate::canonical::is_least_root(&faces, across, self.n, 0, |v| {
            self.degree(v as usize) == top
        })
    }

    /// Runs the search to the end, calling `leaf` on each labelled triangulation found; stops
    /// early (returning false) when `stop()` says so (asked every 4,096 nodes).
    pub fn run(&mut self, leaf: &mut dyn FnMut(&Self), stop: &dyn Fn() -> bool) -> bool {
        self.nodes += 1;
        if self.nodes & 4095 == 0 && stop() {
            return false;
        }
        let Some((v, p)) = self.next_edge() else {
            if self.leaf_is_complete() {
                self.leaves += 1;
                leaf(self);
            }
            return true;
        };
        for q in 0..=self.used {
            if self.try_apex(v, p, q) {
                let go_on = self.run(leaf, stop);
                self.undo();
                if !go_on {
                    return false;
                }
            }
        }
        true
    }

    /// Knuth's estimate of the number of search nodes (D. E. Knuth, "Estimating the efficiency
    /// of backtrack programs", Math. Comp. 29, 1975): one random root-to-leaf path, the sum over
    /// its depths of the product of the branching factors met. Unbiased; average many probes.
    pub fn probe(&mut self, rng: &mut impl rand::RngExt) -> f64 {
        let mut estimate = 1.0;
        let mut product = 1.0;
        let depth = self.history.len();
        while let Some((v, p)) = self.next_edge() {
            let mut children = Vec::new();
            for q in 0..=self.used {
                if self.try_apex(v, p, q) {
                    self.undo();
                    children.push(q);
                }
            }
            if children.is_empty() {
                break;
            }
            product *= children.len() as f64;
            estimate += product;
            let q = children[rng.random_range(0..children.len())];
            self.try_apex(v, p, q);
        }
        while self.history.len() > depth {
            self.undo();
        }
        estimate
    }
}
