//! 1-to-4 midpoint subdivision, to grow real meshes to millions of triangles.

use crate::Surface;
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
    let mut current = surface.clone();
    current.compact();
    for _ in 0..levels {
        let mesh = &current.mesh;
        let (nv, ne, nf) = (mesh.vertex_count(), mesh.edge_count(), mesh.face_count());
        assert!(
            nv + ne < u32::MAX as usize && 12 * nf < u32::MAX as usize,
            "subdivision exceeds u32 ids"
        );
        let mut positions: Vec<Point3> = Vec::with_capacity(nv + ne);
        positions.extend_from_slice(&current.positions[..nv]);
        positions.extend(mesh.edges().map(|e| {
            let [a, b] = mesh.edge_vertices(e).map(|v| current.positions[v.idx()]);
            [0, 1, 2].map(|k| 0.5 * (a[k] + b[k]))
        }));
        let mut triangles: Vec<[u32; 3]> = Vec::with_capacity(4 * nf);
        for f in mesh.faces() {
            let hs = mesh.face_halfedges(f);
            let [a, b, c] = hs.map(|h| mesh.origin(h).0);
            let [ab, bc, ca] = hs.map(|h| (nv + h.edge().idx()) as u32);
            triangles.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        current = Surface::from_triangles(positions, &triangles)
            .expect("midpoint subdivision of a closed surface is a closed surface");
    }
    current
}
