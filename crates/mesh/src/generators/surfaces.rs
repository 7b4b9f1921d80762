//! Surfaces with boundary, non-orientable surfaces and files of several pieces: the disk,
//! annulus, Möbius band, projective plane, Klein bottle and N_k, connected sums, holes cut from
//! any surface, and side-by-side copies.

use crate::cover::CoveredSurface;
use crate::geometry::Point3;
use rand::SeedableRng;
use rand::seq::SliceRandom;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::TAU;

/// A soup known to be a surface, as a [`CoveredSurface`].
fn surface(positions: Vec<Point3>, triangles: &[[u32; 3]]) -> CoveredSurface {
    CoveredSurface::from_triangles(positions, triangles)
        .expect("a generated surface is a triangulated surface")
        .0
}

/// The grid triangles of an `m x n` array of quads, quad `(i, j)` on the corners `id(i, j)`,
/// `id(i + 1, j)`, `id(i + 1, j + 1)`, `id(i, j + 1)`, split along its diagonal from `(i, j)`.
fn grid(m: u32, n: u32, id: impl Fn(u32, u32) -> u32) -> Vec<[u32; 3]> {
    let mut triangles = Vec::with_capacity(2 * (m * n) as usize);
    for i in 0..m {
        for j in 0..n {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    triangles
}

/// The unit square as an `n x n` grid: a disk with `2 n^2` triangles (n >= 1; 0 is taken as 1).
pub fn disk(n: u32) -> CoveredSurface {
    let n = n.max(1);
    let positions = (0..=n)
        .flat_map(|i| (0..=n).map(move |j| [i as f64 / n as f64, j as f64 / n as f64, 0.0]))
        .collect();
    surface(positions, &grid(n, n, |i, j| i * (n + 1) + j))
}

/// An open cylinder of radius 1 and height 1: an annulus as an `m x n` grid, `m` around (at
/// least 3) and `n` along (at least 1), `2 m n` triangles.
///
/// # Panics
/// If `m < 3` or `n < 1`.
pub fn annulus(m: u32, n: u32) -> CoveredSurface {
    assert!(m >= 3 && n >= 1, "annulus needs m >= 3, n >= 1");
    let mut positions = Vec::with_capacity((m * (n + 1)) as usize);
    for i in 0..m {
        let phi = TAU * i as f64 / m as f64;
        for j in 0..=n {
            positions.push([phi.cos(), phi.sin(), j as f64 / n as f64]);
        }
    }
    surface(positions, &grid(m, n, |i, j| (i % m) * (n + 1) + j))
}

/// A Möbius band as an `m x n` grid, `m` along its core circle (at least 5) and `n` across (at
/// least 1): the strip's ends are glued with a half twist, `(m, j)` to `(0, n - j)`. Embedded in
/// space (core radius 1, width 0.6), `2 m n` triangles.
///
/// # Panics
/// If `m < 5` or `n < 1`.
pub fn mobius_band(m: u32, n: u32) -> CoveredSurface {
    assert!(m >= 5 && n >= 1, "mobius band needs m >= 5, n >= 1");
    let mut positions = Vec::with_capacity((m * (n + 1)) as usize);
    for i in 0..m {
        let theta = TAU * i as f64 / m as f64;
        for j in 0..=n {
            let s = 0.6 * (j as f64 / n as f64 - 0.5);
            let r = 1.0 + s * (theta / 2.0).cos();
            positions.push([r * theta.cos(), r * theta.sin(), s * (theta / 2.0).sin()]);
        }
    }
    let id = |i: u32, j: u32| {
        if i == m { n - j } else { i * (n + 1) + j }
    };
    surface(positions, &grid(m, n, id))
}

/// The 6-vertex projective plane (the hemi-icosahedron: 10 triangles, every two vertices
/// adjacent), its vertices placed at six vertices of an icosahedron.
pub fn projective_plane() -> CoveredSurface {
    let positions = super::basic::icosahedron_vertices()[..6].to_vec();
    surface(positions, &PROJECTIVE_PLANE_6)
}

/// The triangles of the 6-vertex projective plane.
pub const PROJECTIVE_PLANE_6: [[u32; 3]; 10] = [
    [0, 1, 2],
    [0, 1, 3],
    [0, 2, 4],
    [0, 3, 5],
    [0, 4, 5],
    [1, 2, 5],
    [1, 3, 4],
    [1, 4, 5],
    [2, 3, 4],
    [2, 3, 5],
];

/// A Klein bottle as an `m x n` grid (m, n at least 3): the tube's ends glued by a reflection,
/// `(m, j)` to `(0, n - 1 - j)`, placed on the figure-8 immersion, `2 m n` triangles.
///
/// # Panics
/// If `m < 3` or `n < 3`.
pub fn klein_bottle(m: u32, n: u32) -> CoveredSurface {
    assert!(m >= 3 && n >= 3, "klein bottle needs m, n >= 3");
    let mut positions = Vec::with_capacity((m * n) as usize);
    for i in 0..m {
        let theta = TAU * i as f64 / m as f64;
        let (c, s) = ((theta / 2.0).cos(), (theta / 2.0).sin());
        for j in 0..n {
            // Half a step off the figure-8's double circle (v = 0 and v = π meet there).
            let v = TAU * (j as f64 + 0.5) / n as f64;
            let r = 2.0 + c * v.sin() - s * (2.0 * v).sin();
            positions.push([
                r * theta.cos(),
                r * theta.sin(),
                s * v.sin() + c * (2.0 * v).sin(),
            ]);
        }
    }
    let id = |i: u32, j: u32| {
        if i == m {
            (2 * n - 1 - j % n) % n
        } else {
            i * n + j % n
        }
    };
    surface(positions, &grid(m, n, id))
}

/// The non-orientable surface N_k with `k >= 1` crosscaps: the 6-vertex projective plane for
/// k = 1, otherwise the connected sum of k copies of it ([`connected_sum`]): `3k + 3` vertices,
/// `8k + 2` triangles.
pub fn crosscaps(k: u32) -> CoveredSurface {
    let mut sum = projective_plane();
    for _ in 1..k.max(1) {
        sum = connected_sum(&sum, &projective_plane());
    }
    sum
}

/// The connected sum of two surfaces: the last triangle of `a` and the first of `b` are removed
/// and the two triangular holes glued (b's vertices of the glued triangle take a's positions;
/// the rest of b is moved beside a). The Euler characteristics add up minus 2; the sum is
/// orientable iff both are. A sum of simplicial surfaces is simplicial (the glued vertices are
/// joined only by the glued triangle's edges).
pub fn connected_sum(a: &CoveredSurface, b: &CoveredSurface) -> CoveredSurface {
    let (mut positions, mut triangles) = a.to_triangles();
    let (pb, tb) = b.to_triangles();
    let hole_a = triangles.pop().expect("a surface has a triangle");
    let hole_b = tb[0];
    let offset = bounding_width(&positions) * 1.5;
    let mut id = vec![u32::MAX; pb.len()];
    // b's triangle (x, y, z) is glued to a's (p, r, q): reversed, so that two orientable
    // summands keep consistent orientations.
    for (k, &v) in hole_b.iter().enumerate() {
        id[v as usize] = hole_a[[0, 2, 1][k]];
    }
    for (v, p) in pb.iter().enumerate() {
        if id[v] == u32::MAX {
            id[v] = positions.len() as u32;
            positions.push([p[0] + offset, p[1], p[2]]);
        }
    }
    triangles.extend(tb[1..].iter().map(|t| t.map(|v| id[v as usize])));
    surface(positions, &triangles)
}

/// The surface with `holes` holes cut: each removes the faces around a vertex chosen at random
/// (seeded) among the vertices whose neighbours are all interior and that are at least three
/// edges from every other hole's centre and from the boundary, so that each hole is a new
/// boundary loop (the link of its centre) and the rest stays a surface. Returns the surface and
/// the number of holes cut (fewer than asked when no more fit).
pub fn cut_holes(surface_in: &CoveredSurface, holes: usize, seed: u64) -> (CoveredSurface, usize) {
    let (positions, triangles) = surface_in.to_triangles();
    let nv = positions.len();
    // Vertex adjacency (sorted, deduplicated) and edge multiplicities from the soup.
    let mut edges: Vec<(u32, u32)> = triangles
        .iter()
        .flat_map(|t| (0..3).map(move |i| (t[i].min(t[(i + 1) % 3]), t[i].max(t[(i + 1) % 3]))))
        .collect();
    edges.sort_unstable();
    let mut boundary = vec![false; nv];
    let mut neighbours: Vec<Vec<u32>> = vec![Vec::new(); nv];
    for (k, &(a, b)) in edges.iter().enumerate() {
        let repeated = (k > 0 && edges[k - 1] == (a, b)) || edges.get(k + 1) == Some(&(a, b));
        if !repeated {
            boundary[a as usize] = true;
            boundary[b as usize] = true;
        }
        if k == 0 || edges[k - 1] != (a, b) {
            neighbours[a as usize].push(b);
            neighbours[b as usize].push(a);
        }
    }
    // Vertices within two edges of the boundary or of a chosen centre are blocked.
    let mut blocked = vec![0u8; nv];
    let block = |v: usize, blocked: &mut Vec<u8>| {
        blocked[v] = 1;
        for &w in &neighbours[v] {
            blocked[w as usize] = 1;
            for &z in &neighbours[w as usize] {
                blocked[z as usize] = 1;
            }
        }
    };
    for v in (0..nv).filter(|&v| boundary[v]) {
        block(v, &mut blocked);
    }
    let mut order: Vec<usize> = (0..nv).collect();
    order.shuffle(&mut ChaCha8Rng::seed_from_u64(seed));
    let mut removed = vec![false; nv];
    let mut cut = 0;
    for v in order {
        if cut == holes {
            break;
        }
        if blocked[v] == 0 {
            removed[v] = true;
            block(v, &mut blocked);
            cut += 1;
        }
    }
    let kept: Vec<[u32; 3]> = triangles
        .into_iter()
        .filter(|t| !t.iter().any(|&v| removed[v as usize]))
        .collect();
    (surface(positions, &kept), cut)
}

/// `count` copies of a surface side by side along x: a file of several components.
pub fn copies(surface_in: &CoveredSurface, count: u32) -> CoveredSurface {
    let (positions, triangles) = surface_in.to_triangles();
    let step = bounding_width(&positions) * 1.5;
    let nv = positions.len() as u32;
    let mut all_positions = Vec::with_capacity(positions.len() * count as usize);
    let mut all_triangles = Vec::with_capacity(triangles.len() * count as usize);
    for k in 0..count.max(1) {
        let dx = step * k as f64;
        all_positions.extend(positions.iter().map(|p| [p[0] + dx, p[1], p[2]]));
        all_triangles.extend(triangles.iter().map(|t| t.map(|v| v + k * nv)));
    }
    surface(all_positions, &all_triangles)
}

/// The extent of the positions along x (1 when empty or flat).
fn bounding_width(positions: &[Point3]) -> f64 {
    let (lo, hi) = positions
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p[0]), hi.max(p[0]))
        });
    if hi > lo { hi - lo } else { 1.0 }
}
