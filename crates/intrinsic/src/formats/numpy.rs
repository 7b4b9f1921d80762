//! Binary outputs numpy and SciPy read directly: `.npy` (one array, NPY format 1.0) and `.npz`
//! (a zip archive of `.npy` arrays, entries stored uncompressed) in the layout of
//! `scipy.sparse.save_npz`, so `scipy.sparse.load_npz` gives the matrix back.
//!
//! An `.npz` of a [`SparseMatrix`] holds `format` (the bytes `csr`, dtype `|S3`, shape `()`),
//! `shape` (`<i8`, `[n, n]`), `data` (`<f8`), `indices` (column of each entry, `<i4`) and `indptr`
//! (row starts, `<i4`, or `<i8` when the entry count exceeds `i32::MAX`), the arrays of
//! `scipy.sparse.csr_matrix((data, indices, indptr), shape)`. Every entry is stored (CSR has no
//! symmetric storage). Archives are plain zip (no zip64): beyond 4 GiB per entry or in total the
//! writer refuses with an error before writing.

use crate::sparse::SparseMatrix;
use std::io::{self, Write};

/// The NPY header of a little-endian C-order array: magic, version 1.0, the header length, the
/// dictionary padded with spaces and ended by a newline so that the data starts at a multiple of
/// 64 bytes (what numpy writes).
fn npy_header(descr: &str, shape: &[u64]) -> Vec<u8> {
    let dims: Vec<String> = shape.iter().map(u64::to_string).collect();
    let shape = match dims.len() {
        1 => format!("({},)", dims[0]),
        _ => format!("({})", dims.join(", ")),
    };
    let mut dict = format!("{{'descr': '{descr}', 'fortran_order': False, 'shape': {shape}, }}");
    let unpadded = 10 + dict.len() + 1;
    dict.extend(std::iter::repeat_n(
        ' ',
        unpadded.next_multiple_of(64) - unpadded,
    ));
    dict.push('\n');
    let mut out = b"\x93NUMPY\x01\x00".to_vec();
    out.extend_from_slice(&(dict.len() as u16).to_le_bytes());
    out.extend_from_slice(dict.as_bytes());
    out
}

/// One `.npy` file in memory.
fn npy(
    descr: &str,
    shape: &[u64],
    data: impl IntoIterator<Item = [u8; 8]>,
    width: usize,
) -> Vec<u8> {
    let mut out = npy_header(descr, shape);
    for bytes in data {
        out.extend_from_slice(&bytes[..width]);
    }
    out
}

fn f64_npy(values: &[f64]) -> Vec<u8> {
    npy(
        "<f8",
        &[values.len() as u64],
        values.iter().map(|v| v.to_le_bytes()),
        8,
    )
}

/// Writes `values` as a one-dimensional `.npy` array of doubles (`numpy.load` reads it), e.g.
/// the diagonal of the lumped mass matrix.
///
/// # Errors
/// Any I/O error of the writer.
pub fn write_npy<W: Write>(mut out: W, values: &[f64]) -> io::Result<()> {
    out.write_all(&f64_npy(values))?;
    out.flush()
}

/// Writes `m` as an `.npz` archive in `scipy.sparse.save_npz`'s CSR layout (see the module doc).
///
/// # Errors
/// Any I/O error of the writer; `InvalidInput` (before writing anything) when an array or the
/// archive would exceed the 4 GiB of a zip without zip64.
pub fn write_npz<W: Write>(out: W, m: &SparseMatrix) -> io::Result<()> {
    let n = m.n as u64;
    let wide = m.nnz() > i32::MAX as usize || m.n > i32::MAX as usize;
    let (index_descr, width) = if wide { ("<i8", 8) } else { ("<i4", 4) };
    let entries: Vec<(&str, Vec<u8>)> = vec![
        ("format.npy", npy("|S3", &[], [*b"csr\0\0\0\0\0"], 3)),
        (
            "shape.npy",
            npy("<i8", &[2], [n, n].map(u64::to_le_bytes), 8),
        ),
        ("data.npy", f64_npy(&m.values)),
        (
            "indices.npy",
            npy(
                index_descr,
                &[m.cols.len() as u64],
                m.cols.iter().map(|&c| u64::from(c).to_le_bytes()),
                width,
            ),
        ),
        (
            "indptr.npy",
            npy(
                index_descr,
                &[m.row_start.len() as u64],
                m.row_start.iter().map(|&s| (s as u64).to_le_bytes()),
                width,
            ),
        ),
    ];
    write_zip(out, &entries)
}

