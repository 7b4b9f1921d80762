//! Random vertex splits (the inverse of edge contractions, with fresh ids).

use crate::Surface;
use crate::cover::{CoveredSurface, Lifting, split_lifts};
use crate::geometry::Point3;
use crate::ids::{HalfedgeId, VertexId};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A copy of `surface` after `splits` random vertex splits ([`crate::SurfaceMesh::split_vertex_new`]).
///
/// Each split draws a vertex `u` uniformly (new vertices included) and two distinct outgoing
/// half-edges `u -> y`, `u -> x` of it with `x != y`; the neighbours strictly between them in
/// rotation order move to the new vertex `v`, which is joined to `u`, `x` and `y`. So each split
/// adds 1 vertex, 3 edges and 2 faces and keeps the genus. The new vertex is placed at the
/// midpoint of `u` and the centroid of its other neighbours (`x`, `y` and the moved ones), or,
/// when that makes a triangle at `v` of (nearly) zero area (neighbours balanced around `u`), at
/// the centroid of the face of `u` at `x` or at `y`, or at points ever closer to `u` inside the
/// faces that moved from `u` to `v`: the first whose triangles at `v` all have a height above
/// 1e-12 of their longest side (none of exactly zero area, an exact predicate).
///
/// Guarantee: a split is made only at such a placement, so no triangle made by a split is flat
/// and written meshes have no zero-length edge or flat triangle from a split. The placements are
/// tried on the star `v` would have before the split is made; when none passes (a degenerate
/// neighbourhood of `u`, e.g. `u` and its neighbours on one line, or some splits of a boundary
/// vertex of a planar surface), that split is not made and another `u`, `y`, `x` is drawn from
/// the same seeded stream, at most 8 times per split (`SPLIT_DRAWS`); if every draw fails, the
/// split is left out (then fewer than `splits` vertices are added: seen only when much of the
/// surface is degenerate). A split whose first draw passes consumes one draw of the stream.
///
/// A simplicial input stays simplicial (the new edges all end at the new vertex, and every moved
/// neighbour was adjacent to `u` once); a vertex whose outgoing half-edges all reach one
/// destination (possible only in a non-simplicial input) is skipped. Ids are dense. O(splits *
/// degree). Same seed, same result.
pub fn random_vertex_splits(surface: &Surface, splits: usize, seed: u64) -> Surface {
    random_vertex_splits_covered(&surface.clone().into(), splits, seed)
        .into_plain()
        .expect("splits keep a closed orientable surface so")
}

/// [`random_vertex_splits`] on any compact surface: `u` is drawn among the surface's vertices
/// (not the apexes closing the boundary), x or y may be an apex (the split of a boundary vertex
/// then adds a boundary edge), a split of a non-orientable component is made on both lifts
/// ([`split_lifts`]; both lifts sit at the same positions, so one is checked), and the placement
/// ignores the apexes.
pub fn random_vertex_splits_covered(
    surface: &CoveredSurface,
    splits: usize,
    seed: u64,
) -> CoveredSurface {
    let mut out = surface.clone();
    out.compact();
    let simplicial_input = cfg!(debug_assertions) && out.cover.mesh.is_simplicial();
    let CoveredSurface { cover, positions } = &mut out;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut ring: Vec<HalfedgeId> = Vec::new();
    'splits: for _ in 0..splits {
        for _ in 0..SPLIT_DRAWS {
            let classes = cover.sheets.class_count();
            let class = loop {
                let c = rng.random_range(0..classes) as u32;
                if cover.sheets.apex_class() != Some(c) {
                    break c;
                }
            };
            let mesh = &cover.mesh;
            let u = cover.sheets.lift(class);
            ring.clear();
            ring.extend(mesh.outgoing(u));
            let i = rng.random_range(0..ring.len());
            let to_y = ring[i];
            let choices = ring
                .iter()
                .filter(|&&h| mesh.dest(h) != mesh.dest(to_y))
                .count();
            if choices == 0 {
                continue 'splits;
            }
            let pick = rng.random_range(0..choices);
            let to_x = *ring
                .iter()
                .filter(|&&h| mesh.dest(h) != mesh.dest(to_y))
                .nth(pick)
                .expect("pick < choices");
            let Some(p) = placement(cover, positions, to_y, to_x) else {
                continue;
            };
            let (new_class, record) = split_lifts(&mut cover.mesh, &mut cover.sheets, to_y, to_x)
                .expect("two outgoing half-edges of u with distinct destinations");
            debug_assert_eq!(new_class as usize, positions.len());
            positions.push(p);
            debug_assert!(star_flatness(cover, positions, record.removed()) > STAR_HEIGHT);
            continue 'splits;
        }
    }
    debug_assert!(!simplicial_input || out.cover.mesh.is_simplicial());
    out
}

/// Draws of `u`, `y`, `x` per split before a split with no non-flat placement is left out.
const SPLIT_DRAWS: usize = 8;

