//! `surftopo delaunay`: the intrinsic Delaunay triangulation by edge flipping (`--method flip`)
//! or by the Voronoi wave of Dubois, Appendix D (`--method voronoi`, optionally `--exact`), or by
//! Dubois' Theorem 1 (`--method dubois`: Section 8's caps around the cone points, Section 4's
//! reduction of the flat remainder, the caps put back, then the wave from the singular vertices —
//! one vertex on a flat torus), or the method `surftopo_intrinsic::method_choice` picks
//! (`--method auto`, the default), its tessellation, the cotan Laplacian and the lumped mass
//! matrix.

use crate::args::{JsonArg, WeldArg};
use crate::failure::invalid;
use crate::output::{OutputKind, Outputs};
use std::path::{Path, PathBuf};
use surftopo_intrinsic::dubois::{
    DuboisReport, FlatDelaunayOptions, ReduceOptions, delaunay_tessellation_dubois,
};
use surftopo_intrinsic::geometry::{Rational, Scalar};
use surftopo_intrinsic::method_choice::{
    Method as Choice, choose_method, choose_method_for_needle,
};
use surftopo_intrinsic::voronoi::{VoronoiDelaunay, VoronoiOptions, voronoi_delaunay};
use surftopo_intrinsic::{
    DEFAULT_COCIRCULAR_TOLERANCE, DEFAULT_LENGTH_TOLERANCE, DelaunayError, DelaunayOptions,
    DelaunayStats, FlipReport, IntrinsicTriangulation, Portalgon, PortalgonDoc, PortalgonError,
    SparseMatrix, TriangleStyle, cotan_laplacian, delaunay_tessellation, delaunay_with_stats,
    delaunay_with_stats_unless_needle, lumped_mass,
};

/// The arguments of `delaunay`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// A mesh file, or a portalgon JSON file (`.json`, see crates/intrinsic/PORTALGON_FORMAT.md);
    /// `-` for standard input (JSON when it starts with `{`, else a mesh told by its content).
    pub input: PathBuf,
    /// The Delaunay triangulation, as portalgon JSON (.json). Optional: at least one output
    /// (this, --tessellation, --reduced, --laplacian, --mass) or --json is needed.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// The Delaunay tessellation (co-circular triangles merged), as portalgon JSON (.json).
    #[arg(long)]
    pub tessellation: Option<PathBuf>,
    /// The cotan Laplacian (positive semidefinite: positive diagonal): Matrix Market (.mtx,
    /// symmetric storage), or `.npz` (scipy.sparse.load_npz reads it).
    #[arg(long)]
    pub laplacian: Option<PathBuf>,
    /// The lumped (barycentric) mass matrix: Matrix Market (.mtx, symmetric storage), `.npz`, or
    /// `.npy` (its diagonal as a vector).
    #[arg(long)]
    pub mass: Option<PathBuf>,
    /// Stop with an error after this many flips.
    #[arg(long)]
    pub max_flips: Option<u64>,
    /// Mollify degenerate input with this epsilon (relative to the mean edge length).
    #[arg(long)]
    pub mollify: Option<f64>,
    #[command(flatten)]
    pub weld: WeldArg,
    #[command(flatten)]
    pub json: JsonArg,
    /// Corollary 1: the low-happiness triangulation after Dubois' reduction, as portalgon JSON
    /// (with --method dubois; --method auto then takes dubois).
    #[arg(long, value_name = "OUT.json")]
    pub reduced: Option<PathBuf>,
    /// The algorithm and the arithmetic.
    #[command(flatten)]
    pub method: MethodOptions,
}

/// The algorithm computing the Delaunay tessellation.
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Method {
    /// Flipping unless a triangle's aspect ratio ℓ²/(2A) exceeds 1e5 (flipping would need about
    /// √(2·aspect) flips and lose digits in double precision); then dubois on a flat surface,
    /// flipping with cone points (voronoi with --exact). --mollify or --max-flips ask for flip,
    /// --reduced for dubois.
    #[default]
    Auto,
    /// Edge flipping (Bobenko–Springborn).
    Flip,
    /// The multi-source Voronoi wave and its dual (Dubois, Appendix D).
    Voronoi,
    /// Dubois' Theorem 1: Proposition 2 (Section 8's caps around the cone points, Section 4's
    /// reduction of the flat remainder, the caps put back), then the wave from the singular
    /// vertices (Proposition 3).
    Dubois,
}

