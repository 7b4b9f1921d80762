//! End-to-end tests of the `surftopo` binary: exit codes, JSON keys, malformed input classes.

mod common;

use common::{json_of, read_mtx, surftopo, write};
use serde_json::Value;

const TETRA: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";

/// `surftopo COMMAND INPUT -o OUTPUT ARGS...`'s JSON, which must succeed and have `keys`.
fn command_json(
    command: &str,
    input: &std::path::Path,
    output: &std::path::Path,
    args: &[&str],
    keys: &[&str],
) -> Value {
    json_of(
        surftopo()
            .arg(command)
            .arg(input)
            .arg("-o")
            .arg(output)
            .args(args),
        keys,
    )
}

fn info_json(path: &std::path::Path, extra: &[&str]) -> Value {
    json_of(
        surftopo().arg("info").arg(path).arg("--json").args(extra),
        &[],
    )
}

#[test]
fn info_json_has_the_documented_keys() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(dir.path(), "t.obj", TETRA);
    let v = info_json(&path, &[]);
    for key in [
        "vertices",
        "edges",
        "faces",
        "genus",
        "euler_characteristic",
        "components",
        "closed",
        "orientable",
        "simplicial",
    ] {
        assert!(v.get(key).is_some(), "missing key {key}");
    }
    assert_eq!(v["vertices"], 4);
    assert_eq!(v["edges"], 6);
    assert_eq!(v["faces"], 4);
    assert_eq!(v["genus"], 0);
    assert_eq!(v["euler_characteristic"], 2);
    assert_eq!(v["closed"], true);
}

/// Every malformed-input class: `info --strict` and `convert`-free loading both exit with 2 and
/// a message starting with `error:` that names the file.
#[test]
fn malformed_inputs_exit_with_code_2_and_say_where() {
    let cases: &[(&str, &str, &str)] = &[
        ("empty.obj", "# no vertex, no face\n", "no faces"),
        (
            "range.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n",
            "out of range",
        ),
        (
            "repeat.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\n",
            "repeated",
        ),
        ("duplicate.obj", &format!("{TETRA}f 1 3 2\n"), "duplicate"),
        (
            "nonmanifold_edge.obj",
            &format!("{TETRA}v 1 1 1\nf 1 2 5\n"),
            "non-manifold edge",
        ),
        (
            "nonmanifold_vertex.obj",
            &format!("{TETRA}v 2 0 0\nv 2 1 0\nv 2 0 1\nf 1 6 5\nf 1 5 7\nf 5 6 7\nf 1 7 6\n"),
            "non-manifold vertex",
        ),
        (
            "nan.obj",
            &TETRA.replace("v 1 0 0", "v nan 0 0"),
            "non-finite",
        ),
        (
            "garbage.obj",
            "v 0 zero 0\n",
            "bad.obj".trim_end_matches(".obj"),
        ),
    ];
    // The projective plane (6 vertices, 10 triangles): closed but not orientable.
    let rp2 = "v 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 0\nv 0 1 1\nv 1 0 1\n\
               f 1 2 3\nf 1 3 4\nf 1 4 5\nf 1 5 6\nf 1 6 2\nf 2 3 5\nf 3 4 6\nf 4 5 2\nf 5 6 3\nf 6 2 4\n";
    let dir = tempfile::tempdir().unwrap();
    let all: Vec<(String, String, String)> = cases
        .iter()
        .map(|(n, t, m)| (n.to_string(), t.to_string(), m.to_string()))
        .collect();
    // Surfaces with boundary, non-orientable or in pieces are no problems: `--strict` passes
    // and each piece is classified.
    let surfaces = [
        (
            "boundary.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\n".to_string(),
            vec!["disk"],
        ),
        (
            "disconnected.obj",
            format!(
                "{TETRA}v 5 0 0\nv 6 0 0\nv 5 1 0\nv 5 0 1\nf 5 7 6\nf 5 6 8\nf 6 7 8\nf 5 8 7\n"
            ),
            vec!["sphere", "sphere"],
        ),
        (
            "quad.obj",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n".to_string(),
            vec!["disk"],
        ),
        ("rp2.obj", rp2.to_string(), vec!["projective plane"]),
    ];
    for (name, text, names) in &surfaces {
        let path = write(dir.path(), name, text);
        let v = info_json(&path, &["--strict"]);
        let got: Vec<&str> = v["surfaces"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| s["name"].as_str().unwrap())
            .collect();
        assert_eq!(&got, names, "{name}");
        assert_eq!(v["valid"], true, "{name}");
    }
    for (name, text, message) in &all {
        let path = write(dir.path(), name, text);
        let out = surftopo()
            .arg("info")
            .arg(&path)
            .arg("--strict")
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {stderr}");
        assert!(stderr.starts_with("error:"), "{name}: {stderr}");
        assert!(
            stderr.contains(name.as_str()),
            "{name}: message does not name the file: {stderr}"
        );
        let stdout = String::from_utf8_lossy(&out.stdout);
        let said = format!("{stdout}{stderr}");
        if name != "garbage.obj" {
            assert!(
                said.contains(message.as_str()),
                "{name}: expected '{message}' in: {said}"
            );
        }
    }
}

#[test]
fn a_face_error_names_the_line_of_the_face() {
    let dir = tempfile::tempdir().unwrap();
    // A fin: a fourth face on the edge 1-2 of an open tetrahedron.
    let text = "# comment\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 2 5\n";
    let path = write(dir.path(), "fin.obj", text);
    let out = surftopo().arg("info").arg(&path).output().unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("fin.obj: line 7: non-manifold edge"),
        "{stdout}"
    );
}

#[test]
fn inconsistent_orientation_is_reported_and_fixable() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(
        dir.path(),
        "flipped.obj",
        &TETRA.replace("f 2 3 4", "f 2 4 3"),
    );
    let v = info_json(&path, &["--strict"]);
    assert_eq!(v["valid"], true);
    assert_eq!(v["reoriented_faces"], 1);
    assert_eq!(v["genus"], 0);
}

#[test]
fn usage_errors_exit_with_code_2() {
    surftopo().arg("no-such-command").assert().code(2);
    surftopo().args(["info"]).assert().code(2);
    surftopo()
        .args(["info", "missing-file.obj"])
        .assert()
        .code(2);
    surftopo().args(["info", "file.xyz"]).assert().code(2);
    surftopo()
        .args(["generate", "torus", "--m", "2", "-o", "x.obj"])
        .assert()
        .code(2);
}

/// The modifiers that need a surface mesh are refused, with exit code 2 and no file written, for
/// a generator that makes an intrinsic triangulation.
#[test]
fn surface_modifiers_are_refused_for_intrinsic_generators() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("t.json");
    for modifier in [&["--shuffle-faces"][..], &["--subdivide", "1"]] {
        let assert = surftopo()
            .args(["generate", "flat-torus", "--x", "3", "-o"])
            .arg(&out)
            .args(modifier)
            .assert()
            .code(2);
        let stderr = String::from_utf8_lossy(&assert.get_output().stderr).into_owned();
        assert!(
            stderr.contains("need a surface mesh"),
            "{modifier:?}: {stderr}"
        );
        assert!(!out.exists(), "{modifier:?}");
    }
}

