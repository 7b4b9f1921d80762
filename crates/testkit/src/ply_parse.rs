//! An independent reading of the PLY files surftopo writes, for tests: the header split into
//! words, the body decoded from it (ascii words, or binary little or big endian), with nothing
//! of surftopo-io's reader.

/// A PLY file parsed independently: vertex property names (with types) and vertex rows.
pub struct ParsedPly {
    /// `ascii`, `binary_little_endian` or `binary_big_endian`.
    pub format: String,
    /// Vertex property names, x y z included.
    pub names: Vec<String>,
    /// Their PLY type names.
    pub types: Vec<String>,
    /// One row of values per vertex.
    pub rows: Vec<Vec<f64>>,
    /// The faces' vertex indices.
    pub faces: Vec<Vec<u32>>,
}

/// A minimal PLY reader for what our writer emits: one vertex element of scalars, then a face
/// element of one list.
pub fn parse(bytes: &[u8]) -> ParsedPly {
    let end = bytes
        .windows(11)
        .position(|w| w == b"end_header\n")
        .unwrap()
        + 11;
    let header = std::str::from_utf8(&bytes[..end]).unwrap();
    let mut format = "";
    let (mut nv, mut nf) = (0, 0);
    let (mut names, mut types) = (Vec::new(), Vec::new());
    let mut list = (String::new(), String::new());
    for line in header.lines() {
        let w: Vec<&str> = line.split_whitespace().collect();
        match w[..] {
            ["format", f, _] => format = f,
            ["element", "vertex", n] => nv = n.parse().unwrap(),
            ["element", "face", n] => nf = n.parse().unwrap(),
            ["property", "list", c, i, _] => list = (c.to_owned(), i.to_owned()),
            ["property", t, name] => {
                types.push(t.to_owned());
                names.push(name.to_owned());
            }
            _ => {}
        }
    }
    let body = &bytes[end..];
    let mut rows = Vec::new();
    let mut faces = Vec::new();
    if format == "ascii" {
        let text = std::str::from_utf8(body).unwrap();
        let mut lines = text.lines();
        for _ in 0..nv {
            let words = lines.next().unwrap().split_whitespace();
            rows.push(words.map(|w| w.parse().unwrap()).collect());
        }
        for _ in 0..nf {
            let w: Vec<u32> = lines
                .next()
                .unwrap()
                .split_whitespace()
                .map(|w| w.parse().unwrap())
                .collect();
            assert_eq!(w[0] as usize, w.len() - 1);
            faces.push(w[1..].to_vec());
        }
        return ParsedPly {
            format: format.to_owned(),
            names,
            types,
            rows,
            faces,
        };
    }
    let be = format == "binary_big_endian";
    let mut pos = 0;
    let mut take = |n: usize| {
        let mut b = body[pos..pos + n].to_vec();
        if be {
            b.reverse();
        }
        pos += n;
        b
    };
    let mut value = |t: &str| -> f64 {
        match t {
            "char" => f64::from(take(1)[0] as i8),
            "uchar" => f64::from(take(1)[0]),
            "short" => f64::from(i16::from_le_bytes(take(2).try_into().unwrap())),
            "ushort" => f64::from(u16::from_le_bytes(take(2).try_into().unwrap())),
            "int" => f64::from(i32::from_le_bytes(take(4).try_into().unwrap())),
            "uint" => f64::from(u32::from_le_bytes(take(4).try_into().unwrap())),
            "float" => f64::from(f32::from_le_bytes(take(4).try_into().unwrap())),
            "double" => f64::from_le_bytes(take(8).try_into().unwrap()),
            other => panic!("type {other}"),
        }
    };
    for _ in 0..nv {
        rows.push(types.iter().map(|t| value(t)).collect());
    }
    for _ in 0..nf {
        let n = value(&list.0) as usize;
        faces.push((0..n).map(|_| value(&list.1) as u32).collect());
    }
    ParsedPly {
        format: format.to_owned(),
        names,
        types,
        rows,
        faces,
    }
}
