//! Removal of flat vertices from an intrinsic triangulation, towards the paper's canonical
//! Delaunay tessellation whose vertices are the singularities (Dubois, Section 1.2 and
//! Appendix C; for a flat torus, exactly one vertex).
//!
//! A flat vertex v (angle sum 2π within the tolerance, not incident to a loop) is removed as in
//! Sharp, Soliman & Crane, "Navigating intrinsic triangulations" (ACM TOG 38(4), 2019,
//! Section 5.3): flip edges incident to v until v has degree 3, then replace its three triangles by
//! the one triangle they tile (v is flat, so the three outer edges keep their lengths; done with
//! `SurfaceMesh::contract_unchecked` of an edge into v, which keeps the three outer edge ids). An
//! incident edge is flipped only if its quad is convex at both of its ends (strictly if possible;
//! otherwise straight at v — the square-with-centre case — which leaves a zero-area triangle at v
//! that disappears with v). A loop at v is flipped away the same way when possible.
//!
//! Why a flip always exists for a loop-free flat vertex v of degree `d > 3`: its star unfolds into
//! a simple star-shaped polygon around v; by the two-ears theorem the link polygon has two ears
//! with disjoint interiors, so one ear `w` does not contain v; then the quad of the edge `vw` is
//! convex at w and at most straight at v. With loops at v this argument fails (and the paper too
//! needs other tools, Section 4.3): a vertex that gets stuck has its flips undone and is retried
//! later (after the other removals, after a Delaunay flip of everything); if it stays stuck the
//! removal fails with [`RemovalError::Stuck`] rather than guess. Each attempt costs O(d²).

use crate::error::RemovalError;
use crate::flip::{DelaunayOptions, flip_to_delaunay};
use crate::triangulation::IntrinsicTriangulation;
use crate::triangulation::quality::flat_vertices;
use crate::triangulation::trig;
use surftopo_mesh::{EdgeId, VertexId};

/// What [`remove_flat_vertices`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RemovalReport {
    /// Vertices removed.
    pub removed: usize,
    /// Flips made to bring them to degree 3.
    pub flips: u64,
    /// On a flat torus (no singular vertex at all), the one flat vertex kept.
    pub kept_flat: Option<VertexId>,
}

/// Removes every flat vertex (`|Θ_v - 2π| <= angle_tolerance`), keeping one if all vertices are
/// flat (the surface is then a flat torus). Vertex, edge and face ids of the remaining elements are
/// kept (removed ones become tombstones); the surface is unchanged up to rounding.
///
/// Vertices are tried in increasing id order; one that gets stuck (see the module doc) has its
/// flips undone and is retried after the others, then after a Delaunay flip of the whole
/// triangulation; on a flat torus every vertex is in turn allowed to be the one kept. O(Σ d²)
/// per pass over the flat vertices, a handful of passes.
///
/// # Errors
/// [`RemovalError::Geometry`] for unusable lengths; [`RemovalError::Stuck`] naming a flat vertex
/// that no flip brings to degree 3 without loops (the triangulation is then valid, with that
/// vertex and the other stuck ones still in it).
pub fn remove_flat_vertices(
    tri: &mut IntrinsicTriangulation,
    angle_tolerance: f64,
) -> Result<RemovalReport, RemovalError> {
    tri.validate()?;
    let mut pending = flat_vertices(tri, angle_tolerance);
    let mut report = RemovalReport::default();
    let all_flat = pending.len() == tri.mesh().vertex_count();
    if all_flat && !pending.is_empty() {
        report.kept_flat = Some(pending.remove(0));
    }
    let mut keep_candidates_tried = 1usize;
    let mut delaunay_tried = false;
    while !pending.is_empty() {
        let before = pending.len();
        let mut still = Vec::new();
        for v in pending {
            match remove_vertex(tri, v) {
                Some(flips) => {
                    report.flips += flips;
                    report.removed += 1;
                }
                None => still.push(v),
            }
        }
        pending = still;
        if pending.is_empty() || pending.len() < before {
            delaunay_tried = false;
            continue;
        }
        if !delaunay_tried {
            flip_to_delaunay(tri, &DelaunayOptions::default())?;
            delaunay_tried = true;
            continue;
        }
        match report.kept_flat {
            Some(kept) if keep_candidates_tried <= pending.len() => {
                // Keep another vertex of the flat torus instead.
                pending.push(kept);
                report.kept_flat = Some(pending.remove(0));
                keep_candidates_tried += 1;
                delaunay_tried = false;
            }
            _ => {
                let v = pending[0];
                return Err(RemovalError::Stuck {
                    vertex: v.0,
                    degree: tri.mesh().degree(v),
                });
            }
        }
    }
    Ok(report)
}

