//! The Ramaswami–Siqueira algorithm (RS): Section 4 of the irreducible-triangulations paper,
//! Algorithms 4.1–4.7.
//!
//! Vertices are processed one at a time in queue order (Algorithm 4.2). Processing u contracts
//! contractible edges [u, v] (v identified with u, Figure 7) until u is trapped. The untested edges
//! at u wait in the list lue (edges to degree-3 vertices in front), the tested ones that failed in
//! lte. A degree-3 neighbour v is contracted without a test (Proposition 6,
//! PROCESSVERTEXOFDEGREEEQ3, Algorithm 4.3); otherwise [u, v] is tested once by counting the
//! critical cycles through it with the neighbour marks n (PROCESSVERTEXOFDEGREEGT3, Algorithm 4.4),
//! and the counters c of the edges in lte are kept exact by the time stamps o, t and ts
//! (Section 4.3) so that an edge of lte that becomes contractible is found at the front of lte
//! without a second test (PROCESSEDELIST, Algorithm 4.6). CONTRACT (Algorithm 4.5) updates the
//! attributes, pushes the record on the stack S and calls COLLAPSE (Algorithm 4.7), which is
//! [`SurfaceMesh::contract_unchecked`] here.
//!
//! # Decisions where the pseudocode is silent, ambiguous or wrong
//!
//! 1. **Queue Q.** Q is filled once with all vertices and never refilled (Algorithm 4.1), so it is
//!    the ascending order of vertex ids; removed (tombstone) input vertices count as processed.
//!    d(u) is counted in one pass over the half-edges rather than around each vertex.
//! 2. **Edge records.** While u is processed every edge of interest is [u, z], and the paper keys
//!    all its per-edge data by z (c(z), o(z), t(z), "move [u, z] to the front of lte"). So the
//!    "edge record" of [u, z] is node z: it holds the list links (its place in lue/lte) and the
//!    half-edge u → z. Mesh edge ids persist through contractions (Figure 7: [v, z] becomes [u, z]
//!    keeping its id, and so does its half-edge, now leaving u; [u, x], [u, y] keep theirs), so a
//!    node stays valid until z is removed. The "edge tested" flag of the counters is kept per mesh
//!    edge id; RS never tests an id twice (checked by a `debug_assert!`).
//! 3. **Initialising lue** (Algorithm 4.2, lines 8–19) also sets **c(v) ← 0** for every neighbour
//!    v of u. The paper omits it (its Proposition 8 (6) appeals to Algorithm 4.1 only), but an
//!    unprocessed vertex left in lte when an earlier vertex finished keeps c(v) > 0 (this happens
//!    thousands of times on ordinary inputs), and its edge to u would then be counted as
//!    non-contractible without any critical cycle: with the literal pseudocode, `genus_surface(1, 1)`
//!    (48 vertices) ends with 18 vertices, not irreducible, and so do 160 of 200 of our generated
//!    test inputs. (Algorithm 4.4 then counts c(v) from 0, as the paper's increments do.)
//! 4. **End of processing u** (line 34): the paper stops when lue is empty after PROCESSEDELIST.
//!    But PROCESSEDELIST contracts at most one edge of degree > 3, and if all new neighbours of that
//!    contraction are already processed, lue stays empty while the front of lte could still hold an
//!    edge with c = 0 (a degree-3 contraction can zero two counters at once, lines 5–7 of
//!    Algorithm 4.3); Corollary 24 (every edge left in lte is non-contractible) is not argued for
//!    this case. So the loop also goes on while the front of lte has c = 0, an O(1) check. We never
//!    saw it fire (all shared meshes, and 55,000 random small inputs of genus 1 to 40 with shuffled
//!    ids, where each of its two preconditions did occur), but it makes Corollary 24 hold by
//!    construction; a debug assertion checks at the end of every vertex that every edge left in lte
//!    has c > 0 and degree > 3.
//! 5. **The tetrahedron.** When v has degree 3 and so does u, K is T4 (Proposition 6): [u, v] is
//!    dropped from the lists untested and uncontracted, as line 2 of Algorithm 4.3 says. A T4 input
//!    thus returns unchanged with ℓ = 0.
//! 6. Line 22 of Algorithm 4.3 says "move [u, y] to the front of P": P is lte.
//! 7. **ℓ** counts the executions of Algorithm 4.4 (the only link-condition test); the degree-3
//!    shortcut is not a test (the paper's Table 6 has ℓ_RS < number of contractions).
//! 8. **Lines 33–41 of Algorithm 4.5** look, for a new neighbour z of u that is already processed,
//!    for the vertices w ∉ Λ_uz adjacent to z with n(w) = u and t(w) ≠ −1, i.e. with [u, w] in
//!    lte (Propositions 8–9). Processed vertices are trapped hubs whose links grow long (average
//!    degree 164 on the paper's genus-3,500 brick at 1.2M triangles, where this scan took most of
//!    the time), while lte is short (7 edges on average there, and empty in half the cases). So we
//!    enumerate the same set from whichever side is shorter: lk(z), as the paper does, or the links
//!    of the vertices of lte (found with the degrees d, in O(min(|lte|, d(z))) time). The set of w,
//!    hence every counter, is the same; only the order in which edges whose counter becomes 1 are
//!    moved to the rear of lte can differ, and the order of the edges with c > 0 never decides
//!    anything (an edge only acts from the front, and reaches it when its counter drops to 0).
//!    The two versions gave identical histories on 101 inputs (all shared meshes, genus up to
//!    3,500); the time bound of Theorem 12 is unchanged, since the cost is at most the paper's.
//!
//! 9. **Surfaces beyond the paper** ([`crate::reduce_surface`]): K is the surface a closed
//!    oriented mesh covers; every vertex of the pseudocode is a vertex class (both lifts of a
//!    vertex of a doubled non-orientable component; all apexes closing the boundary form one
//!    class ω), attributes are kept per class, rotations are read at a lift (a lift's star is
//!    the vertex's star), and CONTRACT contracts both lifts. ω is processed from the start (p =
//!    true), so no edge to it enters lue and none is tested or contracted; its critical cycles
//!    (u, z, ω) make an interior edge between two boundary vertices non-contractible, which is
//!    Dey et al.'s rule. Lines 33–41 of Algorithm 4.5 find the cycles through a new neighbour
//!    z = ω from the lte side always (ω's link is every boundary vertex, so the paper's scan of
//!    lk(z) would be long and would need all apexes). Degrees are those of the coned surface, so
//!    Proposition 6 holds as stated (a boundary vertex of degree 3 is an ear: its two boundary
//!    edges contract).
//!
//! Attributes are one flat array of small structs indexed by vertex id (no hashing): d, p, n, c,
//! o, t of Table 1, with `u32::MAX` standing for the paper's −1 and nil.

