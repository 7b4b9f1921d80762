//! The period lattice of a flat torus, for the isometry test where flat-vertex removal fails.
//!
//! A closed surface of genus 1 whose vertices are all flat is a flat torus `R² / Λ`, and two flat
//! tori are isometric iff their lattices are congruent (a rotation or a reflection of the plane
//! takes one onto the other). So instead of removing all but one vertex by flips (which can get
//! stuck on loops, [`crate::remove_flat_vertices`]; Dubois, Section 4.3, needs other tools there
//! too), the lattice is read off the triangulation:
//!
//! 1. a tree-cotree decomposition: a spanning tree T of the vertices, a spanning tree C of the
//!    faces across edges not in T; `2 - χ = 2` edges remain, whose dual loops generate the first
//!    homology of the torus;
//! 2. the faces are developed into the plane along C (each face placed rigidly against the one it
//!    was reached from, with Kahan's half-angle layout);
//! 3. across each of the two remaining edges, the two copies of a vertex differ by a translation:
//!    the periods of the two generating loops, a basis of Λ (checked: the parallelogram they span
//!    has the surface's area, and both ends of each edge give the same translation);
//! 4. Lagrange–Gauss reduction of the basis; `(|b1|, |b2|, |b1 · b2|)` of the reduced basis are
//!    the lattice's congruence invariants (continuous across the reduction's ties).
//!
//! O(n). Decision: the development uses the rounded lengths; a lattice whose checks fail by more
//! than `1e-6` relative is not reported (the caller falls back to the tessellations).

use crate::triangulation::IntrinsicTriangulation;
use surftopo_mesh::{FaceId, HalfedgeId};

/// Congruence invariants `[|b1|, |b2|, |b1 · b2|]` of the reduced period lattice of `tri`, when
/// it is a flat torus (genus 1, every angle sum within `angle_tolerance` of 2π) whose development
/// passes the checks of the module doc; `None` otherwise.
pub fn flat_torus_invariants(
    tri: &IntrinsicTriangulation,
    angle_tolerance: f64,
) -> Option<[f64; 3]> {
    let mesh = tri.mesh();
    if mesh.euler_characteristic() != 0 {
        return None;
    }
    let sums = tri.angle_sums();
    if mesh
        .vertices()
        .any(|v| (sums[v.idx()] - std::f64::consts::TAU).abs() > angle_tolerance)
    {
        return None;
    }
    let (corners, generators) = develop(tri)?;
    let scale = tri.lengths().iter().fold(0.0f64, |m, &l| m.max(l));
    let mut basis = [[0.0; 2]; 2];
    for (b, h) in basis.iter_mut().zip(generators) {
        // h is corner i of face f, its twin t corner j of face g: origin(h) = dest(t) is corner
        // j + 1 of g, dest(h) = origin(t) corner j; each end gives the translation.
        let t = h.twin();
        let (i, j) = (corner_index(tri, h), corner_index(tri, t));
        let (pf, pg) = (corners[mesh.face(h).idx()], corners[mesh.face(t).idx()]);
        let d0 = sub(pg[(j + 1) % 3], pf[i]);
        let d1 = sub(pg[j], pf[(i + 1) % 3]);
        if dist(d0, d1) > 1e-6 * scale {
            return None;
        }
        *b = [(d0[0] + d1[0]) / 2.0, (d0[1] + d1[1]) / 2.0];
    }
    let area = tri.total_area();
    let spanned = cross(basis[0], basis[1]).abs();
    if (spanned - area).abs() > 1e-6 * area {
        return None;
    }
    let [b1, b2] = reduce(basis[0], basis[1]);
    Some([norm(b1), norm(b2), dot(b1, b2).abs()])
}

/// Index of `h` in its face's half-edge list (corner index of its origin).
fn corner_index(tri: &IntrinsicTriangulation, h: HalfedgeId) -> usize {
    let mesh = tri.mesh();
    mesh.face_halfedges(mesh.face(h))
        .iter()
        .position(|&g| g == h)
        .expect("a half-edge is in its face")
}

/// The three corners of a face in the plane.
type FaceCorners = [[f64; 2]; 3];

