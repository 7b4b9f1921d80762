//! `surftopo convert`: any readable format to OBJ, OFF or PLY (polygons kept as they are).

use crate::args::WeldArg;
use crate::input::read_soup;
use std::path::PathBuf;

/// The arguments of `convert`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input mesh file.
    pub input: PathBuf,
    /// Output mesh file (.obj, .off, .ply, optionally .gz).
    pub output: PathBuf,
    #[command(flatten)]
    pub weld: WeldArg,
}

/// Converts `input` to `output`, welding exactly coincident positions when asked.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let (input, output) = (args.input.as_path(), args.output.as_path());
    crate::output::check_outputs(&[("OUTPUT", output, crate::output::OutputKind::Mesh)])?;
    let (soup, welded) = crate::progress::step("reading", || read_soup(input, args.weld.weld))?;
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
