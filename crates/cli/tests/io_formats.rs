//! Matrix outputs of `delaunay` by extension (Matrix Market in symmetric storage, `.npz` in
//! SciPy's `save_npz` layout, `.npy` for the mass diagonal), each read back by a minimal reader
//! written here (independent of surftopo's own) and compared with the Matrix Market reader's.

mod common;

use common::{generated_genus_surface, surftopo};
use std::collections::BTreeMap;
use std::path::Path;

type Entries = BTreeMap<(usize, usize), f64>;

/// A minimal Matrix Market coordinate reader: header, size line, entries; `symmetric` mirrors
/// the entries below the diagonal. Returns the size and every entry.
fn parse_matrix_market(text: &str) -> (usize, Entries) {
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split_whitespace().collect();
    assert_eq!(
        &header[..4],
        ["%%MatrixMarket", "matrix", "coordinate", "real"]
    );
    let symmetric = header[4] == "symmetric";
    let mut lines = lines.filter(|l| !l.starts_with('%'));
    let size: Vec<usize> = lines
        .next()
        .unwrap()
        .split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect();
    let mut entries = Entries::new();
    let mut count = 0;
    for line in lines {
        let f: Vec<&str> = line.split_whitespace().collect();
        let (i, j): (usize, usize) = (f[0].parse().unwrap(), f[1].parse().unwrap());
        let v: f64 = f[2].parse().unwrap();
        if symmetric {
            assert!(j <= i, "symmetric storage holds the lower triangle: {line}");
            entries.insert((j - 1, i - 1), v);
        }
        entries.insert((i - 1, j - 1), v);
        count += 1;
    }
    assert_eq!(count, size[2], "entry count of the size line");
    (size[0], entries)
}

/// A minimal `.npy` reader: the header's dictionary and the data bytes.
fn parse_npy(bytes: &[u8]) -> (String, &[u8]) {
    assert_eq!(&bytes[..8], b"\x93NUMPY\x01\x00");
    let len = u16::from_le_bytes([bytes[8], bytes[9]]) as usize;
    let dict = std::str::from_utf8(&bytes[10..10 + len])
        .unwrap()
        .to_owned();
    (dict, &bytes[10 + len..])
}

/// A minimal reader of an uncompressed zip: each entry by its local header, its crc-32 checked
/// by a bitwise implementation here.
fn parse_zip(bytes: &[u8]) -> BTreeMap<String, Vec<u8>> {
    let u16_at = |k: usize| u16::from_le_bytes([bytes[k], bytes[k + 1]]) as usize;
    let u32_at = |k: usize| u32::from_le_bytes(bytes[k..k + 4].try_into().unwrap());
    let mut out = BTreeMap::new();
    let mut k = 0;
    while bytes[k..].starts_with(b"PK\x03\x04") {
        assert_eq!(u16_at(k + 8), 0, "stored");
        let crc = u32_at(k + 14);
        let size = u32_at(k + 18) as usize;
        let name_len = u16_at(k + 26);
        let extra = u16_at(k + 28);
        let name = String::from_utf8(bytes[k + 30..k + 30 + name_len].to_vec()).unwrap();
        let start = k + 30 + name_len + extra;
        let data = bytes[start..start + size].to_vec();
        let mut c = !0u32;
        for &b in &data {
            c ^= u32::from(b);
            for _ in 0..8 {
                c = if c & 1 == 1 {
                    (c >> 1) ^ 0xEDB8_8320
                } else {
                    c >> 1
                };
            }
        }
        assert_eq!(!c, crc, "crc of {name}");
        out.insert(name, data);
        k = start + size;
    }
    assert!(
        bytes[k..].starts_with(b"PK\x01\x02"),
        "central directory follows"
    );
    out
}

fn words<const N: usize>(data: &[u8]) -> impl Iterator<Item = [u8; N]> + '_ {
    data.chunks_exact(N).map(|c| c.try_into().unwrap())
}

fn delaunay(input: &Path, outputs: &[(&str, &Path)]) {
    let mut cmd = surftopo();
    cmd.arg("delaunay").arg(input);
    for (flag, path) in outputs {
        cmd.arg(flag).arg(path);
    }
    cmd.assert().success();
}

