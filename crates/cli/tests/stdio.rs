//! Standard input and output (`-`), `--format`, and formats told from the content: every mesh
//! written is parsed back by the minimal readers here (independent of surftopo-io) and compared
//! with the input's vertices, faces and positions.

mod common;

use common::{generated_genus_surface, surftopo, write};
use std::io::{Read, Write};
use std::path::Path;

/// A mesh as the minimal readers see it: positions and faces.
#[derive(Debug, PartialEq)]
struct Mesh {
    positions: Vec<[f64; 3]>,
    faces: Vec<Vec<usize>>,
}

impl Mesh {
    /// Every face's triangle fan as corner positions rounded to `f32` (what STL holds).
    fn fan_corners(&self) -> Vec<[[f32; 3]; 3]> {
        let at = |v: usize| self.positions[v].map(|c| c as f32);
        self.faces
            .iter()
            .flat_map(|f| (1..f.len() - 1).map(move |i| [at(f[0]), at(f[i]), at(f[i + 1])]))
            .collect()
    }
}

fn numbers<T: std::str::FromStr>(line: &str) -> Vec<T>
where
    T::Err: std::fmt::Debug,
{
    line.split_whitespace()
        .map(|t| t.parse().unwrap())
        .collect()
}

/// OBJ: `v x y z` and `f i j k ...` (1-based, `i/t/n` forms cut at the slash).
fn parse_obj(text: &str) -> Mesh {
    let mut mesh = Mesh {
        positions: vec![],
        faces: vec![],
    };
    for line in text.lines() {
        if let Some(rest) = line.strip_prefix("v ") {
            let p: Vec<f64> = numbers(rest);
            mesh.positions.push([p[0], p[1], p[2]]);
        } else if let Some(rest) = line.strip_prefix("f ") {
            let face = rest.split_whitespace();
            let face = face.map(|t| t.split('/').next().unwrap().parse::<usize>().unwrap() - 1);
            mesh.faces.push(face.collect());
        }
    }
    mesh
}

/// ASCII OFF as surftopo writes it: `OFF`, counts, vertex lines, `k i1 .. ik` lines.
fn parse_off(text: &str) -> Mesh {
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("OFF"));
    let counts: Vec<usize> = numbers(lines.next().unwrap());
    let positions = (0..counts[0])
        .map(|_| {
            let p: Vec<f64> = numbers(lines.next().unwrap());
            [p[0], p[1], p[2]]
        })
        .collect();
    let faces = (0..counts[1])
        .map(|_| {
            let f: Vec<usize> = numbers(lines.next().unwrap());
            assert_eq!(f[0], f.len() - 1);
            f[1..].to_vec()
        })
        .collect();
    Mesh { positions, faces }
}

/// PLY, through the test kit's independent reader ([`surftopo_testkit::ply_parse`]).
fn parse_ply(bytes: &[u8]) -> Mesh {
    let ply = surftopo_testkit::ply_parse::parse(bytes);
    assert_eq!(ply.names[..3], ["x", "y", "z"]);
    Mesh {
        positions: ply.rows.iter().map(|r| [r[0], r[1], r[2]]).collect(),
        faces: ply
            .faces
            .iter()
            .map(|f| f.iter().map(|&v| v as usize).collect())
            .collect(),
    }
}

/// Binary STL: 80-byte header, count, 50-byte records; each triangle's corners as its own
/// vertices.
fn parse_stl(bytes: &[u8]) -> Mesh {
    let n = u32::from_le_bytes(bytes[80..84].try_into().unwrap()) as usize;
    assert_eq!(bytes.len(), 84 + 50 * n, "the binary STL size rule");
    assert!(!bytes.starts_with(b"solid"));
    let f = |k: usize| f64::from(f32::from_le_bytes(bytes[k..k + 4].try_into().unwrap()));
    let mut mesh = Mesh {
        positions: vec![],
        faces: vec![],
    };
    for t in 0..n {
        let record = 84 + 50 * t;
        for corner in 0..3 {
            let at = record + 12 + 12 * corner;
            mesh.positions.push([f(at), f(at + 4), f(at + 8)]);
        }
        mesh.faces.push(vec![3 * t, 3 * t + 1, 3 * t + 2]);
    }
    mesh
}

