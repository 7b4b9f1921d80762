//! One test per error class: typed variant, file name and line / offset in
//! the message.

use std::path::Path;

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

#[test]
fn bad_float() {
    let e = err(
        b"v 0 0 0\nv 1 0 0\nv 0 1.5.2 0\nf 1 2 3\n",
        Format::Obj,
        "m.obj",
    );
    assert!(
        matches!(
            e,
            IoError::Parse {
                at: Location::Line(3),
                ..
            }
        ),
        "{e:?}"
    );
    starts(&e, "m.obj:3: invalid y coordinate '1.5.2'");

    let e = err(
        b"OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n",
        Format::Off,
        "m.off",
    );
    assert!(
        matches!(
            e,
            IoError::Parse {
                at: Location::Line(4),
                ..
            }
        ),
        "{e:?}"
    );
    starts(&e, "m.off:4: invalid y coordinate");

    let ply = b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 zz\n";
    let e = err(ply, Format::Ply, "m.ply");
    assert!(
        matches!(
            e,
            IoError::Parse {
                at: Location::Line(8),
                ..
            }
        ),
        "{e:?}"
    );
    starts(&e, "m.ply:8: invalid vertex z 'zz'");

    let stl = b"solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 q\n";
    let e = err(stl, Format::Stl, "m.stl");
    assert!(
        matches!(
            e,
            IoError::Parse {
                at: Location::Line(5),
                ..
            }
        ),
        "{e:?}"
    );
    starts(&e, "m.stl:5: invalid z coordinate 'q'");
}

