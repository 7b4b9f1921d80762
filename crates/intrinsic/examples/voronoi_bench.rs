//! The Voronoi wave (Dubois, Appendix D) against edge flipping, side by side in one run: on the
//! shared meshes of about 100k faces (f64 only: their lengths are square roots, so exact mode does
//! not apply), on generated inputs (an icosphere under random intrinsic flips, sheared tori) and on
//! the flat torus T_x for x from 10 to 10⁶ (exact, f64 and flipping).
//!
//! ```text
//! SURFTOPO_MESHES=../shared/meshes cargo run --release -p surftopo-intrinsic \
//!     --example voronoi_bench -- [--out-dir DIR] [--repeat N] [--budget SECONDS] \
//!     [--mesh-timeout SECONDS]
//! ```
//!
//! - Meshes: `flip pipeline` = edge lengths from the positions, [`flip_to_delaunay`], cotan
//!   Laplacian; `voronoi pipeline` = edge lengths, the triangles laid out as a portalgon,
//!   [`voronoi_delaunay`] (V = every vertex), its triangulation, cotan Laplacian. Best of
//!   `--repeat` (default 3) runs each, alternated, in a child process per mesh that is stopped
//!   after `--mesh-timeout` seconds (default 180); the ratio is voronoi / flip.
//! - T_x: one run per x and mode; a mode stops after a failure, or once ten times its last
//!   time exceeds `--budget` seconds (default 120): x grows tenfold from one row to the next.
//! - Results: `results/voronoi.jsonl` and `results/voronoi.md` under `--out-dir` (default: the
//!   workspace root), with this command.

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use serde_json::{Value, json};
use surftopo_intrinsic::generators::{
    flat_torus, flat_torus_portalgon, random_flips, sheared_torus,
};
use surftopo_intrinsic::geometry::{Rational, Scalar};
use surftopo_intrinsic::voronoi::{Sources, VoronoiOptions, voronoi_delaunay};
use surftopo_intrinsic::{
    DelaunayOptions, IntrinsicTriangulation, cotan_laplacian, flip_to_delaunay,
};
use surftopo_testkit::{load, shared_meshes};

struct Args {
    out_dir: PathBuf,
    repeat: usize,
    budget: f64,
    mesh_timeout: f64,
    one_mesh: Option<String>,
    one_generated: Option<usize>,
}

fn parse_args() -> Args {
    let mut args = Args {
        out_dir: Path::new(env!("CARGO_MANIFEST_DIR")).join("../.."),
        repeat: 3,
        budget: 120.0,
        mesh_timeout: 180.0,
        one_mesh: None,
        one_generated: None,
    };
    let mut it = std::env::args().skip(1);
    while let Some(a) = it.next() {
        let mut value = || it.next().unwrap_or_else(|| panic!("{a} needs a value"));
        match a.as_str() {
            "--out-dir" => args.out_dir = PathBuf::from(value()),
            "--repeat" => args.repeat = value().parse::<usize>().expect("--repeat N").max(1),
            "--budget" => args.budget = value().parse().expect("--budget SECONDS"),
            "--mesh-timeout" => {
                args.mesh_timeout = value().parse().expect("--mesh-timeout SECONDS");
            }
            "--one-mesh" => args.one_mesh = Some(value()),
            "--one-generated" => {
                args.one_generated = Some(value().parse().expect("--one-generated K"))
            }
            other => panic!("unknown argument {other}"),
        }
    }
    args
}

/// One mesh, in this (child) process: best of `repeat` alternated runs of both pipelines.
fn measure_mesh(mesh: &surftopo_testkit::SharedMesh, repeat: usize) -> Value {
    let surface = load(mesh);
    let make = || {
        IntrinsicTriangulation::from_positions(surface.mesh.clone(), &surface.positions).unwrap()
    };
    measure(&mesh.file, mesh.faces, make, repeat)
}

