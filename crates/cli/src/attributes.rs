//! Attributes through the commands that write meshes (`convert`, `quad`, `irreducible`): the
//! per-vertex ones follow their vertex (renumbered when vertices are dropped), and everything
//! that cannot be kept is said on stderr, with how much of it: what the reader skipped, the
//! per-corner tables of a command that makes new faces, what the output format cannot hold.

use crate::output::MeshFormat;
use std::path::Path;
use surftopo_io::{Attributes, Format, PolygonSoup};
use surftopo_mesh::VertexId;

/// The per-vertex columns of `attributes` through an old-to-new vertex map (invalid: dropped).
pub fn renumbered(
    attributes: &Attributes,
    new_count: usize,
    old_to_new: &[VertexId],
) -> Attributes {
    attributes.renumbered_vertices(new_count, |old| {
        old_to_new
            .get(old)
            .filter(|v| v.is_valid())
            .map(|v| v.idx())
    })
}

/// Warns that what the reader of `input` skipped is not in `output`.
pub fn warn_not_read(input: &Path, output: &Path, attributes: &Attributes) {
    for what in &attributes.not_kept {
        stderr_println!(
            "warning: {}: {what}: not read, so not in {}",
            crate::input::name(input),
            crate::output::name(output)
        );
    }
}

/// Warns that the per-corner tables of the input are dropped by `command`, whose faces are not
/// the input's.
pub fn warn_new_faces(command: &str, output: &Path, attributes: &Attributes) {
    for what in attributes.corner_descriptions() {
        stderr_println!(
            "warning: {}: {what}: dropped ({command} makes new faces; per-vertex attributes are kept)",
            crate::output::name(output)
        );
    }
}

/// The format `output` is written in: `--format`'s, else the extension's.
pub fn target_format(output: &Path, format: Option<MeshFormat>) -> Option<Format> {
    format
        .map(|f| f.format)
        .or_else(|| Format::from_path(output))
}

/// Warns about everything of `soup`'s attributes the writer of `output`'s format (`--format`'s,
/// else the extension's) leaves out.
pub fn warn_unwritable(output: &Path, format: Option<MeshFormat>, soup: &PolygonSoup) {
    let Some(format) = target_format(output, format) else {
        return;
    };
    for what in soup.unwritable(format) {
        stderr_println!("warning: {}: {what}; dropped", crate::output::name(output));
    }
}
