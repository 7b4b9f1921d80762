//! The exact quality pairing against its peers, side by side in one run: surftopo's
//! `min_cost_perfect_matching` (the matching and its certificate) against LEMON 1.3's
//! `MaxWeightedPerfectMatching::run()` on the same dual graph and integer costs, and the whole
//! `quad --objective quality` call (`quadrangulate_by_quality`: costs, matching, certificate
//! check, quads, quality report) against Gmsh's Blossom recombination of the same triangles
//! (`gmsh.model.mesh.recombine()` without topological optimisation or smoothing, so that its
//! quads too are pairs of the input's triangles).
//!
//! ```text
//! make -C crates/quad/peer
//! SURFTOPO_MESHES=../shared/meshes cargo run --release -p surftopo-quad --example quality_bench -- \
//!     [--lemon crates/quad/peer/lemon_matching] [--python PYTHON] [--rounds R] [--seed S] \
//!     [--input SPEC]... [--out results/quality_bench]
//! ```
//! `PYTHON`: an interpreter with the pip package `gmsh` (a venv; never needed by the tests).
//! Each round runs every tool once on the input, in turn, the order reversed every other round,
//! so that a slow spell of the shared machine hits all of them; a round's paired ratio is
//! ours / LEMON (and Gmsh / ours) within that round. Printed and written per input: the median
//! wall and CPU seconds of each tool (ours: this thread's; LEMON: its `run()`'s thread; Gmsh:
//! its process's, the call alone, mesh loading excluded) and the median, smallest and largest
//! paired ratio. Every round's matching is checked by the certificate verifier, LEMON's optimum
//! must equal ours, and Gmsh's output must keep the input's vertices.
//!
//! SPEC: a shared mesh by the start of its file name (`koala`), `flips:MESH:N` (N random edge
//! flips of a shared mesh: long thin triangles among the others), `splits:MESH:N` (N random
//! vertex splits: small triangles and needles), `genus:G:SIZE:FLIPS` (a genus-G surface with
//! random flips), `icosphere:S`; the random ones drawn with `--seed` (default 1). Without
//! `--input`: armadillo_43k, koala, hand1_50k, `flips:hand1_50k:30000`,
//! `flips:armadillo_43k:50000`, `splits:armadillo_43k:20000`, `genus:40:8:30000`,
//! `genus:120:6:40000`. Writes `<out>.jsonl` and `<out>.md`.

mod support;

use std::error::Error;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use support::peers::run_peer;
use support::{
    Results, Seconds, export_dual, lemon_weighted, machine_note, median, ratio_summary, ratios,
    timed, write_off,
};
use surftopo_matching::weighted::{min_cost_perfect_matching, verify_min_cost_perfect_matching};
use surftopo_mesh::Surface;
use surftopo_mesh::generators::{genus_surface, icosphere, random_flips, random_vertex_splits};
use surftopo_quad::quality::COST_RESOLUTION;
use surftopo_quad::{QualityObjective, pair_costs, quadrangulate_by_quality};

/// The command line (see the module doc).
struct Args {
    /// Where the results go, and the command line.
    results: Results,
    lemon: Option<PathBuf>,
    python: Option<PathBuf>,
    rounds: usize,
    seed: u64,
    inputs: Vec<String>,
    /// The day and the load when the run began.
    began: String,
}

fn parse_args() -> Result<Args, Box<dyn Error>> {
    let (results, given) = Results::from_args("quality_bench")?;
    let mut args = Args {
        results,
        lemon: None,
        python: None,
        rounds: 5,
        seed: 1,
        inputs: Vec::new(),
        began: machine_note(),
    };
    let mut it = given.into_iter();
    while let Some(flag) = it.next() {
        let mut value = || it.next().ok_or(format!("{flag} needs a value"));
        match flag.as_str() {
            "--lemon" => args.lemon = Some(PathBuf::from(value()?)),
            "--python" => args.python = Some(PathBuf::from(value()?)),
            "--rounds" => args.rounds = value()?.parse::<usize>()?.max(1),
            "--seed" => args.seed = value()?.parse()?,
            "--input" => args.inputs.push(value()?),
            other => return Err(format!("unknown argument {other}").into()),
        }
    }
    if args.inputs.is_empty() {
        args.inputs = [
            "armadillo_43k",
            "koala",
            "hand1_50k",
            "flips:hand1_50k:30000",
            "flips:armadillo_43k:50000",
            "splits:armadillo_43k:20000",
            "genus:40:8:30000",
            "genus:120:6:40000",
        ]
        .map(String::from)
        .to_vec();
    }
    Ok(args)
}

/// The shared mesh whose file name starts with `name`.
fn shared(name: &str) -> Result<Surface, Box<dyn Error>> {
    let mesh = surftopo_testkit::shared_meshes()
        .into_iter()
        .find(|m| m.file.starts_with(name))
        .ok_or(format!("no shared mesh {name} (is SURFTOPO_MESHES set?)"))?;
    Ok(surftopo_testkit::load(&mesh))
}

