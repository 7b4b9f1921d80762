//! `surftopo demo`: the main job on a built-in example, needing no file.

use crate::commands::generate::{self, Kind, Modifiers};
use crate::commands::irreducible::reduce_surface;
use crate::commands::quad::{quad_soup, quadrangulate_surface};
use crate::output::{emit, write_file};
use std::fmt::Write as _;
use std::path::PathBuf;
use surftopo_intrinsic::{
    DelaunayOptions, IntrinsicTriangulation, TriangleStyle, cotan_laplacian, delaunay_with_stats,
};
use surftopo_irreducible::Algorithm;
use surftopo_quad::QuadAlgorithm;

/// The arguments of `demo`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Folder for the results.
    #[arg(long, default_value = "surftopo-demo")]
    pub out: PathBuf,
}

/// Generates a surface (a genus-2 brick with irregular connectivity), runs every capability on it,
/// writes the results into `--out` and prints a summary.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let out_dir = args.out.as_path();
    std::fs::create_dir_all(out_dir).map_err(|e| crate::failure::unwritable(out_dir, &e))?;
    let mut summary = String::new();
    let kind = Kind::Genus { genus: 2, size: 2 };
    let modifiers = Modifiers {
        output: None,
        format: None,
        subdivide: 1,
        simplify: None,
        flips: 2000,
        splits: 0,
        shuffle_faces: false,
        seed: 7,
    };
    let surface = generate::modify(generate::generate(&kind)?, &modifiers)?;
    let input = out_dir.join("input.obj");
    crate::output::write_surface(&input, &surface)?;
    let mesh = &surface.mesh;
    writeln!(
        summary,
        "surftopo demo: results in {}",
        crate::failure::shown(out_dir)
    )?;
    writeln!(
        summary,
        "  input         {}: genus-2 brick, subdivided, 2000 random flips: {} vertices, {} edges, {} faces, genus {}",
        crate::failure::shown(&input),
        mesh.vertex_count(),
        mesh.edge_count(),
        mesh.face_count(),
        mesh.genus()
    )?;

    let (irreducible, report) = reduce_surface(&surface, Algorithm::RamaswamiSiqueira)?;
    let irreducible_path = out_dir.join("irreducible.obj");
    crate::output::write_surface(&irreducible_path, &irreducible)?;
    writeln!(
        summary,
        "  irreducible   {}: {} vertices, {} edges, {} faces, genus {} (RS: {} contractions, {} link tests, {} edges tested twice, {})",
        crate::failure::shown(&irreducible_path),
        report.output.vertices,
        report.output.edges,
        report.output.faces,
        report.output.genus,
        report.contractions,
        report.link_tests,
        report.edges_tested_more_than_once,
        crate::output::format_seconds(report.seconds)
    )?;

    for algorithm in [QuadAlgorithm::KarpSipser, QuadAlgorithm::Lrs] {
        let result = quadrangulate_surface(&surface, algorithm)?;
        let label = result.stats.algorithm.clone();
        let path = out_dir.join(format!("quads-{label}.obj"));
        crate::output::write_soup(&path, &quad_soup(&surface, &result))?;
        let stats = &result.stats;
        writeln!(
            summary,
            "  quad ({label:<3})    {}: {} quads; initial pairing {:.1}% ({} unpaired), {} flipped edges, {} in all",
            crate::failure::shown(&path),
            result.quads.len(),
            stats.paired_percent,
            stats.unpaired,
            stats.flipped_edges,
            crate::output::format_seconds(stats.total_seconds)
        )?;
    }

    let quality = surftopo_quad::quadrangulate_by_quality(
        &surface.mesh,
        &surface.positions,
        surftopo_quad::QualityObjective::Exact,
    )?;
    let path = out_dir.join("quads-quality.obj");
    crate::output::write_soup(&path, &quad_soup(&surface, &quality.result))?;
    writeln!(
        summary,
        "  quad (quality) {}: {} quads of least total cost 1 - quality ({:.3}, optimum certified); quality median {:.3}, {:.2}% bad quads, {}",
        path.display(),
        quality.result.quads.len(),
        quality.cost,
        quality.report.median,
        quality.report.bad_quads_percent,
        crate::output::format_seconds(quality.result.stats.total_seconds)
    )?;

    let mut tri = IntrinsicTriangulation::from_positions(surface.mesh.clone(), &surface.positions)?;
    let stats = delaunay_with_stats(&mut tri, &DelaunayOptions::default())?;
    let delaunay = out_dir.join("delaunay.json");
    write_file(
        &delaunay,
        |w| Ok(tri.write_json(w, TriangleStyle::Lengths)?),
    )?;
    let laplacian = out_dir.join("laplacian.mtx");
    crate::output::write_matrix(
        &laplacian,
        &cotan_laplacian(&tri),
        "cotan Laplacian (positive semidefinite)",
    )?;
    writeln!(
        summary,
        "  delaunay      {}: {} flips, {} non-Delaunay edges left, {} multi-edges, {}; Laplacian in {}",
        crate::failure::shown(&delaunay),
        stats.flips,
        stats.non_delaunay_edges,
        stats.multi_edges,
        crate::output::format_seconds(stats.seconds),
        crate::failure::shown(&laplacian)
    )?;
    emit(&summary)
}
