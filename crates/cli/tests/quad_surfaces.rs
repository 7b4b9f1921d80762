//! `surftopo quad` on every kind of surface `generate` makes (with boundary, non-orientable,
//! closed non-orientable, several pieces) with every algorithm and objective, with and without
//! `--all-quads`: the output read back (by surftopo-io and by the independent OBJ statement
//! reader of the testkit), checked against the input's triangles and the JSON figures; LRS's
//! refusal of non-orientable pieces; the per-vertex attributes of added vertices; bad input.

mod common;

use common::{generate, json_of, surftopo, write};
use serde_json::Value;
use std::collections::HashMap;
use std::path::Path;

/// The faces of an OBJ file by the testkit's statement reader (1-based indices made 0-based).
fn obj_faces(path: &Path) -> (usize, Vec<Vec<u32>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let vertices = surftopo_testkit::obj_text::statements(&text, "v").len();
    let faces = surftopo_testkit::obj_text::statements(&text, "f")
        .iter()
        .map(|f| {
            f.iter()
                .map(|c| c.split('/').next().unwrap().parse::<u32>().unwrap() - 1)
                .collect()
        })
        .collect();
    (vertices, faces)
}

/// Checks one output against the input's triangles and the JSON: every input triangle is a
/// triangle left, or half of one quad (the quad's corners 0-2 its diagonal), or (all quads)
/// split at an added vertex (corner 0) into a quad; counts agree with the figures.
fn check(name: &str, input: &[[u32; 3]], output: &Path, json: &Value, all_quads: bool, lrs: bool) {
    let (vertices, faces) = obj_faces(output);
    let soup = surftopo_io::read_path(output).unwrap();
    assert_eq!(soup.vertex_count(), vertices, "{name}");
    let n = input.iter().flatten().max().map_or(0, |&v| v as usize + 1);
    let added = json["added_vertices"].as_u64().unwrap() as usize;
    let left = json["unpaired_triangles"].as_u64().unwrap() as usize;
    let bound = json["deficiency_lower_bound"].as_u64().unwrap() as usize;
    assert_eq!(vertices, n + added, "{name}: vertices");
    let quads: Vec<&Vec<u32>> = faces.iter().filter(|f| f.len() == 4).collect();
    let triangles: Vec<&Vec<u32>> = faces.iter().filter(|f| f.len() == 3).collect();
    assert_eq!(quads.len() + triangles.len(), faces.len(), "{name}");
    assert_eq!(triangles.len(), left, "{name}");
    if all_quads {
        assert_eq!((left, added), (0, bound), "{name}");
    } else {
        assert_eq!((left, added), (bound, 0), "{name}");
    }
    assert_eq!(2 * quads.len() + left, input.len() + added, "{name}");
    if lrs {
        return;
    }
    let key = |t: [u32; 3]| {
        let mut k = t;
        k.sort_unstable();
        k
    };
    let mut count: HashMap<[u32; 3], usize> = input.iter().map(|&t| (key(t), 0)).collect();
    let mut hit = |t: [u32; 3]| {
        *count
            .get_mut(&key(t))
            .unwrap_or_else(|| panic!("{name}: {t:?} is no input triangle")) += 1;
    };
    for q in &quads {
        if q[0] as usize >= n {
            hit([q[3], q[1], q[2]]);
        } else {
            hit([q[0], q[2], q[3]]);
            hit([q[2], q[0], q[1]]);
        }
    }
    for t in &triangles {
        hit([t[0], t[1], t[2]]);
    }
    assert!(
        count.values().all(|&c| c == 1),
        "{name}: a triangle not used once"
    );
}

fn quad_json(input: &Path, output: &Path, args: &[&str]) -> Value {
    let mut quad = surftopo();
    quad.arg("quad")
        .arg(input)
        .arg("-o")
        .arg(output)
        .arg("--json")
        .args(args);
    json_of(&mut quad, &[])
}

/// `surftopo quad INPUT -o OUTPUT ARGS`.
fn quad(input: &Path, output: &Path, args: &[&str]) -> assert_cmd::Command {
    let mut cmd = surftopo();
    cmd.arg("quad").arg(input).arg("-o").arg(output).args(args);
    cmd
}

