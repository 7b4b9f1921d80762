//! Tables 4.3 and 4.4 of the quadrangulation paper (`tri-quad-conversion-long.txt`, Section 4):
//! for SG, PS, LRS (and DS on the smaller inputs), (a) initial pairing seconds, (b) percentage
//! paired, (c) unpaired triangles, (d) augmentation seconds, (e) total seconds, and LRS's flipped
//! edges — on the shared meshes and on the paper's groups A (genus-0 brick with 3,844 cavities)
//! and B (the brick with 3,500 of its pits through-holes, genus 3,500), from the generators.
//!
//! Each algorithm runs with the default augmenting search (`forest`), with the budgeted
//! single-root one (`local`) and, where affordable, with the paper's global one. With `--lemon BIN` (build it with `make -C crates/quad/peer`), every dual
//! graph is also exported and matched by LEMON's `MaxMatching`, and the ratio of the fastest
//! surftopo pairing (and total) to LEMON's `run()` time is recorded. With `--side-by-side` (and
//! `--lemon`), only KS and LEMON run, in alternate rounds (`--runs` of them), with the ratio of
//! each round.
//!
//! ```text
//! SURFTOPO_MESHES=/work/shared/meshes cargo run --release -p surftopo-quad --example quad_tables -- \
//!     [--max-triangles N] [--min-triangles N] [--runs R] [--no-shared] [--no-groups] [--ds-max-triangles N] \
//!     [--global-max-work W] [--lemon crates/quad/peer/lemon_matching] [--side-by-side] \
//!     [--only NAME]... [--out results/quad]
//! ```
//! `--only NAME` (repeatable) keeps the inputs whose name contains NAME.
//! Writes `<out>.jsonl` (one record per input and algorithm) and `<out>.md`.

use std::collections::BTreeMap;
use std::error::Error;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::PathBuf;
use std::process::Command;

use surftopo_mesh::generators::{Surface, cavity_box};
use surftopo_quad::{AugmentStrategy, QuadAlgorithm, QuadOptions, quadrangulate_with};

/// Group A: Table 4.2(a) triangle counts (genus 0, 3,844 cavities).
const GROUP_A: [(&str, u64); 5] = [
    ("A5", 344_704),
    ("A4", 836_142),
    ("A3", 1_491_390),
    ("A2", 1_982_828),
    ("A1", 4_194_296),
];
/// Group B: Table 4.2(b) triangle counts (genus 3,500).
const GROUP_B: [(&str, u64); 5] = [
    ("B5", 360_736),
    ("B4", 853_700),
    ("B3", 1_510_988),
    ("B2", 2_003_954),
    ("B1", 4_222_296),
];

struct Args {
    max_triangles: u64,
    min_triangles: u64,
    runs: u64,
    shared: bool,
    groups: bool,
    ds_max_triangles: u64,
    global_max_work: f64,
    lemon: Option<PathBuf>,
    side_by_side: bool,
    /// Only the inputs whose name contains one of these.
    only: Vec<String>,
    out: PathBuf,
}

fn parse_args() -> Result<Args, Box<dyn Error>> {
    let mut args = Args {
        max_triangles: 5_000_000,
        min_triangles: 0,
        runs: 3,
        shared: true,
        groups: true,
        ds_max_triangles: 300_000,
        global_max_work: 3e9,
        lemon: None,
        side_by_side: false,
        only: Vec::new(),
        out: PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../results/quad")),
    };
    let mut it = std::env::args().skip(1);
    while let Some(flag) = it.next() {
        let mut value = || it.next().ok_or(format!("{flag} needs a value"));
        match flag.as_str() {
            "--max-triangles" => args.max_triangles = value()?.parse()?,
            "--min-triangles" => args.min_triangles = value()?.parse()?,
            "--runs" => args.runs = value()?.parse::<u64>()?.max(1),
            "--no-shared" => args.shared = false,
            "--no-groups" => args.groups = false,
            "--ds-max-triangles" => args.ds_max_triangles = value()?.parse()?,
            "--global-max-work" => args.global_max_work = value()?.parse()?,
            "--lemon" => args.lemon = Some(PathBuf::from(value()?)),
            "--side-by-side" => args.side_by_side = true,
            "--only" => args.only.push(value()?),
            "--out" => args.out = PathBuf::from(value()?),
            other => return Err(format!("unknown argument {other}").into()),
        }
    }
    Ok(args)
}

