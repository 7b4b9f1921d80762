//! Issue 38, "exact means exact, and nothing stalls": one test per item, on inputs made here.

mod common;

use common::{surftopo, write};
use std::path::Path;
use std::process::Output;

fn run(args: &[&str]) -> Output {
    surftopo().args(args).output().unwrap()
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn stdout(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The command ended with `code` and its stderr contains every one of `needles`.
fn assert_code(out: &Output, code: i32, needles: &[&str]) {
    let err = stderr(out);
    assert_eq!(out.status.code(), Some(code), "{err}");
    for needle in needles {
        assert!(err.contains(needle), "no {needle:?} in: {err}");
    }
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The flat torus T_x by exact corners (Dubois, Section 9), written by `generate`.
fn flat_torus(dir: &Path, x: &str) -> std::path::PathBuf {
    let path = dir.join(format!("t{}.json", x.replace('/', "_")));
    let out = run(&["generate", "flat-torus", "--x", x, "-o", s(&path)]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    path
}

/// Item 6: exit codes as README says. A file whose exact corners make valid triangles that
/// double precision flattens is a numerical failure (exit 4, the file named, `--exact`
/// advised), and `isometric` calls it undecidable in double precision (exit 3) whatever the
/// method; degenerate input is refused by `isometric` as by `delaunay` (exit 2).
#[test]
fn item6_exit_codes_follow_the_readme() {
    let dir = tempfile::tempdir().unwrap();
    for x in ["1000000", "3000000", "10000000000"] {
        let t = flat_torus(dir.path(), x);
        for method in ["auto", "flip", "voronoi", "dubois"] {
            let out = run(&["delaunay", s(&t), "--json", "--method", method]);
            assert_code(&out, 4, &[s(&t), "--exact", "zero-area"]);
        }
        for method in ["auto", "flip", "voronoi", "dubois"] {
            let out = run(&["isometric", s(&t), s(&t), "--method", method]);
            assert_code(&out, 3, &["--exact"]);
            assert_eq!(stdout(&out), "undecidable in double precision\n");
        }
        let exact = run(&["delaunay", s(&t), "--json", "--method", "dubois", "--exact"]);
        assert_code(&exact, 0, &[]);
        let exact = run(&["isometric", s(&t), s(&t), "--exact"]);
        assert_code(&exact, 0, &[]);
    }
    // Degenerate in exact arithmetic too: all-zero lengths, a zero-area face.
    let zero = write(
        dir.path(),
        "zero.json",
        r#"{"polygons":[{"lengths":[0,0,0],"vertices":[0,0,0]},{"lengths":[0,0,0],"vertices":[0,0,0]}],
            "matching":[[[0,0],[1,0]],[[0,1],[1,1]],[[0,2],[1,2]]]}"#,
    );
    let flat_face = write(
        dir.path(),
        "flat.obj",
        "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n",
    );
    let collinear = write(
        dir.path(),
        "collinear.json",
        r#"{"polygons":[{"corners":[[0,0],[1,0],[2,0]]},{"corners":[[1,0],[3,0],[2,0]]}],
            "matching":[[[0,0],[1,1]],[[0,1],[1,2]],[[0,2],[1,0]]]}"#,
    );
    for (file, needle) in [
        (&zero, "not positive"),
        (&flat_face, "zero-area"),
        (&collinear, "zero-area"),
    ] {
        let out = run(&["delaunay", s(file), "--json"]);
        assert_code(&out, 2, &[s(file), needle]);
        for method in ["auto", "flip", "voronoi", "dubois"] {
            let out = run(&["isometric", s(file), s(file), "--method", method]);
            assert_code(&out, 2, &[s(file), needle]);
        }
    }
}

/// Item 4: `--time-limit SECONDS` stops any command with exit 2, naming the step then running,
/// leaving no output and no temporary file; a command within its limit is unaffected.
#[test]
fn item4_time_limit_stops_a_long_run_with_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    // T_x at x = 10^5: the exact wave has about x events (minutes).
    let t = flat_torus(dir.path(), "100000");
    let out = dir.path().join("d.json");
    let started = std::time::Instant::now();
    let run_out = run(&[
        "delaunay",
        s(&t),
        "--method",
        "voronoi",
        "--exact",
        "-o",
        s(&out),
        "--time-limit",
        "0.5",
    ]);
    assert!(started.elapsed().as_secs_f64() < 30.0);
    assert_code(
        &run_out,
        2,
        &["--time-limit", "while running the Voronoi wave"],
    );
    let left: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    assert_eq!(left, [t.file_name().unwrap().to_str().unwrap()]);
    // Within the limit: the same command on a small x.
    let small = flat_torus(dir.path(), "10");
    let ok = run(&[
        "delaunay",
        s(&small),
        "--method",
        "voronoi",
        "--exact",
        "-o",
        s(&out),
        "--time-limit",
        "60",
    ]);
    assert_code(&ok, 0, &[]);
    let tet = dir.path().join("tet.obj");
    let ok = run(&[
        "generate",
        "tetrahedron",
        "-o",
        s(&tet),
        "--time-limit",
        "60",
    ]);
    assert_code(&ok, 0, &[]);
    for bad in ["0", "-1", "nan", "abc"] {
        let option = format!("--time-limit={bad}");
        let refused = run(&["generate", "tetrahedron", "-o", s(&tet), &option]);
        assert_code(&refused, 2, &["--time-limit"]);
    }
}

/// `generate intrinsic-flips --input INPUT --count COUNT --seed SEED -o OUTPUT`.
fn intrinsic_flips(input: &Path, count: &str, seed: u64, output: &Path) -> Output {
    let seed = seed.to_string();
    run(&[
        "generate",
        "intrinsic-flips",
        "--input",
        s(input),
        "--count",
        count,
        "--seed",
        &seed,
        "-o",
        s(output),
    ])
}

/// The doubled right triangle with legs 1 and 1e-12 (a thin pillowcase), by exact corners.
const THIN_RIGHT_PILLOWCASE: &str = r#"{"polygons": [
  {"corners": [[0, 0], [1, 0], [0, "1/1000000000000"]]},
  {"corners": [[0, 0], [0, "-1/1000000000000"], [1, 0]]}],
 "matching": [[[0, 0], [1, 2]], [[0, 1], [1, 1]], [[0, 2], [1, 0]]]}"#;

