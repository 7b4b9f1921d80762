//! Random simplicial edge flips: irregular connectivity on a fixed vertex set.

use crate::cover::{CoveredSurface, Lifting, flip_lifts};
use crate::geometry::Point3;
use crate::ids::{EdgeId, VertexId};
use crate::{Surface, SurfaceMesh};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A copy of `surface` after `flips` random edge flips, each keeping the mesh simplicial
/// ([`crate::SurfaceMesh::can_flip_simplicial`]) and its geometry non-degenerate (neither new
/// triangle may be flat: on flat regions such as the bricks' lattice faces, a flip could otherwise
/// make three collinear points a triangle); positions are unchanged, ids dense.
///
/// Edges are drawn uniformly among the live edges; a drawn edge that cannot be flipped is skipped
/// (not counted). When `E` draws in a row fail, all edges are scanned: if none can be flipped
/// (e.g. the tetrahedron), the flips stop early, so the call always ends. Expected
/// O(flips * degree) time when a constant fraction of the edges is flippable. Same seed, same
/// result.
pub fn random_flips(surface: &Surface, flips: usize, seed: u64) -> Surface {
    random_flips_covered(&surface.clone().into(), flips, seed)
        .into_plain()
        .expect("flips keep a closed orientable surface so")
}

/// [`random_flips`] on any compact surface: boundary edges are never flipped (nor the edges of
/// the cones closing the boundary), and a flip of a non-orientable component is made on both
/// lifts ([`flip_lifts`]). Edges are drawn among the cover's edges, those that are not the
/// surface's (cone and mirror edges) skipped like unflippable ones.
pub fn random_flips_covered(surface: &CoveredSurface, flips: usize, seed: u64) -> CoveredSurface {
    let mut out = surface.clone();
    out.compact();
    let CoveredSurface { cover, positions } = &mut out;
    let edges = cover.mesh.edge_count();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (mut done, mut failures) = (0usize, 0usize);
    while done < flips && edges > 0 {
        let e = EdgeId::new(rng.random_range(0..edges));
        if flippable(&cover.mesh, &cover.sheets, positions, e) {
            flip_lifts(&mut cover.mesh, &mut cover.sheets, e).expect("checked by flippable");
            done += 1;
            failures = 0;
        } else {
            failures += 1;
            if failures >= edges {
                let (mesh, sheets) = (&cover.mesh, &cover.sheets);
                if !mesh.edges().any(|e| flippable(mesh, sheets, positions, e)) {
                    break;
                }
                failures = 0;
            }
        }
    }
    out
}

/// Whether `e` is an edge of the surface (the first of its mirror pair, not at an apex, not on
/// the boundary) whose flip keeps the surface simplicial and both new triangles fat.
fn flippable<L: Lifting>(mesh: &SurfaceMesh, lifting: &L, positions: &[Point3], e: EdgeId) -> bool {
    if lifting.edge_key(e) != e || !can_flip_simplicial(mesh, lifting, e) {
        return false;
    }
    let h = e.halfedge();
    let corners = [
        mesh.origin(h),
        mesh.dest(h),
        mesh.opposite_vertex(h),
        mesh.opposite_vertex(h.twin()),
    ];
    if corners.iter().any(|&v| lifting.is_apex(v)) {
        return false;
    }
    let [a, b, c, d] = corners.map(|v| positions[lifting.class(v) as usize]);
    fat(d, c, a) && fat(c, d, b)
}

/// [`SurfaceMesh::can_flip_simplicial`] on the covered surface: adjacency of vertex classes.
fn can_flip_simplicial<L: Lifting>(mesh: &SurfaceMesh, lifting: &L, e: EdgeId) -> bool {
    if !mesh.can_flip(e) {
        return false;
    }
    let h = e.halfedge();
    let (a, b) = (mesh.origin(h), mesh.dest(h));
    let (c, d) = (mesh.opposite_vertex(h), mesh.opposite_vertex(h.twin()));
    if lifting.class(c) == lifting.class(d) || mesh.degree(a) <= 3 || mesh.degree(b) <= 3 {
        return false;
    }
    let (small, other) = if mesh.degree(c) <= mesh.degree(d) {
        (c, d)
    } else {
        (d, c)
    };
    let other = lifting.class(other);
    !mesh
        .neighbors(small)
        .any(|w: VertexId| lifting.class(w) == other)
}

/// Whether triangle (x, y, z) has an area above a relative threshold (1e-12 of the squared
/// longest side).
fn fat(x: Point3, y: Point3, z: Point3) -> bool {
    let u = [y[0] - x[0], y[1] - x[1], y[2] - x[2]];
    let w = [z[0] - x[0], z[1] - x[1], z[2] - x[2]];
    let n = [
        u[1] * w[2] - u[2] * w[1],
        u[2] * w[0] - u[0] * w[2],
        u[0] * w[1] - u[1] * w[0],
    ];
    let area2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    let longest = [u, w, [z[0] - y[0], z[1] - y[1], z[2] - y[2]]]
        .iter()
        .map(|v| v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
        .fold(0.0, f64::max);
    area2 > 1e-24 * longest * longest
}
