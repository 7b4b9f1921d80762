//! Formats told from the content (files without a mesh extension, streams), and the binary STL
//! writer, checked by reading back.

mod common;

use common::{assert_same, cube_quads, mixed, torus};
use surftopo_io::{
    Format, IoError, PolygonSoup, ReadLimits, WriteOptions, load_reader, read_bytes,
    read_bytes_detected, read_path_detected, write_encoded,
};

/// The triangles of a soup's fans, as corner positions rounded to `f32` (what STL holds).
fn fan_corners(soup: &PolygonSoup) -> Vec<[[f32; 3]; 3]> {
    let at = |v: u32| soup.positions[v as usize].map(|c| c as f32);
    soup.faces()
        .flat_map(|f| (1..f.len() - 1).map(move |i| [at(f[0]), at(f[i]), at(f[i + 1])]))
        .collect()
}

/// Checks that `back` is `soup` as written in `format` (STL: the fans, corner by corner).
fn check_same(soup: &PolygonSoup, back: &PolygonSoup, format: Format) {
    if format == Format::Stl {
        assert_eq!(fan_corners(soup), fan_corners(back));
        assert!(back.faces().all(|f| f.len() == 3));
    } else {
        assert_same(soup, back);
    }
}

fn encoded(soup: &PolygonSoup, format: Format, gzip: bool) -> Vec<u8> {
    let mut bytes = Vec::new();
    write_encoded(&mut bytes, soup, format, gzip, &WriteOptions::default()).unwrap();
    bytes
}

#[test]
fn every_written_format_is_told_from_a_file_without_extension_plain_and_gzip() {
    let dir = tempfile::tempdir().unwrap();
    for soup in [cube_quads(), mixed(), torus(4, 6)] {
        for format in Format::ALL {
            for gzip in [false, true] {
                let path = dir.path().join(format!("mesh-{format}-{gzip}"));
                std::fs::write(&path, encoded(&soup, format, gzip)).unwrap();
                let (back, told) = read_path_detected(&path, &ReadLimits::default()).unwrap();
                assert_eq!(told, format, "{}", path.display());
                check_same(&soup, &back, format);
            }
        }
    }
}

#[test]
fn a_stream_is_decompressed_by_its_magic_and_sniffed() {
    let soup = torus(3, 5);
    for format in Format::ALL {
        let gz = encoded(&soup, format, true);
        assert!(gz.starts_with(&[0x1f, 0x8b]));
        let bytes = load_reader(&gz[..], &ReadLimits::default(), "<stdin>").unwrap();
        assert_eq!(bytes, encoded(&soup, format, false));
        let (back, told) = read_bytes_detected(&bytes, "<stdin>").unwrap();
        assert_eq!(told, format);
        check_same(&soup, &back, format);
    }
    let small = ReadLimits { max_bytes: 100 };
    let bomb = encoded(&torus(20, 20), Format::Obj, true);
    let e = load_reader(&bomb[..], &small, "<stdin>").unwrap_err();
    assert!(matches!(e, IoError::InputTooLarge { .. }), "{e}");
}

#[test]
fn a_name_with_an_extension_is_believed_and_undecidable_content_is_a_typed_error() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("mesh.data");
    std::fs::write(&path, b"hello\nworld\n").unwrap();
    let e = read_path_detected(&path, &ReadLimits::default()).unwrap_err();
    assert!(matches!(e, IoError::UnknownContent { .. }), "{e:?}");
    assert!(e.to_string().contains("mesh.data: cannot tell"), "{e}");
    assert!(e.to_string().contains("line 1"), "{e}");
    // An OFF file named .obj is read as OBJ (no face: an error), not sniffed.
    let off = dir.path().join("m.obj");
    std::fs::write(&off, encoded(&cube_quads(), Format::Off, false)).unwrap();
    let e = read_path_detected(&off, &ReadLimits::default()).unwrap_err();
    assert!(matches!(e, IoError::NoFaces { .. }), "{e:?}");
}

#[test]
fn binary_stl_rounds_coordinates_to_f32_and_gives_unit_normals() {
    let mut soup = PolygonSoup::new();
    for p in [
        [0.1, 0.0, 0.0],
        [2.0, 0.0, 0.0],
        [0.0, 3.0, 0.0],
        [1.0, 1.0, 0.0],
    ] {
        soup.push_vertex(p);
    }
    soup.push_face(&[0, 1, 2]);
    soup.push_face(&[0, 1, 3]);
    soup.push_face(&[1, 1, 2]); // degenerate: zero normal
    let bytes = encoded(&soup, Format::Stl, false);
    assert_eq!(bytes.len(), 84 + 3 * 50);
    assert_eq!(u32::from_le_bytes(bytes[80..84].try_into().unwrap()), 3);
    let back = read_bytes(&bytes, Format::Stl, "m.stl").unwrap();
    assert_eq!(back.positions[0], [f64::from(0.1f32), 0.0, 0.0]);
    let normal = |t: usize| -> [f32; 3] {
        let at = 84 + 50 * t;
        [0, 1, 2].map(|k| f32::from_le_bytes(bytes[at + 4 * k..at + 4 * k + 4].try_into().unwrap()))
    };
    assert_eq!(normal(0), [0.0, 0.0, 1.0]);
    assert_eq!(normal(1), [0.0, 0.0, 1.0]);
    assert_eq!(normal(2), [0.0, 0.0, 0.0]);
}

proptest::proptest! {
    /// Any bytes after each format's opening: sniffing and reading what it decides never panic,
    /// and every outcome is a soup with faces or a typed error naming the input.
    #[test]
    fn any_bytes_are_sniffed_without_panicking(
        opening in proptest::sample::select(vec!["", "ply\n", "OFF\n", "solid x\nfacet ", "v 0 0 0\n"]),
        tail in proptest::collection::vec(proptest::prelude::any::<u8>(), 0..400),
    ) {
        let bytes = [opening.as_bytes(), &tail].concat();
        match read_bytes_detected(&bytes, "fuzz") {
            Ok((soup, _)) => proptest::prop_assert!(soup.face_count() > 0),
            Err(e) => proptest::prop_assert!(e.to_string().starts_with("fuzz"), "{}", e),
        }
    }
}