impl Method {
    /// The method [`choose_method`]'s answer names; in exact mode flipping (which works on
    /// lengths) becomes the exact wave.
    pub fn chosen(choice: Choice, exact: bool) -> Self {
        match choice {
            Choice::Dubois => Method::Dubois,
            Choice::Voronoi => Method::Voronoi,
            Choice::Flip if exact => Method::Voronoi,
            Choice::Flip => Method::Flip,
        }
    }
}

/// `--method` and `--exact`, shared by `delaunay` and `isometric`.
#[derive(clap::Args, Clone, Copy, Debug, Default)]
pub struct MethodOptions {
    /// The algorithm: auto (default), flip, voronoi, or dubois.
    #[arg(long, value_enum, default_value_t = Method::Auto)]
    pub method: Method,
    /// Compute in exact rational arithmetic (with --method voronoi or dubois; the input must be a
    /// portalgon JSON file given by exact corners).
    #[arg(long)]
    pub exact: bool,
    /// With --method dubois: run all 350 inner repetitions of ALGORITHM (Section 4.5) per outer
    /// iteration, as the paper does, instead of stopping at the first repetition that changes
    /// nothing (the output is the same; slower).
    #[arg(long)]
    pub faithful: bool,
}

impl MethodOptions {
    /// Refuses `--exact` where it cannot apply.
    ///
    /// # Errors
    /// An invalid-input error (exit 2).
    pub fn check(&self) -> anyhow::Result<()> {
        if self.faithful && self.method != Method::Dubois {
            return Err(invalid("--faithful applies to --method dubois only"));
        }
        if self.exact && self.method == Method::Flip {
            return Err(invalid(
                "--exact computes with --method voronoi or dubois only (the flip algorithm works on \
                 lengths, which are square roots)",
            ));
        }
        Ok(())
    }

    /// Proposition 2's reduction options (`--faithful`).
    pub fn reduce_options(&self) -> ReduceOptions {
        ReduceOptions {
            faithful: self.faithful,
            ..ReduceOptions::default()
        }
    }
}

