//! Schipper's algorithm (S), as Section 3 of the irreducible-triangulations paper describes it
//! (H. Schipper, "Generating triangulations of 2-manifolds", 1991).
//!
//! Every vertex u keeps a dictionary D_u of its link lk(u, K), and a global dictionary holds the
//! loose vertices (those not yet found trapped) ordered by current degree. Repeatedly, a vertex v
//! of lowest degree is taken from the global dictionary and its edges [v, w] are tested in rotation
//! order: [v, w] is contractible iff K is not T4 and no vertex of D_v other than w and the two
//! vertices opposite [v, w] is in D_w (Theorem 3), which costs O(d_v lg d_w). The first contractible
//! edge is contracted, identifying v with w: the low-degree vertex is the one removed, O(d_v) in
//! the half-edge mesh, as Schipper's O(n lg n + g lg n + g⁴) bound needs (keeping it instead
//! removes w, O(d_w): quadratic where high-degree vertices form, measured by the bench example
//! `schipper_epsilon`). If no edge is contractible, v is trapped and leaves the global dictionary
//! for good (Lemma 5). Nothing prevents an edge from being tested again after a later
//! contraction (ε counts those).
//!
//! Decisions: D_u is a sorted vector (O(lg d) search as in a balanced tree; O(d) update, small at
//! the degrees of surface meshes; compact); the global dictionary is a `BTreeSet` of (degree,
//! vertex id), so ties go to the smallest id and choosing a vertex costs O(lg m), m loose
//! vertices, as in the paper's analysis; edges of v are tested in its rotation order from its
//! stored half-edge, including edges to trapped vertices (which fail), as the paper's ε_S = 6 on
//! genus 0 implies.

use std::collections::BTreeSet;

use surftopo_mesh::{
    Contraction, EdgeId, HalfedgeId, Lifting, Plain, SurfaceMesh, VertexId, contract_lifts,
};

use crate::tally::TestTally;
use crate::{IrreducibleError, Reduction};

/// Schipper's algorithm (Section 3 of the paper): contracts edges of `mesh`, always at a loose
/// vertex of lowest degree, until it is an irreducible triangulation of the same surface.
///
/// Takes a closed orientable simplicial surface (checked first). Guarantees: the result is
/// irreducible and simplicial with the input's genus; surviving vertices keep their ids; the history
/// replays back to the input. Deterministic. Time O(n lg n + g lg n + g⁴) in Schipper's analysis;
/// memory O(n).
///
/// # Errors
/// [`IrreducibleError`] if the mesh is not simplicial (nothing is done then).
pub fn schipper(mesh: SurfaceMesh) -> Result<Reduction, IrreducibleError> {
    run(mesh, |_, _, _| {})
}

/// One link-condition test made by [`schipper_traced`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LinkTest {
    /// The edge tested (its id in the input mesh; ids survive contractions, see
    /// [`SurfaceMesh::contract_unchecked`]).
    pub edge: EdgeId,
    /// Its two ends when tested: the chosen vertex first.
    pub ends: [VertexId; 2],
    /// Contractions made before this test (an index into [`Reduction::history`]).
    pub contractions_before: usize,
}

/// [`schipper`], also returning every link-condition test in the order made, so that ε (Section
/// 5.3: "the number of edges tested more than once") can be recounted under another identity of
/// an edge through contractions. Same result and counters as [`schipper`].
///
/// # Errors
/// As [`schipper`].
pub fn schipper_traced(mesh: SurfaceMesh) -> Result<(Reduction, Vec<LinkTest>), IrreducibleError> {
    let mut tests = Vec::new();
    let reduction = run(mesh, |m, h, contractions_before| {
        tests.push(LinkTest {
            edge: h.edge(),
            ends: [m.origin(h), m.dest(h)],
            contractions_before,
        });
    })?;
    Ok((reduction, tests))
}

