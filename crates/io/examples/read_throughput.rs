//! Prints read (and write) throughput in MB/s for OBJ, OFF and binary PLY
//! at 1M and 4M triangles. Run with
//! `cargo run --release -p surftopo-io --example read_throughput`.

#[path = "../benches/support/torus.rs"]
mod torus;

use std::time::Instant;

use surftopo_io::{Format, PlyEncoding, WriteOptions, read_bytes, write};

fn best_of<T>(runs: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..runs {
        let t = Instant::now();
        let v = f();
        best = best.min(t.elapsed().as_secs_f64());
        last = Some(v);
    }
    (best, last.expect("at least one run"))
}

fn main() {
    let runs = 3;
    println!(
        "{:<6} {:<22} {:>10} {:>12} {:>12}",
        "size", "format", "MB", "read MB/s", "write MB/s"
    );
    for (label, n, m) in torus::SIZES {
        for (digits, tag) in [(Some(6), "6 decimals"), (None, "17 digits")] {
            let soup = torus::torus(n, m, digits);
            for (format, enc, name) in [
                (Format::Obj, PlyEncoding::Ascii, "obj"),
                (Format::Off, PlyEncoding::Ascii, "off"),
                (Format::Ply, PlyEncoding::BinaryLittleEndian, "ply binary"),
            ] {
                if format == Format::Ply && digits.is_none() {
                    continue; // binary: digits do not matter
                }
                let opts = WriteOptions::default().with_ply_encoding(enc);
                let (wt, bytes) = best_of(1, || {
                    let mut b = Vec::new();
                    write(&mut b, &soup, format, &opts).expect("write");
                    b
                });
                let (rt, back) = best_of(runs, || read_bytes(&bytes, format, name).expect("read"));
                assert_eq!(back.face_count(), soup.face_count());
                let mb = bytes.len() as f64 / 1e6;
                let fname = if format == Format::Ply {
                    name.to_string()
                } else {
                    format!("{name} ({tag})")
                };
                println!(
                    "{label:<6} {fname:<22} {mb:>10.1} {:>12.0} {:>12.0}",
                    mb / rt,
                    mb / wt
                );
            }
        }
    }
}
