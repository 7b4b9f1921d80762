//! RS, Schipper and brute force side by side, as in Section 5 of the irreducible-triangulations
//! paper: the shared meshes and the paper's groups B (Table 3: genus-0 brick with 3,844 cavities),
//! C (Table 4: 344 cavities and 3,500 holes, genus 3,500) and D (Table 5: about 4.2M triangles,
//! genus 10 to 3,500), regenerated with `surftopo_mesh::generators::cavity_box`, plus a genus-0
//! scaling series for RS. The brick cannot be coarser than 95,252 triangles (B) or 109,252 (C):
//! where a paper size is below that, the input is, as in the paper, "obtained from B_{i-1} by a
//! simplification process" — here `surftopo_mesh::generators::simplify` (random link-condition
//! contractions, seed [`SIMPLIFY_SEED`]) from the previous input of the group, labelled
//! "(simplified)": B7, B8, B9 and C7.
//!
//! ```text
//! cargo run --release -p surftopo-irreducible --example irreducible_tables -- \
//!     [--groups shared,B,C,D,scaling] [--only B7,B8,B9,C7] [--merge] [--max-triangles N] \
//!     [--time-limit SECONDS] [--algorithms rs,schipper,bf] [--bf-seed N] [--meshes DIR] \
//!     [--out-dir DIR]
//! ```
//!
//! `--only` keeps the inputs whose name (first word) is listed; `--merge` keeps the rows already in
//! `irreducible.jsonl`, replacing those of the same group and input and inserting the others after
//! the last row of their group.
//!
//! Every (input, algorithm) run happens in a child process of this binary (which builds the input
//! again, untimed), so that `--time-limit` (default 600 s) can stop it; a stopped run is reported
//! as a timeout. Two times are recorded per run: `seconds`, the wall-clock time of the algorithm
//! alone ([`Counters::seconds`], as the paper's `run()`), and `cpu_seconds`, the CPU time of the
//! running thread over the same call (Linux `/proc/thread-self/schedstat`; the CPU time of the
//! input check, measured the same way, is subtracted). Runs shorter than a second are repeated
//! until a second has accumulated: `seconds` is then the least wall-clock time and `cpu_seconds`
//! the mean CPU time (the thread CPU clock advances in ticks of a few milliseconds). On a shared
//! machine the wall-clock time mostly measures the other processes, so the ratios t_S/t_RS and
//! t_BF/t_RS use CPU times. Each
//! output is checked (irreducible, same genus) before its figures are accepted. Results go to
//! `results/irreducible.jsonl` (one object per input) and `results/irreducible.md`, rewritten after
//! every input.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use serde::{Deserialize, Serialize};
use surftopo_irreducible::{Algorithm, Counters, SurfaceMesh, is_irreducible, reduce};
use surftopo_mesh::generators::{CavityBox, Surface, icosphere, simplify};

/// Table 3 (group B): triangle counts of B0..B9.
const GROUP_B: [u64; 10] = [
    4_194_296, 2_194_296, 1_194_296, 594_296, 294_296, 144_296, 69_296, 31_796, 16_796, 8_796,
];
/// Table 4 (group C): triangle counts of C0..C7 (genus 3,500).
const GROUP_C: [u64; 8] = [
    4_222_296, 2_222_296, 1_222_296, 722_296, 372_296, 197_296, 97_296, 47_796,
];
/// Table 5 (group D): (genus, triangles) of D0..D9.
const GROUP_D: [(u32, u64); 10] = [
    (3500, 4_222_296),
    (3000, 4_218_296),
    (2500, 4_214_296),
    (2000, 4_210_296),
    (1500, 4_206_296),
    (1000, 4_202_296),
    (500, 4_198_296),
    (100, 4_195_096),
    (50, 4_194_696),
    (10, 4_194_376),
];
/// Genus-0 scaling series for RS (triangle targets of the cavity brick).
const SCALING: [u64; 8] = [
    100_000, 200_000, 400_000, 800_000, 1_600_000, 2_400_000, 3_200_000, 4_194_296,
];

/// Seed of the simplifications that give the inputs below the coarsest brick.
const SIMPLIFY_SEED: u64 = 1;