/// The input a SPEC names (see the module doc).
fn make_input(spec: &str, seed: u64) -> Result<Surface, Box<dyn Error>> {
    let parts: Vec<&str> = spec.split(':').collect();
    let number = |i: usize| -> Result<usize, Box<dyn Error>> {
        Ok(parts
            .get(i)
            .ok_or(format!("{spec}: missing field {i}"))?
            .parse()?)
    };
    Ok(match parts[0] {
        "flips" => random_flips(&shared(parts[1])?, number(2)?, seed),
        "splits" => random_vertex_splits(&shared(parts[1])?, number(2)?, seed),
        "genus" => {
            let surface = genus_surface(number(1)? as u32, number(2)? as u32);
            random_flips(&surface, number(3)?, seed)
        }
        "icosphere" => icosphere(number(1)? as u32),
        name => shared(name)?,
    })
}

/// One tool's times over the rounds.
#[derive(Clone, Debug, Default, serde::Serialize)]
struct Times {
    wall: Vec<f64>,
    cpu: Vec<f64>,
}

impl Times {
    fn push(&mut self, (wall, cpu): Seconds) {
        self.wall.push(wall);
        self.cpu.push(cpu);
    }
}

/// One line of the results file.
#[derive(Clone, Debug, Default, serde::Serialize)]
struct Record {
    input: String,
    seed: u64,
    faces: usize,
    genus: i64,
    /// The optimum in integer units (10⁹ per unit of cost).
    cost_units: i64,
    /// `min_cost_perfect_matching`, `quadrangulate_by_quality`, LEMON's `run()`, Gmsh's
    /// `recombine()`, per round.
    matching: Times,
    call: Times,
    lemon: Times,
    gmsh: Times,
    /// The solver's figures (last round): nodes exposed after its greedy and fractional
    /// starts, events popped, tree nodes, blossoms formed, seconds of its phases.
    exposed_after_greedy: usize,
    exposed_after_fractional: usize,
    events: u64,
    tree_nodes: u64,
    shrinks: u64,
    greedy_seconds: f64,
    fractional_seconds: f64,
    search_seconds: f64,
    /// Gmsh: quads made and triangles left.
    gmsh_quads: usize,
    gmsh_triangles_left: usize,
}

/// Gmsh's Blossom recombination once (`quad_peers.py gmsh-blossom`): (wall, CPU) seconds, quads
/// and triangles left; fails when the output does not keep the input's vertices.
fn gmsh_round(
    python: &Path,
    input: &Path,
    vertices: usize,
) -> Result<(Seconds, usize, usize), Box<dyn Error>> {
    let output = run_peer(python, "gmsh-blossom", input)?;
    let kept = output.positions.len();
    if kept != vertices {
        return Err(format!("gmsh: {kept} vertices out of {vertices}").into());
    }
    Ok((
        (output.seconds, output.cpu_seconds),
        output.quads().len(),
        output.triangles_left(),
    ))
}

fn measure(name: &str, surface: &Surface, args: &Args) -> Result<Record, Box<dyn Error>> {
    let mesh = &surface.mesh;
    let costs = pair_costs(mesh, &surface.positions);
    let mut record = Record {
        input: name.into(),
        seed: args.seed,
        faces: mesh.face_count(),
        genus: mesh.genus(),
        ..Record::default()
    };
    let weights: Vec<i64> = costs.iter().map(|c| COST_RESOLUTION as i64 - c).collect();
    let dual = match &args.lemon {
        Some(_) => Some(export_dual(surface, Some(&weights), "quality-bench")?),
        None => None,
    };
    let off = match &args.python {
        Some(_) => {
            let path = std::env::temp_dir().join(format!("surftopo-qb-{}.off", std::process::id()));
            write_off(surface, &path)?;
            Some(path)
        }
        None => None,
    };
    for round in 0..args.rounds {
        let mut tools = [0, 1, 2, 3];
        if round % 2 == 1 {
            tools.reverse();
        }
        for tool in tools {
            match tool {
                0 => {
                    let (times, result) = timed(|| min_cost_perfect_matching(mesh, &costs));
                    let result = result?;
                    let verified = verify_min_cost_perfect_matching(
                        mesh,
                        &costs,
                        &result.edges,
                        &result.certificate,
                    )?;
                    if verified != result.cost || (round > 0 && result.cost != record.cost_units) {
                        return Err(format!("{name}: optimum {} not verified", result.cost).into());
                    }
                    record.cost_units = result.cost;
                    let stats = &result.stats;
                    record.exposed_after_greedy = stats.exposed_after_greedy;
                    record.exposed_after_fractional = stats.exposed_after_fractional;
                    record.events = stats.events;
                    record.tree_nodes = stats.tree_nodes;
                    record.shrinks = stats.shrinks;
                    record.greedy_seconds = stats.greedy_seconds;
                    record.fractional_seconds = stats.fractional_seconds;
                    record.search_seconds = stats.search_seconds;
                    record.matching.push(times);
                }
                1 => {
                    let (times, quads) = timed(|| {
                        quadrangulate_by_quality(mesh, &surface.positions, QualityObjective::Exact)
                    });
                    quads?;
                    record.call.push(times);
                }
                2 => {
                    if let (Some(binary), Some(dual)) = (&args.lemon, &dual) {
                        let (wall, cpu, cost) = lemon_weighted(binary, dual, mesh.face_count(), 1)?;
                        if record.cost_units != 0 && cost != record.cost_units {
                            return Err(format!(
                                "{name}: LEMON's optimum {cost} differs from {}",
                                record.cost_units
                            )
                            .into());
                        }
                        record.lemon.push((wall, cpu));
                    }
                }
                _ => {
                    if let (Some(python), Some(off)) = (&args.python, &off) {
                        let (times, quads, left) =
                            gmsh_round(python, off, surface.positions.len())?;
                        record.gmsh.push(times);
                        record.gmsh_quads = quads;
                        record.gmsh_triangles_left = left;
                    }
                }
            }
        }
    }
    for path in dual.iter().chain(&off) {
        std::fs::remove_file(path)?;
    }
    Ok(record)
}

