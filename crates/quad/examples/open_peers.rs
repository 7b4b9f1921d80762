//! Quadrangulations of open meshes against their peers, side by side in one run.
//!
//! Quality: surftopo's maximum pairings (`count` = Karp–Sipser, `quality` = the exact maximum
//! pairing of least cost, `quality-fast`) against Gmsh's Blossom recombination and Blender's
//! join_triangles (`crates/quad/peer/quad_peers.py`; Gmsh with and without its topology
//! optimisation and smoothing; a peer that fails is recorded with its message), every output
//! measured the same way (the corners of each quad in space, as `quality_peers` measures
//! them): triangles left, median largest deviation from 90°, bad quads (a corner above 170° or
//! below 10°), median η.
//!
//! Speed, on the same dual graphs (the surface's dual, boundary sides left out): KS to a maximum
//! (`karp_sipser_maximum_with`, its Tutte–Berge barrier included) against LEMON 1.3's
//! `MaxMatching::run()`, and the exact maximum pairing of least cost
//! (`min_cost_maximum_matching`, its certificate included) against LEMON's
//! `MaxWeightedMatching::run()` with weights `B − cost`, `B` above the cost of KS's maximum matching,
//! so that LEMON's heaviest matching is a maximum one of least cost (LEMON's size and cost must equal
//! ours). Each round runs ours `CALLS` times and LEMON's `run()` as often in its harness, the
//! fastest of each kept; a round's ratio is ours / LEMON's; printed: the median and range of the
//! rounds' ratios.
//!
//! ```text
//! make -C crates/quad/peer
//! SURFTOPO_MESHES=../shared/meshes cargo run --release -p surftopo-quad --example open_peers -- \
//!     --lemon crates/quad/peer/lemon_matching [--python PYTHON] [--rounds R] [--seed S]... \
//!     [--input SPEC]... [--out results/open_peers]
//! ```
//! `PYTHON`: an interpreter with the pip packages `gmsh` and (optionally) `bpy` (a venv; never
//! needed by the tests); without it, only the speed table. SPEC: `holes:MESH:K` (K holes cut
//! around random vertices of the shared mesh whose file name starts with MESH,
//! `surftopo_mesh::generators::cut_holes`), `annulus:M:N:FLIPS`, `mobius:M:N:FLIPS` (a
//! non-orientable band), `disk:N:FLIPS` (the generators' grids after FLIPS random flips),
//! `genus:G:SIZE:FLIPS:K` (a genus-G surface, random flips, K holes cut). The random ones drawn
//! with `--seed` (default 40961); given more than once, every input is made with each seed, the
//! first seed's measured in full, the further seeds' (fresh draws) by the KS comparison alone
//! (the slow weighted one skipped) and without the peers' quality. Without `--input`: 600 holes cut from each of the eleven
//! shared meshes of 95k–105k triangles, `annulus:250:200:60000`, `mobius:250:200:60000`,
//! `disk:224:60000`, `genus:30:9:60000:400`. Writes `<out>.md`. `--ks-only N` (no `--lemon`
//! needed): KS alone, N calls per input, its figures on stderr and nothing written (for a
//! profiler).

mod support;

use std::error::Error;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use support::peers::{PeerOutput, peer_version, run_peer};
use support::{
    Results, export_graph, machine_note, median, ratio_summary, ratios, thread_cpu_seconds, timed,
    write_off_triangles,
};
use surftopo_matching::{
    DualGraph, KarpSipserOptions, SurfaceDual, karp_sipser_maximum_with, min_cost_maximum_matching,
};
use surftopo_mesh::generators::{
    annulus, cut_holes, disk, genus_surface, mobius_band, random_flips_covered,
};
use surftopo_mesh::{CoveredSurface, SurfaceKind};
use surftopo_quad::quality::{QualityReport, space_quality_report};
use surftopo_quad::{
    QuadAlgorithm, QualityObjective, SurfaceOptions, quadrangulate_surface_by_quality,
    quadrangulate_surface_with_quality, surface_pair_costs,
};