/// How to build one input (also the child-process argument).
#[derive(Clone, Debug, PartialEq)]
enum Spec {
    /// A shared mesh file.
    Mesh(PathBuf),
    /// `CavityBox::fit(cavities, holes, target)`.
    Box {
        cavities: u32,
        holes: u32,
        target: u64,
    },
    /// `icosphere(s)`.
    Icosphere(u32),
    /// `simplify(base, target, seed)`.
    Simplified {
        base: Box<Spec>,
        target: u64,
        seed: u64,
    },
}

impl Spec {
    fn to_arg(&self) -> String {
        match self {
            Spec::Mesh(p) => format!("mesh:{}", p.display()),
            Spec::Box {
                cavities,
                holes,
                target,
            } => format!("box:{cavities}:{holes}:{target}"),
            Spec::Icosphere(s) => format!("icosphere:{s}"),
            Spec::Simplified { base, target, seed } => {
                format!("simplify:{target}:{seed}:{}", base.to_arg())
            }
        }
    }

    fn from_arg(arg: &str) -> Spec {
        let (kind, rest) = arg.split_once(':').expect("spec kind:args");
        match kind {
            "mesh" => Spec::Mesh(PathBuf::from(rest)),
            "icosphere" => Spec::Icosphere(rest.parse().expect("subdivisions")),
            "simplify" => {
                let mut it = rest.splitn(3, ':');
                let mut number = || it.next().expect("simplify:target:seed:base");
                let target = number().parse().expect("target");
                let seed = number().parse().expect("seed");
                let base = Box::new(Spec::from_arg(number()));
                Spec::Simplified { base, target, seed }
            }
            "box" => {
                let v: Vec<u64> = rest
                    .split(':')
                    .map(|x| x.parse().expect("number"))
                    .collect();
                Spec::Box {
                    cavities: v[0] as u32,
                    holes: v[1] as u32,
                    target: v[2],
                }
            }
            _ => panic!("unknown spec {arg}"),
        }
    }

    /// Triangle count without building, where known.
    fn triangles(&self) -> Option<u64> {
        match self {
            Spec::Mesh(_) => None,
            Spec::Box {
                cavities,
                holes,
                target,
            } => Some(CavityBox::fit(*cavities, *holes, *target).triangle_count()),
            Spec::Icosphere(s) => Some(20 * 4u64.pow(*s)),
            Spec::Simplified { target, .. } => Some(*target),
        }
    }

    fn build(&self) -> SurfaceMesh {
        match self {
            Spec::Mesh(p) => load_mesh(p),
            _ => self.surface().mesh,
        }
    }

    /// The generated surface (positions included); not for shared meshes.
    fn surface(&self) -> Surface {
        match self {
            Spec::Mesh(p) => panic!("{}: only generated inputs are simplified", p.display()),
            Spec::Box {
                cavities,
                holes,
                target,
            } => CavityBox::fit(*cavities, *holes, *target).generate(),
            Spec::Icosphere(s) => icosphere(*s),
            Spec::Simplified { base, target, seed } => {
                simplify(&base.surface(), *target as usize, *seed)
            }
        }
    }
}

fn load_mesh(path: &Path) -> SurfaceMesh {
    let soup = surftopo_io::read_path(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let triangles = soup.triangles().expect("triangles");
    if let Ok((mesh, _)) = surftopo_mesh::build(soup.positions.len(), &triangles) {
        return mesh;
    }
    let (positions, remap) = surftopo_mesh::geometry::weld_exact(&soup.positions);
    let triangles: Vec<[u32; 3]> = triangles
        .iter()
        .map(|t| t.map(|i| remap[i as usize]))
        .collect();
    surftopo_mesh::build(positions.len(), &triangles)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .0
}

/// Sizes of an input.
#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize)]
struct Sizes {
    vertices: usize,
    edges: usize,
    faces: usize,
    genus: i64,
}

/// One run, as reported by a child process.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
struct Run {
    /// "ok", "timeout" or "failed: ...".
    status: String,
    input: Sizes,
    output_vertices: usize,
    link_tests: u64,
    edges_tested_more_than_once: u64,
    contractions: u64,
    /// Wall-clock seconds of the algorithm alone (the least over the repetitions).
    seconds: f64,
    /// Mean CPU seconds of the algorithm alone per repetition.
    cpu_seconds: f64,
    /// Number of timed repetitions (short runs are repeated to accumulate a second).
    repetitions: u32,
}

/// CPU time of the calling thread in seconds (0 where `/proc/thread-self/schedstat` is missing).
fn thread_cpu_seconds() -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<u64>().ok())
        .map_or(0.0, |ns| ns as f64 * 1e-9)
}