/// Best of `repeat` alternated runs of both pipelines on the triangulation `make` builds (its
/// building is timed in both).
fn measure(
    name: &str,
    faces: usize,
    make: impl Fn() -> IntrinsicTriangulation,
    repeat: usize,
) -> Value {
    let (mut best_flip, mut best_wave) = (f64::INFINITY, f64::INFINITY);
    let mut outcome = String::from("ok");
    let mut figures = (0u64, 0usize, 0usize);
    for _ in 0..repeat {
        let start = Instant::now();
        let mut tri = make();
        flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
        std::hint::black_box(cotan_laplacian(&tri));
        best_flip = best_flip.min(start.elapsed().as_secs_f64());

        let start = Instant::now();
        let tri = make();
        let (p, _) = tri.to_portalgon();
        match voronoi_delaunay(&p, &VoronoiOptions::default()) {
            Ok(v) => {
                let t = v.triangulation().unwrap();
                std::hint::black_box(cotan_laplacian(&t));
                best_wave = best_wave.min(start.elapsed().as_secs_f64());
                figures = (
                    v.wave.events,
                    v.wave.max_constellation(),
                    v.tessellation.polygon_count(),
                );
            }
            Err(e) => {
                outcome = format!("refused: {e}");
                break;
            }
        }
    }
    let ratio = best_wave / best_flip;
    json!({
        "kind": "mesh", "mesh": name, "faces": faces,
        "flip_ms": 1e3 * best_flip, "voronoi_ms": 1e3 * best_wave, "ratio": ratio,
        "wave_events": figures.0, "events_per_triangle": figures.0 as f64 / faces as f64,
        "max_constellation": figures.1, "polygons": figures.2, "outcome": outcome,
    })
}

/// The header of a mesh table.
const HEADER: &str = "| mesh | F | flip pipeline | voronoi pipeline | ratio | wave events | \
events / triangle | max \\|X_Δ\\| | polygons | outcome |\n\
|---|---:|---:|---:|---:|---:|---:|---:|---:|---|";

/// One row of a mesh table.
fn row(md: &mut String, name: &str, faces: usize, record: &Value) {
    let f = |k: &str| {
        record[k]
            .as_f64()
            .map_or(String::new(), |x| format!("{x:.2}"))
    };
    let u = |k: &str| record[k].as_u64().map_or(String::new(), |x| x.to_string());
    writeln!(
        md,
        "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
        name,
        faces,
        f("flip_ms"),
        f("voronoi_ms"),
        f("ratio"),
        u("wave_events"),
        record["events_per_triangle"]
            .as_f64()
            .map_or(String::new(), |x| format!("{x:.3}")),
        u("max_constellation"),
        u("polygons"),
        record["outcome"].as_str().unwrap_or("")
    )
    .unwrap();
}

/// How many generated inputs [`generated`] makes.
const GENERATED: usize = 5;

/// Generated input `k`: its name, its face count and a builder.
fn generated(k: usize) -> (String, usize, Box<dyn Fn() -> IntrinsicTriangulation>) {
    if k < 3 {
        let flips = [0u64, 20_000, 100_000][k];
        let ico = surftopo_mesh::generators::icosphere(6);
        let faces = ico.mesh.face_count();
        let make = move || {
            let mut t =
                IntrinsicTriangulation::from_positions(ico.mesh.clone(), &ico.positions).unwrap();
            random_flips(&mut t, flips, 1);
            t
        };
        (
            format!("icosphere 6 + {flips} flips"),
            faces,
            Box::new(make),
        )
    } else {
        let (m, n, shear) = [(250u32, 200u32, 3u32), (500, 100, 20)][k - 3];
        let torus = sheared_torus(m, n, shear);
        let faces = torus.mesh.face_count();
        let make = move || {
            IntrinsicTriangulation::from_positions(torus.mesh.clone(), &torus.positions).unwrap()
        };
        (
            format!("sheared torus {m}×{n} shear {shear}"),
            faces,
            Box::new(make),
        )
    }
}