/// Reads a portalgon JSON file given by exact corners, for `--exact`.
///
/// # Errors
/// An invalid-input error naming the file: not JSON, not closed, or not given by corners (a mesh
/// or a portalgon given by lengths: their lengths are square roots).
pub fn load_exact(path: &Path) -> anyhow::Result<Portalgon<Rational>> {
    if !is_json_input(path)? {
        return Err(invalid(format!(
            "{}: --exact needs a portalgon JSON file given by exact corners (a mesh's lengths are \
             square roots)",
            path.display()
        )));
    }
    let name = crate::input::name(path);
    let bytes = crate::input::input_bytes(path)?;
    let p = PortalgonDoc::from_slice(&bytes)
        .and_then(|doc| doc.to_portalgon_in::<Rational>(0.0))
        .map_err(|e| invalid(format!("{name}: {e}")))?;
    p.check_closed()
        .map_err(|e| invalid(format!("{name}: {e}")))?;
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

/// The tessellation of [`tessellate`], its figures, and (dubois) the reduced triangulation.
type Tessellated<S> = (VoronoiDelaunay<S>, WaveFigures, Option<Portalgon<S>>);

/// The Delaunay tessellation by the wave (`--method voronoi`: from every vertex) or by Theorem 1
/// (`--method dubois`: caps, reduction, caps back, then the wave from the singular vertices), with
/// its figures. Errors are invalid input (exit 2) naming `input`, except a numerical refusal of
/// the `f64` wave ([`surftopo_intrinsic::voronoi::VoronoiError::is_numerical`], exit 4) and any
/// failure of dubois in `f64` on the validated input (exit 4).
fn tessellate<S: Scalar>(
    p: &Portalgon<S>,
    method: Method,
    reduce: ReduceOptions,
    input: &Path,
) -> anyhow::Result<Tessellated<S>> {
    let fail = |e: &dyn std::fmt::Display| invalid(format!("{}: {e}", input.display()));
    let (v, reduction, reduced) = if method == Method::Dubois {
        let out = crate::progress::step(
            "reducing (Dubois, Sections 8 and 4) and running the wave",
            || {
                // V = the input's vertices, as flip and voronoi (Section 1's footnote 1), so the
                // Laplacian has a row per input vertex; a flat surface gets Theorem 1's one.
                let options = FlatDelaunayOptions {
                    reduce,
                    sources: surftopo_intrinsic::voronoi::Sources::All,
                    ..FlatDelaunayOptions::default()
                };
                delaunay_tessellation_dubois(p, &options)
            },
        )
        .map_err(|e| {
            // The input was validated: in f64 a failure is rounding breaking a check (exit 4).
            if S::EXACT {
                fail(&e)
            } else {
                crate::failure::numerical(format!(
                    "{}: {e} (a numerical failure of double precision: try --exact on exact \
                     input, or --method flip)",
                    input.display()
                ))
            }
        })?;
        (out.delaunay, Some(out.reduction), Some(out.reduced))
    } else {
        let v = crate::progress::step("running the Voronoi wave", || {
            voronoi_delaunay(p, &VoronoiOptions::default())
        })
        .map_err(|e| {
            if !S::EXACT && e.is_numerical() {
                crate::failure::numerical(format!(
                    "{}: {e} (a numerical failure of double precision: try --exact on exact \
                     input, or --method flip)",
                    input.display()
                ))
            } else {
                fail(&e)
            }
        })?;
        (v, None, None)
    };
    let figures = WaveFigures {
        events: v.wave.events,
        max_constellation: v.wave.max_constellation(),
        arithmetic: S::ARITHMETIC,
        reduction,
    };
    Ok((v, figures, reduced))
}

/// Whether an input is portalgon JSON: a `.json` file, or standard input starting with `{`.
fn is_json_input(path: &Path) -> anyhow::Result<bool> {
    if crate::input::is_stdio(path) {
        return crate::input::stdin_is_json();
    }
    Ok(path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json")))
}

/// Reads a mesh file or a portalgon JSON file (a triangulation, or a tessellation whose polygons
/// are then cut into triangles along shortcuts) as an intrinsic triangulation, within the limits
/// (`--max-input-bytes` for the text, `--max-elements` for the polygons).
pub fn load_intrinsic(path: &Path, weld: bool) -> anyhow::Result<IntrinsicTriangulation> {
    load_numbered(path, weld).map(|(tri, _)| tri)
}

/// Where the matrices' rows go in the input's vertex numbering: the input index of each vertex
/// id of the triangulation read ([`surftopo_mesh::BuildReport::input_vertices`]), and the
/// input's vertex count (vertices in no face get empty rows and columns).
pub struct InputNumbering {
    input_vertices: Vec<u32>,
    count: usize,
    /// The file's face (polygon) of each triangle, when polygons were cut.
    polygon_of: Option<Vec<u32>>,
}

impl InputNumbering {
    /// `matrix` (rows: the live vertices of `tri` in id order) on the input's rows and columns;
    /// the matrix as it is when `tri` has vertex ids the input does not (none in practice: the
    /// algorithms keep the vertices read).
    fn on_input_rows(&self, tri: &IntrinsicTriangulation, matrix: SparseMatrix) -> SparseMatrix {
        let rows = tri.matrix_rows();
        let mut row_to_input = vec![0u32; matrix.n];
        for (v, &row) in rows.iter().enumerate() {
            match (
                row_to_input.get_mut(row as usize),
                self.input_vertices.get(v),
            ) {
                (Some(slot), Some(&input)) => *slot = input,
                (None, _) => {}
                (Some(_), None) => return matrix,
            }
        }
        let triplets: Vec<(u32, u32, f64)> = matrix
            .triplets()
            .map(|(i, j, v)| (row_to_input[i as usize], row_to_input[j as usize], v))
            .collect();
        SparseMatrix::from_triplets(self.count, &triplets)
    }
}

/// [`load_intrinsic`], with the input's vertex numbering for a mesh file (`None` for a portalgon
/// file, whose vertices are its own).
pub fn load_numbered(
    path: &Path,
    weld: bool,
) -> anyhow::Result<(IntrinsicTriangulation, Option<InputNumbering>)> {
    let name = crate::input::name(path);
    if is_json_input(path)? {
        let bytes = crate::input::input_bytes(path)?;
        let doc = PortalgonDoc::from_slice(&bytes).map_err(|e| invalid(format!("{name}: {e}")))?;
        drop(bytes);
        crate::limits::check_elements(&name, doc.polygons.len() as u64, "polygons")?;
        let fail = |e: PortalgonError| invalid(format!("{name}: {e}"));
        let tri = match doc.to_triangulation(DEFAULT_LENGTH_TOLERANCE) {
            // A tessellation (`delaunay --tessellation`): its polygons cut into triangles.
            Err(PortalgonError::NotTriangle { .. }) => {
                let p = doc.to_portalgon(DEFAULT_LENGTH_TOLERANCE).map_err(fail)?;
                let triangles = p.triangulated().map_err(fail)?;
                IntrinsicTriangulation::from_portalgon(&triangles, DEFAULT_LENGTH_TOLERANCE)
                    .map_err(fail)
            }
            other => other.map_err(fail),
        }?;
        return Ok((tri, None));
    }
    let loaded = crate::input::read_surface(path, weld)?;
    let numbering = InputNumbering {
        input_vertices: loaded.report.input_vertices(),
        count: loaded.soup.vertex_count(),
        polygon_of: loaded.polygon_of,
    };
    let tri =
        IntrinsicTriangulation::from_positions(loaded.surface.mesh, &loaded.surface.positions)
            .map_err(|e| invalid(format!("{name}: {e}")))?;
    Ok((tri, Some(numbering)))
}

/// Refuses to write a matrix that is not representable
/// ([`SparseMatrix::check_representable`]: an `inf` entry, or a mass matrix of zeros). (A
/// Laplacian may have a zero diagonal: a one-vertex torus.)
fn check_matrix(matrix: &SparseMatrix, what: &str, positive_diagonal: bool) -> anyhow::Result<()> {
    matrix
        .check_representable(positive_diagonal)
        .map_err(|e| invalid(format!("{what}: {e}")))
}

/// Refuses, before any work, outputs whose extensions do not fit (portalgon JSON for `-o`,
/// `--tessellation` and `--reduced`, Matrix Market or .npz for `--laplacian`, and .npy too for `--mass`), a file named twice, and a run
/// with nothing to write and no `--json`.
fn check_outputs(options: &Args) -> anyhow::Result<()> {
    let named = [
        ("-o", &options.output, OutputKind::Portalgon),
        (
            "--tessellation",
            &options.tessellation,
            OutputKind::Portalgon,
        ),
        ("--reduced", &options.reduced, OutputKind::Portalgon),
        ("--laplacian", &options.laplacian, OutputKind::Matrix),
        ("--mass", &options.mass, OutputKind::DiagonalMatrix),
    ];
    let outputs: Vec<_> = named
        .iter()
        .filter_map(|(option, path, kind)| Some((*option, path.as_deref()?, *kind)))
        .collect();
    if outputs.is_empty() && !options.json.json {
        return Err(invalid(
            "delaunay: nothing to write: give -o, --tessellation, --reduced, --laplacian or --mass (or \
             --json for the figures alone)",
        ));
    }
    crate::output::check_outputs(&outputs)
}

/// Runs `delaunay`: resolves `--method auto` on the input read (see [`Method::Auto`]), then
/// flips or runs the wave (after the reduction for dubois).
pub fn run(options: &Args) -> anyhow::Result<()> {
    check_outputs(options)?;
    options.method.check()?;
    let flip_options_given = options.mollify.is_some() || options.max_flips.is_some();
    let requested = options.method.method;
    if options.method.exact {
        let p = crate::progress::step("reading", || load_exact(&options.input))?;
        let method = match requested {
            Method::Auto if options.reduced.is_some() => Method::Dubois,
            Method::Auto => Method::chosen(choose_method(&p), true),
            m => m,
        };
        return run_exact(options, &p, method);
    }
    let (tri, numbering) = crate::progress::step("reading", || {
        load_numbered(&options.input, options.weld.weld)
    })?;
    let numbering = numbering.as_ref();
    let method = match requested {
        Method::Auto if options.reduced.is_some() => Method::Dubois,
        Method::Auto if flip_options_given => Method::Flip,
        Method::Auto => return run_auto(options, tri, numbering),
        m => m,
    };
    if method == Method::Flip {
        run_flip(options, tri, numbering)
    } else {
        run_wave(options, tri, method, numbering)
    }
}

/// `--method auto` in `f64`: flipping with [`choose_method`]'s needle test after its first pass
/// ([`delaunay_with_stats_unless_needle`]); at a needle, nothing is flipped and the rule goes on
/// from there ([`choose_method_for_needle`]).
fn run_auto(
    options: &Args,
    mut tri: IntrinsicTriangulation,
    numbering: Option<&InputNumbering>,
) -> anyhow::Result<()> {
    let flipped = crate::progress::step("flipping to Delaunay", || {
        delaunay_with_stats_unless_needle(&mut tri, &flip_options(options))
    })
    .map_err(|e| flip_error(options, e, numbering))?;
    match flipped {
        Some(stats) => write_flipped(options, tri, &stats, numbering),
        None => match Method::chosen(choose_method_for_needle(&tri), false) {
            Method::Flip => run_flip(options, tri, numbering),
            method => run_wave(options, tri, method, numbering),
        },
    }
}

/// The [`DelaunayOptions`] of `--max-flips` and `--mollify`.
fn flip_options(options: &Args) -> DelaunayOptions {
    DelaunayOptions {
        max_flips: options.max_flips,
        mollify: options.mollify,
        ..DelaunayOptions::default()
    }
}

/// A flipping failure, naming the input: a numerical breakdown is a numerical failure (exit 4),
/// degenerate lengths as [`geometry_error`] says, anything else invalid input (exit 2).
fn flip_error(
    options: &Args,
    e: DelaunayError,
    numbering: Option<&InputNumbering>,
) -> anyhow::Error {
    let name = crate::input::name(&options.input);
    match e {
        DelaunayError::NumericalBreakdown { .. } => crate::failure::numerical(format!(
            "{name}: {e} (double precision cannot finish flipping this input: try --method \
             voronoi or dubois, --exact on exact input)"
        )),
        DelaunayError::Geometry(e) => {
            geometry_error(&options.input, &MollifyHint(&e, "", polygon_of(numbering)))
        }
        other => invalid(format!("{name}: {other}")),
    }
}

/// Degenerate lengths of an input read in double precision (a zero-length side, a zero-area
/// triangle, a broken triangle inequality): invalid input (exit 2), unless the input is a
/// portalgon file whose exact corners make valid triangles (`generate flat-torus --x 1000000`:
/// sides 1, x − 1 and x in double precision are flat): then double precision could not hold
/// it, a numerical failure (exit 4) advising `--exact`.
pub fn geometry_error(input: &Path, e: &dyn std::fmt::Display) -> anyhow::Error {
    let name = crate::input::name(input);
    let exactly_valid = !crate::input::is_stdio(input)
        && is_json_input(input).unwrap_or(false)
        && load_exact(input).is_ok();
    if exactly_valid {
        crate::failure::numerical(format!(
            "{name}: {e} in double precision, but its exact corners make valid triangles: use \
             --exact (with --method voronoi or dubois)"
        ))
    } else {
        invalid(format!("{name}: {e}"))
    }
}

/// A degenerate-lengths error with the option that makes such input usable: `--mollify EPS`
/// (after the given options, `--method flip ` where the method run is not flipping), and the
/// file's polygon of the triangle it names when polygons were cut (the third field).
struct MollifyHint<'a>(
    &'a surftopo_intrinsic::GeometryError,
    &'static str,
    Option<&'a [u32]>,
);

/// The polygon of each triangle, when the input's polygons were cut.
fn polygon_of(numbering: Option<&InputNumbering>) -> Option<&[u32]> {
    numbering.and_then(|n| n.polygon_of.as_deref())
}

impl std::fmt::Display for MollifyHint<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        use surftopo_intrinsic::GeometryError as G;
        write!(f, "{}", self.0)?;
        let face = match self.0 {
            G::ZeroArea { face, .. } | G::TriangleInequality { face, .. } => Some(*face),
            _ => None,
        };
        if let Some(polygon) = face.and_then(|t| self.2?.get(t as usize)) {
            write!(f, " (a triangle cut from the file's face {polygon})")?;
        }
        if matches!(
            self.0,
            G::ZeroArea { .. } | G::TriangleInequality { .. } | G::NonPositiveLength { .. }
        ) {
            write!(
                f,
                " (`{}--mollify EPS` mollifies degenerate triangles, EPS relative to the mean \
                 edge length, e.g. 1e-6; `surftopo info` lists the near-degenerate ones)",
                self.1
            )?;
        }
        Ok(())
    }
}

