//! No input may make a reader panic: random bytes and random mutations of
//! valid files go through every reader (errors are fine).

mod common;

use proptest::prelude::*;
use surftopo_io::{Format, PlyEncoding, WriteOptions, read_bytes, write};

/// Valid files of every kind, as seeds for mutation.
fn seeds() -> Vec<(Format, Vec<u8>)> {
    let mut out = Vec::new();
    for soup in [
        common::cube_quads(),
        common::octahedron(),
        common::torus(3, 3),
    ] {
        for (format, enc) in [
            (Format::Obj, PlyEncoding::Ascii),
            (Format::Off, PlyEncoding::Ascii),
            (Format::Ply, PlyEncoding::Ascii),
            (Format::Ply, PlyEncoding::BinaryLittleEndian),
            (Format::Ply, PlyEncoding::BinaryBigEndian),
        ] {
            let mut bytes = Vec::new();
            write(
                &mut bytes,
                &soup,
                format,
                &WriteOptions::default().with_ply_encoding(enc),
            )
            .unwrap();
            out.push((format, bytes));
        }
    }
    out.push((Format::Ply, tristrip_ply()));
    // Attributes: OBJ per-corner vt/vn, PLY vertex properties, COFF colours.
    out.push((
        Format::Obj,
        b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0 0\nvt 0 1\nvn 0 0 1\n\
f 1/1/1 3/3/1 2/2/1\nf 1/2/1 2/2/1 4/1/1\nf 2//1 3//1 4//1\nf 3/3 1/1 4/2\n"
            .to_vec(),
    ));
    out.push((
        Format::Ply,
        b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n\
property float y\nproperty float z\nproperty uchar red\nproperty float nx\nproperty int q\n\
element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0 1 0.5 -3\n\
1 0 0 2 0.25 4\n0 1 0 255 1 5\n3 0 1 2\n"
            .to_vec(),
    ));
    out.push((
        Format::Off,
        b"COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2\n".to_vec(),
    ));
    out.push((Format::Stl, b"solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid a\n".to_vec()));
    let mut stl = vec![b' '; 80];
    stl.extend_from_slice(&1u32.to_le_bytes());
    stl.extend((0..50u8).map(|b| b.wrapping_mul(37)));
    out.push((Format::Stl, stl));
    out.push((
        Format::Off,
        b"COFF 3 1 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1 1\n3 0 1 2 1 0 0\n".to_vec(),
    ));
    out
}

fn tristrip_ply() -> Vec<u8> {
    let mut f = b"ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n".to_vec();
    for i in 0..12 {
        f.extend_from_slice(&(i as f32).to_le_bytes());
    }
    f.extend_from_slice(&6i32.to_le_bytes());
    for v in [0i32, 1, 2, 3, -1, 2] {
        f.extend_from_slice(&v.to_le_bytes());
    }
    f
}

#[derive(Clone, Debug)]
enum Edit {
    Flip(usize, u8),
    Insert(usize, Vec<u8>),
    Delete(usize, usize),
    Truncate(usize),
    Splice(usize, &'static str),
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Edit::Flip(i, b)),
        (any::<usize>(), proptest::collection::vec(any::<u8>(), 1..8))
            .prop_map(|(i, v)| Edit::Insert(i, v)),
        (any::<usize>(), 1usize..16).prop_map(|(i, n)| Edit::Delete(i, n)),
        any::<usize>().prop_map(Edit::Truncate),
        (
            any::<usize>(),
            prop::sample::select(vec![
                "-1",
                "4294967295",
                "99999999999999999999",
                "nan",
                "1e999",
                " ",
                "\n",
                "#",
                "/",
                "\\\n",
                "-",
                "element face 4294967295\n",
                "property list uint int vertex_indices\n",
                "end_header\n",
                "solid",
                "facet",
                "endfacet",
                "vertex",
                "OFF",
                "\r\n",
                "0",
            ])
        )
            .prop_map(|(i, s)| Edit::Splice(i, s)),
    ]
}

