//! `surftopo census` and `surftopo isomorphic`: exit codes, outputs read back and checked by the
//! census library's verifiers, resumable runs, Ctrl-C.

mod common;

use common::{json_of, surftopo, write};
use serde_json::Value;
use surftopo_census::{Triangulation, canonical_form, parse_lutz};

fn run_json(args: &[&str], dir: &std::path::Path) -> Value {
    json_of(surftopo().current_dir(dir).args(args).arg("--json"), &[])
}

#[test]
fn census_of_the_torus_writes_21_irreducible_triangulations() {
    let dir = tempfile::tempdir().unwrap();
    let out = surftopo()
        .current_dir(dir.path())
        .args(["census", "torus", "-o", "torus.txt"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let stdout = String::from_utf8_lossy(&out.stdout);
    for line in [
        "7 vertices: 1 (1 chiral)",
        "8 vertices: 4",
        "9 vertices: 15",
        "10 vertices: 1",
    ] {
        assert!(stdout.contains(line), "{stdout}");
    }
    assert!(
        stdout.contains("21 irreducible triangulations of torus"),
        "{stdout}"
    );
    let text = std::fs::read_to_string(dir.path().join("torus.txt")).unwrap();
    let list = parse_lutz(&text).unwrap();
    assert_eq!(list.len(), 21);
    for t in &list {
        assert!(t.is_irreducible() && t.is_orientable() && t.euler_characteristic() == 0);
        assert_eq!(canonical_form(t).faces(), t.faces(), "canonical labelling");
    }
    let v = run_json(&["census", "klein-bottle", "-o", "kb.txt"], dir.path());
    for key in [
        "surface",
        "total",
        "chiral",
        "complete",
        "searched_up_to",
        "bound",
        "mirror_images_identified",
        "per_vertex_count",
        "candidates",
        "duplicates",
        "nodes",
        "seconds",
    ] {
        assert!(v.get(key).is_some(), "missing {key} in {v}");
    }
    assert_eq!(v["total"], 29);
    assert_eq!(v["complete"], true);
    let kb = parse_lutz(&std::fs::read_to_string(dir.path().join("kb.txt")).unwrap()).unwrap();
    assert!(kb.iter().all(|t| !t.is_orientable() && t.is_irreducible()));
}

#[test]
fn bad_requests_exit_2_before_any_work() {
    let dir = tempfile::tempdir().unwrap();
    for (args, says) in [
        (
            vec!["census", "sfere", "-o", "x.txt"],
            "unknown surface `sfere`",
        ),
        (vec!["census", "n3", "-o", "x.txt"], "--max-vertices"),
        (vec!["census", "genus-2", "-o", "x.txt"], "beyond reach"),
        (vec!["census", "torus", "-o", "missing/x.txt"], "no folder"),
        (
            vec!["census", "torus", "-o", "x.txt", "--checkpoint", "x.txt"],
            "named by both",
        ),
    ] {
        let out = surftopo()
            .current_dir(dir.path())
            .args(&args)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            stderr.starts_with("error:") && stderr.contains(says),
            "{args:?}: {stderr}"
        );
    }
    let out = surftopo()
        .current_dir(dir.path())
        .args(["census", "genus-2", "-o", "x.txt"])
        .output()
        .unwrap();
    assert!(String::from_utf8_lossy(&out.stderr).contains("estimated"));
    assert!(!dir.path().join("x.txt").exists());
}

#[test]
fn a_cut_census_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let out = surftopo()
        .current_dir(dir.path())
        .args([
            "census",
            "torus",
            "-o",
            "t.txt",
            "--max-vertices",
            "8",
            "--json",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("complete up to there, not for the surface")
    );
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["complete"], false);
    assert_eq!(v["total"], 5);
}