/// One table row.
#[derive(Clone, Debug, Serialize, Deserialize)]
struct Row {
    group: String,
    input: String,
    #[serde(flatten)]
    sizes: Sizes,
    rs: Option<Run>,
    schipper: Option<Run>,
    brute_force: Option<Run>,
    bf_seed: u64,
    /// CPU-time ratios.
    t_s_over_t_rs: Option<f64>,
    t_bf_over_t_rs: Option<f64>,
}

struct Options {
    groups: Vec<String>,
    only: Option<Vec<String>>,
    merge: bool,
    max_triangles: u64,
    time_limit: f64,
    algorithms: Vec<String>,
    bf_seed: u64,
    meshes: Option<PathBuf>,
    out_dir: PathBuf,
}

fn parse_options(args: &[String]) -> Options {
    let mut o = Options {
        groups: ["shared", "B", "C", "D", "scaling"]
            .map(String::from)
            .to_vec(),
        only: None,
        merge: false,
        max_triangles: u64::MAX,
        time_limit: 600.0,
        algorithms: ["rs", "schipper", "bf"].map(String::from).to_vec(),
        bf_seed: 1,
        meshes: std::env::var_os("SURFTOPO_MESHES").map(PathBuf::from),
        out_dir: Path::new(env!("CARGO_MANIFEST_DIR")).join("../../results"),
    };
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        let mut value = || {
            it.next()
                .unwrap_or_else(|| panic!("{flag} needs a value"))
                .clone()
        };
        let list = |v: String| v.split(',').map(String::from).collect::<Vec<_>>();
        match flag.as_str() {
            "--groups" => o.groups = list(value()),
            "--only" => o.only = Some(list(value())),
            "--merge" => o.merge = true,
            "--max-triangles" => o.max_triangles = value().parse().expect("--max-triangles N"),
            "--time-limit" => o.time_limit = value().parse().expect("--time-limit SECONDS"),
            "--algorithms" => o.algorithms = list(value()),
            "--bf-seed" => o.bf_seed = value().parse().expect("--bf-seed N"),
            "--meshes" => o.meshes = Some(PathBuf::from(value())),
            "--out-dir" => o.out_dir = PathBuf::from(value()),
            _ => panic!("unknown option {flag} (see the doc comment of this example)"),
        }
    }
    o
}

fn algorithm(name: &str, seed: u64) -> Algorithm {
    match name {
        "rs" => Algorithm::RamaswamiSiqueira,
        "schipper" | "s" => Algorithm::Schipper,
        "bf" | "brute-force" => Algorithm::BruteForce { seed },
        _ => panic!("unknown algorithm {name}"),
    }
}

/// Short runs are repeated until this much wall-clock time has passed...
const MIN_TOTAL_SECONDS: f64 = 1.0;
/// ...or this many calls were made.
const MAX_REPETITIONS: usize = 1_000_000;

/// Calls `f` once, then again while less than `MIN_TOTAL_SECONDS` have passed (the thread CPU
/// clock advances in ticks of a few milliseconds, so one short call says little).
fn repeat(mut f: impl FnMut()) {
    let start = Instant::now();
    let mut n = 0;
    while n == 0 || (start.elapsed().as_secs_f64() < MIN_TOTAL_SECONDS && n < MAX_REPETITIONS) {
        f();
        n += 1;
    }
}

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len().max(1) as f64
}

