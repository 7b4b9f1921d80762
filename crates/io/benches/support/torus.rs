//! Triangulated grid torus used by the read benchmarks (shared with
//! `examples/read_throughput.rs` through `#[path]`).

use surftopo_io::PolygonSoup;

/// A torus of `2 * n * m` triangles; coordinates are rounded to `digits`
/// decimals (like typical mesh files) unless `digits` is `None`.
pub fn torus(n: u32, m: u32, digits: Option<i32>) -> PolygonSoup {
    let round = |x: f64| match digits {
        Some(d) => {
            let s = 10f64.powi(d);
            (x * s).round() / s
        }
        None => x,
    };
    let mut positions = Vec::with_capacity((n * m) as usize);
    for i in 0..n {
        for j in 0..m {
            let u = f64::from(i) / f64::from(n) * std::f64::consts::TAU;
            let v = f64::from(j) / f64::from(m) * std::f64::consts::TAU;
            let r = 3.0 + v.cos();
            positions.push([round(r * u.cos()), round(r * u.sin()), round(v.sin())]);
        }
    }
    let id = |i: u32, j: u32| (i % n) * m + (j % m);
    let mut tris = Vec::with_capacity(2 * (n * m) as usize);
    for i in 0..n {
        for j in 0..m {
            tris.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            tris.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    PolygonSoup::from_triangles(positions, &tris)
}

/// (label, n, m) for 1M and 4M triangles.
pub const SIZES: [(&str, u32, u32); 2] = [("1M", 1000, 500), ("4M", 2000, 1000)];
