//! Format variants the readers must accept.

use surftopo_io::{Format, PolygonSoup, read_bytes};

fn read(data: &[u8], format: Format) -> PolygonSoup {
    read_bytes(data, format, "test").unwrap_or_else(|e| panic!("{e}"))
}

fn faces(s: &PolygonSoup) -> Vec<Vec<u32>> {
    s.faces().map(<[u32]>::to_vec).collect()
}

#[test]
fn obj_variants() {
    let src = b"# comment\r\nmtllib a.mtl\r\no thing\r\nv 0 0 0 1\r\nv\t1 0 0 0.5 0.2 0.1\r\nvt 0 0\r\nvn 0 0 1\r\nv 0 1 0\r\n  v 1 1 0\r\ns off\r\ng grp\r\nusemtl m\r\nf 1/1/1 2/1/1 3/1/1\r\nf 2//1 4//1 3//1\r\nf -4/1 -3/1 -1/1 -2/1\r\nl 1 2\r\nf 1 2 \\\r\n 4\r\n\r\n";
    let s = read(src, Format::Obj);
    assert_eq!(s.positions.len(), 4);
    assert_eq!(s.positions[1], [1.0, 0.0, 0.0]);
    assert_eq!(
        faces(&s),
        vec![
            vec![0, 1, 2],
            vec![1, 3, 2],
            vec![0, 1, 3, 2],
            vec![0, 1, 3]
        ]
    );
    assert_eq!(s.face_lines, vec![13, 14, 15, 17]);
}

#[test]
fn obj_forward_reference_is_accepted() {
    let s = read(b"f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", Format::Obj);
    assert_eq!(faces(&s), vec![vec![0, 1, 2]]);
}

#[test]
fn off_variants() {
    // Counts on the header line, comments, CRLF, trailing blanks.
    let s = read(
        b"OFF 4 2 0\r\n# c\r\n0 0 0 \r\n1 0 0\r\n0 1 0\r\n1 1 0\r\n3 0 1 2\r\n3 1 3 2 \r\n",
        Format::Off,
    );
    assert_eq!(s.positions.len(), 4);
    assert_eq!(faces(&s), vec![vec![0, 1, 2], vec![1, 3, 2]]);
    assert_eq!(s.face_lines, vec![7, 8]);

    // COFF with vertex colours, face colours, no edge count.
    let s = read(
        b"COFF\n3 1\n0 0 0 255 255 255 255\n1 0 0 1 2 3 4\n0 1 0 5 6 7 8\n3 0 1 2 0.5 0.5 0.5\n",
        Format::Off,
    );
    assert_eq!(
        s.positions,
        vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
    );
    assert_eq!(faces(&s), vec![vec![0, 1, 2]]);

    // NOFF / STOFF / nOFF.
    let s = read(
        b"NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n",
        Format::Off,
    );
    assert_eq!(s.face_count(), 1);
    let s = read(
        b"STOFF\n3 1 0\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n",
        Format::Off,
    );
    assert_eq!(s.positions[2], [0.0, 1.0, 0.0]);
    let s = read(
        b"nOFF\n3\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 2 1 0\n",
        Format::Off,
    );
    assert_eq!(faces(&s), vec![vec![2, 1, 0]]);

    // No keyword at all.
    let s = read(b"3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", Format::Off);
    assert_eq!(s.face_count(), 1);
}

#[test]
fn off_token_stream() {
    // Everything on one line.
    let s = read(
        b"OFF 4 2 0 0 0 0 1 0 0 0 1 0 1 1 0 3 0 1 2 3 1 3 2",
        Format::Off,
    );
    assert_eq!(s.positions[3], [1.0, 1.0, 0.0]);
    assert_eq!(faces(&s), vec![vec![0, 1, 2], vec![1, 3, 2]]);
    // Oddly split lines: two vertices per line, a face split over lines.
    let s = read(
        b"OFF\n4 2 0\n0 0 0 0 1 0\n0 1 0 1 1 0\n3 0 1\n2 3 1 3 2\n",
        Format::Off,
    );
    assert_eq!(
        s.positions,
        vec![
            [0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 1.0, 0.0]
        ]
    );
    assert_eq!(faces(&s), vec![vec![0, 1, 2], vec![1, 3, 2]]);
    // Values split over lines in line mode.
    let s = read(b"OFF\n3 1 0\n0 0\n0\n1 0 0\n0 1 0\n3\n0 1 2\n", Format::Off);
    assert_eq!(s.positions[0], [0.0, 0.0, 0.0]);
    assert_eq!(faces(&s), vec![vec![0, 1, 2]]);
}

