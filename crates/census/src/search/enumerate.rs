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
//!   neighbour; and its look-ahead on the edges from a closed vertex to an open one
//!   ([`Enumerator::open_edges_can_fail`]);
//! - the root flag (0, 1, 2) is preferred ([`Enumerator::root_flag_order`]), checked as the
//!   degrees it compares become final;
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
    /// Bit w of `full[u]` when the edge uw lies in two faces.
    full: [u64; MAX_VERTICES],
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
            full: [0; MAX_VERTICES],
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
        if self.apexes[a * MAX_VERTICES + b][1] != NONE {
            self.full[a] |= bit(b);
            self.full[b] |= bit(a);
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
        self.full[a] &= !bit(b);
        self.full[b] &= !bit(a);
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
        if !self.root_flag_order() {
            return false;
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
        self.open_edges_can_fail()
    }

    /// The root flag (0, 1, 2) is a *preferred* flag: among the vertices of degree d, vertex 0
    /// has the largest sum of neighbour degrees; vertex 1 has the largest degree among the
    /// neighbours of 0, and the apex 2 of the face 0 1 2 has at least the degree of the other apex
    /// d of the edge 01. Every triangulation has a preferred flag at a vertex of maximum degree,
    /// so labelling from one loses nothing; the search checks the two inequalities as soon as
    /// both degrees are final (both vertices closed), and the canonical-root test at the leaves
    /// compares the preferred flags only.
    pub fn root_flag_order(&self) -> bool {
        if self.closed & 0b10 != 0 {
            let top = self.degree(1);
            let mut others = self.adjacency[0] & self.closed & !0b10;
            while others != 0 {
                let i = others.trailing_zeros() as usize;
                others &= others - 1;
                if self.degree(i) > top {
                    return false;
                }
            }
        }
        let d = self.max_degree;
        if self.closed & bit(2) != 0 && self.closed & bit(d) != 0 && self.degree(d) > self.degree(2)
        {
            return false;
        }
        // Vertex 0 has the largest sum of neighbour degrees among the vertices of degree d:
        // once 0's neighbours are closed its sum is final, and a closed vertex's sum can only
        // grow (its neighbours are final, their degrees grow).
        if self.adjacency[0] & !self.closed == 0 {
            let own = self.neighbour_degree_sum(0);
            let mut rivals = self.closed & !1;
            while rivals != 0 {
                let x = rivals.trailing_zeros() as usize;
                rivals &= rivals - 1;
                if self.degree(x) == d && self.neighbour_degree_sum(x) > own {
                    return false;
                }
            }
        }
        true
    }

    /// The sum of the current degrees of v's neighbours.
    fn neighbour_degree_sum(&self, v: usize) -> usize {
        let mut m = self.adjacency[v];
        let mut sum = 0;
        while m != 0 {
            sum += self.degree(m.trailing_zeros() as usize);
            m &= m - 1;
        }
        sum
    }

    /// The look-ahead of irreducibility on the edges xy with x closed and y open: x's neighbours
    /// are final, so y can only gain common neighbours among x's open neighbours not yet
    /// adjacent to y, and at most as many as y's degree has room for (d − deg y); the edge needs
    /// three common neighbours in the end.
    pub fn open_edges_can_fail(&self) -> bool {
        let mut closed = self.closed;
        while closed != 0 {
            let x = closed.trailing_zeros() as usize;
            closed &= closed - 1;
            let mut open_neighbours = self.adjacency[x] & !self.closed;
            while open_neighbours != 0 {
                let y = open_neighbours.trailing_zeros() as usize;
                open_neighbours &= open_neighbours - 1;
                let common = (self.adjacency[x] & self.adjacency[y]).count_ones() as usize;
                if common >= 3 {
                    continue;
                }
                let reachable = (self.adjacency[x] & !self.adjacency[y] & !self.closed & !bit(y))
                    .count_ones() as usize;
                let room = self.max_degree - self.degree(y);
                if common + reachable.min(room) < 3 {
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

    /// The labels given so far, as a mask.
    fn labelled(&self) -> u64 {
        if self.used >= 64 {
            u64::MAX
        } else {
            bit(self.used) - 1
        }
    }

    /// The open vertex of least label and the edge to extend: (v, p, apex of vp's one face).
    fn next_edge(&self) -> Option<(usize, usize)> {
        let open = self.labelled() & !self.closed;
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

    /// The apexes worth trying on the edge vp (a superset of those [`Self::try_apex`] accepts):
    /// labelled open vertices other than v, p and the apex of vp's face, whose edges to v and p
    /// are not yet in two faces, and adjacent to v (to p) when v (p) has its full degree; and the
    /// next new label.
    fn candidates(&self, v: usize, p: usize) -> u64 {
        let labelled = self.labelled();
        let r = self.apexes[v * MAX_VERTICES + p][0] as usize;
        let mut mask =
            labelled & !self.closed & !bit(v) & !bit(p) & !bit(r) & !self.full[v] & !self.full[p];
        if self.degree(v) >= self.max_degree {
            mask &= self.adjacency[v];
        }
        if self.degree(p) >= self.max_degree {
            mask &= self.adjacency[p];
        }
        if self.used < self.n
            && self.degree(v) < self.max_degree
            && self.degree(p) < self.max_degree
        {
            mask |= bit(self.used);
        }
        mask
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

    /// Whether the faces placed can be oriented coherently: propagation across edges (the
    /// second face on an edge must traverse it opposite to the first).
    fn current_is_orientable(&self) -> bool {
        let n = self.n;
        let faces: Vec<[usize; 3]> = self
            .history
            .iter()
            .map(|a| a.face.map(usize::from))
            .collect();
        let mut face_of = vec![[u8::MAX; 2]; n * n];
        for (f, face) in faces.iter().enumerate() {
            for i in 0..3 {
                let (x, y) = (face[i], face[(i + 1) % 3]);
                let slot = &mut face_of[x.min(y) * n + x.max(y)];
                if slot[0] == u8::MAX {
                    slot[0] = f as u8;
                } else {
                    slot[1] = f as u8;
                }
            }
        }
        // orientation[f]: 0 unset, 1 as stored, 2 reversed.
        let mut orientation = vec![0u8; faces.len()];
        orientation[0] = 1;
        let mut stack = vec![0usize];
        while let Some(f) = stack.pop() {
            let face = faces[f];
            let oriented = if orientation[f] == 1 {
                face
            } else {
                [face[0], face[2], face[1]]
            };
            for i in 0..3 {
                let (x, y) = (oriented[i], oriented[(i + 1) % 3]);
                let [g0, g1] = face_of[x.min(y) * n + x.max(y)];
                let g = usize::from(if usize::from(g0) == f { g1 } else { g0 });
                // g must traverse y -> x: as stored when it has y followed by x.
                let other = faces[g];
                let stored_y_then_x = (0..3).any(|j| other[j] == y && other[(j + 1) % 3] == x);
                let wanted = if stored_y_then_x { 1 } else { 2 };
                if orientation[g] == 0 {
                    orientation[g] = wanted;
                    stack.push(g);
                } else if orientation[g] != wanted {
                    return false;
                }
            }
        }
        true
    }

    /// The faces placed so far.
    pub fn faces(&self) -> impl Iterator<Item = [u32; 3]> + '_ {
        self.history.iter().map(|a| a.face.map(u32::from))
    }

    /// At a leaf: whether its labelling is the canonical one of its class, i.e. its root flag
    /// (vertex 0, then 1, then 2: the first face placed) has the least code among the preferred
    /// flags ([`Self::root_flag_order`]) at the vertices of maximum degree d
    /// ([`crate::canonical_form`]); each class then passes exactly once per job.
    pub fn is_canonical_leaf(&self) -> bool {
        let faces: Vec<[u32; 3]> = self.faces().collect();
        let n = self.n;
        let mut face_of = vec![[u32::MAX; 2]; n * n];
        for (f, face) in faces.iter().enumerate() {
            for i in 0..3 {
                let (x, y) = (face[i] as usize, face[(i + 1) % 3] as usize);
                let slot = &mut face_of[x.min(y) * n + x.max(y)];
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
                    let [g, h] = face_of[x.min(y) * n + x.max(y)];
                    if g == f as u32 { h } else { g }
                })
            })
            .collect();
        let degree: Vec<usize> = (0..self.n).map(|v| self.degree(v)).collect();
        let largest_neighbour: Vec<usize> = (0..self.n)
            .map(|v| {
                let mut m = self.adjacency[v];
                let mut best = 0;
                while m != 0 {
                    best = best.max(degree[m.trailing_zeros() as usize]);
                    m &= m - 1;
                }
                best
            })
            .collect();
        let top = self.max_degree;
        let sums: Vec<usize> = (0..self.n).map(|v| self.neighbour_degree_sum(v)).collect();
        let best_sum = (0..self.n)
            .filter(|&v| degree[v] == top)
            .map(|v| sums[v])
            .max();
        crate::canonical::is_least_root(&faces, across, self.n, 0, |[a, b, c], other_apex| {
            let (a, b, c) = (a as usize, b as usize, c as usize);
            degree[a] == top
                && Some(sums[a]) == best_sum
                && degree[b] == largest_neighbour[a]
                && degree[c] >= degree[other_apex as usize]
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
        let mut candidates = self.candidates(v, p);
        while candidates != 0 {
            let q = candidates.trailing_zeros() as usize;
            candidates &= candidates - 1;
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

    /// The apexes the first branching (from the start state) accepts: a job's *parts*, each
    /// the subtree below one of them ([`Self::enter_part`]). Empty when the start has no open
    /// vertex.
    pub fn root_choices(&mut self) -> Vec<usize> {
        match self.next_edge() {
            Some((v, p)) => self.accepted_apexes(v, p),
            None => Vec::new(),
        }
    }

    /// The apexes the edge `(v, p)` accepts now, each tried and undone.
    fn accepted_apexes(&mut self, v: usize, p: usize) -> Vec<usize> {
        let mut accepted = Vec::new();
        let mut candidates = self.candidates(v, p);
        while candidates != 0 {
            let q = candidates.trailing_zeros() as usize;
            candidates &= candidates - 1;
            if self.try_apex(v, p, q) {
                self.undo();
                accepted.push(q);
            }
        }
        accepted
    }

    /// Takes the first branching's apex `q` (one of [`Self::root_choices`]): the search then
    /// covers that part only. False when `q` is not accepted.
    pub fn enter_part(&mut self, q: usize) -> bool {
        match self.next_edge() {
            Some((v, p)) => self.try_apex(v, p, q),
            None => false,
        }
    }

    /// Knuth's estimate of the number of search nodes (D. E. Knuth, "Estimating the efficiency
    /// of backtrack programs", Math. Comp. 29, 1975): one random root-to-leaf path, the sum over
    /// its depths of the product of the branching factors met. Unbiased; average many probes.
    pub fn probe(&mut self, rng: &mut impl rand::RngExt) -> f64 {
        let mut estimate = 1.0;
        let mut product = 1.0;
        let depth = self.history.len();
        while let Some((v, p)) = self.next_edge() {
            let children = self.accepted_apexes(v, p);
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
