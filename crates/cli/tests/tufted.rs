//! `delaunay --tufted` and `delaunay` on non-manifold meshes: the note on stderr, the JSON keys,
//! the matrices read back equal to the library's `tufted_laplacian`, the options refused, and
//! errors located with exit 2.

mod common;

use common::{surftopo, write};
use serde_json::Value;
use surftopo_intrinsic::{SparseMatrix, TuftedOptions, read_matrix_market, tufted_laplacian};

/// Three triangles on one edge (a book) and an unreferenced vertex.
const BOOK: &str = "v 0 0 0\nv 1 0 0\nv 0.5 1 0\nv 0.5 -0.8 0.3\nv 0.4 0.1 1\nv 9 9 9\n\
                    f 1 2 3\nf 2 1 4\nf 1 2 5\n";

fn book() -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let p = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.5, 1.0, 0.0],
        [0.5, -0.8, 0.3],
        [0.4, 0.1, 1.0],
        [9.0, 9.0, 9.0],
    ];
    (p, vec![[0, 1, 2], [1, 0, 3], [0, 1, 4]])
}

fn read(path: &std::path::Path) -> SparseMatrix {
    read_matrix_market(std::io::BufReader::new(std::fs::File::open(path).unwrap())).unwrap()
}

fn stderr(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[test]
fn a_non_manifold_mesh_takes_the_tufted_cover_with_a_note() {
    let dir = tempfile::tempdir().unwrap();
    let input = write(dir.path(), "book.obj", BOOK);
    let (l, m) = (dir.path().join("L.mtx"), dir.path().join("M.mtx"));
    let out = surftopo()
        .args(["delaunay", "--json", "--laplacian"])
        .arg(&l)
        .arg("--mass")
        .arg(&m)
        .arg(&input)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(stderr(&out).contains("not a manifold (1 non-manifold edges"));
    let json: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["tufted"], true);
    assert_eq!(json["automatic"], true);
    for (key, value) in [
        ("vertices", 6),
        ("faces", 3),
        ("edges", 7),
        ("book_edges", 1),
    ] {
        assert_eq!(json[key], value, "{key}");
    }
    for key in [
        "fin_edges",
        "cover_vertices",
        "cover_edges",
        "cover_faces",
        "flips",
    ] {
        assert!(json[key].is_u64(), "{key}");
    }
    assert!(json["mollify_delta"].is_f64() && json["seconds"].is_f64());
    // The files hold the library's matrices (Matrix Market keeps 17 significant digits).
    let (p, t) = book();
    let want = tufted_laplacian(&p, &t, &TuftedOptions::default()).unwrap();
    for (file, matrix) in [(&l, &want.laplacian), (&m, &want.mass)] {
        let got = read(file);
        assert_eq!(got.n, 6);
        for (i, j, v) in matrix.triplets() {
            assert!((got.get(i as usize, j as usize) - v).abs() <= 1e-15 * v.abs().max(1.0));
        }
    }
    // --tufted asks for the same, without the note; the plain JSON says tufted: false.
    let asked = surftopo()
        .args(["delaunay", "--tufted", "--json"])
        .arg(&input)
        .output()
        .unwrap();
    assert!(asked.status.success() && !stderr(&asked).contains("not a manifold"));
    let json: Value = serde_json::from_slice(&asked.stdout).unwrap();
    assert_eq!(
        (json["tufted"].clone(), json["automatic"].clone()),
        (true.into(), false.into())
    );
    let closed = write(
        dir.path(),
        "tet.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n",
    );
    let plain = surftopo()
        .args(["delaunay", "--json"])
        .arg(&closed)
        .output()
        .unwrap();
    let json: Value = serde_json::from_slice(&plain.stdout).unwrap();
    assert_eq!(json["tufted"], false);
}

#[test]
fn options_the_tufted_cover_does_not_serve_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let input = write(dir.path(), "book.obj", BOOK);
    let json = dir.path().join("out.json");
    for (args, option) in [
        (vec!["-o", json.to_str().unwrap()], "-o"),
        (
            vec!["--json", "--method", "voronoi"],
            "--method voronoi or dubois",
        ),
        (
            vec!["--json", "--tufted", "--method", "dubois"],
            "--method voronoi or dubois",
        ),
    ] {
        let out = surftopo()
            .arg("delaunay")
            .args(&args)
            .arg(&input)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(
            stderr(&out).contains(&format!("{option}: ")),
            "{}",
            stderr(&out)
        );
        assert!(!json.exists());
    }
}

#[test]
fn bad_soups_are_located_with_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    // A flat face without mollification: named with its line.
    let flat = write(
        dir.path(),
        "flat.obj",
        "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 4\nf 1 2 3\nf 2 1 4\n",
    );
    let out = surftopo()
        .args(["delaunay", "--tufted", "--json", "--mollify", "0"])
        .arg(&flat)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("line 6: face 1:"), "{}", stderr(&out));
    // Mollified by default.
    let out = surftopo()
        .args(["delaunay", "--tufted", "--json"])
        .arg(&flat)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    let json: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(json["mollify_delta"].as_f64().unwrap() > 0.0);
    // A repeated vertex and an invalid factor.
    let repeated = write(
        dir.path(),
        "rep.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 2\n",
    );
    let out = surftopo()
        .args(["delaunay", "--tufted", "--json"])
        .arg(&repeated)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("line 5: face 1"), "{}", stderr(&out));
    let out = surftopo()
        .args(["delaunay", "--tufted", "--json", "--mollify", "-1"])
        .arg(&repeated)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}
