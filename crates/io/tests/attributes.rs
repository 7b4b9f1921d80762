//! Attributes through the readers and writers: OBJ `vt`/`vn` (per vertex or per corner), PLY
//! vertex properties by name and type, COFF colours; every written file is also parsed here by
//! a small independent reader (text split into words; binary PLY decoded from its header).

use surftopo_io::{
    CornerTable, Format, IoError, PlyEncoding, PlyPrecision, PolygonSoup, ScalarType,
    VertexProperty, WriteOptions, read_bytes,
};
use surftopo_testkit::obj_text::{corners as obj_corners, statements as obj_lines};
use surftopo_testkit::ply_parse::parse as parse_ply;

fn read(text: &[u8], format: Format) -> PolygonSoup {
    read_bytes(text, format, "test").unwrap()
}

fn write(soup: &PolygonSoup, format: Format, options: &WriteOptions) -> Vec<u8> {
    let mut out = Vec::new();
    surftopo_io::write(&mut out, soup, format, options).unwrap();
    out
}

fn column<'a>(soup: &'a PolygonSoup, name: &str) -> &'a [f64] {
    let i = soup
        .attributes
        .vertex_property(name)
        .unwrap_or_else(|| panic!("no vertex property {name}"));
    &soup.attributes.vertex[i].values
}

fn numbers(words: &[&str]) -> Vec<f64> {
    words.iter().map(|w| w.parse().unwrap()).collect()
}

/// A square pyramid; vertex 4 (the apex) has one texture coordinate on two of its faces and
/// another on the other two: a seam, so the coordinates are per corner.
const SEAM_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n\
vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\nvt 0.25 0.75\n\
vn 0 0 -1\nvn 0 0 1\n\
f 1/1/1 4/4/1 3/3/1 2/2/1\nf 1/1/2 2/2/2 5/5/2\nf 2/2/2 3/3/2 5/5/2\nf 3/3/2 4/4/2 5/6/2\nf 4/4/2 1/1/2 5/6/2\n";

#[test]
fn obj_per_corner_texcoords_survive_an_obj_round_trip() {
    let soup = read(SEAM_OBJ.as_bytes(), Format::Obj);
    let table = soup
        .attributes
        .corner_texcoords
        .as_ref()
        .expect("per corner");
    assert_eq!((table.len(), table.width), (6, 2));
    // The normals differ between corners of vertex 0 too (faces 0 and 1).
    assert!(soup.attributes.corner_normals.is_some());
    assert!(soup.attributes.vertex.is_empty());
    let text = String::from_utf8(write(&soup, Format::Obj, &WriteOptions::default())).unwrap();
    let vt: Vec<Vec<f64>> = obj_lines(&text, "vt").iter().map(|w| numbers(w)).collect();
    let vn: Vec<Vec<f64>> = obj_lines(&text, "vn").iter().map(|w| numbers(w)).collect();
    assert_eq!(vt.len(), 6);
    assert_eq!(vn.len(), 2);
    // Every corner keeps its coordinate and normal: compare with the input, parsed the same way.
    let input_vt: Vec<Vec<f64>> = obj_lines(SEAM_OBJ, "vt")
        .iter()
        .map(|w| numbers(w))
        .collect();
    let input_vn: Vec<Vec<f64>> = obj_lines(SEAM_OBJ, "vn")
        .iter()
        .map(|w| numbers(w))
        .collect();
    let (a, b) = (obj_corners(SEAM_OBJ), obj_corners(&text));
    assert_eq!(a.len(), b.len());
    for ((va, ta, na), (vb, tb, nb)) in a.into_iter().zip(b) {
        assert_eq!(va, vb);
        assert_eq!(input_vt[ta.unwrap()], vt[tb.unwrap()]);
        assert_eq!(input_vn[na.unwrap()], vn[nb.unwrap()]);
    }
    // Read back by our reader: the same soup.
    assert_eq!(read(text.as_bytes(), Format::Obj), soup);
}

