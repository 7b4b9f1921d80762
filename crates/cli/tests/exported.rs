//! Meshes as exporters write them: vertices in no face (the input's numbering kept in every
//! output), polygon faces (cut into triangles, or a quad mesh's own quads), triangle soups (the
//! `--weld` hint), near-degenerate triangles (a warning, and `--mollify` in `delaunay`'s
//! refusal), point clouds. Outputs are parsed here independently of the library.

mod common;

use common::{read_mtx, surftopo, write};
use serde_json::Value;
use surftopo_testkit::obj_text::statements as lines;

const TETRA_FACES: [[usize; 3]; 4] = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
const TETRA_CORNERS: [[f64; 3]; 4] = [
    [0.0, 0.0, 0.0],
    [1.0, 0.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.0, 0.0, 1.0],
];

/// The tetrahedron on vertices 1, 2, 4, 5 of seven (0, 3 and 6 in no face).
fn tetra_with_loose_vertices() -> String {
    let slots = [1usize, 2, 4, 5];
    let mut positions = vec![[9.0, 9.0, 9.0], [0.0; 3], [0.0; 3], [7.0, 7.0, 7.0]];
    positions.extend([[0.0; 3], [0.0; 3], [5.0, 5.0, 5.0]]);
    for (k, &s) in slots.iter().enumerate() {
        positions[s] = TETRA_CORNERS[k];
    }
    let mut text: String = positions
        .iter()
        .map(|p| format!("v {} {} {}\n", p[0], p[1], p[2]))
        .collect();
    for f in TETRA_FACES {
        let f = f.map(|v| slots[v] + 1);
        text += &format!("f {} {} {}\n", f[0], f[1], f[2]);
    }
    text
}

#[test]
fn matrices_and_meshes_keep_the_input_vertex_numbering() {
    let dir = tempfile::tempdir().unwrap();
    let loose = write(dir.path(), "loose.obj", &tetra_with_loose_vertices());
    let dense_text: String = TETRA_CORNERS
        .iter()
        .map(|p| format!("v {} {} {}\n", p[0], p[1], p[2]))
        .chain(
            TETRA_FACES
                .iter()
                .map(|f| format!("f {} {} {}\n", f[0] + 1, f[1] + 1, f[2] + 1)),
        )
        .collect();
    let dense = write(dir.path(), "dense.obj", &dense_text);
    let slots = [1usize, 2, 4, 5];
    for method in ["flip", "voronoi", "dubois"] {
        let out = |name: &str| dir.path().join(format!("{name}-{method}.mtx"));
        for (input, tag) in [(&loose, "loose"), (&dense, "dense")] {
            surftopo()
                .arg("delaunay")
                .arg(input)
                .args(["--method", method, "--laplacian"])
                .arg(out(&format!("L-{tag}")))
                .arg("--mass")
                .arg(out(&format!("M-{tag}")))
                .assert()
                .success();
        }
        for m in ["L", "M"] {
            let (big, small) = (
                read_mtx(&out(&format!("{m}-loose"))),
                read_mtx(&out(&format!("{m}-dense"))),
            );
            assert_eq!((big.len(), big[0].len()), (7, 7), "{m} {method}");
            for (i, row) in big.iter().enumerate() {
                for (j, &got) in row.iter().enumerate() {
                    let expected = match (
                        slots.iter().position(|&s| s == i),
                        slots.iter().position(|&s| s == j),
                    ) {
                        (Some(a), Some(b)) => small[a][b],
                        _ => 0.0,
                    };
                    assert!(
                        (got - expected).abs() <= 1e-12 * expected.abs().max(1.0),
                        "{m} {method} ({i}, {j}): {got} against {expected}"
                    );
                }
            }
        }
    }
    // quad and irreducible write the input's vertex list, faces on its indices.
    let text = tetra_with_loose_vertices();
    for (command, faces) in [("irreducible", 4), ("quad", 2)] {
        let output = dir.path().join(format!("{command}.obj"));
        surftopo()
            .arg(command)
            .arg(&loose)
            .arg("-o")
            .arg(&output)
            .assert()
            .success();
        let written = std::fs::read_to_string(&output).unwrap();
        assert_eq!(lines(&written, "v"), lines(&text, "v"), "{command}");
        let f = lines(&written, "f");
        assert_eq!(f.len(), faces, "{command}");
        for face in f {
            for corner in face {
                let v: usize = corner.split('/').next().unwrap().parse().unwrap();
                assert!(slots.contains(&(v - 1)), "{command}: vertex {v}");
            }
        }
    }
}

