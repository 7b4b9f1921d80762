//! Loading a mesh file into a validated surface, with errors that say where (file, line, face).

use crate::failure::invalid;
use std::path::Path;
use std::sync::Mutex;
use surftopo_io::PolygonSoup;
use surftopo_mesh::{BuildError, BuildReport, CoveredSurface, Lifting, Surface, geometry};

/// A surface read from a file, with what building it changed.
pub struct Loaded {
    /// The validated surface.
    pub surface: Surface,
    /// Reoriented faces, dropped vertices.
    pub report: BuildReport,
    /// Vertices merged by welding.
    pub welded: usize,
}

/// The name of standard input in messages.
pub const STDIN_NAME: &str = "<stdin>";

/// Whether a path is `-`: standard input as an input, standard output as an output.
pub fn is_stdio(path: &Path) -> bool {
    path.as_os_str() == "-"
}

/// An input path as messages show it: [`STDIN_NAME`] for `-`, else [`crate::failure::shown`].
pub fn name(path: &Path) -> String {
    if is_stdio(path) {
        STDIN_NAME.to_owned()
    } else {
        crate::failure::shown(path)
    }
}

/// Standard input: not read yet, read into memory (peeked at, not yet handed over), or handed
/// over to the one input that names it.
enum Stdin {
    Unread,
    Buffered(Vec<u8>),
    Taken,
}

static STDIN: Mutex<Stdin> = Mutex::new(Stdin::Unread);

fn stdin_state() -> std::sync::MutexGuard<'static, Stdin> {
    STDIN
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// All of standard input within the read limits, decompressed when it starts with the gzip magic.
fn load_stdin() -> anyhow::Result<Vec<u8>> {
    surftopo_io::load_reader(
        std::io::stdin().lock(),
        &crate::limits::read_limits(),
        STDIN_NAME,
    )
    .map_err(explain_limit)
}

/// `-` named for a second input.
fn read_once() -> anyhow::Error {
    invalid(format!(
        "{STDIN_NAME}: standard input can be read once: give `-` for one input only"
    ))
}

/// The whole of standard input ([`load_stdin`]), handed over to the one input that names it;
/// a second call is refused (exit 2).
pub fn stdin_bytes() -> anyhow::Result<Vec<u8>> {
    match std::mem::replace(&mut *stdin_state(), Stdin::Taken) {
        Stdin::Unread => load_stdin(),
        Stdin::Buffered(bytes) => Ok(bytes),
        Stdin::Taken => Err(read_once()),
    }
}

/// Whether standard input holds JSON (its first byte after blanks is `{`): portalgon JSON, not
/// a mesh. The bytes read stay for [`stdin_bytes`].
pub fn stdin_is_json() -> anyhow::Result<bool> {
    let mut state = stdin_state();
    if let Stdin::Unread = *state {
        *state = Stdin::Buffered(load_stdin()?);
    }
    match &*state {
        Stdin::Buffered(bytes) => {
            Ok(bytes.iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'{'))
        }
        _ => Err(read_once()),
    }
}

/// The bytes of an input that is not a mesh (portalgon JSON): standard input for `-`, else the
/// file (decompressed when its name ends in `.gz`), within the read limits.
pub fn input_bytes(path: &Path) -> anyhow::Result<Vec<u8>> {
    if is_stdio(path) {
        return stdin_bytes();
    }
    surftopo_io::load_path(path, &crate::limits::read_limits()).map_err(explain_limit)
}

/// Reads a polygon soup, welding exactly coincident positions when asked (always for STL). The
/// format comes from the extension, else from the content (`-`: standard input; see
/// [`surftopo_io::sniff_format`]).
pub fn read_soup(path: &Path, weld: bool) -> anyhow::Result<(PolygonSoup, usize)> {
    read_soup_with(path, weld, surftopo_io::NonFinite::Refuse)
}

/// [`read_soup`], keeping or refusing NaN and infinite coordinates (`info` keeps them to list
/// them among its problems; every other command refuses them, naming file, line and vertex).
pub fn read_soup_with(
    path: &Path,
    weld: bool,
    non_finite: surftopo_io::NonFinite,
) -> anyhow::Result<(PolygonSoup, usize)> {
    let (soup, format) = if is_stdio(path) {
        surftopo_io::read_bytes_detected(&stdin_bytes()?, STDIN_NAME, non_finite)
    } else {
        surftopo_io::read_path_detected(path, &crate::limits::read_limits(), non_finite)
    }
    .map_err(explain_limit)?;
    weld_soup(
        &name(path),
        soup,
        weld || format == surftopo_io::Format::Stl,
    )
}

