//! Quality-aware pairings side by side: the exact minimum-cost perfect matching of
//! `surftopo_matching::weighted` (cost `1 − η` per quad, Remacle et al.'s quality, see
//! `surftopo_quad::quality`) against LEMON 1.3's `MaxWeightedPerfectMatching` on the same
//! integer costs, and the quality table of KS, LRS, the exact optimum and the fast mode.
//!
//! ```text
//! make -C crates/quad/peer
//! SURFTOPO_MESHES=../shared/meshes cargo run --release -p surftopo-quad --example quality_tables -- \
//!     [--lemon crates/quad/peer/lemon_matching] [--rounds R] [--min-triangles N] \
//!     [--max-triangles N] [--no-shared] [--no-generated] [--only NAME]... [--out results/quality]
//! ```
//! Per input: every exact result is checked by the certificate verifier, and LEMON's optimum
//! must equal it exactly (it runs on the same integers, as weights `10⁹ − cost`; the relative
//! difference is recorded). `--rounds` rounds alternate three exact calls and three LEMON `run()`s
//! (in its harness, graph construction excluded), the fastest of each kept, and record the ratio
//! of each round, so that a slow spell of the shared machine hits both. KS, LRS and the fast mode
//! run once per input for the quality table. Inputs: the shared meshes of `--min-triangles` to
//! `--max-triangles` (default 40k–400k) and generated ones of any size up to `--max-triangles`
//! (icospheres, a refined genus-45 surface with random flips, the paper's cavity brick of genus
//! 3,500, shared meshes refined by midpoint subdivision and shuffled). Writes `<out>.jsonl` and
//! `<out>.md`, whose first line repeats the arguments (`--out` left out).

mod support;

use std::collections::BTreeMap;
use std::error::Error;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use support::{Results, export_dual, lemon_weighted, thread_cpu_seconds};
use surftopo_matching::weighted::{
    fast_min_cost_perfect_matching, min_cost_perfect_matching, verify_min_cost_perfect_matching,
};
use surftopo_mesh::EdgeId;
use surftopo_mesh::Surface;
use surftopo_mesh::generators::{
    cavity_box, genus_surface, icosphere, random_flips, shuffle_faces, subdivide_midpoint,
};
use surftopo_quad::quality::COST_RESOLUTION;
use surftopo_quad::{QuadAlgorithm, QualityReport, pair_costs, quadrangulate, quality_report};

/// Exact calls (and LEMON `run()`s) per round, the fastest kept.
const ROUND_CALLS: usize = 3;

/// The command line (see the module doc).
struct Args {
    /// Where the results go, and the command line.
    results: Results,
    /// The LEMON harness, if given.
    lemon: Option<PathBuf>,
    /// Rounds of exact calls and LEMON runs.
    rounds: usize,
    /// Shared meshes from this many triangles...
    min_triangles: usize,
    /// ... up to this many (generated inputs too).
    max_triangles: usize,
    /// Whether the shared meshes and the generated inputs are measured.
    shared: bool,
    /// See `shared`.
    generated: bool,
    /// Only the inputs whose name contains one of these.
    only: Vec<String>,
}

fn parse_args() -> Result<Args, Box<dyn Error>> {
    let (results, given) = Results::from_args("quality")?;
    let mut args = Args {
        results,
        lemon: None,
        rounds: 2,
        min_triangles: 40_000,
        max_triangles: 400_000,
        shared: true,
        generated: true,
        only: Vec::new(),
    };
    let mut it = given.into_iter();
    while let Some(flag) = it.next() {
        let mut value = || it.next().ok_or(format!("{flag} needs a value"));
        match flag.as_str() {
            "--lemon" => args.lemon = Some(PathBuf::from(value()?)),
            "--rounds" => args.rounds = value()?.parse::<usize>()?.max(1),
            "--min-triangles" => args.min_triangles = value()?.parse()?,
            "--max-triangles" => args.max_triangles = value()?.parse()?,
            "--no-shared" => args.shared = false,
            "--no-generated" => args.generated = false,
            "--only" => args.only.push(value()?),
            other => return Err(format!("unknown argument {other}").into()),
        }
    }
    Ok(args)
}

type Make = Box<dyn Fn() -> Surface>;

