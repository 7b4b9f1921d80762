//! Every kind of surface through the binary: `generate` makes each kind (with boundary,
//! non-orientable, in pieces), `info` classifies it, `irreducible` reduces it keeping the
//! classification, `delaunay` flips it (`quad` pairs it: `quad_surfaces.rs`), and the commands
//! that do not take it yet say what they do not support.

mod common;

use common::{generate, json_of, refused, run_ok, surftopo};
use serde_json::Value;
use std::path::Path;

/// `info --json` of a file, which must succeed (with `--strict` when `strict`).
fn info_of(path: &Path, strict: bool) -> Value {
    let mut info = surftopo();
    info.args(["info", "--json"])
        .args(strict.then_some("--strict"))
        .arg(path);
    json_of(&mut info, &[])
}

/// `info --json` of a file whose combinatorics are valid: no problem but geometric ones (an
/// irreducible triangulation or a simplification keeps input positions, which may be collinear:
/// a midpoint and its edge's ends).
fn info(path: &Path) -> Value {
    let v = info_of(path, false);
    let geometric = v["zero_area_faces"].as_u64().unwrap();
    assert_eq!(v["problems_total"].as_u64().unwrap(), geometric, "{v}");
    v
}

/// The names of the pieces `info` reports.
fn names(v: &Value) -> Vec<String> {
    v["surfaces"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["name"].as_str().unwrap().to_string())
        .collect()
}

#[test]
fn every_kind_is_generated_classified_and_reduced() {
    let dir = tempfile::tempdir().unwrap();
    let cases: &[(&[&str], &[&str], std::ops::RangeInclusive<u64>)] = &[
        (&["disk", "--n", "5", "--flips", "30"], &["disk"], 3..=3),
        (&["annulus", "--m", "8", "--n", "2"], &["annulus"], 6..=40),
        (
            &["mobius-band", "--m", "9", "--n", "2", "--splits", "20"],
            &["Möbius band"],
            5..=6,
        ),
        (
            &["projective-plane", "--subdivide", "2", "--flips", "100"],
            &["projective plane"],
            6..=7,
        ),
        (
            &["klein-bottle", "--m", "8", "--n", "6", "--splits", "40"],
            &["Klein bottle"],
            8..=11,
        ),
        (
            &["non-orientable", "--crosscaps", "3", "--subdivide", "1"],
            &["N_3"],
            9..=35,
        ),
        (
            &[
                "genus",
                "--genus",
                "2",
                "--size",
                "2",
                "--cut-holes",
                "2",
                "--shuffle-faces",
            ],
            &["genus 2 with 2 boundary loops"],
            4..=200,
        ),
        (
            &[
                "projective-plane",
                "--subdivide",
                "1",
                "--copies",
                "2",
                "--simplify",
                "20",
            ],
            &["projective plane", "projective plane"],
            12..=14,
        ),
    ];
    for (k, (args, want, vertices)) in cases.iter().enumerate() {
        let input = generate(dir.path(), &format!("s{k}.ply"), args);
        let v = info(&input);
        if !args.contains(&"--simplify") {
            info_of(&input, true);
        }
        assert_eq!(names(&v), *want, "{args:?}");
        for algorithm in ["rs", "schipper", "brute-force"] {
            let output = dir.path().join(format!("s{k}-{algorithm}.obj"));
            let out = surftopo()
                .arg("irreducible")
                .arg(&input)
                .arg("-o")
                .arg(&output)
                .args(["--algorithm", algorithm, "--json"])
                .output()
                .unwrap();
            assert!(
                out.status.success(),
                "{}",
                String::from_utf8_lossy(&out.stderr)
            );
            let report: Value = serde_json::from_slice(&out.stdout).unwrap();
            let reduced = info(&output);
            assert_eq!(names(&reduced), *want, "{args:?} {algorithm}");
            assert_eq!(report["output"]["surfaces"], reduced["surfaces"]);
            assert_eq!(report["input"]["surfaces"], v["surfaces"]);
            let n = reduced["vertices"].as_u64().unwrap();
            assert!(vertices.contains(&n), "{args:?} {algorithm}: {n} vertices");
            assert_eq!(
                report["contractions"].as_u64().unwrap(),
                v["vertices"].as_u64().unwrap() - n
            );
        }
    }
}

