//! Loading a mesh file into a validated surface, with errors that say where (file, line, face).

use crate::failure::invalid;
use std::path::Path;
use std::sync::Mutex;
use surftopo_io::PolygonSoup;
use surftopo_mesh::{
    BuildError, BuildReport, CoveredSurface, PolygonTriangulation, Surface, geometry,
};

/// A surface read from a file, with what building it changed.
pub struct Loaded {
    /// The validated surface (vertex ids: the input's referenced vertices, in input order).
    pub surface: Surface,
    /// Reoriented faces, dropped vertices.
    pub report: BuildReport,
    /// Vertices merged by welding.
    pub welded: usize,
    /// The input as read (welded with `--weld`): the vertex list and per-vertex attributes that
    /// outputs on the input's vertices keep (README, "Vertex numbering"), and the faces.
    pub soup: PolygonSoup,
    /// The soup face of each face id, when polygons were cut into triangles.
    pub polygon_of: Option<Vec<u32>>,
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
    match read_mesh_or_points(path, weld, non_finite)? {
        Read::Mesh(soup, welded) => Ok((soup, welded)),
        Read::PointCloud(points) => Err(explain_limit(surftopo_io::IoError::NoFaces {
            file: name(path),
            binary_at: None,
            points: Some(Box::new(points)),
        })),
    }
}

/// A mesh file read: a mesh (with the number of vertices welded) or a point cloud.
pub enum Read {
    /// Faces were read.
    Mesh(PolygonSoup, usize),
    /// Vertices only (with their attributes).
    PointCloud(PolygonSoup),
}