/// Writes a zip archive of uncompressed (`stored`) entries: local headers (30 bytes and the
/// name) with their data, the central directory (46 bytes and the name per entry), its end
/// record (22 bytes). Times are 1980-01-01 00:00, so the same entries give the
/// same bytes.
fn write_zip<W: Write>(mut out: W, entries: &[(&str, Vec<u8>)]) -> io::Result<()> {
    let too_large = || io::Error::new(io::ErrorKind::InvalidInput, "too large for a .npz (4 GiB)");
    let total: u64 = entries
        .iter()
        .map(|(name, data)| data.len() as u64 + 2 * name.len() as u64 + 76)
        .sum::<u64>()
        + 22;
    if total > u64::from(u32::MAX) {
        return Err(too_large());
    }
    const DATE_1980_01_01: u16 = (1 << 5) | 1;
    let mut central = Vec::new();
    let mut offset = 0u32;
    for (name, data) in entries {
        let crc = crc32fast::hash(data);
        let size = u32::try_from(data.len()).map_err(|_| too_large())?;
        let mut common = Vec::with_capacity(26);
        common.extend_from_slice(&20u16.to_le_bytes()); // version needed: 2.0
        common.extend_from_slice(&0u16.to_le_bytes()); // flags
        common.extend_from_slice(&0u16.to_le_bytes()); // method: stored
        common.extend_from_slice(&0u16.to_le_bytes()); // time
        common.extend_from_slice(&DATE_1980_01_01.to_le_bytes());
        common.extend_from_slice(&crc.to_le_bytes());
        common.extend_from_slice(&size.to_le_bytes()); // compressed
        common.extend_from_slice(&size.to_le_bytes()); // uncompressed
        common.extend_from_slice(&(name.len() as u16).to_le_bytes());
        common.extend_from_slice(&0u16.to_le_bytes()); // extra length
        out.write_all(b"PK\x03\x04")?;
        out.write_all(&common)?;
        out.write_all(name.as_bytes())?;
        out.write_all(data)?;
        central.extend_from_slice(b"PK\x01\x02");
        central.extend_from_slice(&20u16.to_le_bytes()); // version made by
        central.extend_from_slice(&common);
        central.extend_from_slice(&[0; 6]); // comment length, disk, internal attributes
        central.extend_from_slice(&0u32.to_le_bytes()); // external attributes
        central.extend_from_slice(&offset.to_le_bytes());
        central.extend_from_slice(name.as_bytes());
        offset += 30 + name.len() as u32 + size;
    }
    out.write_all(&central)?;
    let count = entries.len() as u16;
    out.write_all(b"PK\x05\x06")?;
    out.write_all(&[0; 4])?; // disk numbers
    out.write_all(&count.to_le_bytes())?;
    out.write_all(&count.to_le_bytes())?;
    out.write_all(&(central.len() as u32).to_le_bytes())?;
    out.write_all(&offset.to_le_bytes())?;
    out.write_all(&0u16.to_le_bytes())?; // comment length
    out.flush()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn npy_header_is_aligned_and_parsable() {
        let bytes = f64_npy(&[1.5, -2.0]);
        let header_len = u16::from_le_bytes([bytes[8], bytes[9]]) as usize;
        assert_eq!((10 + header_len) % 64, 0);
        let dict = std::str::from_utf8(&bytes[10..10 + header_len]).unwrap();
        assert!(dict.starts_with("{'descr': '<f8', 'fortran_order': False, 'shape': (2,), }"));
        assert!(dict.ends_with('\n'));
        assert_eq!(
            &bytes[10 + header_len..10 + header_len + 8],
            1.5f64.to_le_bytes()
        );
        assert_eq!(bytes.len(), 10 + header_len + 16);
        let scalar = npy_header("|S3", &[]);
        assert!(
            std::str::from_utf8(&scalar[10..])
                .unwrap()
                .contains("'shape': ()")
        );
        let two = npy_header("<i8", &[2, 3]);
        assert!(
            std::str::from_utf8(&two[10..])
                .unwrap()
                .contains("'shape': (2, 3)")
        );
    }

    fn u16_at(bytes: &[u8], at: usize) -> usize {
        usize::from(u16::from_le_bytes([bytes[at], bytes[at + 1]]))
    }

    fn u32_at(bytes: &[u8], at: usize) -> usize {
        u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap()) as usize
    }

    /// Walks the archive as a zip reader does (APPNOTE 4.3.7, 4.3.12, 4.3.16): from the end
    /// record to the central directory, each of its 46-byte headers to its local header, whose
    /// name, sizes and crc must agree; the directory must end where the end record says.
    #[test]
    fn zip_directory_points_at_its_entries() {
        let m = SparseMatrix::from_triplets(2, &[(0, 0, 2.0), (1, 0, -1.0), (1, 1, 3.0)]);
        let mut bytes = Vec::new();
        write_npz(&mut bytes, &m).unwrap();
        let end = bytes.len() - 22;
        assert_eq!(&bytes[end..end + 4], b"PK\x05\x06");
        assert_eq!(u16_at(&bytes, end + 10), 5);
        let (size, start) = (u32_at(&bytes, end + 12), u32_at(&bytes, end + 16));
        assert_eq!(start + size, end, "the directory ends at the end record");
        let mut at = start;
        let mut names = Vec::new();
        while at < end {
            assert_eq!(&bytes[at..at + 4], b"PK\x01\x02");
            let name_len = u16_at(&bytes, at + 28);
            let extra_and_comment = u16_at(&bytes, at + 30) + u16_at(&bytes, at + 32);
            let (crc, stored) = (u32_at(&bytes, at + 16), u32_at(&bytes, at + 20));
            let local = u32_at(&bytes, at + 42);
            let name = &bytes[at + 46..at + 46 + name_len];
            assert_eq!(&bytes[local..local + 4], b"PK\x03\x04");
            assert_eq!(u16_at(&bytes, local + 26), name_len);
            assert_eq!(&bytes[local + 30..local + 30 + name_len], name);
            let data = local + 30 + name_len + u16_at(&bytes, local + 28);
            assert_eq!(crc32fast::hash(&bytes[data..data + stored]) as usize, crc);
            names.push(String::from_utf8(name.to_vec()).unwrap());
            at += 46 + name_len + extra_and_comment;
        }
        assert_eq!(at, end);
        assert_eq!(
            names,
            [
                "format.npy",
                "shape.npy",
                "data.npy",
                "indices.npy",
                "indptr.npy"
            ]
        );
        // A crc-32 of a known string (the zip/PNG polynomial).
        assert_eq!(crc32fast::hash(b"123456789"), 0xCBF4_3926);
    }
}