/// A cube of six quads, 1-based faces.
const CUBE: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
                    f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

#[test]
fn polygon_meshes_are_cut_and_a_quad_mesh_is_its_own_quad_mesh() {
    let dir = tempfile::tempdir().unwrap();
    let cube = write(dir.path(), "cube.obj", CUBE);
    let output = dir.path().join("q.obj");
    let run = surftopo()
        .arg("quad")
        .arg(&cube)
        .arg("-o")
        .arg(&output)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{stderr}");
    assert!(stderr.contains("its own quads are written"), "{stderr}");
    let written = std::fs::read_to_string(&output).unwrap();
    assert_eq!(lines(&written, "v"), lines(CUBE, "v"));
    assert_eq!(lines(&written, "f"), lines(CUBE, "f"));
    // A prism with pentagon ends (10 vertices, 2 pentagons, 5 quads) through delaunay: the
    // note counts the polygons and their triangles; the Laplacian has one row per vertex.
    let mut prism = String::new();
    for z in [0.0, 1.0] {
        for k in 0..5 {
            let t = std::f64::consts::TAU * f64::from(k) / 5.0;
            prism += &format!("v {} {} {z}\n", t.cos(), t.sin());
        }
    }
    prism += "f 5 4 3 2 1\nf 6 7 8 9 10\n";
    for k in 0..5 {
        let (a, b) = (k + 1, (k + 1) % 5 + 1);
        prism += &format!("f {a} {b} {} {}\n", b + 5, a + 5);
    }
    let prism = write(dir.path(), "prism.obj", &prism);
    let laplacian = dir.path().join("L.mtx");
    let run = surftopo()
        .arg("delaunay")
        .arg(&prism)
        .arg("--laplacian")
        .arg(&laplacian)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{stderr}");
    assert!(
        stderr.contains("7 polygons of 4 to 5 sides cut into 16 triangles"),
        "{stderr}"
    );
    let l = read_mtx(&laplacian);
    assert_eq!(l.len(), 10);
    for row in &l {
        assert!(row.iter().sum::<f64>().abs() < 1e-12, "{row:?}");
    }
}

#[test]
fn a_triangle_soup_gets_the_weld_hint() {
    let dir = tempfile::tempdir().unwrap();
    let mut soup = String::new();
    for f in TETRA_FACES {
        for v in f {
            let p = TETRA_CORNERS[v];
            soup += &format!("v {} {} {}\n", p[0], p[1], p[2]);
        }
    }
    for k in 0..4 {
        soup += &format!("f {} {} {}\n", 3 * k + 1, 3 * k + 2, 3 * k + 3);
    }
    let path = write(dir.path(), "soup.obj", &soup);
    let hint = "`--weld` would merge 8 vertices into others at the same position, making one \
                closed surface (sphere)";
    // `isometric` compares the four lone triangles as four pieces, with the hint as a note.
    let run = surftopo()
        .arg("isometric")
        .arg(&path)
        .arg(&path)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(0), "{stderr}");
    assert!(
        stderr.contains("note: ") && stderr.contains(hint),
        "{stderr}"
    );
    assert!(stderr.contains("the 4 pieces pair up"), "{stderr}");
    // `quad` and `delaunay` take several pieces (four lone triangles), with the hint as a note.
    for (command, output) in [("quad", "q.obj"), ("delaunay", "d.json")] {
        let run = surftopo()
            .arg(command)
            .arg(&path)
            .arg("-o")
            .arg(dir.path().join(output))
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(0), "{command}: {stderr}");
        assert!(
            stderr.contains("note: ") && stderr.contains(hint),
            "{command}: {stderr}"
        );
    }
    let out = surftopo()
        .args(["info", "--json"])
        .arg(&path)
        .output()
        .unwrap();
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(v["weld_hint"].as_str().unwrap().contains("--weld"), "{v}");
    surftopo()
        .arg("quad")
        .arg(&path)
        .arg("--weld")
        .arg("-o")
        .arg(dir.path().join("q.obj"))
        .assert()
        .success();
}

