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

/// The tolerance of `info`'s near-degenerate warning, the one place it is set: a triangle is
/// *near-degenerate* when its area is not exactly zero but its height over its longest side is
/// below this fraction of that side ([`relative_height`]). Why 1e-6: the intrinsic algorithms
/// (`delaunay`, `isometric`, the Laplacian) see a triangle through its side lengths rounded to
/// double precision, whose excess b + c − a is about 2(h/a)²·a at its smallest; at h/a = 1e-6
/// that is 2e-12·a, so angles and areas computed from the lengths keep only about four
/// significant digits, and below h/a ≈ 1.5e-8 the rounded lengths no longer make a triangle
/// (`delaunay` then refuses it as a zero-area triangle unless `--mollify`). The warning thus
/// covers every triangle refused that way, with a margin of a hundredfold.
pub const NEAR_DEGENERATE_RELATIVE_HEIGHT: f64 = 1e-6;

/// The smallest height of triangle `a, b, c` divided by its longest side, i.e. twice its area
/// over the longest side squared: 0 for collinear corners, √3/2 for an equilateral triangle.
/// Scale-free: computed on the differences divided by their largest magnitude, so coordinates
/// of any finite magnitude neither overflow nor vanish (the cross product's rounding is about
/// 1e-16 of the result's scale). NaN when a coordinate is not finite.
pub fn relative_height(a: Point3, b: Point3, c: Point3) -> f64 {
    let mut sides = [sub(b, a), sub(c, b), sub(a, c)];
    if sides.iter().flatten().any(|d| d.is_infinite()) {
        // The differences overflow: halve the coordinates first (exact but for subnormals).
        let half = |p: Point3| p.map(|x| x * 0.5);
        sides = [
            sub(half(b), half(a)),
            sub(half(c), half(b)),
            sub(half(a), half(c)),
        ];
    }
    let m = sides.iter().flatten().fold(0.0f64, |m, d| m.max(d.abs()));
    if m == 0.0 || m.is_nan() {
        return if m == 0.0 { 0.0 } else { f64::NAN };
    }
    let [u, v, w] = sides.map(|d| d.map(|x| x / m));
    let n = [
        u[1] * w[2] - u[2] * w[1],
        u[2] * w[0] - u[0] * w[2],
        u[0] * w[1] - u[1] * w[0],
    ];
    let norm2 = |d: Point3| d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    let longest = norm2(u).max(norm2(v)).max(norm2(w));
    norm2(n).sqrt() / longest
}

fn sub(p: Point3, q: Point3) -> Point3 {
    [p[0] - q[0], p[1] - q[1], p[2] - q[2]]
}

/// What is wrong with a face of [`near_degenerate_faces`] whose smallest relative height is
/// `height`, in words (the caller adds where, and the option that makes it usable).
pub fn describe_near_degenerate(height: f64) -> String {
    if height == 0.0 {
        "one of the triangles it is cut into is flat".to_owned()
    } else {
        format!(
            "near-degenerate: height {height:.1e} times its longest side (below \
             {NEAR_DEGENERATE_RELATIVE_HEIGHT:e})"
        )
    }
}

/// Whether triangle `a, b, c` is near-degenerate: not of exactly zero area
/// ([`is_zero_area_triangle`]) but of [`relative_height`] below
/// [`NEAR_DEGENERATE_RELATIVE_HEIGHT`].
pub fn is_near_degenerate_triangle(a: Point3, b: Point3, c: Point3) -> bool {
    relative_height(a, b, c) < NEAR_DEGENERATE_RELATIVE_HEIGHT && !is_zero_area_triangle(a, b, c)
}

