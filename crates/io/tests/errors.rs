//! One test per error class: typed variant, file name and line / offset in
//! the message.

use std::path::Path;

use Location::{Line, Offset};
use surftopo_io::{Format, IoError, Location, NonFinite, read_bytes, read_bytes_with, read_path};

fn err(data: &[u8], format: Format, name: &str) -> IoError {
    match read_bytes(data, format, name) {
        Ok(s) => panic!("{name}: expected an error, got {} faces", s.face_count()),
        Err(e) => e,
    }
}

/// Asserts the message starts with `prefix` (file and location).
fn starts(e: &IoError, prefix: &str) {
    let msg = e.to_string();
    assert!(
        msg.starts_with(prefix),
        "message {msg:?} does not start with {prefix:?}"
    );
}

/// Reads `data` expecting a refusal located `at` whose message starts with
/// `prefix`; returns the error for the caller's variant check.
fn refused_at(data: &[u8], format: Format, name: &str, at: Location, prefix: &str) -> IoError {
    let e = err(data, format, name);
    assert_eq!(e.location(), Some(at), "{e:?}");
    starts(&e, prefix);
    e
}

#[test]
fn bad_float() {
    let ply = b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 zz\n";
    let stl = b"solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 q\n";
    let cases: [(&[u8], Format, &str, u64, &str); 4] = [
        (
            b"v 0 0 0\nv 1 0 0\nv 0 1.5.2 0\nf 1 2 3\n",
            Format::Obj,
            "m.obj",
            3,
            "m.obj:3: invalid y coordinate '1.5.2'",
        ),
        (
            b"OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n",
            Format::Off,
            "m.off",
            4,
            "m.off:4: invalid y coordinate",
        ),
        (
            ply,
            Format::Ply,
            "m.ply",
            8,
            "m.ply:8: invalid vertex z 'zz'",
        ),
        (
            stl,
            Format::Stl,
            "m.stl",
            5,
            "m.stl:5: invalid z coordinate 'q'",
        ),
    ];
    for (data, format, name, line, prefix) in cases {
        let e = refused_at(data, format, name, Line(line), prefix);
        assert!(matches!(e, IoError::Parse { .. }), "{e:?}");
    }
}

#[test]
fn index_out_of_range_obj_positive_and_negative() {
    let e = refused_at(
        b"v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 9\n",
        Format::Obj,
        "m.obj",
        Line(5),
        "m.obj:5: face index 9 out of range (3 vertices)",
    );
    assert!(
        matches!(
            e,
            IoError::IndexOutOfRange {
                index: 9,
                vertex_count: 3,
                ..
            }
        ),
        "{e:?}"
    );
    assert_eq!(
        e.to_string(),
        "m.obj:5: face index 9 out of range (3 vertices)"
    );

    for (face, index) in [("f -1 -2 -4", -4), ("f 0 1 2", 0)] {
        let src = format!("v 0 0 0\nv 1 0 0\nv 0 1 0\n{face}\n");
        let prefix = format!("m.obj:4: face index {index} out of range (3 vertices)");
        let e = refused_at(src.as_bytes(), Format::Obj, "m.obj", Line(4), &prefix);
        assert!(
            matches!(e, IoError::IndexOutOfRange { index: i, .. } if i == index),
            "{e:?}"
        );
    }
}

#[test]
fn index_out_of_range_other_formats() {
    let e = refused_at(
        b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
        Format::Off,
        "m.off",
        Line(6),
        "m.off:6: face index 3 out of range (3 vertices)",
    );
    assert!(
        matches!(e, IoError::IndexOutOfRange { index: 3, .. }),
        "{e:?}"
    );

    let e = err(
        b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n",
        Format::Off,
        "m.off",
    );
    assert!(
        matches!(e, IoError::IndexOutOfRange { index: -1, .. }),
        "{e:?}"
    );

    let mut ply = binary_ply_header(3, 1);
    push_vertices(&mut ply, 3);
    ply.push(3);
    for i in [0u32, 1, 7] {
        ply.extend_from_slice(&i.to_le_bytes());
    }
    let offset = ply.len() - 4;
    let e = refused_at(
        &ply,
        Format::Ply,
        "m.ply",
        Offset(offset as u64),
        &format!("m.ply:byte {offset}: face index 7 out of range (3 vertices)"),
    );
    assert!(
        matches!(e, IoError::IndexOutOfRange { index: 7, .. }),
        "{e:?}"
    );
}