/// Checks a soup read from `source` against the element limits and welds exactly coincident
/// positions when `weld`; returns it with the number of vertices welded away.
fn weld_soup(
    source: &str,
    mut soup: PolygonSoup,
    weld: bool,
) -> anyhow::Result<(PolygonSoup, usize)> {
    crate::limits::check_elements(source, soup.vertex_count() as u64, "vertices")?;
    crate::limits::check_elements(source, soup.face_count() as u64, "faces")?;
    crate::limits::check_elements(source, soup.face_indices.len() as u64 / 3, "triangles")?;
    let mut welded = 0;
    if weld {
        let weld = soup.weld_exact();
        welded = weld.merged;
        if weld.conflicting > 0 {
            stderr_println!(
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
        | BuildError::NotTriangle { face, .. }
        | BuildError::ZeroArea { face } => Some(face),
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
    format!("{}: {line}{error}", name(path))
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

/// The command running, for messages ([`set_command`]).
static COMMAND: std::sync::OnceLock<&'static str> = std::sync::OnceLock::new();

/// Names the command running (`quad`, `delaunay`, ...), for the messages of [`load_surface`].
pub fn set_command(command: &'static str) {
    let _ = COMMAND.set(command);
}

/// Reads and validates a closed, connected, orientable triangulated surface; the refusal of a
/// surface with boundary, non-orientable or in pieces says that the command running does not
/// support it yet.
pub fn load_surface(path: &Path, weld: bool) -> anyhow::Result<Loaded> {
    let command = COMMAND.get().copied().unwrap_or("surftopo");
    let (soup, welded) = read_soup(path, weld)?;
    let triangles = triangles(path, &soup)?;
    geometry::check_finite(&soup.positions).map_err(|e| invalid(locate(path, &soup, &e)))?;
    let (mesh, report) = surftopo_mesh::build(soup.positions.len(), &triangles)
        .map_err(|e| invalid(not_supported(path, &soup, &triangles, command, &e)))?;
    let mut positions = vec![[0.0; 3]; mesh.vertex_slots()];
    for (old, new) in report.vertex_old_to_new.iter().enumerate() {
        if new.is_valid() {
            positions[new.idx()] = soup.positions[old];
        }
    }
    Ok(Loaded {
        surface: Surface { mesh, positions },
        report,
        welded,
    })
}

/// Notes on stderr what building changed (reoriented faces, dropped or welded vertices).
pub fn log_report(path: &Path, loaded: &Loaded) {
    log_changes(path, loaded.welded, &loaded.report);
}

/// [`log_report`] from its parts.
fn log_changes(path: &Path, welded: usize, report: &BuildReport) {
    let name = name(path);
    if welded > 0 {
        stderr_println!("note: {name}: welded {welded} coincident vertices");
    }
    if !report.dropped_vertices.is_empty() {
        stderr_println!(
            "note: {name}: dropped {} unreferenced vertices",
            report.dropped_vertices.len()
        );
    }
    if report.reoriented_faces > 0 {
        stderr_println!(
            "note: {name}: reoriented {} faces to make the orientation consistent",
            report.reoriented_faces
        );
    }
}

/// The message for a build error of `command`: a surface with boundary, non-orientable or in
/// pieces is a valid surface that `command` does not support yet (with its classification and
/// the first place that shows it); any other error is located as usual.
fn not_supported(
    path: &Path,
    soup: &PolygonSoup,
    triangles: &[[u32; 3]],
    command: &str,
    error: &BuildError,
) -> String {
    let what = match error {
        BuildError::BoundaryEdge { .. } => "surfaces with boundary are",
        BuildError::NonOrientable { .. } => "non-orientable surfaces are",
        BuildError::Disconnected { .. } => "files of several pieces are",
        _ => return locate(path, soup, error),
    };
    let kinds = surftopo_mesh::inspect(soup.positions.len(), triangles).surfaces;
    let names: Vec<String> = kinds.iter().map(|k| k.name()).collect();
    let name = name(path);
    let located = locate(path, soup, error);
    let place = located
        .strip_prefix(&format!("{name}: "))
        .unwrap_or(&located);
    format!(
        "{name}: {command}: {what} not supported yet (input: {}; `surftopo info` classifies it, \
         `surftopo irreducible` takes it); {place}",
        names.join(" + "),
    )
}

/// Reads and validates a surface with a progress spinner, noting on stderr what building changed.
pub fn read_surface(path: &Path, weld: bool) -> anyhow::Result<Loaded> {
    let loaded = crate::progress::step("reading", || load_surface(path, weld))?;
    log_report(path, &loaded);
    Ok(loaded)
}

/// A surface of any kind read from a file (boundary loops, non-orientable, several pieces), with
/// what building it changed.
pub struct LoadedCovered {
    /// The surface as its cover, with positions.
    pub surface: CoveredSurface,
    /// Reoriented faces (of orientable pieces), dropped vertices.
    pub report: BuildReport,
    /// Vertices merged by welding.
    pub welded: usize,
    /// The input's attributes, per-vertex ones on the surface's vertex ids (its classes).
    pub attributes: surftopo_io::Attributes,
}

/// Reads and validates a triangulated compact surface of any kind, with a progress spinner,
/// noting on stderr what building changed. Non-manifold edges and vertices, degenerate or
/// duplicate faces are refused with their location.
pub fn read_covered(path: &Path, weld: bool) -> anyhow::Result<LoadedCovered> {
    let loaded = crate::progress::step("reading", || {
        let (soup, welded) = read_soup(path, weld)?;
        let triangles = triangles(path, &soup)?;
        let (surface, report) = CoveredSurface::from_triangles(soup.positions.clone(), &triangles)
            .map_err(|e| invalid(locate(path, &soup, &e)))?;
        let classes = surface.cover.sheets.class_count();
        let attributes = crate::attributes::on_mesh(&soup, &report, classes);
        anyhow::Ok(LoadedCovered {
            surface,
            report,
            welded,
            attributes,
        })
    })?;
    log_changes(path, loaded.welded, &loaded.report);
    Ok(loaded)
}