fn gunzip(bytes: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    flate2::read::GzDecoder::new(bytes)
        .read_to_end(&mut out)
        .unwrap();
    out
}

fn gzip(bytes: &[u8]) -> Vec<u8> {
    let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    e.write_all(bytes).unwrap();
    e.finish().unwrap()
}

/// Parses a mesh written as `format` (`obj`, `off`, `ply`, `stl`, optionally `.gz`).
fn parse(bytes: &[u8], format: &str) -> Mesh {
    let (name, plain) = match format.strip_suffix(".gz") {
        Some(name) => (name, gunzip(bytes)),
        None => (format, bytes.to_vec()),
    };
    match name {
        "obj" => parse_obj(std::str::from_utf8(&plain).unwrap()),
        "off" => parse_off(std::str::from_utf8(&plain).unwrap()),
        "ply" => parse_ply(&plain),
        "stl" => parse_stl(&plain),
        other => panic!("{other}"),
    }
}

/// Asserts that `written` (in `format`) is `original`: the same positions and faces, or for STL
/// the same triangle corners in single precision.
fn assert_same_mesh(original: &Mesh, written: &Mesh, format: &str) {
    if format.starts_with("stl") {
        assert_eq!(original.fan_corners(), written.fan_corners(), "{format}");
    } else {
        assert_eq!(original, written, "{format}");
    }
}

const FORMATS: [&str; 8] = [
    "obj", "off", "ply", "stl", "obj.gz", "off.gz", "ply.gz", "stl.gz",
];

/// A small genus-2 surface written by `generate` as OBJ, and its mesh.
fn original(dir: &Path) -> (std::path::PathBuf, Mesh) {
    let path = generated_genus_surface(dir, "g.obj", 2);
    let mesh = parse_obj(&std::fs::read_to_string(&path).unwrap());
    assert!(mesh.faces.len() > 50);
    (path, mesh)
}

/// Runs `surftopo ARGS` with `stdin`; returns (exit code, stdout, stderr).
fn run(args: &[&str], stdin: &[u8]) -> (Option<i32>, Vec<u8>, String) {
    let out = surftopo()
        .args(args)
        .write_stdin(stdin.to_vec())
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    (out.status.code(), out.stdout, stderr)
}

#[test]
fn convert_from_stdin_to_stdout_in_every_format_and_back() {
    let dir = tempfile::tempdir().unwrap();
    let (path, mesh) = original(dir.path());
    let obj = std::fs::read(&path).unwrap();
    for format in FORMATS {
        let (code, stdout, stderr) = run(&["convert", "-", "-", "--format", format], &obj);
        assert_eq!(code, Some(0), "{format}: {stderr}");
        assert_same_mesh(&mesh, &parse(&stdout, format), format);
        // The summary went to stderr: stdout holds the mesh alone.
        assert!(stderr.contains("wrote <stdout>"), "{stderr}");
        // And back: the written bytes on stdin, told by their content, to OBJ on stdout.
        let (code, back, stderr) = run(&["convert", "-", "-", "--format", "obj"], &stdout);
        assert_eq!(code, Some(0), "{format} back: {stderr}");
        let back = parse_obj(std::str::from_utf8(&back).unwrap());
        if format.starts_with("stl") {
            // STL input is welded: the corners come back shared, in single precision.
            assert_eq!(back.faces.len(), mesh.faces.len());
            assert_eq!(back.positions.len(), mesh.positions.len());
            assert_same_mesh(&mesh, &back, format);
        } else {
            assert_eq!(back, mesh, "{format} back");
        }
    }
}

