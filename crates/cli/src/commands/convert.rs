//! `surftopo convert`: any readable format to OBJ, OFF, PLY or binary STL (polygons kept as they
//! are, except in STL, which holds triangles; the attributes the target format holds are kept:
//! see [`crate::attributes`]).

use crate::args::{FormatArg, WeldArg};
use crate::input::read_soup;
use std::path::PathBuf;
use surftopo_io::{Format, PlyEncoding, PlyPrecision, WriteOptions};

/// The arguments of `convert`.
#[derive(clap::Args, Debug)]
#[command(after_help = ATTRIBUTES_HELP)]
pub struct Args {
    /// Input mesh file, `-` for standard input (format from the extension, else the content).
    pub input: PathBuf,
    /// Output mesh file (.obj, .off, .ply, .stl, optionally .gz), `-` for standard output (with
    /// --format).
    pub output: PathBuf,
    #[command(flatten)]
    pub weld: WeldArg,
    /// PLY output in ascii instead of binary little-endian.
    #[arg(long)]
    pub ascii: bool,
    /// PLY output with positions (and double properties) as 32-bit `float` instead of `double`:
    /// half the size, about 7 significant digits.
    #[arg(long)]
    pub float: bool,
    #[command(flatten)]
    pub format: FormatArg,
}

/// What `convert --help` says about attributes and PLY variants.
const ATTRIBUTES_HELP: &str = "Attributes: OBJ texture coordinates (vt) and normals (vn), PLY \
vertex properties (nx ny nz, u v / s t / texture_u texture_v, red green blue alpha, any other \
scalar, with its type) and COFF colours are kept where the output format holds them: OBJ writes \
texture coordinates and normals (per vertex or per face corner), PLY every per-vertex property \
(OBJ texture coordinates as u v), OFF colours. What cannot be kept (per-corner texture \
coordinates to PLY, colours to OBJ, normals to OFF, what the reader skips, differing attributes \
of welded vertices) is named in a warning on stderr. PLY is written binary little-endian with \
double positions unless --ascii or --float.";

/// The write options of the flags, refused (exit 2) when the output is not PLY.
fn write_options(args: &Args) -> anyhow::Result<WriteOptions> {
    let mut options = WriteOptions::default();
    let target = crate::attributes::target_format(&args.output, args.format.format);
    let is_ply = target == Some(Format::Ply);
    for (given, flag) in [(args.ascii, "--ascii"), (args.float, "--float")] {
        if given && !is_ply {
            return Err(crate::failure::invalid(format!(
                "{}: {flag} applies to PLY output only",
                crate::output::name(&args.output)
            )));
        }
    }
    if args.ascii {
        options = options.with_ply_encoding(PlyEncoding::Ascii);
    }
    if args.float {
        options = options.with_ply_precision(PlyPrecision::Float);
    }
    Ok(options)
}

/// Converts `input` to `output`, welding exactly coincident positions when asked.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let (input, output) = (args.input.as_path(), args.output.as_path());
    let kind = crate::output::mesh_kind(args.format.format);
    crate::output::check_outputs(&[("OUTPUT", output, kind)])?;
    let options = write_options(args)?;
    let (soup, welded) = crate::progress::step("reading", || read_soup(input, args.weld.weld))?;
    crate::output::write_soup_with(output, &soup, args.format.format, &options)?;
    crate::attributes::warn_not_read(input, output, &soup.attributes);
    crate::attributes::warn_unwritable(output, args.format.format, &soup);
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
