//! Test and benchmark surfaces: the flat torus T_x (Dubois, Section 9), sheared tori, sheared
//! pillowcases (needles with cone points), and random isometric re-triangulations by intrinsic
//! flips.

use crate::error::PortalgonError;
use crate::geometry::{Point, Scalar};
use crate::portalgon::{PolygonId, Portalgon};
use crate::triangulation::IntrinsicTriangulation;
use crate::triangulation::convert::{TriangleGluing, triangulation_from_gluing};
use rand::RngExt;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use surftopo_mesh::{EdgeId, Side};

/// The flat torus T_x of Section 9, refined `m × m`.
///
/// T_x is `R² / Λ` with Λ spanned by `u = (1, 0)` and `w = (x, 2)`: two triangles, the first with
/// corners `(0, 0)`, `(1, 0)`, `(x, 2)`, the second its image under the half-turn about the middle
/// of the side from `(1, 0)` to `(x, 2)`, each side glued to the corresponding side of the other
/// (one vertex, three edges). With `m > 1` the same torus is cut into the `m × m` grid of
/// parallelograms spanned by `u/m` and `w/m`, each split into two triangles along its
/// `u/m → w/m` diagonal, like the original: `m²` vertices (all flat), `3m²` edges, `2m²` faces.
/// Triangle `2(jm + i)` has corners `p(i, j), p(i+1, j), p(i, j+1)`, triangle `2(jm + i) + 1` has
/// `p(i+1, j), p(i+1, j+1), p(i, j+1)`, where `p(i, j) = (i u + j w) / m`.
///
/// For integer x the flip algorithm needs exactly `x - 1` flips on T_x (m = 1) and ends with the
/// 1 × 2 rectangle split by a diagonal: lengths 1, 2, √5.
///
/// # Errors
/// [`PortalgonError::InvalidParameter`] unless `x` is finite and `1 <= m <= 30000`, or when `x`
/// is so large that the rounded lengths give triangles whose area is off by more than 1e-3 (from
/// about `|x| = 10^5`: they no longer describe T_x); a gluing error is impossible.
pub fn flat_torus(x: f64, m: u32) -> Result<IntrinsicTriangulation, PortalgonError> {
    let invalid = |name, value: String, requirement: &str| PortalgonError::InvalidParameter {
        name,
        value,
        requirement: requirement.into(),
    };
    if !x.is_finite() {
        return Err(invalid("x", format!("{x:?}"), "must be a finite number"));
    }
    if !(1..=30_000).contains(&m) {
        return Err(invalid("m", m.to_string(), "must be between 1 and 30000"));
    }
    let mf = f64::from(m);
    let len_u = 1.0 / mf;
    let len_w = x.hypot(2.0) / mf;
    let len_d = (x - 1.0).hypot(2.0) / mf;
    // Each triangle has area 1/m² (T_x has area 2); lengths rounded beyond that (huge |x|) no
    // longer describe T_x.
    let area = crate::triangulation::trig::area(len_u, len_d, len_w) * mf * mf;
    if (area - 1.0).abs().is_nan() || (area - 1.0).abs() > 1e-3 {
        return Err(invalid(
            "x",
            format!("{x:?}"),
            &format!(
                "too large for double precision: the rounded side lengths give triangles of \
                 area {area:e} instead of 1/m²"
            ),
        ));
    }
    let n = (m * m) as usize;
    let mut sides = Vec::with_capacity(2 * n);
    for _ in 0..n {
        // A: u, w - u, -w;  B: w, -u, u - w.
        sides.push([len_u, len_d, len_w]);
        sides.push([len_w, len_u, len_d]);
    }
    let pairs = flat_torus_pairs(m);
    let polygon_index: Vec<usize> = (0..2 * n).collect();
    triangulation_from_gluing(&TriangleGluing {
        sides: &sides,
        pairs: &pairs,
        labels: None,
        polygon_index: &polygon_index,
        tolerance: 0.0,
    })
}

/// T_x refined `m × m` as a portalgon given by corners, in the scalar type `S` (exactly, for
/// [`crate::geometry::Rational`] and any rational `x`): the same triangles, sides and
/// matching as [`flat_torus`] (triangle `2(jm + i)` has corners `p(i, j), p(i+1, j), p(i, j+1)`,
/// triangle `2(jm + i) + 1` has `p(i+1, j), p(i+1, j+1), p(i, j+1)`, with `p(i, j) = (i u + j
/// w)/m`, `u = (1, 0)`, `w = (x, 2)`); the corner at `p(i, j)` is labelled with the vertex
/// `(j mod m) m + (i mod m)`. For `m = 1`: the corners `(0, 0), (1, 0), (x, 2)` and
/// `(1, 0), (1 + x, 2), (x, 2)`.
///
/// # Errors
/// [`PortalgonError::InvalidParameter`] naming `x` or `m` unless `x` is finite and
/// `1 <= m <= 30000`.
pub fn flat_torus_portalgon<S: Scalar>(x: &S, m: u32) -> Result<Portalgon<S>, PortalgonError> {
    let invalid = |name, value: String, requirement: &str| PortalgonError::InvalidParameter {
        name,
        value,
        requirement: requirement.into(),
    };
    if !x.is_finite() {
        return Err(invalid("x", format!("{x}"), "must be a finite number"));
    }
    if !(1..=30_000).contains(&m) {
        return Err(invalid("m", m.to_string(), "must be between 1 and 30000"));
    }
    let ms = S::from_i64(i64::from(m));
    let point = |i: u32, j: u32| -> Point<S> {
        let (i, j) = (S::from_i64(i64::from(i)), S::from_i64(i64::from(j)));
        [
            (i + j.clone() * x.clone()) / ms.clone(),
            (j * S::from_i64(2)) / ms.clone(),
        ]
    };
    let label = |i: u32, j: u32| (j % m) * m + (i % m);
    let mut p = Portalgon::empty();
    for j in 0..m {
        for i in 0..m {
            p.push_polygon(
                &[point(i, j), point(i + 1, j), point(i, j + 1)],
                Some(&[label(i, j), label(i + 1, j), label(i, j + 1)]),
            );
            p.push_polygon(
                &[point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)],
                Some(&[label(i + 1, j), label(i + 1, j + 1), label(i, j + 1)]),
            );
        }
    }
    for (a, b) in flat_torus_pairs(m) {
        let side = |s: Side| p.side(PolygonId(s.face), usize::from(s.side));
        let (sa, sb) = (side(a), side(b));
        // Exact lengths agree exactly; in f64 the tolerance covers the rounding of `point`.
        p.glue(sa, sb, 1e-12)?;
    }
    Ok(p)
}

