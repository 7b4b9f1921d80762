//! `surftopo convert`: any readable format to OBJ, OFF, PLY or binary STL (polygons kept as they
//! are, except in STL, which holds triangles).

use crate::args::{FormatArg, WeldArg};
use crate::input::read_soup;
use std::path::PathBuf;

/// The arguments of `convert`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input mesh file, `-` for standard input (format from the extension, else the content).
    pub input: PathBuf,
    /// Output mesh file (.obj, .off, .ply, .stl, optionally .gz), `-` for standard output (with
    /// --format).
    pub output: PathBuf,
    #[command(flatten)]
    pub weld: WeldArg,
    #[command(flatten)]
    pub format: FormatArg,
}

/// Converts `input` to `output`, welding exactly coincident positions when asked.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let (input, output) = (args.input.as_path(), args.output.as_path());
    let kind = crate::output::mesh_kind(args.format.format);
    crate::output::check_outputs(&[("OUTPUT", output, kind)])?;
    let (soup, welded) = crate::progress::step("reading", || read_soup(input, args.weld.weld))?;
    crate::output::write_soup_as(output, &soup, args.format.format)?;
    crate::output::emit(&format!(
        "wrote {} ({} vertices, {} faces{})\n",
        crate::output::name(output),
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