#[test]
fn generate_convert_and_read_back() {
    let dir = tempfile::tempdir().unwrap();
    let obj = dir.path().join("torus.obj");
    surftopo()
        .args(["generate", "torus", "--m", "9", "--n", "5", "-o"])
        .arg(&obj)
        .assert()
        .success();
    for ext in ["off", "ply", "obj.gz", "ply.gz", "stl"] {
        let out = dir.path().join(format!("torus.{ext}"));
        surftopo()
            .arg("convert")
            .arg(&obj)
            .arg(&out)
            .assert()
            .success();
        let v = info_json(&out, &["--strict"]);
        assert_eq!(
            (v["vertices"].as_u64(), v["faces"].as_u64()),
            (Some(45), Some(90))
        );
        assert_eq!(v["genus"], 1);
    }
}

#[test]
fn a_failed_write_leaves_no_file_behind() {
    let dir = tempfile::tempdir().unwrap();
    let obj = write(dir.path(), "t.obj", TETRA);
    let target = dir.path().join("missing").join("out.obj");
    surftopo()
        .arg("convert")
        .arg(&obj)
        .arg(&target)
        .assert()
        .code(2);
    assert!(!target.exists());
    let leftovers: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(leftovers.len(), 1, "{leftovers:?}");
}

/// `demo` exits 0, names every capability (each algorithm of each paper, every output of
/// `delaunay`, both `isometric` verdicts) on a line with a time, and its files check out
/// independently of it.
/// The files in `dir`, recursively, as paths relative to it.
fn files_under(dir: &std::path::Path) -> Vec<String> {
    let mut found = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap().flatten() {
        let path = entry.path();
        if path.is_dir() {
            found.extend(files_under(&path));
        } else {
            found.push(path.display().to_string());
        }
    }
    found
}

/// A demo step that fails after others wrote their files (here a folder stands where the
/// flipped triangulation goes) leaves none of the run's files, and keeps what was there before.
#[test]
fn a_failing_demo_step_removes_every_file_of_the_run() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("demo");
    std::fs::create_dir_all(out.join("delaunay-flip.json")).unwrap();
    std::fs::write(out.join("mine.txt"), "kept").unwrap();
    let assert = surftopo()
        .arg("demo")
        .arg("--out")
        .arg(&out)
        .assert()
        .code(2);
    let stderr = String::from_utf8_lossy(&assert.get_output().stderr).to_string();
    assert!(stderr.contains("delaunay-flip.json"), "{stderr}");
    assert_eq!(
        files_under(&out),
        [out.join("mine.txt").display().to_string()]
    );
    assert!(out.join("delaunay-flip.json").is_dir());
}

/// `demo --out` on a full disk (a 256 KiB tmpfs, mounted when the tests run as root; skipped
/// with a note otherwise): exit 2 and no file left, the folder it created removed.
#[test]
fn demo_on_a_full_disk_leaves_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let mount = |args: &[&str]| {
        std::process::Command::new(args[0])
            .args(&args[1..])
            .stderr(std::process::Stdio::null())
            .status()
            .is_ok_and(|s| s.success())
    };
    let point = dir.path().display().to_string();
    if !mount(&["mount", "-t", "tmpfs", "-o", "size=256k", "tmpfs", &point]) {
        eprintln!(
            "note: no tmpfs could be mounted (not root?): the full-disk demo test is skipped"
        );
        return;
    }
    let out = dir.path().join("demo");
    let result = surftopo()
        .arg("demo")
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let left = files_under(dir.path());
    let out_exists = out.exists();
    assert!(mount(&["umount", &point]), "umount {point}");
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("No space left on device"), "{stderr}");
    assert!(left.is_empty(), "left behind: {left:?}");
    assert!(!out_exists);
}

#[test]
fn demo_shows_every_capability() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("demo");
    let assert = surftopo()
        .arg("demo")
        .arg("--out")
        .arg(&out)
        .assert()
        .success();
    let stdout = String::from_utf8_lossy(&assert.get_output().stdout).to_string();
    let stderr = String::from_utf8_lossy(&assert.get_output().stderr).to_string();
    assert!(stdout.contains("surftopo demo"), "{stdout}");
    // The commands' notes would break the lines: every line says what they would.
    assert!(stderr.is_empty(), "stderr: {stderr}");
    for step in [
        "generate genus",
        "klein-bottle + irreducible",
        "torus --cut-holes 2 + irreducible",
        "delaunay (torus with 2 holes)",
        "quad (torus with 2 holes)",
        "delaunay --method dubois --exact (needles)",
        "generate flat-torus",
        "info ",
        "info (a broken mesh)",
        "convert input.obj input.ply",
        "convert input.obj input.off.gz",
        "irreducible --algorithm rs ",
        "irreducible --algorithm schipper ",
        "irreducible --algorithm brute-force ",
        "quad --algorithm sg ",
        "quad --algorithm ps ",
        "quad --algorithm ds ",
        "quad --algorithm lrs ",
        "quad --algorithm ks ",
        "quad --objective quality ",
        "quad --objective quality-fast ",
        "delaunay --method flip ",
        "delaunay (polygons, a loose vertex)",
        "delaunay --method voronoi ",
        "delaunay --method dubois --exact ",
        "delaunay --method auto ",
        "isometric --method dubois --exact",
        "isometric --method flip",
        "census torus",
        "isomorphic input.obj input.ply",
    ] {
        let line = stdout
            .lines()
            .find(|l| l.trim_start().starts_with(step))
            .unwrap_or_else(|| panic!("no line for '{step}' in:\n{stdout}"));
        assert!(
            ["µs", "ms", " s)", " s ("]
                .iter()
                .any(|unit| line.contains(unit)),
            "no time on: {line}"
        );
    }
    for words in [
        "--laplacian",
        "--mass",
        "--tessellation",
        "--reduced",
        "(flip)",
        "(voronoi)",
        "(dubois)",
        "T_x, T_{x+1}: isometric",
        "T_x, T_{x+1/3}: not isometric",
        "non finite coordinates",
        "zero area faces",
        "7 polygons cut into 16 triangles; --laplacian: 11 rows, row 0 empty",
        "Klein bottle, 272 vertices",
        "genus 1 with 2 boundary loops",
        "natural boundary condition",
        "a pillowcase sheared by s = 1000, 4 cone points",
        "21 irreducible triangulations",
    ] {
        assert!(stdout.contains(words), "'{words}' missing in:\n{stdout}");
    }
    demo_outputs_check_out(&out);
    let v = info_json(&out.join("input.obj"), &["--strict"]);
    assert_eq!(v["genus"], 2);
    // The verdicts, again by the command itself.
    let verdict = |a: &str, b: &str, extra: &[&str]| {
        surftopo()
            .arg("isometric")
            .arg(out.join(a))
            .arg(out.join(b))
            .args(extra)
            .output()
            .unwrap()
            .status
            .code()
    };
    assert_eq!(verdict("input.obj", "delaunay-flip.json", &[]), Some(0));
    let exact = ["--method", "dubois", "--exact"];
    assert_eq!(verdict("tx.json", "tx-plus-1.json", &exact), Some(0));
    assert_eq!(verdict("tx.json", "tx-plus-third.json", &exact), Some(1));
    for file in [
        "laplacian.mtx",
        "mass.mtx",
        "tessellation-flip.json",
        "tessellation-voronoi.json",
        "dx-tessellation.json",
        "dx-reduced.json",
        "dx-laplacian.mtx",
        "input.ply",
        "input.off.gz",
    ] {
        assert!(out.join(file).is_file(), "{file}");
    }
    for algorithm in ["rs", "schipper", "brute-force"] {
        let v = info_json(&out.join(format!("irreducible-{algorithm}.obj")), &[]);
        assert_eq!(v["genus"], 2, "{algorithm}");
    }
    for quads in ["sg", "ps", "ds", "lrs", "ks", "quality", "quality-fast"] {
        let v = info_json(&out.join(format!("quads-{quads}.obj")), &["--strict"]);
        assert_eq!(v["genus"], 2, "{quads}");
        assert_eq!(v["simplicial"], false, "{quads}: not quads");
    }
}