/// The table row of a record: medians and paired ratios.
fn row(r: &Record) -> String {
    let m = |v: &[f64]| {
        if v.is_empty() {
            "-".into()
        } else {
            format!("{:.3}", median(v))
        }
    };
    format!(
        "| {} | {} | {} | {} / {} | {} / {} | {} | {} | {} / {} | {} / {} | {} | {} | {} |",
        r.input,
        r.faces,
        r.genus,
        m(&r.matching.wall),
        m(&r.matching.cpu),
        m(&r.lemon.wall),
        m(&r.lemon.cpu),
        ratio_summary(&ratios(&r.matching.wall, &r.lemon.wall)),
        ratio_summary(&ratios(&r.matching.cpu, &r.lemon.cpu)),
        m(&r.call.wall),
        m(&r.call.cpu),
        m(&r.gmsh.wall),
        m(&r.gmsh.cpu),
        ratio_summary(&ratios(&r.gmsh.wall, &r.call.wall)),
        ratio_summary(&ratios(&r.gmsh.cpu, &r.call.cpu)),
        if r.gmsh.wall.is_empty() {
            "-".into()
        } else {
            format!("{:.1}", 100.0 * (2 * r.gmsh_quads) as f64 / r.faces as f64)
        },
    )
}

const HEADER: &str = "| input | triangles | genus | ours s (wall / CPU) | LEMON s (wall / CPU) | \
     ours / LEMON, wall | ours / LEMON, CPU | ours call s (wall / CPU) | Gmsh s (wall / CPU) | \
     Gmsh / ours call, wall | Gmsh / ours call, CPU | Gmsh quads % |\n\
     |---|---:|---:|---:|---:|---|---|---:|---:|---|---|---:|";

fn main() -> Result<(), Box<dyn Error>> {
    let args = parse_args()?;
    println!("{HEADER}");
    let mut records = Vec::new();
    for spec in &args.inputs {
        let surface = make_input(spec, args.seed)?;
        let record = measure(spec, &surface, &args)?;
        println!("{}", row(&record));
        eprintln!(
            "  exposed after greedy {} / fractional {}, {} events, {} tree nodes, {} shrinks; \
             greedy {:.3} s, fractional {:.3} s, searches {:.3} s",
            record.exposed_after_greedy,
            record.exposed_after_fractional,
            record.events,
            record.tree_nodes,
            record.shrinks,
            record.greedy_seconds,
            record.fractional_seconds,
            record.search_seconds
        );
        records.push(record);
        args.results.write(&records, &markdown(&records, &args))?;
    }
    Ok(())
}

fn markdown(records: &[Record], args: &Args) -> String {
    let mut md = format!(
        "# The exact quality pairing against LEMON and Gmsh\n\n\
         Generated by `make -C crates/quad/peer && SURFTOPO_MESHES=../shared/meshes cargo run \
         --release -p surftopo-quad --example quality_bench -- {}` on a 2-core machine shared \
         with other work (began {}; {} rounds, each tool once per round, in turn, the order \
         reversed every other round). `ours`: `surftopo_matching::weighted::min_cost_perfect_matching` (the \
         matching and its certificate, verified after every round); LEMON: LEMON 1.3 \
         `MaxWeightedPerfectMatching::run()` on the same dual and integer costs (graph \
         construction excluded; the same optimum checked); `ours call`: \
         `quadrangulate_by_quality` (costs, matching, certificate check, quads, quality report), \
         as `surftopo quad --objective quality` runs it; Gmsh: `gmsh.model.mesh.recombine()` with \
         Blossom recombination and no topological optimisation or smoothing (the same \
         triangles paired; mesh loading excluded). Seconds: medians over the rounds; ratios: \
         median (smallest–largest) of the rounds' paired ratios. CPU: this thread's (ours, \
         LEMON) or the process's (Gmsh).\n\n{HEADER}\n",
        args.results.command, args.began, args.rounds
    );
    for r in records {
        let _ = writeln!(md, "{}", row(r));
    }
    md
}
