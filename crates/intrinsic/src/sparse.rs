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
}
