//! `surftopo delaunay --tufted`, and `delaunay` on a mesh that is not a manifold: the Laplacian
//! and mass matrix of the tufted cover (Sharp & Crane, "A Laplacian for Nonmanifold Triangle
//! Meshes", 2020), a thin layer over `surftopo_intrinsic::tufted_laplacian`.

use super::delaunay_args::{Args, Method};
use crate::failure::invalid;
use crate::input::is_json_input;
use crate::output::{Outputs, check_matrix};
use std::time::Instant;
use surftopo_intrinsic::{
    DEFAULT_MOLLIFY_FACTOR, DelaunayError, TuftedError, TuftedOptions, TuftedReport,
    tufted_laplacian,
};
use surftopo_io::PolygonSoup;

/// After `delaunay` failed to read its input as a closed surface with `error`: runs the tufted
/// cover, with a note on stderr, when the input is a mesh that is not a manifold (a non-manifold
/// edge or vertex, a duplicate face); otherwise returns `error`.
pub fn run_if_not_manifold(options: &Args, error: anyhow::Error) -> anyhow::Result<()> {
    if options.method.exact || is_json_input(&options.input)? {
        return Err(error);
    }
    let Ok((soup, _)) = crate::input::read_soup(&options.input, options.weld.weld) else {
        return Err(error);
    };
    let Ok(triangles) = soup.triangles() else {
        return Err(error);
    };
    let counts = surftopo_mesh::inspect(soup.positions.len(), &triangles).counts;
    if counts.non_manifold_edges + counts.non_manifold_vertices + counts.duplicate_faces == 0 {
        return Err(error);
    }
    stderr_println!(
        "note: {}: not a manifold ({} non-manifold edges, {} non-manifold vertices, {} duplicate \
         faces): the Laplacian and mass matrix are the tufted cover's (Sharp & Crane 2020; \
         --tufted asks for it)",
        crate::input::name(&options.input),
        counts.non_manifold_edges,
        counts.non_manifold_vertices,
        counts.duplicate_faces
    );
    run_on(options, &soup, &triangles, true)
}

/// `delaunay --tufted`: reads the input as a triangle soup and runs the tufted cover.
pub fn run(options: &Args) -> anyhow::Result<()> {
    let (soup, _) = crate::progress::step("reading", || {
        crate::input::read_soup(&options.input, options.weld.weld)
    })?;
    let triangles = crate::input::triangles(&options.input, &soup)?;
    run_on(options, &soup, &triangles, false)
}

/// Refuses the options the tufted cover does not serve: it gives the Laplacian, the mass
/// matrix and the figures of a mesh, by flipping.
fn check_options(options: &Args, automatic: bool) -> anyhow::Result<()> {
    let why = if automatic {
        "the input is not a manifold: the tufted cover"
    } else {
        "--tufted"
    };
    let refused = [
        (options.output.is_some(), "-o"),
        (options.tessellation.is_some(), "--tessellation"),
        (options.reduced.is_some(), "--reduced"),
        (options.method.exact, "--exact"),
        (options.method.faithful, "--faithful"),
        (
            !matches!(options.method.method, Method::Auto | Method::Flip),
            "--method voronoi or dubois",
        ),
    ];
    if let Some((_, option)) = refused.iter().find(|(given, _)| *given) {
        return Err(invalid(format!(
            "{}: {option}: {why} gives --laplacian, --mass and --json only (by flipping)",
            crate::input::name(&options.input)
        )));
    }
    if is_json_input(&options.input)? {
        return Err(invalid(format!(
            "{}: --tufted takes a mesh file (a portalgon is a closed surface already)",
            crate::input::name(&options.input)
        )));
    }
    Ok(())
}

/// The figures of `--json`: `tufted` (true), `automatic` (taken because the input is not a
/// manifold), then [`TuftedReport`]'s and the seconds.
#[derive(serde::Serialize)]
struct JsonReport {
    tufted: bool,
    automatic: bool,
    vertices: usize,
    faces: usize,
    edges: usize,
    fin_edges: usize,
    book_edges: usize,
    cover_vertices: usize,
    cover_edges: usize,
    cover_faces: usize,
    mollify_factor: f64,
    mollify_delta: f64,
    flips: u64,
    seconds: f64,
}