/// [`IntrinsicTriangulation::validate`] with [`geometry_error`]'s verdict.
///
/// # Errors
/// Invalid input (exit 2) or a numerical failure (exit 4).
pub fn validated(input: &Path, tri: &IntrinsicTriangulation) -> anyhow::Result<()> {
    tri.validate().map_err(|e| geometry_error(input, &e))
}

/// `--method flip`.
fn run_flip(
    options: &Args,
    mut tri: IntrinsicTriangulation,
    numbering: Option<&InputNumbering>,
) -> anyhow::Result<()> {
    if options.reduced.is_some() {
        return Err(invalid("--reduced applies to --method dubois only"));
    }
    let stats = crate::progress::step("flipping to Delaunay", || {
        delaunay_with_stats(&mut tri, &flip_options(options))
    })
    .map_err(|e| flip_error(options, e, numbering))?;
    write_flipped(options, tri, &stats, numbering)
}

/// The outputs and the report of a flipped triangulation.
fn write_flipped(
    options: &Args,
    tri: IntrinsicTriangulation,
    stats: &DelaunayStats,
    numbering: Option<&InputNumbering>,
) -> anyhow::Result<()> {
    let mut outputs = Outputs::default();
    if let Some(path) = &options.output {
        outputs.file(path, |w| Ok(tri.write_json(w, TriangleStyle::Lengths)?))?;
    }
    if let Some(path) = &options.tessellation {
        let tessellation = crate::progress::step("merging co-circular triangles", || {
            delaunay_tessellation(&tri, DEFAULT_COCIRCULAR_TOLERANCE)
        });
        outputs.file(path, |w| {
            Ok(PortalgonDoc::from_portalgon(&tessellation.portalgon).write(w, false)?)
        })?;
    }
    write_matrices(options, &tri, numbering, &mut outputs)?;
    outputs.commit()?;
    report(options, Method::Flip, stats, None)
}