/// The matching of [`flat_torus`]: `3m²` pairs of sides.
fn flat_torus_pairs(m: u32) -> Vec<(Side, Side)> {
    let cell = |i: u32, j: u32| (j % m) * m + (i % m);
    let side = |face: u32, side: u8| Side { face, side };
    let mut pairs = Vec::with_capacity(3 * (m * m) as usize);
    for j in 0..m {
        for i in 0..m {
            let c = cell(i, j);
            let (a, b) = (2 * c, 2 * c + 1);
            // Bottom of A(i, j) with the top of B(i, j - 1).
            pairs.push((side(a, 0), side(2 * cell(i, j + m - 1) + 1, 1)));
            // The diagonal.
            pairs.push((side(a, 1), side(b, 2)));
            // Left of A(i, j) with the right of B(i - 1, j).
            pairs.push((side(a, 2), side(2 * cell(i + m - 1, j) + 1, 0)));
        }
    }
    pairs
}

/// Sheared tori (a torus of revolution whose grid diagonals wind around the tube): the mesh
/// crate's generator, re-exported here beside the other intrinsic test surfaces.
pub use surftopo_mesh::generators::sheared_torus;

/// Re-triangulates `tri` isometrically by up to `count` random intrinsic flips: edges drawn
/// uniformly (seeded `ChaCha8Rng`), flipped only when their quad is convex with margin
/// (`tan(α₁/2) tan(α₂/2) < 0.9` at both ends, i.e. angles below about 168°, so no new triangle is
/// nearly degenerate) and keeps the triangulation valid and its area (see
/// [`IntrinsicTriangulation::flip_if_convex`]). At most `20 · count` draws, so it always returns. Returns the number of
/// flips made. Same seed, same result.
pub fn random_flips(tri: &mut IntrinsicTriangulation, count: u64, seed: u64) -> u64 {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let slots = tri.mesh().edge_slots();
    if slots == 0 {
        return 0;
    }
    let mut flips = 0;
    for _ in 0..count.saturating_mul(20) {
        if flips == count {
            break;
        }
        let e = EdgeId::new(rng.random_range(0..slots));
        if tri.mesh().is_edge_live(e) && tri.flip_if_convex_with_margin(e, 0.9) {
            flips += 1;
        }
    }
    flips
}

/// The pillowcase `R²/(2L ⋊ ±1)` of the lattice `L = ⟨u, v⟩`: a sphere with four cone points of
/// angle π (the images of `L`), triangulated from the parallelogram `0, 2u, 2u + v, v` by the
/// triangles `(0, u, v)`, `(u, u+v, v)`, `(u, 2u, u+v)`, `(2u, 2u+v, u+v)`: the bottom and top
/// sides folded at `u` and `u + v` by half-turns, the left side glued to the right by `2u`.
/// Replacing `v` by `v + k·u` gives the same surface with needles of aspect ratio about `k²`; its
/// Delaunay tessellation is the image of the planar Delaunay tessellation of `L` (the cone points'
/// lifts are exactly `L`), known by construction. Exact for exact `S`.
///
/// # Errors
/// [`PortalgonError`] when `u, v` are not a positively oriented basis (a degenerate triangle).
pub fn pillowcase<S: Scalar>(u: &Point<S>, v: &Point<S>) -> Result<Portalgon<S>, PortalgonError> {
    let add =
        |a: &Point<S>, b: &Point<S>| [a[0].clone() + b[0].clone(), a[1].clone() + b[1].clone()];
    let z = [S::zero(), S::zero()];
    let (u2, uv) = (add(u, u), add(u, v));
    let u2v = add(&u2, v);
    let mut p = Portalgon::<S>::empty();
    let a = p.add_polygon(&[z, u.clone(), v.clone()])?;
    let b = p.add_polygon(&[u.clone(), uv.clone(), v.clone()])?;
    let c = p.add_polygon(&[u.clone(), u2.clone(), uv.clone()])?;
    let d = p.add_polygon(&[u2, u2v, uv])?;
    for ((x, i), (y, j)) in [
        ((a, 0), (c, 0)), // 0→u with u→2u: the half-turn about u
        ((b, 1), (d, 1)), // u+v→v with 2u+v→u+v: the half-turn about u+v
        ((a, 2), (d, 0)), // v→0 with 2u→2u+v: the translation by 2u
        ((a, 1), (b, 2)),
        ((b, 0), (c, 2)),
        ((c, 1), (d, 2)),
    ] {
        p.glue(
            p.side(x, i),
            p.side(y, j),
            crate::geometry::Tolerances::DEFAULT.length,
        )?;
    }
    Ok(p)
}