fn run(
    mesh: SurfaceMesh,
    on_test: impl FnMut(&SurfaceMesh, HalfedgeId, usize),
) -> Result<Reduction, IrreducibleError> {
    Reduction::of_plain_run(mesh, |mesh, plain| run_lifted(mesh, plain, on_test))
}

/// S on the surface a mesh covers (see [`crate::reduce_surface`]): the vertices are the vertex
/// classes (the apexes closing the boundary are never chosen, and edges to them are not the
/// surface's: never tested), the link condition is Dey et al.'s with the apexes as one vertex,
/// contractions are made on every lift. `on_test` sees each test with the number of
/// contractions made before it.
pub(crate) fn run_lifted<L: Lifting>(
    mesh: &mut SurfaceMesh,
    lifting: &L,
    mut on_test: impl FnMut(&SurfaceMesh, HalfedgeId, usize),
) -> (Vec<Contraction>, TestTally, u64) {
    let class = |v: VertexId| VertexId(lifting.class(v));
    let mut dict = LinkDictionaries::of(mesh, lifting);
    // (degree, vertex) packed as `degree << 32 | vertex`: the same order, one integer compare.
    let key = |degree: u32, v: u32| u64::from(degree) << 32 | u64::from(v);
    let mut by_degree: BTreeSet<u64> = (0..lifting.class_count() as u32)
        .filter(|&c| lifting.apex_class() != Some(c))
        .filter(|&c| lifting.lift(c).is_valid() && mesh.is_vertex_live(lifting.lift(c)))
        .map(|c| key(dict.degree(VertexId(c)), c))
        .collect();
    let mut tally = TestTally::new(mesh.edge_slots());
    let mut history = Vec::with_capacity(mesh.vertex_count().saturating_sub(4));
    let mut contractions = 0u64;
    let mut fan: Vec<HalfedgeId> = Vec::new();
    let mut ticker = surftopo_mesh::stop::Ticker::default();
    while let Some(&first) = by_degree.first() {
        ticker.tick();
        let vi = first as u32;
        let v = VertexId(vi);
        fan.clear();
        fan.extend(
            mesh.outgoing(lifting.lift(vi))
                .filter(|&h| !lifting.is_apex(mesh.dest(h))),
        );
        let found = fan.iter().copied().find(|&h| {
            tally.record(lifting.edge_key(h.edge()));
            on_test(mesh, h, contractions as usize);
            dict.link_condition_of(mesh, lifting, h)
        });
        let Some(h) = found else {
            by_degree.remove(&first); // v is trapped, and stays so (Lemma 5)
            continue;
        };
        let w = class(mesh.dest(h));
        let (x, y) = (
            class(mesh.opposite_vertex(h)),
            class(mesh.opposite_vertex(h.twin())),
        );
        let old = [w, x, y].map(|z| key(dict.degree(z), z.0));
        contract_lifts(mesh, lifting, h.twin(), &mut history); // v identified with w
        contractions += 1;
        dict.contract(v, w, [x, y]);
        by_degree.remove(&first);
        for (old_key, z) in old.into_iter().zip([w, x, y]) {
            if by_degree.remove(&old_key) {
                by_degree.insert(key(dict.degree(z), z.0));
            }
        }
    }
    (history, tally, contractions)
}

/// S's dictionaries D_u (Section 3 of the paper): for every vertex slot (vertex class, on a
/// covered surface), the vertices of its link lk(u, K), sorted; empty for a removed vertex and
/// for the apexes' class (never tested, so not kept). Public so that the bench's variants of S
/// (`schipper_epsilon`, `schipper_time`) use the same dictionaries as [`schipper`].
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LinkDictionaries {
    links: Vec<Vec<u32>>,
    /// The apexes' class, `u32::MAX` when there is none.
    apex: u32,
}

impl LinkDictionaries {
    /// The dictionaries of `mesh`, one per vertex slot. O(n lg d).
    pub fn new(mesh: &SurfaceMesh) -> Self {
        Self::of(
            mesh,
            &Plain {
                slots: mesh.vertex_slots(),
            },
        )
    }