/// Writes `--laplacian` and `--mass` of a Delaunay triangulation (under temporary names), on
/// the input's vertex numbering when it is a mesh file (`numbering`: rows and columns of the
/// vertices in no face are empty).
fn write_matrices(
    options: &Args,
    tri: &IntrinsicTriangulation,
    numbering: Option<&InputNumbering>,
    outputs: &mut Outputs,
) -> anyhow::Result<()> {
    let on_input = |m: SparseMatrix| match numbering {
        Some(numbering) => numbering.on_input_rows(tri, m),
        None => m,
    };
    if let Some(path) = &options.laplacian {
        let comment = "cotan Laplacian of the intrinsic Delaunay triangulation (positive semidefinite: positive diagonal, off-diagonal -w_ij)";
        let laplacian = crate::progress::step("building the Laplacian", || cotan_laplacian(tri));
        check_matrix(&laplacian, "the cotan Laplacian", false)?;
        let laplacian = on_input(laplacian);
        outputs.file(path, |w| {
            crate::output::fill_matrix(w, path, &laplacian, comment)
        })?;
    }
    if let Some(path) = &options.mass {
        let comment = "lumped (barycentric) mass matrix: a third of the incident triangle areas";
        let mass = crate::progress::step("building the mass matrix", || lumped_mass(tri));
        check_matrix(&mass, "the mass matrix", true)?;
        let mass = on_input(mass);
        outputs.file(path, |w| {
            crate::output::fill_matrix(w, path, &mass, comment)
        })?;
    }
    Ok(())
}

