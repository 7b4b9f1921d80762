//! Write-then-read round trips: identical faces, bit-identical positions.

mod common;

use common::{assert_same, cube_quads, mixed, octahedron, torus};
use proptest::prelude::*;
use surftopo_io::{
    Format, IoError, PlyEncoding, PolygonSoup, WriteOptions, read_bytes, read_path, write,
    write_path,
};

/// Every writable (format, PLY encoding) combination, with a file extension.
fn variants() -> Vec<(Format, PlyEncoding, &'static str)> {
    vec![
        (Format::Obj, PlyEncoding::default(), "obj"),
        (Format::Off, PlyEncoding::default(), "off"),
        (Format::Ply, PlyEncoding::Ascii, "ply"),
        (Format::Ply, PlyEncoding::BinaryLittleEndian, "ply"),
        (Format::Ply, PlyEncoding::BinaryBigEndian, "ply"),
    ]
}

fn in_memory(soup: &PolygonSoup, format: Format, enc: PlyEncoding) -> PolygonSoup {
    let mut bytes = Vec::new();
    let opts = WriteOptions::default().with_ply_encoding(enc);
    write(&mut bytes, soup, format, &opts).unwrap();
    read_bytes(&bytes, format, "memory").unwrap()
}

#[test]
fn round_trip_in_memory() {
    for soup in [octahedron(), cube_quads(), mixed(), torus(5, 7)] {
        for (format, enc, _) in variants() {
            let back = in_memory(&soup, format, enc);
            assert_same(&soup, &back);
        }
    }
}

#[test]
fn round_trip_files_plain_and_gz() {
    let dir = tempfile::tempdir().unwrap();
    for (k, soup) in [octahedron(), cube_quads(), mixed()]
        .into_iter()
        .enumerate()
    {
        for (_, enc, ext) in variants() {
            for gz in [false, true] {
                let name = format!("m{k}_{enc:?}.{ext}{}", if gz { ".gz" } else { "" });
                let path = dir.path().join(name);
                let opts = WriteOptions::default().with_ply_encoding(enc);
                write_path(&path, &soup, &opts).unwrap();
                let raw = std::fs::read(&path).unwrap();
                assert_eq!(raw.starts_with(&[0x1f, 0x8b]), gz, "{}", path.display());
                let back = read_path(&path).unwrap();
                assert_same(&soup, &back);
            }
        }
    }
    // Only the written files remain: no temporary leftovers.
    let n = std::fs::read_dir(dir.path()).unwrap().count();
    assert_eq!(n, 3 * variants().len() * 2);
}

/// An empty soup can be written, but no reader takes a file without faces for a mesh: it is
/// refused with `NoFaces` (so that the wrong format or binary garbage never reads as an empty
/// mesh).
#[test]
fn empty_soup_is_written_but_refused_on_reading() {
    let soup = PolygonSoup::new();
    for (format, enc, _) in variants() {
        let mut bytes = Vec::new();
        let opts = WriteOptions::default().with_ply_encoding(enc);
        write(&mut bytes, &soup, format, &opts).unwrap();
        let err = read_bytes(&bytes, format, "memory").unwrap_err();
        assert!(
            matches!(
                err,
                IoError::NoFaces {
                    binary_at: None,
                    ..
                }
            ),
            "{format}: {err}"
        );
    }
}

/// A point cloud (vertices, no faces) is refused as a mesh, with its vertices and per-vertex
/// attributes in the error for a caller that describes point clouds (`surftopo info`).
#[test]
fn a_point_cloud_is_refused_with_its_points() {
    let mut soup = PolygonSoup::new();
    soup.positions = vec![[0.0, 1.0, 2.0], [3.0, 4.5, -6.0], [1e-300, 7.0, 8.0]];
    soup.attributes.vertex = ["nx", "ny", "nz"]
        .iter()
        .map(|name| surftopo_io::VertexProperty {
            name: (*name).to_owned(),
            scalar: surftopo_io::ScalarType::F32,
            values: vec![0.0, 0.5, 1.0],
        })
        .collect();
    for (format, enc, _) in variants() {
        if format == Format::Stl {
            continue;
        }
        let mut bytes = Vec::new();
        let opts = WriteOptions::default().with_ply_encoding(enc);
        write(&mut bytes, &soup, format, &opts).unwrap();
        match read_bytes(&bytes, format, "cloud") {
            Err(IoError::NoFaces {
                points: Some(points),
                binary_at: None,
                ..
            }) => {
                assert_eq!(points.positions, soup.positions, "{format}");
                assert_eq!(points.face_count(), 0);
                let names: Vec<&str> = points
                    .attributes
                    .vertex
                    .iter()
                    .map(|p| p.name.as_str())
                    .collect();
                // OFF holds colours only.
                let expected: &[&str] = if format == Format::Off {
                    &[]
                } else {
                    &["nx", "ny", "nz"]
                };
                assert_eq!(names, expected, "{format}");
            }
            other => panic!("{format}: {other:?}"),
        }
        let message = read_bytes(&bytes, format, "cloud").unwrap_err().to_string();
        assert_eq!(
            message, "cloud: no faces: a point cloud of 3 vertices",
            "{format}"
        );
    }
}