/// Child process: build the input, run one algorithm (repeated while the runs are short), check
/// the output of the first run, print the run as JSON.
fn worker(spec: &str, name: &str, seed: u64) {
    let mesh = Spec::from_arg(spec).build();
    let input = Sizes {
        vertices: mesh.vertex_count(),
        edges: mesh.edge_count(),
        faces: mesh.face_count(),
        genus: mesh.genus(),
    };
    if let Err(e) = surftopo_irreducible::check_simplicial(&mesh) {
        let run = Run {
            status: format!("failed: {e}"),
            input,
            ..Run::default()
        };
        println!("{}", serde_json::to_string(&run).expect("json"));
        return;
    }
    // CPU time of the input check that every call of `reduce` makes, subtracted below.
    let mut check_cpu = Vec::new();
    repeat(|| {
        let before = thread_cpu_seconds();
        surftopo_irreducible::check_simplicial(&mesh).expect("checked above");
        check_cpu.push(thread_cpu_seconds() - before);
    });
    let algorithm = algorithm(name, seed);
    let (mut first, mut cpu, mut wall) = (None, Vec::new(), f64::INFINITY);
    repeat(|| {
        let copy = mesh.clone();
        let before = thread_cpu_seconds();
        let red = reduce(copy, algorithm).expect("checked above");
        cpu.push(thread_cpu_seconds() - before);
        wall = wall.min(red.counters.seconds);
        first.get_or_insert(red);
    });
    let first = first.expect("one run at least");
    let ok = first.mesh.genus() == input.genus && is_irreducible(&first.mesh);
    let Counters {
        link_tests,
        edges_tested_more_than_once,
        contractions,
        ..
    } = first.counters;
    let run = Run {
        status: if ok { "ok" } else { "failed: not irreducible" }.into(),
        input,
        output_vertices: first.mesh.vertex_count(),
        link_tests,
        edges_tested_more_than_once,
        contractions,
        seconds: wall,
        cpu_seconds: (mean(&cpu) - mean(&check_cpu)).max(0.0),
        repetitions: cpu.len() as u32,
    };
    println!("{}", serde_json::to_string(&run).expect("json"));
}

/// Runs one (input, algorithm) in a child process, killed after `limit` seconds.
fn run_child(spec: &Spec, name: &str, seed: u64, limit: f64) -> Run {
    let exe = std::env::current_exe().expect("current exe");
    let mut child = Command::new(exe)
        .args(["--worker", &spec.to_arg(), name, &seed.to_string()])
        .stdout(Stdio::piped())
        .stderr(Stdio::inherit())
        .spawn()
        .expect("spawn worker");
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().expect("wait") {
            let out = child.wait_with_output().expect("output");
            let text = String::from_utf8_lossy(&out.stdout);
            return match serde_json::from_str(text.trim()) {
                Ok(run) if status.success() => run,
                _ => Run {
                    status: format!("failed: worker exited with {status}"),
                    ..Run::default()
                },
            };
        }
        if start.elapsed().as_secs_f64() > limit {
            child.kill().ok();
            child.wait().ok();
            return Run {
                status: format!("timeout ({limit} s, including building the input)"),
                ..Run::default()
            };
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}

fn inputs(o: &Options) -> Vec<(String, String, Spec)> {
    let mut v: Vec<(String, String, Spec)> = Vec::new();
    let mut push = |group: &str, name: String, spec: Spec| {
        // Targets below the coarsest brick all give the coarsest brick: keep it once.
        let same = |s: &Spec| {
            *s == spec
                || matches!((s, &spec), (Spec::Box { .. }, Spec::Box { .. }) if s.triangles() == spec.triangles())
        };
        let listed = |name: &str| {
            let first = name.split(' ').next().unwrap_or(name);
            o.only.as_ref().is_none_or(|l| l.iter().any(|x| x == first))
        };
        if spec.triangles().is_none_or(|f| f <= o.max_triangles)
            && listed(&name)
            && !v.iter().any(|(g, _, s)| g == group && same(s))
        {
            v.push((group.into(), name, spec));
        }
    };
    for group in &o.groups {
        match group.as_str() {
            "shared" => {
                let Some(dir) = &o.meshes else {
                    eprintln!("no --meshes / SURFTOPO_MESHES: skipping the shared meshes");
                    continue;
                };
                let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)
                    .unwrap_or_else(|e| panic!("--meshes {}: {e}", dir.display()))
                    .map(|e| e.expect("entry").path())
                    .filter(|p| p.to_string_lossy().ends_with(".gz"))
                    .collect();
                paths.sort();
                for p in paths {
                    let name = p.file_name().expect("name").to_string_lossy().into_owned();
                    push("shared", name, Spec::Mesh(p));
                }
            }
            "B" => {
                for (name, spec) in bricks_then_simplified("B", 3844, 0, &GROUP_B) {
                    push("B", name, spec);
                }
            }
            "C" => {
                for (name, spec) in bricks_then_simplified("C", 344, 3500, &GROUP_C) {
                    push("C", name, spec);
                }
            }
            "D" => {
                for (i, &(g, t)) in GROUP_D.iter().enumerate() {
                    let spec = Spec::Box {
                        cavities: 3844 - g,
                        holes: g,
                        target: t,
                    };
                    push("D", format!("D{i}"), spec);
                }
            }
            "scaling" => {
                for &t in &SCALING {
                    let spec = Spec::Box {
                        cavities: 3844,
                        holes: 0,
                        target: t,
                    };
                    push("scaling", format!("brick {t}"), spec);
                }
                for s in 5..=9 {
                    push("scaling", format!("icosphere({s})"), Spec::Icosphere(s));
                }
            }
            other => panic!("unknown group {other}"),
        }
    }
    v
}