/// A spanning tree of the vertices (depth-first from the first vertex), by edge.
fn primal_tree(tri: &IntrinsicTriangulation) -> Option<Vec<bool>> {
    let mesh = tri.mesh();
    let mut in_tree = vec![false; mesh.edge_slots()];
    let mut seen = vec![false; mesh.vertex_slots()];
    let start = mesh.vertices().next()?;
    seen[start.idx()] = true;
    let mut stack = vec![start];
    while let Some(v) = stack.pop() {
        for h in mesh.outgoing(v) {
            let w = mesh.dest(h);
            if !seen[w.idx()] {
                seen[w.idx()] = true;
                in_tree[h.edge().idx()] = true;
                stack.push(w);
            }
        }
    }
    Some(in_tree)
}

/// The tree-cotree decomposition and the development (see the module doc): the corners of every
/// face in one chart of the plane (corner `i` of face `f` is the origin of
/// `face_halfedges(f)[i]`), faces placed breadth-first across edges not in the primal tree; and
/// the two edges in neither tree, as half-edges. `None` if the decomposition does not leave
/// exactly two edges.
fn develop(tri: &IntrinsicTriangulation) -> Option<(Vec<FaceCorners>, [HalfedgeId; 2])> {
    let mesh = tri.mesh();
    let mut used = primal_tree(tri)?;
    let mut corners = vec![[[f64::NAN; 2]; 3]; mesh.face_slots()];
    let first = mesh.faces().next()?;
    corners[first.idx()] = tri.layout_face(first);
    let mut reached = vec![false; mesh.face_slots()];
    reached[first.idx()] = true;
    let mut queue = std::collections::VecDeque::from([first]);
    let mut count = 1;
    while let Some(f) = queue.pop_front() {
        for h in mesh.face_halfedges(f) {
            let g = h.twin();
            let next: FaceId = mesh.face(g);
            if used[h.edge().idx()] || reached[next.idx()] {
                continue;
            }
            used[h.edge().idx()] = true;
            reached[next.idx()] = true;
            count += 1;
            queue.push_back(next);
            // g runs from dest(h) to origin(h): its corner j sits at h's corner i + 1, and its
            // corner j + 1 at h's corner i (copied exactly, so rounding does not build up there).
            let placed = corners[f.idx()];
            let (i, j) = (corner_index(tri, h), corner_index(tri, g));
            let (p, q) = (placed[(i + 1) % 3], placed[i]);
            let local = tri.layout_face(next);
            let moved = rigid_motion(local[j], local[(j + 1) % 3], p, q);
            let mut out = local.map(&moved);
            out[j] = p;
            out[(j + 1) % 3] = q;
            corners[next.idx()] = out;
        }
    }
    if count != mesh.face_count() {
        return None;
    }
    let mut left = mesh
        .edges()
        .filter(|e| !used[e.idx()])
        .map(|e| e.halfedge());
    let generators = [left.next()?, left.next()?];
    left.next().is_none().then_some((corners, generators))
}

/// The rigid motion taking `a` to `p` and the direction of `a -> b` to that of `p -> q`.
fn rigid_motion(
    a: [f64; 2],
    b: [f64; 2],
    p: [f64; 2],
    q: [f64; 2],
) -> impl Fn([f64; 2]) -> [f64; 2] {
    let (u, w) = (sub(b, a), sub(q, p));
    let n = norm(u) * norm(w);
    let (cos, sin) = (dot(u, w) / n, cross(u, w) / n);
    move |x| {
        let d = sub(x, a);
        [
            p[0] + cos * d[0] - sin * d[1],
            p[1] + sin * d[0] + cos * d[1],
        ]
    }
}

/// Lagrange–Gauss reduction: a basis of the same lattice with `|b1| <= |b2| <= |b2 ± b1|`.
fn reduce(mut b1: [f64; 2], mut b2: [f64; 2]) -> [[f64; 2]; 2] {
    if norm(b1) > norm(b2) {
        std::mem::swap(&mut b1, &mut b2);
    }
    for _ in 0..200 {
        let m = (dot(b1, b2) / dot(b1, b1)).round();
        b2 = [b2[0] - m * b1[0], b2[1] - m * b1[1]];
        if norm(b2) >= norm(b1) {
            break;
        }
        std::mem::swap(&mut b1, &mut b2);
    }
    [b1, b2]
}

fn sub(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] - b[0], a[1] - b[1]]
}
fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}
fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}
fn norm(a: [f64; 2]) -> f64 {
    a[0].hypot(a[1])
}
fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    norm(sub(a, b))
}