/// The near-degenerate faces of a soup cut into triangles (`cut`, by
/// [`crate::triangulate_polygons`]), in face order, each with the smallest [`relative_height`]
/// of its triangles: a triangle face when [`is_near_degenerate_triangle`]; a polygon when one of
/// its triangles has a relative height below [`NEAR_DEGENERATE_RELATIVE_HEIGHT`] (zero included:
/// a polygon that is not simple in its plane may be cut into a flat triangle) unless all of
/// them are flat (the polygon has zero area: a problem, [`problems`]). Faces with an index out
/// of range, a repeated vertex or a non-finite coordinate are skipped (problems of their own).
pub fn near_degenerate_faces(
    positions: &[Point3],
    cut: &crate::PolygonTriangulation,
) -> Vec<(usize, f64)> {
    let mut found = Vec::new();
    let mut start = 0;
    while start < cut.triangles.len() {
        let face = cut.face_of[start];
        let end = start + cut.face_of[start..].partition_point(|&f| f == face);
        let triangles = &cut.triangles[start..end];
        start = end;
        let usable = triangles.iter().all(|t| {
            t[0] != t[1]
                && t[1] != t[2]
                && t[0] != t[2]
                && t.iter().all(|&v| {
                    positions
                        .get(v as usize)
                        .is_some_and(|p| p.iter().all(|c| c.is_finite()))
                })
        });
        if !usable {
            continue;
        }
        let corners = |t: &[u32; 3]| t.map(|v| positions[v as usize]);
        let heights: Vec<f64> = triangles
            .iter()
            .map(|t| {
                let [a, b, c] = corners(t);
                if is_zero_area_triangle(a, b, c) {
                    0.0
                } else {
                    relative_height(a, b, c).max(f64::MIN_POSITIVE)
                }
            })
            .collect();
        let least = heights.iter().copied().fold(f64::INFINITY, f64::min);
        let all_flat = heights.iter().all(|&h| h == 0.0);
        let near = if triangles.len() == 1 {
            least > 0.0 && least < NEAR_DEGENERATE_RELATIVE_HEIGHT
        } else {
            !all_flat && least < NEAR_DEGENERATE_RELATIVE_HEIGHT
        };
        if near {
            found.push((face as usize, least));
        }
    }
    found
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
        face.iter().all(|&v| {
            positions
                .get(v as usize)
                .is_some_and(|p| p.iter().all(|c| c.is_finite()))
        }) && !repeats_a_vertex(face)
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

/// What welding exactly coincident positions ([`weld_exact`]) would make of a soup that has
/// boundary edges or several pieces: the fix to suggest for a triangle soup (every triangle with
/// its own three vertices, as STL and some exporters write), which is otherwise refused as a
/// surface with boundary or read as a pile of disks.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WeldEffect {
    /// Vertices that share their position with an earlier vertex (merged into it).
    pub merged: usize,
    /// The welded triangles, inspected.
    pub after: crate::Inspection,
}

impl WeldEffect {
    /// In words: "would merge 640 vertices into others at the same position, making one closed
    /// surface (sphere)" or "..., leaving 2 pieces with 3 boundary loops (...)".
    pub fn describe(&self) -> String {
        let a = &self.after;
        let names: Vec<String> = a.surfaces.iter().map(crate::SurfaceKind::name).collect();
        let what = if a.boundary_edges == 0 && a.components == 1 {
            format!("making one closed surface ({})", names.join(""))
        } else {
            format!(
                "leaving {} piece{} with {} boundary loop{} ({})",
                a.components,
                if a.components == 1 { "" } else { "s" },
                a.boundary_loops,
                if a.boundary_loops == 1 { "" } else { "s" },
                names.join(" + ")
            )
        };
        format!(
            "would merge {} vertices into others at the same position, {what}",
            self.merged
        )
    }
}

/// What welding would do to the soup of `positions` and `triangles` (inspected as `before`),
/// when it helps: the soup has boundary edges or several pieces, some positions are equal, and
/// the welded soup is a surface (no combinatorial problem) with fewer boundary edges or fewer
/// pieces. `None` otherwise. O(n log n); meant for the paths where the answer is shown (an
/// error, a note), not for every read.
pub fn weld_effect(
    positions: &[Point3],
    triangles: &[[u32; 3]],
    before: &crate::Inspection,
) -> Option<WeldEffect> {
    if before.boundary_edges == 0 && before.components <= 1 {
        return None;
    }
    let (welded, map) = weld_exact(positions);
    if welded.len() == positions.len() {
        return None;
    }
    let merged_triangles: Vec<[u32; 3]> = triangles
        .iter()
        .map(|t| t.map(|v| map.get(v as usize).copied().unwrap_or(v)))
        .collect();
    let after = crate::inspect(welded.len(), &merged_triangles);
    let better =
        after.boundary_edges < before.boundary_edges || after.components < before.components;
    (better && after.is_combinatorially_valid()).then(|| WeldEffect {
        merged: positions.len() - welded.len(),
        after,
    })
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

/// Whether a face lists a vertex twice (O(k log k)).
pub(crate) fn repeats_a_vertex(face: &[u32]) -> bool {
    if face.len() <= 16 {
        return (1..face.len()).any(|i| face[..i].contains(&face[i]));
    }
    let mut sorted = face.to_vec();
    sorted.sort_unstable();
    sorted.windows(2).any(|w| w[0] == w[1])
}