use surftopo_mesh::{Contraction, HalfedgeId, Lifting, SurfaceMesh, VertexId, contract_lifts};

use crate::edge_lists::{EdgeLists, List};
use crate::tally::TestTally;
use crate::{IrreducibleError, Reduction};

/// The paper's −1 (time attributes) and nil (n).
const NONE: u32 = u32::MAX;

/// Table 1: the attributes of a vertex v while a vertex u is processed.
#[derive(Clone, Copy, Debug)]
struct Attributes {
    /// d: degree of v.
    d: u32,
    /// n: u when v is a neighbour of u (nil otherwise).
    n: u32,
    /// c: number of critical cycles containing [u, v].
    c: u32,
    /// o: time at which v became a neighbour of u.
    o: u32,
    /// t: time at which [u, v] was removed from lue.
    t: u32,
    /// p: whether v has been processed (or removed).
    p: bool,
}

/// Ramaswami–Siqueira (Section 4, Algorithms 4.1–4.7): contracts edges of `mesh` until it is an
/// irreducible triangulation of the same surface.
///
/// Takes a closed orientable simplicial surface (the mesh type guarantees closed, connected and
/// orientable; simpliciality is checked first). Guarantees: the result is irreducible and
/// simplicial with the input's genus; its vertices are the processed input vertices, with their
/// ids; every contraction satisfied the link condition; no edge is tested twice (ε = 0); the
/// history replays back to the input with [`SurfaceMesh::split_vertex`]. For genus 0 the result is
/// T4 and every contraction happens while the first vertex is processed (Section 4.6).
///
/// Time O(g² + g·n) for genus g > 0 and O(n) for genus 0, n the number of triangles
/// (Theorem 12); memory O(n).
///
/// # Errors
/// [`IrreducibleError`] if the mesh is not simplicial (nothing is done then).
pub fn ramaswami_siqueira(mesh: SurfaceMesh) -> Result<Reduction, IrreducibleError> {
    Reduction::of_plain_run(mesh, run)
}

