//! Writing results: mesh files atomically through surftopo-io; JSON to stdout.

use std::path::Path;
use surftopo_io::{PolygonSoup, WriteOptions};
use surftopo_mesh::generators::Surface;

/// Writes a surface's live faces (dense vertex ids) to a mesh file, atomically.
pub fn write_surface(path: &Path, surface: &Surface) -> anyhow::Result<()> {
    let (positions, triangles) = surface.to_triangles();
    write_soup(path, &PolygonSoup::from_triangles(positions, &triangles))
}

/// Writes a polygon soup to a mesh file (format from the extension), atomically.
pub fn write_soup(path: &Path, soup: &PolygonSoup) -> anyhow::Result<()> {
    surftopo_io::write_path(path, soup, &WriteOptions::default()).map_err(|e| match e {
        // The soup is surftopo's own: an inconsistent one is an internal failure.
        surftopo_io::IoError::InvalidSoup { .. } => anyhow::Error::new(e),
        surftopo_io::IoError::Io { source, .. } => crate::failure::unwritable(path, &source),
        other => crate::failure::invalid(other.to_string()),
    })
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

/// Writes a symmetric matrix atomically in the format [`MatrixFile::of`] gives for `path`.
pub fn write_matrix(
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
    let format = MatrixFile::of(path, diagonal)?;
    write_file(path, |w| {
        match format {
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
    })
}

/// Prints a value as pretty JSON on stdout.
pub fn print_json(value: &impl serde::Serialize) -> anyhow::Result<()> {
    let mut text = serde_json::to_string_pretty(value)?;
    text.push('\n');
    emit(&text)
}

/// Writes results to stdout. A closed pipe (`surftopo info x | head`) is not an error: see
/// [`is_broken_pipe`]; any other failure (a full disk) names stdout, exit code 2.
pub fn emit(text: &str) -> anyhow::Result<()> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| {
            if e.kind() == std::io::ErrorKind::BrokenPipe {
                anyhow::Error::new(e)
            } else {
                crate::failure::invalid(format!("stdout: not written: {e}"))
            }
        })
}

/// Whether an error is stdout's reader having gone away.
pub fn is_broken_pipe(error: &anyhow::Error) -> bool {
    error.chain().any(|cause| {
        cause
            .downcast_ref::<std::io::Error>()
            .is_some_and(|e| e.kind() == std::io::ErrorKind::BrokenPipe)
    })
}

/// Writes a file atomically (temporary sibling, then rename) with `fill` writing its contents. Any
/// failure (missing folder, read-only or full disk) is an unwritable output: exit code 2, like
/// mesh outputs.
pub fn write_file(
    path: &Path,
    fill: impl FnOnce(&mut std::io::BufWriter<&mut std::fs::File>) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    use std::io::Write;
    let mut failure = None;
    let result = surftopo_io::atomic_write(path, |mut file| {
        let mut writer = std::io::BufWriter::new(&mut file);
        if let Err(e) = fill(&mut writer) {
            failure = Some(e);
            return Err(std::io::Error::other("writing failed"));
        }
        writer.flush()?;
        drop(writer);
        Ok(file)
    });
    match (failure, result) {
        (Some(e), _) => Err(crate::failure::unwritable(
            path,
            &crate::failure::message(&e),
        )),
        (None, Err(e)) => Err(crate::failure::unwritable(path, &e)),
        (None, Ok(())) => Ok(()),
    }
}
