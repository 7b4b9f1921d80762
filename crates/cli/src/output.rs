//! Writing results: output paths checked before any work ([`check_outputs`]), files written
//! atomically through surftopo-io (several outputs of one command together: [`Outputs`]), JSON
//! to stdout. A mesh output `-` is standard output (its format from `--format`, [`MeshFormat`]);
//! summaries then go to stderr ([`emit`]).

use crate::failure::{invalid, shown};
use std::path::{Component, Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use surftopo_intrinsic::SparseMatrix;
use surftopo_io::{Format, PolygonSoup, StagedFile, WriteOptions};
use surftopo_mesh::Surface;

/// A mesh output's format as `--format` gives it: `obj`, `off`, `ply` or `stl`, optionally
/// followed by `.gz` (gzip-compressed), as a file name would end.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MeshFormat {
    /// The format.
    pub format: Format,
    /// gzip-compressed.
    pub gzip: bool,
}

impl MeshFormat {
    /// The format a file name's ending gives, if it names one (`m.ply.gz`: PLY, gzip).
    pub fn of_path(path: &Path) -> Option<Self> {
        Format::from_path(path).map(|format| MeshFormat {
            format,
            gzip: surftopo_io::is_gzip_path(path),
        })
    }

    /// Parses `--format`'s value (case-insensitive).
    ///
    /// # Errors
    /// The accepted values, for clap's message (exit 2).
    pub fn parse(value: &str) -> Result<Self, String> {
        let lower = value.to_ascii_lowercase();
        let (name, gzip) = match lower.strip_suffix(".gz") {
            Some(name) => (name, true),
            None => (lower.as_str(), false),
        };
        Format::from_extension(name)
            .map(|format| MeshFormat { format, gzip })
            .ok_or_else(|| {
                "expected obj, off, ply or stl, optionally followed by .gz (e.g. ply.gz)".to_owned()
            })
    }
}

impl std::fmt::Display for MeshFormat {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let gz = if self.gzip { ".gz" } else { "" };
        write!(f, "{}{gz}", self.format.extension())
    }
}

/// What an output file holds, and so the extensions it may have.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputKind {
    /// A mesh: `.obj`, `.off`, `.ply` or `.stl`, optionally `.gz`.
    Mesh,
    /// A mesh in the format `--format` gives: written to standard output for `-`, to a file of
    /// any name otherwise (a name whose extension says another format is refused).
    MeshIn(MeshFormat),
    /// An intrinsic triangulation or tessellation: portalgon JSON, `.json` (a mesh file cannot
    /// hold its loops and multi-edges).
    Portalgon,
    /// A sparse matrix: Matrix Market (`.mtx`) or SciPy's sparse `.npz`.
    Matrix,
    /// A diagonal matrix: as [`OutputKind::Matrix`], or its diagonal as a NumPy `.npy` vector.
    DiagonalMatrix,
}

/// The kind of a mesh output, given `--format` or not.
pub fn mesh_kind(format: Option<MeshFormat>) -> OutputKind {
    format.map_or(OutputKind::Mesh, OutputKind::MeshIn)
}

/// An output path as messages show it: `<stdout>` for `-`, else [`shown`].
pub fn name(path: &Path) -> String {
    if crate::input::is_stdio(path) {
        "<stdout>".to_owned()
    } else {
        shown(path)
    }
}

/// Set once an output is standard output: summaries and JSON figures then go to stderr.
static STDOUT_CARRIES_OUTPUT: AtomicBool = AtomicBool::new(false);

/// Whether the file name of `path` ends in `.ext` (case-insensitive).
fn has_extension(path: &Path, ext: &str) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case(ext))
}