/// Item 5: the exact wave ends with 0 non-Delaunay edges, counted exactly (the f64 count of the
/// needle said 1); what it writes is read back.
#[test]
fn item5_exact_voronoi_on_a_thin_pillowcase_is_delaunay() {
    let dir = tempfile::tempdir().unwrap();
    let input = write(dir.path(), "pillowcase.json", THIN_RIGHT_PILLOWCASE);
    let output = dir.path().join("d.json");
    let out = run(&[
        "delaunay",
        s(&input),
        "--method",
        "voronoi",
        "--exact",
        "--json",
        "-o",
        s(&output),
    ]);
    assert_code(&out, 0, &[]);
    let report: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    assert_eq!(report["non_delaunay_edges"], 0, "{report}");
    let out = run(&[
        "delaunay",
        s(&output),
        "--method",
        "voronoi",
        "--exact",
        "--json",
    ]);
    assert_code(&out, 0, &[]);
}

/// Item 5: `generate intrinsic-flips` refuses an input with a zero-area face (what every
/// reader refuses) and writes nothing; over many seeds and perturbations every file it writes
/// is read back by `delaunay`.
#[test]
fn item5_intrinsic_flips_writes_only_what_it_reads() {
    use rand::{RngExt, SeedableRng};
    let dir = tempfile::tempdir().unwrap();
    // A face made flat (its third corner on the midpoint of the other two): refused, exit 2.
    let flat = write(
        dir.path(),
        "flat.obj",
        "v 0 0 0\nv 2 0 0\nv 1 0 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n",
    );
    let output = dir.path().join("f.json");
    let out = intrinsic_flips(&flat, "10", 1, &output);
    assert_code(&out, 2, &["flat.obj", "zero-area"]);
    assert!(!output.exists());
    let base =
        surftopo_mesh::generators::subdivide_midpoint(&surftopo_mesh::generators::icosphere(1), 1);
    let (positions, triangles) = base.to_triangles();
    for seed in 0..12u64 {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let amount = 10f64.powf(rng.random_range(-9.0..-3.0));
        let moved: Vec<[f64; 3]> = positions
            .iter()
            .map(|p| p.map(|x| x + amount * rng.random_range(-1.0..1.0)))
            .collect();
        let obj = dir.path().join(format!("m{seed}.obj"));
        let soup = surftopo_io::PolygonSoup::from_triangles(moved, &triangles);
        surftopo_io::write_path(&obj, &soup, &surftopo_io::WriteOptions::default()).unwrap();
        let flipped = dir.path().join(format!("f{seed}.json"));
        let count = ["10", "100", "1000"][seed as usize % 3];
        let out = intrinsic_flips(&obj, count, seed, &flipped);
        assert_code(&out, 0, &[]);
        let out = run(&["delaunay", s(&flipped), "--json"]);
        assert_code(&out, 0, &[]);
    }
}

