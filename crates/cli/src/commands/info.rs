//! `surftopo info`: counts, topology and every problem found, valid mesh or not.
//!
//! Polygon meshes (quads from `surftopo quad`, exported quad meshes) are inspected through the
//! triangles the other commands cut them into (`surftopo_mesh::triangulate_polygons`), which have
//! the same Euler characteristic, closedness, orientability and vertex fans; the face and edge
//! counts (of the whole and of each piece) are corrected for the added diagonals. (A diagonal that
//! coincides with an existing edge shows up as a non-manifold edge.) A point cloud (vertices, no
//! faces) is described by its counts and vertex properties.

use crate::args::{JsonArg, WeldArg};
use crate::failure::invalid;
use crate::input::{Read, locate, read_mesh_or_points};
use serde::Serialize;
use std::path::{Path, PathBuf};
use surftopo_mesh::{ProblemCounts, SurfaceKind};

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
    /// Exit with code 2 when any problem is found (the faces are not a triangulated surface, or
    /// a coordinate is not finite, or a face has zero area).
    #[arg(long)]
    pub strict: bool,
}

/// One connected component, classified (the `surfaces` entries of `--json`).
#[derive(Serialize, Clone, Debug)]
pub struct SurfaceJson {
    /// Its faces.
    pub faces: usize,
    /// V − E + F.
    pub euler_characteristic: i64,
    /// Whether it has a consistent orientation.
    pub orientable: bool,
    /// Its boundary loops.
    pub boundary_loops: usize,
    /// g with χ = 2 − 2g − b (null when non-orientable).
    pub genus: Option<u64>,
    /// k with χ = 2 − k − b (null when orientable).
    pub crosscaps: Option<u64>,
    /// 2g or k.
    pub euler_genus: u64,
    /// sphere, torus, genus-g surface, projective plane, Klein bottle, N_k, disk, annulus,
    /// Möbius band, "genus g with b boundary loops", "N_k with b boundary loops".
    pub name: String,
}

impl From<&SurfaceKind> for SurfaceJson {
    fn from(k: &SurfaceKind) -> Self {
        SurfaceJson {
            faces: k.faces,
            euler_characteristic: k.euler_characteristic,
            orientable: k.orientable,
            boundary_loops: k.boundary_loops,
            genus: k.genus,
            crosscaps: k.crosscaps,
            euler_genus: k.euler_genus,
            name: k.name(),
        }
    }
}

