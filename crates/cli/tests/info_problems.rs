//! `surftopo info`: every problem class on a small hostile file of its own, counted under its
//! JSON key, labelled with the same words in the text report, and `--strict` failing on it.

mod common;

use common::{json_of, surftopo, write};
use serde_json::Value;
use std::path::Path;

const TETRA: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";

/// The problem classes, in the order of the JSON keys.
const CLASSES: [&str; 7] = [
    "non_finite_coordinates",
    "zero_area_faces",
    "degenerate_faces",
    "duplicate_faces",
    "non_manifold_edges",
    "non_manifold_vertices",
    "other_problems",
];

fn info_json(path: &Path) -> Value {
    json_of(surftopo().arg("info").arg(path).arg("--json"), &[])
}

/// Checks what holds for every report: the documented keys in order, the class counts summing
/// to `problems_total`, the list cut at 100 exactly when `problems_truncated` says so.
fn check_report(v: &Value) {
    let keys: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
    let mut expected = vec![
        "vertices",
        "edges",
        "faces",
        "point_cloud",
        "vertex_properties",
        "genus",
        "euler_characteristic",
        "components",
        "closed",
        "orientable",
        "boundary_loops",
        "boundary_edges",
        "simplicial",
        "valid",
        "reoriented_faces",
        "unreferenced_vertices",
        "welded_vertices",
    ];
    expected.extend(CLASSES);
    expected.extend([
        "problems_total",
        "problems_truncated",
        "problems",
        "near_degenerate_faces",
        "warnings",
        "weld_hint",
        "surfaces",
    ]);
    assert_eq!(keys, expected);
    let total = v["problems_total"].as_u64().unwrap();
    let sum: u64 = CLASSES.iter().map(|k| v[k].as_u64().unwrap()).sum();
    assert_eq!(sum, total, "{v}");
    let listed = v["problems"].as_array().unwrap().len() as u64;
    assert_eq!(listed, total.min(100), "{v}");
    assert_eq!(v["problems_truncated"], total > listed, "{v}");
    assert_eq!(v["valid"], total == 0, "{v}");
}

/// One file per class: the class's count is as built, the message lists it, the text report
/// labels it with the key's words, and `--strict` exits with 2.
#[test]
fn every_problem_class_is_counted_under_its_key() {
    // The 6-vertex projective plane: closed (every edge in two faces), not orientable.
    let rp2 = "v 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 0\nv 0 1 1\nv 1 0 1\n\
               f 1 2 3\nf 1 3 4\nf 1 4 5\nf 1 5 6\nf 1 6 2\nf 2 3 5\nf 3 4 6\nf 4 5 2\nf 5 6 3\nf 6 2 4\n";
    let two_tetras =
        format!("{TETRA}v 5 0 0\nv 6 0 0\nv 5 1 0\nv 5 0 1\nf 5 7 6\nf 5 6 8\nf 6 7 8\nf 5 8 7\n");
    // (file, text, class, count, words of the message)
    let cases: Vec<(&str, String, &str, u64, &str)> = vec![
        (
            "nan.obj",
            TETRA
                .replace("v 1 0 0", "v nan 0 0")
                .replace("v 0 0 1", "v 0 -inf inf"),
            "non_finite_coordinates",
            3,
            "non-finite coordinate",
        ),
        (
            "nan.off",
            "OFF\n4 4 0\n0 0 0\n1 0 0\n0 NaN 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n".into(),
            "non_finite_coordinates",
            1,
            "vertex 2: non-finite coordinate NaN on axis 1",
        ),
        (
            // Vertices 1, 2, 3 on the x axis: face 0 (1 3 2) has zero area, the others not.
            "collinear.obj",
            TETRA.replace("v 0 1 0", "v 2 0 0"),
            "zero_area_faces",
            1,
            "face 0: zero area",
        ),
        (
            // A quad whose four corners lie on one line, closed by a second quad: both zero.
            "flat-quads.obj",
            "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf 1 2 3 4\nf 4 3 2 1\n".into(),
            "zero_area_faces",
            2,
            "zero area",
        ),
        (
            "repeat.obj",
            TETRA.replace("f 1 4 3", "f 1 4 4"),
            "degenerate_faces",
            1,
            "repeated",
        ),
        (
            "duplicate.obj",
            format!("{TETRA}f 1 3 2\n"),
            "duplicate_faces",
            1,
            "duplicate of face 0",
        ),
        (
            "nonmanifold_edge.obj",
            format!("{TETRA}v 1 1 1\nf 1 2 5\n"),
            "non_manifold_edges",
            1,
            "non-manifold edge",
        ),
        (
            "nonmanifold_vertex.obj",
            format!("{TETRA}v 2 0 0\nv 2 1 0\nv 2 0 1\nf 1 6 5\nf 1 5 7\nf 5 6 7\nf 1 7 6\n"),
            "non_manifold_vertices",
            1,
            "non-manifold vertex",
        ),
    ];
    let dir = tempfile::tempdir().unwrap();
    for (name, text, class, count, words) in &cases {
        let path = write(dir.path(), name, text);
        let v = info_json(&path);
        check_report(&v);
        assert_eq!(v[*class], *count, "{name}: {v}");
        let listed = v["problems"].as_array().unwrap();
        assert!(
            listed
                .iter()
                .any(|p| p.as_str().unwrap().contains(words) && p.as_str().unwrap().contains(name)),
            "{name}: no problem says '{words}': {v}"
        );
        let report = surftopo().arg("info").arg(&path).output().unwrap();
        assert!(report.status.success());
        let report = String::from_utf8_lossy(&report.stdout);
        let label = class.replace('_', " ");
        assert!(
            report.lines().any(|l| l.trim_start().starts_with(&label)
                && l.trim_end().ends_with(&count.to_string())),
            "{name}: no '{label} {count}' line in:\n{report}"
        );
        let strict = surftopo()
            .arg("info")
            .arg(&path)
            .arg("--strict")
            .output()
            .unwrap();
        assert_eq!(strict.status.code(), Some(2), "{name}");
    }
    // Valid surfaces (boundary, no orientation, pieces are not problems): every class 0, each
    // piece classified, `--strict` passes.
    for (name, text, names) in [
        ("open.obj", TETRA.replace("f 1 4 3\n", ""), vec!["disk"]),
        ("rp2.obj", rp2.to_string(), vec!["projective plane"]),
        ("two.obj", two_tetras, vec!["sphere", "sphere"]),
    ] {
        let path = write(dir.path(), name, &text);
        let v = info_json(&path);
        check_report(&v);
        let got: Vec<&str> = v["surfaces"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| s["name"].as_str().unwrap())
            .collect();
        assert_eq!(got, names, "{name}");
        surftopo()
            .args(["info", "--strict"])
            .arg(&path)
            .assert()
            .success();
    }
    // A valid file: every class 0, genus given, `--strict` passes.
    let path = write(dir.path(), "tetra.obj", TETRA);
    let v = info_json(&path);
    check_report(&v);
    assert_eq!(
        (v["problems_total"].as_u64(), v["genus"].as_i64()),
        (Some(0), Some(0))
    );
    surftopo()
        .args(["info", "--strict"])
        .arg(&path)
        .assert()
        .success();
}