/// Whether `v` is the base of a loop edge.
fn has_loop(tri: &IntrinsicTriangulation, v: VertexId) -> bool {
    let mesh = tri.mesh();
    mesh.outgoing(v).any(|h| mesh.dest(h) == v)
}

/// The incident edge of `v` whose flip is best (smallest convexity product at its two ends): the
/// quad must be strictly convex at the far end (`< 1`) and below `bound_at_v` at v, and the new
/// triangle away from v must be a valid triangle (the one at v may be degenerate when
/// `bound_at_v > 1`: it disappears with v).
fn best_flip(tri: &IntrinsicTriangulation, v: VertexId, bound_at_v: f64) -> Option<(EdgeId, f64)> {
    let mesh = tri.mesh();
    let mut best: Option<(f64, EdgeId, f64)> = None;
    for h in mesh.outgoing(v) {
        let e = h.edge();
        if !mesh.can_flip(e) {
            continue;
        }
        // h = v -> w: v is the quad's a, w its b; the new triangles are (d, c, v) and (c, d, w).
        let q = tri.quad(h);
        let (at_v, at_w) = (q.convexity_at_a(), q.convexity_at_b());
        let score = at_v.max(at_w);
        let length = q.flipped_length();
        if at_v < bound_at_v
            && at_w < 1.0
            && trig::is_triangle(length, q.db, q.bc)
            && best.is_none_or(|(s, _, _)| score < s)
        {
            best = Some((score, e, length));
        }
    }
    best.map(|(_, e, l)| (e, l))
}

/// Removes one flat vertex; returns the number of flips, or `None` (with every flip undone) when
/// it gets stuck.
fn remove_vertex(tri: &mut IntrinsicTriangulation, v: VertexId) -> Option<u64> {
    let mut done: Vec<(EdgeId, f64)> = Vec::new();
    let limit = 4 * tri.mesh().degree(v) + 16;
    let stuck = loop {
        if tri.mesh().degree(v) == 3 && !has_loop(tri, v) {
            break false;
        }
        let next = best_flip(tri, v, 1.0)
            .or_else(|| best_flip(tri, v, (1.0 + 1e-9) * (1.0 + 1e-9)))
            .filter(|_| done.len() < limit);
        let Some((e, length)) = next else {
            break true;
        };
        done.push((e, tri.length(e)));
        tri.apply_flip(e, length);
    };
    if !stuck {
        let mesh = tri.mesh();
        let out = mesh.vertex_halfedge(v);
        // The face of v's star that survives: not on either side of the contracted edge.
        let kept = mesh
            .outgoing(v)
            .map(|h| mesh.face(h))
            .find(|&f| f != mesh.face(out) && f != mesh.face(out.twin()))
            .expect("a degree-3 vertex without loops has three faces");
        // Contract u -> v into u: v, [u,v] and the two edges [v,x], [v,y] go; [u,x], [u,y] and
        // [x,y] keep their ids and lengths, and become the sides of the kept face.
        let (mesh, _) = tri.parts_mut();
        let record = mesh.contract_unchecked(out.twin());
        let [a, b, c] = tri.face_sides(kept);
        if trig::is_triangle(a, b, c) {
            return Some(done.len() as u64);
        }
        // Rounding made the merged triangle flat: undo, as if stuck.
        let (mesh, _) = tri.parts_mut();
        mesh.split_vertex(&record);
    }
    // Flipping an edge again restores the other diagonal; the old length is restored exactly.
    for &(e, old) in done.iter().rev() {
        tri.apply_flip(e, old);
    }
    None
}
