//! `surftopo`: triangulated surfaces (closed or with boundary, orientable or not, in pieces) from the command line.
//!
//! A thin layer over the surftopo libraries. Exit codes (see [`failure`]): 0 on success, 2 on
//! invalid input, usage or an unwritable output (message on stderr starting with `error:`), 1 on
//! an internal failure, 4 on a numerical failure of double precision; `isometric` has its own (0, 1, 2, 3 undecidable, 4). Results go to stdout (to
//! stderr when stdout carries a mesh, `-`), progress and notes to stderr; output files are written atomically, and SIGINT, SIGTERM or
//! SIGHUP remove the temporary file of a write in progress before the process exits.

/// `eprintln!` that never panics: when stderr is closed or full (`2>/dev/full`) the text is
/// lost and the command goes on (its exit code still tells the outcome). Nothing is written
/// while notes are muted ([`output::mute_notes`]: the demo, whose lines say it).
macro_rules! stderr_println {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        if !crate::output::notes_muted() {
            let _ = writeln!(std::io::stderr(), $($arg)*);
        }
    }};
}

/// `eprint!` that never panics (see [`stderr_println`]).
macro_rules! stderr_print {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = write!(std::io::stderr(), $($arg)*);
    }};
}

mod args;
mod attributes;
mod commands;
mod failure;
mod input;
mod limits;
mod output;
mod progress;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Triangulated surfaces (closed or with boundary, orientable or not, in pieces): irreducible
/// triangulations, quadrangulations, intrinsic Delaunay triangulations.
#[derive(Parser, Debug)]
#[command(name = "surftopo", version, about, long_about = None, after_help = EXIT_CODES)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    #[command(flatten)]
    limits: args::LimitArgs,
}

/// The exit codes, at the end of `--help`.
const EXIT_CODES: &str = "Exit codes: 0 success; 1 internal failure; 2 invalid input or usage, or an \
output that cannot be written (missing folder, read-only or full disk, full or closed stdout); 128+N stopped by \
signal N, temporary files removed; 4 numerical failure (double precision could not finish on \
valid input: use `--exact` on exact input, or another `--method`). `isometric`: 0 isometric, 1 not isometric, 2 invalid input, 3 \
undecidable in double precision, 4 internal failure.";

/// The subcommands; each owns its arguments (`commands::NAME::Args`).
#[derive(Subcommand, Debug)]
enum Command {
    /// Vertices, edges, faces, genus, Euler characteristic, components, closed, orientable,
    /// simplicial, and every problem found.
    Info(commands::info::Args),
    /// Generate a surface.
    Generate(commands::generate::Args),
    /// Convert between mesh formats (polygons are kept, and the attributes the output format
    /// holds: texture coordinates, normals, PLY properties; a warning names what is dropped).
    Convert(commands::convert::Args),
    /// An irreducible triangulation (every edge fails the link condition) by topology-preserving
    /// edge contractions; its vertices are surviving input vertices, with their positions.
    Irreducible(commands::irreducible::Args),
    /// A quadrangulation with the same vertices, by a perfect pairing of the triangles (each quad is
    /// two adjacent triangles of the input, or of a flipped triangulation K for `lrs`).
    Quad(commands::quad::Args),
    /// The intrinsic Delaunay triangulation by edge flipping; optionally its tessellation, the cotan
    /// Laplacian and the lumped mass matrix.
    Delaunay(commands::delaunay::Args),
    /// Whether two polyhedral surfaces (any kind: boundary loops, non-orientable, several pieces)
    /// are isometric: prints `isometric` (exit 0), `not isometric` (exit 1), `undecidable in
    /// double precision` or `undecided` (exit 3); exit 2 for invalid input, 4 for an internal
    /// failure.
    Isometric(commands::isometric::Args),
    /// Run every capability on a built-in example and write the results into a folder.
    Demo(commands::demo::Args),
    /// Every irreducible triangulation of a closed surface up to isomorphism (mirror images
    /// identified), one per line in Lutz's format; the count per vertex number on stdout.
    Census(commands::census::Args),
    /// Whether two triangulated closed surfaces (orientable or not) are isomorphic as simplicial
    /// complexes, mirror images included: prints `isomorphic` (exit 0) or `not isomorphic`
    /// (exit 1); exit 2 for invalid input.
    Isomorphic(commands::isomorphic::Args),
}

fn run(command: Command) -> anyhow::Result<ExitCode> {
    let done = |r: anyhow::Result<()>| r.map(|()| ExitCode::SUCCESS);
    match command {
        Command::Info(args) => done(commands::info::run(&args)),
        Command::Generate(args) => done(commands::generate::run(&args)),
        Command::Convert(args) => done(commands::convert::run(&args)),
        Command::Irreducible(args) => done(commands::irreducible::run(&args)),
        Command::Quad(args) => done(commands::quad::run(&args)),
        Command::Delaunay(args) => done(commands::delaunay::run(&args)),
        Command::Isometric(args) => {
            commands::isometric::run(&args).map(|v| ExitCode::from(v.exit_code()))
        }
        Command::Demo(args) => done(commands::demo::run(&args)),
        Command::Census(args) => done(commands::census::run(&args)),
        Command::Isomorphic(args) => commands::isomorphic::run(&args),
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

/// `--time-limit SECONDS`: a thread that, once the time is up, removes the temporary files of
/// writes in progress and exits with code 2, naming the step then running (as the signal
/// handler does, so no output is half-written: a write's rename waits for it or never happens).
fn stop_after(seconds: f64) {
    std::thread::spawn(move || {
        std::thread::sleep(std::time::Duration::from_secs_f64(seconds));
        let step = progress::current().map_or_else(String::new, |s| format!(" while {s}"));
        surftopo_io::remove_temporaries_then(|| {
            stderr_println!(
                "error: stopped after {seconds} s (--time-limit){step}; temporary files removed"
            );
            std::process::exit(2)
        })
    });
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if e.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            stderr_println!("error: a command is needed\n");
            let _ = e.print();
            return ExitCode::from(2);
        }
        Err(e) => e.exit(),
    };
    limits::set(cli.limits.limits());
    input::set_command(match cli.command {
        Command::Quad(_) => "quad",
        Command::Delaunay(_) => "delaunay",
        Command::Isometric(_) => "isometric",
        Command::Generate(_) => "generate",
        _ => "surftopo",
    });
    if output::stdout_was_closed() {
        output::STDOUT_CLOSED.store(true, std::sync::atomic::Ordering::Relaxed);
    }
    remove_temporaries_on_signals();
    if let Some(seconds) = cli.limits.time_limit {
        stop_after(seconds);
    }
    let isometric = matches!(cli.command, Command::Isometric(_));
    match run(cli.command) {
        Ok(code) => code,
        Err(error) => {
            stderr_println!("error: {}", failure::message(&error));
            ExitCode::from(failure::command_exit_code(&error, isometric))
        }
    }
}
