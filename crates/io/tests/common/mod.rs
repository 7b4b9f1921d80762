//! Helpers shared by the integration tests.
#![allow(dead_code)]

use surftopo_io::PolygonSoup;

/// Asserts equal face lists and bit-identical positions.
pub fn assert_same(a: &PolygonSoup, b: &PolygonSoup) {
    assert_eq!(a.positions.len(), b.positions.len(), "vertex count");
    for (i, (p, q)) in a.positions.iter().zip(&b.positions).enumerate() {
        let pb = p.map(f64::to_bits);
        let qb = q.map(f64::to_bits);
        assert_eq!(pb, qb, "vertex {i}: {p:?} vs {q:?}");
    }
    assert_eq!(a.face_offsets, b.face_offsets, "face offsets");
    assert_eq!(a.face_indices, b.face_indices, "face indices");
}

/// A closed cube made of 6 quads.
pub fn cube_quads() -> PolygonSoup {
    let (corners, faces) = surftopo_testkit::unit_cube();
    let mut s = PolygonSoup::new();
    for p in corners {
        s.push_vertex(p);
    }
    for f in faces {
        s.push_face(&f);
    }
    s
}

/// An octahedron (8 triangles) with awkward coordinates.
pub fn octahedron() -> PolygonSoup {
    let p = vec![
        [0.1, -0.0, 1e-300],
        [-1.0 / 3.0, 5e-324, 2.5],
        [1e308, -1e308, 0.0],
        [f64::MIN_POSITIVE, f64::EPSILON, -7.0],
        [123_456_789.123_456_79, -0.000001, 3.0e-7],
        [f64::MAX, f64::MIN, 1.0],
    ];
    PolygonSoup::from_triangles(
        p,
        &[
            [0, 1, 2],
            [0, 2, 3],
            [0, 3, 4],
            [0, 4, 1],
            [5, 2, 1],
            [5, 3, 2],
            [5, 4, 3],
            [5, 1, 4],
        ],
    )
}

/// Triangles, quads, a pentagon and a 300-gon (forces wide PLY counts).
pub fn mixed() -> PolygonSoup {
    let mut s = PolygonSoup::new();
    for i in 0..300 {
        let a = f64::from(i) * 0.021;
        s.push_vertex([a.cos(), a.sin(), a * 1e-3]);
    }
    s.push_face(&[0, 1, 2]);
    s.push_face(&[3, 4, 5, 6]);
    s.push_face(&[7, 8, 9, 10, 11]);
    let big: Vec<u32> = (0..300).rev().collect();
    s.push_face(&big);
    s.push_face(&[299, 0, 150]);
    s
}

/// Triangulated grid torus with `n * m * 2` triangles.
pub fn torus(n: u32, m: u32) -> PolygonSoup {
    let mut pos = Vec::with_capacity((n * m) as usize);
    for i in 0..n {
        for j in 0..m {
            let u = f64::from(i) / f64::from(n) * std::f64::consts::TAU;
            let v = f64::from(j) / f64::from(m) * std::f64::consts::TAU;
            let r = 3.0 + v.cos();
            pos.push([r * u.cos(), r * u.sin(), v.sin()]);
        }
    }
    let id = |i: u32, j: u32| (i % n) * m + (j % m);
    let mut tris = Vec::with_capacity((2 * n * m) as usize);
    for i in 0..n {
        for j in 0..m {
            tris.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            tris.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    PolygonSoup::from_triangles(pos, &tris)
}
