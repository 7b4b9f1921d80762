//! The expansion step of LRS (Lemos, Ramaswami, Siqueira): Section 3.3.1 of the quadrangulation
//! paper (`tri-quad-conversion-long.txt`), Algorithm 3.1 (EXPANSIONS) with Algorithms 3.2
//! (EXPANDMATCHDEGREE3), 3.3 (EXPANDMATCHDEGREE4) and 3.4 (EXPANDMATCHDEGREEGREATERTHAN4).
//!
//! The contraction step (Ramaswami–Siqueira, `surftopo-irreducible`) leaves an irreducible
//! triangulation T′ and the stack S of its contractions. Here the contractions are undone in
//! reverse order with [`SurfaceMesh::split_vertex`], which restores the input T exactly (same
//! ids), while a matching M (a set of primal edges) and a per-edge `flipped` flag are maintained as
//! the paper's pseudocode says. The triangulation K of the paper is T with the flagged flips
//! applied; M's dual edges match every triangle of K except those of T′ (Proposition 3.3), so at
//! most `max(4, 56g − 12)` triangles are left unmatched.
//!
//! # Decisions
//! 1. **When the flips happen.** The paper only flags flips ("there is no need to explicitly
//!    construct K during the execution of Algorithm 3.1"). A vertex split needs the mesh exactly as
//!    the contraction left it, so the mesh is kept equal to T during the expansion and the flips
//!    are applied at the end. They are recorded as a chronological list of flip operations (an
//!    "unflip" of Algorithm 3.2, line 3, is one more flip of the same edge) and replayed in that
//!    order, because consecutive flips in one region do not commute (Figure 3.9: the face across
//!    [v, x] in K may itself come from a flip). Replaying at the end is exact: a flip never touches
//!    the split edges [u, x], [u, y] of a later split (they are not safe, so never flipped — this
//!    is checked before every split), so the flip's quadrilateral lies on one side of the path
//!    x–u–y and commutes with the split.
//! 2. **The flags** are read by edge id (`Vec<bool>`): `flipped(e)` is the paper's flag, toggled by
//!    every flip operation of `e`. The `flipped_edges` figure counts edges whose final flag is set
//!    (an edge flipped and unflipped counts as not flipped), as the paper's "flips 3392 edges".
//! 3. **Local configuration.** After splitting `h = u → v` (Figure 3.1, faces [u, v, x] and
//!    [v, u, y]), `next(h)` is v → x and `prev(twin h)` is y → v. With v of degree 3 the face across
//!    [v, x] is [x, v, y] and [x, y] is its third edge; with degree 4 it is [x, v, z], z is the
//!    fourth neighbour, [x, z] its third edge, and [y, z] the third edge of the face across [v, y].
//!    Each identification is checked, as is every paper invariant below; a violation is reported as
//!    [`QuadError::Internal`] with the record index (a wrong history or a bug), never as a result.
//! 4. **Checks at the end.** Every flip replays (`SurfaceMesh::flip` succeeds), M contains no
//!    flipped edge and is a matching of K's dual (no triangle in two pairs; Claim 3.1 (ii)).
//!
//! Complexity: O(n) (one split per record, O(degree of v) to read the degree, at most two flips
//! per split), memory O(n).

use surftopo_matching::Pairing;
use surftopo_mesh::{Contraction, EdgeId, HalfedgeId, SurfaceMesh};

use crate::QuadError;

/// How many expansions each branch of Algorithm 3.1 handled.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct ExpansionCases {
    /// Line 7: neither split edge in M; [u, v] inserted.
    pub neither_split_edge_matched: u64,
    /// Line 9: EXPANDMATCHDEGREE3 (Algorithm 3.2).
    pub degree3: u64,
    /// Of those, the ones that unflipped [x, y] (Algorithm 3.2, line 3).
    pub degree3_unflips: u64,
    /// Line 13: EXPANDMATCHDEGREE4 (Algorithm 3.3).
    pub degree4: u64,
    /// Line 15: degree 4 but [x, z] or [y, z] flipped: Algorithm 3.4.
    pub degree4_with_flipped_edge: u64,
    /// Line 18: degree above 4: Algorithm 3.4.
    pub degree_above4: u64,
}

/// The result of the expansion: K and the matching M on its dual.
#[derive(Clone, Debug)]
pub struct Expansion {
    /// K: the input triangulation (same vertex, edge and face ids) with the flips applied.
    pub mesh: SurfaceMesh,
    /// M, as a pairing of K's triangles (face ids of `mesh`).
    pub pairing: Pairing,
    /// The final `flipped` flag per edge id: whether K holds the flip of the input's edge.
    pub flipped: Vec<bool>,
    /// Number of edges whose final flag is set.
    pub flipped_edges: usize,
    /// Number of flip operations replayed (flips and unflips).
    pub flip_operations: usize,
    /// Branch counts of Algorithm 3.1.
    pub cases: ExpansionCases,
}

