//! Attributes through `convert`, `quad` and `irreducible`: texture coordinates and normals
//! follow their vertex (checked by position, on outputs parsed here independently), what cannot
//! be kept is named in a warning, and `convert --ascii` / `--float` write PLY variants.

mod common;

use common::{run_ok, surftopo, write};
use std::collections::HashMap;
use std::io::Read;
use std::path::{Path, PathBuf};
use surftopo_testkit::obj_text::{corners, statements as lines};

/// A generated genus-1 OBJ whose vertex `i` has `vt` (i/1000, i/500) and `vn` (1, 0, i):
/// per-vertex attributes, written `f a/a/a`. Returns its path and its text.
fn surface_with_attributes(dir: &Path) -> (PathBuf, String) {
    let plain = dir.join("plain.obj");
    surftopo()
        .args([
            "generate", "genus", "--genus", "1", "--size", "2", "--flips", "50", "-o",
        ])
        .arg(&plain)
        .assert()
        .success();
    let text = std::fs::read_to_string(&plain).unwrap();
    let mut out = String::new();
    let n = lines(&text, "v").len();
    for v in lines(&text, "v") {
        out += &format!("v {}\n", v.join(" "));
    }
    for i in 0..n {
        out += &format!("vt {} {}\n", i as f64 / 1000.0, i as f64 / 500.0);
    }
    for i in 0..n {
        out += &format!("vn 1 0 {i}\n");
    }
    for f in lines(&text, "f") {
        let f: Vec<String> = f.iter().map(|i| format!("{i}/{i}/{i}")).collect();
        out += &format!("f {}\n", f.join(" "));
    }
    (write(dir, "attributes.obj", &out), out)
}

/// Per position (the `v` line's words), the `vt` and `vn` words of the vertex there, read
/// through the face corners of an OBJ text; also checks that every corner of a vertex agrees.
fn attributes_by_position(text: &str) -> HashMap<String, (String, String)> {
    let (v, vt, vn) = (lines(text, "v"), lines(text, "vt"), lines(text, "vn"));
    let mut out = HashMap::new();
    for (vertex, t, n) in corners(text) {
        let key = v[vertex].join(" ");
        let value = (vt[t.unwrap()].join(" "), vn[n.unwrap()].join(" "));
        let previous = out.insert(key.clone(), value.clone());
        assert!(previous.is_none_or(|p| p == value), "vertex at {key}");
    }
    out
}

#[test]
fn quad_and_irreducible_keep_each_vertex_attributes() {
    let dir = tempfile::tempdir().unwrap();
    let (input, text) = surface_with_attributes(dir.path());
    let expected = attributes_by_position(&text);
    assert_eq!(expected.len(), lines(&text, "v").len());
    for (command, name) in [("quad", "q.obj"), ("irreducible", "i.obj")] {
        let output = dir.path().join(name);
        let run = run_ok(
            surftopo().arg(command).arg(&input).arg("-o").arg(&output),
            command,
        );
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert!(!stderr.contains("warning"), "{command}: {stderr}");
        let written = std::fs::read_to_string(&output).unwrap();
        let got = attributes_by_position(&written);
        // The input's vertex list, in its order (its numbering kept), with every attribute.
        assert_eq!(lines(&written, "v"), lines(&text, "v"), "{command}");
        let vertices = lines(&written, "v").len();
        assert_eq!(lines(&written, "vt").len(), vertices, "{command}");
        if command == "irreducible" {
            assert!(
                got.len() < expected.len() / 4,
                "{command}: {} vertices in faces",
                got.len()
            );
        } else {
            assert_eq!(got.len(), vertices, "{command}: every vertex in a quad");
        }
        for (position, attributes) in got {
            assert_eq!(
                expected[&position], attributes,
                "{command}: vertex at {position}"
            );
        }
    }
    // To PLY with `--compact`: the survivors' columns, read back by the library, follow their
    // positions.
    let output = dir.path().join("i.ply");
    surftopo()
        .arg("irreducible")
        .arg(&input)
        .arg("--compact")
        .arg("-o")
        .arg(&output)
        .assert()
        .success();
    let soup = surftopo_io::read_path(&output).unwrap();
    let attributes = &soup.attributes;
    let [u, v] = attributes.vertex_texcoords().unwrap();
    let [_, _, nz] = attributes.vertex_normals().unwrap();
    assert!(soup.vertex_count() < expected.len() / 4);
    for (i, p) in soup.positions.iter().enumerate() {
        let (vt, vn) = &expected[&p.map(|c| c.to_string()).join(" ")];
        let value = |k: usize| attributes.vertex[k].values[i].to_string();
        assert_eq!(*vt, format!("{} {}", value(u), value(v)));
        assert_eq!(vn.split(' ').nth(2).unwrap(), value(nz));
    }
}