#[test]
fn obj_consistent_corners_become_per_vertex_and_go_to_ply() {
    // vt permuted against v, but each vertex's corners agree: per-vertex.
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n\
vt 0.3 0.4\nvt 0.1 0.2\nvt 0.5 0.6\nvt 0.7 0.8\n\
f 1/2 3/3 2/1\nf 1/2 2/1 4/4\nf 2/1 3/3 4/4\nf 3/3 1/2 4/4\n";
    let soup = read(obj.as_bytes(), Format::Obj);
    assert!(soup.attributes.corner_texcoords.is_none());
    assert_eq!(column(&soup, "u"), [0.1, 0.3, 0.5, 0.7]);
    assert_eq!(column(&soup, "v"), [0.2, 0.4, 0.6, 0.8]);
    assert!(soup.unwritable(Format::Ply).is_empty());
    let ply = write(
        &soup,
        Format::Ply,
        &WriteOptions::default().with_ply_encoding(PlyEncoding::Ascii),
    );
    let parsed = parse_ply(&ply);
    assert_eq!(parsed.names, ["x", "y", "z", "u", "v"]);
    assert_eq!(parsed.rows[2], [0.0, 1.0, 0.0, 0.5, 0.6]);
    // And back to OBJ: one vt per vertex, `f a/a`.
    let back = read(&ply, Format::Ply);
    let text = String::from_utf8(write(&back, Format::Obj, &WriteOptions::default())).unwrap();
    assert_eq!(obj_lines(&text, "vt")[3], ["0.7", "0.8"]);
    assert!(
        obj_corners(&text)
            .iter()
            .all(|&(v, t, n)| t == Some(v) && n.is_none())
    );
}

#[test]
fn obj_unreferenced_normals_one_per_vertex_are_per_vertex() {
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n\
vn 1 0 0\nvn 0 1 0\nvn 0 0 1\nvn 0.5 0.5 0.5\n\
f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
    let soup = read(obj.as_bytes(), Format::Obj);
    assert_eq!(column(&soup, "nz"), [0.0, 0.0, 1.0, 0.5]);
    // Unreferenced and not one per vertex: kept as a table whose corners have none, written back.
    let obj = obj.replace("vn 0.5 0.5 0.5\n", "");
    let soup = read(obj.as_bytes(), Format::Obj);
    let table = soup.attributes.corner_normals.as_ref().unwrap();
    assert_eq!(table.len(), 3);
    assert!(table.corners.iter().all(|&c| c == CornerTable::NONE));
    let text = String::from_utf8(write(&soup, Format::Obj, &WriteOptions::default())).unwrap();
    assert_eq!(obj_lines(&text, "vn").len(), 3);
    let warnings = soup.unwritable(Format::Ply);
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(warnings[0].contains("per-corner normals (vn): 3 values on 0 face corners"));
}

#[test]
fn obj_bad_texcoord_index_names_the_line() {
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/2\n";
    let err = read_bytes(obj.as_bytes(), Format::Obj, "t.obj").unwrap_err();
    assert_eq!(
        err.to_string(),
        "t.obj:5: vt index 2 out of range (1 vt lines)"
    );
    let err = read_bytes(
        b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x 2 3\n",
        Format::Obj,
        "t.obj",
    );
    assert!(
        err.unwrap_err()
            .to_string()
            .starts_with("t.obj:4: invalid face vertex")
    );
    let err = read_bytes(
        b"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 a\nf 1 2 3\n",
        Format::Obj,
        "t.obj",
    );
    assert!(
        err.unwrap_err()
            .to_string()
            .starts_with("t.obj:4: invalid vt number 2")
    );
}