/// Item 5: a mesh and its own intrinsic flips, one vertex moved within 1e-12 of another, at
/// scales 1, 1e-6 and 1e6: isometric or undecidable (exit 0 or 3), never "not isometric".
#[test]
fn item5_a_vertex_near_another_is_not_a_proof_of_difference() {
    let dir = tempfile::tempdir().unwrap();
    let base =
        surftopo_mesh::generators::subdivide_midpoint(&surftopo_mesh::generators::tetrahedron(), 1);
    let (mut positions, triangles) = base.to_triangles();
    let [v, w, _] = triangles[0].map(|x| x as usize);
    positions[v] = positions[w].map(|x| x + 1.25e-12);
    for scale in [1.0, 1e-6, 1e6] {
        let scaled: Vec<[f64; 3]> = positions.iter().map(|p| p.map(|x| x * scale)).collect();
        let obj = dir.path().join(format!("m{scale}.obj"));
        let soup = surftopo_io::PolygonSoup::from_triangles(scaled, &triangles);
        surftopo_io::write_path(&obj, &soup, &surftopo_io::WriteOptions::default()).unwrap();
        let flipped = dir.path().join(format!("f{scale}.json"));
        let out = intrinsic_flips(&obj, "50", 1, &flipped);
        assert_code(&out, 0, &[]);
        let out = run(&["isometric", s(&obj), s(&flipped)]);
        assert!(
            matches!(out.status.code(), Some(0 | 3)),
            "scale {scale}: {}",
            stderr(&out)
        );
    }
}

