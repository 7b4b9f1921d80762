//! What `delaunay -o` writes it reads: portalgon files of every surface kind (boundary sides
//! unmatched, orientation-reversing gluings flagged, several pieces) as inputs of `delaunay`
//! and `isometric`.
//!
//! Vertex identity: the file's `vertices` labels are K's vertices, the mesh's vertex indices
//! (every generated vertex is in a face, so no index is dropped); the Laplacian of the mesh
//! (rows: input indices) and of the file (rows: labels) are compared entry by entry, and both
//! against the cotan Laplacian computed here from the file's triangles and labels alone. The
//! Delaunay property is checked here edge by edge from the file's lengths (the two angles
//! opposite each glued pair).

mod common;

use common::{generate, read_mtx, surftopo};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// The surface kinds `generate` makes, with boundary, non-orientable or in pieces.
const KINDS: [(&str, &[&str]); 8] = [
    ("disk", &["disk", "--n", "5"]),
    ("annulus", &["annulus", "--flips", "20"]),
    ("mobius", &["mobius-band", "--flips", "20"]),
    ("rp2", &["projective-plane", "--subdivide", "1"]),
    ("klein", &["klein-bottle", "--flips", "20"]),
    ("n3", &["non-orientable", "--crosscaps", "3"]),
    ("holes", &["torus", "--cut-holes", "2"]),
    ("pieces", &["mobius-band", "--copies", "3"]),
];

/// `surftopo delaunay ARGS`, which must succeed; returns its `--json` figures when asked.
fn delaunay(args: &[&std::ffi::OsStr]) -> Value {
    let out = surftopo().arg("delaunay").args(args).output().unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap_or(Value::Null)
}

/// The triangles of a portalgon file written by lengths: lengths and labels.
fn triangles(doc: &Value) -> Vec<([f64; 3], [usize; 3])> {
    doc["polygons"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            let l: Vec<f64> = p["lengths"]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect();
            let v: Vec<usize> = p["vertices"]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_u64().unwrap() as usize)
                .collect();
            ([l[0], l[1], l[2]], [v[0], v[1], v[2]])
        })
        .collect()
}

/// The angle of a triangle with sides `l` opposite side `i` (law of cosines).
fn angle_opposite(l: [f64; 3], i: usize) -> f64 {
    let (a, b, c) = (l[i], l[(i + 1) % 3], l[(i + 2) % 3]);
    ((b * b + c * c - a * a) / (2.0 * b * c))
        .clamp(-1.0, 1.0)
        .acos()
}

/// The cotan Laplacian of the file's triangles, rows by label: half the cotangent of the angle
/// opposite each side, summed per side (a boundary side has one, a glued pair two).
fn cotan_laplacian(tris: &[([f64; 3], [usize; 3])]) -> Vec<Vec<f64>> {
    let n = 1 + tris.iter().flat_map(|t| t.1).max().unwrap();
    let mut m = vec![vec![0.0; n]; n];
    for &(l, v) in tris {
        for i in 0..3 {
            let w = 0.5 / angle_opposite(l, i).tan();
            let w = if w.is_finite() { w } else { 0.0 };
            let (a, b) = (v[i], v[(i + 1) % 3]);
            m[a][b] -= w;
            m[b][a] -= w;
            m[a][a] += w;
            m[b][b] += w;
        }
    }
    m
}

/// Side `i` of triangle `t`: the angle opposite it.
fn opposite(tris: &[([f64; 3], [usize; 3])], side: &Value) -> f64 {
    let (t, i) = (
        side[0].as_u64().unwrap() as usize,
        side[1].as_u64().unwrap() as usize,
    );
    angle_opposite(tris[t].0, i)
}

fn assert_close(a: &[Vec<f64>], b: &[Vec<f64>], what: &str) {
    assert_within(a, b, 1e-12, what);
}

/// Equal entries within `relative` times the largest.
fn assert_within(a: &[Vec<f64>], b: &[Vec<f64>], relative: f64, what: &str) {
    assert_eq!(a.len(), b.len(), "{what}: sizes");
    let scale = a.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    for (i, (ra, rb)) in a.iter().zip(b).enumerate() {
        for (j, (x, y)) in ra.iter().zip(rb).enumerate() {
            assert!(
                (x - y).abs() <= relative * scale,
                "{what}: entry ({i}, {j}) {x} against {y}"
            );
        }
    }
}

