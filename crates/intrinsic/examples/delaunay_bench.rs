//! Intrinsic Delaunay by edge flipping: flip counts and seconds on the shared meshes and on randomly
//! flipped meshes, with the libigl peer comparison. The paper's own experiment (the flat torus
//! T_x of Section 9) and the sheared tori are in `surftopo-bench papers`
//! (`results/papers/intrinsic.md`).
//!
//! ```text
//! cargo run --release -p surftopo-intrinsic --example delaunay_bench -- \
//!     [--out-dir DIR] [--peer DIR] [--max-faces N] [--repeat N]
//! ```
//!
//! - The shared meshes are found through `SURFTOPO_MESHES` (as in the tests); without it the mesh
//!   tables are skipped.
//! - `--peer DIR`: the output of `crates/intrinsic/peer/libigl_peer.py`; for each mesh it timed,
//!   our Laplacian is compared entry by entry with libigl's (`max |L_ours + L_igl| / max |L|`,
//!   libigl's sign being the opposite) and the times are put side by side.
//! - Results: `results/intrinsic.jsonl` (one object per run, with a `kind`) and
//!   `results/intrinsic.md` (tables), under `--out-dir` (default: the workspace root).
//!
//! Times are best of `--repeat` (default 10) runs, in this process, excluding file reading:
//! `flip` is [`flip_to_delaunay`] alone; `pipeline` is what libigl's `intrinsic_delaunay_cotmatrix`
//! does from (V, F): building the mesh, the edge lengths, the flips and the cotan Laplacian
//! ([`IntrinsicTriangulation::from_soup`] then [`intrinsic_delaunay_laplacian`]).
//! Every result is checked Delaunay by the crate's own counter; the tests check it independently.

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use serde_json::{Value, json};
use surftopo_intrinsic::generators::random_flips;
use surftopo_intrinsic::{
    DelaunayOptions, IntrinsicTriangulation, IsometryOptions, SparseMatrix, flip_to_delaunay,
    intrinsic_delaunay_laplacian, isometric, read_matrix_market,
};
use surftopo_testkit::load;

struct Args {
    out_dir: PathBuf,
    peer: Option<PathBuf>,
    max_faces: usize,
    repeat: usize,
}

fn parse_args() -> Args {
    let mut args = Args {
        out_dir: Path::new(env!("CARGO_MANIFEST_DIR")).join("../.."),
        peer: None,
        max_faces: usize::MAX,
        repeat: 10,
    };
    let mut it = std::env::args().skip(1);
    while let Some(a) = it.next() {
        let mut value = || it.next().unwrap_or_else(|| panic!("{a} needs a value"));
        match a.as_str() {
            "--out-dir" => args.out_dir = PathBuf::from(value()),
            "--peer" => args.peer = Some(PathBuf::from(value())),
            "--max-faces" => args.max_faces = value().parse().expect("--max-faces N"),
            "--repeat" => args.repeat = value().parse::<usize>().expect("--repeat N").max(1),
            other => panic!("unknown argument {other}"),
        }
    }
    args
}

/// CPU time of this thread in seconds (Linux `/proc/thread-self/schedstat`), if available: on a
/// loaded machine it measures the work, not the wait for a core.
fn thread_cpu_seconds() -> Option<f64> {
    let text = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let ns: f64 = text.split_whitespace().next()?.parse().ok()?;
    Some(ns * 1e-9)
}

/// A measured run: best wall-clock seconds over the repeats, and mean thread CPU seconds per run
/// (the CPU clock of `/proc/thread-self/schedstat` only advances at scheduler ticks, so it is
/// read around all the repeats together).
#[derive(Clone, Copy)]
struct Timing {
    wall: f64,
    cpu: Option<f64>,
}

