//! `surftopo delaunay`: the intrinsic Delaunay triangulation by edge flipping, its tessellation,
//! the cotan Laplacian and the lumped mass matrix.

use crate::failure::invalid;
use crate::output::write_file;
use std::path::{Path, PathBuf};
use surftopo_intrinsic::{
    DEFAULT_COCIRCULAR_TOLERANCE, DEFAULT_LENGTH_TOLERANCE, DelaunayError, DelaunayOptions,
    IntrinsicTriangulation, PortalgonDoc, TriangleStyle, cotan_laplacian, delaunay_tessellation,
    delaunay_with_stats, lumped_mass, write_matrix_market,
};

/// Options of `delaunay`.
#[derive(clap::Args, Debug)]
pub struct Options {
    /// A mesh file, or a portalgon JSON file (`.json`, see crates/intrinsic/PORTALGON_FORMAT.md).
    pub input: PathBuf,
    /// The Delaunay triangulation, as portalgon JSON.
    #[arg(short, long)]
    pub output: PathBuf,
    /// The Delaunay tessellation (co-circular triangles merged), as portalgon JSON.
    #[arg(long)]
    pub tessellation: Option<PathBuf>,
    /// The cotan Laplacian (positive semidefinite: positive diagonal), Matrix Market.
    #[arg(long)]
    pub laplacian: Option<PathBuf>,
    /// The lumped (barycentric) mass matrix, Matrix Market.
    #[arg(long)]
    pub mass: Option<PathBuf>,
    /// Stop with an error after this many flips.
    #[arg(long)]
    pub max_flips: Option<u64>,
    /// Mollify degenerate input with this epsilon (relative to the mean edge length).
    #[arg(long)]
    pub mollify: Option<f64>,
    /// Merge vertices with exactly equal positions first (mesh input).
    #[arg(long)]
    pub weld: bool,
    /// Print the figures as JSON.
    #[arg(long)]
    pub json: bool,
}

/// Reads a mesh file or a portalgon JSON file as an intrinsic triangulation.
pub fn load_intrinsic(path: &Path, weld: bool) -> anyhow::Result<IntrinsicTriangulation> {
    let is_json = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json"));
    if is_json {
        let file =
            std::fs::File::open(path).map_err(|e| invalid(format!("{}: {e}", path.display())))?;
        return IntrinsicTriangulation::read_json(
            std::io::BufReader::new(file),
            DEFAULT_LENGTH_TOLERANCE,
        )
        .map_err(|e| invalid(format!("{}: {e}", path.display())));
    }
    let loaded = crate::input::read_surface(path, weld)?;
    IntrinsicTriangulation::from_positions(loaded.surface.mesh, &loaded.surface.positions)
        .map_err(|e| invalid(format!("{}: {e}", path.display())))
}

/// Runs `delaunay`.
pub fn run(options: &Options) -> anyhow::Result<()> {
    let mut tri =
        crate::progress::step("reading", || load_intrinsic(&options.input, options.weld))?;
    let flip_options = DelaunayOptions {
        max_flips: options.max_flips,
        mollify: options.mollify,
        ..DelaunayOptions::default()
    };
    let stats = crate::progress::step("flipping to Delaunay", || {
        delaunay_with_stats(&mut tri, &flip_options)
    })
    .map_err(|e| match e {
        DelaunayError::NumericalBreakdown { .. } => anyhow::Error::new(e),
        other => invalid(format!("{}: {other}", options.input.display())),
    })?;
    write_file(&options.output, |w| {
        Ok(tri.write_json(w, TriangleStyle::Lengths)?)
    })?;
    if let Some(path) = &options.tessellation {
        let tessellation = delaunay_tessellation(&tri, DEFAULT_COCIRCULAR_TOLERANCE);
        write_file(path, |w| {
            Ok(PortalgonDoc::from_portalgon(&tessellation.portalgon).write(w, false)?)
        })?;
    }
    if let Some(path) = &options.laplacian {
        let comment = "cotan Laplacian of the intrinsic Delaunay triangulation (positive semidefinite: positive diagonal, off-diagonal -w_ij)";
        write_file(path, |w| {
            Ok(write_matrix_market(w, &cotan_laplacian(&tri), comment)?)
        })?;
    }
    if let Some(path) = &options.mass {
        let comment = "lumped (barycentric) mass matrix: a third of the incident triangle areas";
        write_file(path, |w| {
            Ok(write_matrix_market(w, &lumped_mass(&tri), comment)?)
        })?;
    }
    if options.json {
        crate::output::print_json(&stats)?;
    } else {
        crate::output::emit(&format!(
            "{}: {} vertices, {} edges, {} faces; {} flips, {} non-Delaunay edges, {} loops, {} multi-edges, {:.3} s\n",
            options.output.display(),
            stats.vertices,
            stats.edges,
            stats.faces,
            stats.flips,
            stats.non_delaunay_edges,
            stats.loops,
            stats.multi_edges,
            stats.seconds
        ))?;
    }
    Ok(())
}
