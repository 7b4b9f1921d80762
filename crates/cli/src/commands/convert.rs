//! `surftopo convert`: any readable format to OBJ, OFF or PLY (polygons kept as they are).

use crate::input::read_soup;
use std::path::Path;

/// Converts `input` to `output`, welding exactly coincident positions when asked.
pub fn run(input: &Path, output: &Path, weld: bool) -> anyhow::Result<()> {
    let (soup, welded) = crate::progress::step("reading", || read_soup(input, weld))?;
    crate::output::write_soup(output, &soup)?;
    crate::output::emit(&format!(
        "wrote {} ({} vertices, {} faces{})\n",
        crate::failure::shown(output),
        soup.positions.len(),
        soup.face_count(),
        if welded > 0 {
            format!(", {welded} welded")
        } else {
            String::new()
        }
    ))?;
    Ok(())
}
