//! Matrix Market coordinate format (NIST), written and read by hand.
//!
//! Written as `%%MatrixMarket matrix coordinate real general`, every stored entry on its own line
//! with 1-based indices and the value in Rust's shortest round-trip exponent form (`{:e}`), so
//! reading the file back gives bit-identical values. The reader accepts `general` and `symmetric`
//! real coordinate files (SciPy's `mmwrite` output included) and is used by the tests and the
//! benchmark's comparison with libigl.

use crate::laplacian::SparseMatrix;
use std::io::{self, BufRead, Write};

/// Writes `m` in Matrix Market coordinate format with a `%` comment line.
///
/// # Errors
/// Any I/O error of the writer.
pub fn write_matrix_market<W: Write>(out: W, m: &SparseMatrix, comment: &str) -> io::Result<()> {
    let mut out = io::BufWriter::new(out);
    writeln!(out, "%%MatrixMarket matrix coordinate real general")?;
    for line in comment.lines() {
        writeln!(out, "% {line}")?;
    }
    writeln!(out, "{} {} {}", m.n, m.n, m.nnz())?;
    for (i, j, v) in m.triplets() {
        writeln!(out, "{} {} {:e}", i + 1, j + 1, v)?;
    }
    out.flush()
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
        let mut bytes = Vec::new();
        write_matrix_market(&mut bytes, &m, "test\nsecond line").unwrap();
        let text = String::from_utf8(bytes.clone()).unwrap();
        assert!(text.starts_with("%%MatrixMarket matrix coordinate real general\n% test\n"));
        let back = read_matrix_market(&bytes[..]).unwrap();
        assert_eq!(back, m);
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