/// Calls per round and side: the first call of each runs on caches the other program has just
/// filled.
const CALLS: usize = 3;

struct Args {
    results: Results,
    lemon: PathBuf,
    python: Option<PathBuf>,
    rounds: usize,
    seeds: Vec<u64>,
    inputs: Vec<String>,
    /// `--ks-only N`: only KS, N calls per input, its figures printed (for a profiler).
    ks_only: Option<usize>,
}

fn parse_args() -> Result<Args, Box<dyn Error>> {
    let (results, given) = Results::from_args("open_peers")?;
    let (mut lemon, mut python, mut rounds, mut seeds, mut inputs) =
        (None, None, 5, vec![], vec![]);
    let mut ks_only = None;
    let mut it = given.into_iter();
    while let Some(flag) = it.next() {
        let mut value = || it.next().ok_or(format!("{flag} needs a value"));
        match flag.as_str() {
            "--lemon" => lemon = Some(PathBuf::from(value()?)),
            "--python" => python = Some(PathBuf::from(value()?)),
            "--rounds" => rounds = value()?.parse::<usize>()?.max(1),
            "--seed" => seeds.push(value()?.parse()?),
            "--input" => inputs.push(value()?),
            "--ks-only" => ks_only = Some(value()?.parse::<usize>()?.max(1)),
            other => return Err(format!("unknown argument {other}").into()),
        }
    }
    if inputs.is_empty() {
        for shared in surftopo_testkit::shared_meshes() {
            if (95_000..=105_000).contains(&shared.faces) {
                let name = shared.file.split('.').next().unwrap_or_default();
                inputs.push(format!("holes:{name}:600"));
            }
        }
        for spec in [
            "annulus:250:200:60000",
            "mobius:250:200:60000",
            "disk:224:60000",
            "genus:30:9:60000:400",
        ] {
            inputs.push(spec.into());
        }
    }
    if seeds.is_empty() {
        seeds.push(40961);
    }
    if ks_only.is_some() {
        lemon.get_or_insert_with(PathBuf::new);
    }
    Ok(Args {
        results,
        ks_only,
        lemon: lemon.ok_or("--lemon BIN is required (make -C crates/quad/peer)")?,
        python,
        rounds,
        seeds,
        inputs,
    })
}

/// The open surface a SPEC names (see the module doc), as a triangle soup's surface with the
/// classification of its pieces.
fn make_input(spec: &str, seed: u64) -> Result<(CoveredSurface, Vec<SurfaceKind>), Box<dyn Error>> {
    let parts: Vec<&str> = spec.split(':').collect();
    let number = |i: usize| -> Result<u32, Box<dyn Error>> {
        Ok(parts
            .get(i)
            .ok_or(format!("{spec}: missing field {i}"))?
            .parse()?)
    };
    let made: CoveredSurface = match parts[0] {
        "holes" => {
            let name = parts.get(1).ok_or(format!("{spec}: no mesh"))?;
            let shared = surftopo_testkit::shared_meshes()
                .into_iter()
                .find(|m| m.file.starts_with(name))
                .ok_or(format!("no shared mesh {name} (is SURFTOPO_MESHES set?)"))?;
            let closed: CoveredSurface = surftopo_testkit::load(&shared).into();
            cut_holes(&closed, number(2)? as usize, seed).0
        }
        "annulus" => {
            random_flips_covered(&annulus(number(1)?, number(2)?), number(3)? as usize, seed)
        }
        "mobius" => random_flips_covered(
            &mobius_band(number(1)?, number(2)?),
            number(3)? as usize,
            seed,
        ),
        "disk" => random_flips_covered(&disk(number(1)?), number(2)? as usize, seed),
        "genus" => {
            let closed: CoveredSurface = genus_surface(number(1)?, number(2)?).into();
            let flipped = random_flips_covered(&closed, number(3)? as usize, seed);
            cut_holes(&flipped, number(4)? as usize, seed).0
        }
        other => return Err(format!("unknown input kind {other}").into()),
    };
    // Through a soup, as the CLI reads a file: dense ids and the pieces' classification.
    let (positions, triangles) = made.to_triangles();
    let (surface, report) = CoveredSurface::from_triangles(positions, &triangles)?;
    Ok((surface, report.surfaces))
}

