//! Matrix Market coordinate format (NIST), written and read by hand.
//!
//! Written as `%%MatrixMarket matrix coordinate real general` (every stored entry) or `... real
//! symmetric` (the entries on and below the diagonal only, as the format defines; about half the
//! bytes for a Laplacian), one entry per line with 1-based indices and the value as the shortest
//! decimal that reads back to the same double ([`surftopo_mesh::decimal::push_f64`]), so reading
//! the file back gives bit-identical values. The reader accepts `general` and `symmetric` real
//! coordinate files (SciPy's `mmwrite` output included) and is used by the tests and the
//! benchmark's comparison with libigl.

use crate::formats::text_blocks::{block_count, block_range, write_blocks};
use crate::sparse::SparseMatrix;
use std::io::{self, BufRead, Write};
use surftopo_mesh::decimal::{push_f64, push_u64};

/// Matrix rows per block of the writer ([`crate::formats::text_blocks`]): a few hundred kilobytes of a
/// Laplacian.
const ROWS_PER_BLOCK: usize = 4096;

/// How [`write_matrix_market`] stores a matrix.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MatrixStorage {
    /// Every stored entry (`general`).
    #[default]
    General,
    /// The entries on and below the diagonal (`symmetric`); the matrix must be symmetric.
    Symmetric,
}

/// Writes `m` in Matrix Market coordinate format with `%` comment lines, stored as `storage`
/// says. [`MatrixStorage::Symmetric`] is for matrices symmetric by construction (the cotan
/// Laplacian and the mass matrix of this crate, whose tests check
/// [`SparseMatrix::is_symmetric`]): the entries above the diagonal are not written, and checking
/// them would cost more than writing (a debug assertion does). Rows are formatted in blocks on
/// several threads and written in order.
///
/// # Errors
/// Any I/O error of the writer.
pub fn write_matrix_market<W: Write>(
    mut out: W,
    m: &SparseMatrix,
    comment: &str,
    storage: MatrixStorage,
) -> io::Result<()> {
    let symmetric = storage == MatrixStorage::Symmetric;
    debug_assert!(
        !symmetric || m.is_symmetric(),
        "symmetric storage of an asymmetric matrix"
    );
    let mut head = Vec::new();
    head.extend_from_slice(b"%%MatrixMarket matrix coordinate real ");
    head.extend_from_slice(if symmetric {
        b"symmetric\n"
    } else {
        b"general\n"
    });
    for line in comment.lines() {
        head.extend_from_slice(b"% ");
        head.extend_from_slice(line.as_bytes());
        head.push(b'\n');
    }
    // The end of the entries written of each row: all of them, or those up to the diagonal.
    let ends: Vec<usize> = (0..m.n)
        .map(|i| {
            let row = m.row_start[i]..m.row_start[i + 1];
            if symmetric {
                row.start + m.cols[row].partition_point(|&j| j as usize <= i)
            } else {
                row.end
            }
        })
        .collect();
    let stored: usize = (0..m.n).map(|i| ends[i] - m.row_start[i]).sum();
    for (k, v) in [m.n, m.n, stored].into_iter().enumerate() {
        if k > 0 {
            head.push(b' ');
        }
        push_u64(&mut head, v as u64);
    }
    head.push(b'\n');
    out.write_all(&head)?;
    write_blocks(&mut out, block_count(m.n, ROWS_PER_BLOCK), |block, buf| {
        for i in block_range(block, ROWS_PER_BLOCK, m.n) {
            for k in m.row_start[i]..ends[i] {
                push_u64(buf, i as u64 + 1);
                buf.push(b' ');
                push_u64(buf, u64::from(m.cols[k]) + 1);
                buf.push(b' ');
                push_f64(buf, m.values[k]);
                buf.push(b'\n');
            }
        }
    })?;
    out.flush()
}

impl SparseMatrix {
    /// Whether every stored entry `(i, j)` equals `(j, i)` bit for bit (absent counts as 0).
    /// O(nnz log d), with random access to the rows: the writers do not call it in release
    /// builds.
    pub fn is_symmetric(&self) -> bool {
        (0..self.n).all(|i| {
            (self.row_start[i]..self.row_start[i + 1])
                .all(|k| self.get(self.cols[k] as usize, i).to_bits() == self.values[k].to_bits())
        })
    }
}

