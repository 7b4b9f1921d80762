//! `surftopo delaunay`: the intrinsic Delaunay triangulation by edge flipping, its tessellation,
//! the cotan Laplacian and the lumped mass matrix.

use crate::failure::invalid;
use crate::output::write_file;
use std::path::{Path, PathBuf};
use surftopo_intrinsic::{
    DEFAULT_COCIRCULAR_TOLERANCE, DEFAULT_LENGTH_TOLERANCE, DelaunayError, DelaunayOptions,
    IntrinsicTriangulation, PortalgonDoc, SparseMatrix, TriangleStyle, cotan_laplacian,
    delaunay_tessellation, delaunay_with_stats, lumped_mass, write_matrix_market,
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

/// Reads a mesh file or a portalgon JSON file as an intrinsic triangulation, within the limits
/// (`--max-input-bytes` for the text, `--max-elements` for the polygons).
pub fn load_intrinsic(path: &Path, weld: bool) -> anyhow::Result<IntrinsicTriangulation> {
    let is_json = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json"));
    let name = crate::failure::shown(path);
    if is_json {
        let bytes = surftopo_io::load_path(path, &crate::limits::read_limits())
            .map_err(crate::input::explain_limit)?;
        let doc = PortalgonDoc::read(&bytes[..]).map_err(|e| invalid(format!("{name}: {e}")))?;
        drop(bytes);
        crate::limits::check_elements(&name, doc.polygons.len() as u64, "polygons")?;
        return doc
            .to_triangulation(DEFAULT_LENGTH_TOLERANCE)
            .map_err(|e| invalid(format!("{name}: {e}")));
    }
    let loaded = crate::input::read_surface(path, weld)?;
    IntrinsicTriangulation::from_positions(loaded.surface.mesh, &loaded.surface.positions)
        .map_err(|e| invalid(format!("{name}: {e}")))
}

/// Refuses to write a matrix with a non-finite entry, or (`positive_diagonal`: the mass matrix,
/// whose diagonal holds areas) a diagonal entry that is not a positive normal number: the areas
/// are beyond double precision's range (they overflow or underflow), and writing them would give
/// `inf` or a silently zero matrix. Lengths themselves are handled scale-free
/// (`surftopo_intrinsic::trig`; cotan weights do not depend on the scale), so this happens only
/// when the results are not representable. (A Laplacian may have a zero diagonal: a one-vertex
/// torus.)
fn check_matrix(matrix: &SparseMatrix, what: &str, positive_diagonal: bool) -> anyhow::Result<()> {
    if let Some((i, j, v)) = matrix.triplets().find(|t| !t.2.is_finite()) {
        return Err(invalid(format!(
            "{what}: entry ({}, {}) is {v}: beyond double precision's range (scale the input)",
            i + 1,
            j + 1
        )));
    }
    let small = (0..matrix.n)
        .map(|i| (i, matrix.get(i, i)))
        .find(|&(_, v)| v.is_nan() || v < f64::MIN_POSITIVE);
    if let Some((i, v)) = small.filter(|_| positive_diagonal) {
        return Err(invalid(format!(
            "{what}: diagonal entry {} is {v:e}, not a positive normal number: the triangles are \
             too small for double precision (scale the input)",
            i + 1
        )));
    }
    Ok(())
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
        other => invalid(format!(
            "{}: {other}",
            crate::failure::shown(&options.input)
        )),
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
        let laplacian = cotan_laplacian(&tri);
        check_matrix(&laplacian, "the cotan Laplacian", false)?;
        write_file(path, |w| Ok(write_matrix_market(w, &laplacian, comment)?))?;
    }
    if let Some(path) = &options.mass {
        let comment = "lumped (barycentric) mass matrix: a third of the incident triangle areas";
        let mass = lumped_mass(&tri);
        check_matrix(&mass, "the mass matrix", true)?;
        write_file(path, |w| Ok(write_matrix_market(w, &mass, comment)?))?;
    }
    if options.json {
        crate::output::print_json(&stats)?;
    } else {
        crate::output::emit(&format!(
            "{}: {} vertices, {} edges, {} faces; {} flips, {} non-Delaunay edges, {} loops, {} multi-edges, {:.3} s\n",
            crate::failure::shown(&options.output),
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