fn inputs(args: &Args) -> Vec<(String, &'static str, Make)> {
    let mut out: Vec<(String, &'static str, Make)> = Vec::new();
    if args.shared {
        for shared in surftopo_testkit::shared_meshes() {
            if (args.min_triangles..=args.max_triangles).contains(&shared.faces) {
                let name = shared.file.trim_end_matches(".gz").to_string();
                out.push((
                    name,
                    "shared",
                    Box::new(move || surftopo_testkit::load(&shared)),
                ));
            }
        }
    }
    if args.generated {
        let mut generated: Vec<(String, usize, Make)> = vec![
            ("icosphere(6)".into(), 20 << 12, Box::new(|| icosphere(6))),
            ("icosphere(7)".into(), 20 << 14, Box::new(|| icosphere(7))),
            (
                "icosphere(7) shuffled".into(),
                20 << 14,
                Box::new(|| shuffle_faces(&icosphere(7), 1)),
            ),
            ("icosphere(8)".into(), 20 << 16, Box::new(|| icosphere(8))),
            (
                "genus45 flipped, subdivided".into(),
                4 * 26_880,
                Box::new(|| {
                    let g = genus_surface(45, 4);
                    let flips = g.mesh.edge_count() / 2;
                    subdivide_midpoint(&random_flips(&g, flips, 3), 1)
                }),
            ),
            (
                "B5 (cavity brick, genus 3500)".into(),
                360_736,
                Box::new(|| cavity_box(344, 3500, 360_736)),
            ),
        ];
        for (file, faces) in [
            ("feline.off.gz", 99_732usize),
            ("venus_50k.off.gz", 100_000),
        ] {
            let found = surftopo_testkit::shared_meshes()
                .into_iter()
                .find(|m| m.file == file);
            if let Some(mesh) = found {
                let name = file.trim_end_matches(".off.gz");
                let again = mesh.clone();
                generated.push((
                    format!("{name} subdivided"),
                    4 * faces,
                    Box::new(move || subdivide_midpoint(&surftopo_testkit::load(&mesh), 1)),
                ));
                generated.push((
                    format!("{name} subdivided twice, shuffled"),
                    16 * faces,
                    Box::new(move || {
                        let s = subdivide_midpoint(&surftopo_testkit::load(&again), 2);
                        shuffle_faces(&s, 1)
                    }),
                ));
            }
        }
        for (name, faces, make) in generated {
            if faces <= args.max_triangles {
                out.push((name, "generated", make));
            }
        }
    }
    if !args.only.is_empty() {
        out.retain(|(name, _, _)| args.only.iter().any(|o| name.contains(o.as_str())));
    }
    out
}

/// One line of the results file.
#[derive(Clone, Debug, Default, serde::Serialize)]
struct Record {
    input: String,
    kind: String,
    faces: usize,
    genus: i64,
    /// Exact solver: fastest call (seconds) and its phases.
    exact_seconds: f64,
    /// Thread CPU seconds of the fastest call (robust to a loaded machine).
    exact_cpu_seconds: f64,
    exact_greedy_seconds: f64,
    exact_search_seconds: f64,
    exact_exposed_after_greedy: usize,
    exact_exposed_after_fractional: usize,
    exact_blossoms: usize,
    exact_shrinks: u64,
    exact_expands: u64,
    /// The optimum in integer units (10⁹ per unit of cost) and in cost units.
    exact_cost_units: i64,
    exact_cost: f64,
    certificate_verified: bool,
    verify_seconds: f64,
    /// LEMON's fastest `run()`, its CPU seconds, its optimum in the same units.
    lemon_seconds: Option<f64>,
    lemon_cpu_seconds: Option<f64>,
    lemon_cost_units: Option<i64>,
    lemon_relative_difference: Option<f64>,
    /// Exact / LEMON time, fastest of each, and per round.
    exact_to_lemon: Option<f64>,
    exact_to_lemon_rounds: Vec<f64>,
    /// The same ratio on thread CPU seconds (LEMON's: the mean over its calls of a round).
    exact_to_lemon_cpu_rounds: Vec<f64>,
    fast_seconds: f64,
    fast_cost_units: i64,
    /// (fast − exact) / exact.
    fast_gap: f64,
    fast_exchanges: u64,
    ks_seconds: f64,
    lrs_seconds: Option<f64>,
    /// Quality reports of `ks`, `lrs`, `exact`, `fast`.
    quality: BTreeMap<String, QualityReport>,
}

fn diagonals(edges: &[u32]) -> Vec<EdgeId> {
    edges.iter().map(|&e| EdgeId(e)).collect()
}

fn measure(
    name: &str,
    kind: &str,
    surface: &Surface,
    args: &Args,
) -> Result<Record, Box<dyn Error>> {
    let mesh = &surface.mesh;
    let positions = &surface.positions;
    let costs = pair_costs(mesh, positions);
    let mut record = Record {
        input: name.into(),
        kind: kind.into(),
        faces: mesh.face_count(),
        genus: mesh.genus(),
        exact_seconds: f64::INFINITY,
        exact_cpu_seconds: f64::INFINITY,
        ..Record::default()
    };
    let exported = match &args.lemon {
        Some(_) => {
            let full = COST_RESOLUTION as i64;
            let weights: Vec<i64> = costs.iter().map(|c| full - c).collect();
            Some(export_dual(surface, Some(&weights), "wdual")?)
        }
        None => None,
    };
    let mut lemon_best = f64::INFINITY;
    let mut exact = None;
    for _ in 0..args.rounds {
        let mut round_best = f64::INFINITY;
        let mut round_cpu = f64::INFINITY;
        for _ in 0..ROUND_CALLS {
            let start = Instant::now();
            let cpu_start = thread_cpu_seconds();
            let result = min_cost_perfect_matching(mesh, &costs)?;
            let seconds = start.elapsed().as_secs_f64();
            round_cpu = round_cpu.min(thread_cpu_seconds() - cpu_start);
            record.exact_cpu_seconds = record.exact_cpu_seconds.min(round_cpu);
            round_best = round_best.min(seconds);
            if seconds <= record.exact_seconds {
                record.exact_seconds = seconds;
                record.exact_greedy_seconds = result.stats.greedy_seconds;
                record.exact_search_seconds = result.stats.search_seconds;
            }
            exact = Some(result);
        }
        if let (Some(binary), Some(path)) = (&args.lemon, &exported) {
            let (run, cpu, cost) = lemon_weighted(binary, path, mesh.face_count(), ROUND_CALLS)?;
            record.exact_to_lemon_rounds.push(round_best / run);
            record.exact_to_lemon_cpu_rounds.push(round_cpu / cpu);
            if run < lemon_best {
                lemon_best = run;
            }
            let best_cpu = record.lemon_cpu_seconds.map_or(cpu, |c: f64| c.min(cpu));
            record.lemon_cpu_seconds = Some(best_cpu);
            record.lemon_cost_units = Some(cost);
        }
    }
    if let Some(path) = exported {
        std::fs::remove_file(path)?;
    }
    let exact = exact.ok_or("no rounds")?;
    let start = Instant::now();
    let verified =
        verify_min_cost_perfect_matching(mesh, &costs, &exact.edges, &exact.certificate)?;
    record.verify_seconds = start.elapsed().as_secs_f64();
    record.certificate_verified = verified == exact.cost;
    record.exact_cost_units = exact.cost;
    record.exact_cost = exact.cost as f64 / COST_RESOLUTION;
    record.exact_exposed_after_greedy = exact.stats.exposed_after_greedy;
    record.exact_exposed_after_fractional = exact.stats.exposed_after_fractional;
    record.exact_blossoms = exact.stats.blossoms;
    record.exact_shrinks = exact.stats.shrinks;
    record.exact_expands = exact.stats.expands;
    if let Some(cost) = record.lemon_cost_units {
        record.lemon_seconds = Some(lemon_best);
        record.exact_to_lemon = Some(record.exact_seconds / lemon_best);
        let difference = (cost - exact.cost).abs() as f64 / (exact.cost.max(1) as f64);
        record.lemon_relative_difference = Some(difference);
        if difference > 1e-9 {
            return Err(
                format!("{name}: LEMON's optimum {cost} differs from {}", exact.cost).into(),
            );
        }
    }
    let report = |edges: &[EdgeId]| quality_report(mesh, positions, edges);
    record
        .quality
        .insert("exact".into(), report(&diagonals(&exact.edges)));

    let start = Instant::now();
    let fast = fast_min_cost_perfect_matching(mesh, &costs)?;
    record.fast_seconds = start.elapsed().as_secs_f64();
    record.fast_cost_units = fast.cost;
    record.fast_gap = (fast.cost - exact.cost) as f64 / exact.cost.max(1) as f64;
    record.fast_exchanges = fast.stats.exchanges;
    record
        .quality
        .insert("fast".into(), report(&diagonals(&fast.edges)));

    let ks = quadrangulate(mesh, QuadAlgorithm::KarpSipser)?;
    record.ks_seconds = ks.stats.total_seconds;
    record.quality.insert("ks".into(), report(&ks.diagonals));
    if mesh.is_simplicial() {
        let lrs = quadrangulate(mesh, QuadAlgorithm::Lrs)?;
        record.lrs_seconds = Some(lrs.stats.total_seconds);
        let k = lrs.triangulation.as_ref().unwrap_or(mesh);
        record
            .quality
            .insert("lrs".into(), quality_report(k, positions, &lrs.diagonals));
    }
    Ok(record)
}

fn main() -> Result<(), Box<dyn Error>> {
    let args = parse_args()?;
    let mut records = Vec::new();
    for (name, kind, make) in inputs(&args) {
        let surface = make();
        eprintln!(
            "{name}: {} triangles, genus {}",
            surface.mesh.face_count(),
            surface.mesh.genus()
        );
        let record = measure(&name, kind, &surface, &args)?;
        eprintln!(
            "  exact {:.4} s (CPU {:.4}, {} / {} exposed), LEMON {} (CPU {}), fast {:.4} s gap {:.2e}",
            record.exact_seconds,
            record.exact_cpu_seconds,
            record.exact_exposed_after_greedy,
            record.exact_exposed_after_fractional,
            record
                .lemon_seconds
                .map_or("-".into(), |s| format!("{s:.4} s")),
            record
                .lemon_cpu_seconds
                .map_or("-".into(), |s| format!("{s:.4}")),
            record.fast_seconds,
            record.fast_gap
        );
        records.push(record);
        args.results.write(&records, &markdown(&records, &args))?;
    }
    Ok(())
}

fn markdown(records: &[Record], args: &Args) -> String {
    let mut md = String::new();
    let _ = writeln!(
        md,
        "# Quality-aware pairing: exact optimum against LEMON, and the quality table\n\n\
         Generated by `make -C crates/quad/peer && SURFTOPO_MESHES=../shared/meshes cargo run \
         --release -p surftopo-quad --example quality_tables -- {}` on a 2-core machine shared \
         with other work. Cost per quad `1 − η`, η = Remacle et al.'s quality, in integer units \
         of 10⁻⁹. `exact`: `surftopo_matching::weighted::min_cost_perfect_matching` (fastest of \
         {ROUND_CALLS} calls per round, certificate verified); `LEMON`: LEMON 1.3 \
         `MaxWeightedPerfectMatching::run()` on the same integers (fastest of {ROUND_CALLS} per \
         round, graph construction excluded); ratio = exact / LEMON per round; `fast`: the fast \
         mode (one call), gap = (fast − exact) / exact.\n",
        args.results.command
    );
    let _ = writeln!(
        md,
        "## Exact optimum against LEMON\n\n\
         | input | kind | triangles | genus | exact s | exact CPU s | exposed after greedy | \
         LEMON s | LEMON CPU s | exact / LEMON (rounds) | on CPU (rounds) | same optimum (rel. \
         diff.) | fast s | fast gap |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|---|---|---|---:|---:|"
    );
    for r in records {
        let rounds: Vec<String> = r
            .exact_to_lemon_rounds
            .iter()
            .map(|x| format!("{x:.2}"))
            .collect();
        let cpu_rounds: Vec<String> = r
            .exact_to_lemon_cpu_rounds
            .iter()
            .map(|x| format!("{x:.2}"))
            .collect();
        let list = |v: Vec<String>| {
            if v.is_empty() {
                "-".into()
            } else {
                v.join(", ")
            }
        };
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {:.4} | {:.4} | {} | {} | {} | {} | {} | {} | {:.4} | {:.2e} |",
            r.input,
            r.kind,
            r.faces,
            r.genus,
            r.exact_seconds,
            r.exact_cpu_seconds,
            r.exact_exposed_after_greedy,
            r.lemon_seconds.map_or("-".into(), |s| format!("{s:.4}")),
            r.lemon_cpu_seconds
                .map_or("-".into(), |s| format!("{s:.4}")),
            list(rounds),
            list(cpu_rounds),
            r.lemon_relative_difference
                .map_or("-".into(), |d| format!("yes ({d:.0e})")),
            r.fast_seconds,
            r.fast_gap,
        );
    }
    let _ = writeln!(
        md,
        "\n## Quality\n\n\
         η: min / p5 / median / mean; bad: % of quads with a corner above 170° or below 10°; \
         dev: median over the quads of max |corner − 90°| (degrees). Corners measured on the \
         surface (`surftopo_quad::quality`). Every pairing is perfect (100% quads).\n\n\
         | input | pairing | seconds | η min | η p5 | η median | η mean | bad % | dev ° |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|"
    );
    for r in records {
        for (pairing, seconds) in [
            ("ks", Some(r.ks_seconds)),
            ("lrs", r.lrs_seconds),
            ("exact", Some(r.exact_seconds)),
            ("fast", Some(r.fast_seconds)),
        ] {
            let Some(q) = r.quality.get(pairing) else {
                continue;
            };
            let _ = writeln!(
                md,
                "| {} | {pairing} | {} | {:.3} | {:.3} | {:.3} | {:.3} | {:.2} | {:.1} |",
                r.input,
                seconds.map_or("-".into(), |s| format!("{s:.4}")),
                q.min,
                q.p5,
                q.median,
                q.mean,
                q.bad_quads_percent,
                q.median_max_angle_deviation_degrees,
            );
        }
    }
    md
}
