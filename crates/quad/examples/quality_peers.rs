//! The quality table against the peer tools: surftopo's pairings (`count` = Karp–Sipser,
//! `quality` = the exact optimum, `quality-fast`) and Gmsh's Blossom recombination and Blender's
//! join_triangles (through `crates/quad/peer/quad_peers.py`), every output measured the same
//! way: the corners of each quad in space (`surftopo_quad::quality::space_corner_angles`), a
//! quad bad when a corner is above 170° or below 10°.
//!
//! ```text
//! SURFTOPO_MESHES=../shared/meshes cargo run --release -p surftopo-quad --example quality_peers -- \
//!     --python PYTHON [--only NAME]... [--out results/quality_peers]
//! ```
//! `PYTHON`: an interpreter with the pip packages `gmsh` and `bpy` (e.g. a venv under `target/`;
//! never needed by the tests). Inputs: armadillo_43k, koala and the shared meshes of 99k–101k
//! triangles. Times: surftopo's whole call (costs, matching, certificate check, quads); the
//! peers' conversion call alone (mesh loading excluded), one run each. Writes `<out>.md`.

mod support;

use std::error::Error;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use support::peers::{peer_version, run_peer};
use support::{Results, thread_cpu_seconds, write_off};
use surftopo_mesh::Surface;
use surftopo_quad::quality::space_quality_report;
use surftopo_quad::{
    QualityObjective, QualityReport, quadrangulate_by_quality, quadrangulate_with_quality,
};

/// One tool's figures on one input.
struct Row {
    tool: &'static str,
    quads: usize,
    triangles_left: usize,
    report: QualityReport,
    seconds: f64,
    cpu_seconds: f64,
}

fn peer(python: &Path, tool: &'static str, input: &Path) -> Result<Row, Box<dyn Error>> {
    let output = run_peer(python, tool, input)?;
    let quads = output.quads();
    Ok(Row {
        tool: if tool == "gmsh" {
            "Gmsh Blossom recombination"
        } else {
            "Blender join_triangles"
        },
        quads: quads.len(),
        triangles_left: output.triangles_left(),
        report: space_quality_report(&output.positions, &quads),
        seconds: output.seconds,
        cpu_seconds: output.cpu_seconds,
    })
}

fn ours(surface: &Surface) -> Result<Vec<Row>, Box<dyn Error>> {
    let (mesh, positions) = (&surface.mesh, &surface.positions);
    let row = |tool, quads: &[[surftopo_mesh::VertexId; 4]], (seconds, cpu_seconds)| {
        let quads: Vec<[usize; 4]> = quads.iter().map(|q| q.map(|v| v.idx())).collect();
        Row {
            tool,
            quads: quads.len(),
            triangles_left: mesh.face_count() - 2 * quads.len(),
            report: space_quality_report(positions, &quads),
            seconds,
            cpu_seconds,
        }
    };
    let (start, cpu) = (Instant::now(), thread_cpu_seconds());
    let count =
        quadrangulate_with_quality(mesh, positions, surftopo_quad::QuadAlgorithm::KarpSipser)?;
    let count_seconds = (start.elapsed().as_secs_f64(), thread_cpu_seconds() - cpu);
    let mut rows = vec![row(
        "surftopo --objective count",
        &count.result.quads,
        count_seconds,
    )];
    for (tool, objective) in [
        ("surftopo --objective quality", QualityObjective::Exact),
        ("surftopo --objective quality-fast", QualityObjective::Fast),
    ] {
        let (start, cpu) = (Instant::now(), thread_cpu_seconds());
        let q = quadrangulate_by_quality(mesh, positions, objective)?;
        let times = (start.elapsed().as_secs_f64(), thread_cpu_seconds() - cpu);
        rows.push(row(tool, &q.result.quads, times));
    }
    Ok(rows)
}

fn main() -> Result<(), Box<dyn Error>> {
    let mut python = None;
    let mut only = Vec::new();
    let (results, given) = Results::from_args("quality_peers")?;
    let mut args = given.into_iter();
    while let Some(a) = args.next() {
        let mut value = || args.next().ok_or(format!("{a} needs a value"));
        match a.as_str() {
            "--python" => python = Some(PathBuf::from(value()?)),
            "--only" => only.push(value()?),
            other => return Err(format!("unknown argument {other}").into()),
        }
    }
    let python = python.ok_or("--python PYTHON is required")?;
    let work = std::env::temp_dir().join(format!("surftopo_quality_peers_{}", std::process::id()));
    std::fs::create_dir_all(&work)?;
    let mut table = String::new();
    for shared in surftopo_testkit::shared_meshes() {
        let name = shared.file.trim_end_matches(".gz").to_string();
        let chosen = name.starts_with("armadillo_43k")
            || name.starts_with("koala")
            || (99_000..=101_000).contains(&shared.faces);
        if !chosen || (!only.is_empty() && !only.iter().any(|o| name.contains(o.as_str()))) {
            continue;
        }
        let surface = surftopo_testkit::load(&shared);
        let input = work.join("input.off");
        write_off(&surface, &input)?;
        let mut rows = ours(&surface)?;
        for tool in ["gmsh", "blender"] {
            rows.push(peer(&python, tool, &input)?);
        }
        let exact_cpu = rows[1].cpu_seconds;
        let triangles = surface.mesh.face_count();
        for r in &rows {
            let line = format!(
                "| {name} | {} | {:.1} | {} | {:.1} | {:.2} | {:.3} | {:.3} | {:.3} | {:.2} |",
                r.tool,
                100.0 * (2 * r.quads) as f64 / triangles as f64,
                r.triangles_left,
                r.report.median_max_angle_deviation_degrees,
                r.report.bad_quads_percent,
                r.report.median,
                r.seconds,
                r.cpu_seconds,
                r.cpu_seconds / exact_cpu,
            );
            eprintln!("{line}");
            writeln!(table, "{line}")?;
        }
    }
    std::fs::remove_dir_all(&work)?;
    let mut md = String::new();
    writeln!(
        md,
        "# Quality against the peer tools\n\nGenerated by `SURFTOPO_MESHES=../shared/meshes cargo run \
         --release -p surftopo-quad --example quality_peers -- {}` on a 2-core machine shared with \
         other work (one run each; times are noisy). Gmsh {} and Blender (bpy) {} from pip, run by \
         `crates/quad/peer/quad_peers.py`.\n\nOne measure for every tool's output: the corners of \
         each quad in space (the angle between its two edges at each vertex); dev = median over \
         the quads of max |corner − 90°|; bad = a corner above 170° or below 10°; η = Remacle et \
         al.'s quality. quads % = triangles in quads. Time: surftopo's whole call (costs, \
         matching, certificate check for the exact one, quads); the peers' conversion call alone \
         (Gmsh's includes its topology optimisation and smoothing, which move and remove \
         vertices: its quads are measured on its own output vertices, and quads % is relative \
         to the input's triangles). seconds: wall clock; CPU s: this thread's CPU time (ours), \
         the process's (peers), robust to the shared machine's load; CPU / exact: over \
         surftopo's exact optimum's.\n",
        results.command,
        peer_version(&python, "gmsh", "gmsh.__version__"),
        peer_version(&python, "bpy", "bpy.app.version_string"),
    )?;
    md.push_str(
        "| input | tool | quads % | triangles left | dev ° | bad % | η median | seconds | CPU s | CPU / exact |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    md.push_str(&table);
    results.write_markdown(&md)
}
