//! surftopo-bench's library: the papers' experiments (`surftopo-bench papers`), shared by the
//! binary and its tests.

pub mod papers;

/// Appends `lines` (JSON lines, each ending in a newline) to the file at `path`, creating it and
/// its folder if needed.
///
/// # Errors
/// Creating the folder, opening or writing the file.
pub fn append_lines(path: &std::path::Path, lines: &str) -> std::io::Result<()> {
    use std::io::Write;
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent)?;
    }
    std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(path)?
        .write_all(lines.as_bytes())
}