/// One line of the results file.
#[derive(Clone, Debug, Default, serde::Serialize)]
struct Record {
    input: String,
    group: String,
    genus: i64,
    vertices: usize,
    faces: usize,
    algorithm: String,
    /// `forest`, `local`, `global` or `lemon`.
    augment: String,
    runs: u64,
    initial_pairing_seconds: f64,
    paired_percent: f64,
    unpaired: f64,
    augmentation_seconds: f64,
    total_seconds: f64,
    /// Minimum over the runs of initial pairing + augmentation: the perfect pairing alone,
    /// without building the quads (LEMON: `run()`, like `total_seconds`).
    pairing_seconds: f64,
    /// Median over the runs of the total (the other times are minima).
    total_seconds_median: f64,
    /// Mean on-CPU seconds of the whole call (this thread's run time, robust to a loaded
    /// machine; LEMON: of `run()`).
    cpu_seconds: f64,
    flipped_edges: f64,
    /// Nodes reached by the augmenting searches (average per run).
    augment_reached: f64,
    /// Searches started (average per run).
    augment_searches: f64,
    /// LEMON only: seconds to build its graph (not in `total_seconds`).
    #[serde(skip_serializing_if = "Option::is_none")]
    lemon_build_seconds: Option<f64>,
    /// `--side-by-side`, KS only: per round, KS's pairing seconds over LEMON's `run()` seconds
    /// measured right after it.
    #[serde(skip_serializing_if = "Option::is_none")]
    round_ratios: Option<Vec<f64>>,
}

/// Runs `algorithm` (`runs` seeds for SG and PS): counts are averaged over the runs, times are the
/// minimum over the runs (the machine is shared; the minimum is the least disturbed estimate),
/// with the median total kept as well.
fn measure(
    surface: &Surface,
    base: &Record,
    algorithm: impl Fn(u64) -> QuadAlgorithm,
    augment: AugmentStrategy,
    runs: u64,
) -> Result<Record, Box<dyn Error>> {
    let mut r = Record {
        runs,
        augment: match augment {
            AugmentStrategy::Global => "global".into(),
            AugmentStrategy::Local { .. } => "local".into(),
            AugmentStrategy::Forest => "forest".into(),
        },
        initial_pairing_seconds: f64::INFINITY,
        augmentation_seconds: f64::INFINITY,
        total_seconds: f64::INFINITY,
        pairing_seconds: f64::INFINITY,
        ..base.clone()
    };
    let mut totals = Vec::new();
    let cpu_start = cpu_ns();
    for seed in 0..runs {
        let a = algorithm(seed);
        let result = quadrangulate_with(&surface.mesh, a, &QuadOptions { augment })?;
        let s = &result.stats;
        r.algorithm = s.algorithm.clone();
        r.initial_pairing_seconds = r.initial_pairing_seconds.min(s.initial_pairing_seconds);
        r.augmentation_seconds = r.augmentation_seconds.min(s.augmentation_seconds);
        r.total_seconds = r.total_seconds.min(s.total_seconds);
        r.pairing_seconds = r
            .pairing_seconds
            .min(s.initial_pairing_seconds + s.augmentation_seconds);
        totals.push(s.total_seconds);
        r.paired_percent += s.paired_percent;
        r.unpaired += s.unpaired as f64;
        r.flipped_edges += s.flipped_edges as f64;
        r.augment_reached += result.augmentation.reached as f64;
        r.augment_searches += result.augmentation.searches as f64;
    }
    r.cpu_seconds = (cpu_ns().saturating_sub(cpu_start)) as f64 * 1e-9 / runs as f64;
    totals.sort_by(f64::total_cmp);
    r.total_seconds_median = totals[totals.len() / 2];
    let n = runs as f64;
    for x in [
        &mut r.paired_percent,
        &mut r.unpaired,
        &mut r.flipped_edges,
        &mut r.augment_reached,
        &mut r.augment_searches,
    ] {
        *x /= n;
    }
    Ok(r)
}