/// The outputs of the demo's steps beyond closed orientable surfaces, checked by `info` and by
/// computations written here: the irreducible Klein bottle and open torus, the open torus's
/// Laplacian and mass (symmetric, rows summing to zero, the mass its area), its quads, the
/// needle's Delaunay tessellation (two unit squares), the census file (21 triangulations).
fn demo_outputs_check_out(out: &std::path::Path) {
    let v = info_json(&out.join("klein-bottle-irreducible.obj"), &["--strict"]);
    assert_eq!(v["surfaces"][0]["name"], "Klein bottle");
    let v = info_json(&out.join("open-torus-irreducible.obj"), &["--strict"]);
    assert_eq!(v["surfaces"][0]["name"], "genus 1 with 2 boundary loops");
    let open = info_json(&out.join("open-torus.obj"), &["--strict"]);
    let n = open["vertices"].as_u64().unwrap() as usize;
    let laplacian = read_mtx(&out.join("open-laplacian.mtx"));
    assert_eq!(laplacian.len(), n);
    for (i, row) in laplacian.iter().enumerate() {
        let sum: f64 = row.iter().sum();
        assert!(
            sum.abs() <= 1e-9 * row[i].abs().max(1.0),
            "row {i} sums to {sum}"
        );
    }
    let mass = read_mtx(&out.join("open-mass.mtx"));
    let soup = surftopo_io::read_path(&out.join("open-torus.obj")).unwrap();
    let area: f64 = soup
        .faces()
        .map(|f| {
            let [a, b, c] = [f[0], f[1], f[2]].map(|v| soup.positions[v as usize]);
            let (u, w) = (sub(b, a), sub(c, a));
            let cross = [
                u[1] * w[2] - u[2] * w[1],
                u[2] * w[0] - u[0] * w[2],
                u[0] * w[1] - u[1] * w[0],
            ];
            0.5 * cross.iter().map(|x| x * x).sum::<f64>().sqrt()
        })
        .sum();
    let total: f64 = mass.iter().flatten().sum();
    assert!((total - area).abs() <= 1e-9 * area, "{total} vs {area}");
    let quads = info_json(&out.join("open-quads.obj"), &["--strict"]);
    assert_eq!(quads["simplicial"], false);
    assert_eq!(
        quads["surfaces"][0]["name"],
        "genus 1 with 2 boundary loops"
    );
    assert_eq!(quads["vertices"], open["vertices"]);
    // The needle's Delaunay tessellation: two unit squares (corners exact in the file, checked
    // here in double precision).
    let text = std::fs::read_to_string(out.join("needle-tessellation.json")).unwrap();
    let doc: Value = serde_json::from_str(&text).unwrap();
    let polygons = doc["polygons"].as_array().unwrap();
    assert_eq!(polygons.len(), 2, "{text}");
    for polygon in polygons {
        let corners = corners(polygon);
        assert_eq!(corners.len(), 4, "{text}");
        for k in 0..4 {
            let [p, q, r] = [0, 1, 2].map(|j| corners[(k + j) % 4]);
            let (a, b) = ([q[0] - p[0], q[1] - p[1]], [r[0] - q[0], r[1] - q[1]]);
            assert!(
                ((a[0] * a[0] + a[1] * a[1]).sqrt() - 1.0).abs() < 1e-9,
                "{text}"
            );
            assert!(
                (a[0] * b[0] + a[1] * b[1]).abs() < 1e-9,
                "not a right angle: {text}"
            );
        }
    }
    // The census: 21 triangulations, each a torus (χ = 0), in Lutz's format.
    let census = std::fs::read_to_string(out.join("census-torus.txt")).unwrap();
    let lines: Vec<&str> = census.lines().filter(|l| !l.trim().is_empty()).collect();
    assert_eq!(lines.len(), 21);
    for line in lines {
        let triangles: Vec<[u32; 3]> = serde_json::from_str(line).unwrap();
        let mut edges = std::collections::BTreeSet::new();
        let mut vertices = std::collections::BTreeSet::new();
        for t in &triangles {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                edges.insert((a.min(b), a.max(b)));
                vertices.insert(a);
            }
        }
        let chi = vertices.len() as i64 - edges.len() as i64 + triangles.len() as i64;
        assert_eq!(chi, 0, "{line}");
        assert!(triangles.len() == 2 * edges.len() / 3, "{line}: not closed");
    }
}

/// `a - b`.
fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// The corners of a portalgon JSON polygon in double precision (a coordinate is a number, or
/// a string `p/q` or `p`).
fn corners(polygon: &Value) -> Vec<[f64; 2]> {
    let number = |v: &Value| -> f64 {
        let text = v.as_str().map_or_else(|| v.to_string(), str::to_string);
        match text.split_once('/') {
            Some((p, q)) => p.parse::<f64>().unwrap() / q.parse::<f64>().unwrap(),
            None => text.parse().unwrap(),
        }
    };
    polygon["corners"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| [number(&c[0]), number(&c[1])])
        .collect()
}

#[test]
fn info_reads_polygon_meshes() {
    let dir = tempfile::tempdir().unwrap();
    let cube = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
                f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    let path = write(dir.path(), "cube.obj", cube);
    let v = info_json(&path, &["--strict"]);
    assert_eq!(
        (
            v["vertices"].as_u64(),
            v["edges"].as_u64(),
            v["faces"].as_u64()
        ),
        (Some(8), Some(12), Some(6))
    );
    assert_eq!(v["genus"], 0);
    assert_eq!(v["simplicial"], false);
    let open = write(
        dir.path(),
        "open_cube.obj",
        &cube.replace("f 4 1 5 8\n", ""),
    );
    // An open cube: a disk of 5 quads, its faces counted as polygons.
    let v = info_json(&open, &[]);
    assert_eq!(v["surfaces"][0]["name"], "disk");
    assert_eq!(v["surfaces"][0]["faces"], 5);
    assert_eq!(
        (v["faces"].as_u64(), v["boundary_loops"].as_u64()),
        (Some(5), Some(1))
    );
}