#[test]
fn quad_takes_every_surface_generate_makes() {
    let dir = tempfile::tempdir().unwrap();
    let kinds: [(&str, &[&str], usize); 8] = [
        ("disk.obj", &["disk", "--n", "5"], 1),
        ("annulus.obj", &["annulus", "--m", "9", "--n", "3"], 1),
        ("mobius.obj", &["mobius-band", "--m", "9", "--n", "3"], 1),
        ("rp2.obj", &["projective-plane", "--subdivide", "1"], 1),
        ("kb.obj", &["klein-bottle", "--m", "8", "--n", "6"], 1),
        ("n3.obj", &["non-orientable", "--crosscaps", "3"], 1),
        (
            "holes.obj",
            &[
                "genus",
                "--genus",
                "2",
                "--size",
                "3",
                "--cut-holes",
                "3",
                "--seed",
                "4",
            ],
            1,
        ),
        (
            "pieces.obj",
            &[
                "torus",
                "--m",
                "7",
                "--n",
                "5",
                "--cut-holes",
                "1",
                "--copies",
                "2",
            ],
            2,
        ),
    ];
    let mut deficient = 0;
    // A middle triangle with an ear on each side: two triangles left by any pairing.
    let ears = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n\
                f 1 2 3\nf 2 1 4\nf 3 2 5\nf 1 3 6\n";
    write(dir.path(), "ears.obj", ears);
    let written: [(&str, &[&str], usize); 1] = [("ears.obj", &[], 1)];
    for (file, args, pieces) in written.into_iter().chain(kinds) {
        let input = if args.is_empty() {
            dir.path().join(file)
        } else {
            generate(dir.path(), file, args)
        };
        let triangles = surftopo_io::read_path(&input).unwrap().triangles().unwrap();
        let non_orientable = ["mobius.obj", "rp2.obj", "kb.obj", "n3.obj"].contains(&file);
        let runs = ["sg", "ps", "lrs", "ds", "ks"]
            .map(|a| vec!["--algorithm", a])
            .into_iter()
            .chain(["quality", "quality-fast"].map(|o| vec!["--objective", o]));
        for run in runs {
            for all_quads in [false, true] {
                let mut args = run.clone();
                if all_quads {
                    args.push("--all-quads");
                }
                let name = format!("{file} {args:?}");
                let output = dir.path().join("out.obj");
                let _ = std::fs::remove_file(&output);
                let lrs = run[1] == "lrs";
                if lrs && non_orientable {
                    let mut cmd = quad(&input, &output, &args);
                    common::refused(&mut cmd, "is non-orientable", &name);
                    assert!(!output.exists(), "{name}");
                    continue;
                }
                let json = quad_json(&input, &output, &args);
                check(&name, &triangles, &output, &json, all_quads, lrs);
                deficient += usize::from(json["deficiency_lower_bound"].as_u64() > Some(0));
                match json.get("components") {
                    Some(list) => {
                        let list = list.as_array().unwrap();
                        assert_eq!(list.len(), pieces, "{name}");
                        for c in list {
                            for key in ["name", "faces", "quads", "unpaired_triangles"] {
                                assert!(c.get(key).is_some(), "{name}: {key}");
                            }
                        }
                    }
                    None => assert_eq!(pieces, 1, "{name}"),
                }
                if run[1] == "quality" && !all_quads {
                    assert_eq!(json["optimality_gap"], 0.0, "{name}");
                }
            }
        }
    }
    assert!(deficient >= 18, "{deficient}");
}

/// An odd fan of triangles: five around a centre (odd, one left); with `--all-quads` one vertex
/// is added at the middle of a boundary edge, its per-vertex attributes (normals, here) the mean
/// of the edge's ends; the vertex list is the input's, then the added one.
#[test]
fn all_quads_adds_a_boundary_midpoint_with_mean_attributes() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("v 0 0 0\nvn 0 0 1\n");
    for k in 0..5 {
        let a = f64::from(k) * std::f64::consts::TAU / 5.0;
        text += &format!("v {} {} 0\nvn {} 0 1\n", a.cos(), a.sin(), f64::from(k));
    }
    for k in 0..5 {
        let (b, c) = (2 + k, 2 + (k + 1) % 5);
        text += &format!("f 1//1 {b}//{b} {c}//{c}\n");
    }
    let input = write(dir.path(), "fan.obj", &text);
    let output = dir.path().join("fan-quads.obj");
    let json = quad_json(&input, &output, &["--all-quads"]);
    assert_eq!(json["added_vertices"], 1);
    assert_eq!(json["deficiency_lower_bound"], 1);
    let soup = surftopo_io::read_path(&output).unwrap();
    assert_eq!(soup.vertex_count(), 7);
    let (_, faces) = obj_faces(&output);
    assert!(faces.iter().all(|f| f.len() == 4));
    let added = soup.positions[6];
    // The midpoint of a rim edge, between two rim vertices i and j.
    let rim: Vec<usize> = (1..6)
        .filter(|&i| {
            let p = soup.positions[i];
            ((p[0] - added[0]).powi(2) + (p[1] - added[1]).powi(2)).sqrt() < 0.6
        })
        .collect();
    assert_eq!(rim.len(), 2, "{added:?}");
    let nx = soup.attributes.vertex_normals().expect("normals kept")[0];
    let values = &soup.attributes.vertex[nx].values;
    assert_eq!(values.len(), 7);
    assert_eq!(values[6], 0.5 * (values[rim[0]] + values[rim[1]]));
    // Without --all-quads: one triangle left, no vertex added.
    let json = quad_json(&input, &output, &[]);
    assert_eq!(json["unpaired_triangles"], 1);
    let (vertices, faces) = obj_faces(&output);
    assert_eq!(vertices, 6);
    assert_eq!(faces.iter().filter(|f| f.len() == 3).count(), 1);
}

/// Bad input is refused as before: a non-manifold edge named with its file, line and face, exit
/// 2, nothing written.
#[test]
fn a_non_manifold_edge_is_refused_with_its_location() {
    let dir = tempfile::tempdir().unwrap();
    let input = write(
        dir.path(),
        "fin.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n",
    );
    let output = dir.path().join("q.obj");
    for args in [vec![], vec!["--objective", "quality"], vec!["--all-quads"]] {
        let stderr = common::refused(&mut quad(&input, &output, &args), "fin.obj: line 6", "quad");
        assert!(stderr.contains("non-manifold edge (0, 1)"), "{stderr}");
        assert!(stderr.contains("face 0"), "{stderr}");
        assert!(!output.exists());
    }
}
