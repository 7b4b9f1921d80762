//! `surftopo delaunay`: the intrinsic Delaunay triangulation by edge flipping (`--method flip`)
//! or by the Voronoi wave of Dubois, Appendix D (`--method voronoi`, optionally `--exact`), or by
//! Dubois' Theorem 1 on flat surfaces (`--method dubois`: Section 4's reduction, then the wave from
//! one vertex), its tessellation, the cotan Laplacian and the lumped mass matrix.

use crate::failure::invalid;
use crate::output::{MatrixFile, write_file, write_matrix};
use std::path::{Path, PathBuf};
use surftopo_intrinsic::dubois::{
    DuboisReport, FlatDelaunayError, FlatDelaunayOptions, delaunay_tessellation_flat,
};
use surftopo_intrinsic::geometry::{Rational, Scalar};
use surftopo_intrinsic::voronoi::{VoronoiDelaunay, VoronoiOptions, voronoi_delaunay};
use surftopo_intrinsic::{
    DEFAULT_COCIRCULAR_TOLERANCE, DEFAULT_LENGTH_TOLERANCE, DelaunayError, DelaunayOptions,
    DelaunayStats, FlipReport, IntrinsicTriangulation, Portalgon, PortalgonDoc, SparseMatrix,
    TriangleStyle, cotan_laplacian, delaunay_tessellation, delaunay_with_stats, lumped_mass,
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
    /// The cotan Laplacian (positive semidefinite: positive diagonal): Matrix Market (symmetric
    /// storage), or `.npz` (scipy.sparse.load_npz reads it).
    #[arg(long)]
    pub laplacian: Option<PathBuf>,
    /// The lumped (barycentric) mass matrix: Matrix Market (symmetric storage), `.npz`, or `.npy`
    /// (its diagonal as a vector).
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
    /// The algorithm and the arithmetic.
    #[command(flatten)]
    pub method: MethodOptions,
}

/// The algorithm computing the Delaunay tessellation.
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Method {
    /// Edge flipping (Bobenko–Springborn).
    #[default]
    Flip,
    /// The multi-source Voronoi wave and its dual (Dubois, Appendix D).
    Voronoi,
    /// Dubois' Theorem 1 on flat closed surfaces: Section 4's reduction (Proposition 2 without
    /// caps), then the wave from one vertex (Proposition 3). Refuses cone points.
    Dubois,
}

/// `--method` and `--exact`, shared by `delaunay` and `isometric`.
#[derive(clap::Args, Clone, Copy, Debug, Default)]
pub struct MethodOptions {
    /// The algorithm: flip (default), voronoi, or dubois (flat surfaces only).
    #[arg(long, value_enum, default_value_t = Method::Flip)]
    pub method: Method,
    /// Compute in exact rational arithmetic (with --method voronoi or dubois; the input must be a
    /// portalgon JSON file given by exact corners).
    #[arg(long)]
    pub exact: bool,
}

impl MethodOptions {
    /// Refuses `--exact` where it cannot apply.
    ///
    /// # Errors
    /// An invalid-input error (exit 2).
    pub fn check(&self) -> anyhow::Result<()> {
        if self.exact && self.method == Method::Flip {
            return Err(invalid(
                "--exact computes with --method voronoi or dubois only (the flip algorithm works on \
                 lengths, which are square roots)",
            ));
        }
        Ok(())
    }
}

/// Reads a portalgon JSON file given by exact corners, for `--exact`.
///
/// # Errors
/// An invalid-input error naming the file: not JSON, not closed, or not given by corners (a mesh
/// or a portalgon given by lengths: their lengths are square roots).
pub fn load_exact(path: &Path) -> anyhow::Result<Portalgon<Rational>> {
    let is_json = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json"));
    if !is_json {
        return Err(invalid(format!(
            "{}: --exact needs a portalgon JSON file given by exact corners (a mesh's lengths are \
             square roots)",
            path.display()
        )));
    }
    let file =
        std::fs::File::open(path).map_err(|e| invalid(format!("{}: {e}", path.display())))?;
    let p = PortalgonDoc::read(std::io::BufReader::new(file))
        .and_then(|doc| doc.to_portalgon_in::<Rational>(0.0))
        .map_err(|e| invalid(format!("{}: {e}", path.display())))?;
    p.check_closed()
        .map_err(|e| invalid(format!("{}: {e}", path.display())))?;
    Ok(p)
}