#[test]
fn every_generator_gives_a_valid_surface_of_its_genus() {
    let dir = tempfile::tempdir().unwrap();
    let cases: &[(&[&str], i64)] = &[
        (&["tetrahedron"], 0),
        (&["icosphere", "--subdivisions", "2"], 0),
        (&["icosphere", "--subdivisions", "2", "--shuffle-faces"], 0),
        (
            &[
                "torus", "--m", "8", "--n", "6", "--flips", "40", "--seed", "3",
            ],
            1,
        ),
        (
            &["genus", "--genus", "3", "--size", "1", "--subdivide", "1"],
            3,
        ),
        (
            &[
                "cavity-box",
                "--cavities",
                "8",
                "--holes",
                "2",
                "--triangles",
                "5000",
                "--splits",
                "30",
            ],
            2,
        ),
    ];
    for (k, (args, genus)) in cases.iter().enumerate() {
        let out = dir.path().join(format!("g{k}.off"));
        surftopo()
            .arg("generate")
            .args(*args)
            .arg("-o")
            .arg(&out)
            .assert()
            .success();
        let v = info_json(&out, &["--strict"]);
        assert_eq!(v["genus"], *genus, "{args:?}");
        assert_eq!(v["simplicial"], true, "{args:?}");
    }
    // Same seed, same file; another seed, another file.
    let run = |seed: &str, name: &str| {
        let out = dir.path().join(name);
        surftopo()
            .args(["generate", "torus", "--flips", "50", "--seed", seed, "-o"])
            .arg(&out)
            .assert()
            .success();
        std::fs::read(out).unwrap()
    };
    assert_eq!(run("5", "a.obj"), run("5", "b.obj"));
    assert_ne!(run("5", "c.obj"), run("6", "d.obj"));
}