#[test]
fn commands_name_what_they_do_not_support_yet() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (
            generate(dir.path(), "open.obj", &["torus", "--cut-holes", "1"]),
            "surfaces with boundary are not supported yet",
        ),
        (
            generate(dir.path(), "kb.obj", &["klein-bottle"]),
            "non-orientable surfaces are not supported yet",
        ),
        (
            generate(dir.path(), "two.obj", &["torus", "--copies", "2"]),
            "files of several pieces are not supported yet",
        ),
    ];
    for (input, message) in &cases {
        let out = surftopo()
            .args(["generate", "intrinsic-flips", "--count", "3", "--input"])
            .arg(input)
            .arg("-o")
            .arg(dir.path().join("flipped.json"))
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(stderr.contains(&format!("generate: {message}")), "{stderr}");
    }
}

#[test]
fn cut_holes_that_do_not_fit_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let out = surftopo()
        .args(["generate", "tetrahedron", "--cut-holes", "2", "-o"])
        .arg(dir.path().join("x.obj"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("only 1 holes fit"));
    assert!(!dir.path().join("x.obj").exists());
}

/// A Matrix Market file written by the CLI, as a dense matrix (symmetric storage expanded).
fn dense_matrix(path: &Path) -> Vec<Vec<f64>> {
    let file = std::fs::File::open(path).unwrap();
    let m = surftopo_intrinsic::read_matrix_market(std::io::BufReader::new(file)).unwrap();
    let mut dense = vec![vec![0.0; m.n]; m.n];
    for (i, j, v) in m.triplets() {
        dense[i as usize][j as usize] = v;
    }
    dense
}

#[test]
fn delaunay_flips_every_surface_kind_and_refuses_the_methods_of_closed_orientable_ones() {
    let dir = tempfile::tempdir().unwrap();
    let kinds: [&[&str]; 9] = [
        &["disk", "--n", "6", "--flips", "30"],
        &["annulus", "--flips", "30"],
        &["mobius-band", "--flips", "30"],
        &["projective-plane", "--subdivide", "1", "--flips", "20"],
        &["klein-bottle", "--flips", "60"],
        &["non-orientable", "--crosscaps", "3"],
        &["torus", "--cut-holes", "2", "--flips", "40"],
        &["mobius-band", "--copies", "3"],
        &["torus", "--copies", "2"],
    ];
    for (k, args) in kinds.iter().enumerate() {
        let input = generate(dir.path(), &format!("in{k}.obj"), args);
        let v = info(&input);
        let (l_path, m_path) = (dir.path().join("l.mtx"), dir.path().join("m.mtx"));
        let out = surftopo()
            .arg("delaunay")
            .arg(&input)
            .arg("--laplacian")
            .arg(&l_path)
            .arg("--mass")
            .arg(&m_path)
            .arg("--json")
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{args:?}: {stderr}");
        let report: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(report["method"], "flip", "{args:?}");
        assert_eq!(report["non_delaunay_edges"], 0, "{args:?}");
        for key in ["vertices", "edges", "faces"] {
            assert_eq!(report[key], v[key], "{args:?}: {key}");
        }
        // The Laplacian: one row per vertex, symmetric, rows summing to zero; the mass matrix's
        // trace is the area (every triangle once).
        let l = dense_matrix(&l_path);
        assert_eq!(l.len() as u64, v["vertices"].as_u64().unwrap());
        let scale = l.iter().flatten().fold(0.0f64, |a, x| a.max(x.abs()));
        for (i, row) in l.iter().enumerate() {
            assert!(
                row.iter().sum::<f64>().abs() <= 1e-9 * scale,
                "{args:?}: row {i}"
            );
            for (j, x) in row.iter().enumerate() {
                assert_eq!(*x, l[j][i], "{args:?}: ({i}, {j})");
            }
            assert!(row[i] > 0.0, "{args:?}: vertex {i} has no weight");
        }
        let m = dense_matrix(&m_path);
        assert!((0..m.len()).all(|i| m[i][i] > 0.0), "{args:?}");
    }
    // The wave and Theorem 1 need a closed orientable surface: exit 2, naming what works,
    // nothing written.
    let input = generate(dir.path(), "mb.obj", &["mobius-band"]);
    let refusals: [(&[&str], &str); 2] = [
        (
            &["--method", "voronoi", "--tessellation", "t.json"],
            "--method flip",
        ),
        (&["--method", "dubois", "--json"], "--method flip"),
    ];
    for (args, message) in refusals {
        let mut cmd = surftopo();
        cmd.current_dir(dir.path())
            .arg("delaunay")
            .arg(&input)
            .args(args);
        refused(&mut cmd, message, &format!("{args:?}"));
        assert!(!dir.path().join("t.json").exists());
    }
}

