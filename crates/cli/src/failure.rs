//! Exit codes: 0 success, 2 invalid input or usage, 1 internal failure.

use std::fmt;

/// Marks an error as the user's input being invalid (exit code 2).
#[derive(Debug)]
pub struct InvalidInput(pub String);

impl fmt::Display for InvalidInput {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for InvalidInput {}

/// An `anyhow` error marked as invalid input.
pub fn invalid(message: impl Into<String>) -> anyhow::Error {
    anyhow::Error::new(InvalidInput(message.into()))
}

/// The exit code for an error: 2 when any cause is invalid input (including every reader error),
/// 1 otherwise.
pub fn exit_code(error: &anyhow::Error) -> u8 {
    let input = error
        .chain()
        .any(|cause| cause.is::<InvalidInput>() || cause.is::<surftopo_io::IoError>());
    if input { 2 } else { 1 }
}