fn best_of<T>(repeat: usize, mut run: impl FnMut() -> T) -> (T, Timing) {
    let mut wall = f64::INFINITY;
    let mut out = None;
    let cpu0 = thread_cpu_seconds();
    for _ in 0..repeat {
        let start = Instant::now();
        let r = run();
        wall = wall.min(start.elapsed().as_secs_f64());
        out = Some(r);
    }
    let cpu = match (cpu0, thread_cpu_seconds()) {
        (Some(a), Some(b)) => Some((b - a) / repeat as f64),
        _ => None,
    };
    (out.expect("repeat >= 1"), Timing { wall, cpu })
}

fn delaunay_options() -> DelaunayOptions {
    DelaunayOptions::default()
}

/// Runs the flip algorithm on clones of `tri`; returns the flipped triangulation, the flip count
/// and the best time (the clone is outside the timed part).
fn time_flips(tri: &IntrinsicTriangulation, repeat: usize) -> (IntrinsicTriangulation, u64, f64) {
    let mut best = f64::INFINITY;
    let mut out = None;
    for _ in 0..repeat {
        let mut t = tri.clone();
        let start = Instant::now();
        let r = flip_to_delaunay(&mut t, &delaunay_options()).expect("Delaunay flips");
        best = best.min(start.elapsed().as_secs_f64());
        assert_eq!(r.non_delaunay_edges, 0);
        out = Some((t, r.flips));
    }
    let (t, flips) = out.expect("repeat >= 1");
    (t, flips, best)
}

fn loops_and_multi_edges(tri: &IntrinsicTriangulation) -> (usize, usize) {
    let s = surftopo_intrinsic::DelaunayStats::new(tri, &Default::default(), 0.0);
    (s.loops, s.multi_edges)
}

fn compare(ours: &SparseMatrix, igl: &SparseMatrix) -> f64 {
    assert_eq!(ours.n, igl.n, "vertex counts differ");
    let scale = ours.values.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    let mut worst = 0.0f64;
    for i in 0..ours.n {
        for (j, v) in ours.row(i) {
            worst = worst.max((v + igl.get(i, j as usize)).abs());
        }
        for (j, v) in igl.row(i) {
            worst = worst.max((ours.get(i, j as usize) + v).abs());
        }
    }
    worst / scale
}

/// The 1-minute load average (Linux `/proc/loadavg`), if available.
fn load_average() -> Option<String> {
    let text = std::fs::read_to_string("/proc/loadavg").ok()?;
    text.split_whitespace().next().map(str::to_string)
}