/// RS on the surface a mesh covers (see [`crate::reduce_surface`]): every vertex below is a
/// vertex class of the surface, every edit is made on every lift; returns the history, the tally
/// and the number of contractions of the surface.
pub(crate) fn run<L: Lifting>(
    mesh: &mut SurfaceMesh,
    lifting: &L,
) -> (Vec<Contraction>, TestTally, u64) {
    let mut rs = Rs::initialization(mesh, lifting);
    rs.contractions();
    let Rs {
        stack,
        st,
        contractions,
        ..
    } = rs;
    (stack, st.tally, contractions)
}

/// Everything but the mesh, so that the mesh can be read while the state changes.
struct State {
    attr: Vec<Attributes>,
    /// lue and lte; node z is the edge [u, z].
    lists: EdgeLists,
    /// Per node z: the half-edge u → z of the edge record [u, z].
    to: Vec<HalfedgeId>,
    /// The global time stamp ts.
    ts: u32,
    /// The vertex being processed.
    u: VertexId,
    tally: TestTally,
}

struct Rs<'m, L> {
    /// K, the current triangulation (as the mesh that covers it).
    mesh: &'m mut SurfaceMesh,
    /// How the mesh stands for K: vertex classes are K's vertices.
    lifting: &'m L,
    /// Contractions of K made.
    contractions: u64,
    st: State,
    /// S: the contraction records.
    stack: Vec<Contraction>,
    /// The list temp of Algorithm 4.5: half-edges v → z, z in Π_uv (u → z after the contraction).
    temp: Vec<HalfedgeId>,
    /// Scratch for the vertices w found by lines 33–41 of Algorithm 4.5 (decision 8).
    hits: Vec<VertexId>,
}

/// Whether the links of the vertices w with [u, w] in lte are shorter in total than `budget`
/// (the degree of z): decides how lines 33–41 of Algorithm 4.5 enumerate (decision 8).
/// O(min(|lte|, budget)).
fn lte_links_are_shorter(st: &State, budget: u32) -> bool {
    let mut total = 0u32;
    for w in st.lists.iter(List::Lte) {
        total += st.attr[w as usize].d;
        if total >= budget {
            return false;
        }
    }
    true
}

impl State {
    /// c(z) ← c(z) + 1 for [u, z] in lte; an edge that gets its first critical cycle goes to the
    /// rear of lte (Algorithm 4.4 lines 6–9, Algorithm 4.5 lines 36–39).
    #[inline]
    fn increment(&mut self, z: VertexId) {
        debug_assert_eq!(self.lists.list_of(z.0), Some(List::Lte));
        let c = &mut self.attr[z.idx()].c;
        *c += 1;
        if *c == 1 {
            self.lists.move_to_back(z.0);
        }
    }

    /// c(z) ← c(z) − 1 for [u, z] in lte; an edge without critical cycles goes to the front of lte
    /// (Algorithm 4.3 lines 6–23).
    #[inline]
    fn decrement(&mut self, z: VertexId) {
        debug_assert_eq!(self.lists.list_of(z.0), Some(List::Lte));
        let c = &mut self.attr[z.idx()].c;
        debug_assert!(*c > 0, "critical-cycle counter of {z:?} underflows");
        *c -= 1;
        if *c == 0 {
            self.lists.move_to_front(z.0);
        }
    }

