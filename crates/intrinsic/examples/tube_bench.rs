//! Proposition 4 (Dubois, Appendix B) on random tubes: seconds for both routes
//! ([`TubeRoute::Direct`], docs/dubois.md §3.1(c), and [`TubeRoute::Paper`], Lemmas 28, 25, 26), in
//! f64 and exact arithmetic, against the number of triangles (10² to 10⁵) and against the aspect
//! ratio (translation tubes sheared further and further: the shortest offset, a lower bound on the
//! happiness, grows with the shear).
//!
//! ```text
//! cargo run --release -p surftopo-intrinsic --example tube_bench -- \
//!     [--out-dir DIR] [--max-triangles N] [--repeat N]
//! ```
//!
//! Results: `results/tube_bench.jsonl` (one object per run) and `results/tube_bench.md`, under
//! `--out-dir` (default: the workspace root). Times are the best of `--repeat` (default 3) runs of
//! [`Portalgon::good_biface_of_tube`] alone (the tube is built once, by the tests' generator); the
//! two routes' bifaces are compared (squared interior lengths) and a disagreement is reported in
//! the table.

#[path = "../tests/common_tubes/mod.rs"]
mod common_tubes;

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use common_tubes::random_tube_skewed;
use serde_json::json;
use surftopo_intrinsic::geometry::{Rational, Scalar};
use surftopo_intrinsic::{GoodBiface, Portalgon, TubeReport, TubeRoute};

struct Args {
    out_dir: PathBuf,
    max_triangles: usize,
    repeat: usize,
}

fn parse_args() -> Args {
    let mut args = Args {
        out_dir: PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../..")),
        max_triangles: 100_000,
        repeat: 3,
    };
    let mut it = std::env::args().skip(1);
    while let Some(flag) = it.next() {
        let mut value = || it.next().unwrap_or_else(|| panic!("{flag} needs a value"));
        match flag.as_str() {
            "--out-dir" => args.out_dir = PathBuf::from(value()),
            "--max-triangles" => args.max_triangles = value().parse().expect("--max-triangles N"),
            "--repeat" => args.repeat = value().parse::<usize>().expect("--repeat N").max(1),
            other => panic!("unknown option {other}"),
        }
    }
    args
}

struct Run {
    seconds: f64,
    good: GoodBiface<f64>,
    report: TubeReport,
}

fn run<S: Scalar>(p: &Portalgon<S>, route: TubeRoute, repeat: usize) -> Run {
    let polygons: Vec<_> = p.polygons().collect();
    let tolerance = if S::EXACT { 0.0 } else { 1e-9 };
    let mut best = f64::INFINITY;
    let mut out = None;
    for _ in 0..repeat {
        let start = Instant::now();
        let result = p.good_biface_of_tube(&polygons, route, tolerance);
        best = best.min(start.elapsed().as_secs_f64());
        out = Some(result.expect("Proposition 4"));
    }
    let (good, report) = out.expect("at least one run");
    let to = |x: &[S; 2]| [x[0].to_f64(), x[1].to_f64()];
    let b = &good.biface;
    let good = GoodBiface {
        biface: surftopo_intrinsic::Biface::new(to(b.a()), to(b.d()), to(b.b()), to(b.c()), 1e-6)
            .expect("a biface"),
        rung_offset: good.rung_offset.to_f64(),
        shortest_offset: good.shortest_offset.to_f64(),
        shortest_length2: good.shortest_length2.to_f64(),
        unchanged: good.unchanged,
    };
    Run {
        seconds: best,
        good,
        report,
    }
}

