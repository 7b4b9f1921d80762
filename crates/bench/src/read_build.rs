//! Read throughput (OBJ, binary PLY) and half-edge build time, separately and together.
//!
//! Inputs: grid tori of about 1M and 4M triangles, and (when `SURFTOPO_MESHES` is set) the largest
//! shared mesh, `igea.ply.gz`, grown to about 4.3M triangles by two levels of midpoint subdivision.
//! Each figure is the best of `--repeat` runs (machines here are shared and noisy).

use serde::Serialize;
use std::path::{Path, PathBuf};
use std::time::Instant;
use surftopo_io::{PolygonSoup, WriteOptions};
use surftopo_mesh::Surface;
use surftopo_mesh::generators;

/// Options of `read-build`.
#[derive(clap::Args)]
pub struct Options {
    /// Runs per figure; the best is kept.
    #[arg(long, default_value_t = 3)]
    repeat: usize,
    /// Where to append the JSON lines.
    #[arg(long, default_value = "results/read_build.jsonl")]
    output: PathBuf,
}

#[derive(Serialize)]
struct Row {
    input: String,
    format: &'static str,
    triangles: usize,
    file_mb: f64,
    read_seconds: f64,
    read_mb_per_s: f64,
    build_seconds: f64,
    read_and_build_seconds: f64,
}

fn best<T>(repeat: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..repeat.max(1) {
        let t = Instant::now();
        let value = f();
        best = best.min(t.elapsed().as_secs_f64());
        last = Some(value);
    }
    (best, last.expect("at least one run"))
}

fn build(soup: &PolygonSoup) -> anyhow::Result<surftopo_mesh::SurfaceMesh> {
    Ok(surftopo_mesh::build(soup.positions.len(), &soup.triangles()?)?.0)
}

fn measure(name: &str, surface: &Surface, dir: &Path, repeat: usize) -> anyhow::Result<Vec<Row>> {
    let (positions, triangles) = surface.to_triangles();
    let soup = PolygonSoup::from_triangles(positions, &triangles);
    let mut rows = Vec::new();
    for (format, ext) in [("obj", "obj"), ("ply-binary", "ply")] {
        let path = dir.join(format!("{name}.{ext}"));
        surftopo_io::write_path(&path, &soup, &WriteOptions::default())?;
        let bytes = std::fs::metadata(&path)?.len() as f64 / 1e6;
        let (read_seconds, read) = best(repeat, || surftopo_io::read_path(&path));
        let read = read?;
        let (build_seconds, mesh) = best(repeat, || build(&read));
        anyhow::ensure!(
            mesh?.face_count() == triangles.len(),
            "{name}: face count changed"
        );
        let (both, _) = best(repeat, || surftopo_io::read_path(&path).map(|s| build(&s)));
        rows.push(Row {
            input: name.to_string(),
            format,
            triangles: triangles.len(),
            file_mb: bytes,
            read_seconds,
            read_mb_per_s: bytes / read_seconds,
            build_seconds,
            read_and_build_seconds: both,
        });
    }
    Ok(rows)
}

/// Runs the benchmark and appends its rows to `options.output`.
pub fn run(options: &Options) -> anyhow::Result<()> {
    let dir = tempfile::tempdir()?;
    let mut inputs: Vec<(String, Surface)> = vec![
        ("torus-1M".into(), generators::torus(1000, 500)),
        ("torus-4M".into(), generators::torus(2000, 1000)),
    ];
    if let Some(meshes) = std::env::var_os("SURFTOPO_MESHES") {
        let soup = surftopo_io::read_path(&Path::new(&meshes).join("igea.ply.gz"))?;
        let igea = Surface::from_triangles(soup.positions.clone(), &soup.triangles()?)?;
        inputs.push(("igea-x16".into(), generators::subdivide_midpoint(&igea, 2)));
    }
    println!(
        "{:<10} {:<11} {:>10} {:>8} {:>8} {:>9} {:>8} {:>10}",
        "input", "format", "triangles", "MB", "read s", "read MB/s", "build s", "read+build"
    );
    let mut lines = String::new();
    for (name, surface) in &inputs {
        for row in measure(name, surface, dir.path(), options.repeat)? {
            println!(
                "{:<10} {:<11} {:>10} {:>8.1} {:>8.3} {:>9.0} {:>8.3} {:>10.3}",
                row.input,
                row.format,
                row.triangles,
                row.file_mb,
                row.read_seconds,
                row.read_mb_per_s,
                row.build_seconds,
                row.read_and_build_seconds
            );
            lines.push_str(&serde_json::to_string(&row)?);
            lines.push('\n');
        }
    }
    surftopo_bench::append_lines(&options.output, &lines)?;
    println!("appended to {}", options.output.display());
    Ok(())
}