    /// Inserts [u, z] into lue: at the front when d(z) = 3, else at the rear (Proposition 8 (2)).
    #[inline]
    fn insert_unprocessed(&mut self, z: VertexId) {
        if self.attr[z.idx()].d == 3 {
            self.lists.push_front(List::Lue, z.0);
        } else {
            self.lists.push_back(List::Lue, z.0);
        }
    }
}

impl<'m, L: Lifting> Rs<'m, L> {
    /// INITIALIZATION (Algorithm 4.1): d, p, n, c, o, t of every vertex; Q is the id order.
    /// The apexes closing the boundary form one vertex, processed from the start (never
    /// processed, never contracted).
    fn initialization(mesh: &'m mut SurfaceMesh, lifting: &'m L) -> Self {
        let slots = lifting.class_count();
        let mut attr = vec![
            Attributes {
                d: 0,
                n: NONE,
                c: 0,
                o: NONE,
                t: NONE,
                p: false,
            };
            slots
        ];
        for i in 0..mesh.halfedge_slots() {
            let v = mesh.origin(HalfedgeId::new(i));
            if v.is_valid() {
                attr[lifting.class(v) as usize].d += 1;
            }
        }
        for (i, a) in attr.iter_mut().enumerate() {
            let lift = lifting.lift(i as u32);
            a.p = !(lift.is_valid() && mesh.is_vertex_live(lift))
                || lifting.apex_class() == Some(i as u32);
            // Both lifts of a doubled vertex were counted.
            if lifting.doubled() && !a.p && lifting.mirror(mesh.vertex_halfedge(lift)).is_some() {
                a.d /= 2;
            }
        }
        let edges = mesh.edge_slots();
        Rs {
            st: State {
                attr,
                lists: EdgeLists::new(slots),
                to: vec![HalfedgeId::INVALID; slots],
                ts: 0,
                u: VertexId::INVALID,
                tally: TestTally::new(edges),
            },
            stack: Vec::with_capacity(mesh.vertex_count().saturating_sub(4)),
            temp: Vec::new(),
            hits: Vec::new(),
            mesh,
            lifting,
            contractions: 0,
        }
    }

    /// CONTRACTIONS (Algorithm 4.2): processes every unprocessed vertex of Q.
    fn contractions(&mut self) {
        for i in 0..self.st.attr.len() {
            if !self.st.attr[i].p {
                self.process(VertexId::new(i));
            }
        }
    }

    /// Lines 7–35 of Algorithm 4.2: contracts edges at u until u is trapped.
    fn process(&mut self, u: VertexId) {
        let (mesh, lifting) = (&*self.mesh, self.lifting);
        let st = &mut self.st;
        st.u = u;
        // Lines 7–19: lue holds the edges to unprocessed neighbours, degree-3 ones first.
        for h in mesh.outgoing(lifting.lift(u.0)) {
            let v = VertexId(lifting.class(mesh.dest(h)));
            let a = &mut st.attr[v.idx()];
            a.n = u.0;
            a.o = st.ts;
            a.t = NONE;
            a.c = 0; // decision 3
            st.to[v.idx()] = h;
            if !a.p {
                st.insert_unprocessed(v);
            }
        }
        debug_assert!(st.lists.is_empty(List::Lte));
        // Lines 21–34 (with the exit condition of decision 4).
        let mut ticker = surftopo_mesh::stop::Ticker::default();
        loop {
            while let Some(v) = self.st.lists.pop_front(List::Lue) {
                ticker.tick();
                let v = VertexId(v);
                self.st.attr[v.idx()].t = self.st.ts;
                if self.st.attr[v.idx()].d == 3 {
                    self.process_vertex_of_degree_eq3(v);
                } else {
                    self.process_vertex_of_degree_gt3(v);
                }
            }
            if !self.st.lists.is_empty(List::Lte) {
                self.process_edge_list();
            }
            let lte_front_contractible = self
                .st
                .lists
                .front(List::Lte)
                .is_some_and(|v| self.st.attr[v as usize].c == 0);
            if self.st.lists.is_empty(List::Lue) && !lte_front_contractible {
                break;
            }
        }
        // Line 35; lte is emptied for the next vertex (line 20).
        debug_assert!(
            self.st
                .lists
                .iter(List::Lte)
                .all(|v| self.st.attr[v as usize].c > 0 && self.st.attr[v as usize].d > 3),
            "an edge left in lte at the end of processing {u:?} is contractible"
        );
        self.st.attr[u.idx()].p = true;
        self.st.lists.clear(List::Lte);
    }