    /// The dictionaries of the surface `mesh` covers, one per vertex class. O(n lg d).
    pub fn of<L: Lifting>(mesh: &SurfaceMesh, lifting: &L) -> Self {
        let links = (0..lifting.class_count() as u32)
            .map(|c| {
                let v = lifting.lift(c);
                if lifting.apex_class() == Some(c) || !v.is_valid() || !mesh.is_vertex_live(v) {
                    return Vec::new();
                }
                let mut link: Vec<u32> = mesh.neighbors(v).map(|w| lifting.class(w)).collect();
                link.sort_unstable();
                link
            })
            .collect();
        Self {
            links,
            apex: lifting.apex_class().unwrap_or(u32::MAX),
        }
    }

    /// The degree of `v`: the size of D_v.
    #[inline]
    pub fn degree(&self, v: VertexId) -> u32 {
        self.links[v.idx()].len() as u32
    }

    /// The link condition for `h = v → w` in `mesh`, whose dictionaries these are: K is not T4 and
    /// no vertex of D_v but w and the two vertices opposite [v, w] belongs to D_w. O(d_v lg d_w).
    #[inline]
    pub fn link_condition(&self, mesh: &SurfaceMesh, h: HalfedgeId) -> bool {
        let plain = Plain {
            slots: mesh.vertex_slots(),
        };
        self.link_condition_of(mesh, &plain, h)
    }

    /// [`Self::link_condition`] on the surface `mesh` covers, on vertex classes: the apexes are
    /// one vertex (Dey et al.'s ω), and an edge at an apex is never contractible.
    #[inline]
    pub fn link_condition_of<L: Lifting>(
        &self,
        mesh: &SurfaceMesh,
        lifting: &L,
        h: HalfedgeId,
    ) -> bool {
        let (v, w) = (lifting.class(mesh.origin(h)), lifting.class(mesh.dest(h)));
        if lifting.apex_class().is_some_and(|a| a == v || a == w) {
            return false;
        }
        let (dv, dw) = (&self.links[v as usize], &self.links[w as usize]);
        if dv.len() == 3 && dw.len() == 3 {
            return false; // K is T4 (Proposition 6)
        }
        let (x, y) = (
            lifting.class(mesh.opposite_vertex(h)),
            lifting.class(mesh.opposite_vertex(h.twin())),
        );
        !dv.iter()
            .any(|&z| z != w && z != x && z != y && dw.binary_search(&z).is_ok())
    }

    /// The update for contracting the edge between `removed` and `kept` into `kept`, `opposite`
    /// being the edge's two opposite vertices: D_removed is emptied and returned, `removed` leaves
    /// the other dictionaries, and `kept` and each vertex of D_removed but `kept` and `opposite`
    /// enter each other's (the apexes' dictionary is not kept).
    pub fn contract(
        &mut self,
        removed: VertexId,
        kept: VertexId,
        opposite: [VertexId; 2],
    ) -> Vec<u32> {
        let [x, y] = opposite;
        let link = std::mem::take(&mut self.links[removed.idx()]);
        for z in [kept, x, y] {
            if z.0 != self.apex {
                dict_remove(&mut self.links[z.idx()], removed.0);
            }
        }
        for &z in &link {
            if z != kept.0 && z != x.0 && z != y.0 {
                if z != self.apex {
                    let dz = &mut self.links[z as usize];
                    dict_remove(dz, removed.0);
                    dict_insert(dz, kept.0);
                }
                dict_insert(&mut self.links[kept.idx()], z);
            }
        }
        link
    }
}

fn dict_remove(d: &mut Vec<u32>, z: u32) {
    if let Ok(i) = d.binary_search(&z) {
        d.remove(i);
    }
}

fn dict_insert(d: &mut Vec<u32>, z: u32) {
    if let Err(i) = d.binary_search(&z) {
        d.insert(i, z);
    }
}