/// Where the split of `u = origin(to_y)` between `to_y` and `to_x` puts its new vertex `v` (see
/// [`random_vertex_splits`]), or `None` when every placement leaves a triangle at `v` with height
/// at most [`STAR_HEIGHT`] of its longest side. Computed before the split, on the star `v` would
/// have: the faces of `u` from `to_y` up to `to_x` in rotation order (which move to `v`), and the
/// new faces `[u, v, x]` and `[v, u, y]`, each with its vertices in the order the split gives it,
/// so the figures are those of the split mesh.
fn placement(
    cover: &crate::ClosedCover,
    positions: &[Point3],
    to_y: HalfedgeId,
    to_x: HalfedgeId,
) -> Option<Point3> {
    let (mesh, sheets) = (&cover.mesh, &cover.sheets);
    let u = mesh.origin(to_y);
    let at = |w: VertexId| positions[sheets.class(w) as usize];
    // The wedge: u's outgoing half-edges from to_y up to (not including) to_x; the first's
    // destination is y, the others' are the neighbours that move to v.
    let mut wedge = vec![to_y];
    let mut k = mesh.rotate(to_y);
    while k != to_x {
        wedge.push(k);
        k = mesh.rotate(k);
    }
    // v's faces, None standing for v.
    let star: Vec<[Option<VertexId>; 3]> = wedge
        .iter()
        .map(|&k| {
            mesh.face_vertices(mesh.face(k))
                .map(|w| if w == u { None } else { Some(w) })
        })
        .chain([
            [Some(u), None, Some(mesh.dest(to_x))],
            [None, Some(u), Some(mesh.dest(to_y))],
        ])
        .collect();
    let (mut sum, mut count) = ([0.0; 3], 0.0);
    let others = wedge.iter().map(|&k| mesh.dest(k)).chain([mesh.dest(to_x)]);
    for w in others.filter(|&w| w != u && !sheets.is_apex(w)) {
        let p = at(w);
        sum = [0, 1, 2].map(|k| sum[k] + p[k]);
        count += 1.0;
    }
    let pu = at(u);
    let midpoint: Point3 = [0, 1, 2].map(|k| 0.5 * (pu[k] + sum[k] / count));
    let centroid = |face: [VertexId; 3]| {
        if face.iter().any(|&w| sheets.is_apex(w)) {
            return None;
        }
        let [a, b, c] = face.map(at);
        Some([0, 1, 2].map(|k| (a[k] + b[k] + c[k]) / 3.0))
    };
    // Faces of u at x and at y.
    let face_at_x = [u, mesh.dest(to_x), mesh.dest(mesh.next(to_x))];
    let face_at_y = [u, mesh.dest(to_y), mesh.dest(mesh.next(to_y))];
    // The midpoint of u and the centroid of the other neighbours, unless that makes a
    // (nearly) zero-area triangle at v (neighbours balanced around u, as on a regular grid,
    // put it on u or on a line through two of them): then the centroid of a face of u, which
    // lies strictly inside that face; then points ever closer to u inside each face that
    // moves from u to v (near u, v's triangles are close to u's old ones, none flat, and
    // inside a face in the middle of the moved wedge v is on the right side of u–x and u–y).
    let moved: Vec<Point3> = wedge
        .iter()
        .filter_map(|&k| centroid(mesh.face_vertices(mesh.face(k))))
        .collect();
    let near_u = [0.5, 0.125, 1.0 / 64.0].into_iter().flat_map(|t| {
        moved
            .iter()
            .map(move |c| [0, 1, 2].map(|k| pu[k] + t * (c[k] - pu[k])))
    });
    [Some(midpoint), centroid(face_at_x), centroid(face_at_y)]
        .into_iter()
        .flatten()
        .chain(near_u)
        .find(|&p| {
            let flatness = star.iter().map(|face| {
                if face.iter().flatten().any(|&w| sheets.is_apex(w)) {
                    return f64::INFINITY;
                }
                height_ratio(face.map(|w| w.map_or(p, at)))
            });
            flatness.fold(f64::INFINITY, f64::min) > STAR_HEIGHT
        })
}

/// A triangle made by a split is kept only if twice its area exceeds this times its longest side
/// squared (its height is above this fraction of that side): far above the rounding of lengths
/// computed from positions (about 1e-16), so that every reader, the ones that measure lengths in
/// double precision included, takes it as a triangle. 1e-12.
const STAR_HEIGHT: f64 = 1e-12;

/// Twice the area of triangle `[a, b, c]` over its longest side squared (its height over that
/// side), 0 for a triangle of exactly zero area ([`crate::geometry::is_zero_area_triangle`]: an
/// exact predicate, so a flat face never passes for rounding's sake).
fn height_ratio([a, b, c]: [Point3; 3]) -> f64 {
    use crate::geometry::{distance, is_zero_area_triangle, triangle_area};
    if is_zero_area_triangle(a, b, c) {
        return 0.0;
    }
    let longest = distance(a, b).max(distance(b, c)).max(distance(c, a));
    2.0 * triangle_area(a, b, c) / (longest * longest)
}

/// The smallest [`height_ratio`] among the faces around `v` (apex faces aside): the check, after
/// a split, that [`placement`] saw the star the split made.
fn star_flatness(cover: &crate::ClosedCover, positions: &[Point3], v: VertexId) -> f64 {
    let mesh = &cover.mesh;
    mesh.outgoing(v)
        .map(|h| {
            let face = mesh.face_vertices(mesh.face(h));
            if face.iter().any(|&w| cover.sheets.is_apex(w)) {
                return f64::INFINITY;
            }
            height_ratio(face.map(|w| positions[cover.class(w) as usize]))
        })
        .fold(f64::INFINITY, f64::min)
}