#[test]
fn every_format_is_told_from_its_content_in_a_file_without_extension_and_on_stdin() {
    let dir = tempfile::tempdir().unwrap();
    let (path, mesh) = original(dir.path());
    for format in FORMATS {
        let named = dir.path().join(format!("m.{format}"));
        surftopo()
            .arg("convert")
            .arg(&path)
            .arg(&named)
            .assert()
            .success();
        let bytes = std::fs::read(&named).unwrap();
        assert_same_mesh(&mesh, &parse(&bytes, format), format);
        let bare = dir
            .path()
            .join(format!("bare-{}", format.replace('.', "-")));
        std::fs::write(&bare, &bytes).unwrap();
        let file = surftopo()
            .args(["info", "--json"])
            .arg(&bare)
            .output()
            .unwrap();
        let (code, stdin, stderr) = run(&["info", "-", "--json"], &bytes);
        assert_eq!(file.status.code(), Some(0), "{format}");
        assert_eq!(code, Some(0), "{format}: {stderr}");
        for json in [file.stdout, stdin] {
            let info: serde_json::Value = serde_json::from_slice(&json).unwrap();
            // STL is welded on reading: the same vertex count as the original.
            assert_eq!(info["vertices"], mesh.positions.len(), "{format}");
            assert_eq!(info["faces"], mesh.faces.len(), "{format}");
            assert_eq!(info["genus"], 2, "{format}");
        }
    }
    // gzip data named like a plain file without extension, from stdin: sniffed inside.
    let off = std::fs::read(dir.path().join("m.off")).unwrap();
    let (code, stdout, stderr) = run(&["convert", "-", "-", "--format", "ply"], &gzip(&off));
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(parse_ply(&stdout), mesh);
}

#[test]
fn undecidable_content_is_refused_with_exit_2_and_says_why() {
    let dir = tempfile::tempdir().unwrap();
    let junk = write(dir.path(), "notes", "hello\nworld\n");
    let out = surftopo().arg("info").arg(&junk).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("notes: cannot tell the mesh format from the content"),
        "{stderr}"
    );
    assert!(
        stderr.contains("line 1 starts with no OBJ keyword"),
        "{stderr}"
    );
    for input in [&b""[..], b"4 4 6\n", &gzip(b"solid empty\nendsolid\n")] {
        let (code, stdout, stderr) = run(&["convert", "-", "-", "--format", "obj"], input);
        assert_eq!(code, Some(2), "{stderr}");
        assert!(stderr.contains("<stdin>: cannot tell"), "{stderr}");
        assert!(stdout.is_empty());
    }
}

