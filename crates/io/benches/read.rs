//! Read throughput (criterion, MB/s): grid torus of 1M and 4M triangles
//! written as OBJ and binary PLY to a temporary directory, read back with
//! `read_path`.

#[path = "support/torus.rs"]
mod torus;

use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use surftopo_io::{PlyEncoding, WriteOptions, read_path, write_path};

fn read_benches(c: &mut Criterion) {
    let dir = tempfile::tempdir().expect("temp dir");
    let mut group = c.benchmark_group("read");
    group.sample_size(10);
    group.warm_up_time(Duration::from_secs(1));
    group.measurement_time(Duration::from_secs(8));
    for (label, n, m) in torus::SIZES {
        let soup = torus::torus(n, m, Some(6));
        for ext in ["obj", "ply"] {
            let path = dir.path().join(format!("torus_{label}.{ext}"));
            let opts = WriteOptions::default().with_ply_encoding(PlyEncoding::BinaryLittleEndian);
            write_path(&path, &soup, &opts).expect("write");
            let bytes = std::fs::metadata(&path).expect("metadata").len();
            group.throughput(Throughput::Bytes(bytes));
            group.bench_function(format!("{ext}_{label}"), |b| {
                b.iter(|| read_path(&path).expect("read"));
            });
        }
    }
    group.finish();
}

criterion_group!(benches, read_benches);
criterion_main!(benches);