/// The facts `info` reports (JSON keys as named; the text labels are the same words).
#[derive(Serialize)]
pub struct Info {
    /// Referenced vertices.
    pub vertices: usize,
    /// Distinct edges.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// Whether the file holds vertices and no faces (a point cloud: every other command needs
    /// faces; the surface keys are then 0, false or null).
    pub point_cloud: bool,
    /// The names of the per-vertex properties read beside the positions (`nx`, `u`, `red`, ...:
    /// what the commands that keep the vertex list carry along).
    pub vertex_properties: Vec<String>,
    /// Genus, when the faces form one orientable surface, closed or not (whatever the
    /// coordinates: non-finite ones and zero-area faces leave it defined).
    pub genus: Option<i64>,
    /// V - E + F.
    pub euler_characteristic: i64,
    /// Connected components.
    pub components: usize,
    /// Every edge in exactly two faces.
    pub closed: bool,
    /// A consistent orientation exists (of every component).
    pub orientable: bool,
    /// Boundary loops (over all components; 0 when the faces are not a surface).
    pub boundary_loops: usize,
    /// Edges in one face.
    pub boundary_edges: usize,
    /// All faces triangles, none degenerate or duplicate (a simplicial complex).
    pub simplicial: bool,
    /// No problem found: a triangulated surface (boundary, non-orientable pieces and several
    /// components allowed) with finite coordinates and no zero-area face.
    pub valid: bool,
    /// Faces that would be reversed for a consistent orientation (not a problem: commands
    /// reorient them).
    pub reoriented_faces: usize,
    /// Vertices no face uses (not a problem: commands drop them).
    pub unreferenced_vertices: usize,
    /// Vertices merged by `--weld`.
    pub welded_vertices: usize,
    /// The problems counted by class, one key per class (`non_finite_coordinates`,
    /// `zero_area_faces`, ...: [`surftopo_mesh::ProblemCounts`]).
    #[serde(flatten)]
    pub counts: Counts,
    /// Total number of problems (the sum of the class counts).
    pub problems_total: usize,
    /// Whether `problems` lists fewer than `problems_total` (it stops at
    /// [`surftopo_mesh::MAX_LISTED_PROBLEMS`]).
    pub problems_truncated: bool,
    /// The problems (at most 100), each saying where and what.
    pub problems: Vec<String>,
    /// Faces that are not degenerate but nearly so (warnings, not problems: `valid` does not
    /// count them): the height of a triangle below
    /// [`surftopo_mesh::geometry::NEAR_DEGENERATE_RELATIVE_HEIGHT`] times its longest side,
    /// where double-precision side lengths lose their digits (`delaunay` may refuse them without
    /// `--mollify`).
    pub near_degenerate_faces: usize,
    /// The warnings (at most 100), each saying where and what.
    pub warnings: Vec<String>,
    /// What `--weld` would do, when the faces have boundary edges or several pieces that
    /// merging vertices of equal positions would close or join (null otherwise, and with
    /// `--weld`).
    pub weld_hint: Option<String>,
    /// One classification per connected component, in the order of their first face (empty
    /// when the faces do not form a surface).
    pub surfaces: Vec<SurfaceJson>,
}

/// The class counts, serialised as one key per class in [`ProblemCounts::entries`] order.
pub struct Counts(pub ProblemCounts);

impl Serialize for Counts {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let entries = self.0.entries();
        let mut map = serializer.serialize_map(Some(entries.len()))?;
        for (key, count) in entries {
            map.serialize_entry(key, &count)?;
        }
        map.end()
    }
}

/// Runs `info`; with `--strict`, any problem makes it fail with exit code 2.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let (path, json, strict) = (args.mesh.as_path(), args.json.json, args.strict);
    let info = inspect_path(path, args.weld.weld)?;
    if json {
        crate::output::print_json(&info)?;
    } else {
        crate::output::emit(&text(path, &info))?;
    }
    if strict && !info.valid {
        return Err(invalid(format!(
            "{}: {} problem(s) found",
            crate::input::name(path),
            info.problems_total
        )));
    }
    Ok(())
}