#[test]
fn delaunay_writes_its_outputs_and_isometric_answers() {
    let dir = tempfile::tempdir().unwrap();
    let d = |name: &str| dir.path().join(name);
    surftopo()
        .args(["generate", "flat-torus", "--x", "12", "-o"])
        .arg(d("t.json"))
        .assert()
        .success();
    let v = json_of(
        surftopo()
            .arg("delaunay")
            .arg(d("t.json"))
            .arg("-o")
            .arg(d("td.json"))
            .arg("--tessellation")
            .arg(d("tt.json"))
            .arg("--laplacian")
            .arg(d("L.mtx"))
            .arg("--mass")
            .arg(d("M.mtx"))
            .arg("--json"),
        &[
            "vertices",
            "edges",
            "faces",
            "flips",
            "non_delaunay_edges",
            "seconds",
        ],
    );
    assert_eq!(v["flips"], 11);
    assert_eq!(v["non_delaunay_edges"], 0);
    for f in ["td.json", "tt.json", "L.mtx", "M.mtx"] {
        assert!(d(f).is_file(), "{f} not written");
    }
    assert!(
        std::fs::read_to_string(d("L.mtx"))
            .unwrap()
            .starts_with("%%MatrixMarket")
    );
    // The flipped torus is isometric to the original; another torus is not.
    surftopo()
        .arg("isometric")
        .arg(d("t.json"))
        .arg(d("td.json"))
        .assert()
        .code(0);
    surftopo()
        .args(["generate", "flat-torus", "--x", "12.5", "-o"])
        .arg(d("other.json"))
        .assert()
        .success();
    let out = surftopo()
        .arg("isometric")
        .arg(d("t.json"))
        .arg(d("other.json"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), "not isometric");
    // Exceeding --max-flips is a clear error; nothing is written.
    let out = surftopo()
        .arg("delaunay")
        .arg(d("t.json"))
        .args(["--max-flips", "2", "-o"])
        .arg(d("never.json"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("stopped after 2 flips"));
    assert!(!d("never.json").exists());
    // A degenerate triangle (zero area) is a typed error; mollification repairs it.
    let flat = write(
        dir.path(),
        "flat.obj",
        &TETRA.replace("v 0 0 1", "v 0.5 0.5 0"),
    );
    let out = surftopo()
        .arg("delaunay")
        .arg(&flat)
        .arg("-o")
        .arg(d("f.json"))
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    surftopo()
        .arg("delaunay")
        .arg(&flat)
        .args(["--mollify", "1e-4", "-o"])
        .arg(d("f.json"))
        .assert()
        .success();
    // A broken portalgon file names itself.
    let bad = write(
        dir.path(),
        "bad.json",
        "{\"format\": \"surftopo-portalgon\"",
    );
    let out = surftopo()
        .arg("delaunay")
        .arg(&bad)
        .arg("-o")
        .arg(d("b.json"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("bad.json"));
}

/// Independent irreducibility check of a triangle soup: every edge's endpoints have more than the
/// two common neighbours of its triangles (so contracting it would break the surface), unless the
/// surface is the tetrahedron.
fn is_irreducible_soup(triangles: &[[u32; 3]]) -> bool {
    use std::collections::{BTreeMap, BTreeSet};
    let mut neighbours: BTreeMap<u32, BTreeSet<u32>> = BTreeMap::new();
    for t in triangles {
        for i in 0..3 {
            neighbours.entry(t[i]).or_default().insert(t[(i + 1) % 3]);
            neighbours.entry(t[(i + 1) % 3]).or_default().insert(t[i]);
        }
    }
    if neighbours.len() == 4 {
        return true;
    }
    neighbours.iter().all(|(_, na)| {
        na.iter()
            .all(|b| na.intersection(&neighbours[b]).count() > 2)
    })
}

#[test]
fn irreducible_outputs_an_irreducible_triangulation_of_the_same_genus() {
    let dir = tempfile::tempdir().unwrap();
    let input = common::generated_genus_surface(dir.path(), "g3.off", 3);
    for algorithm in ["rs", "schipper", "brute-force"] {
        let output = dir.path().join(format!("irr-{algorithm}.obj"));
        let v = command_json(
            "irreducible",
            &input,
            &output,
            &["--algorithm", algorithm, "--seed", "9", "--json"],
            &[
                "algorithm",
                "input",
                "output",
                "link_tests",
                "edges_tested_more_than_once",
                "contractions",
                "seconds",
            ],
        );
        assert_eq!(v["algorithm"], algorithm);
        assert_eq!(v["input"]["genus"], 3);
        assert_eq!(v["output"]["genus"], 3);
        if algorithm == "rs" {
            assert_eq!(v["edges_tested_more_than_once"], 0);
        }
        let soup = surftopo_io::read_path(&output).unwrap();
        let triangles = soup.triangles().unwrap();
        assert!(
            is_irreducible_soup(&triangles),
            "{algorithm}: output is not irreducible"
        );
        // Surviving vertices keep their positions, so collinear corners of the brick can make
        // zero-area faces: every other problem class must be empty.
        let info = info_json(&output, &[]);
        assert_eq!(info["problems_total"], info["zero_area_faces"], "{info}");
        assert_eq!(info["genus"], 3);
        assert_eq!(info["vertices"], v["output"]["vertices"]);
        assert!(info["vertices"].as_i64().unwrap() <= 26 * 3 - 4);
    }
}

#[test]
fn irreducible_cuts_polygons_and_refuses_input_that_is_not_a_surface() {
    let dir = tempfile::tempdir().unwrap();
    // A cube of quads: cut into 12 triangles (a note says so), reduced to a tetrahedron on
    // four of the cube's corners, written on the cube's eight vertices.
    let cube_text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    let quad = write(dir.path(), "cube.obj", cube_text);
    let out = surftopo()
        .arg("irreducible")
        .arg(&quad)
        .arg("-o")
        .arg(dir.path().join("x.obj"))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains("6 polygons of 4 to 4 sides cut into 12 triangles"),
        "{stderr}"
    );
    let written = std::fs::read_to_string(dir.path().join("x.obj")).unwrap();
    let v_lines = |t: &str| -> Vec<String> {
        t.lines()
            .filter(|l| l.starts_with("v "))
            .map(str::to_owned)
            .collect()
    };
    assert_eq!(v_lines(&written), v_lines(cube_text));
    let v = info_json(&dir.path().join("x.obj"), &["--strict"]);
    assert_eq!(
        (v["vertices"].as_u64(), v["faces"].as_u64()),
        (Some(4), Some(4))
    );
    assert_eq!(v["genus"], 0);
    let fin = write(
        dir.path(),
        "fin.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 2 5\n",
    );
    let out = surftopo()
        .arg("irreducible")
        .arg(&fin)
        .arg("-o")
        .arg(dir.path().join("y.obj"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("line 6: non-manifold edge (0, 1)"));
    assert!(!dir.path().join("y.obj").exists());
}

#[test]
fn quad_outputs_a_closed_quad_mesh_of_input_triangle_pairs() {
    use std::collections::HashSet;
    let dir = tempfile::tempdir().unwrap();
    let input = common::generated_genus_surface(dir.path(), "g2.obj", 2);
    let soup = surftopo_io::read_path(&input).unwrap();
    // Input triangles as rotation-invariant oriented keys.
    let key = |t: [u32; 3]| {
        let r = (0..3).min_by_key(|&i| t[i]).unwrap();
        [t[r], t[(r + 1) % 3], t[(r + 2) % 3]]
    };
    let triangles: HashSet<[u32; 3]> = soup.triangles().unwrap().into_iter().map(key).collect();
    for algorithm in ["sg", "ps", "lrs", "ds", "ks"] {
        let output = dir.path().join(format!("q-{algorithm}.obj"));
        command_json(
            "quad",
            &input,
            &output,
            &["--algorithm", algorithm, "--json"],
            &[
                "algorithm",
                "faces",
                "initial_pairing_seconds",
                "paired_percent",
                "unpaired",
                "augmentation_seconds",
                "total_seconds",
                "flipped_edges",
                "file_order",
                "subdivision_levels",
            ],
        );
        let quads = surftopo_io::read_path(&output).unwrap();
        assert_eq!(
            quads.positions, soup.positions,
            "{algorithm}: vertex list changed"
        );
        let polygons: Vec<Vec<u32>> = quads.faces().map(<[u32]>::to_vec).collect();
        assert!(
            polygons.iter().all(|p| p.len() == 4),
            "{algorithm}: not all quads"
        );
        assert_eq!(2 * polygons.len(), triangles.len());
        let chi = surftopo_testkit::check_closed_oriented_manifold(&polygons)
            .unwrap_or_else(|e| panic!("{algorithm}: {e}"));
        assert_eq!(chi, -2, "{algorithm}: genus changed");
        let used: HashSet<u32> = polygons.iter().flatten().copied().collect();
        assert_eq!(
            used.len(),
            soup.positions.len(),
            "{algorithm}: a vertex is unused"
        );
        if algorithm != "lrs" {
            // Each quad [a, d, b, c] is the input triangles (a, b, c) and (b, a, d) joined along a-b.
            let mut covered = HashSet::new();
            for q in &polygons {
                let halves = [[q[0], q[2], q[3]], [q[2], q[0], q[1]]].map(key);
                let other = [[q[1], q[3], q[0]], [q[3], q[1], q[2]]].map(key);
                let pair = if halves.iter().all(|t| triangles.contains(t)) {
                    halves
                } else {
                    other
                };
                for t in pair {
                    assert!(
                        triangles.contains(&t),
                        "{algorithm}: quad {q:?} is not two input triangles"
                    );
                    assert!(
                        covered.insert(t),
                        "{algorithm}: triangle {t:?} in two quads"
                    );
                }
            }
        }
    }
}

/// `file_order` and `subdivision_levels` in `quad --json`: a generated torus is written quad by
/// quad, so KS takes it as it is; subdivided twice, KS lifts the torus's pairing through two
/// levels; shuffled, neither; the other algorithms report neither. The summary line without
/// `--json` says the same in words.
#[test]
fn quad_json_says_whether_the_file_order_or_a_subdivision_was_taken() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (&[][..], "ks", true, 0),
        (&["--subdivide", "2"][..], "ks", false, 2),
        (&["--shuffle-faces"][..], "ks", false, 0),
        (&["--subdivide", "2"][..], "sg", false, 0),
    ];
    for (k, (extra, algorithm, file_order, levels)) in cases.into_iter().enumerate() {
        let input = dir.path().join(format!("t{k}.obj"));
        surftopo()
            .args(["generate", "torus", "--m", "12", "--n", "8", "-o"])
            .arg(&input)
            .args(extra)
            .assert()
            .success();
        let output = dir.path().join(format!("q{k}.obj"));
        let v = command_json(
            "quad",
            &input,
            &output,
            &["--algorithm", algorithm, "--json"],
            &["file_order", "subdivision_levels"],
        );
        assert_eq!(
            v["subdivision_levels"], levels,
            "{algorithm} {extra:?}: {v}"
        );
        assert_eq!(v["file_order"], file_order, "{algorithm} {extra:?}: {v}");
        // Without --json, the summary line says it in words.
        let out = surftopo()
            .args(["quad", "--algorithm", algorithm, "-o"])
            .arg(&output)
            .arg(&input)
            .output()
            .unwrap();
        assert!(out.status.success());
        let line = String::from_utf8(out.stdout).unwrap();
        let said = [
            line.contains("the file's own quads"),
            line.contains(&format!("lifted through {levels} levels")),
        ];
        assert_eq!(
            said,
            [file_order, levels > 0],
            "{algorithm} {extra:?}: {line}"
        );
    }
}