/// On-CPU nanoseconds of the current thread (`/proc/thread-self/schedstat`; updated at scheduler
/// ticks, so meaningful as a mean over several runs), 0 where unavailable.
fn cpu_ns() -> u64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse().ok())
        .unwrap_or(0)
}

/// Exports the dual graph and times LEMON's MaxMatching on it (`runs` times in one process).
fn lemon(
    binary: &PathBuf,
    surface: &Surface,
    base: &Record,
    runs: u64,
) -> Result<Record, Box<dyn Error>> {
    let path = export_dual(surface)?;
    let record = lemon_on(binary, &path, surface, base, runs);
    std::fs::remove_file(&path)?;
    record
}

/// Writes the dual graph of `surface` in the LEMON harness's binary format to a temporary file.
fn export_dual(surface: &Surface) -> Result<PathBuf, Box<dyn Error>> {
    let mesh = &surface.mesh;
    assert_eq!(mesh.face_slots(), mesh.face_count(), "dense ids expected");
    let path = std::env::temp_dir().join(format!("surftopo-dual-{}.bin", std::process::id()));
    let mut out = std::io::BufWriter::new(std::fs::File::create(&path)?);
    out.write_all(&(mesh.face_count() as u32).to_le_bytes())?;
    out.write_all(&(mesh.edge_count() as u32).to_le_bytes())?;
    for e in mesh.edges() {
        let h = e.halfedge();
        out.write_all(&mesh.face(h).0.to_le_bytes())?;
        out.write_all(&mesh.face(h.twin()).0.to_le_bytes())?;
    }
    out.flush()?;
    Ok(path)
}

/// Runs the LEMON harness on an exported dual graph and checks that its matching is perfect.
fn lemon_on(
    binary: &PathBuf,
    path: &PathBuf,
    surface: &Surface,
    base: &Record,
    runs: u64,
) -> Result<Record, Box<dyn Error>> {
    let mesh = &surface.mesh;
    let output = Command::new(binary)
        .arg(path)
        .arg(runs.to_string())
        .output()?;
    if !output.status.success() {
        return Err(format!("LEMON harness: {}", String::from_utf8_lossy(&output.stderr)).into());
    }
    let v: serde_json::Value = serde_json::from_slice(&output.stdout)?;
    let size = v["matching_size"].as_u64().ok_or("no matching_size")? as usize;
    if 2 * size != mesh.face_count() {
        return Err(format!("LEMON matched {size} pairs of {} faces", mesh.face_count()).into());
    }
    let run = v["run_seconds"].as_f64().ok_or("no run_seconds")?;
    Ok(Record {
        algorithm: "lemon".into(),
        augment: "lemon".into(),
        runs,
        total_seconds_median: v["median_run_seconds"].as_f64().unwrap_or(run),
        cpu_seconds: v["cpu_run_seconds"].as_f64().unwrap_or(run),
        paired_percent: 100.0,
        total_seconds: run,
        pairing_seconds: run,
        lemon_build_seconds: v["build_seconds"].as_f64(),
        ..base.clone()
    })
}