/// What `info` reports on the mesh file `path` (welded first when asked).
///
/// The file is read keeping NaN and infinite coordinates ([`surftopo_io::NonFinite::Keep`]), so
/// that they are listed problems here while every other command refuses them.
///
/// # Errors
/// A file that cannot be read or parsed (exit 2).
pub fn inspect_path(path: &Path, weld: bool) -> anyhow::Result<Info> {
    let (soup, welded) = match read_mesh_or_points(path, weld, surftopo_io::NonFinite::Keep)? {
        Read::Mesh(soup, welded) => (soup, welded),
        Read::PointCloud(points) => return Ok(point_cloud(path, &points)),
    };
    // Polygon meshes are inspected through the triangles the commands cut them into.
    let polygons = surftopo_mesh::inspect_polygons(&soup.positions, soup.faces());
    let (inspection, cut) = (polygons.inspection, polygons.cut);
    let cut_warning = polygons.fans_because.map(|problem| {
        format!(
            "{} (in the polygons cut by ear clipping; the fans of their corner 0, inspected \
             here and used by the commands, make a surface)",
            locate(path, &soup, &problem)
        )
    });
    let weld_hint = (!weld)
        .then(|| surftopo_mesh::geometry::weld_effect(&soup.positions, &cut.triangles, &inspection))
        .flatten()
        .map(|effect| format!("`--weld` {}", effect.describe()));
    let all_triangles = cut.is_identity();
    let surfaces: Vec<SurfaceJson> = inspection.surfaces.iter().map(Into::into).collect();
    let near = surftopo_mesh::geometry::near_degenerate_faces(&soup.positions, &cut);
    let warnings = cut_warning
        .into_iter()
        .chain(
            near.iter()
                .take(surftopo_mesh::MAX_LISTED_PROBLEMS)
                .map(|&(face, height)| near_degenerate_warning(path, &soup, face, height)),
        )
        .collect();

    let simplicial = all_triangles && !inspection.has_degenerate_faces();
    let valid = inspection.is_valid();
    Ok(Info {
        vertices: inspection.vertices,
        edges: inspection.edges,
        faces: inspection.faces,
        point_cloud: false,
        vertex_properties: property_names(&soup),
        genus: inspection.genus(),
        euler_characteristic: inspection.euler_characteristic(),
        components: inspection.components,
        closed: inspection.is_closed(),
        orientable: inspection.orientable,
        boundary_loops: inspection.boundary_loops,
        boundary_edges: inspection.boundary_edges,
        simplicial,
        valid,
        reoriented_faces: inspection.reoriented_faces,
        unreferenced_vertices: inspection.dropped_vertices,
        welded_vertices: welded,
        counts: Counts(inspection.counts),
        problems_total: inspection.problem_count,
        problems_truncated: inspection.is_truncated(),
        problems: inspection
            .problems
            .iter()
            .map(|p| locate(path, &soup, p))
            .collect(),
        near_degenerate_faces: near.len(),
        warnings,
        weld_hint,
        surfaces,
    })
}

/// The warning of a near-degenerate face, with its file, line and face.
fn near_degenerate_warning(
    path: &Path,
    soup: &surftopo_io::PolygonSoup,
    face: usize,
    height: f64,
) -> String {
    let line = soup
        .face_line(face)
        .map(|l| format!("line {l}: "))
        .unwrap_or_default();
    let height = surftopo_mesh::geometry::describe_near_degenerate(height);
    format!(
        "{}: {line}face {face}: {height}; `delaunay` may refuse it as a zero-area triangle \
         (`--mollify EPS` mollifies it)",
        crate::input::name(path)
    )
}

/// The names of the soup's per-vertex properties.
fn property_names(soup: &surftopo_io::PolygonSoup) -> Vec<String> {
    soup.attributes
        .vertex
        .iter()
        .map(|p| p.name.clone())
        .collect()
}

/// What `info` reports on a point cloud: its vertex count, properties and non-finite
/// coordinates; the surface keys 0, false or null.
fn point_cloud(path: &Path, points: &surftopo_io::PolygonSoup) -> Info {
    let mut counts = ProblemCounts::default();
    let problems: Vec<_> =
        surftopo_mesh::geometry::non_finite_coordinates(&points.positions).collect();
    problems.iter().for_each(|p| counts.add(p));
    Info {
        vertices: points.vertex_count(),
        edges: 0,
        faces: 0,
        point_cloud: true,
        vertex_properties: property_names(points),
        genus: None,
        euler_characteristic: points.vertex_count() as i64,
        components: 0,
        closed: false,
        orientable: false,
        boundary_loops: 0,
        boundary_edges: 0,
        simplicial: false,
        valid: problems.is_empty(),
        reoriented_faces: 0,
        unreferenced_vertices: 0,
        welded_vertices: 0,
        counts: Counts(counts),
        problems_total: problems.len(),
        problems_truncated: problems.len() > surftopo_mesh::MAX_LISTED_PROBLEMS,
        problems: problems
            .iter()
            .take(surftopo_mesh::MAX_LISTED_PROBLEMS)
            .map(|p| format!("{}: {p}", crate::input::name(path)))
            .collect(),
        near_degenerate_faces: 0,
        warnings: Vec::new(),
        weld_hint: None,
        surfaces: Vec::new(),
    }
}