/// Geometric problems leave the topology defined: the genus of a closed surface with a NaN or
/// a zero-area face is still reported, though the mesh is not valid.
#[test]
fn geometric_problems_keep_the_genus() {
    let dir = tempfile::tempdir().unwrap();
    for (name, text) in [
        ("nan.obj", TETRA.replace("v 1 0 0", "v nan 0 0")),
        ("flat.obj", TETRA.replace("v 0 1 0", "v 2 0 0")),
    ] {
        let v = info_json(&write(dir.path(), name, &text));
        assert_eq!(
            (v["genus"].as_i64(), &v["valid"]),
            (Some(0), &Value::Bool(false)),
            "{v}"
        );
        assert_eq!(v["closed"], true);
    }
}

/// More than 100 problems: the list stops at 100 and says so; the counts are complete.
#[test]
fn a_truncated_problem_list_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from(TETRA);
    for k in 0..150 {
        // 150 vertices with a non-finite coordinate, none used by a face (x is NaN).
        text.push_str(&format!("v nan {k} 0\n"));
    }
    let path = write(dir.path(), "many.obj", &text);
    let v = info_json(&path);
    check_report(&v);
    assert_eq!(v["non_finite_coordinates"], 150);
    assert_eq!(v["unreferenced_vertices"], 150);
    assert_eq!(v["problems_total"], 150);
    assert_eq!(v["problems_truncated"], true);
    let report = surftopo().arg("info").arg(&path).output().unwrap();
    let report = String::from_utf8_lossy(&report.stdout);
    assert!(report.contains("problems truncated"), "{report}");
}

/// Only `info` keeps non-finite coordinates: every other command refuses them with exit 2 and a
/// message naming the file, the line and the vertex.
#[test]
fn other_commands_refuse_non_finite_coordinates() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(
        dir.path(),
        "nan.obj",
        &TETRA.replace("v 0 1 0", "v 0 nan 0"),
    );
    let out_mesh = dir.path().join("out.obj");
    let out_json = dir.path().join("out.json");
    let runs: [Vec<&std::ffi::OsStr>; 4] = [
        vec!["convert".as_ref(), path.as_ref(), out_mesh.as_ref()],
        vec![
            "quad".as_ref(),
            path.as_ref(),
            "-o".as_ref(),
            out_mesh.as_ref(),
        ],
        vec![
            "irreducible".as_ref(),
            path.as_ref(),
            "-o".as_ref(),
            out_mesh.as_ref(),
        ],
        vec![
            "delaunay".as_ref(),
            path.as_ref(),
            "-o".as_ref(),
            out_json.as_ref(),
        ],
    ];
    for args in runs {
        let out = surftopo().args(&args).output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.contains("nan.obj:3: non-finite coordinate NaN of vertex 2"),
            "{args:?}: {stderr}"
        );
        assert!(!out_mesh.exists() && !out_json.exists());
    }
}
