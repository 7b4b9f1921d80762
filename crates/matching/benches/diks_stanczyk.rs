//! Criterion benchmark of the Diks–Stanczyk perfect matching on random bridgeless cubic
//! multigraphs (shuffled ids) and on torus duals (mesh order), 10³ to 10⁵ nodes.
//! `cargo bench -p surftopo-matching --bench diks_stanczyk`; the doubling series up to millions
//! of nodes is `examples/ds_doubling.rs`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use surftopo_matching::diks_stanczyk;
use surftopo_matching::generators::{random_bridgeless_cubic, torus_dual};

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("diks_stanczyk");
    group.sample_size(10);
    for n in [1_000u32, 10_000, 100_000] {
        let g = random_bridgeless_cubic(n, 1);
        group.bench_with_input(BenchmarkId::new("random", n), &g, |b, g| {
            b.iter(|| diks_stanczyk(black_box(g)))
        });
        let side = ((n / 2) as f64).sqrt().round() as u32;
        let t = torus_dual(side, (n / 2).div_ceil(side));
        group.bench_with_input(BenchmarkId::new("torus", t.node_count()), &t, |b, t| {
            b.iter(|| diks_stanczyk(black_box(t)))
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
