//! Writing results: mesh files atomically through surftopo-io; JSON to stdout.

use std::path::Path;
use surftopo_io::{PolygonSoup, WriteOptions};
use surftopo_mesh::Surface;

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