#[test]
fn obj_skipped_statements_are_listed() {
    let obj = "mtllib a.mtl\no thing\nusemtl red\nv 0 0 0 1 0 0\nv 1 0 0 # c\nv 0 1 0 0.5\nusemtl blue\nf 1 2 3\n";
    let soup = read(obj.as_bytes(), Format::Obj);
    assert_eq!(
        soup.attributes.not_kept,
        [
            "OBJ numbers after x y z (colours or weights) on 2 'v' statements",
            "OBJ 'mtllib' statements (1)",
            "OBJ 'o' statements (1)",
            "OBJ 'usemtl' statements (2)"
        ]
    );
}

/// A tetrahedron with normals, `s t`, RGBA colours, a float `quality` and an int `flags`.
fn rich_soup() -> PolygonSoup {
    let mut soup = PolygonSoup::from_triangles(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 0.1],
        ],
        &[[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]],
    );
    let column = |name: &str, scalar, values: [f64; 4]| VertexProperty {
        name: name.to_owned(),
        scalar,
        values: values.to_vec(),
    };
    soup.attributes.vertex = vec![
        column("nx", ScalarType::F64, [-0.5, 1.0, 0.0, 0.1]),
        column("ny", ScalarType::F64, [-0.5, 0.0, 1.0, 0.2]),
        column("nz", ScalarType::F64, [-0.7071067811865475, 0.0, 0.0, 0.3]),
        column("s", ScalarType::F32, [0.0, 1.0, 0.0, 0.5]),
        column("t", ScalarType::F32, [0.0, 0.0, 1.0, 0.25]),
        column("red", ScalarType::U8, [255.0, 0.0, 10.0, 128.0]),
        column("green", ScalarType::U8, [0.0, 255.0, 20.0, 128.0]),
        column("blue", ScalarType::U8, [0.0, 0.0, 30.0, 128.0]),
        column("alpha", ScalarType::U8, [255.0, 255.0, 255.0, 0.0]),
        column(
            "quality",
            ScalarType::F32,
            [0.125, -2.5, 3.0, 1e-3f32 as f64],
        ),
        column(
            "flags",
            ScalarType::I32,
            [-7.0, 0.0, 123456.0, i32::MIN as f64],
        ),
    ];
    soup
}

#[test]
fn ply_properties_round_trip_in_every_encoding() {
    let soup = rich_soup();
    for encoding in [
        PlyEncoding::Ascii,
        PlyEncoding::BinaryLittleEndian,
        PlyEncoding::BinaryBigEndian,
    ] {
        let options = WriteOptions::default().with_ply_encoding(encoding);
        let bytes = write(&soup, Format::Ply, &options);
        // Our reader: the same soup, bit for bit (names, types, values).
        let mut back = read(&bytes, Format::Ply);
        back.face_lines.clear();
        assert_eq!(back, soup, "{encoding:?}");
        // The independent parse: names, types and values by position.
        let parsed = parse_ply(&bytes);
        let mut names = vec!["x", "y", "z"];
        names.extend(soup.attributes.vertex.iter().map(|p| p.name.as_str()));
        assert_eq!(parsed.names, names, "{encoding:?}");
        assert_eq!(parsed.types[..3], ["double"; 3]);
        assert_eq!(parsed.types[8], "uchar");
        assert_eq!(parsed.types[13], "int");
        for (v, row) in parsed.rows.iter().enumerate() {
            assert_eq!(row[..3], soup.positions[v]);
            for (k, p) in soup.attributes.vertex.iter().enumerate() {
                // An ascii `float` is the shortest decimal of the f32: compare as f32.
                let written = match &parsed.types[3 + k][..] {
                    "float" => f64::from(row[3 + k] as f32),
                    _ => row[3 + k],
                };
                assert_eq!(
                    written, p.values[v],
                    "{encoding:?} {} of vertex {v}",
                    p.name
                );
            }
        }
        assert_eq!(parsed.faces.len(), 4);
        assert_eq!(parsed.faces[2], [1, 2, 3]);
    }
}