/// The input with vertex 1's corners given texture coordinates of their own (a seam): the
/// coordinates are per corner.
fn with_a_seam(dir: &Path, text: &str) -> PathBuf {
    let vt = lines(text, "vt").len();
    let mut out = text.to_owned();
    let mut seam = 0;
    out = out
        .lines()
        .map(|l| {
            if !l.starts_with("f ") {
                return format!("{l}\n");
            }
            let f: Vec<String> = l[2..]
                .split(' ')
                .map(|c| {
                    if c == "1/1/1" {
                        seam += 1;
                        format!("1/{}/1", vt + seam)
                    } else {
                        c.to_owned()
                    }
                })
                .collect();
            format!("f {}\n", f.join(" "))
        })
        .collect();
    assert!(seam >= 3);
    for k in 0..seam {
        out += &format!("vt 0.5 {k}\n");
    }
    write(dir, "seam.obj", &out)
}

#[test]
fn what_cannot_be_kept_is_named_in_a_warning() {
    let dir = tempfile::tempdir().unwrap();
    let (input, text) = surface_with_attributes(dir.path());
    let n = lines(&text, "v").len();
    let corners = corners(&text).len();
    let seam = with_a_seam(dir.path(), &text);
    let seam_text = std::fs::read_to_string(&seam).unwrap();
    let vt = lines(&seam_text, "vt").len();
    let stderr = |args: &[&str], output: &Path| {
        let run = surftopo().args(args).arg(output).output().unwrap();
        assert!(run.status.success(), "{args:?}");
        String::from_utf8(run.stderr).unwrap()
    };
    let seam = seam.to_str().unwrap();
    // quad: per-corner coordinates dropped, per-vertex normals kept.
    let q = dir.path().join("q.obj");
    let warning = stderr(&["quad", seam, "-o"], &q);
    assert!(
        warning.contains(&format!(
            "per-corner texture coordinates (vt): {vt} values on {corners} face corners: dropped \
             (quad makes new faces"
        )),
        "{warning}"
    );
    let written = std::fs::read_to_string(&q).unwrap();
    assert_eq!(lines(&written, "vt").len(), 0);
    assert_eq!(lines(&written, "vn").len(), n);
    // convert to PLY: the same, because PLY has no per-corner values; the normals go.
    let ply = dir.path().join("s.ply");
    let warning = stderr(&["convert", seam], &ply);
    assert!(
        warning.contains(&format!(
            "per-corner texture coordinates (vt): {vt} values on {corners} face corners: PLY \
             cannot hold per-corner values; dropped"
        )),
        "{warning}"
    );
    let soup = surftopo_io::read_path(&ply).unwrap();
    assert!(soup.attributes.vertex_normals().is_some());
    assert!(soup.attributes.vertex_texcoords().is_none());
    // convert to OBJ: everything kept, no warning.
    let obj = dir.path().join("s.obj");
    assert_eq!(stderr(&["convert", seam], &obj), "");
    let written = std::fs::read_to_string(&obj).unwrap();
    assert_eq!(lines(&written, "vt").len(), vt);
    // irreducible to OFF: per-vertex attributes the format cannot hold.
    let off = dir.path().join("i.off");
    let warning = stderr(&["irreducible", input.to_str().unwrap(), "-o"], &off);
    assert!(
        warning.contains("per-vertex u v nx ny nz (")
            && warning.contains("OFF cannot hold them; dropped"),
        "{warning}"
    );
    // Welding vertices whose normals differ keeps the first one's and says so.
    let doubled = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 0 1\n\
vn 1 0 0\nvn 0 1 0\nvn 0 0 1\nvn 0 0 1\nvn 0 0 -1\n\
f 1//1 3//3 2//2\nf 1//1 2//2 4//4\nf 2//2 3//3 5//5\nf 3//3 1//1 5//5\n";
    let doubled = write(dir.path(), "doubled.obj", doubled);
    let welded = dir.path().join("w.obj");
    let warning = stderr(&["convert", "--weld", doubled.to_str().unwrap()], &welded);
    assert!(
        warning.contains("welding merged 1 vertices whose per-vertex attributes differ"),
        "{warning}"
    );
    let written = std::fs::read_to_string(&welded).unwrap();
    assert_eq!(lines(&written, "vn")[3], ["0", "0", "1"]);
}