#[test]
fn face_with_fewer_than_three_vertices() {
    let mut ply = binary_ply_header(3, 1);
    push_vertices(&mut ply, 3);
    let rec = ply.len();
    ply.push(2);
    ply.extend_from_slice(&[0, 0, 0, 0, 1, 0, 0, 0]);
    let ply_prefix = format!("m.ply:byte {rec}: face with 2 vertices");
    let cases: [(&[u8], Format, &str, Location, &str); 3] = [
        (
            b"v 0 0 0\nv 1 0 0\nf 1 2\n",
            Format::Obj,
            "m.obj",
            Line(3),
            "m.obj:3: face with 2 vertices",
        ),
        (
            b"OFF\n2 1 0\n0 0 0\n1 0 0\n2 0 1\n",
            Format::Off,
            "m.off",
            Line(5),
            "m.off:5: face with 2 vertices",
        ),
        (&ply, Format::Ply, "m.ply", Offset(rec as u64), &ply_prefix),
    ];
    for (data, format, name, at, prefix) in cases {
        let e = refused_at(data, format, name, at, prefix);
        assert!(matches!(e, IoError::FaceTooSmall { sides: 2, .. }), "{e:?}");
    }
}

#[test]
fn truncated_files() {
    // OFF with fewer faces than the header says.
    let e = refused_at(
        b"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
        Format::Off,
        "m.off",
        Line(7),
        "m.off:7: ",
    );
    assert!(matches!(e, IoError::UnexpectedEof { .. }), "{e:?}");
    assert_eq!(
        e.to_string(),
        "m.off:7: unexpected end of file, expected vertex count of face 2 of 2"
    );

    // OFF with fewer vertices.
    let e = err(b"OFF\n3 1 0\n0 0 0\n1 0 0\n", Format::Off, "m.off");
    assert!(matches!(e, IoError::UnexpectedEof { .. }), "{e:?}");
    starts(
        &e,
        "m.off:5: unexpected end of file, expected x coordinate of vertex 3 of 3",
    );

    // Binary PLY cut inside the vertex data and inside the faces.
    let mut ply = binary_ply_header(3, 1);
    push_vertices(&mut ply, 3);
    ply.push(3);
    ply.extend_from_slice(&[0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0]);
    let full = ply.len();
    let e = refused_at(
        &ply[..full - 3],
        Format::Ply,
        "m.ply",
        Offset((full - 3) as u64),
        &format!(
            "m.ply:byte {}: unexpected end of file, expected record 1 of 1 of element 'face'",
            full - 3
        ),
    );
    assert!(matches!(e, IoError::UnexpectedEof { .. }), "{e:?}");
    let e = err(&ply[..full - 20], Format::Ply, "m.ply");
    assert!(matches!(e, IoError::UnexpectedEof { .. }), "{e:?}");
    starts(&e, "m.ply:byte ");
    assert!(e.to_string().contains("element 'vertex'"), "{e}");

    // Binary STL announcing 2 triangles, holding 1; then the same with a
    // header starting with "solid" (common in the wild).
    let mut stl = vec![0u8; 80];
    stl.extend_from_slice(&2u32.to_le_bytes());
    stl.extend_from_slice(&[0u8; 50]);
    stl.extend_from_slice(&[0u8; 20]);
    let mut solid = stl.clone();
    solid[..5].copy_from_slice(b"solid");
    for bytes in [&stl, &solid] {
        let e = refused_at(bytes, Format::Stl, "m.stl", Offset(134), "m.stl:byte 134");
        assert!(matches!(e, IoError::UnexpectedEof { .. }), "{e:?}");
        assert_eq!(
            e.to_string(),
            "m.stl:byte 134: unexpected end of file, expected triangle 2 of 2"
        );
    }

    // Ascii STL ending inside a facet.
    let e = err(
        b"solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n",
        Format::Stl,
        "m.stl",
    );
    assert!(matches!(e, IoError::UnexpectedEof { .. }), "{e:?}");
    starts(&e, "m.stl:5: unexpected end of file, expected 'endfacet'");
}

