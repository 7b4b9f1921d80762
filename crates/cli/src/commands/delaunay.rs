//! `surftopo delaunay`: the intrinsic Delaunay triangulation by edge flipping (`--method flip`)
//! or by the Voronoi wave of Dubois, Appendix D (`--method voronoi`, optionally `--exact`), or by
//! Dubois' Theorem 1 (`--method dubois`: Section 8's caps around the cone points, Section 4's
//! reduction of the flat remainder, the caps put back, then the wave from the singular vertices —
//! one vertex on a flat torus), or the method `--method auto` (the default) picks, its
//! tessellation, the cotan Laplacian and the lumped mass matrix: a thin layer over
//! `surftopo_intrinsic::intrinsic_delaunay`.

pub use super::delaunay_args::{Args, Method, MethodOptions, request_error};
use crate::failure::invalid;
pub(crate) use crate::input::is_json_input;
use crate::output::{OutputKind, Outputs, check_matrix};
use std::path::Path;
use surftopo_intrinsic::geometry::{Rational, Tolerances};
use surftopo_intrinsic::{
    CoveredTriangulation, DelaunayError, DelaunayInput, DelaunayOutput, DelaunayOutputs,
    DelaunayRequest, DelaunayStats, IntrinsicDelaunayError, IntrinsicTriangulation, Portalgon,
    PortalgonDoc, PortalgonError, SparseMatrix, TriangleStyle,
};

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
    // The gluing first: a missing one is named before any polygon is checked.
    let p = PortalgonDoc::from_slice(&bytes)
        .and_then(|doc| doc.check_closed().map(|()| doc))
        .and_then(|doc| doc.to_portalgon_in::<Rational>(0.0))
        .map_err(|e| invalid(format!("{name}: {e}")))?;
    p.check_closed()
        .map_err(|e| invalid(format!("{name}: {e}")))?;
    Ok(p)
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
    fn on_input_rows(&self, tri: &IntrinsicTriangulation, matrix: &SparseMatrix) -> SparseMatrix {
        self.rows_on_input(&tri.matrix_rows(), matrix)
    }

    /// `matrix` on the input's rows and columns, `rows` the matrix row of each vertex id (a
    /// surface of any kind: its vertex ids are its rows).
    fn rows_on_input(&self, rows: &[u32], matrix: &SparseMatrix) -> SparseMatrix {
        let mut row_to_input = vec![0u32; matrix.n];
        for (v, &row) in rows.iter().enumerate() {
            match (
                row_to_input.get_mut(row as usize),
                self.input_vertices.get(v),
            ) {
                (Some(slot), Some(&input)) => *slot = input,
                (None, _) => {}
                (Some(_), None) => return matrix.clone(),
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
        let tri = closed_from_doc(&name, &read_doc(path)?)?;
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

/// Reads a portalgon JSON file within the limits (`--max-input-bytes` for the text,
/// `--max-elements` for the polygons).
fn read_doc(path: &Path) -> anyhow::Result<PortalgonDoc> {
    let name = crate::input::name(path);
    let bytes = crate::input::input_bytes(path)?;
    let doc = PortalgonDoc::from_slice(&bytes).map_err(|e| invalid(format!("{name}: {e}")))?;
    drop(bytes);
    crate::limits::check_elements(&name, doc.polygons.len() as u64, "polygons")?;
    Ok(doc)
}

/// The intrinsic triangulation of a portalgon file of one closed oriented piece: a
/// triangulation, or a tessellation (`delaunay --tessellation`) whose polygons are cut into
/// triangles.
fn closed_from_doc(name: &str, doc: &PortalgonDoc) -> anyhow::Result<IntrinsicTriangulation> {
    let fail = |e: PortalgonError| doc_error(name, e, true);
    match doc.to_triangulation(Tolerances::DEFAULT.length) {
        Err(PortalgonError::NotTriangle { .. }) => {
            // Every side glued before any polygon is checked or cut: a missing gluing is
            // named at once.
            doc.check_closed().map_err(fail)?;
            let p = doc.to_portalgon(Tolerances::DEFAULT.length).map_err(fail)?;
            let triangles = p.triangulated().map_err(fail)?;
            IntrinsicTriangulation::from_portalgon(&triangles, Tolerances::DEFAULT.length)
                .map_err(fail)
        }
        other => other.map_err(fail),
    }
}

/// An error reading a portalgon file in double precision: invalid input (exit 2), but exact
/// corners that doubles cannot hold ([`PortalgonError::BeyondDoubles`]: `T_x` for `x = 10³⁰`,
/// whose rounded lengths make a triangle of area 5·10²⁹ instead of 1) are a numerical failure
/// (exit 4), never a silently different surface; the advice is `--exact` for a `closed` surface
/// (exact arithmetic takes closed oriented ones only).
fn doc_error(name: &str, e: PortalgonError, closed: bool) -> anyhow::Error {
    match e {
        PortalgonError::BeyondDoubles { .. } => crate::failure::numerical(if closed {
            format!("{name}: {e} (use --exact, with --method voronoi or dubois)")
        } else {
            format!("{name}: {e} (--exact takes closed orientable surfaces only)")
        }),
        e => invalid(format!("{name}: {e}")),
    }
}

/// Reads a portalgon JSON file of any surface kind: one closed oriented piece as an intrinsic
/// triangulation ([`load_intrinsic`]: every method), triangles glued with boundary sides,
/// orientation-reversing gluings (format version 2) or in several pieces on their closed cover
/// ([`CoveredTriangulation::from_doc`]: flipping). Its vertices are its labels.
pub fn load_json(path: &Path) -> anyhow::Result<DelaunayInput> {
    let (name, doc) = (crate::input::name(path), read_doc(path)?);
    if doc.needs_cover() {
        let tri = CoveredTriangulation::from_doc(&doc, Tolerances::DEFAULT.length)
            .map_err(|e| doc_error(&name, e, false))?;
        return Ok(DelaunayInput::Covered(tri));
    }
    closed_from_doc(&name, &doc).map(DelaunayInput::Lengths)
}

/// Reads a mesh file of any surface kind, with the input's vertex numbering: a closed
/// orientable one as its intrinsic triangulation (every method), any other (boundary loops,
/// non-orientable pieces) on its closed cover (flipping).
fn load_mesh(path: &Path, weld: bool) -> anyhow::Result<(DelaunayInput, InputNumbering)> {
    let name = crate::input::name(path);
    let loaded = crate::input::read_covered(path, weld)?;
    let fail = |e: surftopo_intrinsic::GeometryError| invalid(format!("{name}: {e}"));
    let numbering = InputNumbering {
        input_vertices: loaded.report.input_vertices(),
        count: loaded.soup.vertex_count(),
        polygon_of: loaded.polygon_of,
    };
    let surface = loaded.surface;
    if surface.cover.is_plain() {
        let s = surface
            .into_plain()
            .expect("a plain cover is a closed orientable surface");
        let tri = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).map_err(fail)?;
        return Ok((DelaunayInput::Lengths(tri), numbering));
    }
    let tri = CoveredTriangulation::from_cover(&surface.cover, &surface.positions).map_err(fail)?;
    Ok((DelaunayInput::Covered(tri), numbering))
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

/// Runs `delaunay`: reads the input (exact corners with `--exact`), runs
/// [`surftopo_intrinsic::intrinsic_delaunay`] with the outputs asked for, then writes them and
/// prints the figures.
pub fn run(options: &Args) -> anyhow::Result<()> {
    check_outputs(options)?;
    if options.tufted {
        return super::tufted::run(options);
    }
    options.method.check()?;
    // A mesh file's lengths are those of its faces in space (`DelaunayRequest::mesh_metric`).
    let (input, numbering, mesh_metric) = if options.method.exact {
        let p = crate::progress::step("reading", || load_exact(&options.input))?;
        (DelaunayInput::Exact(p), None, false)
    } else if is_json_input(&options.input)? {
        let input = crate::progress::step("reading", || load_json(&options.input))?;
        (input, None, false)
    } else {
        match load_mesh(&options.input, options.weld.weld) {
            Ok((input, numbering)) => (input, Some(numbering), true),
            Err(e) => return super::tufted::run_if_not_manifold(options, e),
        }
    };
    let request = DelaunayRequest {
        outputs: DelaunayOutputs {
            triangulation: true,
            tessellation: options.tessellation.is_some(),
            reduced: options.reduced.is_some(),
            laplacian: options.laplacian.is_some(),
            mass: options.mass.is_some(),
            figures: true,
        },
        max_flips: options.max_flips,
        mollify: options.mollify,
        mesh_metric,
        ..options.method.request()
    };
    let out = crate::progress::steps(|progress| {
        surftopo_intrinsic::intrinsic_delaunay_reporting(input, &request, progress)
    })
    .map_err(|e| run_error(options, e, numbering.as_ref()))?;
    refuse_non_delaunay(options, &out)?;
    write_outputs(options, &out, numbering.as_ref())?;
    report(options, &out)
}

/// Success means a Delaunay result: a run that ends with non-Delaunay edges (counted
/// independently of the method, exactly in exact mode) is a numerical failure (exit 4), and
/// nothing is written.
fn refuse_non_delaunay(options: &Args, out: &DelaunayOutput) -> anyhow::Result<()> {
    match out.stats.as_ref().map(|s| s.non_delaunay_edges) {
        Some(n) if n > 0 => Err(crate::failure::numerical(format!(
            "{}: the {} method ended with {n} non-Delaunay edges ({} arithmetic); nothing \
             written (use --exact on exact input, or another --method)",
            crate::failure::shown(&options.input),
            out.method.name(),
            out.arithmetic
        ))),
        _ => Ok(()),
    }
}

/// A failure of the run, naming the input: a refused request as its options; a numerical
/// failure of double precision with advice (exit 4): flipping's breakdown, the `f64` wave's
/// refusals and Theorem 1's failures in `f64`; degenerate lengths as [`geometry_error`] says;
/// anything else invalid input (exit 2).
fn run_error(
    options: &Args,
    e: IntrinsicDelaunayError,
    numbering: Option<&InputNumbering>,
) -> anyhow::Error {
    // `--mollify` applies to flipping: the hint names `--method flip` after another method.
    let flipping = matches!(options.method.method, Method::Flip | Method::Auto);
    let prefix = if flipping { "" } else { "--method flip " };
    let polygons = numbering.and_then(|n| n.polygon_of.as_deref());
    let name = crate::input::name(&options.input);
    match e {
        IntrinsicDelaunayError::Request(e) => request_error(e),
        IntrinsicDelaunayError::Flip(e @ DelaunayError::NumericalBreakdown { .. }) => {
            crate::failure::numerical(format!(
                "{name}: {e} (double precision cannot finish flipping this input: try --method \
                 voronoi or dubois, --exact on exact input)"
            ))
        }
        IntrinsicDelaunayError::Flip(DelaunayError::Geometry(e))
        | IntrinsicDelaunayError::Geometry(e) => {
            geometry_error(&options.input, &MollifyHint(&e, prefix, polygons))
        }
        e if e.is_numerical() => crate::failure::numerical(format!(
            "{}: {e} (a numerical failure of double precision: try --exact on exact input, or \
             --method flip)",
            options.input.display()
        )),
        IntrinsicDelaunayError::Flip(e) => invalid(format!("{name}: {e}")),
        e => invalid(format!("{}: {e}", options.input.display())),
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

/// Writes the outputs asked for (under temporary names, renamed together): `-o` (exact corners
/// in exact mode, lengths otherwise), `--tessellation`, `--reduced`, `--laplacian`, `--mass`;
/// the matrices are checked first ([`check_matrix`]), then put on the input's vertex numbering
/// when it is a mesh file (`numbering`: rows and columns of the vertices in no face are empty).
fn write_outputs(
    options: &Args,
    out: &DelaunayOutput,
    numbering: Option<&InputNumbering>,
) -> anyhow::Result<()> {
    let on_input = |m: &SparseMatrix| match (numbering, &out.triangulation, &out.covered) {
        (Some(numbering), Some(tri), _) => numbering.on_input_rows(tri, m),
        (Some(numbering), None, Some(_)) => {
            numbering.rows_on_input(&(0..m.n as u32).collect::<Vec<_>>(), m)
        }
        _ => m.clone(),
    };
    let mut outputs = Outputs::default();
    if let Some(path) = &options.output {
        if let Some(exact) = &out.exact_triangulation {
            outputs.file(path, |w| {
                Ok(PortalgonDoc::from_portalgon(exact).write(w, false)?)
            })?;
        } else if let Some(tri) = &out.triangulation {
            outputs.file(path, |w| Ok(tri.write_json(w, TriangleStyle::Lengths)?))?;
        } else if let Some(covered) = &out.covered {
            // Boundary sides unmatched, orientation-reversing gluings flagged (version 2).
            outputs.file(path, |w| Ok(covered.to_doc().write(w, false)?))?;
        }
    }
    let portalgons = [
        (&options.tessellation, &out.tessellation),
        (&options.reduced, &out.reduced),
    ];
    for (path, portalgon) in portalgons {
        if let (Some(path), Some(p)) = (path, portalgon) {
            outputs.file(path, |w| Ok(p.to_doc().write(w, false)?))?;
        }
    }
    if let (Some(path), Some(t)) = (&options.tessellation, &out.covered_tessellation) {
        // Boundary sides unmatched, orientation-reversing gluings flagged (version 2).
        outputs.file(path, |w| Ok(t.portalgon.write(w, false)?))?;
    }
    if let (Some(path), Some(laplacian)) = (&options.laplacian, &out.laplacian) {
        let comment = "cotan Laplacian of the intrinsic Delaunay triangulation (positive semidefinite: positive diagonal, off-diagonal -w_ij)";
        check_matrix(laplacian, "the cotan Laplacian", false)?;
        let laplacian = on_input(laplacian);
        outputs.file(path, |w| {
            crate::output::fill_matrix(w, path, &laplacian, comment)
        })?;
    }
    if let (Some(path), Some(mass)) = (&options.mass, &out.mass) {
        let comment = "lumped (barycentric) mass matrix: a third of the incident triangle areas";
        check_matrix(mass, "the mass matrix", true)?;
        let mass = on_input(mass);
        outputs.file(path, |w| {
            crate::output::fill_matrix(w, path, &mass, comment)
        })?;
    }
    outputs.commit()
}

/// The `--json` object: `tufted` (false), the stats, then `method` (the one run, after `auto`'s choice),
/// `requested_method`, for dubois the reduction's figures (`outer_iterations` N, `inner_passes`
/// per outer iteration, `inner_passes_total`, `inner_passes_bound` = 350·N, `tubes_replaced`
/// `{thin, thick}`, `peak_active_vertices`, `triangles_after_reduction`), for the wave methods
/// `wave_events` and `max_constellation`, and `arithmetic`. A struct, so the key order is this
/// one.
#[derive(serde::Serialize)]
struct JsonReport<'a> {
    /// Always false here (the tufted cover's report is `tufted::JsonReport`).
    tufted: bool,
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
    /// Proposition 2 kept the mesh as `T′` (happiness 1): no caps, no ALGORITHM.
    mesh_metric: bool,
}

/// `tubes_replaced` of [`ReductionJson`].
#[derive(serde::Serialize)]
struct TubesJson {
    thin: usize,
    thick: usize,
}

/// Prints the figures (`--json`: [`JsonReport`]).
fn report(options: &Args, out: &DelaunayOutput) -> anyhow::Result<()> {
    let stats = out.stats.as_ref().expect("the figures are asked for");
    let method = out.method.name();
    if options.json.json {
        let reduction = out.reduction.as_ref().map(|r| ReductionJson {
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
            mesh_metric: r.mesh_metric,
        });
        crate::output::print_json(&JsonReport {
            tufted: false,
            stats,
            method: method.to_string(),
            requested_method: crate::args::value_name(&options.method.method),
            reduction,
            wave_events: out.wave.map(|w| w.events),
            max_constellation: out.wave.map(|w| w.max_constellation),
            arithmetic: out.arithmetic,
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
            method
        ))?;
    }
    Ok(())
}
