//! Issue 23, "hostile input, faults and precision": one test per item, on inputs made here
//! (a gzip bomb is streamed from a generator, never stored).

mod common;

use common::{surftopo, write};
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

const TETRA: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";

fn binary() -> PathBuf {
    assert_cmd::cargo::cargo_bin("surftopo")
}

fn run(args: &[&str]) -> Output {
    surftopo().args(args).output().unwrap()
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// The command failed with `code` and an `error:` line containing every one of `needles`.
fn assert_fails(out: &Output, code: i32, needles: &[&str]) {
    let err = stderr(out);
    assert_eq!(out.status.code(), Some(code), "{err}");
    assert!(err.contains("error: "), "no error line: {err}");
    for needle in needles {
        assert!(err.contains(needle), "expected '{needle}' in: {err}");
    }
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Files in `dir` whose name holds `.tmp-` (temporaries of an atomic write).
fn temporaries(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains(".tmp-"))
        .collect()
}

fn write_obj(path: &Path, surface: &surftopo_mesh::Surface, scale: f64) {
    let (mut positions, triangles) = surface.to_triangles();
    for p in &mut positions {
        for c in p.iter_mut() {
            *c *= scale;
        }
    }
    let soup = surftopo_io::PolygonSoup::from_triangles(positions, &triangles);
    surftopo_io::write_path(path, &soup, &surftopo_io::WriteOptions::default()).unwrap();
}

/// Item 1: decompression, inputs and generators are bounded by `--max-input-bytes` and
/// `--max-elements` (typed errors, exit 2), and a failed reservation is an error, not an abort.
#[test]
fn item1_memory_is_bounded() {
    let dir = tempfile::tempdir().unwrap();
    // 64 MiB of OBJ vertex lines, gzipped as they are generated (about 200 kB on disk).
    let bomb = dir.path().join("bomb.obj.gz");
    let mut encoder = flate2::write::GzEncoder::new(
        std::fs::File::create(&bomb).unwrap(),
        flate2::Compression::fast(),
    );
    let block = b"v 0 0 0\n".repeat(8192);
    for _ in 0..1024 {
        encoder.write_all(&block).unwrap();
    }
    encoder.finish().unwrap();
    assert!(std::fs::metadata(&bomb).unwrap().len() < 1 << 20);
    let out = run(&["info", s(&bomb), "--max-input-bytes", "4000000"]);
    assert_fails(
        &out,
        2,
        &["bomb.obj.gz", "limit of 4000000 bytes", "--max-input-bytes"],
    );

    // An endless input (a link to /dev/zero) under a 400 MB address-space limit: the default cap
    // (1 GiB) is above what the machine allows, so the reservation fails: a typed error.
    let zero = dir.path().join("zero.obj");
    std::os::unix::fs::symlink("/dev/zero", &zero).unwrap();
    let out = Command::new("sh")
        .arg("-c")
        .arg(format!(
            "ulimit -v 400000 && exec '{}' info '{}'",
            s(&binary()),
            s(&zero)
        ))
        .output()
        .unwrap();
    assert_fails(&out, 2, &["zero.obj", "cannot reserve"]);
    // And with a cap below the machine's limit, the cap speaks first.
    let out = run(&["info", s(&zero), "--max-input-bytes", "1000000"]);
    assert_fails(&out, 2, &["limit of 1000000 bytes"]);

    // Generators are checked before allocating, naming the options.
    let target = dir.path().join("g.obj");
    for (args, named) in [
        (
            &["generate", "genus", "--genus", "1000000"][..],
            "--genus 1000000",
        ),
        (
            &["generate", "torus", "--m", "100000", "--n", "100000"],
            "--m 100000",
        ),
        (
            &[
                "generate",
                "icosphere",
                "--subdivisions",
                "2",
                "--subdivide",
                "9",
            ],
            "--subdivide 9",
        ),
        (
            &["generate", "flat-torus", "--x", "2", "--m", "20000"],
            "--m 20000",
        ),
    ] {
        // An intrinsic generator writes portalgon JSON (any other output is refused first).
        let target = match args[1] {
            "flat-torus" => target.with_extension("json"),
            _ => target.clone(),
        };
        let start = Instant::now();
        let out = surftopo()
            .args(args)
            .arg("-o")
            .arg(&target)
            .output()
            .unwrap();
        assert_fails(&out, 2, &[named, "--max-elements"]);
        assert!(start.elapsed() < Duration::from_secs(5));
        assert!(!target.exists());
    }
    // Inputs are checked against --max-elements before the mesh is built.
    let tetra = write(dir.path(), "t.obj", TETRA);
    assert_fails(
        &run(&["info", s(&tetra), "--max-elements", "3"]),
        2,
        &["4 vertices", "--max-elements 3"],
    );
    surftopo().args(["info", s(&tetra)]).assert().success();
}

/// Item 2: a surface against itself and against an intrinsic re-triangulation, with nearly flat
/// vertices (angle defects near the flatness tolerance, from perturbations of 1e-10), on which the
/// plain flat-vertex removal gets stuck: isometric.
/// Different surfaces stay "not isometric".
#[test]
fn item2_isometry_never_guesses() {
    use rand::{RngExt, SeedableRng};
    let dir = tempfile::tempdir().unwrap();
    let mut surface = surftopo_mesh::generators::cavity_box(2, 1, 2000);
    let tri = surftopo_intrinsic::IntrinsicTriangulation::from_positions(
        surface.mesh.clone(),
        &surface.positions,
    )
    .unwrap();
    let flat = surftopo_intrinsic::flat_vertices(&tri, 1e-12);
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(6);
    for _ in 0..flat.len() {
        let v = flat[rng.random_range(0..flat.len())];
        let axis = rng.random_range(0..3usize);
        surface.positions[v.idx()][axis] += 1e-10 * rng.random_range(-1.0..1.0);
    }
    let a = dir.path().join("a.obj");
    write_obj(&a, &surface, 1.0);
    let out = run(&["isometric", s(&a), s(&a)]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert_eq!(String::from_utf8_lossy(&out.stdout), "isometric\n");
    let b = dir.path().join("b.json");
    surftopo()
        .args([
            "generate",
            "intrinsic-flips",
            "--input",
            s(&a),
            "--count",
            "3000",
        ])
        .args(["--seed", "6", "-o", s(&b)])
        .assert()
        .success();
    let out = run(&["isometric", s(&a), s(&b)]);
    assert!(matches!(out.status.code(), Some(0 | 3)), "{}", stderr(&out));
    // A different surface: exit 1, and a verdict on stdout.
    let other = dir.path().join("other.obj");
    write_obj(&other, &surface, 1.001);
    let out = run(&["isometric", s(&a), s(&other)]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert_eq!(String::from_utf8_lossy(&out.stdout), "not isometric\n");
}

/// Item 3: random intrinsic flips of a needle mesh keep every triangle valid, so `delaunay`
/// reads what `generate intrinsic-flips` writes.
#[test]
fn item3_intrinsic_flips_of_needles_stay_valid() {
    let dir = tempfile::tempdir().unwrap();
    let mut needles = surftopo_mesh::generators::torus(24, 6);
    for p in &mut needles.positions {
        p[1] *= 1e-7; // a torus squashed across its axis: needles of aspect ratio ~1e7
    }
    let input = dir.path().join("needles.obj");
    write_obj(&input, &needles, 1.0);
    for seed in ["1", "2", "3"] {
        let flipped = dir.path().join(format!("f{seed}.json"));
        surftopo()
            .args([
                "generate",
                "intrinsic-flips",
                "--input",
                s(&input),
                "--count",
                "5000",
            ])
            .args(["--seed", seed, "-o", s(&flipped)])
            .assert()
            .success();
        let file = std::fs::File::open(&flipped).unwrap();
        let tri = surftopo_intrinsic::IntrinsicTriangulation::read_json(file, 1e-9).unwrap();
        tri.validate().unwrap();
        let out = run(&["delaunay", s(&flipped), "-o", s(&dir.path().join("d.json"))]);
        assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    }
}

/// Item 4: the mass matrix of coordinates scaled by 1e150 or 1e-100 is the unscaled one times
/// the squared scale (finite, non-zero); where the areas themselves are not representable, or
/// the parameters are absurd, a typed error and no file.
#[test]
fn item4_matrices_are_finite_and_scale_free() {
    let dir = tempfile::tempdir().unwrap();
    let tetra = surftopo_mesh::generators::icosphere(1);
    let delaunay = |input: &Path, extra: &[&str]| {
        let output = dir.path().join("d.json");
        run(&[&["delaunay", s(input), "-o", s(&output)][..], extra].concat())
    };
    let mass = |scale: f64| {
        let input = dir.path().join(format!("m{scale:e}.obj"));
        write_obj(&input, &tetra, scale);
        let (m, l) = (dir.path().join("M.mtx"), dir.path().join("L.mtx"));
        (
            delaunay(&input, &["--mass", s(&m), "--laplacian", s(&l)]),
            m,
        )
    };
    let (out, m) = mass(1.0);
    assert!(out.status.success(), "{}", stderr(&out));
    let read = |m: &Path| {
        surftopo_intrinsic::read_matrix_market(std::io::BufReader::new(
            std::fs::File::open(m).unwrap(),
        ))
        .unwrap()
    };
    let unit = read(&m);
    for (scale, square) in [(1e150, 1e300), (1e77, 1e154), (1e-100, 1e-200)] {
        let (out, m) = mass(scale);
        assert!(out.status.success(), "{scale:e}: {}", stderr(&out));
        let scaled = read(&m);
        for i in 0..unit.n {
            let (want, got) = (unit.get(i, i) * square, scaled.get(i, i));
            assert!(got.is_finite() && got > 0.0, "{scale:e}: {got}");
            assert!(
                (got - want).abs() <= 1e-12 * want,
                "{scale:e}: {got} vs {want}"
            );
        }
    }
    std::fs::remove_file(&m).unwrap();
    let (out, m) = mass(1e-170); // areas near 1e-340: below double precision
    assert_fails(&out, 2, &["mass matrix", "too small"]);
    assert!(!m.exists());
    let out = delaunay(&dir.path().join("m1e0.obj"), &["--mollify", "1e308"]);
    assert_fails(&out, 2, &["mollification epsilon 1e308"]);
    let torus = dir.path().join("t.json");
    // T_x with x = 1e300 is written by its exact corners; its lengths overflow doubles, so
    // flipping in double precision refuses it as a numerical failure naming --exact (exit 4,
    // nothing written). (The exact methods' D_x is tested in the intrinsic crate.)
    let out = run(&["generate", "flat-torus", "--x", "1e300", "-o", s(&torus)]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let tri = dir.path().join("t-delaunay.json");
    let out = run(&["delaunay", s(&torus), "-o", s(&tri)]);
    assert_fails(&out, 4, &["cannot hold", "--exact"]);
    assert!(!tri.exists());
}

/// Item 5: a truncated binary STL whose header starts with `solid` (no newline in the body) and
/// binary garbage in an OBJ are errors, not empty meshes.
#[test]
fn item5_binary_inputs_are_not_empty_meshes() {
    let dir = tempfile::tempdir().unwrap();
    let mut stl = b"solid ".to_vec();
    stl.resize(80, b'x');
    stl.extend_from_slice(&10u32.to_le_bytes());
    for k in 0..3u8 {
        let mut record = [0u8; 50];
        record[12] = k + 1; // some non-zero coordinate bytes
        stl.extend_from_slice(&record);
    }
    let path = dir.path().join("truncated.stl");
    std::fs::write(&path, &stl).unwrap();
    let target = dir.path().join("out.off");
    let out = run(&["convert", s(&path), s(&target)]);
    assert_fails(
        &out,
        2,
        &[
            "truncated.stl",
            "unexpected end of file",
            "triangle 4 of 10",
        ],
    );
    assert!(!target.exists());
    let garbage: Vec<u8> = (0..4096u32)
        .map(|i| (i * 7 % 256) as u8)
        .filter(|&b| b != b'\n')
        .collect();
    let path = dir.path().join("garbage.obj");
    std::fs::write(&path, &garbage).unwrap();
    assert_fails(
        &run(&["info", s(&path)]),
        2,
        &["garbage.obj", "no faces", "binary data at byte 0"],
    );
    let empty = write(dir.path(), "empty.off", "OFF\n0 0 0\n");
    assert_fails(&run(&["info", s(&empty)]), 2, &["empty.off: no faces"]);
}

/// Runs `args`, waits until a temporary file appears in `dir`, sends `signal` and returns the
/// exit status; `None` if the command finished before its temporary file was seen.
fn interrupt_write(args: &[&str], dir: &Path, signal: &str) -> Option<std::process::ExitStatus> {
    let mut child = Command::new(binary())
        .args(args)
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while temporaries(dir).is_empty() {
        if child.try_wait().unwrap().is_some() || start.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(Duration::from_millis(2));
    }
    let pid = child.id().to_string();
    assert!(
        Command::new("kill")
            .args(["-s", signal, &pid])
            .status()
            .unwrap()
            .success()
    );
    Some(child.wait().unwrap())
}

/// Item 6: SIGINT, SIGTERM and SIGHUP during a write remove the temporary file (and leave no
/// target); temporary names stay legal for targets with names of up to 255 bytes.
#[test]
fn item6_signals_remove_temporaries() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("big.obj.gz");
    for (signal, code) in [("TERM", 143), ("INT", 130), ("HUP", 129)] {
        let status = [7, 8].iter().find_map(|level| {
            let level = level.to_string();
            let args = [
                "generate",
                "icosphere",
                "--subdivisions",
                &level,
                "-o",
                s(&target),
            ];
            interrupt_write(&args, dir.path(), signal)
        });
        let status = status.expect("the write took long enough to be interrupted");
        assert_eq!(status.code(), Some(code), "SIG{signal}");
        assert!(
            temporaries(dir.path()).is_empty(),
            "SIG{signal}: {:?}",
            temporaries(dir.path())
        );
        assert!(!target.exists(), "SIG{signal}");
    }
    for len in [241usize, 250, 255] {
        let name = format!("{}.obj", "n".repeat(len - 4));
        let target = dir.path().join(&name);
        surftopo()
            .args(["generate", "tetrahedron", "-o", s(&target)])
            .assert()
            .success();
        assert!(target.exists());
        assert!(temporaries(dir.path()).is_empty());
    }
}

/// Item 7: control characters from input (OFF header, OBJ token, PLY keyword, JSON field name,
/// file name) are escaped in messages: no ESC or BEL byte reaches the terminal.
#[test]
fn item7_messages_escape_control_characters() {
    let dir = tempfile::tempdir().unwrap();
    let attack = "\u{1b}]0;owned\u{7}\u{1b}[2J";
    let cases = [
        (
            "header.off",
            format!("OFF{attack}\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
        ),
        (
            "token.obj",
            format!("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 {attack}\n"),
        ),
        (
            "keyword.ply",
            format!("ply\nformat ascii 1.0\n{attack}x 1\nend_header\n"),
        ),
        (
            "field.json",
            r#"{"polygons": [], "\u001b]0;owned\u0007\u001b[2J": 1}"#.to_string(),
        ),
        (
            &format!("name{attack}.obj") as &str,
            "# no vertex, no face\n".to_string(),
        ),
    ];
    for (name, text) in &cases {
        let path = write(dir.path(), name, text);
        let out = if name.ends_with(".json") {
            run(&["delaunay", s(&path), "-o", s(&dir.path().join("o.json"))])
        } else {
            run(&["info", s(&path)])
        };
        assert_eq!(out.status.code(), Some(2), "{name}");
        assert!(
            !out.stderr.iter().any(|&b| b == 0x1b || b == 0x07),
            "{name}: raw control bytes in {:?}",
            stderr(&out)
        );
        assert!(stderr(&out).contains("\\u{1b}"), "{name}: {}", stderr(&out));
    }
}

/// Item 8: one exit code (2) for every unwritable output, usage errors that say so, messages
/// naming the option or field, OS errors printed once, stdout named, `--size 0` refused, gzip
/// zero padding accepted.
#[test]
fn item8_exit_codes_and_messages() {
    let dir = tempfile::tempdir().unwrap();
    let tetra = write(dir.path(), "t.obj", TETRA);
    let missing = dir.path().join("no/such/folder");
    let torus = dir.path().join("t.json");
    surftopo()
        .args(["generate", "flat-torus", "--x", "3", "-o", s(&torus)])
        .assert()
        .success();
    for args in [
        vec!["generate", "tetrahedron", "-o", "MISSING/x.obj"],
        vec!["convert", s(&tetra), "MISSING/x.ply"],
        vec!["generate", "flat-torus", "--x", "3", "-o", "MISSING/x.json"],
        vec!["delaunay", s(&torus), "-o", "MISSING/x.json"],
        vec![
            "delaunay",
            s(&torus),
            "-o",
            "OK/d.json",
            "--laplacian",
            "MISSING/L.mtx",
        ],
        vec![
            "delaunay",
            s(&torus),
            "-o",
            "OK/d.json",
            "--mass",
            "MISSING/M.mtx",
        ],
        vec![
            "delaunay",
            s(&torus),
            "-o",
            "OK/d.json",
            "--tessellation",
            "MISSING/T.json",
        ],
        vec!["irreducible", s(&tetra), "-o", "MISSING/i.obj"],
    ] {
        let args: Vec<String> = args
            .iter()
            .map(|a| {
                a.replace("MISSING", s(&missing))
                    .replace("OK", s(dir.path()))
            })
            .collect();
        let out = surftopo().args(&args).output().unwrap();
        assert_fails(&out, 2, &["not written"]);
        assert_eq!(
            stderr(&out).matches("os error 2").count(),
            1,
            "{}",
            stderr(&out)
        );
    }
    // No command: usage with an error line.
    let out = surftopo().output().unwrap();
    assert_fails(&out, 2, &["a command is needed", "Usage:"]);
    // Messages name the field or option.
    let negative = write(
        dir.path(),
        "neg.json",
        r#"{"polygons": [{"lengths": [1, -1, 1]}, {"lengths": [1, 1, 1]}], "matching": []}"#,
    );
    let o = dir.path().join("o.json");
    let g = dir.path().join("g.obj");
    let named: [(&[&str], &str); 4] = [
        (
            &["delaunay", s(&negative), "-o", s(&o)],
            "\"lengths\"[1] = -1 is negative",
        ),
        (
            &[
                "generate",
                "flat-torus",
                "--x",
                "2",
                "--m",
                "0",
                "-o",
                s(&torus),
            ],
            "parameter m = 0",
        ),
        (
            &["generate", "flat-torus", "--x", "nan", "-o", s(&torus)],
            "invalid value 'nan' for '--x <X>'",
        ),
        (
            &["generate", "genus", "--size", "0", "-o", s(&g)],
            "--size must be at least 1",
        ),
    ];
    for (args, needle) in named {
        assert_fails(&run(args), 2, &[needle]);
    }
    // An OS error once.
    let out = run(&["info", s(&dir.path().join("absent.obj"))]);
    assert_fails(&out, 2, &["absent.obj"]);
    assert_eq!(
        stderr(&out).matches("os error 2").count(),
        1,
        "{}",
        stderr(&out)
    );
    // A full stdout is named.
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let out = Command::new(binary())
        .args(["info", s(&tetra)])
        .stdout(full)
        .output()
        .unwrap();
    assert_fails(&out, 2, &["stdout: not written"]);
    // `demo --out` on an existing file.
    let out = run(&["demo", "--out", s(&tetra)]);
    assert_fails(&out, 2, &["t.obj: not written"]);
    // gzip: zero padding after the members is accepted, other trailing bytes are not.
    let mut gz = Vec::new();
    let mut encoder = flate2::write::GzEncoder::new(&mut gz, flate2::Compression::default());
    encoder.write_all(TETRA.as_bytes()).unwrap();
    encoder.finish().unwrap();
    let padded = dir.path().join("padded.obj.gz");
    std::fs::write(&padded, [&gz[..], &[0u8; 1024]].concat()).unwrap();
    surftopo().args(["info", s(&padded)]).assert().success();
    let trailing = dir.path().join("trailing.obj.gz");
    std::fs::write(&trailing, [&gz[..], b"\0\0junk"].concat()).unwrap();
    assert_fails(&run(&["info", s(&trailing)]), 2, &["trailing garbage"]);
}

/// Item 9: flip counts are bounded by the mesh size (a message naming the option), and a long
/// run stops at once on SIGINT.
#[test]
fn item9_work_is_bounded_and_interruptible() {
    let dir = tempfile::tempdir().unwrap();
    let out_path = dir.path().join("i.obj");
    let start = Instant::now();
    let out = run(&[
        "generate",
        "icosphere",
        "--subdivisions",
        "2",
        "--flips",
        "1000000000000",
        "-o",
        s(&out_path),
    ]);
    assert_fails(
        &out,
        2,
        &["--flips 1000000000000", "at most 100 flips per edge"],
    );
    let tetra = write(dir.path(), "t.obj", TETRA);
    let out = run(&[
        "generate",
        "intrinsic-flips",
        "--input",
        s(&tetra),
        "--count",
        "1000000000000000",
        "-o",
        s(&dir.path().join("f.json")),
    ]);
    assert_fails(
        &out,
        2,
        &["--count 1000000000000000", "at most 100 flips per edge"],
    );
    assert!(start.elapsed() < Duration::from_secs(10));
    // A long but bounded run (49M flips allowed on icosphere(7)) is interrupted at once.
    let mut child = Command::new(binary())
        .args([
            "generate",
            "icosphere",
            "--subdivisions",
            "7",
            "--flips",
            "40000000",
        ])
        .args(["-o", s(&out_path)])
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_millis(500));
    let pid = child.id().to_string();
    let sent = Instant::now();
    assert!(
        Command::new("kill")
            .args(["-s", "INT", &pid])
            .status()
            .unwrap()
            .success()
    );
    let status = child.wait().unwrap();
    assert!(sent.elapsed() < Duration::from_secs(2));
    assert_eq!(status.code(), Some(130));
    assert!(!out_path.exists());
}
