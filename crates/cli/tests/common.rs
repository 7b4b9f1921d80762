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

/// Writes `name` in `dir`: `surftopo generate genus --genus G --size 2 --flips 300` (a small
/// closed surface of genus `genus` with irregular connectivity), and returns the path.
pub fn generated_genus_surface(dir: &Path, name: &str, genus: u32) -> PathBuf {
    let path = dir.join(name);
    let genus = genus.to_string();
    surftopo()
        .args([
            "generate", "genus", "--genus", &genus, "--size", "2", "--flips", "300", "-o",
        ])
        .arg(&path)
        .assert()
        .success();
    path
}
