//! `surftopo`: triangulations of closed surfaces from the command line.
//!
//! A thin layer over the surftopo libraries. Exit code 0 on success, 2 on invalid input or usage
//! (message on stderr starting with `error:`), 1 on an internal failure. Results go to stdout,
//! progress and notes to stderr; output files are written atomically.

mod commands;
mod failure;
mod input;
mod output;
mod progress;

use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;

/// Triangulations of closed surfaces: irreducible triangulations, quadrangulations, intrinsic
/// Delaunay triangulations.
#[derive(Parser, Debug)]
#[command(name = "surftopo", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

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
    /// Whether two closed polyhedral surfaces are isometric: prints `isometric` (exit 0) or
    /// `not isometric` (exit 1).
    Isometric {
        /// First surface (mesh or portalgon JSON).
        a: PathBuf,
        /// Second surface (mesh or portalgon JSON).
        b: PathBuf,
        /// Merge vertices with exactly equal positions first (mesh input).
        #[arg(long)]
        weld: bool,
    },
    /// Run every capability on a built-in example and write the results into a folder.
    Demo {
        /// Folder for the results.
        #[arg(long, default_value = "surftopo-demo")]
        out: PathBuf,
    },
}

fn run(cli: Cli) -> anyhow::Result<ExitCode> {
    let done = |r: anyhow::Result<()>| r.map(|()| ExitCode::SUCCESS);
    match cli.command {
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
        Command::Isometric { a, b, weld } => Ok(if commands::isometric::run(&a, &b, weld)? {
            ExitCode::SUCCESS
        } else {
            ExitCode::from(1)
        }),
        Command::Demo { out } => done(commands::demo::run(&out)),
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(code) => code,
        Err(error) if output::is_broken_pipe(&error) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("error: {error:#}");
            ExitCode::from(failure::exit_code(&error))
        }
    }
}