/// The pieces the text report lists one by one (a triangle soup has as many as triangles).
const LISTED_PIECES: usize = 20;

/// The text report: one line per fact, labelled with its JSON key's words (`_` read as a space).
fn text(path: &Path, info: &Info) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    let yes = |b: bool| if b { "yes" } else { "no" };
    let mut line = |key: &str, value: &dyn std::fmt::Display| {
        writeln!(s, "  {:<24}{value}", key.replace('_', " ")).ok();
    };
    line("vertices", &info.vertices);
    if info.point_cloud {
        line(
            "faces",
            &"0: a point cloud (`info` describes it; every other command needs faces)",
        );
        if !info.vertex_properties.is_empty() {
            line("vertex_properties", &info.vertex_properties.join(" "));
        }
        if info.problems_total == 0 {
            line("problems_total", &"0 (none)");
        } else {
            line("problems_total", &info.problems_total);
        }
        let mut s = format!("{}\n{s}", crate::input::name(path));
        for p in &info.problems {
            writeln!(s, "    {p}").ok();
        }
        return s;
    }
    line("edges", &info.edges);
    line("faces", &info.faces);
    match info.genus {
        Some(g) => line("genus", &g),
        None => line("genus", &"- (the faces do not form one orientable surface)"),
    }
    line("euler_characteristic", &info.euler_characteristic);
    line("components", &info.components);
    line("closed", &yes(info.closed));
    line("orientable", &yes(info.orientable));
    line("boundary_loops", &info.boundary_loops);
    if info.boundary_edges > 0 {
        line("boundary_edges", &info.boundary_edges);
    }
    line("simplicial", &yes(info.simplicial));
    line("valid", &yes(info.valid));
    for (key, n) in [
        ("reoriented_faces", info.reoriented_faces),
        ("unreferenced_vertices", info.unreferenced_vertices),
        ("welded_vertices", info.welded_vertices),
    ] {
        if n > 0 {
            line(key, &n);
        }
    }
    for (key, n) in info.counts.0.entries() {
        if n > 0 {
            line(key, &n);
        }
    }
    if info.problems_total == 0 {
        line("problems_total", &"0 (none)");
    } else {
        line("problems_total", &info.problems_total);
    }
    if info.problems_truncated {
        line(
            "problems_truncated",
            &format!("yes (the first {} listed)", info.problems.len()),
        );
    }
    if info.near_degenerate_faces > 0 {
        line(
            "near_degenerate_faces",
            &format!("{} (warnings, listed below)", info.near_degenerate_faces),
        );
    }
    if !info.vertex_properties.is_empty() {
        line("vertex_properties", &info.vertex_properties.join(" "));
    }
    if let Some(hint) = &info.weld_hint {
        line("weld_hint", hint);
    }
    for (k, piece) in info.surfaces.iter().enumerate().take(LISTED_PIECES) {
        let detail = match (piece.genus, piece.crosscaps) {
            (Some(g), _) => format!("orientable, genus {g}"),
            (_, Some(c)) => format!("non-orientable, {c} crosscaps"),
            _ => String::new(),
        };
        line(
            &format!("surface {k}"),
            &format!(
                "{}: {} faces, χ {}, {detail}, {} boundary loops, Euler genus {}",
                piece.name,
                piece.faces,
                piece.euler_characteristic,
                piece.boundary_loops,
                piece.euler_genus
            ),
        );
    }
    if info.surfaces.len() > LISTED_PIECES {
        line(
            "surfaces",
            &format!(
                "{} more pieces (`--json` lists every one)",
                info.surfaces.len() - LISTED_PIECES
            ),
        );
    }
    let mut s = format!("{}\n{s}", crate::input::name(path));
    for p in &info.problems {
        writeln!(s, "    {p}").ok();
    }
    for w in &info.warnings {
        writeln!(s, "    warning: {w}").ok();
    }
    s
}