/// One tool's quadrangulation of one input, measured.
struct QualityRow {
    tool: String,
    quads: usize,
    triangles_left: usize,
    report: QualityReport,
    seconds: f64,
    cpu_seconds: f64,
}

impl QualityRow {
    fn of_peer(tool: &str, output: &PeerOutput) -> Self {
        let quads = output.quads();
        QualityRow {
            tool: tool.into(),
            quads: quads.len(),
            triangles_left: output.triangles_left(),
            report: space_quality_report(&output.positions, &quads),
            seconds: output.seconds,
            cpu_seconds: output.cpu_seconds,
        }
    }
}

/// surftopo's three objectives on the surface (whole calls: costs, pairing, certificate checks,
/// quads), and the fewest triangles any pairing leaves (the verified certificate's bound).
fn ours(
    surface: &CoveredSurface,
    pieces: &[SurfaceKind],
) -> Result<(Vec<QualityRow>, usize), Box<dyn Error>> {
    let row = |tool: &str, result: &surftopo_quad::SurfaceQuads, (seconds, cpu_seconds)| {
        let quads: Vec<[usize; 4]> = result.quads.iter().map(|q| q.map(|v| v as usize)).collect();
        QualityRow {
            tool: tool.into(),
            quads: quads.len(),
            triangles_left: result.triangles.len(),
            report: space_quality_report(&surface.positions, &quads),
            seconds,
            cpu_seconds,
        }
    };
    let (times, count) = timed(|| {
        quadrangulate_surface_with_quality(
            surface,
            pieces,
            QuadAlgorithm::KarpSipser,
            &SurfaceOptions::default(),
        )
    });
    let count = count?;
    let bound = count.result.stats.deficiency_lower_bound;
    let mut rows = vec![row("surftopo --objective count (ks)", &count.result, times)];
    for (tool, objective) in [
        ("surftopo --objective quality", QualityObjective::Exact),
        ("surftopo --objective quality-fast", QualityObjective::Fast),
    ] {
        let (times, q) =
            timed(|| quadrangulate_surface_by_quality(surface, pieces, objective, false));
        let q = q?;
        if q.result.triangles.len() != bound {
            return Err(format!(
                "{tool}: {} triangles left, not {bound}",
                q.result.triangles.len()
            )
            .into());
        }
        rows.push(row(tool, &q.result, times));
    }
    if rows[0].triangles_left != bound {
        return Err("ks: not a maximum pairing".into());
    }
    Ok((rows, bound))
}

/// The dual's edges between two triangles (boundary sides left out), with dense node ids.
struct PlainDual {
    nodes: usize,
    /// Per exported edge: its dual edge id.
    edge_ids: Vec<u32>,
    ends: Vec<[u32; 2]>,
}

impl PlainDual {
    fn of(dual: &SurfaceDual) -> Self {
        let mut dense = vec![u32::MAX; dual.node_slots()];
        let mut nodes = 0;
        for v in 0..dual.node_slots() as u32 {
            if dual.is_node(v) {
                dense[v as usize] = nodes;
                nodes += 1;
            }
        }
        let (mut edge_ids, mut ends) = (Vec::new(), Vec::new());
        for e in 0..dual.edge_slots() as u32 {
            if dual.is_edge(e) && !dual.is_boundary(e) {
                let [a, b] = dual.endpoints(e);
                edge_ids.push(e);
                ends.push([dense[a as usize], dense[b as usize]]);
            }
        }
        PlainDual {
            nodes: nodes as usize,
            edge_ids,
            ends,
        }
    }
}