/// Refuses the flip-only options and `--reduced` without dubois.
fn check_wave_options(options: &Args, method: Method) -> anyhow::Result<()> {
    if options.mollify.is_some() || options.max_flips.is_some() {
        return Err(invalid(
            "--mollify and --max-flips apply to --method flip only",
        ));
    }
    if options.reduced.is_some() && method != Method::Dubois {
        return Err(invalid("--reduced applies to --method dubois only"));
    }
    Ok(())
}

/// `--method voronoi` and `--method dubois` with `--exact`: the exact wave and its dual (after
/// the exact reduction for dubois); the triangulation written is the tessellation cut along
/// shortcuts by exact corners.
fn run_exact(options: &Args, p: &Portalgon<Rational>, method: Method) -> anyhow::Result<()> {
    check_wave_options(options, method)?;
    let start = std::time::Instant::now();
    let fail = |e: &dyn std::fmt::Display| invalid(format!("{}: {e}", options.input.display()));
    let (v, figures, reduced) =
        tessellate(p, method, options.method.reduce_options(), &options.input)?;
    let triangulated = v.triangulated().map_err(|e| fail(&e))?;
    let mut outputs = Outputs::default();
    if let Some(path) = &options.output {
        outputs.file(path, |w| {
            Ok(PortalgonDoc::from_portalgon(&triangulated).write(w, false)?)
        })?;
    }
    write_tessellation(options, &v.tessellation, &mut outputs)?;
    write_reduced(options, reduced.as_ref(), &mut outputs)?;
    let tri = v.triangulation().map_err(|e| fail(&e))?;
    finish(options, method, &tri, &figures, start, outputs, None)
}