/// Refuses an output whose extension does not fit what it will hold (exit 2); `option` names the
/// option that gave it (`-o`, `--laplacian`, ...).
fn check_extension(option: &str, path: &Path, kind: OutputKind) -> anyhow::Result<()> {
    let refuse = |what: &str| Err(invalid(format!("{}: {option}: {what}", name(path))));
    let stdio = crate::input::is_stdio(path);
    match kind {
        OutputKind::Mesh if stdio => refuse(
            "a mesh written to standard output needs --format obj, off, ply or stl (optionally \
             .gz, e.g. --format ply.gz)",
        ),
        OutputKind::Mesh => match Format::from_path(path) {
            Some(_) => Ok(()),
            None => refuse(
                "not a mesh file name; write .obj, .off, .ply or .stl (optionally .gz), or give \
                 --format",
            ),
        },
        OutputKind::MeshIn(_) if stdio => Ok(()),
        OutputKind::MeshIn(format) => match MeshFormat::of_path(path) {
            Some(named) if named != format => refuse(&format!(
                "the name says {named}, --format says {format}: give one format"
            )),
            _ => Ok(()),
        },
        _ if stdio => {
            refuse("standard output (`-`) takes a mesh only; write this output to a file")
        }
        OutputKind::Portalgon if has_extension(path, "json") => Ok(()),
        OutputKind::Portalgon => refuse(
            "an intrinsic triangulation is written as portalgon JSON (.json): a mesh file cannot \
             hold its loops and multi-edges",
        ),
        OutputKind::Matrix | OutputKind::DiagonalMatrix
            if has_extension(path, "mtx") || has_extension(path, "npz") =>
        {
            Ok(())
        }
        OutputKind::DiagonalMatrix if has_extension(path, "npy") => Ok(()),
        OutputKind::Matrix if has_extension(path, "npy") => refuse(
            "a .npy file holds a vector (the diagonal mass matrix); write a sparse matrix to .npz \
             or .mtx",
        ),
        OutputKind::Matrix | OutputKind::DiagonalMatrix => {
            refuse("a matrix is written as Matrix Market (.mtx) or SciPy sparse (.npz)")
        }
    }
}

/// The path that identifies an output file: the canonical path when the file exists; else its
/// folder's canonical path joined with its name when the folder exists; else the path made
/// absolute with `.` and `..` resolved lexically.
fn identity(path: &Path) -> PathBuf {
    if let Ok(canonical) = std::fs::canonicalize(path) {
        return canonical;
    }
    let absolute = std::env::current_dir()
        .map(|dir| dir.join(path))
        .unwrap_or_else(|_| path.to_path_buf());
    if let (Some(parent), Some(name)) = (absolute.parent(), absolute.file_name())
        && let Ok(folder) = std::fs::canonicalize(parent)
    {
        return folder.join(name);
    }
    let mut normal = PathBuf::new();
    for component in absolute.components() {
        match component {
            Component::CurDir => {}
            Component::ParentDir => {
                normal.pop();
            }
            other => normal.push(other),
        }
    }
    normal
}

/// Checks a command's outputs before any work: each extension fits its kind (`-`, standard
/// output, only for a mesh with `--format`), and no file is named by two options (compared by
/// [`identity`]). `outputs`: (option, path, kind). Once an output is `-`, [`emit`] writes to
/// stderr.
///
/// # Errors
/// An invalid-input error (exit 2) naming the path and the option(s).
pub fn check_outputs(outputs: &[(&str, &Path, OutputKind)]) -> anyhow::Result<()> {
    for &(option, path, kind) in outputs {
        check_extension(option, path, kind)?;
    }
    if outputs.iter().any(|o| crate::input::is_stdio(o.1)) {
        STDOUT_CARRIES_OUTPUT.store(true, Ordering::Relaxed);
    }
    let identities: Vec<PathBuf> = outputs.iter().map(|o| identity(o.1)).collect();
    for (j, id) in identities.iter().enumerate() {
        if let Some(i) = identities[..j].iter().position(|earlier| earlier == id) {
            return Err(invalid(format!(
                "{}: named by both {} and {}: give each output its own file",
                shown(outputs[j].1),
                outputs[i].0,
                outputs[j].0
            )));
        }
    }
    Ok(())
}

/// The output files of one command, written under temporary names and renamed over their
/// targets by [`Outputs::commit`] only once every one is written: a failure before that (an
/// error, or a signal: the temporary files are registered with surftopo-io) leaves no output
/// behind. The renames follow one another; a rename failing midway (rare: same folder, already
/// written) leaves the outputs committed before it. A mesh for standard output (`-`) is encoded
/// in memory and written by [`Outputs::commit`], before the renames (stdout cannot be staged).
#[derive(Default)]
pub struct Outputs {
    staged: Vec<StagedFile>,
    stdout: Option<Vec<u8>>,
}

