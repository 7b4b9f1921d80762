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
    surftopo_io::write_path(path, soup, &WriteOptions::default())?;
    Ok(())
}

/// Prints a value as pretty JSON on stdout.
pub fn print_json(value: &impl serde::Serialize) -> anyhow::Result<()> {
    let mut text = serde_json::to_string_pretty(value)?;
    text.push('\n');
    emit(&text)
}

/// Writes results to stdout. A closed pipe (`surftopo info x | head`) is not an error: see
/// [`is_broken_pipe`].
pub fn emit(text: &str) -> anyhow::Result<()> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes())?;
    out.flush()?;
    Ok(())
}

/// Whether an error is stdout's reader having gone away.
pub fn is_broken_pipe(error: &anyhow::Error) -> bool {
    error.chain().any(|cause| {
        cause
            .downcast_ref::<std::io::Error>()
            .is_some_and(|e| e.kind() == std::io::ErrorKind::BrokenPipe)
    })
}

/// Writes a file atomically (temporary sibling, then rename) with `fill` writing its contents.
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
        (Some(e), _) => Err(e.context(format!("{}: not written", path.display()))),
        (None, Err(e)) => {
            Err(anyhow::Error::new(e).context(format!("{}: not written", path.display())))
        }
        (None, Ok(())) => Ok(()),
    }
}
