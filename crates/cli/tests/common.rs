//! Shared test helpers: the binary, temporary files, the shared meshes.

#![allow(dead_code)]

use assert_cmd::Command;
use std::path::{Path, PathBuf};

/// The `surftopo` binary.
pub fn surftopo() -> Command {
    Command::cargo_bin("surftopo").expect("binary built")
}

/// Writes `text` to `name` in `dir` and returns the path.
pub fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}
