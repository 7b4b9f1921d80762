//! Writing `delaunay`'s outputs against reading its input, side by side in one run.
//!
//! For each input mesh: reading it as `surftopo delaunay` does (file, gzip, parse, half-edge
//! build, edge lengths), flipping to Delaunay, then writing every output to a file next to the
//! others (atomically, temporary name then rename, as the CLI writes): the triangulation as portalgon JSON (the
//! streamed writer `IntrinsicTriangulation::write_json`, and the serde writer of a
//! `PortalgonDoc` for comparison), the Laplacian and the mass matrix as Matrix Market (symmetric
//! storage, general storage, and general storage formatted by `std::fmt` as a reference), as
//! `.npz` and the mass diagonal as `.npy`. Each output is written as a new file (a previous one
//! removed first, untimed: deleting an old file's data is its own cost, measured apart as
//! `D.json over an existing file`). Each figure is the best of `--repeat` runs; the report
//! (`results/output_speed.md`) gives the ratio of writing `-o D.json --laplacian L.mtx` to
//! reading, with the cores and the load average of the machine during the run.

use serde::Serialize;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::Instant;
use surftopo_intrinsic::{
    DelaunayOptions, IntrinsicTriangulation, MatrixStorage, PortalgonDoc, SparseMatrix,
    TriangleStyle, cotan_laplacian, flip_to_delaunay, lumped_mass, write_matrix_market, write_npy,
    write_npz,
};

/// Options of `output-speed`.
#[derive(clap::Args)]
pub struct Options {
    /// Input meshes (default: the ~100k-face meshes koala, gargoyle_50k and seahorse2_100K of
    /// `SURFTOPO_MESHES`).
    inputs: Vec<PathBuf>,
    /// Runs per figure; the best is kept.
    #[arg(long, default_value_t = 5)]
    repeat: usize,
    /// Where the output files are written (default: a temporary folder in the current one, so
    /// that the disk is the one users write to).
    #[arg(long)]
    dir: Option<PathBuf>,
    /// Where to append the JSON lines.
    #[arg(long, default_value = "results/output_speed.jsonl")]
    output: PathBuf,
    /// The Markdown report.
    #[arg(long, default_value = "results/output_speed.md")]
    report: PathBuf,
}

/// One figure: an input, a step, its time and the bytes it wrote.
#[derive(Serialize)]
struct Row {
    input: String,
    faces: usize,
    step: &'static str,
    seconds: f64,
    /// Formatting into memory only (no file).
    memory_seconds: f64,
    bytes: u64,
}

fn best<T>(repeat: usize, mut f: impl FnMut() -> anyhow::Result<T>) -> anyhow::Result<(f64, T)> {
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..repeat.max(1) {
        let t = Instant::now();
        let value = f()?;
        best = best.min(t.elapsed().as_secs_f64());
        last = Some(value);
    }
    Ok((best, last.expect("at least one run")))
}

/// [`best`] of writing `target` as a new file: a file left by the previous run is removed
/// before each run, outside the timing.
fn best_fresh(
    repeat: usize,
    target: &Path,
    mut f: impl FnMut() -> anyhow::Result<u64>,
) -> anyhow::Result<(f64, u64)> {
    let mut best = f64::INFINITY;
    let mut bytes = 0;
    for _ in 0..repeat.max(1) {
        if target.exists() {
            std::fs::remove_file(target)?;
        }
        let t = Instant::now();
        bytes = f()?;
        best = best.min(t.elapsed().as_secs_f64());
    }
    Ok((best, bytes))
}

/// What `surftopo delaunay` does before flipping: read, check, build, measure lengths.
fn read_intrinsic(path: &Path) -> anyhow::Result<IntrinsicTriangulation> {
    let soup = surftopo_io::read_path(path)?;
    let triangles = soup.triangles()?;
    surftopo_mesh::geometry::check_finite(&soup.positions)?;
    let (mesh, report) = surftopo_mesh::build(soup.positions.len(), &triangles)?;
    let mut positions = vec![[0.0; 3]; mesh.vertex_slots()];
    for (old, new) in report.vertex_old_to_new.iter().enumerate() {
        if new.is_valid() {
            positions[new.idx()] = soup.positions[old];
        }
    }
    Ok(IntrinsicTriangulation::from_positions(mesh, &positions)?)
}

/// Writes a file as the CLI does (temporary sibling, renamed) and returns its size.
fn write(
    path: &Path,
    fill: impl FnOnce(&mut dyn Write) -> anyhow::Result<()>,
) -> anyhow::Result<u64> {
    let mut failure = None;
    surftopo_io::atomic_write(path, |file| {
        let mut w = std::io::BufWriter::new(file);
        if let Err(e) = fill(&mut w) {
            failure = Some(e);
            return Err(std::io::Error::other("failed"));
        }
        w.into_inner().map_err(|e| e.into_error())
    })
    .map_err(|e| failure.take().unwrap_or_else(|| e.into()))?;
    Ok(std::fs::metadata(path)?.len())
}

