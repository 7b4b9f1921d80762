//! Geometry held beside the topology: vertex positions and edge lengths.
//!
//! The topology knows nothing of geometry; algorithms that need lengths or angles take these.

use crate::error::BuildError;
use crate::ids::{EdgeId, FaceId, VertexId};
use crate::topology::SurfaceMesh;

/// A 3D point.
pub type Point3 = [f64; 3];

/// Checks that every coordinate is finite.
///
/// # Errors
/// [`BuildError::NonFinite`] naming the first offending vertex and axis.
pub fn check_finite(positions: &[Point3]) -> Result<(), BuildError> {
    for (vertex, p) in positions.iter().enumerate() {
        if let Some(axis) = p.iter().position(|c| !c.is_finite()) {
            return Err(BuildError::NonFinite {
                vertex: vertex as u32,
                axis,
                value: format!("{}", p[axis]),
            });
        }
    }
    Ok(())
}

/// Every NaN or infinite coordinate, one [`BuildError::NonFinite`] per coordinate, in vertex
/// then axis order.
pub fn non_finite_coordinates(positions: &[Point3]) -> impl Iterator<Item = BuildError> + '_ {
    positions.iter().enumerate().flat_map(|(vertex, p)| {
        (0..3)
            .filter(|&axis| !p[axis].is_finite())
            .map(move |axis| BuildError::NonFinite {
                vertex: vertex as u32,
                axis,
                value: format!("{}", p[axis]),
            })
    })
}

/// Whether the triangle `a, b, c` has exactly zero area: its cross product `(b - a) × (c - a)`
/// is zero, i.e. the orientations of its projections on the three coordinate planes (the
/// cross product's components) all vanish. Each is decided exactly by Shewchuk's adaptive
/// `orient2d` (the `robust` crate), so no tolerance is involved and rounding neither hides nor
/// invents a zero; this holds while the predicates' products neither overflow nor underflow
/// (coordinate differences between about 1e-140 and 1e140 in magnitude).
pub fn is_zero_area_triangle(a: Point3, b: Point3, c: Point3) -> bool {
    let on = |i: usize, j: usize| {
        let p = |q: Point3| robust::Coord { x: q[i], y: q[j] };
        robust::orient2d(p(a), p(b), p(c)) == 0.0
    };
    on(0, 1) && on(1, 2) && on(2, 0)
}

/// Whether a face (a polygon given by vertex indices into `positions`) has exactly zero area:
/// every triangle of its fan from the first vertex has ([`is_zero_area_triangle`]); for a
/// triangle, its three vertices are collinear. The caller checks that indices are in range.
pub fn is_zero_area_face(positions: &[Point3], face: &[u32]) -> bool {
    let at = |k: usize| positions[face[k] as usize];
    face.len() >= 3 && (1..face.len() - 1).all(|k| is_zero_area_triangle(at(0), at(k), at(k + 1)))
}

/// The geometric problems of a soup: every non-finite coordinate
/// ([`non_finite_coordinates`]), then every face of exactly zero area ([`is_zero_area_face`],
/// [`BuildError::ZeroArea`], `face` its index in `faces`). A face with a vertex index out of
/// range, a repeated vertex or a non-finite vertex is not tested for zero area: it is a
/// problem of its own kind already ([`crate::inspect`], or the first list). No relative
/// threshold ("near-zero" area) is applied: a zero-area test with a tolerance would depend on
/// the scale chosen, and exactly zero is what makes the intrinsic triangle degenerate.
pub fn problems<'a>(
    positions: &[Point3],
    faces: impl IntoIterator<Item = &'a [u32]>,
) -> Vec<BuildError> {
    let mut found: Vec<BuildError> = non_finite_coordinates(positions).collect();
    let testable = |face: &[u32]| {
        face.iter().enumerate().all(|(k, &v)| {
            positions
                .get(v as usize)
                .is_some_and(|p| p.iter().all(|c| c.is_finite()))
                && !face[..k].contains(&v)
        })
    };
    for (face, indices) in faces.into_iter().enumerate() {
        if testable(indices) && is_zero_area_face(positions, indices) {
            found.push(BuildError::ZeroArea { face });
        }
    }
    found
}