#[test]
fn delaunay_writes_a_non_orientable_triangulation_with_reversed_gluings() {
    let dir = tempfile::tempdir().unwrap();
    let input = generate(dir.path(), "mb.obj", &["mobius-band", "--flips", "20"]);
    let output = dir.path().join("mb.json");
    run_ok(
        surftopo()
            .arg("delaunay")
            .arg(&input)
            .arg("-o")
            .arg(&output),
        "delaunay",
    );
    let doc: Value = serde_json::from_slice(&std::fs::read(&output).unwrap()).unwrap();
    assert_eq!(doc["version"], 2);
    let v = info(&input);
    assert_eq!(
        doc["polygons"].as_array().unwrap().len() as u64,
        v["faces"].as_u64().unwrap()
    );
    let pairs = doc["matching"].as_array().unwrap();
    let reversed = pairs
        .iter()
        .filter(|p| p.get(2) == Some(&Value::Bool(true)))
        .count();
    assert!(reversed > 0);
    // Interior edges are matched, boundary edges are not.
    let boundary = v["boundary_edges"].as_u64().unwrap() as usize;
    assert_eq!(
        2 * pairs.len() + boundary,
        3 * doc["polygons"].as_array().unwrap().len()
    );
    // Read back: the same triangulation (crates/cli/tests/portalgon_every_surface.rs checks
    // every surface kind).
    let figures = json_of(
        surftopo().arg("delaunay").arg(&output).arg("--json"),
        &["flips"],
    );
    assert_eq!(figures["flips"], 0);
}

#[test]
fn delaunay_tessellates_every_surface_kind() {
    // The tessellation file read back as JSON: polygons by corners, inscribed; V - E + F the
    // surface's Euler characteristic; unmatched sides the boundary edges; reversed gluings on
    // the non-orientable kinds only. (The tessellation itself is verified in the library's
    // tests/every_surface.rs.)
    let dir = tempfile::tempdir().unwrap();
    let kinds: [(&[&str], bool); 6] = [
        (&["disk", "--n", "5"], false),
        (&["annulus", "--flips", "30"], false),
        (&["mobius-band", "--flips", "30"], true),
        (&["klein-bottle", "--flips", "60"], true),
        (&["torus", "--cut-holes", "2", "--flips", "40"], false),
        (&["projective-plane", "--copies", "2"], true),
    ];
    for (k, (args, non_orientable)) in kinds.iter().enumerate() {
        let input = generate(dir.path(), &format!("in{k}.obj"), args);
        let v = info(&input);
        let path = dir.path().join(format!("t{k}.json"));
        let out = surftopo()
            .arg("delaunay")
            .arg(&input)
            .arg("--tessellation")
            .arg(&path)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{args:?}: {stderr}");
        let doc: Value = serde_json::from_slice(&std::fs::read(&path).unwrap()).unwrap();
        let polygons = doc["polygons"].as_array().unwrap();
        let pairs = doc["matching"].as_array().unwrap();
        let sides: usize = polygons
            .iter()
            .map(|p| p["corners"].as_array().unwrap().len())
            .sum();
        let boundary = v["boundary_edges"].as_u64().unwrap() as usize;
        assert_eq!(2 * pairs.len() + boundary, sides, "{args:?}");
        let mut labels: Vec<u64> = polygons
            .iter()
            .flat_map(|p| p["vertices"].as_array().unwrap().iter())
            .map(|x| x.as_u64().unwrap())
            .collect();
        labels.sort_unstable();
        labels.dedup();
        assert_eq!(labels.len() as u64, v["vertices"].as_u64().unwrap());
        let chi = labels.len() as i64 - (pairs.len() + boundary) as i64 + polygons.len() as i64;
        let want = v["vertices"].as_i64().unwrap() - v["edges"].as_i64().unwrap()
            + v["faces"].as_i64().unwrap();
        assert_eq!(chi, want, "{args:?}");
        let reversed = pairs.iter().any(|p| p.get(2) == Some(&Value::Bool(true)));
        assert_eq!(reversed, *non_orientable, "{args:?}");
        assert_eq!(doc["version"], if reversed { 2 } else { 1 });
        // Our reader reads it back.
        surftopo_intrinsic::PortalgonDoc::from_slice(&std::fs::read(&path).unwrap()).unwrap();
    }
}