/// The reference: general Matrix Market with every value formatted by `std::fmt` (`{:e}`).
fn write_std_fmt(out: &mut dyn Write, m: &SparseMatrix) -> std::io::Result<()> {
    writeln!(out, "%%MatrixMarket matrix coordinate real general")?;
    writeln!(out, "{} {} {}", m.n, m.n, m.nnz())?;
    for (i, j, v) in m.triplets() {
        writeln!(out, "{} {} {:e}", i + 1, j + 1, v)?;
    }
    Ok(())
}

type Writer<'a> = Box<dyn Fn(&mut dyn Write) -> anyhow::Result<()> + 'a>;

fn measure(name: &str, path: &Path, dir: &Path, repeat: usize) -> anyhow::Result<Vec<Row>> {
    let (read_seconds, mut tri) = best(repeat, || read_intrinsic(path))?;
    let faces = tri.mesh().face_count();
    let t = Instant::now();
    flip_to_delaunay(&mut tri, &DelaunayOptions::default())?;
    let flip_seconds = t.elapsed().as_secs_f64();
    let (laplacian_seconds, laplacian) = best(repeat, || Ok(cotan_laplacian(&tri)))?;
    let mass = lumped_mass(&tri);
    let mut rows = vec![
        Row {
            input: name.into(),
            faces,
            step: "read",
            seconds: read_seconds,
            memory_seconds: 0.0,
            bytes: std::fs::metadata(path)?.len(),
        },
        Row {
            input: name.into(),
            faces,
            step: "flip",
            seconds: flip_seconds,
            memory_seconds: 0.0,
            bytes: 0,
        },
        Row {
            input: name.into(),
            faces,
            step: "assemble laplacian",
            seconds: laplacian_seconds,
            memory_seconds: 0.0,
            bytes: 0,
        },
    ];
    let comment = "cotan Laplacian";
    let symmetric = MatrixStorage::Symmetric;
    let general = MatrixStorage::General;
    let outputs: Vec<(&'static str, &'static str, Writer<'_>)> = vec![
        (
            "D.json",
            "D.json",
            Box::new(|w| Ok(tri.write_json(w, TriangleStyle::Lengths)?)),
        ),
        (
            "D.json serde_json",
            "D.json",
            Box::new(|w| {
                let doc = PortalgonDoc::from_triangulation(&tri, TriangleStyle::Lengths);
                serde_json::to_writer(&mut *w, &doc)?;
                Ok(w.write_all(b"\n")?)
            }),
        ),
        (
            "L.mtx symmetric",
            "L.mtx",
            Box::new(|w| Ok(write_matrix_market(w, &laplacian, comment, symmetric)?)),
        ),
        (
            "L.mtx general",
            "L.mtx",
            Box::new(|w| Ok(write_matrix_market(w, &laplacian, comment, general)?)),
        ),
        (
            "L.mtx general std::fmt",
            "L.mtx",
            Box::new(|w| Ok(write_std_fmt(w, &laplacian)?)),
        ),
        (
            "L.npz",
            "L.npz",
            Box::new(|w| Ok(write_npz(w, &laplacian)?)),
        ),
        (
            "M.mtx symmetric",
            "M.mtx",
            Box::new(|w| Ok(write_matrix_market(w, &mass, comment, symmetric)?)),
        ),
        (
            "M.npy",
            "M.npy",
            Box::new(|w| Ok(write_npy(w, &mass.values)?)),
        ),
    ];
    for (step, file, fill) in &outputs {
        let target = dir.join(file);
        let (seconds, bytes) = best_fresh(repeat, &target, || write(&target, |w| fill(w)))?;
        let (memory_seconds, _) = best(repeat, || {
            let mut bytes = Vec::new();
            fill(&mut bytes)?;
            Ok(bytes.len())
        })?;
        rows.push(Row {
            input: name.into(),
            faces,
            step,
            seconds,
            memory_seconds,
            bytes,
        });
    }
    // The triangulation written again over the file of the same name left by the loop above.
    let (_, _, json) = &outputs[0];
    let target = dir.join("D.json");
    let (seconds, bytes) = best(repeat, || write(&target, |w| json(w)))?;
    let memory_seconds = rows
        .iter()
        .find(|r| r.step == "D.json")
        .map_or(0.0, |r| r.memory_seconds);
    rows.push(Row {
        input: name.into(),
        faces,
        step: "D.json over an existing file",
        seconds,
        memory_seconds,
        bytes,
    });
    Ok(rows)
}