impl Outputs {
    /// Writes a polygon soup as a mesh in `format` (`--format`; else the extension's) with
    /// `options` (PLY encoding and precision) under a temporary name, or into memory for
    /// standard output (`-`).
    pub fn soup_with(
        &mut self,
        path: &Path,
        soup: &PolygonSoup,
        format: Option<MeshFormat>,
        options: &WriteOptions,
    ) -> anyhow::Result<()> {
        let format = format
            .or_else(|| MeshFormat::of_path(path))
            .ok_or_else(|| invalid(format!("{}: not a mesh file name", name(path))))?;
        if format.format == Format::Stl {
            note_stl_losses(path, soup);
        }
        if crate::input::is_stdio(path) {
            let mut bytes = Vec::new();
            crate::progress::step(&writing(path), || {
                surftopo_io::write_encoded(&mut bytes, soup, format.format, format.gzip, options)
            })
            .map_err(|e| write_error(path, e))?;
            self.stdout = Some(bytes);
        } else {
            self.staged.push(stage_soup(path, soup, format, options)?);
        }
        Ok(())
    }

    /// Writes a file under a temporary name, `fill` writing its contents.
    pub fn file(
        &mut self,
        path: &Path,
        fill: impl FnOnce(&mut std::io::BufWriter<&mut std::fs::File>) -> anyhow::Result<()>,
    ) -> anyhow::Result<()> {
        self.staged.push(stage_file(path, fill)?);
        Ok(())
    }

    /// Renames every file written over its target, in the order written.
    ///
    /// # Errors
    /// An unwritable-output error (exit 2) naming the file whose rename failed.
    pub fn commit(self) -> anyhow::Result<()> {
        if let Some(bytes) = &self.stdout {
            write_stdout(bytes)?;
        }
        for staged in self.staged {
            let target = staged.target().to_path_buf();
            staged
                .commit()
                .map_err(|e| crate::failure::unwritable(&target, &e))?;
        }
        Ok(())
    }
}

/// Writes a surface's live faces (dense vertex ids) to a mesh file, atomically.
pub fn write_surface(path: &Path, surface: &Surface) -> anyhow::Result<()> {
    write_surface_as(path, surface, None)
}

/// [`write_surface`] in `format` (`--format`; else the extension's), `-` to standard output.
pub fn write_surface_as(
    path: &Path,
    surface: &Surface,
    format: Option<MeshFormat>,
) -> anyhow::Result<()> {
    let (positions, triangles) = surface.to_triangles();
    write_soup_as(
        path,
        &PolygonSoup::from_triangles(positions, &triangles),
        format,
    )
}

/// Writes a polygon soup to a mesh file (format from the extension), atomically, under a
/// progress spinner (a gzip-compressed mesh of millions of faces takes seconds).
pub fn write_soup(path: &Path, soup: &PolygonSoup) -> anyhow::Result<()> {
    write_soup_as(path, soup, None)
}

/// [`write_soup`] in `format` (`--format`; else the extension's), `-` to standard output.
pub fn write_soup_as(
    path: &Path,
    soup: &PolygonSoup,
    format: Option<MeshFormat>,
) -> anyhow::Result<()> {
    write_soup_with(path, soup, format, &WriteOptions::default())
}

/// [`write_soup_as`] with the given write options (PLY encoding and precision).
pub fn write_soup_with(
    path: &Path,
    soup: &PolygonSoup,
    format: Option<MeshFormat>,
    options: &WriteOptions,
) -> anyhow::Result<()> {
    let mut outputs = Outputs::default();
    outputs.soup_with(path, soup, format, options)?;
    outputs.commit()
}

/// A polygon soup written as a mesh file in `format` under a temporary name ([`StagedFile`]).
fn stage_soup(
    path: &Path,
    soup: &PolygonSoup,
    format: MeshFormat,
    options: &WriteOptions,
) -> anyhow::Result<StagedFile> {
    crate::progress::step(&writing(path), || {
        surftopo_io::stage_path_as(path, soup, format.format, format.gzip, options)
    })
    .map_err(|e| write_error(path, e))
}