/// Mesh → `delaunay -o A.json` → `delaunay A.json`: the same Laplacian and mass matrix, the
/// file a fixed point (no flip, the same bytes), Delaunay edge by edge; `isometric` says the
/// mesh and the file are isometric.
fn round_trip(dir: &Path, name: &str, mesh: &Path, weld: bool) {
    let p = |file: &str| -> PathBuf { dir.join(format!("{name}-{file}")) };
    let (a, b) = (p("a.json"), p("b.json"));
    let (l1, l2, m1, m2, t) = (
        p("l1.mtx"),
        p("l2.mtx"),
        p("m1.mtx"),
        p("m2.mtx"),
        p("t.json"),
    );
    let mut first: Vec<&std::ffi::OsStr> = vec![
        mesh.as_os_str(),
        "-o".as_ref(),
        a.as_os_str(),
        "--laplacian".as_ref(),
        l1.as_os_str(),
        "--mass".as_ref(),
        m1.as_os_str(),
    ];
    if weld {
        first.push("--weld".as_ref());
    }
    delaunay(&first);
    let figures = delaunay(&[
        a.as_os_str(),
        "-o".as_ref(),
        b.as_os_str(),
        "--laplacian".as_ref(),
        l2.as_os_str(),
        "--mass".as_ref(),
        m2.as_os_str(),
        "--tessellation".as_ref(),
        t.as_os_str(),
        "--method".as_ref(),
        "flip".as_ref(),
        "--json".as_ref(),
    ]);
    assert_eq!(figures["flips"], 0, "{name}: {figures}");
    assert_eq!(figures["non_delaunay_edges"], 0, "{name}: {figures}");
    assert_eq!(
        std::fs::read(&a).unwrap(),
        std::fs::read(&b).unwrap(),
        "{name}: the file read back and written again is the same"
    );
    let doc: Value = serde_json::from_slice(&std::fs::read(&a).unwrap()).unwrap();
    let tris = triangles(&doc);
    // Delaunay edge by edge: the two angles opposite each glued pair sum to at most π.
    for pair in doc["matching"].as_array().unwrap() {
        let sum = opposite(&tris, &pair[0]) + opposite(&tris, &pair[1]);
        assert!(
            sum <= std::f64::consts::PI + 1e-9,
            "{name}: pair {pair}: {sum}"
        );
    }
    let reference = cotan_laplacian(&tris);
    assert_close(
        &read_mtx(&l1),
        &reference,
        &format!("{name}: mesh Laplacian"),
    );
    assert_close(
        &read_mtx(&l2),
        &reference,
        &format!("{name}: file Laplacian"),
    );
    assert_close(&read_mtx(&m1), &read_mtx(&m2), &format!("{name}: mass"));
    // The tessellation is an input too: its cells cut into triangles, flipped to Delaunay, the
    // same Laplacian (it does not depend on how co-circular cells are cut).
    let tess: Value = serde_json::from_slice(&std::fs::read(&t).unwrap()).unwrap();
    assert!(tess["polygons"].as_array().unwrap().len() <= tris.len());
    let l3 = p("l3.mtx");
    let figures = delaunay(&[
        t.as_os_str(),
        "--laplacian".as_ref(),
        l3.as_os_str(),
        "--json".as_ref(),
    ]);
    assert_eq!(figures["non_delaunay_edges"], 0, "{name}: {figures}");
    assert_within(
        &read_mtx(&l3),
        &reference,
        1e-9,
        &format!("{name}: tessellation Laplacian"),
    );
    let out = surftopo()
        .arg("isometric")
        .arg(&t)
        .arg(&a)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{name}: tessellation against triangulation"
    );
    let mut isometric = surftopo();
    isometric.arg("isometric").arg(mesh).arg(&a);
    if weld {
        isometric.arg("--weld");
    }
    let out = isometric.output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{name}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let out = surftopo()
        .args(["isometric", "--json"])
        .arg(&a)
        .arg(&b)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{name}");
}

#[test]
fn every_surface_kind_round_trips_through_its_portalgon_file() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (name, args) in KINDS {
        let mut args = args.to_vec();
        args.extend(["--seed", "3"]);
        let mesh = generate(d, &format!("{name}.obj"), &args);
        round_trip(d, name, &mesh, false);
    }
}

surftopo_testkit::shared_mesh_tests!(holes_cut_in_a_shared_mesh_round_trip);