/// `--side-by-side`: KS and LEMON in alternate rounds (one KS run, then the fastest of three
/// LEMON `run()`s in its harness), so that a slow spell of the shared machine hits both; per round the ratio of
/// KS's pairing time to LEMON's. Returns the KS record (minima over the rounds, and the per-round
/// ratios) and the LEMON one (minima).
fn side_by_side(
    binary: &PathBuf,
    surface: &Surface,
    base: &Record,
    rounds: u64,
) -> Result<[Record; 2], Box<dyn Error>> {
    let path = export_dual(surface)?;
    // A first KS run, not timed, gives the record its counts.
    let mut ks = Record {
        round_ratios: Some(Vec::new()),
        initial_pairing_seconds: f64::INFINITY,
        augmentation_seconds: f64::INFINITY,
        total_seconds: f64::INFINITY,
        pairing_seconds: f64::INFINITY,
        ..measure(
            surface,
            base,
            |_| QuadAlgorithm::KarpSipser,
            AugmentStrategy::default(),
            1,
        )?
    };
    let mut lemon: Option<Record> = None;
    let mut cpu = [0.0; 2];
    for _ in 0..rounds {
        let k = measure(
            surface,
            base,
            |_| QuadAlgorithm::KarpSipser,
            AugmentStrategy::default(),
            1,
        )?;
        // Three runs in the harness, the fastest kept: its first run is a cold process's.
        let l = lemon_on(binary, &path, surface, base, 3)?;
        cpu[0] += k.cpu_seconds / rounds as f64;
        cpu[1] += l.cpu_seconds / rounds as f64;
        if let Some(ratios) = &mut ks.round_ratios {
            ratios.push(k.pairing_seconds / l.pairing_seconds.max(1e-12));
        }
        for (x, y) in [
            (&mut ks.initial_pairing_seconds, k.initial_pairing_seconds),
            (&mut ks.augmentation_seconds, k.augmentation_seconds),
            (&mut ks.total_seconds, k.total_seconds),
            (&mut ks.pairing_seconds, k.pairing_seconds),
        ] {
            *x = x.min(y);
        }
        lemon = Some(match lemon {
            Some(m) if m.total_seconds <= l.total_seconds => m,
            _ => l,
        });
    }
    std::fs::remove_file(&path)?;
    let mut lemon = lemon.ok_or("no rounds")?;
    ks.runs = rounds;
    lemon.runs = rounds;
    ks.cpu_seconds = cpu[0];
    lemon.cpu_seconds = cpu[1];
    Ok([ks, lemon])
}

/// An input: its name, its group and how to make it (lazily, one at a time in memory).
type Input = (String, String, Box<dyn Fn() -> Surface>);

fn inputs(args: &Args) -> Vec<Input> {
    let mut out: Vec<Input> = Vec::new();
    if args.shared {
        for shared in surftopo_testkit::shared_meshes() {
            if (args.min_triangles..=args.max_triangles).contains(&(shared.faces as u64)) {
                let name = shared.file.trim_end_matches(".gz").to_string();
                out.push((
                    name,
                    "shared".into(),
                    Box::new(move || surftopo_testkit::load(&shared)),
                ));
            }
        }
    }
    if args.groups {
        for (group, table, cavities, holes) in [("A", GROUP_A, 3844, 0), ("B", GROUP_B, 344, 3500)]
        {
            for (name, target) in table {
                if (args.min_triangles..=args.max_triangles).contains(&target) {
                    out.push((
                        name.into(),
                        group.into(),
                        Box::new(move || cavity_box(cavities, holes, target)),
                    ));
                }
            }
        }
    }
    if !args.only.is_empty() {
        out.retain(|(name, _, _)| args.only.iter().any(|only| name.contains(only.as_str())));
    }
    out
}

