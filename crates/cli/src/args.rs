//! The flag groups several commands share, each declared once and flattened
//! (`#[command(flatten)]`) into the commands' own `clap::Args`, and the value parser that takes
//! an option's values from a library enum's names.

use clap::builder::{PossibleValue, PossibleValuesParser};

/// The global limits `--max-input-bytes` and `--max-elements` (see [`crate::limits`]).
#[derive(clap::Args, Clone, Copy, Debug)]
pub struct LimitArgs {
    /// The most bytes read from one input file, after decompression (inputs beyond are refused
    /// with exit code 2 before more memory is used).
    #[arg(long, global = true, default_value_t = surftopo_io::DEFAULT_MAX_INPUT_BYTES)]
    pub max_input_bytes: u64,
    /// The most vertices or faces of an input, and the most triangles a generator or modifier may
    /// make (about 100 bytes each once built); checked before allocating.
    #[arg(long, global = true, default_value_t = crate::limits::DEFAULT_MAX_ELEMENTS)]
    pub max_elements: u64,
    /// Stop with exit code 2 after this many seconds (a decimal), naming the step then running;
    /// temporary files are removed and no output is half-written. Default: no limit.
    #[arg(long, global = true, value_name = "SECONDS", value_parser = parse_seconds)]
    pub time_limit: Option<f64>,
}

/// A positive, finite number of seconds.
fn parse_seconds(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(s) if s > 0.0 && s.is_finite() && s < 1e9 => Ok(s),
        _ => Err(format!(
            "{text:?}: a number of seconds above 0 (below 1e9) is needed"
        )),
    }
}

impl LimitArgs {
    /// The limits these options set.
    pub fn limits(&self) -> crate::limits::Limits {
        crate::limits::Limits {
            max_input_bytes: self.max_input_bytes,
            max_elements: self.max_elements,
        }
    }
}

/// `--json`.
#[derive(clap::Args, Clone, Copy, Debug)]
pub struct JsonArg {
    /// Print the results as JSON.
    #[arg(long)]
    pub json: bool,
}

/// `--weld`.
#[derive(clap::Args, Clone, Copy, Debug)]
pub struct WeldArg {
    /// Merge vertices with exactly equal positions first (mesh input; STL input always is).
    #[arg(long)]
    pub weld: bool,
}

/// `--format` of a command's mesh output.
#[derive(clap::Args, Clone, Copy, Debug)]
pub struct FormatArg {
    /// The output mesh's format: obj, off, ply or stl, optionally followed by .gz (e.g. ply.gz,
    /// gzip-compressed). Needed when the output is `-` (standard output) or its name has no mesh
    /// extension; a name whose extension says another format is refused.
    #[arg(long, value_name = "FORMAT", value_parser = crate::output::MeshFormat::parse)]
    pub format: Option<crate::output::MeshFormat>,
}

/// `--seed` of the randomised algorithms.
#[derive(clap::Args, Clone, Copy, Debug)]
pub struct SeedArg {
    /// Seed of the randomised algorithms (brute force, simple greedy, Pulli-Segal).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
}

/// A parser accepting exactly `values` (name, one-line help), so an option's values are the
/// names a library enum gives its variants (e.g. [`surftopo_quad::QuadAlgorithm::name`]) and
/// are listed nowhere else.
pub fn names(
    values: impl IntoIterator<Item = (&'static str, &'static str)>,
) -> PossibleValuesParser {
    PossibleValuesParser::new(
        values
            .into_iter()
            .map(|(name, help)| PossibleValue::new(name).help(help)),
    )
}

/// The name clap gives a value of a CLI-owned [`clap::ValueEnum`] (its kebab-case variant name),
/// for reports that repeat the option's value.
pub fn value_name(value: &impl clap::ValueEnum) -> String {
    value
        .to_possible_value()
        .map_or_else(String::new, |v| v.get_name().to_owned())
}

/// The input, the output and the flags of the commands that turn a mesh into another on its
/// vertex list (`irreducible`, `quad`), with the steps they share.
#[derive(clap::Args, Debug)]
pub struct MeshJobArgs {
    /// Input mesh (a triangulated surface; .obj, .off, .ply, .stl, optionally .gz), `-` for
    /// standard input (format from the extension, else the content).
    pub mesh: std::path::PathBuf,
    /// Output mesh file (.obj, .off, .ply or .stl, optionally .gz), `-` for standard output (with
    /// --format).
    #[arg(short, long)]
    pub output: std::path::PathBuf,
    #[command(flatten)]
    pub format: FormatArg,
    #[command(flatten)]
    pub seed: SeedArg,
    #[command(flatten)]
    pub json: JsonArg,
    #[command(flatten)]
    pub weld: WeldArg,
}

impl MeshJobArgs {
    /// Refuses an output that cannot be written as a mesh, before any work.
    pub fn check_output(&self) -> anyhow::Result<()> {
        let kind = crate::output::mesh_kind(self.format.format);
        crate::output::check_outputs(&[("-o", self.output.as_path(), kind)])
    }

    /// Reads and validates the input surface of any kind (welded with `--weld`).
    pub fn read_covered(&self) -> anyhow::Result<crate::input::LoadedCovered> {
        crate::input::read_covered(&self.mesh, self.weld.weld)
    }

    /// Writes the output mesh, then warns about the input's attributes it does not keep
    /// (`command` names the command in the warnings).
    pub fn write(
        &self,
        command: &str,
        soup: &surftopo_io::PolygonSoup,
        attributes: &surftopo_io::Attributes,
    ) -> anyhow::Result<()> {
        let output = self.output.as_path();
        crate::output::write_soup_as(output, soup, self.format.format)?;
        crate::attributes::warn_not_read(&self.mesh, output, attributes);
        crate::attributes::warn_new_faces(command, output, attributes);
        crate::attributes::warn_unwritable(output, self.format.format, soup);
        Ok(())
    }
}