/// Euclidean distance. When the sum of squares overflows or falls below the normal range (points
/// beyond about 1e154 or closer than about 1e-154), the differences are scaled by their largest
/// magnitude first, so the distance is finite and non-zero whenever it is representable.
#[inline]
pub fn distance(p: Point3, q: Point3) -> f64 {
    let d = [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
    let squares = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if squares.is_normal() || squares == 0.0 && d == [0.0; 3] {
        return squares.sqrt();
    }
    let m = d[0].abs().max(d[1].abs()).max(d[2].abs());
    if !m.is_finite() {
        return squares.sqrt();
    }
    let [x, y, z] = d.map(|c| c / m);
    m * (x * x + y * y + z * z).sqrt()
}

/// Edge lengths from vertex positions, indexed by edge id (0 for removed edges).
pub fn edge_lengths(mesh: &SurfaceMesh, positions: &[Point3]) -> Vec<f64> {
    let mut lengths = vec![0.0; mesh.edge_slots()];
    for e in mesh.edges() {
        let [a, b] = mesh.edge_vertices(e);
        lengths[e.idx()] = distance(positions[a.idx()], positions[b.idx()]);
    }
    lengths
}

/// Area of a face from positions.
pub fn face_area(mesh: &SurfaceMesh, positions: &[Point3], f: FaceId) -> f64 {
    let [a, b, c] = mesh.face_vertices(f).map(|v| positions[v.idx()]);
    triangle_area(a, b, c)
}

/// The area of triangle (a, b, c).
pub fn triangle_area(a: Point3, b: Point3, c: Point3) -> f64 {
    let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let w = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    let n = [
        u[1] * w[2] - u[2] * w[1],
        u[2] * w[0] - u[0] * w[2],
        u[0] * w[1] - u[1] * w[0],
    ];
    0.5 * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt()
}

/// Merges vertices with exactly equal positions (`-0.0 == 0.0`), keeping the first occurrence.
/// Returns the welded positions and, per input vertex, its welded index. O(n log n).
pub fn weld_exact(positions: &[Point3]) -> (Vec<Point3>, Vec<u32>) {
    let key = |p: &Point3| p.map(|c| (c + 0.0).to_bits());
    let mut order: Vec<u32> = (0..positions.len() as u32).collect();
    order.sort_unstable_by_key(|&i| (key(&positions[i as usize]), i));
    let mut representative = vec![0u32; positions.len()];
    let mut i = 0;
    while i < order.len() {
        let k = key(&positions[order[i] as usize]);
        let mut j = i;
        while j < order.len() && key(&positions[order[j] as usize]) == k {
            representative[order[j] as usize] = order[i];
            j += 1;
        }
        i = j;
    }
    let mut new_index = vec![u32::MAX; positions.len()];
    let mut welded = Vec::new();
    let mut map = vec![0u32; positions.len()];
    for (v, &r) in representative.iter().enumerate() {
        if new_index[r as usize] == u32::MAX {
            new_index[r as usize] = welded.len() as u32;
            welded.push(positions[r as usize]);
        }
        map[v] = new_index[r as usize];
    }
    (welded, map)
}

/// Interleaves the low 21 bits of three integers (Morton / Z-order code).
fn morton3(x: u64, y: u64, z: u64) -> u64 {
    fn spread(mut v: u64) -> u64 {
        v &= 0x1f_ffff;
        v = (v | v << 32) & 0x001f_0000_0000_ffff;
        v = (v | v << 16) & 0x001f_0000_ff00_00ff;
        v = (v | v << 8) & 0x100f_00f0_0f00_f00f;
        v = (v | v << 4) & 0x10c3_0c30_c30c_30c3;
        v = (v | v << 2) & 0x1249_2492_4924_9249;
        v
    }
    spread(x) | spread(y) << 1 | spread(z) << 2
}

/// Morton codes of points quantised to a 2^21 grid over their bounding box.
fn morton_codes(points: &[Point3]) -> Vec<u64> {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in points {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let scale = (0..3)
        .map(|k| hi[k] - lo[k])
        .fold(0.0f64, f64::max)
        .max(f64::MIN_POSITIVE);
    let q = |c: f64, k: usize| (((c - lo[k]) / scale) * ((1u64 << 21) - 1) as f64) as u64;
    points
        .iter()
        .map(|p| morton3(q(p[0], 0), q(p[1], 1), q(p[2], 2)))
        .collect()
}

/// Reorders vertices and faces of a compact mesh in Morton (Z-order) of their positions and
/// centroids, and edges in order of first use by the reordered faces; `positions` is permuted
/// to match. Returns the renumbering. O(n log n).
///
/// # Panics
/// If the mesh has tombstones (call [`SurfaceMesh::compact`] first) or `positions` is shorter
/// than the vertex range.
pub fn reorder_morton(mesh: &mut SurfaceMesh, positions: &mut Vec<Point3>) -> crate::Renumbering {
    assert!(
        mesh.vertex_count() == mesh.vertex_slots() && mesh.face_count() == mesh.face_slots(),
        "reorder_morton needs a compact mesh"
    );
    let rank = |codes: Vec<u64>| {
        let mut order: Vec<u32> = (0..codes.len() as u32).collect();
        order.sort_unstable_by_key(|&i| (codes[i as usize], i));
        let mut new_of = vec![0u32; codes.len()];
        for (new, &old) in order.iter().enumerate() {
            new_of[old as usize] = new as u32;
        }
        new_of
    };
    let vertex_rank = rank(morton_codes(&positions[..mesh.vertex_slots()]));
    let centroid = |f: FaceId| {
        let [a, b, c] = mesh.face_vertices(f).map(|v| positions[v.idx()]);
        [0, 1, 2].map(|k| (a[k] + b[k] + c[k]) / 3.0)
    };
    let face_rank = rank(morton_codes(
        &mesh.faces().map(centroid).collect::<Vec<_>>(),
    ));
    let mut faces_in_order: Vec<FaceId> = mesh.faces().collect();
    faces_in_order.sort_unstable_by_key(|f| face_rank[f.idx()]);
    let mut edge_new = vec![EdgeId::INVALID; mesh.edge_slots()];
    let mut next_edge = 0usize;
    for &f in &faces_in_order {
        for h in mesh.face_halfedges(f) {
            let e = h.edge();
            if !edge_new[e.idx()].is_valid() {
                edge_new[e.idx()] = EdgeId::new(next_edge);
                next_edge += 1;
            }
        }
    }
    let map = crate::Renumbering {
        vertices: vertex_rank.iter().map(|&r| VertexId(r)).collect(),
        edges: edge_new,
        faces: face_rank.iter().map(|&r| FaceId(r)).collect(),
    };
    mesh.renumber(&map);
    let mut reordered = vec![[0.0; 3]; positions.len().min(mesh.vertex_slots())];
    for (old, &new) in map.vertices.iter().enumerate() {
        reordered[new.idx()] = positions[old];
    }
    *positions = reordered;
    map
}