/// The voronoi and dubois methods' figures for `--json`.
struct WaveFigures {
    events: u64,
    max_constellation: usize,
    arithmetic: &'static str,
    /// The reduction's report (`--method dubois`).
    reduction: Option<DuboisReport>,
}

/// The Delaunay tessellation by the wave (`--method voronoi`: from every vertex) or by Theorem 1
/// on a flat surface (`--method dubois`: reduction, then the wave from one vertex), with its
/// figures. Errors are invalid input (exit 2) naming `input`; a cone point for `--method dubois`
/// names the vertex and suggests the other methods.
fn tessellate<S: Scalar>(
    p: &Portalgon<S>,
    method: Method,
    input: &Path,
) -> anyhow::Result<(VoronoiDelaunay<S>, WaveFigures)> {
    let fail = |e: &dyn std::fmt::Display| invalid(format!("{}: {e}", input.display()));
    let (v, reduction) = if method == Method::Dubois {
        let out =
            crate::progress::step("reducing (Dubois, Section 4) and running the wave", || {
                delaunay_tessellation_flat(p, &FlatDelaunayOptions::default())
            })
            .map_err(|e| match e {
                FlatDelaunayError::ConePoint { .. } => {
                    fail(&format!("{e}; use --method flip or --method voronoi"))
                }
                other => fail(&other),
            })?;
        (out.delaunay, Some(out.reduction))
    } else {
        let v = crate::progress::step("running the Voronoi wave", || {
            voronoi_delaunay(p, &VoronoiOptions::default())
        })
        .map_err(|e| fail(&e))?;
        (v, None)
    };
    let figures = WaveFigures {
        events: v.wave.events,
        max_constellation: v.wave.max_constellation(),
        arithmetic: S::ARITHMETIC,
        reduction,
    };
    Ok((v, figures))
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
    options.method.check()?;
    check_matrix_outputs(options)?;
    if options.method.method != Method::Flip {
        return run_voronoi(options);
    }
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
    write_matrices(options, &tri)?;
    report(options, &stats, None)
}

/// Writes `--laplacian` and `--mass` of a Delaunay triangulation (format by extension:
/// [`crate::output::MatrixFile`]).
fn write_matrices(options: &Options, tri: &IntrinsicTriangulation) -> anyhow::Result<()> {
    if let Some(path) = &options.laplacian {
        let comment = "cotan Laplacian of the intrinsic Delaunay triangulation (positive semidefinite: positive diagonal, off-diagonal -w_ij)";
        let laplacian = cotan_laplacian(tri);
        check_matrix(&laplacian, "the cotan Laplacian", false)?;
        write_matrix(path, &laplacian, comment)?;
    }
    if let Some(path) = &options.mass {
        let comment = "lumped (barycentric) mass matrix: a third of the incident triangle areas";
        let mass = lumped_mass(tri);
        check_matrix(&mass, "the mass matrix", true)?;
        write_matrix(path, &mass, comment)?;
    }
    Ok(())
}

/// Refuses matrix outputs whose extension cannot hold the matrix (a `.npy` Laplacian) before
/// any work.
fn check_matrix_outputs(options: &Options) -> anyhow::Result<()> {
    if let Some(path) = &options.laplacian {
        MatrixFile::of(path, false)?;
    }
    if let Some(path) = &options.mass {
        MatrixFile::of(path, true)?;
    }
    Ok(())
}