fn holes_cut_in_a_shared_mesh_round_trip() {
    surftopo_testkit::require_shared_meshes();
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mesh = surftopo_testkit::shared_meshes()
        .into_iter()
        .filter(|m| !m.needs_weld && m.faces < 5000)
        .min_by_key(|m| m.faces)
        .expect("a small shared mesh");
    let holes = generate(
        d,
        "holes.obj",
        &[
            "mesh",
            "--input",
            mesh.path.to_str().unwrap(),
            "--cut-holes",
            "3",
            "--seed",
            "7",
        ],
    );
    round_trip(d, "shared-holes", &holes, false);
}

#[test]
fn the_wave_and_theorem_1_refuse_a_version_2_file_naming_flipping() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mesh = generate(d, "band.obj", &["mobius-band"]);
    let doc = d.join("band.json");
    delaunay(&[mesh.as_os_str(), "-o".as_ref(), doc.as_os_str()]);
    for method in ["voronoi", "dubois"] {
        for command in ["delaunay", "isometric"] {
            let mut cmd = surftopo();
            cmd.arg(command).arg(&doc);
            if command == "delaunay" {
                cmd.arg("--json");
            } else {
                cmd.arg(&doc);
            }
            let out = cmd.args(["--method", method]).output().unwrap();
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{command} {method}: {stderr}");
            assert!(stderr.contains("flip"), "{command} {method}: {stderr}");
        }
    }
}

#[test]
fn an_inconsistent_version_2_gluing_is_refused_naming_the_polygon_and_side() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mesh = generate(d, "band.obj", &["mobius-band", "--flips", "10"]);
    let good = d.join("band.json");
    delaunay(&[mesh.as_os_str(), "-o".as_ref(), good.as_os_str()]);
    let doc: Value = serde_json::from_slice(&std::fs::read(&good).unwrap()).unwrap();
    let pairs = doc["matching"].as_array().unwrap();
    let k = pairs
        .iter()
        .position(|p| p.get(2) == Some(&Value::Bool(true)))
        .expect("a reversed gluing");
    let [p, i] = [0, 1].map(|j| pairs[k][0][j].as_u64().unwrap());
    let mut cases: Vec<(&str, Value, String)> = Vec::new();
    // One side of a reversed pair made longer.
    let mut longer = doc.clone();
    let l = longer["polygons"][p as usize]["lengths"][i as usize]
        .as_f64()
        .unwrap();
    longer["polygons"][p as usize]["lengths"][i as usize] = Value::from(1.5 * l);
    cases.push(("longer", longer, format!("({p}, {i})")));
    // The reversed pair's first side glued a second time.
    let mut twice = doc.clone();
    let other = pairs
        .iter()
        .position(|q| q[0][0] != pairs[k][0][0] && q[1][0] != pairs[k][0][0])
        .unwrap();
    twice["matching"][other][0] = pairs[k][0].clone();
    cases.push(("twice", twice, format!("polygon {p}")));
    // A label that disagrees with the gluing.
    let mut labels = doc.clone();
    let v = labels["polygons"][p as usize]["vertices"][0]
        .as_u64()
        .unwrap();
    let n = 1 + doc["polygons"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|q| q["vertices"].as_array().unwrap().iter())
        .map(|x| x.as_u64().unwrap())
        .max()
        .unwrap();
    labels["polygons"][p as usize]["vertices"][0] = Value::from((v + 1) % n);
    cases.push(("labels", labels, format!("polygon {p}")));
    // A reversed gluing in a file that says version 1.
    let mut v1 = doc.clone();
    v1["version"] = Value::from(1);
    cases.push(("v1", v1, format!("matching entry {k}")));
    for (name, text, expected) in cases {
        let path = d.join(format!("{name}.json"));
        std::fs::write(&path, serde_json::to_vec(&text).unwrap()).unwrap();
        for command in ["delaunay", "isometric"] {
            let mut cmd = surftopo();
            cmd.arg(command).arg(&path);
            if command == "delaunay" {
                cmd.arg("--json");
            } else {
                cmd.arg(&mesh);
            }
            let out = cmd.output().unwrap();
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{name} {command}: {stderr}");
            assert!(
                stderr.contains(&format!("{name}.json")) && stderr.contains(&expected),
                "{name} {command}: expected {expected:?} in {stderr}"
            );
        }
    }
}
