//! 1-to-4 midpoint subdivision, to grow real meshes to millions of triangles.

use crate::Surface;
use crate::cover::{CoveredSurface, Lifting};
use crate::geometry::Point3;

/// `surface` refined `levels` times by 1-to-4 splits: each edge gets a new vertex at its midpoint
/// (id `V + edge id`, no hash map), each triangle `(a, b, c)` becomes `(a, ab, ca)`,
/// `(b, bc, ab)`, `(c, ca, bc)` and `(ab, bc, ca)`. Per level: `V' = V + E`, `E' = 2E + 3F`,
/// `F' = 4F`; the genus is kept and a simplicial mesh stays simplicial. Ids are dense; the four
/// children of face `f` are faces `4f..4f+4`. O(F) per level. Deterministic.
///
/// # Panics
/// If the result exceeds the `u32` id range.
pub fn subdivide_midpoint(surface: &Surface, levels: u32) -> Surface {
    subdivide_midpoint_covered(&surface.clone().into(), levels)
        .into_plain()
        .expect("subdivision keeps a closed orientable surface so")
}

/// [`subdivide_midpoint`] on any compact surface: the surface's edges (not the cones' nor the
/// mirrors') get the midpoints, in edge id order, and its faces are refined in face id order.
///
/// # Panics
/// If the result exceeds the `u32` id range.
pub fn subdivide_midpoint_covered(surface: &CoveredSurface, levels: u32) -> CoveredSurface {
    let mut current = surface.clone();
    current.compact();
    for _ in 0..levels {
        let (mesh, sheets) = (&current.cover.mesh, &current.cover.sheets);
        let nv = current.positions.len();
        let nf = mesh.face_count();
        let mut positions: Vec<Point3> = current.positions.clone();
        let mut midpoint = vec![u32::MAX; mesh.edge_slots()];
        for e in mesh.edges() {
            let ends = mesh.edge_vertices(e);
            if sheets.edge_key(e) != e || ends.iter().any(|&v| sheets.is_apex(v)) {
                continue;
            }
            midpoint[e.idx()] = positions.len() as u32;
            let [a, b] = ends.map(|v| current.positions[sheets.class(v) as usize]);
            positions.push([0, 1, 2].map(|k| 0.5 * (a[k] + b[k])));
        }
        assert!(
            positions.len() < u32::MAX as usize && 12 * nf < u32::MAX as usize,
            "subdivision exceeds u32 ids"
        );
        let mut triangles: Vec<[u32; 3]> = Vec::with_capacity(4 * nf);
        for f in current.cover.surface_faces() {
            let hs = mesh.face_halfedges(f);
            let [a, b, c] = hs.map(|h| sheets.class(mesh.origin(h)));
            let [ab, bc, ca] = hs.map(|h| midpoint[sheets.edge_key(h.edge()).idx()]);
            triangles.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        debug_assert!(nv <= positions.len());
        current = CoveredSurface::from_triangles(positions, &triangles)
            .expect("midpoint subdivision of a surface is a surface")
            .0;
    }
    current
}