#[test]
fn with_a_mesh_on_stdout_every_summary_goes_to_stderr() {
    let dir = tempfile::tempdir().unwrap();
    let (path, mesh) = original(dir.path());
    let obj = std::fs::read(&path).unwrap();
    let runs: [&[&str]; 4] = [
        &["quad", "-", "-o", "-", "--format", "off", "--json"],
        &["quad", "-", "-o", "-", "--format", "obj"],
        &["irreducible", "-", "-o", "-", "--format", "ply", "--json"],
        &["irreducible", "-", "-o", "-", "--format", "off"],
    ];
    for args in runs {
        let (code, stdout, stderr) = run(args, &obj);
        assert_eq!(code, Some(0), "{args:?}: {stderr}");
        let format = args[5];
        let written = parse(&stdout, format);
        if args[0] == "quad" {
            // Same vertices, all quads, half as many faces.
            assert_eq!(written.positions, mesh.positions, "{args:?}");
            assert_eq!(2 * written.faces.len(), mesh.faces.len());
            assert!(written.faces.iter().all(|f| f.len() == 4));
        } else {
            // The input's vertex list (its numbering kept), the surviving vertices in faces:
            // a genus-2 irreducible triangulation (V - E + F = -2) with at most 26g - 4 = 48
            // vertices.
            assert_eq!(written.positions, mesh.positions, "{args:?}");
            let used: std::collections::BTreeSet<usize> =
                written.faces.iter().flatten().copied().collect();
            let v = used.len() as i64;
            assert_eq!(v - written.faces.len() as i64 / 2, -2, "{args:?}");
            assert!(v <= 48);
        }
        if args.contains(&"--json") {
            let json = &stderr[stderr.find('{').unwrap()..];
            let figures: serde_json::Value = serde_json::from_str(json).unwrap();
            assert!(figures.is_object(), "{stderr}");
        } else {
            assert!(stderr.contains("<stdout>: "), "{stderr}");
        }
    }
    let out = surftopo()
        .args(["generate", "torus", "--m", "5", "--n", "4", "-o", "-"])
        .args(["--format", "stl.gz"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(parse(&out.stdout, "stl.gz").faces.len(), 40);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("wrote <stdout>: 20 vertices"), "{stderr}");
}

#[test]
fn a_mesh_for_stdout_needs_format_and_is_refused_before_reading() {
    // The input does not exist: refused first, nothing read, nothing written.
    for args in [
        &["convert", "absent.off", "-"][..],
        &["quad", "absent.off", "-o", "-"],
        &["irreducible", "absent.off", "-o", "-"],
        &["generate", "torus", "-o", "-"],
    ] {
        let (code, stdout, stderr) = run(args, b"");
        assert_eq!(code, Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.contains("<stdout>: ") && stderr.contains("needs --format obj, off, ply or stl"),
            "{args:?}: {stderr}"
        );
        assert!(stdout.is_empty());
    }
    let dir = tempfile::tempdir().unwrap();
    let refused = |args: &[&str], message: &str| {
        let mut cmd = surftopo();
        cmd.current_dir(dir.path()).args(args);
        common::refused(&mut cmd, message, &format!("{args:?}"));
    };
    refused(
        &["convert", "absent.off", "x.obj", "--format", "ply"],
        "x.obj: OUTPUT: the name says obj, --format says ply",
    );
    refused(
        &["convert", "absent.off", "-", "--format", "vtk"],
        "expected obj, off, ply or stl",
    );
    refused(
        &["delaunay", "absent.off", "-o", "-"],
        "<stdout>: -o: standard output (`-`) takes a mesh only",
    );
    refused(
        &[
            "generate",
            "flat-torus",
            "--x",
            "2",
            "-o",
            "-",
            "--format",
            "obj",
        ],
        "--format: this generator writes portalgon JSON",
    );
    let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert!(names.is_empty(), "nothing written");
}

#[test]
fn format_names_the_format_of_a_file_without_mesh_extension() {
    let dir = tempfile::tempdir().unwrap();
    let (path, mesh) = original(dir.path());
    let out = dir.path().join("mesh.data");
    surftopo()
        .arg("convert")
        .arg(&path)
        .arg(&out)
        .args(["--format", "off.gz"])
        .assert()
        .success();
    assert_eq!(parse(&std::fs::read(&out).unwrap(), "off.gz"), mesh);
}

#[test]
fn delaunay_isometric_and_intrinsic_flips_read_stdin() {
    let dir = tempfile::tempdir().unwrap();
    let (path, mesh) = original(dir.path());
    let obj = std::fs::read(&path).unwrap();
    let edges = 3 * mesh.faces.len() / 2;
    let (code, stdout, stderr) = run(&["delaunay", "-", "--json"], &obj);
    assert_eq!(code, Some(0), "{stderr}");
    let figures: serde_json::Value = serde_json::from_slice(&stdout).unwrap();
    assert_eq!(figures["edges"], edges, "{figures}");
    // Portalgon JSON on stdin, told by its `{`.
    let json = dir.path().join("d.json");
    surftopo()
        .arg("delaunay")
        .arg(&path)
        .arg("-o")
        .arg(&json)
        .assert()
        .success();
    let (code, stdout, stderr) = run(&["delaunay", "-", "--json"], &std::fs::read(&json).unwrap());
    assert_eq!(code, Some(0), "{stderr}");
    let again: serde_json::Value = serde_json::from_slice(&stdout).unwrap();
    assert_eq!(again["edges"], edges);
    assert_eq!(again["flips"], 0, "already Delaunay");
    let (code, stdout, stderr) = run(&["isometric", "-", json.to_str().unwrap(), "--json"], &obj);
    assert_eq!(code, Some(0), "{stderr}");
    let verdict: serde_json::Value = serde_json::from_slice(&stdout).unwrap();
    assert_eq!(verdict["isometric"], true);
    let (code, _, stderr) = run(&["isometric", "-", "-"], &obj);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("standard input can be read once"),
        "{stderr}"
    );
    let flipped = dir.path().join("f.json");
    let out = surftopo()
        .args([
            "generate",
            "intrinsic-flips",
            "--input",
            "-",
            "--count",
            "20",
            "-o",
        ])
        .arg(&flipped)
        .write_stdin(obj)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let out = surftopo()
        .arg("isometric")
        .arg(&path)
        .arg(&flipped)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "an isometric re-triangulation");
}