    /// PROCESSVERTEXOFDEGREEEQ3 (Algorithm 4.3): d(v) = 3, so [u, v] is contractible unless K is T4
    /// (Proposition 6); after contracting it, the critical cycle (u, x, y) of lk(v) is gone and the
    /// counters of [u, x] and [u, y] that included it are decremented.
    fn process_vertex_of_degree_eq3(&mut self, v: VertexId) {
        let u = self.st.u;
        if self.st.attr[u.idx()].d == 3 {
            return; // K is T4: [u, v] is not contractible (decision 5)
        }
        let [x, y] = self.contract(v);
        let st = &mut self.st;
        let (ax, ay) = (st.attr[x.idx()], st.attr[y.idx()]);
        if ax.t != NONE && ay.t != NONE {
            st.decrement(x);
            st.decrement(y);
        } else if ax.t != NONE && ax.t >= ay.o {
            st.decrement(x);
        } else if ay.t != NONE && ay.t >= ax.o {
            st.decrement(y);
        }
    }

    /// PROCESSVERTEXOFDEGREEGT3 (Algorithm 4.4): the link-condition test of [u, v], d(v) > 3:
    /// c(v) ← number of z in Π_uv with n(z) = u (the critical cycles (u, v, z)); each such cycle
    /// is also added to c(z) when [u, z] was tested before v became a neighbour of u. Contracts
    /// [u, v] when c(v) = 0, else appends it to lte. O(d(v)).
    fn process_vertex_of_degree_gt3(&mut self, v: VertexId) {
        let (mesh, lifting) = (&*self.mesh, self.lifting);
        let class = |w: VertexId| VertexId(lifting.class(w));
        let st = &mut self.st;
        let u = st.u;
        let h = st.to[v.idx()];
        debug_assert_eq!((class(mesh.origin(h)), class(mesh.dest(h))), (u, v));
        let first = st.tally.record(lifting.edge_key(h.edge()));
        debug_assert!(first, "edge {:?} = [{u:?}, {v:?}] tested twice", h.edge());
        let (x, y) = (
            class(mesh.opposite_vertex(h)),
            class(mesh.opposite_vertex(h.twin())),
        );
        let ov = st.attr[v.idx()].o;
        debug_assert_eq!(st.attr[v.idx()].c, 0, "Proposition 8 (6)");
        let mut cv = 0;
        for hz in mesh.outgoing(mesh.dest(h)) {
            let z = class(mesh.dest(hz));
            if z == u || z == x || z == y {
                continue;
            }
            let az = st.attr[z.idx()];
            if az.n == u.0 {
                cv += 1;
                if az.t != NONE && az.t < ov {
                    st.increment(z);
                }
            }
        }
        st.attr[v.idx()].c = cv;
        if cv == 0 {
            self.contract(v);
        } else {
            st.lists.push_back(List::Lte, v.0);
        }
    }