#[test]
fn a_needle_is_a_warning_in_info_and_delaunay_names_mollify() {
    let dir = tempfile::tempdir().unwrap();
    let needle = write(
        dir.path(),
        "needle.obj",
        "v 0 0 0\nv 1 0 0\nv 0.5 1e-10 0\nv 0.3 0.3 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n",
    );
    let out = surftopo()
        .args(["info", "--json", "--strict"])
        .arg(&needle)
        .output()
        .unwrap();
    assert!(out.status.success());
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["valid"], true);
    assert_eq!(v["near_degenerate_faces"], 1);
    let warning = v["warnings"][0].as_str().unwrap();
    assert!(
        warning.contains("line 5: face 0: near-degenerate"),
        "{warning}"
    );
    let run = surftopo()
        .arg("delaunay")
        .arg(&needle)
        .arg("--laplacian")
        .arg(dir.path().join("L.mtx"))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("zero-area triangle"), "{stderr}");
    assert!(stderr.contains("--mollify EPS"), "{stderr}");
    surftopo()
        .arg("delaunay")
        .arg(&needle)
        .args(["--mollify", "1e-6", "--laplacian"])
        .arg(dir.path().join("L.mtx"))
        .assert()
        .success();
}

#[test]
fn a_point_cloud_is_described() {
    let dir = tempfile::tempdir().unwrap();
    let cloud = write(
        dir.path(),
        "cloud.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
         property float z\nproperty float nx\nproperty float ny\nproperty float nz\nend_header\n\
         0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n",
    );
    let out = surftopo()
        .args(["info", "--json"])
        .arg(&cloud)
        .output()
        .unwrap();
    assert!(out.status.success());
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["point_cloud"], true);
    assert_eq!(
        (v["vertices"].as_u64(), v["faces"].as_u64()),
        (Some(3), Some(0))
    );
    assert_eq!(
        v["vertex_properties"],
        serde_json::json!(["nx", "ny", "nz"])
    );
    let text = surftopo().arg("info").arg(&cloud).output().unwrap();
    let stdout = String::from_utf8_lossy(&text.stdout);
    assert!(stdout.contains("a point cloud"), "{stdout}");
    let run = surftopo()
        .arg("quad")
        .arg(&cloud)
        .arg("-o")
        .arg(dir.path().join("q.obj"))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("a point cloud of 3 vertices"), "{stderr}");
    assert!(stderr.contains("needs faces"), "{stderr}");
}

#[test]
fn quads_whose_ear_clipping_is_no_surface_are_read_through_their_fans() {
    // LRS pairs triangles of a flipped triangulation; on the demo's input two of its quads, side
    // by side around a vertex of two faces, have a flat triangle on each cut: ear clipping gives
    // a duplicate triangle, the fans of corner 0 a surface, which every command then uses.
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("g2.obj");
    surftopo()
        .args([
            "generate", "genus", "--genus", "2", "--size", "2", "--flips", "1000",
        ])
        .args(["--seed", "7", "-o"])
        .arg(&input)
        .assert()
        .success();
    let quads = dir.path().join("q.obj");
    surftopo()
        .arg("quad")
        .arg(&input)
        .args(["--algorithm", "lrs", "-o"])
        .arg(&quads)
        .assert()
        .success();
    let out = surftopo()
        .args(["info", "--json", "--strict"])
        .arg(&quads)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["genus"], 2);
    let warnings = v["warnings"].as_array().unwrap();
    assert!(
        warnings[0]
            .as_str()
            .unwrap()
            .contains("the fans of their corner 0"),
        "{warnings:?}"
    );
    let run = surftopo()
        .arg("irreducible")
        .arg(&quads)
        .args(["--json", "-o"])
        .arg(dir.path().join("i.obj"))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{stderr}");
    assert!(
        stderr.contains("the fan of each one's corner 0"),
        "{stderr}"
    );
    let v: Value = serde_json::from_slice(&run.stdout).unwrap();
    assert_eq!(v["output"]["genus"], 2);
}