/// LEMON's harness on an exported graph: its JSON line.
fn lemon_run(
    binary: &Path,
    mode: Option<&str>,
    graph: &Path,
    repeat: usize,
) -> Result<serde_json::Value, Box<dyn Error>> {
    let mut command = Command::new(binary);
    if let Some(mode) = mode {
        command.arg(mode);
    }
    let output = command.arg(graph).arg(repeat.to_string()).output()?;
    if !output.status.success() {
        return Err(format!("LEMON harness: {}", String::from_utf8_lossy(&output.stderr)).into());
    }
    Ok(serde_json::from_slice(&output.stdout)?)
}

/// Per round: (ours, LEMON's) fastest wall seconds, and mean CPU seconds.
#[derive(Default)]
struct Paired {
    ours: Vec<f64>,
    lemon: Vec<f64>,
    ours_cpu: Vec<f64>,
    lemon_cpu: Vec<f64>,
}

impl Paired {
    fn summary(&self) -> [String; 4] {
        if self.ours.is_empty() {
            return ["-".into(), "-".into(), "-".into(), "-".into()];
        }
        [
            format!("{:.4}", median(&self.ours)),
            format!("{:.4}", median(&self.lemon)),
            ratio_summary(&ratios(&self.ours, &self.lemon)),
            ratio_summary(&ratios(&self.ours_cpu, &self.lemon_cpu)),
        ]
    }
}

