//! Loading a mesh file into a validated surface, with errors that say where (file, line, face).

use crate::failure::invalid;
use std::path::Path;
use surftopo_io::PolygonSoup;
use surftopo_mesh::Surface;
use surftopo_mesh::{BuildError, BuildReport, geometry};

/// A surface read from a file, with what building it changed.
pub struct Loaded {
    /// The validated surface.
    pub surface: Surface,
    /// Reoriented faces, dropped vertices.
    pub report: BuildReport,
    /// Vertices merged by welding.
    pub welded: usize,
    /// The input's attributes, per-vertex ones on the surface's vertex ids
    /// ([`crate::attributes::on_mesh`]).
    pub attributes: surftopo_io::Attributes,
}

/// Reads a polygon soup, welding exactly coincident positions when asked (always for STL).
pub fn read_soup(path: &Path, weld: bool) -> anyhow::Result<(PolygonSoup, usize)> {
    let mut soup =
        surftopo_io::read_path_with(path, &crate::limits::read_limits()).map_err(explain_limit)?;
    let source = crate::failure::shown(path);
    crate::limits::check_elements(&source, soup.vertex_count() as u64, "vertices")?;
    crate::limits::check_elements(&source, soup.face_count() as u64, "faces")?;
    crate::limits::check_elements(&source, soup.face_indices.len() as u64 / 3, "triangles")?;
    let is_stl = surftopo_io::Format::from_path(path) == Some(surftopo_io::Format::Stl);
    let mut welded = 0;
    if weld || is_stl {
        let weld = soup.weld_exact();
        welded = weld.merged;
        if weld.conflicting > 0 {
            eprintln!(
                "warning: {source}: welding merged {} vertices whose per-vertex attributes differ \
                 from those of the vertex they were merged into; theirs are dropped",
                weld.conflicting
            );
        }
    }
    Ok((soup, welded))
}

/// A reader error, with the option that raises the limit it hit, if any.
pub fn explain_limit(error: surftopo_io::IoError) -> anyhow::Error {
    match error {
        surftopo_io::IoError::InputTooLarge { .. } => {
            crate::failure::invalid(format!("{error}; raise --max-input-bytes to read it"))
        }
        other => anyhow::Error::new(other),
    }
}

/// The input face a build error names, if any (mutable, to renumber it).
fn face_of(error: &mut BuildError) -> Option<&mut usize> {
    match error {
        BuildError::IndexOutOfRange { face, .. }
        | BuildError::RepeatedVertex { face, .. }
        | BuildError::DuplicateFace { face, .. }
        | BuildError::BoundaryEdge { face, .. }
        | BuildError::NonManifoldEdge { face, .. }
        | BuildError::NonOrientable { face, .. }
        | BuildError::Disconnected { face, .. }
        | BuildError::NotTriangle { face, .. } => Some(face),
        _ => None,
    }
}

/// Renumbers the face a build error names through `map` (e.g. triangle -> polygon).
pub fn renumber_face(mut error: BuildError, map: &[u32]) -> BuildError {
    if let Some(face) = face_of(&mut error) {
        *face = map[*face] as usize;
    }
    error
}

/// Fan triangulation of a polygon soup: the triangles, and the polygon of each triangle.
/// A polygon with k sides gives k - 2 triangles and k - 3 interior diagonals, so the Euler
/// characteristic, closedness, orientability and vertex fans are those of the polygons.
pub fn fan_triangles(soup: &PolygonSoup) -> (Vec<[u32; 3]>, Vec<u32>) {
    let mut triangles = Vec::with_capacity(soup.face_count());
    let mut polygon_of = Vec::with_capacity(soup.face_count());
    for (k, face) in (0..soup.face_count()).map(|k| (k, soup.face(k))) {
        for i in 1..face.len().saturating_sub(1) {
            triangles.push([face[0], face[i], face[i + 1]]);
            polygon_of.push(k as u32);
        }
    }
    (triangles, polygon_of)
}

/// Describes a build error with the file name and, where known, the line of the face it names.
pub fn locate(path: &Path, soup: &PolygonSoup, error: &BuildError) -> String {
    let line = face_of(&mut error.clone())
        .and_then(|f| soup.face_lines.get(*f))
        .map(|l| format!("line {l}: "))
        .unwrap_or_default();
    format!("{}: {line}{error}", crate::failure::shown(path))
}

/// The soup's triangles, or an invalid-input error naming the first non-triangular face.
pub fn triangles(path: &Path, soup: &PolygonSoup) -> anyhow::Result<Vec<[u32; 3]>> {
    soup.triangles().map_err(|e| {
        let error = BuildError::NotTriangle {
            face: e.face,
            sides: e.sides,
        };
        invalid(locate(path, soup, &error))
    })
}

/// Reads and validates a closed, connected, orientable triangulated surface.
pub fn load_surface(path: &Path, weld: bool) -> anyhow::Result<Loaded> {
    let (soup, welded) = read_soup(path, weld)?;
    let triangles = triangles(path, &soup)?;
    geometry::check_finite(&soup.positions).map_err(|e| invalid(locate(path, &soup, &e)))?;
    let (mesh, report) = surftopo_mesh::build(soup.positions.len(), &triangles)
        .map_err(|e| invalid(locate(path, &soup, &e)))?;
    let mut positions = vec![[0.0; 3]; mesh.vertex_slots()];
    for (old, new) in report.vertex_old_to_new.iter().enumerate() {
        if new.is_valid() {
            positions[new.idx()] = soup.positions[old];
        }
    }
    let attributes = crate::attributes::on_mesh(&soup, &report, mesh.vertex_slots());
    Ok(Loaded {
        surface: Surface { mesh, positions },
        report,
        welded,
        attributes,
    })
}

/// Notes on stderr what building changed (reoriented faces, dropped or welded vertices).
pub fn log_report(path: &Path, loaded: &Loaded) {
    let name = crate::failure::shown(path);
    if loaded.welded > 0 {
        eprintln!("note: {name}: welded {} coincident vertices", loaded.welded);
    }
    if !loaded.report.dropped_vertices.is_empty() {
        eprintln!(
            "note: {name}: dropped {} unreferenced vertices",
            loaded.report.dropped_vertices.len()
        );
    }
    if loaded.report.reoriented_faces > 0 {
        eprintln!(
            "note: {name}: reoriented {} faces to make the orientation consistent",
            loaded.report.reoriented_faces
        );
    }
}

/// Reads and validates a surface with a progress spinner, noting on stderr what building changed.
pub fn read_surface(path: &Path, weld: bool) -> anyhow::Result<Loaded> {
    let loaded = crate::progress::step("reading", || load_surface(path, weld))?;
    log_report(path, &loaded);
    Ok(loaded)
}