/// `--method voronoi` and `--method dubois` in f64: the wave and its dual (after the reduction
/// for dubois); the triangulation written is the tessellation cut along shortcuts by lengths.
fn run_wave(
    options: &Args,
    tri: IntrinsicTriangulation,
    method: Method,
    numbering: Option<&InputNumbering>,
) -> anyhow::Result<()> {
    check_wave_options(options, method)?;
    let start = std::time::Instant::now();
    let fail = |e: &dyn std::fmt::Display| invalid(format!("{}: {e}", options.input.display()));
    tri.validate().map_err(|e| {
        let hint = MollifyHint(&e, "--method flip ", polygon_of(numbering));
        geometry_error(&options.input, &hint)
    })?;
    let (p, _) = tri.to_portalgon();
    let (v, figures, reduced) =
        tessellate(&p, method, options.method.reduce_options(), &options.input)?;
    let tri = v.triangulation().map_err(|e| fail(&e))?;
    let mut outputs = Outputs::default();
    if let Some(path) = &options.output {
        outputs.file(path, |w| Ok(tri.write_json(w, TriangleStyle::Lengths)?))?;
    }
    write_tessellation(options, &v.tessellation, &mut outputs)?;
    write_reduced(options, reduced.as_ref(), &mut outputs)?;
    finish(options, method, &tri, &figures, start, outputs, numbering)
}

/// The matrices and the figures of a wave run.
fn finish(
    options: &Args,
    method: Method,
    tri: &IntrinsicTriangulation,
    figures: &WaveFigures,
    start: std::time::Instant,
    mut outputs: Outputs,
    numbering: Option<&InputNumbering>,
) -> anyhow::Result<()> {
    let flips = FlipReport {
        flips: 0,
        mollify_delta: None,
        non_delaunay_edges: tri.non_delaunay_edges(surftopo_intrinsic::DEFAULT_TOLERANCE),
    };
    let stats = DelaunayStats::new(tri, &flips, start.elapsed().as_secs_f64());
    write_matrices(options, tri, numbering, &mut outputs)?;
    outputs.commit()?;
    report(options, method, &stats, Some(figures))
}