#[test]
fn delaunay_by_the_voronoi_wave_in_both_arithmetics() {
    let dir = tempfile::tempdir().unwrap();
    let d = |name: &str| dir.path().join(name);
    // T_x for a fractional x, written by exact corners.
    surftopo()
        .args(["generate", "flat-torus", "--x", "1001/3", "-o"])
        .arg(d("t.json"))
        .assert()
        .success();
    assert!(
        std::fs::read_to_string(d("t.json"))
            .unwrap()
            .contains("\"1001/3\"")
    );
    for exact in [false, true] {
        let mut cmd = surftopo();
        cmd.arg("delaunay")
            .arg(d("t.json"))
            .args(["--method", "voronoi", "-o"])
            .arg(d("vd.json"))
            .arg("--tessellation")
            .arg(d("vt.json"))
            .arg("--laplacian")
            .arg(d("VL.mtx"))
            .arg("--mass")
            .arg(d("VM.mtx"))
            .arg("--json");
        if exact {
            cmd.arg("--exact");
        }
        let v = json_of(
            &mut cmd,
            &[
                "method",
                "arithmetic",
                "wave_events",
                "max_constellation",
                "faces",
            ],
        );
        assert_eq!(v["method"], "voronoi");
        assert_eq!(v["arithmetic"], if exact { "exact" } else { "f64" });
        assert_eq!(v["faces"], 2);
        assert!(v["max_constellation"].as_u64().unwrap() > 300);
        for f in ["vd.json", "vt.json", "VL.mtx", "VM.mtx"] {
            assert!(d(f).is_file(), "{f} not written");
        }
        // D_x: two triangles congruent to (0,0), (1,0), (2/3, 2); exactly so with --exact.
        let tess = std::fs::read_to_string(d("vt.json")).unwrap();
        if exact {
            assert!(tess.contains("/3\""), "{tess}");
        }
        // The voronoi triangulation is isometric to the input, by both methods.
        for method in ["flip", "voronoi"] {
            surftopo()
                .arg("isometric")
                .arg(d("t.json"))
                .arg(d("vd.json"))
                .args(["--method", method])
                .assert()
                .code(0);
        }
    }
    surftopo()
        .arg("isometric")
        .arg(d("t.json"))
        .arg(d("vd.json"))
        .args(["--method", "voronoi", "--exact"])
        .assert()
        .code(0);
    // --exact is refused for meshes, lengths and the flip method (exit 2, saying why).
    surftopo()
        .args(["generate", "tetrahedron", "-o"])
        .arg(d("tet.obj"))
        .assert()
        .success();
    let refused = |args: &[&str], input: &std::path::Path, why: &str| {
        let out = surftopo()
            .arg("delaunay")
            .arg(input)
            .arg("-o")
            .arg(d("x.json"))
            .args(args)
            .assert()
            .code(2);
        let stderr = String::from_utf8_lossy(&out.get_output().stderr).into_owned();
        assert!(stderr.contains(why), "{stderr}");
    };
    refused(
        &["--method", "voronoi", "--exact"],
        &d("tet.obj"),
        "exact corners",
    );
    refused(
        &["--method", "flip", "--exact"],
        &d("t.json"),
        "--method voronoi",
    );
    std::fs::write(
        d("lengths.json"),
        r#"{"polygons": [{"lengths": [1, 1, 1]}, {"lengths": [1, 1, 1]}],
            "matching": [[[0, 0], [1, 0]], [[0, 1], [1, 2]], [[0, 2], [1, 1]]]}"#,
    )
    .unwrap();
    refused(
        &["--method", "voronoi", "--exact"],
        &d("lengths.json"),
        "lengths",
    );
    // A mesh by the wave in f64, and by Dubois (the mesh kept as Proposition 2's output; with
    // --faithful, Section 8's caps and ALGORITHM): the same Laplacian as the flip route's.
    for (method, out) in [
        (&["--method", "flip"][..], "FL.mtx"),
        (&["--method", "voronoi"], "WL.mtx"),
        (&["--method", "dubois"], "DL.mtx"),
        (&["--method", "dubois", "--faithful"], "DFL.mtx"),
    ] {
        surftopo()
            .arg("delaunay")
            .arg(d("tet.obj"))
            .arg("-o")
            .arg(d("tet.json"))
            .args(method)
            .arg("--laplacian")
            .arg(d(out))
            .assert()
            .success();
    }
    // Which route ran: no outer iteration on the mesh's own metric, some with --faithful.
    for (faithful, mesh_metric) in [(false, true), (true, false)] {
        let mut cmd = surftopo();
        cmd.arg("delaunay")
            .arg(d("tet.obj"))
            .args(["--method", "dubois", "--json"]);
        if faithful {
            cmd.arg("--faithful");
        }
        let v = json_of(&mut cmd, &["outer_iterations", "mesh_metric"]);
        assert_eq!(v["mesh_metric"], mesh_metric);
        assert_eq!(v["outer_iterations"].as_u64().unwrap() > 0, faithful);
    }
    let entries = |f: &str| -> Vec<(usize, usize, f64)> {
        std::fs::read_to_string(d(f))
            .unwrap()
            .lines()
            .filter(|l| !l.starts_with('%'))
            .skip(1)
            .map(|l| {
                let w: Vec<&str> = l.split_whitespace().collect();
                (
                    w[0].parse().unwrap(),
                    w[1].parse().unwrap(),
                    w[2].parse().unwrap(),
                )
            })
            .collect()
    };
    for other in ["WL.mtx", "DL.mtx", "DFL.mtx"] {
        let (a, b) = (entries("FL.mtx"), entries(other));
        assert_eq!(a.len(), b.len(), "{other}");
        for (x, y) in a.iter().zip(&b) {
            assert_eq!((x.0, x.1), (y.0, y.1), "{other}");
            assert!(
                (x.2 - y.2).abs() <= 1e-9 * x.2.abs().max(1.0),
                "{other}: {x:?} vs {y:?}"
            );
        }
    }
}