/// Runs this program on one input (`child_args`) in a child process, stopped after
/// `--mesh-timeout` seconds; its record.
fn in_child(child_args: &[&str], name: &str, faces: usize, args: &Args) -> Value {
    let mut child = std::process::Command::new(std::env::current_exe().unwrap())
        .args(child_args)
        .args(["--repeat", &args.repeat.to_string()])
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let finished = loop {
        if child.try_wait().unwrap().is_some() {
            break true;
        }
        if start.elapsed().as_secs_f64() > args.mesh_timeout {
            child.kill().unwrap();
            child.wait().unwrap();
            break false;
        }
        std::thread::sleep(std::time::Duration::from_millis(100));
    };
    if finished {
        let mut text = String::new();
        std::io::Read::read_to_string(&mut child.stdout.take().unwrap(), &mut text).unwrap();
        serde_json::from_str(text.trim()).unwrap()
    } else {
        json!({"kind": "mesh", "mesh": name, "faces": faces,
               "outcome": format!("did not finish within {} s", args.mesh_timeout)})
    }
}

fn main() {
    let args = parse_args();
    if let Some(k) = args.one_generated {
        let (name, faces, make) = generated(k);
        println!("{}", measure(&name, faces, make, args.repeat));
        return;
    }
    if let Some(file) = &args.one_mesh {
        let mesh = shared_meshes()
            .into_iter()
            .find(|m| &m.file == file)
            .expect("a shared mesh");
        println!("{}", measure_mesh(&mesh, args.repeat));
        return;
    }
    let mut records: Vec<Value> = Vec::new();
    let mut md = String::new();
    let command = format!(
        "SURFTOPO_MESHES=../shared/meshes cargo run --release -p surftopo-intrinsic --example \
         voronoi_bench -- --repeat {} --budget {} --mesh-timeout {}",
        args.repeat, args.budget, args.mesh_timeout
    );
    writeln!(
        md,
        "# Delaunay tessellations: the Voronoi wave against edge flipping\n"
    )
    .unwrap();
    writeln!(
        md,
        "Generated by `{command}`. Machine: 2 cores shared with other jobs.\n"
    )
    .unwrap();

    // Shared meshes of about 100k faces.
    writeln!(md, "## Shared meshes of about 100k faces (f64)\n").unwrap();
    writeln!(
        md,
        "Best of {} alternated runs, milliseconds, file reading excluded. Exact mode does not \
         apply (the lengths of a mesh are square roots).\n",
        args.repeat
    )
    .unwrap();
    writeln!(md, "{HEADER}").unwrap();
    let meshes: Vec<_> = shared_meshes()
        .into_iter()
        .filter(|m| (90_000..=110_000).contains(&m.faces))
        .collect();
    for mesh in &meshes {
        let record = in_child(&["--one-mesh", &mesh.file], &mesh.file, mesh.faces, &args);
        row(&mut md, &mesh.file, mesh.faces, &record);
        eprintln!("{}: {}", mesh.file, record);
        records.push(record);
    }
    if meshes.is_empty() {
        writeln!(md, "\n(SURFTOPO_MESHES not set: no meshes.)").unwrap();
    }

    // Generated inputs (not tuned on): an icosphere re-triangulated by random intrinsic flips
    // and sheared tori, in this process.
    writeln!(md, "\n## Generated inputs (f64)\n").unwrap();
    writeln!(
        md,
        "Built in the run (building timed in both pipelines): `icosphere S + F flips` = the \
         icosphere refined S times, then F random intrinsic flips (seed 1); `sheared torus M×N \
         shear K` = [`sheared_torus`]. Same columns.\n"
    )
    .unwrap();
    writeln!(md, "{HEADER}").unwrap();
    for k in 0..GENERATED {
        let (name, faces, _) = generated(k);
        let record = in_child(&["--one-generated", &k.to_string()], &name, faces, &args);
        row(&mut md, &name, faces, &record);
        eprintln!("{name}: {record}");
        records.push(record);
    }

    // T_x.
    writeln!(md, "\n## The flat torus T_x\n").unwrap();
    writeln!(
        md,
        "One run per x. `exact` = the wave and its dual over the rationals from T_x by exact \
         corners (V = the single vertex); `f64` = the same in doubles; `flip` = edge flipping of \
         T_x by lengths. Seconds; events = points added to the constellations; a mode stops after \
         a failure or once ten times its last time exceeds {} s.\n",
        args.budget
    )
    .unwrap();
    writeln!(
        md,
        "| x | exact s | exact events | events / x | max \\|X_Δ\\| | exact D_x | f64 s | f64 events | \
         f64 outcome | flip s | flips |"
    )
    .unwrap();
    writeln!(md, "|---:|---:|---:|---:|---:|---|---:|---:|---|---:|---:|").unwrap();
    let (mut exact_on, mut f64_on) = (true, true);
    for x in ["10", "100", "1000", "10000", "100000", "1000000"] {
        let xr: Rational = x.parse().unwrap();
        let xf = xr.to_f64();
        let options = VoronoiOptions {
            sources: Sources::Singular,
            ..VoronoiOptions::default()
        };
        let mut row = json!({"kind": "flat_torus", "x": xf});
        let (mut exact_cells, mut f64_cells) = (
            " | | | | | skipped".to_string(),
            " | | | skipped".to_string(),
        );
        if exact_on {
            let p = flat_torus_portalgon(&xr, 1).unwrap();
            let start = Instant::now();
            let v = voronoi_delaunay(&p, &options).unwrap();
            let s = start.elapsed().as_secs_f64();
            let d_x = v.tessellation.polygon_count() == 1 && v.tessellation.side_count() == 4;
            exact_cells = format!(
                " | {s:.3} | {} | {:.2} | {} | {}",
                v.wave.events,
                v.wave.events as f64 / xf,
                v.wave.max_constellation(),
                if d_x { "1 × 2 rectangle" } else { "WRONG" }
            );
            row["exact_s"] = json!(s);
            row["exact_events"] = json!(v.wave.events);
            row["max_constellation"] = json!(v.wave.max_constellation());
            row["exact_d_x"] = json!(d_x);
            // The next x is ten times larger: stop when its run would exceed the budget even
            // at linear growth... or at the quadratic growth the O(k) splices allow.
            exact_on = 10.0 * s <= args.budget;
        }
        if f64_on {
            let p = flat_torus_portalgon(&xf, 1).unwrap();
            let start = Instant::now();
            let result = voronoi_delaunay(&p, &options);
            let s = start.elapsed().as_secs_f64();
            let (events, outcome) = match &result {
                Ok(v) => {
                    let d_x =
                        v.tessellation.polygon_count() == 1 && v.tessellation.side_count() == 4;
                    (
                        v.wave.events,
                        if d_x {
                            "D_x".to_string()
                        } else {
                            "not D_x".to_string()
                        },
                    )
                }
                Err(e) => (0, format!("refused: {e}")),
            };
            f64_cells = format!(" | {s:.3} | {events} | {outcome}");
            row["f64_s"] = json!(s);
            row["f64_events"] = json!(events);
            row["f64_outcome"] = json!(outcome);
            f64_on = result.is_ok() && 10.0 * s <= args.budget;
        }
        let start = Instant::now();
        // T_x by lengths is refused once doubles cannot hold its needle.
        let flips = match flat_torus(xf, 1) {
            Ok(mut tri) => flip_to_delaunay(&mut tri, &DelaunayOptions::default())
                .map(|r| r.flips.to_string())
                .unwrap_or_else(|e| format!("failed: {e}")),
            Err(e) => format!("refused: {e}"),
        };
        let s = start.elapsed().as_secs_f64();
        row["flip_s"] = json!(s);
        row["flips"] = json!(flips);
        writeln!(md, "| {x}{exact_cells}{f64_cells} | {s:.4} | {flips} |").unwrap();
        records.push(row);
        eprintln!("T_{x} done");
    }

    let dir = args.out_dir.join("results");
    std::fs::create_dir_all(&dir).unwrap();
    let mut jsonl = std::fs::File::create(dir.join("voronoi.jsonl")).unwrap();
    for r in &records {
        writeln!(jsonl, "{r}").unwrap();
    }
    std::fs::write(dir.join("voronoi.md"), md).unwrap();
}