fn main() -> Result<(), Box<dyn Error>> {
    let args = parse_args()?;
    if let Some(dir) = args.out.parent() {
        std::fs::create_dir_all(dir)?;
    }
    let mut records: Vec<Record> = Vec::new();
    let forest = AugmentStrategy::default();
    for (name, group, make) in inputs(&args) {
        let surface = make();
        let mesh = &surface.mesh;
        let base = Record {
            input: name.clone(),
            group: group.clone(),
            genus: mesh.genus(),
            vertices: mesh.vertex_count(),
            faces: mesh.face_count(),
            ..Record::default()
        };
        eprintln!("{name}: {} triangles, genus {}", base.faces, base.genus);
        if args.side_by_side {
            let binary = args.lemon.as_ref().ok_or("--side-by-side needs --lemon")?;
            let pair = side_by_side(binary, &surface, &base, args.runs)?;
            eprintln!(
                "  ks pairing {:.4} s, LEMON run() {:.4} s",
                pair[0].pairing_seconds, pair[1].pairing_seconds
            );
            records.extend(pair);
            write_results(&records, &args)?;
            continue;
        }
        let mut mine = vec![
            measure(
                &surface,
                &base,
                |s| QuadAlgorithm::SimpleGreedy { seed: s },
                forest,
                args.runs,
            )?,
            measure(
                &surface,
                &base,
                |s| QuadAlgorithm::PulliSegal { seed: s },
                forest,
                args.runs,
            )?,
            measure(&surface, &base, |_| QuadAlgorithm::Lrs, forest, args.runs)?,
            measure(
                &surface,
                &base,
                |_| QuadAlgorithm::KarpSipser,
                forest,
                args.runs,
            )?,
        ];
        if base.faces as u64 <= args.ds_max_triangles {
            mine.push(measure(
                &surface,
                &base,
                |_| QuadAlgorithm::DiksStanczyk,
                forest,
                1,
            )?);
        }
        let afford = |r: &Record| r.unpaired / 2.0 * r.faces as f64 <= args.global_max_work;
        let mut global = Vec::new();
        for (i, algorithm) in [
            QuadAlgorithm::SimpleGreedy { seed: 0 },
            QuadAlgorithm::PulliSegal { seed: 0 },
            QuadAlgorithm::Lrs,
        ]
        .into_iter()
        .enumerate()
        {
            let pick = move |s: u64| match algorithm {
                QuadAlgorithm::SimpleGreedy { .. } => QuadAlgorithm::SimpleGreedy { seed: s },
                QuadAlgorithm::PulliSegal { .. } => QuadAlgorithm::PulliSegal { seed: s },
                other => other,
            };
            let local = AugmentStrategy::Local {
                initial_budget: 256,
            };
            global.push(measure(&surface, &base, pick, local, args.runs)?);
            if afford(&mine[i]) {
                global.push(measure(
                    &surface,
                    &base,
                    pick,
                    AugmentStrategy::Global,
                    args.runs,
                )?);
            }
        }
        for r in mine.iter().chain(&global) {
            eprintln!(
                "  {:>4} {:>6}: (a) {:.4} (b) {:.4}% (c) {:.1} (d) {:.4} (e) {:.4} flipped {:.0}",
                r.algorithm,
                r.augment,
                r.initial_pairing_seconds,
                r.paired_percent,
                r.unpaired,
                r.augmentation_seconds,
                r.total_seconds,
                r.flipped_edges
            );
        }
        records.extend(mine);
        records.extend(global);
        if let Some(binary) = &args.lemon {
            let r = lemon(binary, &surface, &base, args.runs)?;
            eprintln!("  LEMON MaxMatching run(): {:.4} s", r.total_seconds);
            records.push(r);
        }
        // Rewritten after every input, so that an interrupted run keeps what it measured.
        write_results(&records, &args)?;
    }
    eprintln!("wrote {}.{{jsonl,md}}", args.out.display());
    Ok(())
}

fn write_results(records: &[Record], args: &Args) -> Result<(), Box<dyn Error>> {
    let mut jsonl = String::new();
    for r in records {
        writeln!(jsonl, "{}", serde_json::to_string(r)?)?;
    }
    std::fs::write(args.out.with_extension("jsonl"), jsonl)?;
    std::fs::write(args.out.with_extension("md"), markdown(records, args))?;
    Ok(())
}

