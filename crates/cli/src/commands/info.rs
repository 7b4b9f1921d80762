//! `surftopo info`: counts, topology and every problem found, valid mesh or not.
//!
//! Polygon meshes (quads from `surftopo quad`) are inspected through their fan triangulation, which
//! has the same Euler characteristic, closedness, orientability and vertex fans; the edge count is
//! corrected for the added diagonals. (A diagonal that coincides with an existing edge shows up as a
//! non-manifold edge.)

use crate::args::{JsonArg, WeldArg};
use crate::failure::invalid;
use crate::input::{fan_triangles, locate, read_soup, renumber_face};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// The arguments of `info`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Mesh file (.obj, .off, .ply, .stl, optionally .gz), `-` for standard input (format from
    /// the extension, else the content).
    pub mesh: PathBuf,
    #[command(flatten)]
    pub json: JsonArg,
    #[command(flatten)]
    pub weld: WeldArg,
    /// Exit with code 2 when the mesh is not a valid closed orientable surface.
    #[arg(long)]
    pub strict: bool,
}

/// The facts `info` reports (JSON keys as named).
#[derive(Serialize)]
pub struct Info {
    /// Referenced vertices.
    pub vertices: usize,
    /// Distinct edges.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// Genus, when the mesh is a closed connected orientable manifold.
    pub genus: Option<i64>,
    /// V - E + F.
    pub euler_characteristic: i64,
    /// Connected components.
    pub components: usize,
    /// Every edge in exactly two faces.
    pub closed: bool,
    /// A consistent orientation exists.
    pub orientable: bool,
    /// All faces triangles, none degenerate or duplicate (a simplicial complex).
    pub simplicial: bool,
    /// A closed connected orientable surface surftopo accepts.
    pub valid: bool,
    /// Edges in one face.
    pub boundary_edges: usize,
    /// Edges in more than two faces.
    pub non_manifold_edges: usize,
    /// Vertices whose faces form several fans.
    pub non_manifold_vertices: usize,
    /// Faces that would be reversed for a consistent orientation.
    pub reoriented_faces: usize,
    /// Unreferenced vertices in the file.
    pub dropped_vertices: usize,
    /// Vertices merged by `--weld`.
    pub welded_vertices: usize,
    /// Total number of problems.
    pub problem_count: usize,
    /// The problems (at most 100), each saying where and what.
    pub problems: Vec<String>,
}

/// Runs `info`; with `--strict`, problems make it fail with exit code 2.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let (path, json, strict) = (args.mesh.as_path(), args.json.json, args.strict);
    let (soup, welded) = read_soup(path, args.weld.weld)?;
    // Polygon meshes are inspected through their fan triangulation (see `fan_triangles`).
    let (triangles, polygon_of) = fan_triangles(&soup);
    let mut inspection = surftopo_mesh::inspect(soup.positions.len(), &triangles);
    let diagonals = triangles.len() - soup.face_count();
    let all_triangles = diagonals == 0;
    inspection.faces = soup.face_count();
    inspection.edges -= diagonals.min(inspection.edges);
    inspection.problems = inspection
        .problems
        .into_iter()
        .map(|p| renumber_face(p, &polygon_of))
        .collect();

    if let Err(e) = surftopo_mesh::geometry::check_finite(&soup.positions) {
        inspection.add_problem_first(e);
    }
    let simplicial = all_triangles && !inspection.has_degenerate_faces();
    let valid = inspection.is_valid();
    let info = Info {
        vertices: inspection.vertices,
        edges: inspection.edges,
        faces: inspection.faces,
        genus: inspection.genus(),
        euler_characteristic: inspection.euler_characteristic(),
        components: inspection.components,
        closed: inspection.is_closed(),
        orientable: inspection.orientable,
        simplicial,
        valid,
        boundary_edges: inspection.boundary_edges,
        non_manifold_edges: inspection.non_manifold_edges,
        non_manifold_vertices: inspection.non_manifold_vertices,
        reoriented_faces: inspection.reoriented_faces,
        dropped_vertices: inspection.dropped_vertices,
        welded_vertices: welded,
        problem_count: inspection.problem_count,
        problems: inspection
            .problems
            .iter()
            .map(|p| locate(path, &soup, p))
            .collect(),
    };
    if json {
        crate::output::print_json(&info)?;
    } else {
        crate::output::emit(&text(path, &info))?;
    }
    if strict && !valid {
        return Err(invalid(format!(
            "{}: {} problem(s) found",
            crate::input::name(path),
            info.problem_count
        )));
    }
    Ok(())
}

fn text(path: &Path, info: &Info) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    let yes = |b: bool| if b { "yes" } else { "no" };
    writeln!(s, "{}", crate::input::name(path)).ok();
    writeln!(s, "  vertices              {}", info.vertices).ok();
    writeln!(s, "  edges                 {}", info.edges).ok();
    writeln!(s, "  faces                 {}", info.faces).ok();
    match info.genus {
        Some(g) => writeln!(s, "  genus                 {g}"),
        None => writeln!(
            s,
            "  genus                 - (not a closed connected orientable surface)"
        ),
    }
    .ok();
    writeln!(s, "  euler characteristic  {}", info.euler_characteristic).ok();
    writeln!(s, "  components            {}", info.components).ok();
    writeln!(s, "  closed                {}", yes(info.closed)).ok();
    writeln!(s, "  orientable            {}", yes(info.orientable)).ok();
    writeln!(s, "  simplicial            {}", yes(info.simplicial)).ok();
    if info.reoriented_faces > 0 {
        writeln!(s, "  faces to reorient     {}", info.reoriented_faces).ok();
    }
    if info.dropped_vertices > 0 {
        writeln!(s, "  unreferenced vertices {}", info.dropped_vertices).ok();
    }
    if info.welded_vertices > 0 {
        writeln!(s, "  welded vertices       {}", info.welded_vertices).ok();
    }
    if info.problem_count == 0 {
        writeln!(s, "  problems              none").ok();
    } else {
        writeln!(s, "  problems              {}", info.problem_count).ok();
        for p in &info.problems {
            writeln!(s, "    {p}").ok();
        }
        if info.problem_count > info.problems.len() {
            writeln!(
                s,
                "    ... and {} more",
                info.problem_count - info.problems.len()
            )
            .ok();
        }
    }
    s
}
