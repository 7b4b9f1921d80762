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

/// The shared meshes folder from `SURFTOPO_MESHES`, or `None` (with a message) when unset.
pub fn shared_meshes() -> Option<PathBuf> {
    match std::env::var_os("SURFTOPO_MESHES") {
        Some(dir) => {
            let dir = PathBuf::from(dir);
            assert!(
                dir.join("manifest.json").is_file(),
                "SURFTOPO_MESHES={} has no manifest.json",
                dir.display()
            );
            Some(dir)
        }
        None => {
            eprintln!("SURFTOPO_MESHES is not set: real-mesh tests skipped");
            None
        }
    }
}
