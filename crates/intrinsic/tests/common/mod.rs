//! Independent verifiers for the intrinsic tests: angles by the law of cosines, areas by Heron's
//! formula in its plain form, Delaunay checks from those, planar coordinates — none of it uses
//! the crate's `trig` module.
#![allow(dead_code)]

use std::f64::consts::PI;
use surftopo_intrinsic::IntrinsicTriangulation;
use surftopo_mesh::{FaceId, HalfedgeId};

/// The angle opposite side `a` in the triangle (a, b, c), law of cosines, clamped.
pub fn angle(a: f64, b: f64, c: f64) -> f64 {
    ((b * b + c * c - a * a) / (2.0 * b * c))
        .clamp(-1.0, 1.0)
        .acos()
}

/// Heron's formula, plain.
pub fn heron(a: f64, b: f64, c: f64) -> f64 {
    let s = (a + b + c) / 2.0;
    (s * (s - a) * (s - b) * (s - c)).max(0.0).sqrt()
}

/// Lengths of the three sides of face f, starting at its stored half-edge.
pub fn sides(tri: &IntrinsicTriangulation, f: FaceId) -> [f64; 3] {
    tri.mesh()
        .face_halfedges(f)
        .map(|h| tri.lengths()[h.edge().idx()])
}

/// The angle opposite half-edge h in its face.
pub fn opposite_angle(tri: &IntrinsicTriangulation, h: HalfedgeId) -> f64 {
    let m = tri.mesh();
    let l = |g: HalfedgeId| tri.lengths()[g.edge().idx()];
    angle(l(h), l(m.next(h)), l(m.prev(h)))
}

/// Total area by Heron.
pub fn area(tri: &IntrinsicTriangulation) -> f64 {
    tri.mesh()
        .faces()
        .map(|f| {
            let [a, b, c] = sides(tri, f);
            heron(a, b, c)
        })
        .sum()
}

/// Angle sum of every vertex slot (law of cosines).
pub fn angle_sums(tri: &IntrinsicTriangulation) -> Vec<f64> {
    let m = tri.mesh();
    let mut sums = vec![0.0; m.vertex_slots()];
    for h in m.halfedges() {
        // The corner at origin(h) in face(h) is opposite next(h).
        sums[m.origin(h).idx()] += opposite_angle(tri, m.next(h));
    }
    sums
}

/// Checks every edge: its two opposite angles sum to at most π + tol; every face is a triangle.
pub fn check_delaunay(tri: &IntrinsicTriangulation, tol: f64) -> Result<(), String> {
    let m = tri.mesh();
    m.check_invariants().map_err(|e| e.to_string())?;
    for f in m.faces() {
        let [a, b, c] = sides(tri, f);
        if !(a < b + c && b < a + c && c < a + b) {
            return Err(format!("face {f:?}: sides {a} {b} {c} are not a triangle"));
        }
    }
    for e in m.edges() {
        let h = e.halfedge();
        let sum = opposite_angle(tri, h) + opposite_angle(tri, h.twin());
        if sum > PI + tol {
            return Err(format!("edge {e:?}: opposite angles sum to {sum} > π"));
        }
    }
    Ok(())
}

/// Asserts two angle-sum vectors agree on the live vertices of `tri`.
pub fn assert_same_angle_sums(tri: &IntrinsicTriangulation, before: &[f64], tol: f64) {
    let after = angle_sums(tri);
    for v in tri.mesh().vertices() {
        let (x, y) = (before[v.idx()], after[v.idx()]);
        assert!(
            (x - y).abs() <= tol,
            "vertex {v:?}: angle sum {x} became {y}"
        );
    }
}

/// Moves every vertex of `s` by a deterministic pseudo-random offset (xorshift from `seed`) of
/// size up to `amount` per coordinate: no vertex stays flat, and the input is not Delaunay.
pub fn jitter(
    mut s: surftopo_mesh::CoveredSurface,
    amount: f64,
    seed: u64,
) -> surftopo_mesh::CoveredSurface {
    let mut state = 0x9e37_79b9_7f4a_7c15u64 ^ seed;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    for p in &mut s.positions {
        for x in p.iter_mut() {
            *x += amount * next();
        }
    }
    s
}
