//! Half-edge build time from a triangle soup (1M and 4M triangles, natural and shuffled vertex
//! order), one-ring traversal over all vertices, and generator throughput.
//!
//! `cargo bench -p surftopo-mesh --bench build` (about three minutes on 2 cores).

use criterion::{Criterion, criterion_group, criterion_main};
use rand::SeedableRng;
use rand::seq::SliceRandom;
use rand_chacha::ChaCha8Rng;
use std::hint::black_box;
use std::time::Duration;
use surftopo_mesh::generators::{cavity_box, random_flips, subdivide_midpoint, torus};
use surftopo_mesh::{SurfaceMesh, build};

/// A torus soup with about `triangles` triangles: `(vertex count, triangles)`.
fn torus_soup(triangles: usize) -> (usize, Vec<[u32; 3]>) {
    let side = ((triangles / 2) as f64).sqrt().round() as u32;
    let (positions, soup) = torus(side, side).to_triangles();
    (positions.len(), soup)
}

/// The same soup with vertex labels permuted at random (and, if `faces`, face order too).
fn shuffled(vertex_count: usize, soup: &[[u32; 3]], faces: bool) -> Vec<[u32; 3]> {
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let mut label: Vec<u32> = (0..vertex_count as u32).collect();
    label.shuffle(&mut rng);
    let mut out: Vec<[u32; 3]> = soup.iter().map(|t| t.map(|v| label[v as usize])).collect();
    if faces {
        out.shuffle(&mut rng);
    }
    out
}

/// Sum of the neighbour ids over every one-ring (all half-edges visited once).
fn one_ring_pass(mesh: &SurfaceMesh) -> u64 {
    mesh.vertices()
        .map(|v| mesh.neighbors(v).map(|w| u64::from(w.0)).sum::<u64>())
        .sum()
}

fn bench_build(c: &mut Criterion) {
    let mut group = c.benchmark_group("build");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(8));
    for (name, size) in [("1M", 1_000_000), ("4M", 4_000_000)] {
        let (nv, soup) = torus_soup(size);
        group.bench_function(format!("torus_{name}"), |b| {
            b.iter_with_large_drop(|| build(nv, black_box(&soup)).unwrap())
        });
        let vertices_shuffled = shuffled(nv, &soup, false);
        group.bench_function(format!("torus_{name}_shuffled_vertices"), |b| {
            b.iter_with_large_drop(|| build(nv, black_box(&vertices_shuffled)).unwrap())
        });
        if size == 4_000_000 {
            let all_shuffled = shuffled(nv, &soup, true);
            group.bench_function(format!("torus_{name}_shuffled_vertices_and_faces"), |b| {
                b.iter_with_large_drop(|| build(nv, black_box(&all_shuffled)).unwrap())
            });
        }
    }
    group.finish();
}

fn bench_one_ring(c: &mut Criterion) {
    let mut group = c.benchmark_group("one_ring");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(4));
    let (nv, soup) = torus_soup(4_000_000);
    let (natural, _) = build(nv, &soup).unwrap();
    group.bench_function("torus_4M", |b| {
        b.iter(|| one_ring_pass(black_box(&natural)))
    });
    let (scrambled, _) = build(nv, &shuffled(nv, &soup, true)).unwrap();
    group.bench_function("torus_4M_shuffled", |b| {
        b.iter(|| one_ring_pass(black_box(&scrambled)))
    });
    group.finish();
}

fn bench_generators(c: &mut Criterion) {
    let mut group = c.benchmark_group("generate");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(8));
    group.bench_function("cavity_box_3844_pits_4.2M", |b| {
        b.iter_with_large_drop(|| cavity_box(black_box(344), 3500, 4_222_296))
    });
    let base = torus(354, 354);
    group.bench_function("subdivide_midpoint_2_levels_250k_to_4M", |b| {
        b.iter_with_large_drop(|| subdivide_midpoint(black_box(&base), 2))
    });
    let big = torus(707, 707);
    group.bench_function("random_flips_1M_on_1M_triangles", |b| {
        b.iter_with_large_drop(|| random_flips(black_box(&big), 1_000_000, 3))
    });
    group.finish();
}

criterion_group!(benches, bench_build, bench_one_ring, bench_generators);
criterion_main!(benches);