/// Algorithm 3.1 (EXPANSIONS): replays `history` (contraction order, as returned by
/// `surftopo_irreducible::ramaswami_siqueira`) backwards on `reduced`, building the matching M and
/// the flips, then applies the flips, giving K and M on K's dual.
///
/// Takes the irreducible triangulation T′ with tombstones (surviving ids = input ids) and its
/// contraction history; the history must come from a contraction step that processes vertices one
/// at a time, contracting edges [u, v] into u until u is trapped (Section 3.3.1), as RS does.
/// Guarantees: K is a triangulation of the same surface with the input's vertex, edge and face ids;
/// every triangle of K not in T′ is matched by M (Proposition 3.3). O(n) time and memory.
///
/// # Errors
/// [`QuadError::Internal`] when the history does not replay on `reduced` or a paper invariant is
/// violated (a bug, or a history from another contraction order); the message names the record.
pub fn expand(reduced: SurfaceMesh, history: &[Contraction]) -> Result<Expansion, QuadError> {
    expand_guarded(reduced, history, &Unguarded)
}

/// What a step of the expansion may do: flip an edge, put an edge in M. Every step is allowed on
/// a closed oriented triangulation ([`Unguarded`]); on the cover of a surface with boundary the
/// boundary and cone edges are not ([`crate::lrs_surface`]).
pub(crate) trait Guard {
    /// Whether edge `e` of the mesh as split so far may be flipped.
    fn may_flip(&self, mesh: &SurfaceMesh, e: EdgeId) -> bool;
    /// Whether edge `e` of the mesh as split so far may pair its two triangles.
    fn may_pair(&self, mesh: &SurfaceMesh, e: EdgeId) -> bool;
}

/// Every step allowed: the paper's expansion.
pub(crate) struct Unguarded;

impl Guard for Unguarded {
    #[inline(always)]
    fn may_flip(&self, _: &SurfaceMesh, _: EdgeId) -> bool {
        true
    }
    #[inline(always)]
    fn may_pair(&self, _: &SurfaceMesh, _: EdgeId) -> bool {
        true
    }
}