#[test]
fn a_checkpoint_resumes_a_run() {
    let dir = tempfile::tempdir().unwrap();
    let first = run_json(
        &[
            "census",
            "projective-plane",
            "-o",
            "a.txt",
            "--checkpoint",
            "ck.json",
        ],
        dir.path(),
    );
    let checkpoint: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("ck.json")).unwrap())
            .unwrap();
    assert_eq!(checkpoint["complete"], true);
    assert_eq!(first["resumed_jobs"], 0);
    let second = run_json(
        &[
            "census",
            "projective-plane",
            "-o",
            "b.txt",
            "--checkpoint",
            "ck.json",
        ],
        dir.path(),
    );
    assert_eq!(
        second["resumed_jobs"],
        checkpoint["jobs"].as_array().unwrap().len()
    );
    assert_eq!(
        std::fs::read(dir.path().join("a.txt")).unwrap(),
        std::fs::read(dir.path().join("b.txt")).unwrap()
    );
    // A checkpoint of another surface is refused.
    let out = surftopo()
        .current_dir(dir.path())
        .args(["census", "torus", "-o", "c.txt", "--checkpoint", "ck.json"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn ctrl_c_leaves_no_census_file_and_a_checkpoint_marked_incomplete() {
    let dir = tempfile::tempdir().unwrap();
    let mut child = std::process::Command::new(assert_cmd::cargo::cargo_bin("surftopo"))
        .current_dir(dir.path())
        .args([
            "census",
            "n3",
            "--max-vertices",
            "11",
            "-o",
            "n3.txt",
            "--checkpoint",
            "ck.json",
        ])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let checkpoint = dir.path().join("ck.json");
    let start = std::time::Instant::now();
    while !checkpoint.exists() && start.elapsed().as_secs() < 120 {
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    assert!(checkpoint.exists(), "no job finished in two minutes");
    std::process::Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(130));
    assert!(!dir.path().join("n3.txt").exists());
    let v: Value = serde_json::from_str(&std::fs::read_to_string(&checkpoint).unwrap()).unwrap();
    assert_eq!(v["complete"], false);
    assert!(!v["jobs"].as_array().unwrap().is_empty());
}

/// A census member as an OFF file, its vertices permuted by `shift` (i -> (i + shift) mod n).
fn off(t: &Triangulation, shift: u32) -> String {
    let n = t.vertex_count() as u32;
    let mut text = format!("OFF\n{} {} 0\n", n, t.face_count());
    for i in 0..n {
        text.push_str(&format!("{i} {} 0\n", i * i));
    }
    for f in t.faces() {
        let g = f.map(|v| (v + shift) % n);
        text.push_str(&format!("3 {} {} {}\n", g[0], g[2], g[1]));
    }
    text
}

#[test]
fn isomorphic_compares_triangulations_of_any_surface() {
    let dir = tempfile::tempdir().unwrap();
    let census = |name: &str| {
        surftopo_census::census(
            surftopo_census::SurfaceKind::parse(name).unwrap(),
            Default::default(),
        )
        .unwrap()
        .triangulations
    };
    let kb = census("klein-bottle");
    let a = write(dir.path(), "a.off", &off(&kb[3].to_triangulation(), 0));
    let b = write(dir.path(), "b.off", &off(&kb[3].to_triangulation(), 5));
    let c = write(dir.path(), "c.off", &off(&kb[4].to_triangulation(), 0));
    let out = surftopo()
        .arg("isomorphic")
        .arg(&a)
        .arg(&b)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(String::from_utf8_lossy(&out.stdout), "isomorphic\n");
    let out = surftopo()
        .arg("isomorphic")
        .arg(&a)
        .arg(&c)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(String::from_utf8_lossy(&out.stdout), "not isomorphic\n");
    let out = surftopo()
        .arg("isomorphic")
        .arg(&a)
        .arg(&b)
        .arg("--json")
        .output()
        .unwrap();
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["isomorphic"], true);
    assert_eq!(v["orientable"], serde_json::json!([false, false]));
    // A torus member against its mirror image: isomorphic (mirror images identified).
    let torus = census("torus");
    let t = write(dir.path(), "t.off", &off(&torus[0].to_triangulation(), 0));
    let mirror = torus[0].to_triangulation();
    let mirror =
        Triangulation::new(mirror.faces().iter().map(|f| [f[1], f[0], f[2]]).collect()).unwrap();
    let m = write(dir.path(), "m.off", &off(&mirror, 2));
    let out = surftopo()
        .arg("isomorphic")
        .arg(&t)
        .arg(&m)
        .arg("--json")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["chiral"], serde_json::json!([true, true]));
    // An open surface: exit 2, naming the file and the edge.
    let open = "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 3 1\n3 1 3 2\n";
    let bad = write(dir.path(), "open.off", open);
    let out = surftopo()
        .arg("isomorphic")
        .arg(&a)
        .arg(&bad)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("open.off") && stderr.contains("edge ("),
        "{stderr}"
    );
}