/// Writes `--reduced` (Corollary 1's triangulation, exact corners in exact mode; under a
/// temporary name).
fn write_reduced<S: Scalar>(
    options: &Args,
    reduced: Option<&Portalgon<S>>,
    outputs: &mut Outputs,
) -> anyhow::Result<()> {
    if let (Some(path), Some(r)) = (&options.reduced, reduced) {
        outputs.file(path, |w| {
            Ok(PortalgonDoc::from_portalgon(r).write(w, false)?)
        })?;
    }
    Ok(())
}

/// Writes `--tessellation` (under a temporary name).
fn write_tessellation<S: Scalar>(
    options: &Args,
    t: &Portalgon<S>,
    outputs: &mut Outputs,
) -> anyhow::Result<()> {
    if let Some(path) = &options.tessellation {
        outputs.file(path, |w| {
            Ok(PortalgonDoc::from_portalgon(t).write(w, false)?)
        })?;
    }
    Ok(())
}

/// The `--json` object: the stats, then `method` (the one run, after `auto`'s choice),
/// `requested_method`, for dubois the reduction's figures (`outer_iterations` N, `inner_passes`
/// per outer iteration, `inner_passes_total`, `inner_passes_bound` = 350·N, `tubes_replaced`
/// `{thin, thick}`, `peak_active_vertices`, `triangles_after_reduction`), for the wave methods
/// `wave_events` and `max_constellation`, and `arithmetic`. A struct, so the key order is this
/// one.
#[derive(serde::Serialize)]
struct JsonReport<'a> {
    #[serde(flatten)]
    stats: &'a DelaunayStats,
    method: String,
    requested_method: String,
    #[serde(flatten)]
    reduction: Option<ReductionJson<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    wave_events: Option<u64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    max_constellation: Option<usize>,
    arithmetic: &'static str,
}

/// The reduction's keys of [`JsonReport`].
#[derive(serde::Serialize)]
struct ReductionJson<'a> {
    outer_iterations: u32,
    inner_passes: &'a [u32],
    inner_passes_total: u64,
    inner_passes_bound: u64,
    tubes_replaced: TubesJson,
    peak_active_vertices: usize,
    triangles_after_reduction: usize,
}

/// `tubes_replaced` of [`ReductionJson`].
#[derive(serde::Serialize)]
struct TubesJson {
    thin: usize,
    thick: usize,
}

/// Prints the figures (`--json`: [`JsonReport`]).
fn report(
    options: &Args,
    method: Method,
    stats: &DelaunayStats,
    wave: Option<&WaveFigures>,
) -> anyhow::Result<()> {
    if options.json.json {
        let reduction = wave
            .and_then(|w| w.reduction.as_ref())
            .map(|r| ReductionJson {
                outer_iterations: r.outer_iterations,
                inner_passes: &r.inner_passes,
                inner_passes_total: r.inner_passes_total,
                inner_passes_bound: r.inner_passes_bound,
                tubes_replaced: TubesJson {
                    thin: r.tubes_replaced_thin,
                    thick: r.tubes_replaced_thick,
                },
                peak_active_vertices: r.peak_active_vertices,
                triangles_after_reduction: r.triangles_after_reduction,
            });
        crate::output::print_json(&JsonReport {
            stats,
            method: crate::args::value_name(&method),
            requested_method: crate::args::value_name(&options.method.method),
            reduction,
            wave_events: wave.map(|w| w.events),
            max_constellation: wave.map(|w| w.max_constellation),
            arithmetic: wave.map_or("f64", |w| w.arithmetic),
        })?;
    } else {
        crate::output::emit(&format!(
            "{}: {} vertices, {} edges, {} faces; {} flips, {} non-Delaunay edges, {} loops, {} multi-edges, {} ({})\n",
            crate::failure::shown(options.output.as_deref().unwrap_or(&options.input)),
            stats.vertices,
            stats.edges,
            stats.faces,
            stats.flips,
            stats.non_delaunay_edges,
            stats.loops,
            stats.multi_edges,
            crate::output::format_seconds(stats.seconds),
            crate::args::value_name(&method)
        ))?;
    }
    Ok(())
}
