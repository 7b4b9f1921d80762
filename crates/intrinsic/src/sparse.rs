//! [`SparseMatrix`]: the square sparse matrices of this crate (the cotan Laplacian, the mass
//! matrix), in compressed rows.

/// A square sparse matrix in compressed rows, columns sorted within each row.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SparseMatrix {
    /// Number of rows (and columns).
    pub n: usize,
    /// Row `i` is entries `row_start[i]..row_start[i + 1]`; length `n + 1`.
    pub row_start: Vec<usize>,
    /// Column of each entry (0-based).
    pub cols: Vec<u32>,
    /// Value of each entry.
    pub values: Vec<f64>,
}

impl SparseMatrix {
    /// A diagonal matrix.
    pub fn diagonal(values: Vec<f64>) -> Self {
        let n = values.len();
        Self {
            n,
            row_start: (0..=n).collect(),
            cols: (0..n as u32).collect(),
            values,
        }
    }

    /// Builds from `(row, col, value)` triplets, summing duplicates (rows and cols must be `< n`).
    pub fn from_triplets(n: usize, triplets: &[(u32, u32, f64)]) -> Self {
        let mut sorted = triplets.to_vec();
        sorted.sort_unstable_by_key(|&(i, j, _)| (i, j));
        let mut m = Self {
            n,
            row_start: vec![0; n + 1],
            cols: Vec::with_capacity(sorted.len()),
            values: Vec::with_capacity(sorted.len()),
        };
        let mut last: Option<(u32, u32)> = None;
        for (i, j, v) in sorted {
            if last == Some((i, j)) {
                *m.values.last_mut().expect("an entry exists") += v;
            } else {
                m.cols.push(j);
                m.values.push(v);
                m.row_start[i as usize + 1] += 1;
                last = Some((i, j));
            }
        }
        for i in 0..n {
            m.row_start[i + 1] += m.row_start[i];
        }
        m
    }

    /// Number of stored entries.
    pub fn nnz(&self) -> usize {
        self.values.len()
    }

    /// The entries of row `i` as `(col, value)`.
    pub fn row(&self, i: usize) -> impl Iterator<Item = (u32, f64)> + '_ {
        let r = self.row_start[i]..self.row_start[i + 1];
        self.cols[r.clone()]
            .iter()
            .copied()
            .zip(self.values[r].iter().copied())
    }

    /// Entry `(i, j)` (0 if not stored). O(log row length).
    pub fn get(&self, i: usize, j: usize) -> f64 {
        let r = self.row_start[i]..self.row_start[i + 1];
        match self.cols[r.clone()].binary_search(&(j as u32)) {
            Ok(k) => self.values[r.start + k],
            Err(_) => 0.0,
        }
    }

    /// All entries as `(row, col, value)`, row-major.
    pub fn triplets(&self) -> impl Iterator<Item = (u32, u32, f64)> + '_ {
        (0..self.n).flat_map(move |i| self.row(i).map(move |(j, v)| (i as u32, j, v)))
    }

    /// Whether the entries are representable: none is non-finite and (`positive_diagonal`: the
    /// mass matrix, whose diagonal holds areas) every diagonal entry is a positive normal number.
    /// Lengths are handled scale-free (cotan weights do not depend on the scale), so this fails
    /// only when areas overflow or underflow double precision (coordinates of 1e200 or 1e-200):
    /// what the CLI and the Python package refuse to hand over as a matrix of `inf` or zeros.
    /// O(nnz): one branch-free pass over the values (it vectorises); the entry is located only
    /// when one fails.
    ///
    /// # Errors
    /// The first entry out of range, in words (1-based row and column).
    pub fn check_representable(&self, positive_diagonal: bool) -> Result<(), String> {
        let all_finite = self.values.iter().fold(true, |ok, v| ok & v.is_finite());
        if !all_finite {
            let k = self.values.iter().position(|v| !v.is_finite());
            let k = k.expect("a value is not finite");
            let i = self.row_start.partition_point(|&start| start <= k) - 1;
            return Err(format!(
                "entry ({}, {}) is {}: beyond double precision's range (scale the input)",
                i + 1,
                self.cols[k] + 1,
                self.values[k]
            ));
        }
        if !positive_diagonal {
            return Ok(());
        }
        let small = (0..self.n)
            .map(|i| (i, self.get(i, i)))
            .find(|&(_, v)| v.is_nan() || v < f64::MIN_POSITIVE);
        match small {
            Some((i, v)) => Err(format!(
                "diagonal entry {} is {v:e}, not a positive normal number: the triangles are too \
                 small for double precision (scale the input)",
                i + 1
            )),
            None => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn check_representable_names_the_first_entry_out_of_range() {
        let m = SparseMatrix::from_triplets(
            3,
            &[
                (0, 0, 1.0),
                (0, 2, -1.0),
                (1, 1, f64::NAN),
                (2, 0, f64::INFINITY),
            ],
        );
        assert_eq!(
            m.check_representable(false).unwrap_err(),
            "entry (2, 2) is NaN: beyond double precision's range (scale the input)"
        );
        let m = SparseMatrix::from_triplets(3, &[(0, 0, 1.0), (2, 1, f64::NEG_INFINITY)]);
        assert!(
            m.check_representable(false)
                .unwrap_err()
                .starts_with("entry (3, 2) is -inf")
        );
        // Diagonal entries are checked only when asked (a mass matrix): row 2 has none.
        let m = SparseMatrix::from_triplets(3, &[(0, 0, 1.0), (2, 1, -1.0)]);
        assert_eq!(m.check_representable(false), Ok(()));
        assert!(
            m.check_representable(true)
                .unwrap_err()
                .starts_with("diagonal entry 2 is 0e0")
        );
        let mass = SparseMatrix::diagonal(vec![1.0, 1e-320, 0.0]);
        assert_eq!(mass.check_representable(false), Ok(()));
        assert!(
            mass.check_representable(true)
                .unwrap_err()
                .starts_with("diagonal entry 2 is")
        );
        assert_eq!(
            SparseMatrix::diagonal(vec![1.0, 2.0]).check_representable(true),
            Ok(())
        );
    }
}