/// A writer's error as the CLI reports it.
fn write_error(path: &Path, e: surftopo_io::IoError) -> anyhow::Error {
    match e {
        // The soup is surftopo's own: an inconsistent one is an internal failure.
        surftopo_io::IoError::InvalidSoup { .. } => anyhow::Error::new(e),
        surftopo_io::IoError::Io { source, .. } => crate::failure::unwritable(path, &source),
        other => crate::failure::invalid(other.to_string()),
    }
}

/// Notes on stderr what an STL file cannot hold of `soup`: coordinates that single precision
/// rounds, polygons (cut into triangles). Shared vertices are not noted: STL never has them, and
/// reading it back welds exactly coincident corners.
fn note_stl_losses(path: &Path, soup: &PolygonSoup) {
    let rounded = soup
        .positions
        .iter()
        .flatten()
        .filter(|&&c| f64::from(c as f32) != c)
        .count();
    if rounded > 0 {
        stderr_println!(
            "note: {}: STL holds single precision: {rounded} coordinates rounded",
            name(path)
        );
    }
    let polygons = soup.faces().filter(|f| f.len() > 3).count();
    if polygons > 0 {
        stderr_println!(
            "note: {}: STL holds triangles: {polygons} polygons cut into triangle fans",
            name(path)
        );
    }
}

/// Whether standard output was closed when the process started (`surftopo info m.obj >&-`).
/// Rust's runtime then opens `/dev/null` read-write on descriptor 1, so writes would vanish
/// silently; a shell's `>/dev/null` opens it write-only. Linux only (read from `/proc`);
/// elsewhere `false`.
pub fn stdout_was_closed() -> bool {
    let is_null = std::fs::read_link("/proc/self/fd/1").is_ok_and(|p| p == Path::new("/dev/null"));
    let read_write = || {
        let info = std::fs::read_to_string("/proc/self/fdinfo/1").unwrap_or_default();
        info.lines()
            .find_map(|l| l.strip_prefix("flags:"))
            .and_then(|f| u32::from_str_radix(f.trim(), 8).ok())
            .is_some_and(|flags| flags & 0o3 == 0o2)
    };
    is_null && read_write()
}

/// Set by `main` when [`stdout_was_closed`]: every write to stdout then fails (exit 2).
pub static STDOUT_CLOSED: AtomicBool = AtomicBool::new(false);

/// Writes a mesh's bytes to standard output; failures as [`emit`]'s.
fn write_stdout(bytes: &[u8]) -> anyhow::Result<()> {
    use std::io::Write;
    if STDOUT_CLOSED.load(Ordering::Relaxed) {
        return Err(crate::failure::invalid(
            "stdout: not written: standard output is closed",
        ));
    }
    let mut out = std::io::stdout().lock();
    out.write_all(bytes)
        .and_then(|()| out.flush())
        .map_err(stdout_error)
}

/// A failed write to stdout, named (exit 2): a closed pipe (`surftopo convert m.obj - | head -c
/// 10`: the output is not all delivered), a closed or full stdout.
fn stdout_error(e: std::io::Error) -> anyhow::Error {
    let cause = if e.kind() == std::io::ErrorKind::BrokenPipe {
        "its reader closed the pipe before the end".to_string()
    } else {
        e.to_string()
    };
    crate::failure::invalid(format!("stdout: not written: {cause}"))
}

/// How a matrix output is written, by its extension: `.npz` (SciPy's `save_npz` layout,
/// `scipy.sparse.load_npz` reads it), `.npy` (the diagonal as a vector, for diagonal matrices),
/// Matrix Market otherwise (symmetric storage: every matrix surftopo writes is symmetric).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MatrixFile {
    /// `.npz`.
    Npz,
    /// `.npy`: the diagonal.
    NpyDiagonal,
    /// Matrix Market, `symmetric`.
    MatrixMarket,
}

impl MatrixFile {
    /// The format of `path`; `diagonal` says whether the matrix is diagonal, and a `.npy` for a
    /// matrix that is not is refused (exit 2) before any work.
    pub fn of(path: &Path, diagonal: bool) -> anyhow::Result<Self> {
        let ext = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase());
        match ext.as_deref() {
            Some("npz") => Ok(MatrixFile::Npz),
            Some("npy") if diagonal => Ok(MatrixFile::NpyDiagonal),
            Some("npy") => Err(crate::failure::invalid(format!(
                "{}: a .npy file holds a vector (the diagonal mass matrix); write a sparse matrix \
                 to .npz or .mtx",
                crate::failure::shown(path)
            ))),
            _ => Ok(MatrixFile::MatrixMarket),
        }
    }
}