#[test]
fn convert_writes_ascii_and_float_ply() {
    let dir = tempfile::tempdir().unwrap();
    let (input, text) = surface_with_attributes(dir.path());
    let positions: Vec<Vec<f64>> = lines(&text, "v")
        .iter()
        .map(|w| w.iter().map(|x| x.parse().unwrap()).collect())
        .collect();
    for (flags, kind) in [
        (&["--ascii"][..], "double"),
        (&["--ascii", "--float"][..], "float"),
        (&["--float"][..], "float"),
    ] {
        let output = dir.path().join("out.ply");
        surftopo()
            .arg("convert")
            .arg(&input)
            .arg(&output)
            .args(flags)
            .assert()
            .success();
        let parsed = surftopo_testkit::ply_parse::parse(&std::fs::read(&output).unwrap());
        let ascii = flags.contains(&"--ascii");
        let format = if ascii {
            "ascii"
        } else {
            "binary_little_endian"
        };
        assert_eq!(parsed.format, format);
        assert_eq!(parsed.names, ["x", "y", "z", "u", "v", "nx", "ny", "nz"]);
        assert!(
            parsed.types.iter().all(|t| t == kind),
            "{flags:?}: {:?}",
            parsed.types
        );
        assert_eq!(parsed.rows.len(), positions.len());
        for (i, row) in parsed.rows.iter().enumerate() {
            let expected = [
                positions[i][0],
                positions[i][1],
                positions[i][2],
                i as f64 / 1000.0,
                i as f64 / 500.0,
                1.0,
                0.0,
                i as f64,
            ];
            for (k, (&a, &b)) in row.iter().zip(&expected).enumerate() {
                if kind == "float" {
                    assert_eq!(a as f32, b as f32, "{flags:?}: vertex {i} value {k}");
                } else {
                    assert_eq!(a, b, "{flags:?}: vertex {i} value {k}");
                }
            }
        }
        // Our reader agrees.
        let soup = surftopo_io::read_path(&output).unwrap();
        let [u, _] = soup.attributes.vertex_texcoords().unwrap();
        for (i, row) in parsed.rows.iter().enumerate() {
            assert_eq!(
                soup.positions[i].map(|c| c as f32),
                [0, 1, 2].map(|k| row[k] as f32)
            );
            assert_eq!(soup.attributes.vertex[u].values[i] as f32, row[3] as f32);
        }
    }
    // The flags are for PLY only: refused before any work, nothing written.
    let output = dir.path().join("out.obj");
    let run = surftopo()
        .arg("convert")
        .arg(&input)
        .arg(&output)
        .arg("--ascii")
        .output()
        .unwrap();
    assert_eq!(run.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&run.stderr).contains("--ascii applies to PLY output only"));
    assert!(!output.exists());
}

