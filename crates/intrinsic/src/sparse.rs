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
    ///
    /// # Errors
    /// The first entry out of range, in words (1-based row and column).
    pub fn check_representable(&self, positive_diagonal: bool) -> Result<(), String> {
        if let Some((i, j, v)) = self.triplets().find(|t| !t.2.is_finite()) {
            return Err(format!(
                "entry ({}, {}) is {v}: beyond double precision's range (scale the input)",
                i + 1,
                j + 1
            ));
        }
        let small = (0..self.n)
            .map(|i| (i, self.get(i, i)))
            .find(|&(_, v)| v.is_nan() || v < f64::MIN_POSITIVE);
        match small.filter(|_| positive_diagonal) {
            Some((i, v)) => Err(format!(
                "diagonal entry {} is {v:e}, not a positive normal number: the triangles are too \
                 small for double precision (scale the input)",
                i + 1
            )),
            None => Ok(()),
        }
    }
}