/// The inputs of group `prefix`: the brick nearest each size in `sizes`, or, once the brick
/// cannot get coarser (the same brick as the previous size), the previous input simplified to the
/// size.
fn bricks_then_simplified(
    prefix: &str,
    cavities: u32,
    holes: u32,
    sizes: &[u64],
) -> Vec<(String, Spec)> {
    let mut out: Vec<(String, Spec)> = Vec::new();
    let mut previous_brick: Option<u64> = None;
    for (i, &target) in sizes.iter().enumerate() {
        let brick = Spec::Box {
            cavities,
            holes,
            target,
        };
        let triangles = brick.triangles();
        match out.last() {
            Some((_, last)) if triangles == previous_brick => {
                let spec = Spec::Simplified {
                    base: Box::new(last.clone()),
                    target,
                    seed: SIMPLIFY_SEED,
                };
                out.push((format!("{prefix}{i} (simplified)"), spec));
            }
            _ => out.push((format!("{prefix}{i}"), brick)),
        }
        previous_brick = triangles;
    }
    out
}

/// The rows of an earlier `irreducible.jsonl` in `dir` (none if it is missing).
fn read_rows(dir: &Path) -> Vec<Row> {
    let Ok(text) = std::fs::read_to_string(dir.join("irreducible.jsonl")) else {
        return Vec::new();
    };
    text.lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| serde_json::from_str(l).expect("a row of irreducible.jsonl"))
        .collect()
}

/// Puts `row` in place of the row of the same group and input, or after the last row of its
/// group, or at the end.
fn merge_row(rows: &mut Vec<Row>, row: Row) {
    if let Some(old) = rows
        .iter_mut()
        .find(|r| r.group == row.group && r.input == row.input)
    {
        *old = row;
    } else if let Some(i) = rows.iter().rposition(|r| r.group == row.group) {
        rows.insert(i + 1, row);
    } else {
        rows.push(row);
    }
}

/// CPU-time ratio of two successful runs.
fn ratio(a: &Option<Run>, b: &Option<Run>) -> Option<f64> {
    match (a, b) {
        (Some(a), Some(b)) if a.status == "ok" && b.status == "ok" && b.cpu_seconds > 0.0 => {
            Some(a.cpu_seconds / b.cpu_seconds)
        }
        _ => None,
    }
}

/// Seconds as text in s, ms or µs.
fn time(seconds: f64) -> String {
    match seconds {
        s if s >= 1.0 => format!("{s:.2} s"),
        s if s >= 1e-3 => format!("{:.1} ms", s * 1e3),
        s => format!("{:.1} µs", s * 1e6),
    }
}

fn cell(run: &Option<Run>) -> String {
    match run {
        None => "–".into(),
        Some(r) if r.status == "ok" => format!(
            "{} / {} / {} ({}) / {}",
            r.link_tests,
            r.edges_tested_more_than_once,
            time(r.cpu_seconds),
            time(r.seconds),
            r.output_vertices
        ),
        Some(r) => r.status.clone(),
    }
}

/// The 1-minute load average (`/proc/loadavg`), as text.
fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|s| s.split_whitespace().next().map(String::from))
        .unwrap_or_else(|| "?".into())
}

