//! `surftopo isometric`: its exit codes (0 isometric, 1 not, 2 invalid input, 3 undecidable; 4,
//! an internal failure, is unit-tested in failure.rs), `--json`, `--tolerance`, reasons in words,
//! and the tessellation files `delaunay --tessellation` writes as inputs.

mod common;

use common::{generated_genus_surface, surftopo};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// A copy of the OBJ file `mesh` with the z coordinate of its second vertex moved by `amount`.
fn moved_copy(mesh: &Path, amount: f64, name: &str) -> PathBuf {
    let text = std::fs::read_to_string(mesh).unwrap();
    let mut seen = 0;
    let lines: Vec<String> = text
        .lines()
        .map(|line| {
            if !line.starts_with("v ") {
                return line.to_string();
            }
            seen += 1;
            if seen != 2 {
                return line.to_string();
            }
            let mut x: Vec<f64> = line[2..]
                .split_whitespace()
                .map(|t| t.parse().unwrap())
                .collect();
            x[2] += amount;
            format!("v {} {} {}", x[0], x[1], x[2])
        })
        .collect();
    let path = mesh.with_file_name(name);
    std::fs::write(&path, lines.join("\n")).unwrap();
    path
}

/// `surftopo isometric A B ARGS --json`: the exit code and the JSON.
fn isometric_json(a: &Path, b: &Path, args: &[&str]) -> (i32, Value) {
    let out = surftopo()
        .arg("isometric")
        .arg(a)
        .arg(b)
        .args(args)
        .arg("--json")
        .output()
        .unwrap();
    let json = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!("{e}: {}", String::from_utf8_lossy(&out.stderr));
    });
    (out.status.code().unwrap(), json)
}

/// [`isometric_json`], asserting the exit code and the JSON's `isometric`; returns the JSON.
fn expect(a: &Path, b: &Path, args: &[&str], code: i32, isometric: Value) -> Value {
    let (actual, json) = isometric_json(a, b, args);
    assert_eq!(
        (actual, &json["isometric"]),
        (code, &isometric),
        "{args:?}: {json}"
    );
    json
}

#[test]
fn exit_codes_and_json_say_isometric_not_isometric_or_undecidable() {
    let dir = tempfile::tempdir().unwrap();
    let mesh = generated_genus_surface(dir.path(), "g.obj", 2);
    let flipped = dir.path().join("f.json");
    surftopo()
        .args(["generate", "intrinsic-flips", "--count", "300", "--input"])
        .arg(&mesh)
        .arg("-o")
        .arg(&flipped)
        .assert()
        .success();
    let json = expect(&mesh, &flipped, &[], 0, Value::Bool(true));
    assert_eq!(json["verdict"], "isometric");
    assert_eq!(json["tolerance"], 1e-7);
    // One vertex moved by 1e-4: the lengths differ beyond every tolerance variant.
    let far = moved_copy(&mesh, 1e-4, "far.obj");
    expect(&mesh, &far, &[], 1, Value::Bool(false));
    // By 1e-5: beyond the default tolerance, within the hundredfold variant: undecidable.
    let near = moved_copy(&mesh, 1e-5, "near.obj");
    let json = expect(&mesh, &near, &[], 3, Value::Null);
    assert_eq!(json["verdict"], "undecidable in double precision");
    // Invalid input: exit 2, an error naming the file.
    let out = surftopo()
        .arg("isometric")
        .arg(&mesh)
        .arg(dir.path().join("absent.obj"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("absent.obj"));
}

#[test]
fn tolerance_has_a_documented_default_and_decides_what_is_equal() {
    let dir = tempfile::tempdir().unwrap();
    let mesh = generated_genus_surface(dir.path(), "g.obj", 2);
    let far = moved_copy(&mesh, 1e-4, "far.obj");
    let json = expect(&far, &mesh, &["--tolerance", "1e-3"], 0, Value::Bool(true));
    assert_eq!(json["tolerance"], 1e-3);
    for bad in ["0", "1", "-1e-3", "NaN"] {
        surftopo()
            .arg("isometric")
            .arg(&mesh)
            .arg(&far)
            .arg(format!("--tolerance={bad}"))
            .assert()
            .code(2);
    }
    let help = surftopo().args(["isometric", "--help"]).output().unwrap();
    let help = String::from_utf8_lossy(&help.stdout);
    assert!(
        help.contains("--tolerance <T>") && help.contains("[default: 0.0000001]"),
        "{help}"
    );
}

#[test]
fn reasons_name_the_polygon_and_the_lengths_in_words() {
    let dir = tempfile::tempdir().unwrap();
    let mesh = generated_genus_surface(dir.path(), "g.obj", 2);
    let far = moved_copy(&mesh, 1e-4, "far.obj");
    let (_, json) = isometric_json(&mesh, &far, &[]);
    let reason = json["reason"].as_str().unwrap();
    assert!(
        reason.contains("the edge lengths differ: the ")
            && reason.contains(" shortest side of a triangle is ")
            && reason.contains("0.9999"),
        "{reason}"
    );
    let (_, json) = isometric_json(&mesh, &far, &["--tolerance", "1e-3"]);
    let reason = json["reason"].as_str().unwrap();
    assert!(
        reason.contains("correspond: an isometry lays polygon ") && !reason.contains("maps to"),
        "{reason}"
    );
    // The reason goes to stderr without --json, the verdict to stdout.
    let out = surftopo()
        .arg("isometric")
        .arg(&mesh)
        .arg(&far)
        .output()
        .unwrap();
    assert_eq!(String::from_utf8_lossy(&out.stdout), "not isometric\n");
    assert!(String::from_utf8_lossy(&out.stderr).contains("the edge lengths differ"));
}

#[test]
fn tessellation_files_of_delaunay_are_inputs() {
    let dir = tempfile::tempdir().unwrap();
    let mesh = generated_genus_surface(dir.path(), "g.obj", 2);
    let tessellation = dir.path().join("t.json");
    surftopo()
        .arg("delaunay")
        .arg(&mesh)
        .arg("--tessellation")
        .arg(&tessellation)
        .assert()
        .success();
    // The tessellation has polygons of more than three sides (the brick's flat faces).
    let doc: Value =
        serde_json::from_str(&std::fs::read_to_string(&tessellation).unwrap()).unwrap();
    let sides = |p: &Value| {
        p.get("corners")
            .or_else(|| p.get("lengths"))
            .and_then(Value::as_array)
            .map_or(0, Vec::len)
    };
    assert!(
        doc["polygons"]
            .as_array()
            .unwrap()
            .iter()
            .any(|p| sides(p) > 3),
        "no polygon beyond a triangle"
    );
    for method in ["flip", "voronoi"] {
        expect(
            &mesh,
            &tessellation,
            &["--method", method],
            0,
            Value::Bool(true),
        );
    }
    let far = moved_copy(&mesh, 1e-4, "far.obj");
    expect(&far, &tessellation, &[], 1, Value::Bool(false));
}