/// [`read_soup_with`], giving a point cloud (vertices without faces) back instead of refusing
/// it (for `info`).
pub fn read_mesh_or_points(
    path: &Path,
    weld: bool,
    non_finite: surftopo_io::NonFinite,
) -> anyhow::Result<Read> {
    let read = if is_stdio(path) {
        surftopo_io::read_bytes_detected(&stdin_bytes()?, STDIN_NAME, non_finite)
    } else {
        surftopo_io::read_path_detected(path, &crate::limits::read_limits(), non_finite)
    };
    let (soup, format) = match read {
        Ok(read) => read,
        Err(surftopo_io::IoError::NoFaces {
            points: Some(points),
            ..
        }) => {
            crate::limits::check_elements(&name(path), points.vertex_count() as u64, "vertices")?;
            return Ok(Read::PointCloud(*points));
        }
        Err(e) => return Err(explain_limit(e)),
    };
    let (soup, welded) = weld_soup(
        &name(path),
        soup,
        weld || format == surftopo_io::Format::Stl,
    )?;
    Ok(Read::Mesh(soup, welded))
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

/// A reader error, with the option that raises the limit it hit, if any, or what to do with a
/// point cloud.
pub fn explain_limit(error: surftopo_io::IoError) -> anyhow::Error {
    match error {
        surftopo_io::IoError::InputTooLarge { .. } => {
            crate::failure::invalid(format!("{error}; raise --max-input-bytes to read it"))
        }
        surftopo_io::IoError::NoFaces {
            points: Some(_), ..
        } => crate::failure::invalid(format!(
            "{error}: this command needs faces (`surftopo info` describes a point cloud)"
        )),
        other => anyhow::Error::new(other),
    }
}

/// Renumbers the faces a build error names through `map` (e.g. triangle -> polygon).
pub fn renumber_face(error: BuildError, map: &[u32]) -> BuildError {
    error.on_faces(map)
}

/// Describes a build error with the file name and, where known, the line of the face it names.
pub fn locate(path: &Path, soup: &PolygonSoup, error: &BuildError) -> String {
    let line = error
        .clone()
        .face_mut()
        .and_then(|f| soup.face_lines.get(*f))
        .map(|l| format!("line {l}: "))
        .unwrap_or_default();
    format!("{}: {line}{error}", name(path))
}

/// The soup's triangles, or an invalid-input error naming the first non-triangular face (for
/// `isomorphic`, which compares triangulations as given).
pub fn triangles(path: &Path, soup: &PolygonSoup) -> anyhow::Result<Vec<[u32; 3]>> {
    soup.triangles().map_err(|e| {
        let error = BuildError::NotTriangle {
            face: e.face,
            sides: e.sides,
        };
        invalid(locate(path, soup, &error))
    })
}

/// The soup's faces as triangles, for the commands that need triangles.
pub struct Triangulated {
    /// The triangles: the soup's own when every face is one, else its polygons cut by
    /// [`surftopo_mesh::triangulate_polygons`].
    pub triangles: Vec<[u32; 3]>,
    /// The polygon (soup face) of each triangle, when polygons were cut.
    pub polygon_of: Option<Vec<u32>>,
}

impl Triangulated {
    /// A build error on the triangles, naming the soup's face (the polygon) instead.
    pub fn on_faces(&self, error: BuildError) -> BuildError {
        match &self.polygon_of {
            Some(map) => renumber_face(error, map),
            None => error,
        }
    }
}

/// The triangles of a soup's faces, for the commands that need triangles and for `info`
/// ([`surftopo_mesh::triangulate_polygons_as_surface`]: the fans of corner 0, with the reason,
/// when ear clipping makes no surface and they do).
pub fn cut_polygons(soup: &PolygonSoup) -> (PolygonTriangulation, Option<BuildError>) {
    surftopo_mesh::triangulate_polygons_as_surface(&soup.positions, soup.faces())
}

/// [`cut_polygons`], with a note on stderr saying how many polygons were cut (and when the fans
/// were taken instead, why).
pub fn triangulated(path: &Path, soup: &PolygonSoup) -> Triangulated {
    if soup.is_all_triangles() {
        let triangles = soup.faces().map(|f| [f[0], f[1], f[2]]).collect();
        return Triangulated {
            triangles,
            polygon_of: None,
        };
    }
    let (cut, fans_because) = cut_polygons(soup);
    let largest = soup.faces().map(<[u32]>::len).max().unwrap_or(0);
    let irregular = if cut.irregular > 0 {
        format!(
            "; {} of them not simple, not planar or repeating a vertex, so cut without the \
             guarantee of no degenerate triangle",
            cut.irregular
        )
    } else {
        String::new()
    };
    let how = match &fans_because {
        Some(problem) => format!(
            "the fan of each one's corner 0, since ear clipping gives {}",
            locate(path, soup, problem)
        ),
        None => "ear clipping in each polygon's plane".to_owned(),
    };
    stderr_println!(
        "note: {}: {} polygons of 4 to {largest} sides cut into {} triangles ({how}; the \
         triangles keep the polygon's vertices){irregular}",
        name(path),
        cut.polygons,
        cut.triangles.len() - (soup.face_count() - cut.polygons),
    );
    Triangulated {
        triangles: cut.triangles,
        polygon_of: Some(cut.face_of),
    }
}

/// What `--weld` would make of a soup whose triangles have boundary edges or several pieces,
/// as a sentence to append to a message (`None` when welding would not help).
pub fn weld_hint(soup: &PolygonSoup, triangles: &[[u32; 3]]) -> Option<String> {
    let before = surftopo_mesh::inspect(soup.positions.len(), triangles);
    let effect = geometry::weld_effect(&soup.positions, triangles, &before)?;
    Some(format!("`--weld` {}", effect.describe()))
}

/// The command running, for messages ([`set_command`]).
static COMMAND: std::sync::OnceLock<&'static str> = std::sync::OnceLock::new();

/// Names the command running (`quad`, `delaunay`, ...), for the messages of [`load_surface`].
pub fn set_command(command: &'static str) {
    let _ = COMMAND.set(command);
}

/// Reads and validates a closed, connected, orientable triangulated surface (polygons cut into
/// triangles, [`triangulated`]); the refusal of a surface with boundary, non-orientable or in
/// pieces says that the command running does not support it yet.
pub fn load_surface(path: &Path, weld: bool) -> anyhow::Result<Loaded> {
    let command = COMMAND.get().copied().unwrap_or("surftopo");
    let (soup, welded) = read_soup(path, weld)?;
    let cut = triangulated(path, &soup);
    geometry::check_finite(&soup.positions).map_err(|e| invalid(locate(path, &soup, &e)))?;
    let (mesh, report) = surftopo_mesh::build(soup.positions.len(), &cut.triangles)
        .map_err(|e| invalid(not_supported(path, &soup, &cut, command, e, weld)))?;
    let input = report.input_vertices();
    let positions = input.iter().map(|&v| soup.positions[v as usize]).collect();
    Ok(Loaded {
        surface: Surface { mesh, positions },
        report,
        welded,
        soup,
        polygon_of: cut.polygon_of,
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
            "note: {name}: {} vertices in no face",
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
/// the first place that shows it); any other error is located as usual. A soup that welding
/// would close or join (every triangle on vertices of its own) says so, unless `welded`.
fn not_supported(
    path: &Path,
    soup: &PolygonSoup,
    cut: &Triangulated,
    command: &str,
    error: BuildError,
    welded: bool,
) -> String {
    let error = cut.on_faces(error);
    let hint = (!welded)
        .then(|| weld_hint(soup, &cut.triangles))
        .flatten()
        .map(|h| format!("; {h}"))
        .unwrap_or_default();
    let what = match error {
        BuildError::BoundaryEdge { .. } => "surfaces with boundary are",
        BuildError::NonOrientable { .. } => "non-orientable surfaces are",
        BuildError::Disconnected { .. } => "files of several pieces are",
        _ => return format!("{}{hint}", locate(path, soup, &error)),
    };
    let kinds = surftopo_mesh::inspect(soup.positions.len(), &cut.triangles).surfaces;
    let names = piece_names(kinds.iter().map(|k| k.name()));
    let name = name(path);
    let located = locate(path, soup, &error);
    let place = located
        .strip_prefix(&format!("{name}: "))
        .unwrap_or(&located);
    format!(
        "{name}: {command}: {what} not supported yet (input: {names}; `surftopo info` classifies it, \
         `surftopo irreducible` takes it); {place}{hint}"
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
    /// The surface as its cover, with positions (vertex ids: the input's referenced vertices).
    pub surface: CoveredSurface,
    /// Reoriented faces (of orientable pieces), dropped vertices.
    pub report: BuildReport,
    /// Vertices merged by welding.
    pub welded: usize,
    /// The input as read (welded with `--weld`), as [`Loaded::soup`].
    pub soup: PolygonSoup,
    /// The soup face of each face id, when polygons were cut into triangles.
    pub polygon_of: Option<Vec<u32>>,
}

/// Reads and validates a compact surface of any kind (polygons cut into triangles,
/// [`triangulated`]), with a progress spinner, noting on stderr what building changed, and
/// what `--weld` would do when the file is in pieces or has boundary that welding would join
/// or close. Non-manifold edges and vertices, degenerate or duplicate faces are refused with
/// their location.
pub fn read_covered(path: &Path, weld: bool) -> anyhow::Result<LoadedCovered> {
    let (loaded, hint) = crate::progress::step("reading", || {
        let (soup, welded) = read_soup(path, weld)?;
        let cut = triangulated(path, &soup);
        let (surface, report) =
            CoveredSurface::from_triangles(soup.positions.clone(), &cut.triangles).map_err(
                |e| {
                    let hint = (!weld)
                        .then(|| weld_hint(&soup, &cut.triangles))
                        .flatten()
                        .map(|h| format!("; {h}"))
                        .unwrap_or_default();
                    invalid(format!("{}{hint}", locate(path, &soup, &cut.on_faces(e))))
                },
            )?;
        let open =
            report.surfaces.iter().any(|k| k.boundary_loops > 0) || report.surfaces.len() > 1;
        let hint = (open && !weld)
            .then(|| weld_hint(&soup, &cut.triangles))
            .flatten();
        anyhow::Ok((
            LoadedCovered {
                surface,
                report,
                welded,
                soup,
                polygon_of: cut.polygon_of,
            },
            hint,
        ))
    })?;
    log_changes(path, loaded.welded, &loaded.report);
    if let Some(hint) = hint {
        stderr_println!("note: {}: {hint}", name(path));
    }
    Ok(loaded)
}

/// The names of a file's pieces in words: each name once, in the order of first appearance,
/// with its count when above one (`torus + 3 × disk`), so a soup of 320 triangles reads
/// `320 × disk`.
pub fn piece_names(names: impl IntoIterator<Item = String>) -> String {
    let mut counted: Vec<(String, usize)> = Vec::new();
    for name in names {
        match counted.iter_mut().find(|(n, _)| *n == name) {
            Some((_, count)) => *count += 1,
            None => counted.push((name, 1)),
        }
    }
    let parts: Vec<String> = counted
        .into_iter()
        .map(|(name, count)| {
            if count == 1 {
                name
            } else {
                format!("{count} × {name}")
            }
        })
        .collect();
    parts.join(" + ")
}

/// Whether an input is portalgon JSON: a `.json` file, or standard input starting with `{`.
pub(crate) fn is_json_input(path: &Path) -> anyhow::Result<bool> {
    if is_stdio(path) {
        return stdin_is_json();
    }
    Ok(path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json")))
}