/// Reads a real square Matrix Market coordinate matrix (`general` or `symmetric`; duplicate
/// entries are summed).
///
/// # Errors
/// `InvalidData` naming the line for a malformed header, size line or entry.
pub fn read_matrix_market<R: BufRead>(input: R) -> io::Result<SparseMatrix> {
    let bad = |line: usize, what: &str| {
        io::Error::new(io::ErrorKind::InvalidData, format!("line {line}: {what}"))
    };
    let mut lines = input.lines().enumerate();
    let (_, header) = lines.next().ok_or_else(|| bad(1, "empty file"))?;
    let header = header?.to_ascii_lowercase();
    let words: Vec<&str> = header.split_whitespace().collect();
    if words.len() != 5
        || words[0] != "%%matrixmarket"
        || words[1] != "matrix"
        || words[2] != "coordinate"
        || !(words[3] == "real" || words[3] == "integer")
    {
        return Err(bad(1, "expected %%MatrixMarket matrix coordinate real"));
    }
    let symmetric = match words[4] {
        "general" => false,
        "symmetric" => true,
        _ => return Err(bad(1, "only general and symmetric matrices are read")),
    };
    let mut size: Option<(usize, usize)> = None;
    let mut triplets = Vec::new();
    for (k, line) in lines {
        let line = line?;
        let line_no = k + 1;
        let t = line.trim();
        if t.is_empty() || t.starts_with('%') {
            continue;
        }
        let fields: Vec<&str> = t.split_whitespace().collect();
        match size {
            None => {
                let parse = |s: &str| s.parse::<usize>().map_err(|_| bad(line_no, "bad size"));
                if fields.len() != 3 {
                    return Err(bad(line_no, "size line needs rows cols entries"));
                }
                let (r, c, nnz) = (parse(fields[0])?, parse(fields[1])?, parse(fields[2])?);
                if r != c || r >= u32::MAX as usize {
                    return Err(bad(line_no, "matrix must be square"));
                }
                triplets.reserve(nnz.min(1 << 24));
                size = Some((r, nnz));
            }
            Some((n, _)) => {
                if fields.len() != 3 {
                    return Err(bad(line_no, "entry needs row col value"));
                }
                let index = |s: &str| match s.parse::<usize>() {
                    Ok(i) if (1..=n).contains(&i) => Ok((i - 1) as u32),
                    _ => Err(bad(line_no, "index out of range")),
                };
                let (i, j) = (index(fields[0])?, index(fields[1])?);
                let v: f64 = fields[2].parse().map_err(|_| bad(line_no, "bad value"))?;
                triplets.push((i, j, v));
                if symmetric && i != j {
                    triplets.push((j, i, v));
                }
            }
        }
    }
    let (n, _) = size.ok_or_else(|| bad(1, "missing size line"))?;
    Ok(SparseMatrix::from_triplets(n, &triplets))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_is_bit_exact() {
        let m = SparseMatrix::from_triplets(
            3,
            &[
                (0, 0, 1.0 / 3.0),
                (0, 2, -1e-300),
                (2, 0, -1e-300),
                (1, 1, 2.5e17),
                (2, 2, 0.1),
            ],
        );
        for storage in [MatrixStorage::General, MatrixStorage::Symmetric] {
            let mut bytes = Vec::new();
            write_matrix_market(&mut bytes, &m, "test\nsecond line", storage).unwrap();
            let text = String::from_utf8(bytes.clone()).unwrap();
            let kind = if storage == MatrixStorage::General {
                "general"
            } else {
                "symmetric"
            };
            let header = format!("%%MatrixMarket matrix coordinate real {kind}\n% test\n");
            assert!(text.starts_with(&header), "{text}");
            let entries = if storage == MatrixStorage::General {
                5
            } else {
                4
            };
            assert!(text.contains(&format!("\n3 3 {entries}\n")), "{text}");
            let back = read_matrix_market(&bytes[..]).unwrap();
            assert_eq!(back, m);
        }
    }

    #[test]
    fn rows_written_in_blocks_are_the_text_of_one_pass() {
        // A symmetric band matrix of 3 blocks of rows and a part.
        let n = 3 * ROWS_PER_BLOCK + 17;
        let mut triplets = Vec::new();
        for i in 0..n {
            let x = (i as f64 + 0.5).sqrt() * 1e-3;
            triplets.push((i as u32, i as u32, 1.0 / x));
            if i + 3 < n {
                triplets.push((i as u32, i as u32 + 3, -x));
                triplets.push((i as u32 + 3, i as u32, -x));
            }
        }
        let m = SparseMatrix::from_triplets(n, &triplets);
        for storage in [MatrixStorage::General, MatrixStorage::Symmetric] {
            let mut written = Vec::new();
            write_matrix_market(&mut written, &m, "c", storage).unwrap();
            let kind = if storage == MatrixStorage::General {
                "general"
            } else {
                "symmetric"
            };
            let entries: Vec<_> = m
                .triplets()
                .filter(|&(i, j, _)| storage == MatrixStorage::General || j <= i)
                .collect();
            let mut expected = format!(
                "%%MatrixMarket matrix coordinate real {kind}\n% c\n{n} {n} {}\n",
                entries.len()
            )
            .into_bytes();
            for (i, j, v) in entries {
                expected.extend_from_slice(format!("{} {} ", i + 1, j + 1).as_bytes());
                push_f64(&mut expected, v);
                expected.push(b'\n');
            }
            assert_eq!(written, expected, "{kind}");
        }
    }

    #[test]
    fn symmetry_is_bit_exact() {
        let m = SparseMatrix::from_triplets(2, &[(0, 1, 1.0), (1, 0, 1.0 + f64::EPSILON)]);
        assert!(!m.is_symmetric());
        let m = SparseMatrix::from_triplets(2, &[(0, 1, 1.0), (1, 1, 2.0)]);
        assert!(!m.is_symmetric());
        let m = SparseMatrix::from_triplets(2, &[(0, 1, 1.0), (1, 0, 1.0), (1, 1, 2.0)]);
        assert!(m.is_symmetric());
    }

    #[test]
    fn reads_symmetric_and_rejects_garbage() {
        let text = "%%MatrixMarket matrix coordinate real symmetric\n% c\n2 2 2\n1 1 4\n2 1 -1.5\n";
        let m = read_matrix_market(text.as_bytes()).unwrap();
        assert_eq!(m.get(0, 1), -1.5);
        assert_eq!(m.get(1, 0), -1.5);
        assert_eq!(m.get(0, 0), 4.0);
        assert!(read_matrix_market("hello\n".as_bytes()).is_err());
        let bad = "%%MatrixMarket matrix coordinate real general\n2 2 1\n3 1 1.0\n";
        assert!(read_matrix_market(bad.as_bytes()).is_err());
    }
}