#[test]
fn index_out_of_range_obj_positive_and_negative() {
    let e = err(
        b"v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 9\n",
        Format::Obj,
        "m.obj",
    );
    assert!(
        matches!(
            e,
            IoError::IndexOutOfRange {
                at: Location::Line(5),
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

    let e = err(
        b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n",
        Format::Obj,
        "m.obj",
    );
    assert!(
        matches!(e, IoError::IndexOutOfRange { index: -4, .. }),
        "{e:?}"
    );
    starts(&e, "m.obj:4: face index -4 out of range (3 vertices)");

    let e = err(
        b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",
        Format::Obj,
        "m.obj",
    );
    assert!(
        matches!(e, IoError::IndexOutOfRange { index: 0, .. }),
        "{e:?}"
    );
    starts(&e, "m.obj:4: face index 0 out of range");
}

#[test]
fn index_out_of_range_other_formats() {
    let e = err(
        b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
        Format::Off,
        "m.off",
    );
    assert!(
        matches!(
            e,
            IoError::IndexOutOfRange {
                at: Location::Line(6),
                index: 3,
                ..
            }
        ),
        "{e:?}"
    );
    starts(&e, "m.off:6: face index 3 out of range (3 vertices)");

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
    let e = err(&ply, Format::Ply, "m.ply");
    assert!(
        matches!(e, IoError::IndexOutOfRange { at: Location::Offset(o), index: 7, .. } if o == offset as u64),
        "{e:?}"
    );
    starts(
        &e,
        &format!("m.ply:byte {offset}: face index 7 out of range (3 vertices)"),
    );
}

#[test]
fn face_with_fewer_than_three_vertices() {
    let e = err(b"v 0 0 0\nv 1 0 0\nf 1 2\n", Format::Obj, "m.obj");
    assert!(
        matches!(
            e,
            IoError::FaceTooSmall {
                sides: 2,
                at: Location::Line(3),
                ..
            }
        ),
        "{e:?}"
    );
    starts(&e, "m.obj:3: face with 2 vertices");

    let e = err(b"OFF\n2 1 0\n0 0 0\n1 0 0\n2 0 1\n", Format::Off, "m.off");
    assert!(
        matches!(
            e,
            IoError::FaceTooSmall {
                sides: 2,
                at: Location::Line(5),
                ..
            }
        ),
        "{e:?}"
    );

    let mut ply = binary_ply_header(3, 1);
    push_vertices(&mut ply, 3);
    let rec = ply.len();
    ply.push(2);
    ply.extend_from_slice(&[0, 0, 0, 0, 1, 0, 0, 0]);
    let e = err(&ply, Format::Ply, "m.ply");
    assert!(
        matches!(e, IoError::FaceTooSmall { sides: 2, at: Location::Offset(o), .. } if o == rec as u64),
        "{e:?}"
    );
    starts(&e, &format!("m.ply:byte {rec}: face with 2 vertices"));
}

#[test]
fn truncated_files() {
    // OFF with fewer faces than the header says.
    let e = err(
        b"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
        Format::Off,
        "m.off",
    );
    assert!(
        matches!(
            e,
            IoError::UnexpectedEof {
                at: Location::Line(7),
                ..
            }
        ),
        "{e:?}"
    );
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
    let e = err(&ply[..full - 3], Format::Ply, "m.ply");
    assert!(
        matches!(e, IoError::UnexpectedEof { at: Location::Offset(o), .. } if o == (full - 3) as u64),
        "{e:?}"
    );
    starts(
        &e,
        &format!(
            "m.ply:byte {}: unexpected end of file, expected record 1 of 1 of element 'face'",
            full - 3
        ),
    );
    let e = err(&ply[..full - 20], Format::Ply, "m.ply");
    assert!(matches!(e, IoError::UnexpectedEof { .. }), "{e:?}");
    starts(&e, "m.ply:byte ");
    assert!(e.to_string().contains("element 'vertex'"), "{e}");

    // Binary STL announcing 2 triangles, holding 1.
    let mut stl = vec![0u8; 80];
    stl.extend_from_slice(&2u32.to_le_bytes());
    stl.extend_from_slice(&[0u8; 50]);
    stl.extend_from_slice(&[0u8; 20]);
    let e = err(&stl, Format::Stl, "m.stl");
    assert!(
        matches!(
            e,
            IoError::UnexpectedEof {
                at: Location::Offset(134),
                ..
            }
        ),
        "{e:?}"
    );
    assert_eq!(
        e.to_string(),
        "m.stl:byte 134: unexpected end of file, expected triangle 2 of 2"
    );

    // The same with a header starting with "solid" (common in the wild).
    stl[..5].copy_from_slice(b"solid");
    let e = err(&stl, Format::Stl, "m.stl");
    assert!(
        matches!(
            e,
            IoError::UnexpectedEof {
                at: Location::Offset(134),
                ..
            }
        ),
        "{e:?}"
    );

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
    let e = err(b"OFX\n3 1 0\n", Format::Off, "m.off");
    assert!(
        matches!(
            e,
            IoError::BadHeader {
                at: Location::Line(1),
                ..
            }
        ),
        "{e:?}"
    );
    starts(&e, "m.off:1: bad header: expected OFF keyword, found 'OFX'");

    let e = err(b"OFF\n3 x 0\n", Format::Off, "m.off");
    assert!(
        matches!(
            e,
            IoError::BadHeader {
                at: Location::Line(2),
                ..
            }
        ),
        "{e:?}"
    );

    let e = err(b"plx\nformat ascii 1.0\nend_header\n", Format::Ply, "m.ply");
    assert!(
        matches!(
            e,
            IoError::BadHeader {
                at: Location::Line(1),
                ..
            }
        ),
        "{e:?}"
    );
    starts(&e, "m.ply:1: bad header: missing 'ply' magic line");

    let e = err(
        b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n",
        Format::Ply,
        "m.ply",
    );
    assert!(
        matches!(
            e,
            IoError::BadHeader {
                at: Location::Line(4),
                ..
            }
        ),
        "{e:?}"
    );
    starts(&e, "m.ply:4: bad header: unknown property type 'float128'");

    let e = err(b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n", Format::Ply, "m.ply");
    assert!(
        matches!(
            e,
            IoError::BadHeader {
                at: Location::Line(3),
                ..
            }
        ),
        "{e:?}"
    );
    starts(
        &e,
        "m.ply:3: bad header: vertex element has no 'z' property",
    );

    let e = err(
        b"ply\nformat ascii 1.0\nelement vertex 1\n",
        Format::Ply,
        "m.ply",
    );
    assert!(matches!(e, IoError::UnexpectedEof { .. }), "{e:?}");
    starts(&e, "m.ply:4: unexpected end of file, expected 'end_header'");
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
        let e = err(src.as_bytes(), Format::Obj, "m.obj");
        assert!(
            matches!(
                e,
                IoError::NonFinite {
                    at: Location::Line(2),
                    ..
                }
            ),
            "{e:?}"
        );
        assert_eq!(
            e.to_string(),
            format!("m.obj:2: non-finite coordinate {value} of vertex 1")
        );
    }
    let e = err(b"OFF\n1 0 0\n0 nan 0\n", Format::Off, "m.off");
    assert!(
        matches!(
            e,
            IoError::NonFinite {
                at: Location::Line(3),
                ..
            }
        ),
        "{e:?}"
    );

    let mut ply = binary_ply_header(1, 0);
    let o = ply.len() + 16;
    ply.extend_from_slice(&0f64.to_le_bytes());
    ply.extend_from_slice(&0f64.to_le_bytes());
    ply.extend_from_slice(&f64::INFINITY.to_le_bytes());
    let e = err(&ply, Format::Ply, "m.ply");
    assert!(
        matches!(e, IoError::NonFinite { at: Location::Offset(p), .. } if p == o as u64),
        "{e:?}"
    );
    starts(&e, &format!("m.ply:byte {o}: non-finite coordinate inf"));

    let mut stl = vec![0u8; 80];
    stl.extend_from_slice(&1u32.to_le_bytes());
    let mut rec = [0u8; 50];
    rec[16..20].copy_from_slice(&f32::NAN.to_le_bytes());
    stl.extend_from_slice(&rec);
    let e = err(&stl, Format::Stl, "m.stl");
    assert!(
        matches!(
            e,
            IoError::NonFinite {
                at: Location::Offset(100),
                ..
            }
        ),
        "{e:?}"
    );
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