#[test]
fn matrices_by_extension_read_back_by_independent_readers() {
    let dir = tempfile::tempdir().unwrap();
    let d = |name: &str| dir.path().join(name);
    let mesh = generated_genus_surface(dir.path(), "g2.off", 2);
    delaunay(
        &mesh,
        &[
            ("-o", &d("D.json")),
            ("--laplacian", &d("L.mtx")),
            ("--mass", &d("M.mtx")),
        ],
    );
    delaunay(
        &mesh,
        &[
            ("-o", &d("D2.json")),
            ("--laplacian", &d("L.npz")),
            ("--mass", &d("M.npy")),
        ],
    );
    let (n, laplacian) = parse_matrix_market(&std::fs::read_to_string(d("L.mtx")).unwrap());
    let text = std::fs::read_to_string(d("L.mtx")).unwrap();
    assert!(text.starts_with("%%MatrixMarket matrix coordinate real symmetric\n"));
    // Symmetric storage: the lower triangle only, about half of the entries.
    assert!(text.lines().count() < laplacian.len() * 3 / 5 + 5);
    // Rows sum to zero (a Laplacian), up to rounding.
    for i in 0..n {
        let row: f64 = laplacian.range((i, 0)..(i + 1, 0)).map(|(_, v)| v).sum();
        let scale: f64 = laplacian[&(i, i)];
        assert!(row.abs() <= 1e-9 * scale, "row {i} sums to {row}");
    }
    // surftopo's own reader agrees with the minimal one.
    let own = surftopo_intrinsic::read_matrix_market(text.as_bytes()).unwrap();
    assert_eq!(own.nnz(), laplacian.len());
    for (i, j, v) in own.triplets() {
        assert_eq!(laplacian[&(i as usize, j as usize)].to_bits(), v.to_bits());
    }

    // .npz: SciPy's save_npz keys, CSR arrays equal to the Matrix Market entries bit for bit.
    let zip = parse_zip(&std::fs::read(d("L.npz")).unwrap());
    let keys: Vec<&str> = zip.keys().map(String::as_str).collect();
    assert_eq!(
        keys,
        [
            "data.npy",
            "format.npy",
            "indices.npy",
            "indptr.npy",
            "shape.npy"
        ]
    );
    let (dict, format) = parse_npy(&zip["format.npy"]);
    assert!(
        dict.contains("'descr': '|S3'") && dict.contains("'shape': ()"),
        "{dict}"
    );
    assert_eq!(format, b"csr");
    let (dict, shape) = parse_npy(&zip["shape.npy"]);
    assert!(dict.contains("'<i8'"), "{dict}");
    let shape: Vec<i64> = words::<8>(shape).map(i64::from_le_bytes).collect();
    assert_eq!(shape, [n as i64, n as i64]);
    let (_, data) = parse_npy(&zip["data.npy"]);
    let data: Vec<f64> = words::<8>(data).map(f64::from_le_bytes).collect();
    let (dict, indices) = parse_npy(&zip["indices.npy"]);
    assert!(dict.contains("'<i4'"), "{dict}");
    let indices: Vec<i32> = words::<4>(indices).map(i32::from_le_bytes).collect();
    let (_, indptr) = parse_npy(&zip["indptr.npy"]);
    let indptr: Vec<i32> = words::<4>(indptr).map(i32::from_le_bytes).collect();
    assert_eq!(indptr.len(), n + 1);
    assert_eq!(data.len(), laplacian.len());
    for i in 0..n {
        for k in indptr[i] as usize..indptr[i + 1] as usize {
            let v = laplacian[&(i, indices[k] as usize)];
            assert_eq!(
                v.to_bits(),
                data[k].to_bits(),
                "entry ({i}, {})",
                indices[k]
            );
        }
    }

    // .npy: the mass diagonal, equal to the Matrix Market mass matrix's.
    let (_, mass) = parse_matrix_market(&std::fs::read_to_string(d("M.mtx")).unwrap());
    let bytes = std::fs::read(d("M.npy")).unwrap();
    let (dict, diagonal) = parse_npy(&bytes);
    assert!(dict.contains(&format!("'shape': ({n},)")), "{dict}");
    let diagonal: Vec<f64> = words::<8>(diagonal).map(f64::from_le_bytes).collect();
    assert_eq!(diagonal.len(), mass.len());
    for (i, v) in diagonal.iter().enumerate() {
        assert_eq!(mass[&(i, i)].to_bits(), v.to_bits());
    }
    // The triangulation is the same whichever matrix formats were asked for.
    assert_eq!(
        std::fs::read(d("D.json")).unwrap(),
        std::fs::read(d("D2.json")).unwrap()
    );
}

#[test]
fn a_laplacian_cannot_go_to_npy_and_nothing_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let mesh = generated_genus_surface(dir.path(), "g1.off", 1);
    let out = surftopo()
        .arg("delaunay")
        .arg(&mesh)
        .arg("-o")
        .arg(dir.path().join("D.json"))
        .arg("--laplacian")
        .arg(dir.path().join("L.npy"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains(".npz or .mtx"));
    assert!(!dir.path().join("D.json").exists());
    assert!(!dir.path().join("L.npy").exists());
}