/// KS against LEMON's MaxMatching and (with `weighted`) the exact quality pairing against
/// LEMON's MaxWeightedMatching, side by side; checks that LEMON's sizes and cost equal ours.
fn speed(
    surface: &CoveredSurface,
    lemon: &Path,
    rounds: usize,
    weighted_too: bool,
) -> Result<(Paired, Paired, usize), Box<dyn Error>> {
    let dual = SurfaceDual::of_cover(&surface.cover);
    let costs = surface_pair_costs(surface, &dual);
    let plain = PlainDual::of(&dual);
    let ks_options = KarpSipserOptions::default();
    let (pairing, _, _) = karp_sipser_maximum_with(&dual, &ks_options);
    let size = (dual.node_count() - pairing.unmatched_count(&dual)) / 2;
    let exact = min_cost_maximum_matching(&dual, &costs)?;
    if exact.edges.len() != size {
        return Err(format!("exact: {} pairs, KS {size}", exact.edges.len()).into());
    }
    // B above the cost of a maximum matching of least cost (KS's matching costs at least as
    // much): then a matching of k < ν pairs weighs at most k·B < ν·B − (B − 1) ≤ the weight of
    // the optimum, so the heaviest matching is a maximum one, and of least cost.
    let ks_cost: i64 = pairing
        .matched_edges(&dual)
        .iter()
        .map(|&e| costs[e as usize])
        .sum();
    let big = ks_cost + 1;
    // LEMON sums the weights of its matching (at most ν·B) and keeps duals of 4·B.
    if big
        .checked_mul(plain.nodes as i64 / 2 + 1)
        .is_none_or(|w| w > i64::MAX / 2)
    {
        return Err("weights B − cost would overflow LEMON's integer duals".into());
    }
    let weights: Vec<i64> = plain
        .edge_ids
        .iter()
        .map(|&e| big - costs[e as usize])
        .collect();
    let unweighted = export_graph(plain.nodes, &plain.ends, None, "open-dual")?;
    let weighted = export_graph(plain.nodes, &plain.ends, Some(&weights), "open-dual-w")?;
    let (mut ks, mut quality) = (Paired::default(), Paired::default());
    for round in 0..rounds {
        // Order reversed every other round, so that neither side always runs first.
        let mut steps: [u8; 2] = [0, 1];
        if round % 2 == 1 {
            steps.reverse();
        }
        for step in steps {
            if step == 0 {
                let (mut best, mut cpu) = (f64::INFINITY, 0.0);
                for _ in 0..CALLS {
                    let ((wall, c), (p, _, _)) =
                        timed(|| karp_sipser_maximum_with(&dual, &ks_options));
                    if p.unmatched_count(&dual) != dual.node_count() - 2 * size {
                        return Err("KS: a different size".into());
                    }
                    best = best.min(wall);
                    cpu += c / CALLS as f64;
                }
                ks.ours.push(best);
                ks.ours_cpu.push(cpu);
                if !weighted_too {
                    continue;
                }
                let (mut best, mut cpu) = (f64::INFINITY, 0.0);
                for _ in 0..CALLS {
                    let ((wall, c), m) = timed(|| min_cost_maximum_matching(&dual, &costs));
                    if m?.cost != exact.cost {
                        return Err("exact: a different cost".into());
                    }
                    best = best.min(wall);
                    cpu += c / CALLS as f64;
                }
                quality.ours.push(best);
                quality.ours_cpu.push(cpu);
            } else {
                let v = lemon_run(lemon, None, &unweighted, CALLS)?;
                if v["matching_size"].as_u64() != Some(size as u64) {
                    return Err(format!(
                        "LEMON MaxMatching: size {}, ours {size}",
                        v["matching_size"]
                    )
                    .into());
                }
                ks.lemon
                    .push(v["run_seconds"].as_f64().ok_or("no run_seconds")?);
                ks.lemon_cpu
                    .push(v["cpu_run_seconds"].as_f64().ok_or("no cpu")?);
                if !weighted_too {
                    continue;
                }
                let v = lemon_run(lemon, Some("--maximum-weighted"), &weighted, CALLS)?;
                let lemon_size = v["matching_size"].as_i64().ok_or("no matching_size")?;
                let weight = v["matching_weight"].as_i64().ok_or("no matching_weight")?;
                if lemon_size != size as i64 || lemon_size * big - weight != exact.cost {
                    return Err(format!(
                        "LEMON MaxWeightedMatching: size {lemon_size} cost {}, ours {size} {}",
                        lemon_size * big - weight,
                        exact.cost
                    )
                    .into());
                }
                quality
                    .lemon
                    .push(v["run_seconds"].as_f64().ok_or("no run_seconds")?);
                quality
                    .lemon_cpu
                    .push(v["cpu_run_seconds"].as_f64().ok_or("no cpu")?);
            }
        }
    }
    std::fs::remove_file(&unweighted)?;
    std::fs::remove_file(&weighted)?;
    Ok((ks, quality, dual.node_count() - 2 * size))
}

/// `--ks-only`: KS alone, `calls` times (for a profiler), and its figures.
fn ks_alone(surface: &CoveredSurface, calls: usize) {
    let dual = SurfaceDual::of_cover(&surface.cover);
    let options = KarpSipserOptions::default();
    let (mut best, mut last) = (f64::INFINITY, None);
    for _ in 0..calls {
        let ((wall, _), (pairing, stats, _)) = timed(|| karp_sipser_maximum_with(&dual, &options));
        best = best.min(wall);
        last = Some((pairing.unmatched_count(&dual), stats));
    }
    if let Some((left, stats)) = last {
        eprintln!("KS: {best:.4} s (fastest of {calls}), {left} left, {stats:?}");
    }
}