fn write_results(o: &Options, rows: &[Row], load_at_start: &str) {
    std::fs::create_dir_all(&o.out_dir).expect("out dir");
    let mut jsonl = String::new();
    for r in rows {
        jsonl += &serde_json::to_string(r).expect("json");
        jsonl.push('\n');
    }
    std::fs::write(o.out_dir.join("irreducible.jsonl"), jsonl).expect("write jsonl");
    let mut md = String::from(
        "# Irreducible triangulations: RS, Schipper (S), brute force (BF)\n\n\
         Generated by `cargo run --release -p surftopo-irreducible --example irreducible_tables`.\n\
         Each algorithm cell: ℓ (link-condition tests) / ε (edges tested more than once) / CPU \
         time (wall-clock time) of the algorithm alone / output vertices. Ratios are CPU-time \
         ratios. BF: one run, seed in the jsonl (`bf_seed`). Machine: 2 cores shared with other \
         jobs; 1-minute load average {LOAD_START} at the start, {LOAD_NOW} at the last update.\n\n\
         | group | input | V | E | F | g | RS | S | BF | t_S/t_RS | t_BF/t_RS |\n\
         |---|---|---:|---:|---:|---:|---|---|---|---:|---:|\n",
    );
    let fmt = |x: Option<f64>| x.map_or("–".into(), |x| format!("{x:.2}"));
    for r in rows {
        md += &format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            r.group,
            r.input,
            r.sizes.vertices,
            r.sizes.edges,
            r.sizes.faces,
            r.sizes.genus,
            cell(&r.rs),
            cell(&r.schipper),
            cell(&r.brute_force),
            fmt(r.t_s_over_t_rs),
            fmt(r.t_bf_over_t_rs),
        );
    }
    let scaling: Vec<&Row> = rows.iter().filter(|r| r.group == "scaling").collect();
    if !scaling.is_empty() {
        md += "\n## RS on genus 0: time per triangle\n\n| input | F | RS CPU time | wall-clock time | CPU ns per triangle |\n|---|---:|---:|---:|---:|\n";
        for r in scaling {
            if let Some(rs) = r.rs.as_ref().filter(|rs| rs.status == "ok") {
                md += &format!(
                    "| {} | {} | {} | {} | {:.1} |\n",
                    r.input,
                    r.sizes.faces,
                    time(rs.cpu_seconds),
                    time(rs.seconds),
                    rs.cpu_seconds * 1e9 / r.sizes.faces as f64
                );
            }
        }
    }
    let md = md
        .replace("{LOAD_START}", load_at_start)
        .replace("{LOAD_NOW}", &load_average());
    std::fs::write(o.out_dir.join("irreducible.md"), md).expect("write md");
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("--worker") {
        worker(&args[1], &args[2], args[3].parse().expect("seed"));
        return;
    }
    let o = parse_options(&args);
    let load_at_start = load_average();
    let mut rows: Vec<Row> = if o.merge {
        read_rows(&o.out_dir)
    } else {
        Vec::new()
    };
    for (group, name, spec) in inputs(&o) {
        let algorithms: Vec<&str> = if group == "scaling" {
            vec!["rs"]
        } else {
            o.algorithms.iter().map(String::as_str).collect()
        };
        let mut row = Row {
            group,
            input: name,
            sizes: Sizes::default(),
            rs: None,
            schipper: None,
            brute_force: None,
            bf_seed: o.bf_seed,
            t_s_over_t_rs: None,
            t_bf_over_t_rs: None,
        };
        for a in algorithms {
            let run = run_child(&spec, a, o.bf_seed, o.time_limit);
            if run.input.faces > 0 {
                row.sizes = run.input;
            }
            eprintln!(
                "{:8} {:28} {:10} {:>9} {}",
                row.group,
                row.input,
                a,
                row.sizes.faces,
                cell(&Some(run.clone()))
            );
            match algorithm(a, o.bf_seed) {
                Algorithm::RamaswamiSiqueira => row.rs = Some(run),
                Algorithm::Schipper => row.schipper = Some(run),
                Algorithm::BruteForce { .. } => row.brute_force = Some(run),
            }
        }
        row.t_s_over_t_rs = ratio(&row.schipper, &row.rs);
        row.t_bf_over_t_rs = ratio(&row.brute_force, &row.rs);
        merge_row(&mut rows, row);
        write_results(&o, &rows, &load_at_start);
        std::io::stderr().flush().ok();
    }
}