/// The four corners every PLY case below encodes.
const UNIT_SQUARE: [[f64; 3]; 4] = [
    [0.0, 0.0, 0.0],
    [1.0, 0.0, 0.0],
    [0.0, 1.0, 0.0],
    [1.0, 1.0, 0.0],
];

const PLY_HEAD: &str = "ply\nformat {fmt} 1.0\ncomment hi\nobj_info x\nelement vertex 4\nproperty uchar red\nproperty {xt} x\nproperty {xt} y\nproperty {xt} z\nproperty list uchar float extra\nelement edge 1\nproperty int a\nproperty int b\nelement face 2\nproperty uchar flags\nproperty list {ct} {it} vertex_index\nproperty list uchar float texcoord\nend_header\n";

fn ply_header(fmt: &str, xt: &str, ct: &str, it: &str) -> Vec<u8> {
    PLY_HEAD
        .replace("{fmt}", fmt)
        .replace("{xt}", xt)
        .replace("{ct}", ct)
        .replace("{it}", it)
        .into_bytes()
}

#[test]
fn ply_ascii_with_skipped_properties_and_elements() {
    let mut f = ply_header("ascii", "float", "uchar", "int");
    f.extend_from_slice(b"7 0 0 0 2 0.5 0.5\n7 1 0 0 0\n7\n0 1 0 1 9\n7 1 1 0 0\n1 2\n0 3 0 1 2 0\n0 3 1 3 2 2 0.1 0.2\n");
    let s = read(&f, Format::Ply);
    assert_eq!(s.positions, UNIT_SQUARE);
    assert_eq!(faces(&s), vec![vec![0, 1, 2], vec![1, 3, 2]]);
    assert_eq!(s.face_lines, vec![25, 26]);
}

fn put(out: &mut Vec<u8>, be: bool, bytes_le: &[u8]) {
    if be {
        out.extend(bytes_le.iter().rev());
    } else {
        out.extend_from_slice(bytes_le);
    }
}

#[test]
fn ply_binary_both_endians_and_types() {
    for be in [false, true] {
        for (xt, ct, it) in [
            ("float", "uchar", "int"),
            ("double", "ushort", "uint"),
            ("short", "int", "ushort"),
            ("int8", "uint8", "uint8"),
        ] {
            let fmt = if be {
                "binary_big_endian"
            } else {
                "binary_little_endian"
            };
            let mut f = ply_header(fmt, xt, ct, it);
            let coords = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]];
            for p in coords {
                f.push(9); // red
                for c in p {
                    match xt {
                        "float" => put(&mut f, be, &(c as f32).to_le_bytes()),
                        "double" => put(&mut f, be, &f64::from(c).to_le_bytes()),
                        "short" => put(&mut f, be, &(c as i16).to_le_bytes()),
                        _ => f.push(c as u8),
                    }
                }
                f.push(1); // extra list: 1 float
                put(&mut f, be, &1.5f32.to_le_bytes());
            }
            put(&mut f, be, &5i32.to_le_bytes()); // edge
            put(&mut f, be, &6i32.to_le_bytes());
            for face in [[0u32, 1, 2], [1, 3, 2]] {
                f.push(0); // flags
                match ct {
                    "uchar" | "uint8" => f.push(3),
                    "ushort" => put(&mut f, be, &3u16.to_le_bytes()),
                    _ => put(&mut f, be, &3i32.to_le_bytes()),
                }
                for i in face {
                    match it {
                        "int" | "uint" => put(&mut f, be, &i.to_le_bytes()),
                        "ushort" => put(&mut f, be, &(i as u16).to_le_bytes()),
                        _ => f.push(i as u8),
                    }
                }
                f.push(0); // empty texcoord list
            }
            let s = read(&f, Format::Ply);
            assert_eq!(s.positions, UNIT_SQUARE, "{xt} {be}");
            assert_eq!(
                faces(&s),
                vec![vec![0, 1, 2], vec![1, 3, 2]],
                "{xt} {ct} {it} {be}"
            );
            assert!(s.face_lines.is_empty());
        }
    }
}