fn main() -> Result<(), Box<dyn Error>> {
    let args = parse_args()?;
    let work = std::env::temp_dir().join(format!("surftopo_open_peers_{}", std::process::id()));
    std::fs::create_dir_all(&work)?;
    let blender = args
        .python
        .as_ref()
        .is_some_and(|p| peer_version(p, "bpy", "bpy.app.version_string") != "?");
    let (mut quality_table, mut speed_table) = (String::new(), String::new());
    // Per input: per seed, the median and largest KS / LEMON wall ratio of the rounds.
    let mut over_seeds: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    let cpu_start = thread_cpu_seconds();
    for (spec, seed) in args
        .seeds
        .iter()
        .enumerate()
        .flat_map(|(i, &seed)| args.inputs.iter().map(move |spec| (spec, (i, seed))))
    {
        let (first_seed, seed) = (seed.0 == 0, seed.1);
        let (surface, pieces) = make_input(spec, seed)?;
        let triangles = surface.cover.surface_faces().count();
        let kinds: Vec<String> = pieces.iter().map(SurfaceKind::name).collect();
        eprintln!("{spec}: {triangles} triangles, {}", kinds.join(", "));
        if let Some(calls) = args.ks_only {
            ks_alone(&surface, calls);
            continue;
        }
        let (ks, quality, left) = speed(&surface, &args.lemon, args.rounds, first_seed)?;
        let [ko, kl, kr, kc] = ks.summary();
        let per_round = ratios(&ks.ours, &ks.lemon);
        let worst_round = per_round.iter().copied().fold(0.0, f64::max);
        match over_seeds.iter_mut().find(|(s, _)| s == spec) {
            Some((_, medians)) => medians.push((median(&per_round), worst_round)),
            None => over_seeds.push((spec.clone(), vec![(median(&per_round), worst_round)])),
        }
        let [qo, ql, qr, qc] = quality.summary();
        let line = format!(
            "| {spec} | {seed} | {triangles} | {left} | {ko} | {kl} | {kr} | {kc} | {qo} | {ql} | {qr} | {qc} |"
        );
        eprintln!("{line}");
        writeln!(speed_table, "{line}")?;
        let Some(python) = args.python.as_ref().filter(|_| first_seed) else {
            continue;
        };
        let (mut rows, bound) = ours(&surface, &pieces)?;
        let (positions, soup) = surface.to_triangles();
        let input = work.join("input.off");
        write_off_triangles(&positions, &soup, &input)?;
        let mut tools = vec![
            ("gmsh", "Gmsh Blossom recombination"),
            ("gmsh-blossom", "Gmsh Blossom, pairing only"),
        ];
        if blender {
            tools.push(("blender", "Blender join_triangles"));
        }
        for (tool, name) in tools {
            match run_peer(python, tool, &input) {
                Ok(output) => rows.push(QualityRow::of_peer(name, &output)),
                Err(err) => {
                    // A peer's crash is a result too: recorded, not fatal.
                    let why = err.to_string();
                    let why = why.lines().rfind(|l| !l.trim().is_empty()).unwrap_or("");
                    eprintln!("{spec}: {name} failed: {why}");
                    writeln!(
                        quality_table,
                        "| {spec} | {name} | {bound} | failed: {} | | | | | | |",
                        why.trim().replace('|', "/")
                    )?;
                }
            }
        }
        for r in &rows {
            let line = format!(
                "| {spec} | {} | {bound} | {} | {:.1} | {:.1} | {:.2} | {:.3} | {:.3} | {:.3} |",
                r.tool,
                r.triangles_left,
                100.0 * (2 * r.quads) as f64 / triangles as f64,
                r.report.median_max_angle_deviation_degrees,
                r.report.bad_quads_percent,
                r.report.median,
                r.seconds,
                r.cpu_seconds,
            );
            eprintln!("{line}");
            writeln!(quality_table, "{line}")?;
        }
    }
    std::fs::remove_dir_all(&work)?;
    if args.ks_only.is_some() {
        return Ok(());
    }
    let mut md = String::new();
    writeln!(
        md,
        "# Open meshes: surftopo's maximum pairings against the peers\n\nGenerated by \
         `make -C crates/quad/peer && SURFTOPO_MESHES=../shared/meshes cargo run --release -p \
         surftopo-quad --example open_peers -- {}` ({}; a 2-core machine shared with other work; \
         {:.0} s of this thread's CPU). Inputs (seeds {}; the first measured in full, the others (fresh draws) by the KS comparison alone): `holes:MESH:K` = K holes cut around \
         random vertices of a shared mesh; `annulus`, `mobius` (non-orientable), `disk`: the \
         generators' grids after random flips; `genus:G:SIZE:FLIPS:K` = a genus-G surface, \
         flips, K holes.\n",
        args.results.command,
        machine_note(),
        thread_cpu_seconds() - cpu_start,
        args.seeds
            .iter()
            .map(u64::to_string)
            .collect::<Vec<_>>()
            .join(", "),
    )?;
    writeln!(
        md,
        "## Speed on the same dual graphs\n\nKS = `karp_sipser_maximum_with` (its Tutte–Berge \
         barrier included) against LEMON 1.3's `MaxMatching::run()`; exact = \
         `min_cost_maximum_matching` (its certificate included) against LEMON's \
         `MaxWeightedMatching::run()` with weights B − cost (its size and cost checked equal to \
         ours). {} rounds, the order reversed every other round; per round each side's fastest \
         of {CALLS} calls. Seconds: medians over the rounds; ratio: ours / LEMON per round, \
         median (smallest–largest), of wall and of CPU time. left = triangles any pairing \
         leaves.\n\n\
         | input | seed | triangles | left | KS s | LEMON max s | KS / LEMON | (CPU) | exact s | LEMON weighted s | exact / LEMON | (CPU) |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n{speed_table}",
        args.rounds,
    )?;
    if args.seeds.len() > 1 {
        writeln!(
            md,
            "## KS / LEMON over the seeds\n\nPer input: the median KS / LEMON wall ratio of the \
             rounds for each seed (in the order above), the largest of these medians, and the \
             largest ratio of any round.\n\n\
             | input | median per seed | largest median | largest round |\n|---|---|---:|---:|"
        )?;
        for (spec, per_seed) in &over_seeds {
            let medians: Vec<String> = per_seed.iter().map(|(m, _)| format!("{m:.2}")).collect();
            let worst = per_seed.iter().map(|p| p.0).fold(0.0, f64::max);
            let worst_round = per_seed.iter().map(|p| p.1).fold(0.0, f64::max);
            writeln!(
                md,
                "| {spec} | {} | {worst:.2} | {worst_round:.2} |",
                medians.join(", ")
            )?;
        }
        writeln!(md)?;
    }
    if let Some(python) = &args.python {
        writeln!(
            md,
            "## Triangles left and quad quality\n\nGmsh {} (`recombine()` with Blossom, as in \
             `quality_peers`: its topology optimisation and smoothing included, which move and \
             remove vertices; and \"pairing only\", without them, as in `quality_bench`: its \
             quads are pairs of the input's triangles){}; a peer that fails is listed with its \
             message. Every output \
             measured the same way: the corners of each quad in space; dev = median over the \
             quads of max |corner − 90°|; bad = a corner above 170° or below 10°; η = Remacle et \
             al.'s quality; quads % = triangles in quads (Gmsh's relative to the input's \
             triangles). bound = the fewest triangles any pairing of the input leaves (surftopo's \
             verified certificate). Time: surftopo's whole call; the peers' conversion call \
             alone (one run; CPU: this thread's, the peer process's).\n\n\
             | input | tool | bound | triangles left | quads % | dev ° | bad % | η median | seconds | CPU s |\n\
             |---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n{quality_table}",
            peer_version(python, "gmsh", "gmsh.__version__"),
            if blender {
                format!(
                    " and Blender (bpy) {} (`bmesh.ops.join_triangles`, 40° thresholds)",
                    peer_version(python, "bpy", "bpy.app.version_string")
                )
            } else {
                ", Blender (bpy) not installed".into()
            },
        )?;
    }
    args.results.write_markdown(&md)
}
