//! The cotan Laplacian against an independent planar Delaunay triangulation (spade) of a
//! periodic point set, and its structural properties with loops and multi-edges.

mod common;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use spade::{DelaunayTriangulation, HasPosition, Point2, Triangulation};
use std::collections::HashMap;
use surftopo_intrinsic::generators::{flat_torus, random_flips};
use surftopo_intrinsic::{
    DelaunayOptions, IntrinsicTriangulation, MatrixStorage, SparseMatrix, cotan_laplacian,
    cotan_weights, flip_to_delaunay, lumped_mass, read_matrix_market, write_matrix_market,
};
use surftopo_mesh::{Side, SurfaceMesh};

/// A jittered `m × m` periodic point set on the unit square torus, its grid triangulation built
/// by gluing (two triangles per cell, like T_x), lengths from the periodic coordinates. Returns the
/// triangulation, the points, and the vertex id of each point.
fn jittered_torus(m: u32, seed: u64) -> (IntrinsicTriangulation, Vec<[f64; 2]>, Vec<u32>) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mf = f64::from(m);
    let points: Vec<[f64; 2]> = (0..m * m)
        .map(|k| {
            let (i, j) = (f64::from(k % m), f64::from(k / m));
            [
                (i + rng.random_range(-0.1..0.1)) / mf,
                (j + rng.random_range(-0.1..0.1)) / mf,
            ]
        })
        .collect();
    // Corner (i, j) of the infinite grid: its point, shifted by the lattice.
    let at = |i: u32, j: u32| {
        let p = points[((j % m) * m + (i % m)) as usize];
        [p[0] + f64::from(i / m), p[1] + f64::from(j / m)]
    };
    let cell = |i: u32, j: u32| (j % m) * m + (i % m);
    let mut tris: Vec<[(u32, u32); 3]> = Vec::new();
    for j in 0..m {
        for i in 0..m {
            tris.push([(i, j), (i + 1, j), (i, j + 1)]);
            tris.push([(i + 1, j), (i + 1, j + 1), (i, j + 1)]);
        }
    }
    let side = |face: u32, side: u8| Side { face, side };
    let mut pairs = Vec::new();
    for j in 0..m {
        for i in 0..m {
            let c = cell(i, j);
            pairs.push((side(2 * c, 0), side(2 * cell(i, j + m - 1) + 1, 1)));
            pairs.push((side(2 * c, 1), side(2 * c + 1, 2)));
            pairs.push((side(2 * c, 2), side(2 * cell(i + m - 1, j) + 1, 0)));
        }
    }
    let (mesh, corner_vertex) = SurfaceMesh::from_gluing(tris.len(), &pairs).unwrap();
    let side_length = |s: Side| {
        let t = tris[s.face as usize];
        let (a, b) = (t[s.side as usize], t[(s.side as usize + 1) % 3]);
        let (p, q) = (at(a.0, a.1), at(b.0, b.1));
        (p[0] - q[0]).hypot(p[1] - q[1])
    };
    let lengths = pairs.iter().map(|&(s, _)| side_length(s)).collect();
    let mut vertex_of = vec![0u32; (m * m) as usize];
    for (f, t) in tris.iter().enumerate() {
        for (i, &(x, y)) in t.iter().enumerate() {
            vertex_of[cell(x, y) as usize] = corner_vertex[3 * f + i].0;
        }
    }
    let tri = IntrinsicTriangulation::from_parts(mesh, lengths).unwrap();
    (tri, points, vertex_of)
}

struct Site {
    p: Point2<f64>,
    id: usize,
    central: bool,
}
impl HasPosition for Site {
    type Scalar = f64;
    fn position(&self) -> Point2<f64> {
        self.p
    }
}

/// The Laplacian of the periodic Delaunay triangulation, from spade's planar Delaunay
/// triangulation of the 3 × 3 tiling: entries of the central tile's vertices.
fn spade_laplacian(points: &[[f64; 2]]) -> HashMap<(usize, usize), f64> {
    let mut sites = Vec::new();
    for dx in -1..=1 {
        for dy in -1..=1 {
            for (id, p) in points.iter().enumerate() {
                sites.push(Site {
                    p: Point2::new(p[0] + f64::from(dx), p[1] + f64::from(dy)),
                    id,
                    central: dx == 0 && dy == 0,
                });
            }
        }
    }
    let dt = DelaunayTriangulation::<Site>::bulk_load(sites).unwrap();
    let mut l: HashMap<(usize, usize), f64> = HashMap::new();
    for face in dt.inner_faces() {
        let v = face.vertices();
        for k in 0..3 {
            let (c, a, b) = (v[k].data(), v[(k + 1) % 3].data(), v[(k + 2) % 3].data());
            let (u, w) = (
                [a.p.x - c.p.x, a.p.y - c.p.y],
                [b.p.x - c.p.x, b.p.y - c.p.y],
            );
            let cot = (u[0] * w[0] + u[1] * w[1]) / (u[0] * w[1] - u[1] * w[0]).abs();
            for (x, y) in [(a, b), (b, a)] {
                if x.central {
                    *l.entry((x.id, y.id)).or_default() -= 0.5 * cot;
                    *l.entry((x.id, x.id)).or_default() += 0.5 * cot;
                }
            }
        }
    }
    l
}

