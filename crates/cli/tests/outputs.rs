//! The outputs of every command: extensions checked before any work, `delaunay`'s outputs all
//! optional (at least one, or `--json`), no file named twice, and all outputs of a run renamed
//! into place only once every one is written.

mod common;

use common::{generated_genus_surface, surftopo};
use std::path::Path;

/// The names in `dir`, sorted.
fn names_in(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// Runs `surftopo ARGS` in `dir` (relative output names land there); asserts exit code 2 and
/// that stderr holds `message`.
fn refused(dir: &Path, args: &[&str], message: &str) {
    let out = surftopo().current_dir(dir).args(args).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(stderr.contains(message), "{args:?}: {stderr}");
}

/// The entries (row, column, value) of a coordinate Matrix Market file, 0-based, and its size;
/// `symmetric` storage (the lower triangle) is expanded to both triangles.
fn matrix_market(path: &Path) -> (usize, Vec<(usize, usize, f64)>) {
    let text = std::fs::read_to_string(path).unwrap();
    assert!(text.starts_with("%%MatrixMarket matrix coordinate real"));
    let symmetric = text.lines().next().unwrap().ends_with("symmetric");
    let mut lines = text.lines().filter(|l| !l.starts_with('%'));
    let size: Vec<usize> = lines
        .next()
        .unwrap()
        .split_whitespace()
        .map(|t| t.parse().unwrap())
        .collect();
    let entries: Vec<_> = lines
        .map(|l| {
            let t: Vec<&str> = l.split_whitespace().collect();
            let (i, j): (usize, usize) = (t[0].parse().unwrap(), t[1].parse().unwrap());
            (i - 1, j - 1, t[2].parse::<f64>().unwrap())
        })
        .collect();
    assert_eq!(size[0], size[1]);
    assert_eq!(size[2], entries.len());
    let mirrored: Vec<_> = entries
        .iter()
        .filter(|&&(i, j, _)| symmetric && i != j)
        .map(|&(i, j, v)| (j, i, v))
        .collect();
    (size[0], [entries, mirrored].concat())
}

#[test]
fn an_output_whose_extension_does_not_fit_is_refused_before_any_work() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // The input does not exist: the output is refused first, so no work (not even reading) was
    // done.
    let cases: [(&[&str], &str); 8] = [
        (
            &["delaunay", "absent.off", "-o", "sock.obj"],
            "sock.obj: -o: an intrinsic triangulation is written as portalgon JSON (.json)",
        ),
        (
            &["delaunay", "absent.off", "--tessellation", "t.off"],
            "t.off: --tessellation: an intrinsic triangulation is written as portalgon JSON",
        ),
        (
            &["delaunay", "absent.off", "--laplacian", "L.txt"],
            "L.txt: --laplacian: a matrix is written as Matrix Market (.mtx)",
        ),
        (
            &["quad", "absent.off", "-o", "q.ply", "--format", "stl"],
            "q.ply: -o: the name says ply, --format says stl",
        ),
        (
            &["irreducible", "absent.off", "-o", "i.json"],
            "i.json: -o: not a mesh file name",
        ),
        (
            &["convert", "absent.off", "c.txt"],
            "c.txt: OUTPUT: not a mesh file name",
        ),
        (
            &["generate", "torus", "-o", "t.json"],
            "t.json: -o: not a mesh file name",
        ),
        (
            &["generate", "flat-torus", "--x", "2", "-o", "f.obj"],
            "f.obj: -o: an intrinsic triangulation is written as portalgon JSON",
        ),
    ];
    for (args, message) in cases {
        refused(d, args, message);
    }
    assert!(names_in(d).is_empty(), "{:?}", names_in(d));
}

#[test]
fn delaunay_needs_no_triangulation_output_when_another_output_or_json_is_given() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mesh = generated_genus_surface(d, "g.obj", 2);
    surftopo()
        .arg("delaunay")
        .arg(&mesh)
        .arg("--laplacian")
        .arg(d.join("L.mtx"))
        .assert()
        .success();
    assert_eq!(names_in(d), ["L.mtx", "g.obj"]);
    // The cotan Laplacian: symmetric, with zero row sums.
    let (n, entries) = matrix_market(&d.join("L.mtx"));
    let mut row_sums = vec![0.0; n];
    let mut scale = 0.0f64;
    for &(i, j, v) in &entries {
        row_sums[i] += v;
        scale = scale.max(v.abs());
        assert!(
            entries.iter().any(|&(a, b, w)| (a, b) == (j, i) && w == v),
            "({i}, {j}) has no symmetric entry"
        );
    }
    assert!(
        row_sums.iter().all(|s| s.abs() <= 1e-9 * scale),
        "{row_sums:?}"
    );
    // --json alone: the figures, no file.
    let out = surftopo()
        .arg("delaunay")
        .arg(&mesh)
        .arg("--json")
        .output()
        .unwrap();
    assert!(out.status.success());
    let figures: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(figures["non_delaunay_edges"], 0);
    assert_eq!(names_in(d), ["L.mtx", "g.obj"]);
    // Neither: refused.
    refused(
        d,
        &["delaunay", "g.obj"],
        "nothing to write: give -o, --tessellation, --reduced, --laplacian or --mass",
    );
}

#[test]
fn the_same_file_for_two_outputs_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    generated_genus_surface(d, "g.obj", 1);
    std::fs::create_dir(d.join("sub")).unwrap();
    // Files that do not exist yet: compared as normalised paths.
    refused(
        d,
        &[
            "delaunay",
            "g.obj",
            "--laplacian",
            "L.mtx",
            "--mass",
            "sub/../L.mtx",
        ],
        "sub/../L.mtx: named by both --laplacian and --mass",
    );
    // An existing file and a link to it: compared as canonical paths.
    std::fs::write(d.join("D.json"), "old").unwrap();
    std::os::unix::fs::symlink(d.join("D.json"), d.join("link.json")).unwrap();
    refused(
        d,
        &[
            "delaunay",
            "g.obj",
            "-o",
            "D.json",
            "--tessellation",
            "link.json",
        ],
        "link.json: named by both -o and --tessellation",
    );
    assert_eq!(names_in(d), ["D.json", "g.obj", "link.json", "sub"]);
    assert_eq!(std::fs::read_to_string(d.join("D.json")).unwrap(), "old");
}

#[test]
fn a_failing_output_leaves_every_output_of_the_run_as_it_was() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    generated_genus_surface(d, "g.obj", 1);
    std::fs::write(d.join("M.mtx"), "old").unwrap();
    // -o is written (under a temporary name) before the Laplacian, whose folder does not exist.
    refused(
        d,
        &[
            "delaunay",
            "g.obj",
            "-o",
            "D.json",
            "--mass",
            "M.mtx",
            "--laplacian",
            "absent/L.mtx",
        ],
        "absent/L.mtx: not written",
    );
    assert_eq!(
        names_in(d),
        ["M.mtx", "g.obj"],
        "no output, no temporary file"
    );
    assert_eq!(std::fs::read_to_string(d.join("M.mtx")).unwrap(), "old");
}
