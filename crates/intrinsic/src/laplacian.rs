//! The cotangent Laplacian and the lumped mass matrix of an intrinsic triangulation.
//!
//! On the intrinsic Delaunay triangulation this is the discrete Laplace–Beltrami operator of
//! Bobenko & Springborn (2007): it depends only on the surface (all Delaunay triangulations of a
//! surface give the same operator), its weights are non-negative, and it satisfies a maximum
//! principle.
//!
//! **Sign convention: positive semidefinite.** `L[i][i] = Σ_j w_ij > 0`, `L[i][j] = -w_ij` for
//! `i ≠ j`, with `w_e = (cot γ + cot δ) / 2` for an edge e with opposite angles γ, δ, summed over
//! all edges joining i and j (multi-edges add up). This is the matrix of the Dirichlet energy
//! `E(u) = ½ Σ_e w_e (u_i - u_j)²`; a loop edge (i = j) adds `w (u_i - u_i)² = 0`, so loops contribute
//! nothing at all, neither off the diagonal nor on it. Hence every row sums to zero and L is
//! symmetric. (libigl's `cotmatrix` is the negative of this matrix.)
//!
//! The lumped (barycentric) mass matrix is diagonal: `M[i][i] = Σ area(corner's face) / 3` over the
//! corners at vertex i (a triangle with two corners at i counts twice); its trace is the area.
//!
//! Rows and columns are the live vertices in increasing id order ([`dense_vertex_index`]).

use crate::triangulation::IntrinsicTriangulation;
use crate::trig;

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

/// Dense index of each live vertex (increasing id order), `u32::MAX` for removed ids, and the
/// number of live vertices.
pub fn dense_vertex_index(tri: &IntrinsicTriangulation) -> (Vec<u32>, usize) {
    let mesh = tri.mesh();
    let mut index = vec![u32::MAX; mesh.vertex_slots()];
    let mut n = 0usize;
    for v in mesh.vertices() {
        index[v.idx()] = n as u32;
        n += 1;
    }
    (index, n)
}

/// The cotan weight `w_e = (cot γ + cot δ) / 2` of every edge, indexed by edge id (0 for removed
/// edges). Non-negative on a Delaunay triangulation. O(E).
pub fn cotan_weights(tri: &IntrinsicTriangulation) -> Vec<f64> {
    let mesh = tri.mesh();
    let t2 = tri.halfedge_tan_half_sq();
    let mut w = vec![0.0; mesh.edge_slots()];
    for e in mesh.edges() {
        let h = e.halfedge();
        w[e.idx()] = 0.5
            * (trig::cot_from_tan_half_sq(t2[h.idx()])
                + trig::cot_from_tan_half_sq(t2[h.twin().idx()]));
    }
    w
}

/// The cotan Laplacian, positive semidefinite convention (see the module doc). O(E + Σ d log d).
pub fn cotan_laplacian(tri: &IntrinsicTriangulation) -> SparseMatrix {
    let weights = cotan_weights(tri);
    let mesh = tri.mesh();
    let (index, n) = dense_vertex_index(tri);
    // The non-loop edges as (row, col, weight), rows and columns dense vertex indices.
    let edges: Vec<(u32, u32, f64)> = mesh
        .edges()
        .filter_map(|e| {
            let [a, b] = mesh.edge_vertices(e);
            (a != b).then(|| (index[a.idx()], index[b.idx()], weights[e.idx()]))
        })
        .collect();
    // Off-diagonal entries of row i: one per edge end (multi-edges merged below), placed by a
    // counting pass; the diagonal is accumulated apart.
    let mut start = vec![0usize; n + 1];
    for &(i, j, _) in &edges {
        start[i as usize + 1] += 1;
        start[j as usize + 1] += 1;
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let mut entries: Vec<(u32, f64)> = vec![(0, 0.0); start[n]];
    let mut fill = start[..n].to_vec();
    let mut diagonal = vec![0.0; n];
    for &(i, j, w) in &edges {
        for (a, b) in [(i as usize, j), (j as usize, i)] {
            entries[fill[a]] = (b, -w);
            fill[a] += 1;
            diagonal[a] += w;
        }
    }
    drop(fill);
    drop(edges);
    // Sort each row by column, merge multi-edges, insert the diagonal.
    let mut m = SparseMatrix {
        n,
        row_start: Vec::with_capacity(n + 1),
        cols: Vec::with_capacity(start[n] + n),
        values: Vec::with_capacity(start[n] + n),
    };
    m.row_start.push(0);
    for i in 0..n {
        let row = &mut entries[start[i]..start[i + 1]];
        row.sort_unstable_by_key(|&(j, _)| j);
        let mut diagonal_done = false;
        for &(j, v) in row.iter() {
            if !diagonal_done && j as usize > i {
                m.cols.push(i as u32);
                m.values.push(diagonal[i]);
                diagonal_done = true;
            }
            if m.cols.len() > m.row_start[i] && m.cols.last() == Some(&j) {
                *m.values.last_mut().expect("an entry exists") += v;
            } else {
                m.cols.push(j);
                m.values.push(v);
            }
        }
        if !diagonal_done {
            m.cols.push(i as u32);
            m.values.push(diagonal[i]);
        }
        m.row_start.push(m.cols.len());
    }
    m
}

/// The lumped (barycentric) mass matrix: diagonal, a third of each incident triangle's area per
/// corner. O(F).
pub fn lumped_mass(tri: &IntrinsicTriangulation) -> SparseMatrix {
    let mesh = tri.mesh();
    let (index, n) = dense_vertex_index(tri);
    let mut mass = vec![0.0; n];
    for f in mesh.faces() {
        let third = tri.face_area(f) / 3.0;
        for v in mesh.face_vertices(f) {
            mass[index[v.idx()] as usize] += third;
        }
    }
    SparseMatrix::diagonal(mass)
}