    /// CONTRACT (Algorithm 4.5): contracts [u, v] (v identified with u, Figure 7), pushes its record
    /// on S, updates degrees and lue, and counts the new critical cycles (u, z, w) through new
    /// processed neighbours z of u for the edges [u, w] of lte. Returns the link {x, y} of [u, v].
    /// O(d(v) + Σ d(z) over the new processed neighbours z).
    fn contract(&mut self, v: VertexId) -> [VertexId; 2] {
        let lifting = self.lifting;
        let class = |w: VertexId| VertexId(lifting.class(w));
        let st = &mut self.st;
        let u = st.u;
        let h = st.to[v.idx()];
        let (x, y) = {
            let mesh = &*self.mesh;
            debug_assert_eq!((class(mesh.origin(h)), class(mesh.dest(h))), (u, v));
            (
                class(mesh.opposite_vertex(h)),
                class(mesh.opposite_vertex(h.twin())),
            )
        };
        st.ts += 1;
        let ts = st.ts;
        // Lines 4–11 (and temp, which COLLAPSE fills in the paper): the new neighbours Π_uv.
        self.temp.clear();
        for hz in self.mesh.outgoing(self.mesh.dest(h)) {
            let z = class(self.mesh.dest(hz));
            if z == u || z == x || z == y {
                continue;
            }
            let a = &mut st.attr[z.idx()];
            debug_assert_ne!(a.n, u.0, "[{u:?}, {v:?}] is in a critical cycle with {z:?}");
            a.n = u.0;
            a.c = 0;
            a.o = ts;
            a.t = NONE;
            st.to[z.idx()] = hz; // v → z, which becomes u → z
            self.temp.push(hz);
        }
        st.attr[v.idx()].p = true;
        // Lines 13–15: the record of S, and COLLAPSE (Algorithm 4.7), on every lift.
        contract_lifts(self.mesh, lifting, h, &mut self.stack);
        self.contractions += 1;
        // Lines 16–24.
        let dv = st.attr[v.idx()].d;
        st.attr[x.idx()].d -= 1;
        st.attr[y.idx()].d -= 1;
        st.attr[u.idx()].d = st.attr[u.idx()].d + dv - 4;
        for w in [x, y] {
            let a = st.attr[w.idx()];
            if a.d == 3 && !a.p && a.t == NONE {
                debug_assert_eq!(st.lists.list_of(w.0), Some(List::Lue));
                st.lists.move_to_front(w.0);
            }
        }
        // Lines 25–43.
        let mesh = &*self.mesh;
        for &hz in &self.temp {
            let z = class(mesh.dest(hz));
            if !st.attr[z.idx()].p {
                st.insert_unprocessed(z);
                continue;
            }
            let (x2, y2) = (
                class(mesh.opposite_vertex(hz)),
                class(mesh.opposite_vertex(hz.twin())),
            );
            // The apexes are one vertex ω whose link is every boundary vertex: always from the
            // lte side (decision 9).
            if lifting.apex_class() == Some(z.0) || lte_links_are_shorter(st, st.attr[z.idx()].d) {
                // Decision 8: the same w, found from the (unprocessed, low-degree) lte side. Any
                // lift of w has the same neighbouring classes.
                self.hits.clear();
                self.hits
                    .extend(st.lists.iter(List::Lte).map(VertexId).filter(|&w| {
                        w != x2
                            && w != y2
                            && mesh
                                .neighbors(lifting.lift(w.0))
                                .any(|k| lifting.class(k) == z.0)
                    }));
                for &w in &self.hits {
                    st.increment(w);
                }
            } else {
                for hw in mesh.outgoing(mesh.dest(hz)) {
                    let w = class(mesh.dest(hw));
                    if w == u || w == x2 || w == y2 {
                        continue;
                    }
                    let a = st.attr[w.idx()];
                    if a.n == u.0 && a.t != NONE {
                        st.increment(w);
                    }
                }
            }
        }
        [x, y]
    }

    /// PROCESSEDELIST (Algorithm 4.6): contracts the degree-3 edges at the front of lte, then the
    /// front edge if its counter is 0 (Proposition 10: edges with c = 0 precede the others).
    fn process_edge_list(&mut self) {
        while let Some(v) = self.st.lists.front(List::Lte) {
            if self.st.attr[v as usize].d != 3 {
                break;
            }
            self.st.lists.remove(v);
            self.process_vertex_of_degree_eq3(VertexId(v));
        }
        if let Some(v) = self.st.lists.front(List::Lte)
            && self.st.attr[v as usize].c == 0
        {
            self.st.lists.remove(v);
            self.contract(VertexId(v));
        }
    }
}
