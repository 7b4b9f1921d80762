//! Random simplicial edge flips: irregular connectivity on a fixed vertex set.

use crate::Surface;
use crate::ids::EdgeId;
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
    let mut out = surface.clone();
    out.compact();
    let mesh = &mut out.mesh;
    let positions = &out.positions;
    let edges = mesh.edge_count();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (mut done, mut failures) = (0usize, 0usize);
    while done < flips && edges > 0 {
        let e = EdgeId::new(rng.random_range(0..edges));
        if mesh.can_flip_simplicial(e) && keeps_area(mesh, positions, e) {
            mesh.flip(e).expect("checked by can_flip_simplicial");
            done += 1;
            failures = 0;
        } else {
            failures += 1;
            if failures >= edges {
                let flippable = |e| mesh.can_flip_simplicial(e) && keeps_area(mesh, positions, e);
                if !mesh.edges().any(flippable) {
                    break;
                }
                failures = 0;
            }
        }
    }
    out
}

/// Whether the two triangles made by flipping `e`, (d, c, a) and (c, d, b), both have an area
/// above a relative threshold (1e-12 of the squared longest side).
fn keeps_area(mesh: &crate::SurfaceMesh, positions: &[crate::geometry::Point3], e: EdgeId) -> bool {
    let h = e.halfedge();
    let p = |v: crate::VertexId| positions[v.idx()];
    let (a, b) = (p(mesh.origin(h)), p(mesh.dest(h)));
    let (c, d) = (
        p(mesh.opposite_vertex(h)),
        p(mesh.opposite_vertex(h.twin())),
    );
    let fat =
        |x: crate::geometry::Point3, y: crate::geometry::Point3, z: crate::geometry::Point3| {
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
        };
    fat(d, c, a) && fat(c, d, b)
}