fn apply(data: &mut Vec<u8>, e: &Edit) {
    let n = data.len().max(1);
    match e {
        Edit::Flip(i, b) => {
            if !data.is_empty() {
                data[i % n] ^= b | 1;
            }
        }
        Edit::Insert(i, v) => {
            let at = i % (data.len() + 1);
            data.splice(at..at, v.iter().copied());
        }
        Edit::Delete(i, k) => {
            let at = i % n;
            let end = (at + k).min(data.len());
            if at < end {
                data.drain(at..end);
            }
        }
        Edit::Truncate(i) => data.truncate(i % n),
        Edit::Splice(i, s) => {
            let at = i % (data.len() + 1);
            data.splice(at..at, s.bytes());
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2048))]

    #[test]
    fn random_bytes_never_panic(data in proptest::collection::vec(any::<u8>(), 0..1024)) {
        for format in Format::ALL {
            let _ = read_bytes(&data, format, "random");
        }
    }

    #[test]
    fn token_soup_never_panics(
        header in prop::sample::select(vec![
            "", "OFF\n", "COFF 3 1 0\n", "nOFF 3 ", "solid x\n",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n",
            "ply\nformat binary_big_endian 1.0\nelement vertex 2\nproperty uchar x\nproperty uchar y\nproperty uchar z\nelement tristrips 1\nproperty list uchar char vertex_indices\nend_header\n",
        ]),
        tokens in proptest::collection::vec(prop::sample::select(vec![
            "v", "f", "vn", " ", "  ", "\t", "\n", "\r\n", "\\\n", "#", "0", "1", "2", "3", "-1", "-4",
            "1.5", "-2e3", "nan", "/", "//", "1/2/3", "facet", "normal", "outer", "loop", "vertex",
            "endloop", "endfacet", "endsolid", "\u{0}", "\u{ff}", "4294967296", "vt", "1//2",
            "1/1", "2/-1/1",
        ]), 0..64),
    ) {
        let data: Vec<u8> = header.bytes().chain(tokens.concat().bytes()).collect();
        for format in Format::ALL {
            if let Ok(soup) = read_bytes(&data, format, "tokens") {
                prop_assert!(soup.validate().is_ok(), "{:?}", soup.validate());
            }
        }
    }

    #[test]
    fn mutated_files_never_panic(
        seed in any::<prop::sample::Index>(),
        edits in proptest::collection::vec(edit(), 1..6),
    ) {
        let seeds = seeds();
        let (format, mut data) = seeds[seed.index(seeds.len())].clone();
        for e in &edits {
            apply(&mut data, e);
        }
        // The seed's own reader and every other reader.
        if let Ok(soup) = read_bytes(&data, format, "mutated") {
            // Whatever is accepted must be a consistent soup.
            prop_assert!(soup.validate().is_ok(), "{:?}", soup.validate());
        }
        for other in Format::ALL {
            let _ = read_bytes(&data, other, "mutated");
        }
    }
}

#[test]
fn hostile_headers_fail_fast_without_huge_allocation() {
    let cases: &[(Format, &[u8])] = &[
        (Format::Off, b"OFF\n4294967295 4294967295 0\n0 0 0\n"),
        (Format::Off, b"OFF\n99999999999999999999 1 0\n"),
        (Format::Off, b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n"),
        (Format::Ply, b"ply\nformat binary_little_endian 1.0\nelement vertex 4294967295\nproperty float x\nproperty float y\nproperty float z\nend_header\n"),
        (Format::Ply, b"ply\nformat binary_little_endian 1.0\nelement face 18446744073709551615\nproperty list uint uint vertex_indices\nend_header\n\xff\xff\xff\xff"),
        (Format::Ply, b"ply\nformat ascii 1.0\nelement junk 18446744073709551615\nend_header\n"),
        (Format::Ply, b"ply\nformat ascii 1.0\nelement junk 18446744073709551615\nproperty list uint int a\nend_header\n4294967295 1 2"),
        (Format::Ply, b"ply\nformat binary_big_endian 1.0\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n\x7f\xff\xff\xff"),
        (Format::Stl, b"\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\xff\xff\xff\xff"),
    ];
    for (format, data) in cases {
        let r = read_bytes(data, *format, "hostile");
        if let Ok(s) = &r {
            assert!(
                s.positions.is_empty() && s.face_count() == 0,
                "{format}: {s:?}"
            );
        }
    }
}