fn main() {
    let args = parse_args();
    let command = format!(
        "cargo run --release -p surftopo-intrinsic --example tube_bench --{}",
        std::env::args()
            .skip(1)
            .map(|a| format!(" {a}"))
            .collect::<String>()
    );
    let mut rows = Vec::new();
    let mut table = String::new();
    let header = "| kind | gluing | triangles | skew | m* | arithmetic | direct ms | paper ms | paper/direct | Lemma 28 rounds | deleted | bifaces | routes agree |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    let mut cases: Vec<(&str, bool, usize, Option<i64>)> = Vec::new();
    for n in [100, 1_000, 10_000, 100_000] {
        if n <= args.max_triangles {
            cases.push(("size", false, n, Some(40)));
            cases.push(("size", true, n, None));
        }
    }
    for skew in [1, 10, 100, 1_000, 10_000, 100_000] {
        cases.push(("aspect", false, 1_000.min(args.max_triangles), Some(skew)));
    }
    for (kind, rotation, n, skew) in cases {
        // About two triangles per interior point.
        let inner = n / 2;
        let rung = 4;
        let exact: common_tubes::RandomTube<Rational> =
            random_tube_skewed(7, rotation, rung, inner, skew);
        let rounded: common_tubes::RandomTube<f64> =
            random_tube_skewed(7, rotation, rung, inner, skew);
        let triangles = exact.portalgon.polygon_count();
        for arithmetic in ["f64", "exact"] {
            let (direct, paper) = if arithmetic == "f64" {
                (
                    run(&rounded.portalgon, TubeRoute::Direct, args.repeat),
                    run(&rounded.portalgon, TubeRoute::Paper, args.repeat),
                )
            } else {
                (
                    run(&exact.portalgon, TubeRoute::Direct, args.repeat),
                    run(&exact.portalgon, TubeRoute::Paper, args.repeat),
                )
            };
            let (x, y) = (
                direct.good.biface.interior_lengths2(),
                paper.good.biface.interior_lengths2(),
            );
            let agree = (0..2).all(|i| (x[i] - y[i]).abs() <= 1e-9 * x[i].max(y[i]));
            let row = json!({
                "kind": kind,
                "gluing": if rotation { "rotation" } else { "translation" },
                "triangles": triangles,
                "skew": skew,
                "shortest_offset": direct.good.shortest_offset,
                "arithmetic": arithmetic,
                "direct_s": direct.seconds,
                "paper_s": paper.seconds,
                "lemma28_rounds": paper.report.deletion_rounds,
                "deleted_vertices": paper.report.deleted_vertices,
                "bifaces": paper.report.bifaces,
                "routes_agree": agree,
            });
            eprintln!("{row}");
            writeln!(
                table,
                "| {kind} | {} | {triangles} | {} | {} | {arithmetic} | {:.3} | {:.3} | {:.1} | {} | {} | {} | {} |",
                if rotation { "rotation" } else { "translation" },
                skew.map_or("-".to_string(), |s| s.to_string()),
                direct.good.shortest_offset,
                direct.seconds * 1e3,
                paper.seconds * 1e3,
                paper.seconds / direct.seconds,
                paper.report.deletion_rounds,
                paper.report.deleted_vertices,
                paper.report.bifaces,
                if agree { "yes" } else { "no" },
            )
            .unwrap();
            rows.push(row);
        }
    }
    let results = args.out_dir.join("results");
    std::fs::create_dir_all(&results).expect("results directory");
    let mut jsonl = std::fs::File::create(results.join("tube_bench.jsonl")).expect("jsonl");
    for row in &rows {
        writeln!(jsonl, "{row}").unwrap();
    }
    let md = format!(
        "# Proposition 4 on random tubes\n\nCommand: `{command}`\n\nBest of {} runs of `good_biface_of_tube` per cell, one process, side by side. \
         `size`: translation tubes (skew 40) and rotation tubes of growing size; `aspect`: translation tubes of about 1,000 triangles sheared further (m* is the shortest offset, \
         a lower bound on the happiness). `m*` is relative to the generator's rung.\n\n{header}{table}",
        args.repeat
    );
    std::fs::write(results.join("tube_bench.md"), md).expect("markdown");
    println!("{}", results.join("tube_bench.md").display());
}