#[test]
fn delaunay_by_dubois_on_a_flat_torus_and_on_cone_points() {
    let dir = tempfile::tempdir().unwrap();
    let d = |name: &str| dir.path().join(name);
    // T_x for x = 10⁹ by exact corners, written here: `generate flat-torus` refuses x this large
    // (it checks the double-precision lengths' triangulation first).
    std::fs::write(
        d("t.json"),
        r#"{"format":"surftopo-portalgon","version":1,"polygons":[
            {"corners":[["0","0"],["1","0"],["1000000000","2"]]},
            {"corners":[["1","0"],["1000000001","2"],["1000000000","2"]]}],
            "matching":[[[0,0],[1,1]],[[0,1],[1,2]],[[0,2],[1,0]]]}"#,
    )
    .unwrap();
    // In f64, a T_x doubles can hold; at x = 1001 the reduction's rounding (about 4e-8 of the
    // lengths) leaves the rectangle's diagonal failing the f64 test: exit 4, nothing written,
    // the message naming --exact (success means 0 non-Delaunay edges).
    for x in ["301", "1001"] {
        surftopo()
            .args(["generate", "flat-torus", "--x", x, "-o"])
            .arg(d(&format!("t{x}.json")))
            .assert()
            .success();
    }
    let refused = surftopo()
        .arg("delaunay")
        .arg(d("t1001.json"))
        .arg("-o")
        .arg(d("d1001.json"))
        .args(["--method", "dubois"])
        .output()
        .unwrap();
    let message = String::from_utf8_lossy(&refused.stderr);
    assert_eq!(refused.status.code(), Some(4), "{message}");
    assert!(
        message.contains("non-Delaunay") && message.contains("--exact"),
        "{message}"
    );
    assert!(!d("d1001.json").exists());
    for (input, exact) in [("t.json", true), ("t301.json", false)] {
        let mut cmd = surftopo();
        cmd.arg("delaunay")
            .arg(d(input))
            .args(["-o"])
            .arg(d("d.json"))
            .args(["--method", "dubois", "--json", "--tessellation"])
            .arg(d("tt.json"))
            .arg("--laplacian")
            .arg(d("L.mtx"))
            .arg("--mass")
            .arg(d("M.mtx"));
        if exact {
            cmd.arg("--exact");
        }
        // The keys, in the order of issue 22's list (a struct, not a map sorted by name).
        let order = [
            "method",
            "outer_iterations",
            "inner_passes",
            "inner_passes_total",
            "inner_passes_bound",
            "tubes_replaced",
            "peak_active_vertices",
            "triangles_after_reduction",
            "wave_events",
            "max_constellation",
            "arithmetic",
        ];
        let v = json_of(&mut cmd, &order);
        let text = String::from_utf8(cmd.output().unwrap().stdout).unwrap();
        let at = |k: &str| text.find(&format!("\"{k}\"")).unwrap();
        assert!(order.windows(2).all(|w| at(w[0]) < at(w[1])), "{text}");
        assert_eq!(v["method"], "dubois");
        assert_eq!(v["arithmetic"], if exact { "exact" } else { "f64" });
        let n = v["outer_iterations"].as_u64().unwrap();
        assert_eq!(v["inner_passes_bound"].as_u64().unwrap(), 350 * n);
        let per_outer: Vec<u64> = v["inner_passes"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| p.as_u64().unwrap())
            .collect();
        assert!(per_outer.len() as u64 <= n && per_outer.iter().all(|&p| (1..=350).contains(&p)));
        assert_eq!(
            per_outer.iter().sum::<u64>(),
            v["inner_passes_total"].as_u64().unwrap()
        );
        assert!(v["inner_passes_total"].as_u64().unwrap() <= 350 * n);
        assert!(v["tubes_replaced"]["thin"].is_u64() && v["tubes_replaced"]["thick"].is_u64());
        for f in ["d.json", "tt.json", "L.mtx", "M.mtx"] {
            assert!(d(f).is_file(), "{f} not written");
        }
        // D_x for integer x: one rectangle.
        let tess: Value =
            serde_json::from_str(&std::fs::read_to_string(d("tt.json")).unwrap()).unwrap();
        let polygons = tess["polygons"].as_array().unwrap();
        assert_eq!(polygons.len(), 1, "{tess}");
        let sides = polygons[0]["corners"]
            .as_array()
            .or(polygons[0]["lengths"].as_array())
            .unwrap()
            .len();
        assert_eq!(sides, 4, "{tess}");
        // In f64 the output triangulation is the input torus, by the flip method's isometry test
        // (for 10⁹ exactly, the rectangle above is D_x; the exact wave's isometry test is slow).
        if !exact {
            surftopo()
                .arg("isometric")
                .arg(d(input))
                .arg(d("d.json"))
                .assert()
                .code(0);
        }
    }
    // Cone points in double precision: the tetrahedron mesh's dubois Laplacian is compared with
    // the flip route's in `delaunay_by_the_voronoi_wave_in_both_arithmetics`; here the mesh serves
    // `isometric`, which takes flat surfaces only with dubois.
    surftopo()
        .args(["generate", "tetrahedron", "-o"])
        .arg(d("tet.obj"))
        .assert()
        .success();
    // isometric --method dubois takes flat surfaces only: a cone point is refused.
    surftopo()
        .arg("isometric")
        .arg(d("tet.obj"))
        .arg(d("tet.obj"))
        .args(["--method", "dubois"])
        .assert()
        .code(2);
}

/// `T_x = R²/⟨(1, 0), (x, 2)⟩` by exact corners (`x` a rational written as text), as portalgon
/// JSON: triangles `0, u, v` and `u, u + v, v`.
fn t_x_json(x: &str, plus_one: &str) -> String {
    format!(
        r#"{{"format":"surftopo-portalgon","version":1,"polygons":[
            {{"corners":[["0","0"],["1","0"],["{x}","2"]]}},
            {{"corners":[["1","0"],["{plus_one}","2"],["{x}","2"]]}}],
            "matching":[[[0,0],[1,1]],[[0,1],[1,2]],[[0,2],[1,0]]]}}"#
    )
}

/// Corollary 2 by Theorem 1 (`isometric --method dubois --exact`) on `T_x` against `T_{x+k}`
/// (isometric: the same lattice) and `T_{x+1/3}` (not: `D_x` is a rectangle, `D_{x+1/3}` two
/// triangles), each pair also under the default `--method auto` (dubois on these needles).
/// Each input is given as `(x, x + 1)`.
fn isometry_of_t_x(x: [&str; 2], x_plus_k: [&str; 2], x_plus_third: [&str; 2]) {
    let dir = tempfile::tempdir().unwrap();
    let d = |name: &str| dir.path().join(name);
    for (name, [v, w]) in [
        ("a.json", x),
        ("b.json", x_plus_k),
        ("c.json", x_plus_third),
    ] {
        std::fs::write(d(name), t_x_json(v, w)).unwrap();
    }
    for method in [&["--method", "dubois", "--exact"][..], &["--exact"][..]] {
        for (other, code, verdict) in [("b.json", 0, "isometric"), ("c.json", 1, "not isometric")] {
            let out = surftopo()
                .arg("isometric")
                .arg(d("a.json"))
                .arg(d(other))
                .args(method)
                .assert()
                .code(code);
            let stdout = String::from_utf8_lossy(&out.get_output().stdout).into_owned();
            assert_eq!(stdout.trim(), verdict, "{method:?} {other}");
            let stderr = String::from_utf8_lossy(&out.get_output().stderr).into_owned();
            assert!(stderr.contains("Theorem 1"), "{stderr}");
        }
    }
}

#[test]
fn isometric_by_dubois_on_t_x_at_1e9() {
    isometry_of_t_x(
        ["1000000000", "1000000001"],
        ["1000000007", "1000000008"],
        ["3000000001/3", "3000000004/3"],
    );
}

#[test]
fn isometric_by_dubois_on_t_x_at_1e18() {
    isometry_of_t_x(
        ["1000000000000000000", "1000000000000000001"],
        ["1000000000000000007", "1000000000000000008"],
        ["3000000000000000001/3", "3000000000000000004/3"],
    );
}