fn check_structure(l: &SparseMatrix) {
    for i in 0..l.n {
        let sum: f64 = l.row(i).map(|(_, v)| v).sum();
        let scale: f64 = l.row(i).map(|(_, v)| v.abs()).sum::<f64>().max(1e-300);
        assert!(sum.abs() <= 1e-12 * scale, "row {i} sums to {sum}");
        for (j, v) in l.row(i) {
            let t = l.get(j as usize, i);
            assert!(
                (v - t).abs() <= 1e-14 * v.abs().max(1.0),
                "L[{i}][{j}] = {v} vs {t}"
            );
        }
    }
}

#[test]
fn flat_torus_laplacian_matches_spade_delaunay() {
    for (m, seed) in [(2, 1), (3, 2), (8, 3), (15, 4)] {
        let (mut tri, points, vertex_of) = jittered_torus(m, seed);
        random_flips(&mut tri, 3 * u64::from(m * m), seed);
        flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
        common::check_delaunay(&tri, 1e-9).unwrap();
        let ours = cotan_laplacian(&tri);
        check_structure(&ours);
        let theirs = spade_laplacian(&points);
        let scale = theirs.values().fold(0.0f64, |a, v| a.max(v.abs()));
        let n = points.len();
        let mut checked = 0;
        for i in 0..n {
            for j in 0..n {
                let want = theirs.get(&(i, j)).copied().unwrap_or(0.0);
                let got = ours.get(vertex_of[i] as usize, vertex_of[j] as usize);
                assert!(
                    (got - want).abs() <= 1e-9 * scale,
                    "m = {m}: L[{i}][{j}] = {got}, spade says {want}"
                );
                checked += usize::from(want != 0.0);
            }
        }
        assert!(checked >= n * 4, "too few entries compared");
    }
}

#[test]
fn loops_contribute_nothing_and_multi_edges_add_up() {
    // T_x (one vertex, three loops): L = [0]; mass = total area.
    let mut tri = flat_torus(4.0, 1).unwrap();
    flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
    let l = cotan_laplacian(&tri);
    assert_eq!((l.n, l.nnz(), l.get(0, 0)), (1, 1, 0.0));
    let mass = lumped_mass(&tri);
    assert!((mass.get(0, 0) - 2.0).abs() < 1e-12);
    // The 2 x 2 refinement has multi-edges: each row still sums to zero, the matrix is symmetric,
    // and each off-diagonal entry is minus the sum of the weights of the edges joining the pair.
    let mut tri = flat_torus(2.5, 2).unwrap();
    flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
    let l = cotan_laplacian(&tri);
    check_structure(&l);
    let w = cotan_weights(&tri);
    let mesh = tri.mesh();
    let mut pair_sum: HashMap<(u32, u32), f64> = HashMap::new();
    let mut multi = false;
    for e in mesh.edges() {
        let [a, b] = mesh.edge_vertices(e);
        if a != b {
            let key = (a.0.min(b.0), a.0.max(b.0));
            multi |= pair_sum.contains_key(&key);
            *pair_sum.entry(key).or_default() += w[e.idx()];
        }
    }
    assert!(multi, "expected multi-edges on the 2 x 2 torus");
    for (&(a, b), &s) in &pair_sum {
        assert!((l.get(a as usize, b as usize) + s).abs() < 1e-12);
    }
    let trace: f64 = (0..4).map(|i| lumped_mass(&tri).get(i, i)).sum();
    assert!((trace - common::area(&tri)).abs() < 1e-12);
}

#[test]
fn matrix_market_files_read_back_identically() {
    let (mut tri, _, _) = jittered_torus(5, 9);
    flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
    for m in [cotan_laplacian(&tri), lumped_mass(&tri)] {
        assert!(m.is_symmetric());
        for storage in [MatrixStorage::General, MatrixStorage::Symmetric] {
            let mut bytes = Vec::new();
            write_matrix_market(&mut bytes, &m, "surftopo test", storage).unwrap();
            assert_eq!(read_matrix_market(&bytes[..]).unwrap(), m);
        }
    }
}