#[test]
fn ascii_stl_on_stdin_is_welded_and_stdin_obeys_the_input_limit() {
    let corners = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]];
    let mut stl = String::from("solid tetra\n");
    for face in [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]] {
        stl.push_str("facet normal 0 0 0\nouter loop\n");
        for v in face {
            let [x, y, z] = corners[v];
            stl.push_str(&format!("vertex {x} {y} {z}\n"));
        }
        stl.push_str("endloop\nendfacet\n");
    }
    stl.push_str("endsolid tetra\n");
    let (code, stdout, stderr) = run(&["info", "-", "--json", "--strict"], stl.as_bytes());
    assert_eq!(code, Some(0), "{stderr}");
    let info: serde_json::Value = serde_json::from_slice(&stdout).unwrap();
    assert_eq!(
        (info["vertices"].as_u64(), info["faces"].as_u64()),
        (Some(4), Some(4))
    );
    assert_eq!(info["welded_vertices"], 8);
    let (code, stdout, stderr) = run(
        &[
            "convert",
            "-",
            "-",
            "--format",
            "obj",
            "--max-input-bytes",
            "100",
        ],
        stl.as_bytes(),
    );
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("<stdin>") && stderr.contains("--max-input-bytes"),
        "{stderr}"
    );
    assert!(stdout.is_empty());
}

/// A reader that closes the pipe early (`surftopo ... -o - | head -c 10`), a stdout closed from
/// the start (`>&-`) and a full stdout (`>/dev/full`) are unwritable outputs: exit 2 with a
/// message naming stdout. A full stderr (`2>/dev/full`) loses the messages, never panics.
#[test]
fn closed_and_full_stdout_exit_2_and_a_full_stderr_never_panics() {
    let dir = tempfile::tempdir().unwrap();
    let bin = assert_cmd::cargo::cargo_bin("surftopo");
    // Several megabytes of OBJ: far more than a pipe's buffer.
    let mut child = std::process::Command::new(&bin)
        .args([
            "generate", "torus", "--m", "300", "--n", "300", "-o", "-", "--format", "obj",
        ])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 10];
    child.stdout.take().unwrap().read_exact(&mut first).unwrap();
    let output = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("stdout: not written"), "{stderr}");
    let mesh = generated_genus_surface(dir.path(), "g.ply", 1);
    let shell = |script: &str| {
        std::process::Command::new("sh")
            .arg("-c")
            .arg(script)
            .env("SURFTOPO", &bin)
            .env("MESH", &mesh)
            .output()
            .unwrap()
    };
    for script in [
        r#"exec "$SURFTOPO" info "$MESH" >&-"#,
        r#"exec "$SURFTOPO" info "$MESH" --json >&-"#,
        r#"exec "$SURFTOPO" convert "$MESH" - --format off >&-"#,
        r#"exec "$SURFTOPO" info "$MESH" >/dev/full"#,
    ] {
        let out = shell(script);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{script}: {stderr}");
        assert!(
            stderr.contains("error: stdout: not written"),
            "{script}: {stderr}"
        );
    }
    // stdout to /dev/null is a choice, not a closed stdout.
    let out = shell(r#"exec "$SURFTOPO" info "$MESH" >/dev/null"#);
    assert_eq!(out.status.code(), Some(0));
    for (script, code) in [
        (r#"exec "$SURFTOPO" info /nonexistent/m.obj 2>/dev/full"#, 2),
        (r#"exec "$SURFTOPO" info "$MESH" 2>/dev/full"#, 0),
        (
            r#"exec "$SURFTOPO" convert "$MESH" - --format off >/dev/null 2>/dev/full"#,
            0,
        ),
        (r#"exec "$SURFTOPO" info "$MESH" 2>&-"#, 0),
    ] {
        let out = shell(script);
        assert_eq!(out.status.code(), Some(code), "{script}");
    }
}