fn markdown(records: &[Record], args: &Args) -> String {
    let mut md = String::new();
    let _ = writeln!(
        md,
        "# Quadrangulation by triangle pairing: Tables 4.3 / 4.4\n\n\
         Generated by `cargo run --release -p surftopo-quad --example quad_tables -- \
         --max-triangles {} --runs {}{}` (SURFTOPO_MESHES set to the shared meshes) on a \
         2-core machine shared with other benchmarks. Columns as in the paper: (a) initial \
         pairing seconds, (b) % paired, (c) unpaired triangles, (d) augmentation seconds, (e) \
         total seconds. SG and PS: {} seeds. Times are the minimum over the runs, counts the \
         average. Augmenting searches: `forest` (the default), `local` (budgeted single-root \
         searches), `global` (the paper's; run only when unpaired/2 x faces <= {:.0e}). \
         `lemon`: LEMON 1.3 `MaxMatching::run()` on the same dual graph.\n",
        args.max_triangles,
        args.runs,
        if args.lemon.is_some() {
            " --lemon crates/quad/peer/lemon_matching"
        } else {
            ""
        },
        args.runs,
        args.global_max_work,
    );
    let _ = writeln!(
        md,
        "| input | faces | genus | alg. | augment | (a) | (b) | (c) | (d) | (e) | flipped | CPU s |\n\
         |---|---:|---:|---|---|---:|---:|---:|---:|---:|---:|---:|"
    );
    for r in records {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {:.4} | {:.4}% | {:.1} | {:.4} | {:.4} | {:.0} | {:.4} |",
            r.input,
            r.faces,
            r.genus,
            r.algorithm,
            r.augment,
            r.initial_pairing_seconds,
            r.paired_percent,
            r.unpaired,
            r.augmentation_seconds,
            r.total_seconds,
            r.flipped_edges,
            r.cpu_seconds
        );
    }
    // Summary: fastest surftopo total per input vs LEMON.
    let mut by_input: BTreeMap<(String, String), Vec<&Record>> = BTreeMap::new();
    for r in records {
        by_input
            .entry((r.group.clone(), r.input.clone()))
            .or_default()
            .push(r);
    }
    let _ = writeln!(
        md,
        "\n## Fastest surftopo algorithm vs LEMON\n\n\
         Pairing: the perfect pairing alone (initial pairing + augmentation, surftopo's copy of \
         the adjacency included; minimum over the runs), like for like with LEMON's \
         `MaxMatching::run()` (its graph built beforehand, not timed). Total: the whole \
         `quadrangulate` call, building the quads included. CPU: mean on-CPU time of the thread \
         over the runs (surftopo: the whole call), which the other processes of the shared \
         machine disturb much less than wall time.\n\n\
         | input | faces | genus | fastest pairing | pairing s | LEMON run s | pairing ratio | \
         its total s | total ratio | its (d)/(e) | CPU s | LEMON CPU s | CPU ratio |\n\
         |---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    );
    for ((_, input), rs) in &by_input {
        let Some(best) = rs
            .iter()
            .filter(|r| r.augment != "lemon")
            .min_by(|a, b| a.pairing_seconds.total_cmp(&b.pairing_seconds))
        else {
            continue;
        };
        let lemon = rs.iter().find(|r| r.augment == "lemon");
        let seconds = |l: Option<&&Record>, f: fn(&Record) -> f64| {
            l.map_or("-".into(), |l| format!("{:.4}", f(l)))
        };
        let ratio = |a: f64, f: fn(&Record) -> f64| {
            lemon.map_or("-".into(), |l| format!("{:.3}", a / f(l).max(1e-12)))
        };
        let _ = writeln!(
            md,
            "| {input} | {} | {} | {} ({}) | {:.4} | {} | {} | {:.4} | {} | {:.2} | {:.4} | {} | {} |",
            best.faces,
            best.genus,
            best.algorithm,
            best.augment,
            best.pairing_seconds,
            seconds(lemon, |l| l.pairing_seconds),
            ratio(best.pairing_seconds, |l| l.pairing_seconds),
            best.total_seconds,
            ratio(best.total_seconds, |l| l.total_seconds),
            best.augmentation_seconds / best.total_seconds.max(1e-12),
            best.cpu_seconds,
            seconds(lemon, |l| l.cpu_seconds),
            ratio(best.cpu_seconds, |l| l.cpu_seconds),
        );
    }
    let side_by_side: Vec<&Record> = records
        .iter()
        .filter(|r| r.round_ratios.is_some())
        .collect();
    if !side_by_side.is_empty() {
        let _ = writeln!(
            md,
            "\n## KS and LEMON side by side, round by round\n\n\
             Each round: one KS `quadrangulate` call, then three LEMON `run()`s in its harness \
             (the fastest kept; the first is a cold process's); the ratio is KS's pairing time \
             over LEMON's in the same round.\n\n\
             | input | faces | rounds | lowest ratio | median ratio | highest ratio |\n\
             |---|---:|---:|---:|---:|---:|"
        );
        for r in side_by_side {
            let mut ratios = r.round_ratios.clone().unwrap_or_default();
            ratios.sort_by(f64::total_cmp);
            if let (Some(low), Some(high)) = (ratios.first(), ratios.last()) {
                let _ = writeln!(
                    md,
                    "| {} | {} | {} | {low:.3} | {:.3} | {high:.3} |",
                    r.input,
                    r.faces,
                    ratios.len(),
                    ratios[ratios.len() / 2],
                );
            }
        }
    }
    md
}
