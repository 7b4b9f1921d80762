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
//! Rows and columns are the live vertices in increasing id order ([`IntrinsicTriangulation::matrix_rows`]).

use crate::error::DelaunayError;
use crate::flip::{DelaunayOptions, FlipReport, flip_keeping_tan_half_sq};
use crate::sparse::SparseMatrix;
use crate::triangulation::trig;
use crate::triangulation::{IntrinsicTriangulation, dense_vertex_index};
use surftopo_mesh::EdgeId;

/// The cotan weight `w_e = (cot γ + cot δ) / 2` of every edge, indexed by edge id (0 for removed
/// edges). Non-negative on a Delaunay triangulation. O(E).
pub fn cotan_weights(tri: &IntrinsicTriangulation) -> Vec<f64> {
    weights_from_tan_half_sq(tri, &tri.halfedge_tan_half_sq())
}

/// [`cotan_weights`] from the half-angle tangents squared `t2` (by half-edge id, as
/// [`IntrinsicTriangulation::halfedge_tan_half_sq`] computes them).
fn weights_from_tan_half_sq(tri: &IntrinsicTriangulation, t2: &[f64]) -> Vec<f64> {
    let mesh = tri.mesh();
    // Edge e's half-edges are 2e and 2e + 1: one pass over all slots (it vectorizes), then the
    // removed edges, if any, are set to 0.
    let mut w: Vec<f64> = t2
        .chunks_exact(2)
        .map(|t| 0.5 * (trig::cot_from_tan_half_sq(t[0]) + trig::cot_from_tan_half_sq(t[1])))
        .collect();
    if mesh.edge_count() < mesh.edge_slots() {
        for (e, w) in w.iter_mut().enumerate() {
            if !mesh.is_edge_live(EdgeId::new(e)) {
                *w = 0.0;
            }
        }
    }
    w
}

/// The cotan Laplacian, positive semidefinite convention (see the module doc). O(E + Σ d log d),
/// d the vertex degrees.
pub fn cotan_laplacian(tri: &IntrinsicTriangulation) -> SparseMatrix {
    laplacian_from_tan_half_sq(tri, &tri.halfedge_tan_half_sq())
}

/// Flips `tri` to an intrinsic Delaunay triangulation
/// ([`flip_to_delaunay`](crate::flip_to_delaunay)) and returns its cotan Laplacian
/// ([`cotan_laplacian`]): what libigl's `intrinsic_delaunay_cotmatrix` computes (with the
/// opposite sign), in one call that reuses the half-angle tangents the flips kept up to date
/// instead of computing them again. The result equals `cotan_laplacian` after `flip_to_delaunay`
/// bit for bit.
///
/// # Errors
/// As [`flip_to_delaunay`](crate::flip_to_delaunay) (`tri` is then left as that function leaves
/// it).
pub fn intrinsic_delaunay_laplacian(
    tri: &mut IntrinsicTriangulation,
    options: &DelaunayOptions,
) -> Result<(FlipReport, SparseMatrix), DelaunayError> {
    let (report, t2) = flip_keeping_tan_half_sq(tri, options)?;
    Ok((report, laplacian_from_tan_half_sq(tri, &t2)))
}

/// [`cotan_laplacian`] from the half-angle tangents squared `t2` (by half-edge id).
///
/// Assembly without a general sort: the non-loop edges are bucketed by their smaller dense end
/// `lo` (a counting sort), each bucket is sorted by the larger end `hi` (buckets hold a few edges)
/// and its multi-edges, now next to each other, are summed. Going through the buckets in
/// increasing `lo`, row `lo` receives its diagonal and then its entries `hi > lo` in increasing
/// order, and each row `hi` receives its entry `lo < hi`, rows being filled front to back; so
/// every row comes out sorted (entries left of the diagonal were all written by earlier buckets).
pub(crate) fn laplacian_from_tan_half_sq(tri: &IntrinsicTriangulation, t2: &[f64]) -> SparseMatrix {
    let weights = weights_from_tan_half_sq(tri, t2);
    let mesh = tri.mesh();
    let (index, n) = dense_vertex_index(tri);
    assemble_laplacian(n, || {
        mesh.edges().map(|e| {
            let [a, b] = mesh.edge_vertices(e).map(|v| index[v.idx()] as usize);
            (a, b, weights[e.idx()])
        })
    })
}