#[test]
fn text_readers_record_face_lines() {
    let soup = cube_quads();
    for (format, enc) in [
        (Format::Obj, PlyEncoding::Ascii),
        (Format::Off, PlyEncoding::Ascii),
        (Format::Ply, PlyEncoding::Ascii),
    ] {
        let back = in_memory(&soup, format, enc);
        assert_eq!(back.face_lines.len(), 6, "{format}");
        let first = back.face_lines[0];
        assert!(back.face_lines.windows(2).all(|w| w[1] == w[0] + 1));
        let expected = match format {
            Format::Obj => 9,  // after 8 `v` lines
            Format::Off => 11, // OFF, counts, 8 vertices
            _ => 18,           // 9 header lines, 8 vertices
        };
        assert_eq!(first, expected, "{format}");
    }
    let bin = in_memory(&soup, Format::Ply, PlyEncoding::BinaryLittleEndian);
    assert!(bin.face_lines.is_empty());
}

#[test]
fn writers_reject_invalid_soups_and_stl() {
    let mut bad = octahedron();
    bad.face_indices[4] = 99;
    let err = write(Vec::new(), &bad, Format::Obj, &WriteOptions::default()).unwrap_err();
    assert!(matches!(err, IoError::InvalidSoup { .. }), "{err}");
    let mut nan = octahedron();
    nan.positions[2][1] = f64::NAN;
    let err = write(Vec::new(), &nan, Format::Ply, &WriteOptions::default()).unwrap_err();
    assert!(matches!(err, IoError::InvalidSoup { .. }), "{err}");
}

#[test]
fn failed_write_path_keeps_old_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("keep.off");
    write_path(&path, &cube_quads(), &WriteOptions::default()).unwrap();
    let before = std::fs::read(&path).unwrap();
    let mut bad = octahedron();
    bad.face_offsets.push(1000);
    assert!(write_path(&path, &bad, &WriteOptions::default()).is_err());
    assert_eq!(std::fs::read(&path).unwrap(), before);
    // Renaming over a directory fails after the data was written: the
    // temporary file must be gone.
    let target = dir.path().join("adir.obj");
    std::fs::create_dir(&target).unwrap();
    let err = write_path(&target, &cube_quads(), &WriteOptions::default()).unwrap_err();
    assert!(matches!(err, IoError::Io { .. }), "{err}");
    assert!(err.to_string().contains("adir.obj"), "{err}");
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names.len(), 2, "{names:?}");
}

fn finite_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        any::<f64>().prop_filter("finite", |x| x.is_finite()),
        // Subnormals, signed zeros and extremes.
        (0u64..(1u64 << 52)).prop_map(f64::from_bits),
        (0u64..(1u64 << 52)).prop_map(|b| -f64::from_bits(b)),
        Just(-0.0),
        Just(0.0),
        Just(1e308),
        Just(-1e308),
        Just(f64::MAX),
        Just(f64::MIN_POSITIVE),
        Just(5e-324),
        -1e6..1e6f64,
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn positions_round_trip_bit_exact(
        coords in proptest::collection::vec([finite_f64(), finite_f64(), finite_f64()], 3..40),
        extra_faces in proptest::collection::vec(proptest::collection::vec(0u32..1000, 3..7), 0..8),
    ) {
        let n = coords.len() as u32;
        let mut soup = PolygonSoup::new();
        soup.positions = coords;
        soup.push_face(&[0, 1, 2]);
        for f in &extra_faces {
            let f: Vec<u32> = f.iter().map(|i| i % n).collect();
            soup.push_face(&f);
        }
        for (format, enc, _) in variants() {
            let back = in_memory(&soup, format, enc);
            assert_same(&soup, &back);
        }
    }
}
