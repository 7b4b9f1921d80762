//! `surftopo isometric`: its exit codes (0 isometric, 1 not, 2 invalid input, 3 undecidable; 4,
//! an internal failure, is unit-tested in failure.rs), `--json`, `--tolerance`, reasons in words,
//! and the tessellation files `delaunay --tessellation` writes as inputs.

mod common;

use common::{generate, generated_genus_surface, surftopo};
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

/// The vertices and faces (1-based) of an OBJ file of triangles.
fn obj(path: &Path) -> (Vec<[f64; 3]>, Vec<[usize; 3]>) {
    let text = std::fs::read_to_string(path).unwrap();
    let (mut vertices, mut faces) = (Vec::new(), Vec::new());
    for line in text.lines() {
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.first() {
            Some(&"v") => vertices.push([1, 2, 3].map(|k| words[k].parse::<f64>().unwrap())),
            Some(&"f") => faces.push([1, 2, 3].map(|k| words[k].parse::<usize>().unwrap())),
            _ => {}
        }
    }
    (vertices, faces)
}

/// The OBJ files `parts`, each moved by `map`, side by side in one file.
fn joined(dir: &Path, name: &str, parts: &[&Path], map: impl Fn([f64; 3]) -> [f64; 3]) -> PathBuf {
    let mut text = String::new();
    let mut offset = 0;
    let mut faces = String::new();
    for (k, part) in parts.iter().enumerate() {
        let (v, f) = obj(part);
        for p in &v {
            let [x, y, z] = map(*p);
            text.push_str(&format!("v {} {y} {z}\n", x + 10.0 * k as f64));
        }
        for t in &f {
            faces.push_str(&format!(
                "f {} {} {}\n",
                t[0] + offset,
                t[1] + offset,
                t[2] + offset
            ));
        }
        offset += v.len();
    }
    text.push_str(&faces);
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn every_surface_kind_against_its_copies_mirror_images_and_scaled_copies() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let kinds: [(&str, &[&str]); 8] = [
        ("disk", &["disk", "--n", "5"]),
        ("annulus", &["annulus"]),
        ("mobius", &["mobius-band"]),
        ("rp2", &["projective-plane", "--subdivide", "1"]),
        ("klein", &["klein-bottle"]),
        ("n3", &["non-orientable", "--crosscaps", "3"]),
        ("holes", &["torus", "--cut-holes", "2"]),
        ("pieces", &["mobius-band", "--copies", "3"]),
    ];
    for (name, args) in kinds {
        let mut args = args.to_vec();
        args.extend(["--seed", "5"]);
        let mesh = generate(d, &format!("{name}.obj"), &args);
        let mut shuffled_args = args.clone();
        shuffled_args.push("--shuffle-faces");
        let shuffled = generate(d, &format!("{name}-shuffled.obj"), &shuffled_args);
        let json = expect(&mesh, &shuffled, &[], 0, Value::Bool(true));
        assert!(
            json["reason"].as_str().unwrap().contains("correspond"),
            "{name}: {json}"
        );
        let mirror = joined(d, &format!("{name}-mirror.obj"), &[&mesh], |p| {
            [-p[0], p[1], p[2]]
        });
        expect(&mesh, &mirror, &[], 0, Value::Bool(true));
        let scaled = joined(d, &format!("{name}-scaled.obj"), &[&mesh], |p| {
            p.map(|x| 1.001 * x)
        });
        let json = expect(&mesh, &scaled, &[], 1, Value::Bool(false));
        assert!(
            json["reason"].as_str().unwrap().contains("areas"),
            "{name}: {json}"
        );
    }
}

#[test]
fn pieces_boundary_lengths_and_kinds_are_compared() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let band = generate(d, "band.obj", &["mobius-band"]);
    let ring = generate(d, "ring.obj", &["annulus"]);
    let both = joined(d, "both.obj", &[&band, &ring], |p| p);
    let swapped = joined(d, "swapped.obj", &[&ring, &band], |p| p);
    expect(&both, &swapped, &[], 0, Value::Bool(true));
    // A Möbius band is not an annulus, whatever the lengths.
    let json = expect(&band, &ring, &[], 1, Value::Bool(false));
    assert!(
        json["reason"].as_str().unwrap().contains("Möbius band"),
        "{json}"
    );
    // The cylinder twice as wide and half as high: the same area, longer boundary loops.
    let wide = joined(d, "wide.obj", &[&ring], |p| {
        [2.0 * p[0], 2.0 * p[1], 0.5 * p[2]]
    });
    let json = expect(&ring, &wide, &[], 1, Value::Bool(false));
    assert!(
        json["reason"].as_str().unwrap().contains("boundary loops"),
        "{json}"
    );
    let wide_both = joined(d, "wide-both.obj", &[&band, &wide], |p| p);
    expect(&both, &wide_both, &[], 1, Value::Bool(false));
    // Three pieces against two.
    let three = joined(d, "three.obj", &[&band, &ring, &ring], |p| p);
    let json = expect(&both, &three, &[], 1, Value::Bool(false));
    assert!(
        json["reason"]
            .as_str()
            .unwrap()
            .contains("connected pieces"),
        "{json}"
    );
    // A closed mesh of one piece against a band: compared, not refused.
    let torus = generate(d, "torus.obj", &["torus"]);
    expect(&torus, &band, &[], 1, Value::Bool(false));
}

#[test]
fn flat_vertices_on_open_surfaces_are_undecided_and_the_wave_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let band = generate(d, "band.obj", &["mobius-band"]);
    // Midpoint subdivision keeps the surface and adds flat vertices: no proof either way.
    let finer = generate(d, "finer.obj", &["mobius-band", "--subdivide", "1"]);
    let json = expect(&band, &finer, &[], 3, Value::Null);
    assert_eq!(json["verdict"], "undecided");
    assert!(json["reason"].as_str().unwrap().contains("flat"), "{json}");
    for method in ["voronoi", "dubois"] {
        let out = surftopo()
            .arg("isometric")
            .arg(&band)
            .arg(&band)
            .args(["--method", method])
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(
            stderr.contains("band.obj") && stderr.contains("--method flip"),
            "{stderr}"
        );
    }
}
