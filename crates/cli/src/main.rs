//! `surftopo`: triangulations of closed surfaces from the command line.
//!
//! A thin layer over the surftopo libraries. Exit codes (see [`failure`]): 0 on success, 2 on
//! invalid input, usage or an unwritable output (message on stderr starting with `error:`), 1 on
//! an internal failure, 4 on a numerical failure of double precision; `isometric` has its own (0, 1, 2, 3 undecidable, 4). Results go to stdout,
//! progress and notes to stderr; output files are written atomically, and SIGINT, SIGTERM or
//! SIGHUP remove the temporary file of a write in progress before the process exits.

mod commands;
mod failure;
mod input;
mod limits;
mod output;
mod progress;

use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;

/// Triangulations of closed surfaces: irreducible triangulations, quadrangulations, intrinsic
/// Delaunay triangulations.
#[derive(Parser, Debug)]
#[command(name = "surftopo", version, about, long_about = None, after_help = EXIT_CODES)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// The most bytes read from one input file, after decompression (inputs beyond are refused
    /// with exit code 2 before more memory is used).
    #[arg(long, global = true, default_value_t = surftopo_io::DEFAULT_MAX_INPUT_BYTES)]
    max_input_bytes: u64,
    /// The most vertices or faces of an input, and the most triangles a generator or modifier may
    /// make (about 100 bytes each once built); checked before allocating.
    #[arg(long, global = true, default_value_t = limits::DEFAULT_MAX_ELEMENTS)]
    max_elements: u64,
}

/// The exit codes, at the end of `--help`.
const EXIT_CODES: &str = "Exit codes: 0 success; 1 internal failure; 2 invalid input or usage, or an \
output that cannot be written (missing folder, read-only or full disk, full stdout); 128+N stopped by \
signal N, temporary files removed; 4 numerical failure (double precision could not finish: \
`delaunay --method voronoi` without `--exact`). `isometric`: 0 isometric, 1 not isometric, 2 invalid input, 3 \
undecidable in double precision, 4 internal failure.";

#[derive(Subcommand, Debug)]
enum Command {
    /// Vertices, edges, faces, genus, Euler characteristic, components, closed, orientable,
    /// simplicial, and every problem found.
    Info {
        /// Mesh file (.obj, .off, .ply, .stl, optionally .gz).
        mesh: PathBuf,
        /// Print JSON.
        #[arg(long)]
        json: bool,
        /// Merge vertices with exactly equal positions first.
        #[arg(long)]
        weld: bool,
        /// Exit with code 2 when the mesh is not a valid closed orientable surface.
        #[arg(long)]
        strict: bool,
    },
    /// Generate a surface.
    Generate {
        #[command(subcommand)]
        kind: commands::generate::Kind,
        #[command(flatten)]
        modifiers: commands::generate::Modifiers,
    },
    /// Convert between mesh formats (polygons are kept).
    Convert {
        /// Input mesh file.
        input: PathBuf,
        /// Output mesh file (.obj, .off, .ply, optionally .gz).
        output: PathBuf,
        /// Merge vertices with exactly equal positions.
        #[arg(long)]
        weld: bool,
    },
    /// An irreducible triangulation (every edge fails the link condition) by topology-preserving
    /// edge contractions; its vertices are surviving input vertices, with their positions.
    Irreducible {
        #[command(flatten)]
        job: input::MeshJob,
        /// The algorithm.
        #[arg(long, value_enum, default_value_t)]
        algorithm: commands::irreducible::AlgorithmName,
    },
    /// A quadrangulation with the same vertices, by a perfect pairing of the triangles (each quad is
    /// two adjacent triangles of the input, or of a flipped triangulation K for `lrs`).
    Quad {
        #[command(flatten)]
        job: input::MeshJob,
        /// The initial pairing (for `--objective count`).
        #[arg(long, value_enum, default_value_t)]
        algorithm: commands::quad::AlgorithmName,
        /// What the pairing optimises.
        #[arg(long, value_enum, default_value_t)]
        objective: commands::quad::Objective,
    },
    /// The intrinsic Delaunay triangulation by edge flipping; optionally its tessellation, the cotan
    /// Laplacian and the lumped mass matrix.
    Delaunay(commands::delaunay::Options),
    /// Whether two closed polyhedral surfaces are isometric: prints `isometric` (exit 0),
    /// `not isometric` (exit 1) or `undecidable in double precision` (exit 3); exit 2 for invalid
    /// input, 4 for an internal failure.
    Isometric {
        /// First surface (mesh or portalgon JSON).
        a: PathBuf,
        /// Second surface (mesh or portalgon JSON).
        b: PathBuf,
        /// Merge vertices with exactly equal positions first (mesh input).
        #[arg(long)]
        weld: bool,
        /// How the canonical tessellations are computed.
        #[command(flatten)]
        method: commands::delaunay::MethodOptions,
    },
    /// Run every capability on a built-in example and write the results into a folder.
    Demo {
        /// Folder for the results.
        #[arg(long, default_value = "surftopo-demo")]
        out: PathBuf,
    },
}

fn run(command: Command) -> anyhow::Result<ExitCode> {
    let done = |r: anyhow::Result<()>| r.map(|()| ExitCode::SUCCESS);
    match command {
        Command::Info {
            mesh,
            json,
            weld,
            strict,
        } => done(commands::info::run(&mesh, json, weld, strict)),
        Command::Generate { kind, modifiers } => done(commands::generate::run(&kind, &modifiers)),
        Command::Convert {
            input,
            output,
            weld,
        } => done(commands::convert::run(&input, &output, weld)),
        Command::Irreducible { job, algorithm } => {
            done(commands::irreducible::run(&job, algorithm))
        }
        Command::Quad {
            job,
            algorithm,
            objective,
        } => done(commands::quad::run(&job, algorithm, objective)),
        Command::Delaunay(options) => done(commands::delaunay::run(&options)),
        Command::Isometric { a, b, weld, method } => {
            commands::isometric::run(&a, &b, weld, &method).map(|v| ExitCode::from(v.exit_code()))
        }
        Command::Demo { out } => done(commands::demo::run(&out)),
    }
}

/// Removes the temporary files of writes in progress on SIGINT, SIGTERM and SIGHUP, then exits
/// with 128 + the signal number. A thread waits for the signals, so a long computation is
/// interrupted too.
fn remove_temporaries_on_signals() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else {
        return; // the default actions stay: termination without the clean-up
    };
    std::thread::spawn(move || {
        if let Some(signal) = signals.forever().next() {
            surftopo_io::remove_temporaries_then(|| std::process::exit(128 + signal))
        }
    });
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if e.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            eprintln!("error: a command is needed\n");
            let _ = e.print();
            return ExitCode::from(2);
        }
        Err(e) => e.exit(),
    };
    limits::set(limits::Limits {
        max_input_bytes: cli.max_input_bytes,
        max_elements: cli.max_elements,
    });
    remove_temporaries_on_signals();
    let isometric = matches!(cli.command, Command::Isometric { .. });
    match run(cli.command) {
        Ok(code) => code,
        Err(error) if output::is_broken_pipe(&error) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("error: {}", failure::message(&error));
            let code = failure::exit_code(&error);
            ExitCode::from(match (isometric, code) {
                (true, 1) => commands::isometric::INTERNAL_FAILURE,
                _ => code,
            })
        }
    }
}
