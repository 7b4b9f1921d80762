//! `surftopo demo`: the main job on a built-in example, needing no file.

use crate::commands::generate::{self, Kind, Modifiers};
use std::path::Path;

/// Generates a surface, runs every capability on it, writes the results into `out_dir` and prints
/// a summary.
pub fn run(out_dir: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(out_dir)?;
    let kind = Kind::Torus { m: 24, n: 12 };
    let modifiers = Modifiers {
        output: None,
        subdivide: 0,
        flips: 200,
        splits: 0,
        seed: 7,
    };
    let surface = generate::modify(generate::generate(&kind)?, &modifiers)?;
    let input = out_dir.join("input.obj");
    crate::output::write_surface(&input, &surface)?;
    let mesh = &surface.mesh;
    println!("surftopo demo: results in {}", out_dir.display());
    println!(
        "  input        {}: {} vertices, {} edges, {} faces, genus {}",
        input.display(),
        mesh.vertex_count(),
        mesh.edge_count(),
        mesh.face_count(),
        mesh.genus()
    );
    Ok(())
}