fn main() {
    let args = parse_args();
    let load_at_start = load_average();
    let mut rows: Vec<Value> = Vec::new();
    let mut md = String::new();
    let _ = writeln!(
        md,
        "# Intrinsic Delaunay by edge flipping\n\nGenerated by `SURFTOPO_MESHES=... cargo run \
         --release -p surftopo-intrinsic --example delaunay_bench{}`. Times in milliseconds, \
         best of {} runs unless said otherwise, file reading excluded. `flip` = \
         `flip_to_delaunay` alone; `pipeline` = build the mesh from (V, F) + edge lengths + flips \
         + cotan Laplacian (what libigl's `intrinsic_delaunay_cotmatrix` does). Machine: 2 cores \
         shared with other jobs (load averages at the end).\n",
        match (args.peer.is_some(), args.repeat) {
            (true, 10) => " -- --peer DIR".to_string(),
            (true, n) => format!(" -- --repeat {n} --peer DIR"),
            (false, 10) => String::new(),
            (false, n) => format!(" -- --repeat {n}"),
        },
        args.repeat
    );

    // 1. Shared meshes.
    let peer: Vec<Value> = args
        .peer
        .as_ref()
        .and_then(|dir| std::fs::read_to_string(dir.join("libigl.jsonl")).ok())
        .map(|t| {
            t.lines()
                .filter_map(|l| serde_json::from_str(l).ok())
                .collect()
        })
        .unwrap_or_default();
    let meshes = surftopo_testkit::shared_meshes();
    if !meshes.is_empty() {
        let _ = writeln!(
            md,
            "## Shared meshes\n\n`flip` and `pipeline` are wall-clock; `pipeline CPU` is this \
             thread's mean CPU time per run (`/proc/thread-self/schedstat`), and `libigl CPU` the \
             mean of Python's `time.thread_time()` around the call (libigl runs it on one thread: \
             `time.process_time()` agrees): on this loaded machine CPU time \
             measures the \
             work rather than the wait for a core, so the speed-ups use CPU times (wall times \
             when CPU times are missing). `w/o build` leaves out building the half-edge mesh \
             (`surftopo_mesh::build`, a separate crate), which libigl's figure includes.\n\n\
             | mesh | V | F | g | flips | flips/E | loops | multi-edges | flip | pipeline | \
             pipeline CPU | libigl | libigl CPU | speed-up (CPU) | speed-up w/o build (CPU) | \
             max rel. diff. vs libigl |\n\
             |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
        );
        for m in meshes.iter().filter(|m| m.faces <= args.max_faces) {
            let s = load(m);
            let (positions, triangles) = s.to_triangles();
            let tri = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap();
            let (flipped, flips, flip_s) = time_flips(&tri, args.repeat);
            let (lap, pipeline) = best_of(args.repeat, || {
                let (mut t, _) = IntrinsicTriangulation::from_soup(&positions, &triangles).unwrap();
                intrinsic_delaunay_laplacian(&mut t, &delaunay_options())
                    .unwrap()
                    .1
            });
            let mesh = tri.mesh().clone();
            let (_, no_build) = best_of(args.repeat, || {
                let mut t =
                    IntrinsicTriangulation::from_positions(mesh.clone(), &s.positions).unwrap();
                intrinsic_delaunay_laplacian(&mut t, &delaunay_options())
                    .unwrap()
                    .1
            });
            let (loops, multi) = loops_and_multi_edges(&flipped);
            let edges = flipped.mesh().edge_count();
            let peer_row = peer.iter().find(|r| r["input"] == m.file.as_str());
            let (igl_wall, igl_cpu, diff) = match (peer_row, &args.peer) {
                (Some(r), Some(dir)) => {
                    let path = dir.join(format!("{}.libigl.mtx", m.file));
                    let file = std::fs::File::open(&path).expect("peer matrix");
                    let igl = read_matrix_market(std::io::BufReader::new(file)).unwrap();
                    (
                        r["seconds"].as_f64(),
                        r["cpu_seconds"].as_f64(),
                        Some(compare(&lap, &igl)),
                    )
                }
                _ => (None, None, None),
            };
            // Speed-ups on CPU time when both sides have it, else on wall time.
            let (ours, theirs, ours_no_build) = match (pipeline.cpu, igl_cpu, no_build.cpu) {
                (Some(a), Some(b), Some(c)) => (a, igl_cpu.map(|_| b), c),
                _ => (pipeline.wall, igl_wall, no_build.wall),
            };
            let speedup = theirs.map(|t| t / ours);
            let speedup_no_build = theirs.map(|t| t / ours_no_build);
            let row = json!({
                "kind": "mesh", "input": m.file, "vertices": m.vertices, "edges": edges,
                "faces": m.faces, "genus": m.genus, "flips": flips, "loops": loops,
                "multi_edges": multi, "flip_seconds": flip_s,
                "pipeline_seconds": pipeline.wall, "pipeline_cpu_seconds": pipeline.cpu,
                "without_build_seconds": no_build.wall, "without_build_cpu_seconds": no_build.cpu,
                "libigl_seconds": igl_wall, "libigl_cpu_seconds": igl_cpu,
                "speedup_vs_libigl": speedup, "speedup_vs_libigl_without_build": speedup_no_build,
                "max_relative_difference_vs_libigl": diff,
            });
            eprintln!("{row}");
            let cell = |x: Option<f64>, f: &dyn Fn(f64) -> String| x.map_or(String::new(), f);
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {} | {:.3} | {} | {} | {:.3} | {:.3} | {} | {} | {} | {} | {} | {} |",
                m.file,
                m.vertices,
                m.faces,
                m.genus,
                flips,
                flips as f64 / edges as f64,
                loops,
                multi,
                1e3 * flip_s,
                1e3 * pipeline.wall,
                cell(pipeline.cpu, &|t| format!("{:.2}", 1e3 * t)),
                cell(igl_wall, &|t| format!("{:.1}", 1e3 * t)),
                cell(theirs, &|t| format!("{:.1}", 1e3 * t)),
                cell(speedup, &|t| format!("{t:.1}x")),
                cell(speedup_no_build, &|t| format!("{t:.1}x")),
                cell(diff, &|d| format!("{d:.1e}")),
            );
            rows.push(row);
        }

        // 2. Randomly flipped meshes (isometric re-triangulations), and the isometry test.
        let _ = writeln!(
            md,
            "\n## Randomly flipped meshes\n\nE random convex intrinsic flips (seed 1), then \
             Delaunay; `isometric` = the Corollary 2 test of the flipped surface against the \
             original (canonical tessellations, flat vertices removed), seconds for both.\n\n\
             | mesh | F | random flips | Delaunay flips | flip | isometric | isometry |\n\
             |---|---:|---:|---:|---:|---|---:|"
        );
        let wanted = [
            "spot.obj.gz",
            "fandisk.obj.gz",
            "armadillo_43k.obj.gz",
            "gargoyle_50k.off.gz",
        ];
        for m in meshes
            .iter()
            .filter(|m| wanted.contains(&m.file.as_str()) && m.faces <= args.max_faces)
        {
            let s = load(m);
            let tri = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap();
            let mut shuffled = tri.clone();
            let made = random_flips(&mut shuffled, tri.mesh().edge_count() as u64, 1);
            let (_, flips, flip_s) = time_flips(&shuffled, args.repeat);
            let start = Instant::now();
            let outcome = isometric(tri, shuffled, &IsometryOptions::default())
                .map(|o| o.to_string())
                .unwrap_or_else(|e| format!("error: {e}"));
            let iso_s = start.elapsed().as_secs_f64();
            let row = json!({
                "kind": "random_flips", "input": m.file, "faces": m.faces,
                "random_flips": made, "flips": flips, "flip_seconds": flip_s,
                "isometry": outcome, "isometry_seconds": iso_s,
            });
            eprintln!("{row}");
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {:.3} | {} | {:.1} |",
                m.file,
                m.faces,
                made,
                flips,
                1e3 * flip_s,
                // The verdict; the reason (a sentence) is in the JSONL row.
                outcome.split(':').next().unwrap_or_default(),
                1e3 * iso_s
            );
            rows.push(row);
        }
    } else {
        eprintln!("no shared meshes (set SURFTOPO_MESHES or --meshes): mesh tables skipped");
    }

    let _ = writeln!(
        md,
        "\n\nThe flat torus T_x (Section 9) and the sheared tori: \
         [papers/intrinsic.md](papers/intrinsic.md).\n"
    );
    if let (Some(a), Some(b)) = (load_at_start, load_average()) {
        let _ = writeln!(
            md,
            "\nMachine load (1-minute load average, 2 cores): {a} at the start of this run, {b} \
             at the end."
        );
    }

    let results = args.out_dir.join("results");
    std::fs::create_dir_all(&results).expect("results directory");
    let mut jsonl = std::fs::File::create(results.join("intrinsic.jsonl")).expect("jsonl");
    for r in &rows {
        writeln!(jsonl, "{r}").expect("write jsonl");
    }
    std::fs::write(results.join("intrinsic.md"), md).expect("write md");
    eprintln!("wrote {}/intrinsic.{{jsonl,md}}", results.display());
}