#[test]
fn float_ply_rounds_positions_and_double_properties_to_f32() {
    let mut soup = rich_soup();
    soup.positions[3] = [0.1, 1.0 / 3.0, -1e-7];
    for encoding in [PlyEncoding::Ascii, PlyEncoding::BinaryLittleEndian] {
        let options = WriteOptions::default()
            .with_ply_encoding(encoding)
            .with_ply_precision(PlyPrecision::Float);
        let bytes = write(&soup, Format::Ply, &options);
        let parsed = parse_ply(&bytes);
        assert_eq!(parsed.types[..6], ["float"; 6], "{encoding:?}");
        assert_eq!(parsed.types[8], "uchar");
        let back = read(&bytes, Format::Ply);
        for v in 0..4 {
            // Binary: the f32 itself; ascii: the shortest decimal of the f32, which the reader
            // takes as written (positions are not rounded to their declared type).
            let rounded = soup.positions[v].map(|c| match encoding {
                PlyEncoding::Ascii => (c as f32).to_string().parse().unwrap(),
                _ => f64::from(c as f32),
            });
            assert_eq!(back.positions[v], rounded, "{encoding:?}");
            assert_eq!(parsed.rows[v][..3], rounded);
            assert_eq!(
                rounded.map(|c| c as f32),
                soup.positions[v].map(|c| c as f32)
            );
            let nz = f64::from(soup.attributes.vertex[2].values[v] as f32);
            assert_eq!(column(&back, "nz")[v], nz);
            assert_eq!(
                column(&back, "flags")[v],
                soup.attributes.vertex[10].values[v]
            );
        }
        assert_eq!(back.attributes.vertex[2].scalar, ScalarType::F32);
    }
    // Half the size of the double file in binary (positions and normals).
    let double = write(&soup, Format::Ply, &WriteOptions::default());
    let float = write(
        &soup,
        Format::Ply,
        &WriteOptions::default().with_ply_precision(PlyPrecision::Float),
    );
    assert!(float.len() < double.len());
    // A coordinate beyond the range of a float is refused before anything is written.
    soup.positions[0][1] = 1e39;
    let mut out = Vec::new();
    let options = WriteOptions::default().with_ply_precision(PlyPrecision::Float);
    let err = surftopo_io::write(&mut out, &soup, Format::Ply, &options).unwrap_err();
    assert!(matches!(err, IoError::Unrepresentable { .. }), "{err}");
    assert!(out.is_empty());
}

#[test]
fn ply_to_obj_keeps_normals_and_texcoords_and_says_what_it_drops() {
    let soup = rich_soup();
    let text = String::from_utf8(write(&soup, Format::Obj, &WriteOptions::default())).unwrap();
    let vt = obj_lines(&text, "vt");
    let vn = obj_lines(&text, "vn");
    assert_eq!((vt.len(), vn.len()), (4, 4));
    assert_eq!(numbers(&vt[3]), [0.5, 0.25]);
    assert_eq!(numbers(&vn[0]), [-0.5, -0.5, -0.7071067811865475]);
    assert!(
        obj_corners(&text)
            .iter()
            .all(|&(v, t, n)| t == Some(v) && n == Some(v))
    );
    assert_eq!(
        soup.unwritable(Format::Obj),
        ["per-vertex red green blue alpha quality flags (4 vertices): OBJ cannot hold them"]
    );
    assert_eq!(
        soup.unwritable(Format::Off),
        ["per-vertex nx ny nz s t quality flags (4 vertices): OFF cannot hold them"]
    );
    assert!(soup.unwritable(Format::Ply).is_empty());
    let back = read(text.as_bytes(), Format::Obj);
    assert_eq!(column(&back, "u"), column(&soup, "s"));
    assert_eq!(column(&back, "ny"), column(&soup, "ny"));
}