/// The Laplacian of `n` rows from weighted edges `(a, b, w)` (rows `a`, `b` below `n`; loops
/// `a = b` add nothing), multi-edges summed; `edges` is called twice and must give the same
/// sequence. The assembly of [`laplacian_from_tan_half_sq`] (see there).
pub(crate) fn assemble_laplacian<I, F>(n: usize, edges: F) -> SparseMatrix
where
    I: Iterator<Item = (usize, usize, f64)>,
    F: Fn() -> I,
{
    // Bucket sizes by lo, and the diagonal.
    let mut bucket_start = vec![0u32; n + 1];
    let mut diagonal = vec![0.0; n];
    for (a, b, w) in edges() {
        if a != b {
            bucket_start[a.min(b) + 1] += 1;
            diagonal[a] += w;
            diagonal[b] += w;
        }
    }
    for i in 0..n {
        bucket_start[i + 1] += bucket_start[i];
    }
    let mut bucket = vec![(0u32, 0.0f64); bucket_start[n] as usize];
    let mut fill = bucket_start[..n].to_vec();
    for (a, b, w) in edges() {
        if a != b {
            let lo = a.min(b);
            bucket[fill[lo] as usize] = (a.max(b) as u32, w);
            fill[lo] += 1;
        }
    }
    // Sort and merge each bucket (its distinct pairs end at `fill[lo]`), and size the rows: the
    // diagonal and one entry per distinct pair at each end.
    let mut row_start = vec![1usize; n + 1];
    row_start[0] = 0;
    for lo in 0..n {
        let b = &mut bucket[bucket_start[lo] as usize..bucket_start[lo + 1] as usize];
        b.sort_unstable_by_key(|&(hi, _)| hi);
        let mut unique = 0;
        for k in 0..b.len() {
            if unique > 0 && b[unique - 1].0 == b[k].0 {
                b[unique - 1].1 += b[k].1;
            } else {
                b[unique] = b[k];
                unique += 1;
            }
        }
        fill[lo] = bucket_start[lo] + unique as u32;
        row_start[lo + 1] += unique;
        for &(hi, _) in &b[..unique] {
            row_start[hi as usize + 1] += 1;
        }
    }
    for i in 0..n {
        row_start[i + 1] += row_start[i];
    }
    let mut cols = vec![0u32; row_start[n]];
    let mut values = vec![0.0f64; row_start[n]];
    // End of the written part of each row.
    let mut end = row_start[..n].to_vec();
    let mut put = |row: usize, col: u32, value: f64| {
        cols[end[row]] = col;
        values[end[row]] = value;
        end[row] += 1;
    };
    for lo in 0..n {
        put(lo, lo as u32, diagonal[lo]);
        for &(hi, w) in &bucket[bucket_start[lo] as usize..fill[lo] as usize] {
            put(lo, hi, -w);
            put(hi as usize, lo as u32, -w);
        }
    }
    SparseMatrix {
        n,
        row_start,
        cols,
        values,
    }
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flip::flip_to_delaunay;
    use crate::generators::{flat_torus, random_flips, sheared_torus};
    use crate::isometry::flat_vertices::remove_flat_vertices;
    use std::collections::{HashMap, HashSet};

    /// The Laplacian entry by entry from law-of-cosines angles (not [`trig`]), summed in a map
    /// over the edges, rows and columns by dense vertex index: an assembly independent of the one
    /// under test.
    fn independent_laplacian(tri: &IntrinsicTriangulation) -> HashMap<(usize, usize), f64> {
        let mesh = tri.mesh();
        let length = |h: surftopo_mesh::HalfedgeId| tri.lengths()[h.edge().idx()];
        let cot_opposite = |h| {
            let (a, b, c) = (length(h), length(mesh.next(h)), length(mesh.prev(h)));
            let cos = (b * b + c * c - a * a) / (2.0 * b * c);
            cos / (1.0 - cos * cos).sqrt()
        };
        let mut dense = vec![usize::MAX; mesh.vertex_slots()];
        for (i, v) in mesh.vertices().enumerate() {
            dense[v.idx()] = i;
        }
        let mut l: HashMap<(usize, usize), f64> =
            (0..mesh.vertex_count()).map(|i| ((i, i), 0.0)).collect();
        for e in mesh.edges() {
            let h = e.halfedge();
            let w = 0.5 * (cot_opposite(h) + cot_opposite(h.twin()));
            let [a, b] = mesh.edge_vertices(e).map(|v| dense[v.idx()]);
            if a != b {
                for (x, y) in [(a, b), (b, a)] {
                    *l.entry((x, y)).or_default() -= w;
                    *l.entry((x, x)).or_default() += w;
                }
            }
        }
        l
    }

    fn sheared(seed: u64) -> IntrinsicTriangulation {
        let s = sheared_torus(10, 6, 3);
        let mut tri = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap();
        random_flips(&mut tri, 150, seed);
        tri
    }

    #[test]
    fn assembly_matches_an_independent_one_with_loops_multi_edges_and_removed_vertices() {
        let mut cases = Vec::new();
        for (x, m) in [(2.5, 2), (7.0, 3), (1.5, 4)] {
            cases.push(flat_torus(x, m).unwrap());
        }
        // Removing the flat vertices leaves holes in the vertex ids (rows are not ids).
        let mut tri = flat_torus(3.0, 3).unwrap();
        remove_flat_vertices(&mut tri, 1e-9).unwrap();
        assert!(tri.mesh().vertex_count() < tri.mesh().vertex_slots());
        let w = cotan_weights(&tri);
        let removed = (0..w.len()).filter(|&e| !tri.mesh().is_edge_live(EdgeId::new(e)));
        assert!(removed.clone().count() > 0 && removed.clone().all(|e| w[e] == 0.0));
        cases.push(tri);
        cases.extend((1..4).map(sheared));
        let mut saw_multi = false;
        for mut tri in cases {
            flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
            let ours = cotan_laplacian(&tri);
            let want = independent_laplacian(&tri);
            let scale = want.values().fold(1e-300f64, |a, v| a.max(v.abs()));
            assert_eq!(ours.n, tri.mesh().vertex_count());
            assert_eq!(
                ours.nnz(),
                want.len(),
                "one entry per joined pair and per row"
            );
            for i in 0..ours.n {
                let cols: Vec<u32> = ours.row(i).map(|(j, _)| j).collect();
                assert!(cols.windows(2).all(|w| w[0] < w[1]), "row {i} not sorted");
                for (j, v) in ours.row(i) {
                    let expected = want[&(i, j as usize)];
                    assert!(
                        (v - expected).abs() <= 1e-9 * scale,
                        "L[{i}][{j}] = {v}, independently {expected}"
                    );
                }
            }
            let mesh = tri.mesh();
            let mut pairs = HashSet::new();
            for e in mesh.edges() {
                let [a, b] = mesh.edge_vertices(e);
                saw_multi |= a != b && !pairs.insert((a.min(b), a.max(b)));
            }
        }
        assert!(saw_multi, "no case had multi-edges");
    }

    #[test]
    fn intrinsic_delaunay_laplacian_equals_flipping_then_assembling() {
        for seed in 1..4 {
            let tri = sheared(seed);
            let options = DelaunayOptions::default();
            let mut a = tri.clone();
            let (report, l) = intrinsic_delaunay_laplacian(&mut a, &options).unwrap();
            assert!(report.flips > 0);
            let mut b = tri.clone();
            assert_eq!(flip_to_delaunay(&mut b, &options).unwrap(), report);
            assert_eq!(a, b);
            // Bit for bit: the half-angle tangents kept through the flips are the recomputed ones.
            assert_eq!(l, cotan_laplacian(&b));
        }
        // Errors are flip_to_delaunay's.
        let mut tri = sheared(1);
        let options = DelaunayOptions {
            max_flips: Some(0),
            ..DelaunayOptions::default()
        };
        let err = intrinsic_delaunay_laplacian(&mut tri.clone(), &options).unwrap_err();
        assert!(matches!(err, DelaunayError::MaxFlips { flips: 0, .. }));
        assert_eq!(Err(err), flip_to_delaunay(&mut tri, &options));
    }
}