/// Runs the benchmark, appends its rows to `options.output` and writes the report.
pub fn run(options: &Options) -> anyhow::Result<()> {
    let inputs: Vec<PathBuf> = if options.inputs.is_empty() {
        let meshes = std::env::var_os("SURFTOPO_MESHES")
            .ok_or_else(|| anyhow::anyhow!("give input meshes or set SURFTOPO_MESHES"))?;
        [
            "koala.obj.gz",
            "gargoyle_50k.off.gz",
            "seahorse2_100K.off.gz",
        ]
        .iter()
        .map(|f| Path::new(&meshes).join(f))
        .collect()
    } else {
        options.inputs.clone()
    };
    let dir = match &options.dir {
        Some(d) => tempfile::tempdir_in(d)?,
        None => tempfile::tempdir_in(".")?,
    };
    let load_before = load_average();
    let mut rows = Vec::new();
    for path in &inputs {
        let name = path.file_name().map_or_else(
            || path.display().to_string(),
            |n| n.to_string_lossy().into_owned(),
        );
        for row in measure(&name, path, dir.path(), options.repeat)? {
            println!(
                "{:<24} {:>7} {:<26} {:>9.4} s {:>9.4} s {:>10} bytes",
                row.input, row.faces, row.step, row.seconds, row.memory_seconds, row.bytes
            );
            rows.push(row);
        }
    }
    let mut lines = String::new();
    for row in &rows {
        lines.push_str(&serde_json::to_string(row)?);
        lines.push('\n');
    }
    surftopo_bench::append_lines(&options.output, &lines)?;
    println!("appended to {}", options.output.display());
    let machine = Machine {
        cores: std::thread::available_parallelism().map_or(1, |n| n.get()),
        load_before,
        load_after: load_average(),
    };
    std::fs::write(&options.report, report(&rows, options.repeat, &machine))?;
    println!("wrote {}", options.report.display());
    Ok(())
}

/// The machine the figures were taken on.
struct Machine {
    cores: usize,
    /// The one-minute load average (`/proc/loadavg`) before and after the run, when known.
    load_before: Option<f64>,
    load_after: Option<f64>,
}

/// The one-minute load average, on Linux.
fn load_average() -> Option<f64> {
    surftopo_bench::papers::measure::load_average().parse().ok()
}

/// The Markdown report: per input, reading against writing each set of outputs, and every row.
fn report(rows: &[Row], repeat: usize, machine: &Machine) -> String {
    let mut inputs: Vec<&str> = rows.iter().map(|r| r.input.as_str()).collect();
    inputs.dedup();
    let seconds = |input: &str, step: &str| {
        rows.iter()
            .find(|r| r.input == input && r.step == step)
            .map_or(f64::NAN, |r| r.seconds)
    };
    let sets: [(&str, &[&str]); 3] = [
        ("D.json + L.mtx (symmetric)", &["D.json", "L.mtx symmetric"]),
        ("D.json + L.npz", &["D.json", "L.npz"]),
        (
            "reference: serde_json D.json + std::fmt general L.mtx",
            &["D.json serde_json", "L.mtx general std::fmt"],
        ),
    ];
    let load = |l: Option<f64>| l.map_or_else(|| "unknown".to_string(), |l| format!("{l:.1}"));
    let (cores, before, after) = (
        machine.cores,
        load(machine.load_before),
        load(machine.load_after),
    );
    let mut md = String::from(
        "# Writing `delaunay`'s outputs against reading its input\n\n\
         Generated by `cargo run --release -p surftopo-bench -- output-speed` (with \
         `SURFTOPO_MESHES=../shared/meshes`); each figure is the best of ",
    );
    md.push_str(&format!(
        "{repeat} runs, all in one run on a shared machine ({cores} cores, load average {before} \
         before the run and {after} after): compare the ratios. Reading is what `delaunay` does \
         before flipping (gzip, parse, half-edge build, edge lengths); writing is to new files \
         written under a temporary name and renamed as the CLI writes them (text formatted on \
         several threads), a previous file removed first, untimed (see `D.json over \
         an existing file`).\n\n\
         | input | faces | read s | outputs | write s | write / read |\n|---|---|---|---|---|---|\n"
    ));
    for input in &inputs {
        let faces = rows
            .iter()
            .find(|r| r.input == *input)
            .map_or(0, |r| r.faces);
        let read = seconds(input, "read");
        for (name, steps) in &sets {
            let write: f64 = steps.iter().map(|s| seconds(input, s)).sum();
            md.push_str(&format!(
                "| {input} | {faces} | {read:.4} | {name} | {write:.4} | {:.2} |\n",
                write / read
            ));
        }
    }
    md.push_str(
        "\nEvery step (`memory s`: formatting into memory only, no file):\n\n\
         | input | step | s | memory s | bytes |\n|---|---|---|---|---|\n",
    );
    for r in rows {
        md.push_str(&format!(
            "| {} | {} | {:.4} | {:.4} | {} |\n",
            r.input, r.step, r.seconds, r.memory_seconds, r.bytes
        ));
    }
    md
}