/// `--method voronoi` and `--method dubois`: the wave (f64, or exact with `--exact`) and its dual
/// (after the reduction for dubois); the triangulation written is the tessellation cut along
/// shortcuts (by lengths, or by exact corners with `--exact`).
fn run_voronoi(options: &Options) -> anyhow::Result<()> {
    if options.mollify.is_some() || options.max_flips.is_some() {
        return Err(invalid(
            "--mollify and --max-flips apply to --method flip only",
        ));
    }
    let start = std::time::Instant::now();
    let fail = |e: &dyn std::fmt::Display| invalid(format!("{}: {e}", options.input.display()));
    let (tri, figures) = if options.method.exact {
        let p = crate::progress::step("reading", || load_exact(&options.input))?;
        let (v, figures) = tessellate(&p, options.method.method, &options.input)?;
        let triangulated = v.triangulated().map_err(|e| fail(&e))?;
        write_file(&options.output, |w| {
            Ok(PortalgonDoc::from_portalgon(&triangulated).write(w, false)?)
        })?;
        write_tessellation(options, &v.tessellation)?;
        let tri = v.triangulation().map_err(|e| fail(&e))?;
        (tri, figures)
    } else {
        let tri =
            crate::progress::step("reading", || load_intrinsic(&options.input, options.weld))?;
        tri.validate().map_err(|e| fail(&e))?;
        let (p, _) = tri.to_portalgon();
        let (v, figures) = tessellate(&p, options.method.method, &options.input)?;
        let tri = v.triangulation().map_err(|e| fail(&e))?;
        write_file(&options.output, |w| {
            Ok(tri.write_json(w, TriangleStyle::Lengths)?)
        })?;
        write_tessellation(options, &v.tessellation)?;
        (tri, figures)
    };
    let flips = FlipReport {
        flips: 0,
        mollify_delta: None,
        non_delaunay_edges: tri.non_delaunay_edges(surftopo_intrinsic::DEFAULT_TOLERANCE),
    };
    let stats = DelaunayStats::new(&tri, &flips, start.elapsed().as_secs_f64());
    write_matrices(options, &tri)?;
    report(options, &stats, Some(&figures))
}

fn write_tessellation<S: Scalar>(options: &Options, t: &Portalgon<S>) -> anyhow::Result<()> {
    if let Some(path) = &options.tessellation {
        write_file(path, |w| {
            Ok(PortalgonDoc::from_portalgon(t).write(w, false)?)
        })?;
    }
    Ok(())
}

/// Prints the figures (`--json`: the stats with `method`, `arithmetic`, for the voronoi and
/// dubois methods `wave_events` and `max_constellation`, and for dubois the reduction's
/// `outer_iterations`, `inner_passes` (total), `inner_passes_bound` (350·N), `tubes_replaced`
/// (`thin`, `thick`), `peak_active_vertices` and `triangles_after_reduction`).
fn report(
    options: &Options,
    stats: &DelaunayStats,
    wave: Option<&WaveFigures>,
) -> anyhow::Result<()> {
    if options.json {
        let mut value = serde_json::to_value(stats)?;
        if let Some(map) = value.as_object_mut() {
            let method = match options.method.method {
                Method::Flip => "flip",
                Method::Voronoi => "voronoi",
                Method::Dubois => "dubois",
            };
            map.insert("method".into(), method.into());
            map.insert(
                "arithmetic".into(),
                wave.map_or("f64", |w| w.arithmetic).into(),
            );
            if let Some(w) = wave {
                map.insert("wave_events".into(), w.events.into());
                map.insert("max_constellation".into(), w.max_constellation.into());
            }
            if let Some(r) = wave.and_then(|w| w.reduction.as_ref()) {
                map.insert("outer_iterations".into(), r.outer_iterations.into());
                map.insert("inner_passes".into(), r.inner_passes_total.into());
                map.insert("inner_passes_bound".into(), r.inner_passes_bound.into());
                map.insert(
                    "tubes_replaced".into(),
                    serde_json::json!({"thin": r.tubes_replaced_thin, "thick": r.tubes_replaced_thick}),
                );
                map.insert("peak_active_vertices".into(), r.peak_active_vertices.into());
                map.insert(
                    "triangles_after_reduction".into(),
                    r.triangles_after_reduction.into(),
                );
            }
        }
        crate::output::print_json(&value)?;
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
