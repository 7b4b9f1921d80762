//! Exit codes and error messages.
//!
//! | code | meaning |
//! |---|---|
//! | 0 | success (`isometric`: isometric) |
//! | 1 | internal failure (`isometric`: not isometric) |
//! | 2 | invalid input or usage, or an output that cannot be written (missing folder, read-only or full disk, a full or closed stdout or pipe): something the user must fix |
//! | 3 | `isometric` only: double precision cannot decide |
//! | 4 | numerical failure: double precision could not finish on valid input (flipping's breakdown, the f64 wave, exact corners that doubles flatten or cannot hold, Theorem 1 in f64 below the wave's resolution); `isometric`: internal failure ([`ISOMETRIC_INTERNAL_FAILURE`]) |
//! | 128 + N | stopped by signal N (SIGHUP 129, SIGINT 130, SIGTERM 143) after removing temporary files |

use std::fmt;
use std::path::Path;

/// Marks an error as the user's input being invalid (exit code 2).
#[derive(Debug)]
pub struct InvalidInput(pub String);

impl fmt::Display for InvalidInput {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for InvalidInput {}

/// Marks an error as a numerical failure (exit code 4): double precision could not finish a
/// computation on input that is valid (exact arithmetic or another method can).
#[derive(Debug)]
pub struct NumericalFailure(pub String);

impl fmt::Display for NumericalFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for NumericalFailure {}

/// An `anyhow` error marked as a numerical failure.
pub fn numerical(message: impl Into<String>) -> anyhow::Error {
    anyhow::Error::new(NumericalFailure(message.into()))
}

/// The exit code of a numerical failure (`isometric` uses it for internal failures).
pub const NUMERICAL_FAILURE: u8 = 4;

/// An `anyhow` error marked as invalid input.
pub fn invalid(message: impl Into<String>) -> anyhow::Error {
    anyhow::Error::new(InvalidInput(message.into()))
}

/// An output that could not be written (exit code 2, like every unwritable output): the path and
/// the cause, once.
pub fn unwritable(path: &Path, cause: &dyn fmt::Display) -> anyhow::Error {
    invalid(format!("{}: not written: {cause}", shown(path)))
}

/// A path as messages show it: control characters escaped ([`surftopo_mesh::printable`]).
pub fn shown(path: &Path) -> String {
    surftopo_mesh::printable(&path.display().to_string()).into_owned()
}

/// `isometric`'s exit code for an internal failure (its 1 means "not isometric").
pub const ISOMETRIC_INTERNAL_FAILURE: u8 = 4;

/// The exit code for an error of a command: [`exit_code`], except that `isometric` (where 1
/// means "not isometric") reports an internal failure as [`ISOMETRIC_INTERNAL_FAILURE`].
pub fn command_exit_code(error: &anyhow::Error, isometric: bool) -> u8 {
    match (exit_code(error), isometric) {
        (1, true) => ISOMETRIC_INTERNAL_FAILURE,
        (code, _) => code,
    }
}

/// The exit code for an error: 2 when any cause is invalid input (including every reader error),
/// 4 when one is a numerical failure, 1 otherwise.
pub fn exit_code(error: &anyhow::Error) -> u8 {
    if is_invalid_input(error) {
        2
    } else if error.chain().any(|cause| cause.is::<NumericalFailure>()) {
        NUMERICAL_FAILURE
    } else {
        1
    }
}

/// Whether any cause of `error` is invalid input (including every reader error).
pub fn is_invalid_input(error: &anyhow::Error) -> bool {
    error
        .chain()
        .any(|cause| cause.is::<InvalidInput>() || cause.is::<surftopo_io::IoError>())
}

/// The message of `error` and its causes, each cause once: a cause whose text the message
/// already holds (an error that prints its source and also returns it from `source()`) is
/// skipped. Control characters are escaped, since messages quote input.
pub fn message(error: &anyhow::Error) -> String {
    let mut text = String::new();
    for cause in error.chain() {
        let part = cause.to_string();
        if text.contains(&part) {
            continue;
        }
        if !text.is_empty() {
            text.push_str(": ");
        }
        text.push_str(&part);
    }
    surftopo_mesh::printable(&text).into_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_each_cause_once_and_escape_controls() {
        let os = std::io::Error::from(std::io::ErrorKind::NotFound);
        let io = surftopo_io::IoError::Io {
            file: "m.obj".into(),
            source: os,
        };
        let error = anyhow::Error::new(io).context("reading \u{1b}[2J");
        let text = message(&error);
        assert_eq!(text.matches("entity not found").count(), 1, "{text}");
        assert!(text.starts_with("reading \\u{1b}[2J: m.obj: "), "{text}");
        assert_eq!(exit_code(&error), 2);
    }

    #[test]
    fn numerical_failures_exit_with_4_and_other_failures_with_1() {
        let refused = numerical("the dual refused").context("t.json");
        assert_eq!(exit_code(&refused), NUMERICAL_FAILURE);
        assert_eq!(exit_code(&anyhow::anyhow!("a bug")), 1);
        assert_eq!(exit_code(&invalid("bad input")), 2);
    }

    #[test]
    fn isometric_reports_an_internal_failure_as_4_and_invalid_input_as_2() {
        let internal = anyhow::anyhow!("a bug");
        assert_eq!(command_exit_code(&internal, false), 1);
        assert_eq!(
            command_exit_code(&internal, true),
            ISOMETRIC_INTERNAL_FAILURE
        );
        let bad = invalid("a.obj: line 3: not a number");
        assert_eq!(command_exit_code(&bad, false), 2);
        assert_eq!(command_exit_code(&bad, true), 2);
    }
}