/// Writes a symmetric matrix to `w` in the format [`MatrixFile::of`] gives for `path`.
pub fn fill_matrix(
    w: &mut impl std::io::Write,
    path: &Path,
    matrix: &surftopo_intrinsic::SparseMatrix,
    comment: &str,
) -> anyhow::Result<()> {
    let diagonal = matrix
        .cols
        .iter()
        .enumerate()
        .all(|(i, &c)| c as usize == i)
        && matrix.nnz() == matrix.n;
    match MatrixFile::of(path, diagonal)? {
        MatrixFile::Npz => surftopo_intrinsic::write_npz(w, matrix)?,
        MatrixFile::NpyDiagonal => surftopo_intrinsic::write_npy(w, &matrix.values)?,
        MatrixFile::MatrixMarket => surftopo_intrinsic::write_matrix_market(
            w,
            matrix,
            comment,
            surftopo_intrinsic::MatrixStorage::Symmetric,
        )?,
    }
    Ok(())
}

/// Prints a value as pretty JSON on stdout, every time (a number under a key ending in
/// `seconds`) rounded to the microsecond: a clock's last digits are noise, and
/// `0.0012000300000000002` is not a figure anyone reads.
/// Keys keep the order the value serialises them in (serde_json's `preserve_order`: a struct's
/// field order, not sorted by name).
pub fn print_json(value: &impl serde::Serialize) -> anyhow::Result<()> {
    let mut value = serde_json::to_value(value)?;
    round_times(&mut value);
    let mut text = serde_json::to_string_pretty(&value)?;
    text.push('\n');
    emit(&text)
}

/// Rounds, in place and at any depth, the numbers under keys ending in `seconds` to the
/// microsecond.
fn round_times(value: &mut serde_json::Value) {
    match value {
        serde_json::Value::Object(map) => {
            for (key, item) in map.iter_mut() {
                match item.as_f64() {
                    Some(seconds) if key.ends_with("seconds") && item.is_f64() => {
                        let rounded = (seconds * 1e6).round() / 1e6;
                        if let Some(number) = serde_json::Number::from_f64(rounded) {
                            *item = serde_json::Value::Number(number);
                        }
                    }
                    _ => round_times(item),
                }
            }
        }
        serde_json::Value::Array(items) => items.iter_mut().for_each(round_times),
        _ => {}
    }
}

/// A duration for a summary line: three significant digits in µs, ms or s (`412 µs`,
/// `12.3 ms`, `1.23 s`, `123 s`), so that a fast step never reads `0.000 s`.
pub fn format_seconds(seconds: f64) -> String {
    let (value, unit) = if seconds < 1e-3 {
        (seconds * 1e6, "µs")
    } else if seconds < 1.0 {
        (seconds * 1e3, "ms")
    } else {
        (seconds, "s")
    };
    // The thresholds are those of the rounded value, so that 9.996 ms reads `10.0 ms`, not `10.00 ms`.
    let decimals = if value >= 99.95 {
        0
    } else if value >= 9.995 {
        1
    } else {
        2
    };
    format!("{value:.decimals$} {unit}")
}

/// Whether `stderr_println!` writes nothing ([`mute_notes`]).
static NOTES_MUTED: AtomicBool = AtomicBool::new(false);

/// Whether notes and warnings on stderr are muted.
pub fn notes_muted() -> bool {
    NOTES_MUTED.load(Ordering::Relaxed)
}

/// Mutes `stderr_println!` until the guard is dropped: the demo calls the commands' code, whose
/// notes (polygons cut, vertices in no face) would break its lines; each line says what they
/// would. Error messages are printed after the command returns, the guard dropped.
pub fn mute_notes() -> MutedNotes {
    NOTES_MUTED.store(true, Ordering::Relaxed);
    MutedNotes
}

/// The guard of [`mute_notes`].
pub struct MutedNotes;