/// [`expand`] where `guard` may forbid a step: a step of Algorithm 3.1 that would flip or pair
/// an edge the guard forbids is skipped as a whole (nothing flipped, nothing paired), but the
/// unflip of Algorithm 3.2 (line 3), which only restores an edge the guard let flip. M stays a
/// matching of K: a bare split moves the pair of a split edge onto the new triangle beside it and
/// leaves the triangle across free, so every step's outcome is a matching of the next K with or
/// without its own pair (Claim 3.1 (ii) needs no more than that). The triangles of a skipped
/// step stay unpaired (the caller augments).
pub(crate) fn expand_guarded<G: Guard>(
    reduced: SurfaceMesh,
    history: &[Contraction],
    guard: &G,
) -> Result<Expansion, QuadError> {
    let mut mesh = reduced;
    let slots = mesh.edge_slots();
    let mut in_m = vec![false; slots];
    let mut flipped = vec![false; slots];
    let mut operations: Vec<EdgeId> = Vec::new();
    let mut cases = ExpansionCases::default();
    let mut toggle = |e: EdgeId, flipped: &mut Vec<bool>| {
        flipped[e.idx()] ^= true;
        operations.push(e);
    };
    // A cooperative stop (Ctrl-C from Python) is read every few thousand expansion steps.
    let mut ticker = surftopo_mesh::stop::Ticker::default();
    for (index, record) in history.iter().enumerate().rev() {
        ticker.tick();
        let fail = |what: &str| {
            QuadError::Internal(format!(
                "LRS expansion, contraction record {index} (kept {:?}, removed {:?}): {what}",
                record.kept(),
                record.removed()
            ))
        };
        let (u, v) = (record.kept(), record.removed());
        let [x, y] = record.link();
        let [ux, uy] = record.split_edges();
        let uv = record.edge_uv();
        let [vx, vy] = record.removed_edges();
        let replays = mesh.is_vertex_live(u)
            && !mesh.is_vertex_live(v)
            && mesh.is_edge_live(ux)
            && mesh.is_edge_live(uy)
            && !mesh.is_edge_live(uv)
            && [uv, vx, vy].iter().all(|e| e.idx() < slots);
        if !replays {
            return Err(fail("the history does not replay on this mesh"));
        }
        if flipped[ux.idx()] || flipped[uy.idx()] {
            return Err(fail(
                "a split edge is flipped (it must be unsafe, hence never flipped)",
            ));
        }
        mesh.split_vertex(record);
        let (x_matched, y_matched) = (in_m[ux.idx()], in_m[uy.idx()]);
        if !x_matched && !y_matched {
            if guard.may_pair(&mesh, uv) {
                in_m[uv.idx()] = true; // line 7
            }
            cases.neither_split_edge_matched += 1;
            continue;
        }
        let h = record.halfedge_uv();
        let to_x = mesh.next(h); // v -> x
        let from_y = mesh.prev(h.twin()); // y -> v
        let ends = |g: HalfedgeId| (mesh.origin(g), mesh.dest(g));
        if ends(to_x) != (v, x) || ends(from_y) != (y, v) {
            return Err(fail("split faces are not [u, v, x] and [v, u, y]"));
        }
        let degree = mesh.degree(v);
        // The flips and the pair of the branch taken, made only when the guard allows them all.
        let mut flips: [Option<EdgeId>; 2] = [None, None];
        let pair;
        if degree == 3 {
            // Algorithm 3.2: faces [u, v, x], [x, v, y], [v, u, y].
            let y_to_x = mesh.prev(to_x.twin());
            if ends(y_to_x) != (y, x) {
                return Err(fail("degree 3 but the face across [v, x] is not [x, v, y]"));
            }
            let xy = y_to_x.edge();
            if flipped[xy.idx()] {
                toggle(xy, &mut flipped);
                cases.degree3_unflips += 1;
            }
            pair = match (x_matched, y_matched) {
                (true, true) => xy,
                (true, false) => vy,
                _ => vx,
            };
            cases.degree3 += 1;
        } else if degree == 4
            && !flipped[mesh.prev(to_x.twin()).edge().idx()]
            && !flipped[mesh.next(from_y.twin()).edge().idx()]
        {
            // Algorithm 3.3: faces [u, v, x], [x, v, z], [z, v, y], [v, u, y].
            let v_to_z = mesh.next(to_x.twin());
            let z = mesh.dest(v_to_z);
            let z_to_x = mesh.prev(to_x.twin());
            let y_to_z = mesh.next(from_y.twin());
            if ends(z_to_x) != (z, x) || ends(y_to_z) != (y, z) {
                return Err(fail(
                    "degree 4 but the faces at v are not [x, v, z], [z, v, y]",
                ));
            }
            match (x_matched, y_matched) {
                (true, true) => pair = v_to_z.edge(),
                (true, false) => {
                    flips[0] = Some(vx);
                    pair = uv;
                }
                _ => {
                    flips[0] = Some(vy);
                    pair = uv;
                }
            }
            cases.degree4 += 1;
        } else {
            // Algorithm 3.4 (degree above 4, or 4 with [x, z] or [y, z] flipped).
            if degree == 4 {
                let (z_to_x, y_to_z) = (mesh.prev(to_x.twin()), mesh.next(from_y.twin()));
                let z = mesh.origin(z_to_x);
                if ends(z_to_x) != (z, x) || ends(y_to_z) != (y, z) {
                    return Err(fail(
                        "degree 4 but the faces at v are not [x, v, z], [z, v, y]",
                    ));
                }
                cases.degree4_with_flipped_edge += 1;
            } else {
                cases.degree_above4 += 1;
            }
            if x_matched {
                flips[0] = Some(vx);
            }
            if y_matched {
                flips[1] = Some(vy);
            }
            pair = uv;
        }
        let allowed = guard.may_pair(&mesh, pair)
            && flips.iter().flatten().all(|&e| guard.may_flip(&mesh, e));
        if allowed {
            for &e in flips.iter().flatten() {
                toggle(e, &mut flipped);
            }
            in_m[pair.idx()] = true;
        }
    }
    replay(mesh, in_m, flipped, &operations, cases)
}

/// The end of [`expand_guarded`]: the flip operations (in `operations`' order) replayed on the
/// split mesh `mesh` (giving T), and M (`in_m`) checked to hold no flipped edge (Claim 3.1 (ii))
/// and to be a matching of K.
fn replay(
    mut mesh: SurfaceMesh,
    in_m: Vec<bool>,
    flipped: Vec<bool>,
    operations: &[EdgeId],
    cases: ExpansionCases,
) -> Result<Expansion, QuadError> {
    let slots = in_m.len();
    let mut ticker = surftopo_mesh::stop::Ticker::default();
    for (i, &e) in operations.iter().enumerate() {
        ticker.tick();
        mesh.flip(e).map_err(|err| {
            QuadError::Internal(format!(
                "LRS: flip operation {i} of {} ({e:?}) does not replay on T: {err}",
                operations.len()
            ))
        })?;
    }
    let matched: Vec<u32> = (0..slots as u32).filter(|&e| in_m[e as usize]).collect();
    if let Some(&e) = matched.iter().find(|&&e| flipped[e as usize]) {
        return Err(QuadError::Internal(format!(
            "LRS: edge e{e} is in M but flipped (Claim 3.1 (ii))"
        )));
    }
    let pairing = Pairing::from_edges(&mesh, matched)
        .map_err(|err| QuadError::Internal(format!("LRS: M is not a matching of K: {err}")))?;
    let flipped_edges = flipped.iter().filter(|&&f| f).count();
    Ok(Expansion {
        mesh,
        pairing,
        flipped,
        flipped_edges,
        flip_operations: operations.len(),
        cases,
    })
}
