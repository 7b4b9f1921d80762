//! Shared test helpers: the binary, temporary files, the shared meshes.

#![allow(dead_code)]

use assert_cmd::Command;
use std::path::{Path, PathBuf};

/// The `surftopo` binary.
pub fn surftopo() -> Command {
    Command::cargo_bin("surftopo").expect("binary built")
}

/// Runs a command that must succeed (its standard error shown otherwise, after `context`);
/// returns its output.
pub fn run_ok(cmd: &mut Command, context: &str) -> std::process::Output {
    let out = cmd.output().unwrap();
    assert!(
        out.status.success(),
        "{context}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// Runs a command that must be refused as invalid input (exit 2) with a message containing
/// `message`; returns its standard error. `context` prefixes the assertions' messages.
pub fn refused(cmd: &mut Command, message: &str, context: &str) -> String {
    let out = cmd.output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{context}: {stderr}");
    assert!(stderr.contains(message), "{context}: {stderr}");
    stderr
}

/// Runs a command that must succeed and prints JSON with at least `keys`; returns the JSON.
pub fn json_of(cmd: &mut Command, keys: &[&str]) -> serde_json::Value {
    let out = run_ok(cmd, "json_of");
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    for key in keys {
        assert!(v.get(key).is_some(), "missing key {key} in {v}");
    }
    v
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

/// A Matrix Market coordinate file (symmetric or general) as a dense matrix, parsed here.
pub fn read_mtx(path: &std::path::Path) -> Vec<Vec<f64>> {
    let text = std::fs::read_to_string(path).unwrap();
    let symmetric = text.lines().next().unwrap().contains("symmetric");
    let mut rows = text.lines().filter(|l| !l.starts_with('%'));
    let size: Vec<usize> = rows
        .next()
        .unwrap()
        .split_whitespace()
        .map(|w| w.parse().unwrap())
        .collect();
    let mut m = vec![vec![0.0; size[1]]; size[0]];
    for line in rows {
        let w: Vec<&str> = line.split_whitespace().collect();
        let (i, j): (usize, usize) = (w[0].parse().unwrap(), w[1].parse().unwrap());
        let v: f64 = w[2].parse().unwrap();
        m[i - 1][j - 1] = v;
        if symmetric {
            m[j - 1][i - 1] = v;
        }
    }
    m
}

/// `surftopo generate ARGS -o DIR/NAME`, which must succeed; returns the path.
pub fn generate(dir: &Path, name: &str, args: &[&str]) -> PathBuf {
    let path = dir.join(name);
    surftopo()
        .arg("generate")
        .args(args)
        .arg("-o")
        .arg(&path)
        .assert()
        .success();
    path
}