impl Drop for MutedNotes {
    fn drop(&mut self) {
        NOTES_MUTED.store(false, Ordering::Relaxed);
    }
}

/// Writes results to stdout, or to stderr when stdout carries an output (`-`, see
/// [`check_outputs`]). A failure (a closed pipe, a full disk) names stdout, exit code 2; on
/// stderr the text is dropped when stderr cannot take it.
pub fn emit(text: &str) -> anyhow::Result<()> {
    if STDOUT_CARRIES_OUTPUT.load(Ordering::Relaxed) {
        stderr_print!("{text}");
        return Ok(());
    }
    write_stdout(text.as_bytes())
}

/// A progress message naming the output.
fn writing(path: &Path) -> String {
    format!("writing {}", name(path))
}

/// Writes a file atomically (temporary sibling, then rename) with `fill` writing its contents,
/// under a progress spinner. Any failure (missing folder, read-only or full disk) is an
/// unwritable output: exit code 2, like mesh outputs.
pub fn write_file(
    path: &Path,
    fill: impl FnOnce(&mut std::io::BufWriter<&mut std::fs::File>) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    let mut outputs = Outputs::default();
    outputs.file(path, fill)?;
    outputs.commit()
}

/// A file written under a temporary name ([`StagedFile`]), `fill` writing its contents; failures
/// as [`write_file`]'s.
fn stage_file(
    path: &Path,
    fill: impl FnOnce(&mut std::io::BufWriter<&mut std::fs::File>) -> anyhow::Result<()>,
) -> anyhow::Result<StagedFile> {
    use std::io::Write;
    let mut failure = None;
    let result = crate::progress::step(&writing(path), || {
        surftopo_io::stage_write(path, |mut file| {
            let mut writer = std::io::BufWriter::new(&mut file);
            if let Err(e) = fill(&mut writer) {
                failure = Some(e);
                return Err(std::io::Error::other("writing failed"));
            }
            writer.flush()?;
            drop(writer);
            Ok(file)
        })
    });
    match (failure, result) {
        (Some(e), _) => Err(crate::failure::unwritable(
            path,
            &crate::failure::message(&e),
        )),
        (None, Err(e)) => Err(crate::failure::unwritable(path, &e)),
        (None, Ok(staged)) => Ok(staged),
    }
}

/// Refuses to write a matrix that is not representable
/// ([`SparseMatrix::check_representable`]: an `inf` entry, or a mass matrix of zeros). (A
/// Laplacian may have a zero diagonal: a one-vertex torus.)
pub(crate) fn check_matrix(
    matrix: &SparseMatrix,
    what: &str,
    positive_diagonal: bool,
) -> anyhow::Result<()> {
    matrix
        .check_representable(positive_diagonal)
        .map_err(|e| invalid(format!("{what}: {e}")))
}

#[cfg(test)]
mod tests {
    use super::{format_seconds, round_times};

    #[test]
    fn durations_read_with_three_significant_digits_and_a_unit() {
        assert_eq!(format_seconds(0.0), "0.00 µs");
        assert_eq!(format_seconds(0.000_412_3), "412 µs");
        assert_eq!(format_seconds(0.001_200_03), "1.20 ms");
        assert_eq!(format_seconds(0.012_34), "12.3 ms");
        assert_eq!(format_seconds(0.5), "500 ms");
        assert_eq!(format_seconds(1.234_5), "1.23 s");
        assert_eq!(format_seconds(123.4), "123 s");
    }

    #[test]
    fn json_times_are_rounded_to_the_microsecond_and_other_numbers_kept() {
        let mut value = serde_json::json!({
            "seconds": 0.001_200_030_000_000_000_2,
            "quality": {"mean": 0.123_456_789_1, "total_seconds": 2.5e-9},
            "runs": [{"augmentation_seconds": 1.000_000_4}],
            "flips": 3
        });
        round_times(&mut value);
        assert_eq!(value["seconds"], 0.0012);
        assert_eq!(value["quality"]["mean"], 0.123_456_789_1);
        assert_eq!(value["quality"]["total_seconds"], 0.0);
        assert_eq!(value["runs"][0]["augmentation_seconds"], 1.0);
        assert_eq!(value["flips"], 3);
    }
}