#[test]
fn bad_headers() {
    let cases: [(&[u8], Format, &str, u64, &str); 5] = [
        (
            b"OFX\n3 1 0\n",
            Format::Off,
            "m.off",
            1,
            "m.off:1: bad header: expected OFF keyword, found 'OFX'",
        ),
        (b"OFF\n3 x 0\n", Format::Off, "m.off", 2, "m.off:2: bad header"),
        (
            b"plx\nformat ascii 1.0\nend_header\n",
            Format::Ply,
            "m.ply",
            1,
            "m.ply:1: bad header: missing 'ply' magic line",
        ),
        (
            b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n",
            Format::Ply,
            "m.ply",
            4,
            "m.ply:4: bad header: unknown property type 'float128'",
        ),
        (
            b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n",
            Format::Ply,
            "m.ply",
            3,
            "m.ply:3: bad header: vertex element has no 'z' property",
        ),
    ];
    for (data, format, name, line, prefix) in cases {
        let e = refused_at(data, format, name, Line(line), prefix);
        assert!(matches!(e, IoError::BadHeader { .. }), "{e:?}");
    }

    let e = refused_at(
        b"ply\nformat ascii 1.0\nelement vertex 1\n",
        Format::Ply,
        "m.ply",
        Line(4),
        "m.ply:4: unexpected end of file, expected 'end_header'",
    );
    assert!(matches!(e, IoError::UnexpectedEof { .. }), "{e:?}");
}

#[test]
fn non_finite_coordinates() {
    for (text, value) in [
        ("nan", "NaN"),
        ("inf", "inf"),
        ("-Infinity", "-inf"),
        ("1e999", "inf"),
    ] {
        let src = format!("v 0 0 0\nv 1 {text} 0\n");
        let message = format!("m.obj:2: non-finite coordinate {value} of vertex 1");
        let e = refused_at(src.as_bytes(), Format::Obj, "m.obj", Line(2), &message);
        assert!(matches!(e, IoError::NonFinite { .. }), "{e:?}");
        assert_eq!(e.to_string(), message);
    }

    let mut ply = binary_ply_header(1, 0);
    let o = ply.len() + 16;
    ply.extend_from_slice(&0f64.to_le_bytes());
    ply.extend_from_slice(&0f64.to_le_bytes());
    ply.extend_from_slice(&f64::INFINITY.to_le_bytes());
    let ply_prefix = format!("m.ply:byte {o}: non-finite coordinate inf");

    let mut stl = vec![0u8; 80];
    stl.extend_from_slice(&1u32.to_le_bytes());
    let mut rec = [0u8; 50];
    rec[16..20].copy_from_slice(&f32::NAN.to_le_bytes());
    stl.extend_from_slice(&rec);

    let cases: [(&[u8], Format, &str, Location, &str); 3] = [
        (
            b"OFF\n1 0 0\n0 nan 0\n",
            Format::Off,
            "m.off",
            Line(3),
            "m.off:3: ",
        ),
        (&ply, Format::Ply, "m.ply", Offset(o as u64), &ply_prefix),
        (&stl, Format::Stl, "m.stl", Offset(100), "m.stl:byte 100: "),
    ];
    for (data, format, name, at, prefix) in cases {
        let e = refused_at(data, format, name, at, prefix);
        assert!(matches!(e, IoError::NonFinite { .. }), "{e:?}");
    }
}