#[test]
fn ply_reader_lists_what_it_skips_and_checks_integer_values() {
    let ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
property float z\nproperty list uchar int tags\nproperty uchar red\nelement face 1\n\
property list uchar int vertex_indices\nproperty uchar red\nelement edge 2\nproperty int a\n\
end_header\n0 0 0 1 5 7\n1 0 0 0 8\n0 1 0 2 1 2 9\n3 0 1 2 4\n0\n1\n";
    let soup = read(ply.as_bytes(), Format::Ply);
    assert_eq!(column(&soup, "red"), [7.0, 8.0, 9.0]);
    assert_eq!(
        soup.attributes.not_kept,
        [
            "PLY vertex list property 'tags'",
            "PLY face property 'red' (1 records)",
            "PLY element 'edge' (2 records)"
        ]
    );
    let bad = ply.replace("0 1 0 2 1 2 9", "0 1 0 2 1 2 300");
    let err = read_bytes(bad.as_bytes(), Format::Ply, "t.ply").unwrap_err();
    assert_eq!(err.to_string(), "t.ply:17: vertex red 300 is not a uchar");
}

#[test]
fn coff_colours_are_read_and_written() {
    let off = "COFF\n4 4 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n\
0 0 1 10 20 30 40\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";
    let soup = read(off.as_bytes(), Format::Off);
    assert_eq!(column(&soup, "alpha"), [255.0, 255.0, 255.0, 40.0]);
    assert_eq!(soup.attributes.vertex[0].scalar, ScalarType::U8);
    assert!(soup.attributes.not_kept.is_empty());
    let text = String::from_utf8(write(&soup, Format::Off, &WriteOptions::default())).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "COFF");
    assert_eq!(lines[5], "0 0 1 10 20 30 40");
    assert_eq!(read(text.as_bytes(), Format::Off), soup);
    // Colours of differing lengths are not kept, and that is said.
    let ragged = off.replace("10 20 30 40", "10 20 30");
    let soup = read(ragged.as_bytes(), Format::Off);
    assert!(soup.attributes.vertex.is_empty());
    assert_eq!(soup.attributes.not_kept, ["OFF vertex colours (COFF)"]);
}

#[test]
fn weld_keeps_the_first_vertex_attributes_and_counts_conflicts() {
    let mut soup = PolygonSoup::from_triangles(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 1.0, 0.0],
        ],
        &[[0, 1, 2], [3, 5, 4]],
    );
    soup.attributes.vertex.push(VertexProperty {
        name: "quality".into(),
        scalar: ScalarType::F64,
        values: vec![0.0, 1.0, 2.0, 1.0, 9.0, 5.0],
    });
    let weld = soup.weld_exact();
    assert_eq!((weld.merged, weld.conflicting), (2, 1));
    assert_eq!(column(&soup, "quality"), [0.0, 1.0, 2.0, 5.0]);
    assert_eq!(soup.face(1), [1, 3, 2]);
}

#[test]
fn inconsistent_attributes_are_refused_before_writing() {
    let mut soup = rich_soup();
    soup.attributes.vertex[0].values.pop();
    let mut out = Vec::new();
    let err = surftopo_io::write(&mut out, &soup, Format::Ply, &WriteOptions::default());
    assert!(matches!(err, Err(IoError::InvalidSoup { .. })));
    assert!(out.is_empty());
    let mut soup = rich_soup();
    soup.attributes.vertex[5].values[0] = 256.0;
    let err = surftopo_io::write(&mut out, &soup, Format::Ply, &WriteOptions::default());
    assert!(err.unwrap_err().to_string().contains("256 is not a uchar"));
}

#[test]
fn many_properties_and_a_huge_count_fail_without_a_huge_reservation() {
    let mut ply = String::from("ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n");
    for axis in ["x", "y", "z"] {
        ply += &format!("property float {axis}\n");
    }
    for k in 0..2000 {
        ply += &format!("property uchar p{k}\n");
    }
    ply += "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    let mut bytes = ply.into_bytes();
    bytes.extend([0u8; 5000]);
    let err = read_bytes(&bytes, Format::Ply, "huge.ply").unwrap_err();
    assert!(matches!(err, IoError::UnexpectedEof { .. }), "{err}");
}