/// Computes, writes and reports the tufted Laplacian and mass of `triangles`.
fn run_on(
    options: &Args,
    soup: &PolygonSoup,
    triangles: &[[u32; 3]],
    automatic: bool,
) -> anyhow::Result<()> {
    check_options(options, automatic)?;
    let tufted = TuftedOptions {
        mollify_factor: options.mollify.unwrap_or(DEFAULT_MOLLIFY_FACTOR),
        max_flips: options.max_flips,
    };
    let start = Instant::now();
    let out = crate::progress::step("tufted cover, flipping", || {
        tufted_laplacian(&soup.positions, triangles, &tufted)
    })
    .map_err(|e| error(options, soup, e))?;
    let seconds = start.elapsed().as_secs_f64();
    let mut outputs = Outputs::default();
    if let Some(path) = &options.laplacian {
        let comment = "cotan Laplacian of the tufted cover (Sharp & Crane 2020) flipped to intrinsic Delaunay, folded to the input vertices with the factor 1/2 (positive semidefinite)";
        check_matrix(&out.laplacian, "the cotan Laplacian", false)?;
        outputs.file(path, |w| {
            crate::output::fill_matrix(w, path, &out.laplacian, comment)
        })?;
    }
    if let Some(path) = &options.mass {
        let comment = "lumped (barycentric) mass matrix of the tufted cover, folded with the factor 1/2 (0 at unreferenced vertices)";
        // Unreferenced vertices have zero mass: only finiteness is checked.
        check_matrix(&out.mass, "the mass matrix", false)?;
        outputs.file(path, |w| {
            crate::output::fill_matrix(w, path, &out.mass, comment)
        })?;
    }
    outputs.commit()?;
    report(
        options,
        &out.report,
        tufted.mollify_factor,
        automatic,
        seconds,
    )
}

/// Prints the figures (`--json`: [`JsonReport`]).
fn report(
    options: &Args,
    r: &TuftedReport,
    mollify_factor: f64,
    automatic: bool,
    seconds: f64,
) -> anyhow::Result<()> {
    if options.json.json {
        return crate::output::print_json(&JsonReport {
            tufted: true,
            automatic,
            vertices: r.vertices,
            faces: r.faces,
            edges: r.edges,
            fin_edges: r.fin_edges,
            book_edges: r.book_edges,
            cover_vertices: r.cover_vertices,
            cover_edges: r.cover_edges,
            cover_faces: r.cover_faces,
            mollify_factor,
            mollify_delta: r.mollify_delta,
            flips: r.flips,
            seconds,
        });
    }
    crate::output::emit(&format!(
        "{}: tufted cover of {} vertices, {} faces, {} edges ({} fins, {} with 3+ faces): {} \
         vertices, {} edges, {} faces; mollified by {:e}; {} flips, {} (flip)\n",
        crate::failure::shown(&options.input),
        r.vertices,
        r.faces,
        r.edges,
        r.fin_edges,
        r.book_edges,
        r.cover_vertices,
        r.cover_edges,
        r.cover_faces,
        r.mollify_delta,
        r.flips,
        crate::output::format_seconds(seconds),
    ))
}

/// A tufted error as the CLI reports it: the soup's problem located (file, line, face), a
/// degenerate face with its line (exit 2), the flip budget (exit 2), double precision's
/// breakdown (exit 4).
fn error(options: &Args, soup: &PolygonSoup, e: TuftedError) -> anyhow::Error {
    let name = crate::input::name(&options.input);
    match e {
        TuftedError::Input(b) => invalid(crate::input::locate(&options.input, soup, &b)),
        TuftedError::Degenerate(g) => {
            let line = match &g {
                surftopo_intrinsic::GeometryError::TriangleInequality { face, .. }
                | surftopo_intrinsic::GeometryError::ZeroArea { face, .. } => {
                    soup.face_lines.get(*face as usize).copied()
                }
                _ => None,
            }
            .map(|l| format!("line {l}: "))
            .unwrap_or_default();
            invalid(format!(
                "{name}: {line}{g} (give --mollify with a positive factor)"
            ))
        }
        TuftedError::Flip(e @ DelaunayError::NumericalBreakdown { .. }) => {
            crate::failure::numerical(format!("{name}: flipping the tufted cover: {e}"))
        }
        e => invalid(format!("{name}: {e}")),
    }
}