/// `--reduced` (Corollary 1) writes the reduced triangulation of `T_x`: a closed triangular
/// portalgon of the same area (2) as the input, isometric to it; `--method auto` takes dubois on
/// this needle, and `--reduced` is refused with flipping.
#[test]
fn delaunay_writes_the_reduced_triangulation() {
    let dir = tempfile::tempdir().unwrap();
    let d = |name: &str| dir.path().join(name);
    std::fs::write(d("t.json"), t_x_json("1000000000", "1000000001")).unwrap();
    let v = json_of(
        surftopo()
            .arg("delaunay")
            .arg(d("t.json"))
            .arg("-o")
            .arg(d("d.json"))
            .args(["--exact", "--json", "--reduced"])
            .arg(d("r.json")),
        &["method", "requested_method", "triangles_after_reduction"],
    );
    assert_eq!(v["method"], "dubois");
    assert_eq!(v["requested_method"], "auto");
    let reduced: Value =
        serde_json::from_str(&std::fs::read_to_string(d("r.json")).unwrap()).unwrap();
    let polygons = reduced["polygons"].as_array().unwrap();
    assert_eq!(
        polygons.len() as u64,
        v["triangles_after_reduction"].as_u64().unwrap()
    );
    // Exact corners: every polygon a triangle, the areas summing to the input's, 2.
    let mut area = 0.0;
    for p in polygons {
        let c = corners(p);
        assert_eq!(c.len(), 3, "{p}");
        area += ((c[1][0] - c[0][0]) * (c[2][1] - c[0][1])
            - (c[1][1] - c[0][1]) * (c[2][0] - c[0][0]))
            / 2.0;
    }
    assert!((area - 2.0).abs() < 1e-9, "area {area}");
    // The reduced triangulation is the same torus (Corollary 2 by Theorem 1, exactly).
    surftopo()
        .arg("isometric")
        .arg(d("t.json"))
        .arg(d("r.json"))
        .args(["--method", "dubois", "--exact"])
        .assert()
        .code(0);
    surftopo()
        .arg("delaunay")
        .arg(d("t.json"))
        .arg("-o")
        .arg(d("x.json"))
        .args(["--method", "voronoi", "--exact", "--reduced"])
        .arg(d("r2.json"))
        .assert()
        .code(2);
}

/// `--faithful` runs all 350 inner repetitions per outer iteration (the JSON's total equals its
/// bound `350·N`) and writes the same triangulation, tessellation and reduced triangulation,
/// byte for byte, as the default, which stops at the first repetition that changes nothing;
/// `isometric` takes it too; without `--method dubois` it is refused (exit 2).
#[test]
fn faithful_gives_the_default_outputs() {
    let dir = tempfile::tempdir().unwrap();
    let d = |name: &str| dir.path().join(name);
    std::fs::write(d("t.json"), t_x_json("1000", "1001")).unwrap();
    let mut figures = Vec::new();
    for (suffix, extra) in [("", &[][..]), ("-faithful", &["--faithful"][..])] {
        let v = json_of(
            surftopo()
                .arg("delaunay")
                .arg(d("t.json"))
                .arg("-o")
                .arg(d(&format!("d{suffix}.json")))
                .arg("--tessellation")
                .arg(d(&format!("dt{suffix}.json")))
                .arg("--reduced")
                .arg(d(&format!("r{suffix}.json")))
                .args(["--method", "dubois", "--exact", "--json"])
                .args(extra),
            &[
                "inner_passes_total",
                "inner_passes_bound",
                "outer_iterations",
            ],
        );
        figures.push(v);
    }
    let bound = figures[1]["inner_passes_bound"].as_u64().unwrap();
    assert_eq!(
        bound,
        350 * figures[1]["outer_iterations"].as_u64().unwrap()
    );
    assert_eq!(figures[1]["inner_passes_total"].as_u64().unwrap(), bound);
    assert!(figures[0]["inner_passes_total"].as_u64().unwrap() < bound / 10);
    for name in ["d", "dt", "r"] {
        assert_eq!(
            std::fs::read(d(&format!("{name}.json"))).unwrap(),
            std::fs::read(d(&format!("{name}-faithful.json"))).unwrap(),
            "{name}.json"
        );
    }
    surftopo()
        .arg("isometric")
        .arg(d("t.json"))
        .arg(d("r.json"))
        .args(["--method", "dubois", "--exact", "--faithful"])
        .assert()
        .code(0);
    for method in ["auto", "flip", "voronoi"] {
        let out = surftopo()
            .arg("delaunay")
            .arg(d("t.json"))
            .arg("-o")
            .arg(d("x.json"))
            .args(["--faithful", "--method", method])
            .assert()
            .code(2);
        let stderr = String::from_utf8_lossy(&out.get_output().stderr).into_owned();
        assert!(
            stderr.contains("--faithful applies to --method dubois"),
            "{stderr}"
        );
    }
}

/// The `seconds` figures of `--json` are rounded to the microsecond (no `0.0012000300000000002`)
/// and the summary lines give times with a unit (µs, ms, s), never `0.000 s`.
#[test]
fn times_are_short_decimals_in_json_and_carry_a_unit_in_summaries() {
    let dir = tempfile::tempdir().unwrap();
    let input = common::generated_genus_surface(dir.path(), "g2.off", 2);
    let output = dir.path().join("out.obj");
    for command in ["irreducible", "quad"] {
        let out = surftopo()
            .arg(command)
            .arg(&input)
            .arg("-o")
            .arg(&output)
            .arg("--json")
            .output()
            .unwrap();
        assert!(out.status.success());
        let text = String::from_utf8(out.stdout).unwrap();
        let mut times = 0;
        for line in text.lines().filter(|l| l.contains("seconds\": ")) {
            let number = line.split("\": ").nth(1).unwrap().trim_end_matches(',');
            let decimals = number.split('.').nth(1).map_or(0, str::len);
            assert!(decimals <= 6 && !number.contains('e'), "{command}: {line}");
            times += 1;
        }
        assert!(times >= 1, "{command}: no time in {text}");

        let out = common::run_ok(
            surftopo().arg(command).arg(&input).arg("-o").arg(&output),
            command,
        );
        let summary = String::from_utf8(out.stdout).unwrap();
        assert!(
            [" µs", " ms", " s"]
                .iter()
                .any(|unit| summary.contains(unit))
                && !summary.contains("0.000 s"),
            "{command}: {summary}"
        );
    }
}

/// A successful run whose summary ("wrote …, 48 faces") is on stdout, with nothing on stderr.
fn assert_wrote_48_faces_on_stdout(out: &std::process::Output) {
    assert!(out.status.success());
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.starts_with("wrote ") && stdout.contains("48 faces"),
        "{stdout}"
    );
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Every command's summary is on stdout, `generate` and `convert` included; stderr stays free
/// for notes and progress.
#[test]
fn generate_and_convert_print_their_summary_on_stdout() {
    let dir = tempfile::tempdir().unwrap();
    let mesh = dir.path().join("t.off");
    let out = surftopo()
        .args(["generate", "torus", "--m", "6", "--n", "4", "-o"])
        .arg(&mesh)
        .output()
        .unwrap();
    assert_wrote_48_faces_on_stdout(&out);

    let converted = dir.path().join("t.obj");
    let out = surftopo()
        .arg("convert")
        .arg(&mesh)
        .arg(&converted)
        .output()
        .unwrap();
    assert_wrote_48_faces_on_stdout(&out);
}