/// `NonFinite::Keep` keeps NaN and infinite coordinates in every reader (text and binary
/// paths), where `Refuse` names the vertex.
#[test]
fn non_finite_coordinates_are_kept_on_request() {
    let mut ply = binary_ply_header(3, 1);
    for c in [0.0, 0.0, 0.0, 1.0, f64::NAN, 0.0, 0.0, 1.0, f64::INFINITY] {
        ply.extend_from_slice(&c.to_le_bytes());
    }
    ply.extend_from_slice(&[3, 0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0]);
    let mut stl = vec![0u8; 80];
    stl.extend_from_slice(&1u32.to_le_bytes());
    let mut rec = [0u8; 50];
    rec[28..32].copy_from_slice(&f32::NAN.to_le_bytes());
    rec[44..48].copy_from_slice(&f32::INFINITY.to_le_bytes());
    stl.extend_from_slice(&rec);
    let ascii_ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
                     property float z\nelement face 1\nproperty list uchar int vertex_indices\n\
                     end_header\n0 0 0\n1 nan 0\n0 1 inf\n3 0 1 2\n";
    let ascii_stl = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 nan 0\n\
                     vertex 0 1 inf\nendloop\nendfacet\nendsolid s\n";
    let cases: [(&[u8], Format); 6] = [
        (b"v 0 0 0\nv 1 nan 0\nv 0 1 inf\nf 1 2 3\n", Format::Obj),
        (
            b"OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 inf\n3 0 1 2\n",
            Format::Off,
        ),
        (&ply, Format::Ply),
        (ascii_ply.as_bytes(), Format::Ply),
        (&stl, Format::Stl),
        (ascii_stl.as_bytes(), Format::Stl),
    ];
    for (bytes, format) in cases {
        let soup = read_bytes_with(bytes, format, "m", NonFinite::Keep).unwrap();
        assert_eq!(soup.positions.len(), 3, "{format:?}");
        assert!(soup.positions[1][1].is_nan(), "{format:?}");
        assert_eq!(soup.positions[2][2], f64::INFINITY, "{format:?}");
        assert_eq!(soup.face(0), &[0, 1, 2], "{format:?}");
        let e = read_bytes(bytes, format, "m").unwrap_err();
        assert!(
            matches!(e, IoError::NonFinite { vertex: 1, .. }),
            "{format:?}: {e:?}"
        );
        assert!(e.to_string().ends_with("of vertex 1"), "{e}");
    }
}

#[test]
fn unknown_extension() {
    for p in ["mesh.xyz", "mesh", "mesh.tar.gz"] {
        let e = read_path(Path::new(p)).unwrap_err();
        assert!(matches!(e, IoError::UnsupportedFormat { .. }), "{e:?}");
        starts(&e, &format!("{p}: unsupported file extension"));
    }
    let e = surftopo_io::write_path(
        Path::new("out.vtk"),
        &surftopo_io::PolygonSoup::new(),
        &Default::default(),
    )
    .unwrap_err();
    assert!(matches!(e, IoError::UnsupportedFormat { .. }), "{e:?}");
}

#[test]
fn missing_file_and_corrupt_gzip() {
    let e = read_path(Path::new("/nonexistent/dir/m.obj")).unwrap_err();
    assert!(matches!(e, IoError::Io { .. }), "{e:?}");
    starts(&e, "/nonexistent/dir/m.obj: ");
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("bad.off.gz");
    std::fs::write(&p, b"\x1f\x8b\x08\x00garbage garbage garbage").unwrap();
    let e = read_path(&p).unwrap_err();
    assert!(matches!(e, IoError::Io { .. }), "{e:?}");
    assert!(e.to_string().contains("bad.off.gz"), "{e}");
}

fn binary_ply_header(nv: usize, nf: usize) -> Vec<u8> {
    format!(
        "ply\nformat binary_little_endian 1.0\nelement vertex {nv}\nproperty double x\nproperty double y\nproperty double z\nelement face {nf}\nproperty list uchar uint vertex_indices\nend_header\n"
    )
    .into_bytes()
}

fn push_vertices(out: &mut Vec<u8>, n: usize) {
    for i in 0..n {
        for c in [i as f64, 0.5, -1.0] {
            out.extend_from_slice(&c.to_le_bytes());
        }
    }
}