/// Item 2 of the remaining list: exact corners that doubles cannot hold (Dubois' `T_x` for
/// `x = 10³⁰` by exact integers, whose rounded lengths make a triangle of area 5·10²⁹ instead of
/// 1; a square torus offset by 10³⁰, whose rounded corners collapse) are never computed on
/// silently without `--exact`: `delaunay` by every method, with or without `--tessellation`,
/// exits 4 naming `--exact` and writes nothing; `isometric` says undecidable in double
/// precision (exit 3) naming `--exact`; a surface with boundary (which exact arithmetic does
/// not take) exits 4 saying so. With `--exact` the same files are computed; exact corners that
/// doubles hold closely enough (`x = 1000/3`) still run in double precision.
#[test]
fn exact_corners_beyond_doubles_are_not_rounded_silently() {
    let dir = tempfile::tempdir().unwrap();
    let (x, x1) = (
        "1000000000000000000000000000000",
        "1000000000000000000000000000001",
    );
    let torus = flat_torus(dir.path(), x);
    let square = write(
        dir.path(),
        "square.json",
        &format!(
            r#"{{"polygons":[{{"corners":[["{x}",0],["{x1}",0],["{x1}",1],["{x}",1]]}}],
                "matching":[[[0,0],[0,2]],[[0,1],[0,3]]]}}"#
        ),
    );
    // The same torus cut into two triangles: their lengths (measured exactly, rounded once:
    // 1, 1, √2) are what double precision computes on, and they hold the surface, so every
    // method runs; exactly, the same.
    let halves = write(
        dir.path(),
        "halves.json",
        &format!(
            r#"{{"polygons":[{{"corners":[["{x}",0],["{x1}",0],["{x1}",1]]}},
                             {{"corners":[["{x}",0],["{x1}",1],["{x}",1]]}}],
                "matching":[[[0,0],[1,1]],[[0,1],[1,2]],[[0,2],[1,0]]]}}"#
        ),
    );
    let tess = dir.path().join("tess.json");
    for file in [&torus, &square] {
        for method in ["auto", "flip", "voronoi", "dubois"] {
            let out = run(&["delaunay", s(file), "--json", "--method", method]);
            assert_code(&out, 4, &[s(file), "cannot hold", "--exact"]);
            let out = run(&[
                "delaunay",
                s(file),
                "--method",
                method,
                "--tessellation",
                s(&tess),
            ]);
            assert_code(&out, 4, &[s(file), "cannot hold", "--exact"]);
            assert!(!tess.exists());
            let out = run(&["isometric", s(file), s(&torus), "--method", method]);
            assert_code(&out, 3, &["cannot hold", "--exact"]);
            assert_eq!(stdout(&out), "undecidable in double precision\n");
        }
    }
    for method in ["auto", "flip", "voronoi", "dubois"] {
        let out = run(&["delaunay", s(&halves), "--json", "--method", method]);
        assert_code(&out, 0, &[]);
    }
    for file in [&torus, &halves] {
        let exact = run(&["delaunay", s(file), "--json", "--method", "auto", "--exact"]);
        assert_code(&exact, 0, &[]);
        let report: serde_json::Value = serde_json::from_str(&stdout(&exact)).unwrap();
        assert_eq!(report["non_delaunay_edges"], 0, "{report}");
    }
    // A triangle with free sides: read on its cover in double precision only.
    let open = write(
        dir.path(),
        "open.json",
        &format!(
            r#"{{"polygons":[{{"corners":[["0","0"],["1","0"],["{x}","2"]]}}],"matching":[]}}"#
        ),
    );
    let out = run(&["delaunay", s(&open), "--json"]);
    assert_code(&out, 4, &[s(&open), "cannot hold", "closed orientable"]);
    // Exact corners doubles hold to far below the tolerances: computed in double precision.
    let third = flat_torus(dir.path(), "1000/3");
    let text = std::fs::read_to_string(&third).unwrap();
    assert!(text.contains("\"1000/3\""), "{text}");
    let out = run(&["delaunay", s(&third), "--json", "--method", "flip"]);
    assert_code(&out, 0, &[]);
}

/// Item 3 of the remaining list: the thin pillowcase (about 200 bytes; a right triangle of
/// height 10⁻¹², whose Section 8 caps are far below the rounded wave's resolution) under
/// `--method dubois` in double precision stops at once with a numerical failure naming `--exact`
/// (exit 4), well within the test's own generous `--time-limit` (which would be exit 2);
/// `--exact` computes it.
#[test]
fn thin_pillowcase_in_double_precision_stops_naming_exact() {
    let dir = tempfile::tempdir().unwrap();
    let input = write(dir.path(), "pillowcase.json", THIN_RIGHT_PILLOWCASE);
    assert!(std::fs::metadata(&input).unwrap().len() < 300);
    let dubois = |arithmetic: &[&str]| {
        let base = ["delaunay", s(&input), "--json", "--method", "dubois"];
        run(&[&base[..], arithmetic, &["--time-limit", "120"]].concat())
    };
    let out = dubois(&[]);
    assert_code(&out, 4, &[s(&input), "cannot resolve", "--exact"]);
    let out = dubois(&["--exact"]);
    assert_code(&out, 0, &[]);
    let report: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    assert_eq!(report["non_delaunay_edges"], 0, "{report}");
}
