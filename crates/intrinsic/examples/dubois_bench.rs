//! Dubois' ALGORITHM (Section 4.5, `surftopo_intrinsic::dubois::reduce`) in exact arithmetic on
//! Section 9's flat tori `T_x` (`x = 10, 10², …, 10¹⁸` and `3000000001/3`) and on the lattice
//! torus `⟨(1, 0), (10⁶, 1)⟩`: seconds, `N`, inner passes against `350·N`, triangles after the
//! reduction, bifaces marked inactive, peak active vertices, and the longest side of the output
//! (squared, as a double) — a reduced triangulation of `T_x` has sides of length O(1).
//!
//! ```text
//! cargo run --release -p surftopo-intrinsic --example dubois_bench -- [--out-dir DIR]
//! ```
//!
//! Results: `results/dubois_bench.jsonl` (one object per input) and `results/dubois_bench.md`
//! under `--out-dir` (default: the workspace root). Times are single runs of `reduce` and of
//! Theorem 1's whole pipeline (`delaunay_tessellation_flat`: `reduce`, then the wave from one
//! vertex), the input built beforehand.

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use serde_json::json;
use surftopo_intrinsic::Portalgon;
use surftopo_intrinsic::dubois::{
    FlatDelaunayOptions, ReduceOptions, delaunay_tessellation_flat, reduce,
};
use surftopo_intrinsic::geometry::{Rational, Scalar};

fn q(s: &str) -> Rational {
    s.parse().expect("a rational")
}

/// `R²/⟨u, v⟩` as the triangles `0, u, v` and `u + v, v, u`, side i glued to side i.
fn lattice_torus(u: [Rational; 2], v: [Rational; 2]) -> Portalgon<Rational> {
    let uv = [u[0].clone() + v[0].clone(), u[1].clone() + v[1].clone()];
    let mut p = Portalgon::<Rational>::empty();
    let a = p
        .add_polygon(&[[q("0"), q("0")], u.clone(), v.clone()])
        .expect("a triangle");
    let b = p.add_polygon(&[uv, v, u]).expect("a triangle");
    for i in 0..3 {
        p.glue(p.side(a, i), p.side(b, i), 0.0)
            .expect("equal sides");
    }
    p
}

fn main() {
    let mut out_dir = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out-dir" => out_dir = PathBuf::from(args.next().expect("--out-dir DIR")),
            other => panic!("unknown argument {other}"),
        }
    }
    let mut inputs: Vec<(String, Portalgon<Rational>)> = (1..=18)
        .map(|k| {
            let x = format!("1{}", "0".repeat(k));
            let t = lattice_torus([q("1"), q("0")], [q(&x), q("2")]);
            (format!("T_1e{k}"), t)
        })
        .collect();
    inputs.push((
        "T_3000000001/3".into(),
        lattice_torus([q("1"), q("0")], [q("3000000001/3"), q("2")]),
    ));
    inputs.push((
        "<(1,0),(1e6,1)>".into(),
        lattice_torus([q("1"), q("0")], [q("1000000"), q("1")]),
    ));
    let mut md = String::from(
        "| input | seconds | pipeline seconds (Theorem 1) | tessellation polygons | N | inner passes (total / 350·N) | triangles after | inactive bifaces | tubes replaced thin / thick | peak active vertices | longest side² |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let mut jsonl = String::new();
    for (name, t) in &inputs {
        let start = Instant::now();
        let r = reduce(t, &ReduceOptions::default()).expect("a flat torus");
        let seconds = start.elapsed().as_secs_f64();
        // Theorem 1's whole pipeline: the reduction, then the wave from one vertex.
        let start = Instant::now();
        let whole =
            delaunay_tessellation_flat(t, &FlatDelaunayOptions::default()).expect("a flat torus");
        let pipeline_seconds = start.elapsed().as_secs_f64();
        let tessellation_polygons = whole.delaunay.tessellation.polygon_count();
        let longest2 = r
            .portalgon
            .sides()
            .map(|s| r.portalgon.side_length2(s).to_f64())
            .fold(0.0, f64::max);
        let rep = &r.report;
        writeln!(
            md,
            "| {name} | {seconds:.4} | {pipeline_seconds:.4} | {tessellation_polygons} | {} | {} / {} | {} | {} | {} / {} | {} | {longest2} |",
            rep.outer_iterations,
            rep.inner_passes_total,
            rep.inner_passes_bound,
            rep.triangles_after_reduction,
            rep.bifaces_inactive,
            rep.tubes_replaced_thin,
            rep.tubes_replaced_thick,
            rep.peak_active_vertices,
        )
        .expect("write to a string");
        let line = json!({
            "input": name, "seconds": seconds, "pipeline_seconds": pipeline_seconds,
            "tessellation_polygons": tessellation_polygons, "outer_iterations": rep.outer_iterations,
            "inner_passes": rep.inner_passes, "inner_passes_total": rep.inner_passes_total,
            "inner_passes_bound": rep.inner_passes_bound,
            "triangles_after_reduction": rep.triangles_after_reduction,
            "bifaces_inactive": rep.bifaces_inactive,
            "tubes_replaced": {"thin": rep.tubes_replaced_thin, "thick": rep.tubes_replaced_thick},
            "peak_active_vertices": rep.peak_active_vertices,
            "longest_side2": longest2, "arithmetic": rep.arithmetic,
        });
        writeln!(jsonl, "{line}").expect("write to a string");
        eprintln!("{name}: {seconds:.4} s");
    }
    let command = "cargo run --release -p surftopo-intrinsic --example dubois_bench";
    let md = format!(
        "# Dubois' ALGORITHM (Section 4.5) on flat tori, exact arithmetic\n\nProduced by `{command}`.\n\n{md}"
    );
    print!("{md}");
    let results = out_dir.join("results");
    std::fs::create_dir_all(&results).expect("results directory");
    std::fs::File::create(results.join("dubois_bench.md"))
        .and_then(|mut f| f.write_all(md.as_bytes()))
        .expect("write dubois_bench.md");
    std::fs::File::create(results.join("dubois_bench.jsonl"))
        .and_then(|mut f| f.write_all(jsonl.as_bytes()))
        .expect("write dubois_bench.jsonl");
}