/// The shared meshes' attributes through `convert`: spot's per-corner texture coordinates (all
/// 3,225 `vt` lines, each corner keeping its value), hand_4054's normals into PLY.
fn shared_mesh_attributes_survive_convert() {
    surftopo_testkit::require_shared_meshes();
    let meshes = surftopo_testkit::shared_meshes_dir().unwrap();
    let dir = tempfile::tempdir().unwrap();
    let gunzip = |path: &Path| {
        let mut text = String::new();
        flate2::read::GzDecoder::new(std::fs::File::open(path).unwrap())
            .read_to_string(&mut text)
            .unwrap();
        text
    };
    let spot = meshes.join("spot.obj.gz");
    let output = dir.path().join("spot2.obj");
    surftopo()
        .arg("convert")
        .arg(&spot)
        .arg(&output)
        .assert()
        .success();
    let (input, written) = (gunzip(&spot), std::fs::read_to_string(&output).unwrap());
    let (vt_in, vt_out) = (lines(&input, "vt"), lines(&written, "vt"));
    assert_eq!(vt_out.len(), 3225);
    let (a, b) = (corners(&input), corners(&written));
    assert_eq!(a.len(), b.len());
    for ((va, ta, _), (vb, tb, _)) in a.into_iter().zip(b) {
        assert_eq!(va, vb);
        let (x, y) = (&vt_in[ta.unwrap()], &vt_out[tb.unwrap()]);
        let parse = |w: &[&str]| {
            w.iter()
                .map(|x| x.parse::<f64>().unwrap())
                .collect::<Vec<_>>()
        };
        assert_eq!(parse(x), parse(y));
    }
    let hand = meshes.join("hand_4054.obj.gz");
    let output = dir.path().join("hand.ply");
    let run = surftopo()
        .arg("convert")
        .arg(&hand)
        .arg(&output)
        .output()
        .unwrap();
    assert!(run.status.success());
    assert!(
        run.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let soup = surftopo_io::read_path(&output).unwrap();
    let [nx, _, _] = soup.attributes.vertex_normals().unwrap();
    let hand_text = gunzip(&hand);
    let vn_in = lines(&hand_text, "vn");
    assert_eq!(vn_in.len(), 4054);
    for (i, vn) in vn_in.iter().enumerate() {
        assert_eq!(
            soup.attributes.vertex[nx].values[i],
            vn[0].parse::<f64>().unwrap()
        );
    }
}

surftopo_testkit::shared_mesh_tests!(shared_mesh_attributes_survive_convert);

#[test]
fn attributes_and_ply_variants_through_standard_output() {
    let dir = tempfile::tempdir().unwrap();
    let (input, text) = surface_with_attributes(dir.path());
    let run = surftopo()
        .arg("convert")
        .arg(&input)
        .args(["-", "--format", "ply", "--ascii", "--float"])
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let parsed = surftopo_testkit::ply_parse::parse(&run.stdout);
    assert_eq!(parsed.format, "ascii");
    assert_eq!(parsed.names, ["x", "y", "z", "u", "v", "nx", "ny", "nz"]);
    assert_eq!(parsed.rows.len(), lines(&text, "v").len());
    assert_eq!(parsed.rows[5][7], 5.0);
    // To STL, which holds no attributes: said on stderr.
    let run = surftopo()
        .arg("convert")
        .arg(&input)
        .args(["-", "--format", "stl"])
        .output()
        .unwrap();
    assert!(run.status.success());
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(
        stderr.contains("warning: <stdout>: per-vertex u v nx ny nz (")
            && stderr.contains("STL cannot hold them; dropped"),
        "{stderr}"
    );
    // --ascii with another format is refused.
    let run = surftopo()
        .arg("convert")
        .arg(&input)
        .args(["-", "--format", "obj", "--float"])
        .output()
        .unwrap();
    assert_eq!(run.status.code(), Some(2));
    assert!(run.stdout.is_empty());
}
