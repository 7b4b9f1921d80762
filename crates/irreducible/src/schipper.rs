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
use std::time::Instant;

use surftopo_mesh::{EdgeId, HalfedgeId, SurfaceMesh, VertexId};

use crate::tally::TestTally;
use crate::{IrreducibleError, Reduction, check_simplicial};

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
    mut mesh: SurfaceMesh,
    mut on_test: impl FnMut(&SurfaceMesh, HalfedgeId, usize),
) -> Result<Reduction, IrreducibleError> {
    check_simplicial(&mesh)?;
    let start = Instant::now();
    let mut dict = LinkDictionaries::new(&mesh);
    let mut by_degree: BTreeSet<(u32, u32)> =
        mesh.vertices().map(|v| (dict.degree(v), v.0)).collect();
    let mut tally = TestTally::new(mesh.edge_slots());
    let mut history = Vec::with_capacity(mesh.vertex_count().saturating_sub(4));
    let mut fan: Vec<HalfedgeId> = Vec::new();
    while let Some(&(degree, vi)) = by_degree.first() {
        let v = VertexId(vi);
        fan.clear();
        fan.extend(mesh.outgoing(v));
        let found = fan.iter().copied().find(|&h| {
            tally.record(h.edge());
            on_test(&mesh, h, history.len());
            dict.link_condition(&mesh, h)
        });
        let Some(h) = found else {
            by_degree.remove(&(degree, vi)); // v is trapped, and stays so (Lemma 5)
            continue;
        };
        let w = mesh.dest(h);
        let (x, y) = (mesh.opposite_vertex(h), mesh.opposite_vertex(h.twin()));
        let old = [w, x, y].map(|z| (dict.degree(z), z.0));
        history.push(mesh.contract_unchecked(h.twin())); // v identified with w
        dict.contract(v, w, [x, y]);
        by_degree.remove(&(degree, vi));
        for (key, z) in old.into_iter().zip([w, x, y]) {
            if by_degree.remove(&key) {
                by_degree.insert((dict.degree(z), z.0));
            }
        }
    }
    Ok(Reduction::finish(mesh, history, &tally, start))
}

/// S's dictionaries D_u (Section 3 of the paper): for every vertex slot, the ids of the vertices of
/// its link lk(u, K), sorted; empty for a removed vertex. Public so that the bench's variants of S
/// (`schipper_epsilon`, `schipper_time`) use the same dictionaries as [`schipper`].
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LinkDictionaries(Vec<Vec<u32>>);

impl LinkDictionaries {
    /// The dictionaries of `mesh`, one per vertex slot. O(n lg d).
    pub fn new(mesh: &SurfaceMesh) -> Self {
        let dict = (0..mesh.vertex_slots())
            .map(|i| {
                let v = VertexId::new(i);
                if !mesh.is_vertex_live(v) {
                    return Vec::new();
                }
                let mut link: Vec<u32> = mesh.neighbors(v).map(|w| w.0).collect();
                link.sort_unstable();
                link
            })
            .collect();
        Self(dict)
    }

    /// The degree of `v`: the size of D_v.
    #[inline]
    pub fn degree(&self, v: VertexId) -> u32 {
        self.0[v.idx()].len() as u32
    }

    /// The link condition for `h = v → w` in `mesh`, whose dictionaries these are: K is not T4 and
    /// no vertex of D_v but w and the two vertices opposite [v, w] belongs to D_w. O(d_v lg d_w).
    #[inline]
    pub fn link_condition(&self, mesh: &SurfaceMesh, h: HalfedgeId) -> bool {
        let (v, w) = (mesh.origin(h), mesh.dest(h));
        let (dv, dw) = (&self.0[v.idx()], &self.0[w.idx()]);
        if dv.len() == 3 && dw.len() == 3 {
            return false; // K is T4 (Proposition 6)
        }
        let (x, y) = (mesh.opposite_vertex(h).0, mesh.opposite_vertex(h.twin()).0);
        !dv.iter()
            .any(|&z| z != w.0 && z != x && z != y && dw.binary_search(&z).is_ok())
    }

    /// The update for contracting the edge between `removed` and `kept` into `kept`, `opposite`
    /// being the edge's two opposite vertices: D_removed is emptied and returned, `removed` leaves
    /// the other dictionaries, and `kept` and each vertex of D_removed but `kept` and `opposite`
    /// enter each other's.
    pub fn contract(
        &mut self,
        removed: VertexId,
        kept: VertexId,
        opposite: [VertexId; 2],
    ) -> Vec<u32> {
        let [x, y] = opposite;
        let link = std::mem::take(&mut self.0[removed.idx()]);
        for z in [kept, x, y] {
            dict_remove(&mut self.0[z.idx()], removed.0);
        }
        for &z in &link {
            if z != kept.0 && z != x.0 && z != y.0 {
                let dz = &mut self.0[z as usize];
                dict_remove(dz, removed.0);
                dict_insert(dz, kept.0);
                dict_insert(&mut self.0[kept.idx()], z);
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
