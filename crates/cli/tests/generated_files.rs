//! Property: every file `surftopo generate` writes is read back by every command that takes it
//! (issue 23, item 3 and the read/write contract): meshes by `info --strict`, `convert`,
//! `irreducible`, `quad`, `delaunay`, `isometric` and `generate intrinsic-flips`; portalgon JSON
//! by `delaunay`, `isometric` and `generate intrinsic-flips`.

mod common;

use common::surftopo;
use proptest::prelude::*;
use std::path::Path;

/// Generator arguments: a small surface of every kind.
fn kind() -> impl Strategy<Value = Vec<String>> {
    let v = |a: &[&str]| a.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    prop_oneof![
        Just(v(&["tetrahedron"])),
        (0u32..3).prop_map(move |s| v(&["icosphere", "--subdivisions", &s.to_string()])),
        (3u32..9, 3u32..7).prop_map(move |(m, n)| v(&[
            "torus",
            "--m",
            &m.to_string(),
            "--n",
            &n.to_string()
        ])),
        (0u32..4, 1u32..3).prop_map(move |(g, s)| v(&[
            "genus",
            "--genus",
            &g.to_string(),
            "--size",
            &s.to_string()
        ])),
        (1u32..3, 0u32..2).prop_map(move |(c, h)| v(&[
            "cavity-box",
            "--cavities",
            &c.to_string(),
            "--holes",
            &h.to_string(),
            "--triangles",
            "600"
        ])),
        (3u32..6, 3u32..6, 0u32..3).prop_map(move |(m, n, s)| v(&[
            "sheared-torus",
            "--m",
            &m.to_string(),
            "--n",
            &n.to_string(),
            "--shear",
            &s.to_string()
        ])),
    ]
}

/// Runs `surftopo ARGS` and requires exit code 0.
fn ok(args: &[&str]) {
    let out = surftopo().args(args).output().unwrap();
    assert!(
        out.status.success(),
        "surftopo {}: {}",
        args.join(" "),
        String::from_utf8_lossy(&out.stderr)
    );
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Every command that takes a portalgon JSON file, on `json` (and against a random
/// re-triangulation of it).
fn read_json_everywhere(dir: &Path, json: &Path) {
    ok(&["delaunay", s(json), "-o", s(&dir.join("d.json"))]);
    ok(&["isometric", s(json), s(json)]);
    let flipped = dir.join("again.json");
    let count = ["--count", "30", "-o", s(&flipped)];
    ok(&[
        &["generate", "intrinsic-flips", "--input", s(json)][..],
        &count,
    ]
    .concat());
    isometric_or_undecidable(json, &flipped);
}

/// `isometric a b` answers "isometric" (0) or "undecidable in double precision" (3: the
/// flat-vertex removal can get stuck on loops, `remove_flat_vertices`), never "not isometric".
fn isometric_or_undecidable(a: &Path, b: &Path) {
    let out = surftopo().args(["isometric", s(a), s(b)]).output().unwrap();
    let code = out.status.code();
    assert!(
        matches!(code, Some(0 | 3)),
        "isometric {} {}: {code:?} {}",
        s(a),
        s(b),
        String::from_utf8_lossy(&out.stderr)
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, ..ProptestConfig::default() })]

    #[test]
    fn every_generated_file_is_read_by_every_command(
        kind in kind(),
        format in prop::sample::select(vec!["obj", "off", "ply", "obj.gz", "off.gz", "ply.gz"]),
        flips in 0usize..60,
        splits in 0usize..4,
        shuffle in any::<bool>(),
        seed in 0u64..1000,
    ) {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        let mesh = d.join(format!("m.{format}"));
        let mut args: Vec<String> = vec!["generate".into()];
        args.extend(kind);
        args.extend(["--flips".into(), flips.to_string(), "--splits".into(), splits.to_string()]);
        args.extend(["--seed".into(), seed.to_string(), "-o".into(), s(&mesh).into()]);
        if shuffle {
            args.push("--shuffle-faces".into());
        }
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        ok(&args);
        ok(&["info", s(&mesh), "--strict"]);
        ok(&["convert", s(&mesh), s(&d.join("c.ply"))]);
        ok(&["info", s(&d.join("c.ply")), "--strict"]);
        ok(&["irreducible", s(&mesh), "-o", s(&d.join("i.obj"))]);
        ok(&["quad", s(&mesh), "-o", s(&d.join("q.obj"))]);
        ok(&["delaunay", s(&mesh), "-o", s(&d.join("d.json"))]);
        ok(&["isometric", s(&mesh), s(&mesh)]);
        let flipped = d.join("f.json");
        ok(&["generate", "intrinsic-flips", "--input", s(&mesh), "--count", "50",
             "--seed", &seed.to_string(), "-o", s(&flipped)]);
        isometric_or_undecidable(&mesh, &flipped);
        read_json_everywhere(d, &flipped);
    }

    #[test]
    fn every_generated_flat_torus_is_read_by_every_command(
        x in -20.0f64..20.0,
        m in 1u32..4,
        flips in 0usize..30,
        seed in 0u64..1000,
    ) {
        let dir = tempfile::tempdir().unwrap();
        let torus = dir.path().join("t.json");
        ok(&["generate", "flat-torus", &format!("--x={x}"), "--m", &m.to_string(),
             "--flips", &flips.to_string(), "--seed", &seed.to_string(), "-o", s(&torus)]);
        read_json_everywhere(dir.path(), &torus);
    }
}

/// `--splits` never writes a flat face: a split with no non-flat placement of its new vertex is
/// left out, and the command says how many were made. A tetrahedron with its four corners on one
/// line has no such placement anywhere: no split is made, the note says so, the file is the input.
#[test]
fn splits_left_out_are_noted() {
    let dir = tempfile::tempdir().unwrap();
    let input = common::write(
        dir.path(),
        "line_tetrahedron.obj",
        "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf 1 2 3\nf 1 4 2\nf 2 4 3\nf 3 4 1\n",
    );
    let out_path = dir.path().join("split.obj");
    let out = common::run_ok(
        surftopo().args([
            "generate",
            "mesh",
            "--input",
            input.to_str().unwrap(),
            "--splits",
            "3",
            "--seed",
            "1",
            "-o",
            out_path.to_str().unwrap(),
        ]),
        "splits on a line tetrahedron",
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("--splits 3: 0 made"), "{stderr}");
    let written = std::fs::read_to_string(&out_path).unwrap();
    assert_eq!(written.lines().filter(|l| l.starts_with("f ")).count(), 4);
    assert_eq!(written.lines().filter(|l| l.starts_with("v ")).count(), 4);
    // Surfaces where every split has a placement get no note: a sphere, and a disk, whose
    // boundary vertices' splits add one face each (the count is of vertices, not faces).
    for kind in [&["icosphere", "--subdivisions", "1"][..], &["disk"][..]] {
        let written = dir.path().join("split_surface.obj");
        let out = common::run_ok(
            surftopo()
                .arg("generate")
                .args(kind)
                .args(["--splits", "40", "--seed", "3", "-o"])
                .arg(&written),
            "splits on a surface",
        );
        assert!(
            !String::from_utf8_lossy(&out.stderr).contains("left out"),
            "{kind:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
}
