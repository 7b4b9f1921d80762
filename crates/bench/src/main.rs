//! `surftopo-bench`: the project's performance figures, side by side in one run, written to
//! `results/*.jsonl` and printed as a table. Run with `--release`.

mod output_speed;
mod read_build;

use clap::{Parser, Subcommand};

/// Benchmarks of surftopo (run with `cargo run --release -p surftopo-bench -- ...`).
#[derive(Parser)]
#[command(name = "surftopo-bench", about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Reading OBJ / binary PLY and building the half-edge mesh, at 1M and 4M triangles.
    ReadBuild(read_build::Options),
    /// Writing `delaunay`'s outputs (portalgon JSON, Matrix Market, npz/npy) against reading its
    /// input mesh, at about 100k faces.
    OutputSpeed(output_speed::Options),
    /// The papers' experiments as the papers made them: `irreducible.md`, `quad.md`,
    /// `intrinsic.md`, jsonl and SVG plots under `--out` (default `results/papers`).
    Papers(surftopo_bench::papers::Options),
}

fn main() -> anyhow::Result<()> {
    match Cli::parse().command {
        Command::ReadBuild(options) => read_build::run(&options),
        Command::OutputSpeed(options) => output_speed::run(&options),
        Command::Papers(options) => surftopo_bench::papers::run(&options),
    }
}
