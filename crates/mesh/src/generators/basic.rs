//! Tetrahedron, icosphere and (sheared) tori.

use crate::Surface;
use crate::geometry::Point3;
use std::collections::HashMap;

/// The boundary of a regular tetrahedron (4 vertices, genus 0).
pub fn tetrahedron() -> Surface {
    let positions = vec![
        [1.0, 1.0, 1.0],
        [1.0, -1.0, -1.0],
        [-1.0, 1.0, -1.0],
        [-1.0, -1.0, 1.0],
    ];
    Surface::from_triangles(positions, &[[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]])
        .expect("tetrahedron is valid")
}

/// The twelve vertices of an icosahedron: the cyclic shifts of `(±1, ±t, 0)`, `t` the golden
/// ratio, in the order [`icosphere`]'s triangles use.
pub(crate) fn icosahedron_vertices() -> [Point3; 12] {
    let t = (1.0 + 5f64.sqrt()) / 2.0;
    [
        [-1.0, t, 0.0],
        [1.0, t, 0.0],
        [-1.0, -t, 0.0],
        [1.0, -t, 0.0],
        [0.0, -1.0, t],
        [0.0, 1.0, t],
        [0.0, -1.0, -t],
        [0.0, 1.0, -t],
        [t, 0.0, -1.0],
        [t, 0.0, 1.0],
        [-t, 0.0, -1.0],
        [-t, 0.0, 1.0],
    ]
}

/// An icosahedron refined `subdivisions` times by 1-to-4 splits, projected to the unit sphere:
/// `10 * 4^s + 2` vertices, `20 * 4^s` triangles.
pub fn icosphere(subdivisions: u32) -> Surface {
    let mut positions: Vec<Point3> = icosahedron_vertices().to_vec();
    let mut triangles: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..subdivisions {
        let mut midpoint: HashMap<(u32, u32), u32> = HashMap::new();
        let mut mid = |a: u32, b: u32, positions: &mut Vec<Point3>| {
            *midpoint.entry((a.min(b), a.max(b))).or_insert_with(|| {
                let (p, q) = (positions[a as usize], positions[b as usize]);
                positions.push([0, 1, 2].map(|k| (p[k] + q[k]) / 2.0));
                positions.len() as u32 - 1
            })
        };
        let mut refined = Vec::with_capacity(4 * triangles.len());
        for &[a, b, c] in &triangles {
            let (ab, bc, ca) = (
                mid(a, b, &mut positions),
                mid(b, c, &mut positions),
                mid(c, a, &mut positions),
            );
            refined.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        triangles = refined;
    }
    for p in &mut positions {
        let n = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
        *p = p.map(|c| c / n);
    }
    Surface::from_triangles(positions, &triangles).expect("icosphere is valid")
}

/// A torus of revolution triangulated as an `m x n` grid (m around the tube's axis, n around the
/// tube), each quad split along a diagonal: `m n` vertices, `2 m n` triangles. Simplicial for
/// `m, n >= 3`.
///
/// # Panics
/// If `m < 3` or `n < 3`.
pub fn torus(m: u32, n: u32) -> Surface {
    sheared_torus(m, n, 0)
}

/// [`torus`] with the grid sheared: the quad at `(i, j)` joins row `i` to row `i + 1` shifted by
/// `shear`, so the grid lines wind `shear` times around the tube (long, thin triangles that the
/// intrinsic Delaunay flip algorithm must straighten).
///
/// # Panics
/// If `m < 3` or `n < 3`.
pub fn sheared_torus(m: u32, n: u32, shear: u32) -> Surface {
    assert!(m >= 3 && n >= 3, "torus needs m, n >= 3");
    let (big, small) = (1.0, 0.4);
    let tau = std::f64::consts::TAU;
    let mut positions = Vec::with_capacity((m * n) as usize);
    for i in 0..m {
        let phi = tau * i as f64 / m as f64;
        for j in 0..n {
            let theta = tau * j as f64 / n as f64;
            let r = big + small * theta.cos();
            positions.push([r * phi.cos(), r * phi.sin(), small * theta.sin()]);
        }
    }
    let id = |i: u32, j: u32| (i % m) * n + (j % n);
    let shear = shear % n;
    let mut triangles = Vec::with_capacity(2 * (m * n) as usize);
    for i in 0..m {
        for j in 0..n {
            let (a, b, c, d) = (
                id(i, j),
                id(i + 1, j + shear),
                id(i + 1, j + shear + 1),
                id(i, j + 1),
            );
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    Surface::from_triangles(positions, &triangles).expect("torus grid is valid")
}