#[test]
fn ply_tristrips() {
    // Strip 0 1 2 3 4, restart, 5 6 7, restart, degenerate 1 1 2 3.
    let strip: [i32; 14] = [0, 1, 2, 3, 4, -1, 5, 6, 7, -1, 1, 1, 2, 3];
    let expected = vec![
        vec![0, 1, 2],
        vec![2, 1, 3],
        vec![2, 3, 4],
        vec![5, 6, 7],
        vec![2, 1, 3],
    ];
    let head = "ply\nformat {fmt} 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n";
    let mut ascii = head.replace("{fmt}", "ascii").into_bytes();
    for i in 0..8 {
        ascii.extend_from_slice(format!("{i} 0 0\n").as_bytes());
    }
    ascii.extend_from_slice(b"14 0 1 2 3 4 -1 5 6 7 -1 1 1 2 3\n");
    let s = read(&ascii, Format::Ply);
    assert_eq!(faces(&s), expected);
    assert_eq!(s.face_lines, vec![18; 5]);

    let mut bin = head.replace("{fmt}", "binary_little_endian").into_bytes();
    for i in 0..8 {
        for c in [i as f32, 0.0, 0.0] {
            bin.extend_from_slice(&c.to_le_bytes());
        }
    }
    bin.extend_from_slice(&14i32.to_le_bytes());
    for v in strip {
        bin.extend_from_slice(&v.to_le_bytes());
    }
    let s = read(&bin, Format::Ply);
    assert_eq!(faces(&s), expected);
}

#[test]
fn ply_crlf_header() {
    let f = b"ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\nelement face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n";
    let s = read(f, Format::Ply);
    assert_eq!(faces(&s), vec![vec![0, 1, 2]]);
}

#[test]
fn stl_ascii_and_binary() {
    let ascii = b"solid cube\n  facet normal 0 0 -1\n    outer loop\n      vertex 0 0 0\n      vertex 0 1 0\n      vertex 1 0 0\n    endloop\n  endfacet\n  facet normal nan nan nan\n    outer loop\n      vertex 1 0 0\n      vertex 0 1 0\n      vertex 1 1 0\n    endloop\n  endfacet\nendsolid cube\n";
    let s = read(ascii, Format::Stl);
    assert_eq!(s.positions.len(), 6);
    assert_eq!(faces(&s), vec![vec![0, 1, 2], vec![3, 4, 5]]);
    assert_eq!(s.positions[4], [0.0, 1.0, 0.0]);
    assert_eq!(s.face_lines, vec![2, 9]);

    // Binary whose header starts with "solid" (common in the wild).
    let mut bin = b"solid but binary".to_vec();
    bin.resize(80, b' ');
    bin.extend_from_slice(&2u32.to_le_bytes());
    for t in 0..2 {
        bin.extend_from_slice(&[0u8; 12]);
        for k in 0..9 {
            bin.extend_from_slice(&((t * 9 + k) as f32).to_le_bytes());
        }
        bin.extend_from_slice(&[0, 0]);
    }
    let s = read(&bin, Format::Stl);
    assert_eq!(s.positions.len(), 6);
    assert_eq!(s.positions[5], [15.0, 16.0, 17.0]);
    assert_eq!(faces(&s), vec![vec![0, 1, 2], vec![3, 4, 5]]);
    assert!(s.face_lines.is_empty());
}

#[test]
fn soup_helpers() {
    let mut s = PolygonSoup::from_triangles(vec![[0.0; 3]; 4], &[[0, 1, 2], [0, 2, 3]]);
    assert!(s.is_all_triangles());
    assert_eq!(s.triangles().unwrap(), vec![[0, 1, 2], [0, 2, 3]]);
    s.push_face(&[0, 1, 2, 3]);
    assert!(!s.is_all_triangles());
    let e = s.triangles().unwrap_err();
    assert_eq!((e.face, e.sides), (2, 4));
    assert_eq!(e.to_string(), "face 2 has 4 sides, not 3");
    assert_eq!(s.face(2), &[0, 1, 2, 3]);
    assert_eq!(s.faces().len(), 3);
    assert!(s.validate().is_ok());
    s.face_lines = vec![1];
    assert!(s.validate().is_err());
}
