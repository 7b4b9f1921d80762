//! Polygon faces cut into triangles (`triangulate_polygons`), checked by an independent verifier:
//! integer polygons placed exactly on planes in space, the triangles checked with integer
//! arithmetic to form a triangulated disk whose boundary is the polygon and whose triangles all
//! turn the polygon's way with non-zero area — for a simple polygon, a triangulation of it
//! without a degenerate triangle.

use proptest::prelude::*;
use surftopo_mesh::geometry::is_zero_area_triangle;
use surftopo_mesh::{build, triangulate_polygon, triangulate_polygons};

/// Twice the signed area of the triangle of integer points.
fn cross(a: [i64; 2], b: [i64; 2], c: [i64; 2]) -> i128 {
    let (ux, uy) = (i128::from(b[0] - a[0]), i128::from(b[1] - a[1]));
    let (vx, vy) = (i128::from(c[0] - a[0]), i128::from(c[1] - a[1]));
    ux * vy - uy * vx
}

/// Twice the signed area of a polygon of integer points (shoelace).
fn shoelace(points: &[[i64; 2]]) -> i128 {
    (0..points.len())
        .map(|i| {
            let (p, q) = (points[i], points[(i + 1) % points.len()]);
            i128::from(p[0]) * i128::from(q[1]) - i128::from(q[0]) * i128::from(p[1])
        })
        .sum()
}

/// The verifier: `triangles` (indices into `points`, the polygon being 0..k in order) are k − 2
/// triangles of distinct corners forming a disk whose boundary is the polygon (each side once,
/// in its direction; every other side twice, both ways), each turning the polygon's way with
/// non-zero area. For a simple polygon, an orientation-preserving triangulated disk bounded by
/// it is a triangulation of it.
fn check_triangulation(points: &[[i64; 2]], triangles: &[[u32; 3]]) -> Result<(), String> {
    let k = points.len();
    if triangles.len() != k - 2 {
        return Err(format!("{} triangles for {k} corners", triangles.len()));
    }
    let orientation = shoelace(points).signum();
    if orientation == 0 {
        return Err("polygon of zero area".into());
    }
    let mut sides = std::collections::HashMap::<(u32, u32), usize>::new();
    for t in triangles {
        if t.iter().any(|&v| v as usize >= k) || t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
            return Err(format!(
                "triangle {t:?}: corners not distinct corners of the polygon"
            ));
        }
        let c = cross(
            points[t[0] as usize],
            points[t[1] as usize],
            points[t[2] as usize],
        );
        if c.signum() != orientation {
            return Err(format!(
                "triangle {t:?}: orientation {c} (polygon {orientation})"
            ));
        }
        for i in 0..3 {
            *sides.entry((t[i], t[(i + 1) % 3])).or_default() += 1;
        }
    }
    for (&(a, b), &n) in &sides {
        let boundary = (a as usize + 1) % k == b as usize;
        let reverse = sides.get(&(b, a)).copied().unwrap_or(0);
        if n != 1 || (boundary && reverse != 0) || (!boundary && reverse != 1) {
            return Err(format!(
                "side ({a}, {b}): {n} times, reverse {reverse} times"
            ));
        }
        if (b as usize + 1) % k == a as usize {
            return Err(format!("side ({a}, {b}) runs against the polygon"));
        }
    }
    let boundary_sides = (0..k)
        .filter(|&i| sides.contains_key(&(i as u32, ((i + 1) % k) as u32)))
        .count();
    if boundary_sides != k {
        return Err(format!("{boundary_sides} of the {k} sides in a triangle"));
    }
    Ok(())
}

/// The plane `embedding` puts integer points on, exactly (small integers).
fn embed(p: [i64; 2], embedding: u8) -> [f64; 3] {
    let (x, y) = (p[0] as f64, p[1] as f64);
    match embedding % 4 {
        0 => [x, y, 0.0],
        1 => [x, y, x + 2.0 * y],
        2 => [3.0 * y - x, 7.0, x],
        _ => [-y, x + y, 2.0 * x - y],
    }
}

/// Triangulates the polygon of `points` embedded in space and verifies the result.
fn triangulate_and_check(points: &[[i64; 2]], embedding: u8) -> Result<(), String> {
    let positions: Vec<[f64; 3]> = points.iter().map(|&p| embed(p, embedding)).collect();
    let face: Vec<u32> = (0..points.len() as u32).collect();
    let result = triangulate_polygons(&positions, [&face[..]]);
    if result.irregular != 0 {
        return Err("a simple planar polygon took the fallback".into());
    }
    check_triangulation(points, &result.triangles)
}

/// A polygon star-shaped around the origin: integer corners sorted by angle (at most one per
/// direction), with some sides split at their integer midpoint (collinear corners); simple when
/// every side turns left around the origin ([`around_origin`]).
fn star(corners: Vec<(i64, i64)>, splits: Vec<bool>) -> Vec<[i64; 2]> {
    let mut points: Vec<[i64; 2]> = corners
        .into_iter()
        .map(|(x, y)| [x, y])
        .filter(|p| *p != [0, 0])
        .collect();
    points.sort_by(|p, q| {
        let (a, b) = (
            (p[1] as f64).atan2(p[0] as f64),
            (q[1] as f64).atan2(q[0] as f64),
        );
        a.total_cmp(&b)
    });
    // One corner per direction from the origin (exact test), so the polygon is simple.
    points.dedup_by(|q, p| cross([0, 0], *p, *q) == 0 && p[0] * q[0] + p[1] * q[1] > 0);
    let mut out = Vec::new();
    for (i, &p) in points.iter().enumerate() {
        out.push(p);
        let q = points[(i + 1) % points.len()];
        if splits.get(i).copied().unwrap_or(false)
            && (p[0] + q[0]) % 2 == 0
            && (p[1] + q[1]) % 2 == 0
        {
            out.push([(p[0] + q[0]) / 2, (p[1] + q[1]) / 2]);
        }
    }
    out
}

/// Whether every side of the polygon turns left around the origin (strictly inside its kernel):
/// then the polygon is simple.
fn around_origin(points: &[[i64; 2]]) -> bool {
    (0..points.len()).all(|i| cross([0, 0], points[i], points[(i + 1) % points.len()]) > 0)
}

/// An x-monotone polygon: an upper chain above y = 0 and a lower chain below, between (0, 0)
/// and (n + 1, 0); many reflex corners.
fn monotone(upper: Vec<i64>, lower: Vec<i64>) -> Vec<[i64; 2]> {
    let n = upper.len();
    let mut points = vec![[0, 0]];
    for (i, &y) in lower.iter().enumerate() {
        points.push([i as i64 + 1, -y]);
    }
    points.push([n as i64 + 1, 0]);
    for (i, &y) in upper.iter().enumerate().rev() {
        points.push([i as i64 + 1, y]);
    }
    points
}

proptest! {
    #[test]
    fn star_shaped_polygons_are_triangulated(
        corners in prop::collection::vec((-50i64..50, -50i64..50), 3..40),
        splits in prop::collection::vec(any::<bool>(), 40),
        embedding in 0u8..4,
        reverse in any::<bool>(),
    ) {
        let mut points = star(corners, splits);
        prop_assume!(points.len() >= 4 && around_origin(&points));
        if reverse {
            points.reverse();
        }
        prop_assert_eq!(triangulate_and_check(&points, embedding), Ok(()));
    }

    #[test]
    fn monotone_polygons_are_triangulated(
        heights in prop::collection::vec((1i64..20, 1i64..20), 2..60),
        embedding in 0u8..4,
        rotate in 0usize..200,
    ) {
        let (upper, lower): (Vec<i64>, Vec<i64>) = heights.into_iter().unzip();
        let mut points = monotone(upper, lower);
        let r = rotate % points.len();
        points.rotate_left(r);
        prop_assert_eq!(triangulate_and_check(&points, embedding), Ok(()));
    }
}

#[test]
fn a_convex_polygon_is_cut_into_the_fan_of_its_first_corner() {
    let points: Vec<[i64; 2]> = vec![[0, 0], [4, 0], [6, 3], [4, 6], [0, 6], [-2, 3]];
    let positions: Vec<[f64; 3]> = points.iter().map(|&p| embed(p, 1)).collect();
    let triangles = triangulate_polygon(&positions, &[0, 1, 2, 3, 4, 5]);
    assert_eq!(triangles, vec![[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 5]]);
}

#[test]
fn collinear_corners_get_no_degenerate_triangle() {
    // A square with its bottom side split twice: the fan of corner 0 would make (0, 1, 2) flat.
    let points = vec![[0, 0], [1, 0], [2, 0], [3, 0], [3, 3], [0, 3]];
    triangulate_and_check(&points, 0).unwrap();
    // A triangle with a corner in the middle of each side (a hexagon of three flat corners):
    // its only non-degenerate triangulation joins the midpoints.
    let points = vec![[0, 0], [2, 0], [4, 0], [3, 2], [2, 4], [1, 2]];
    triangulate_and_check(&points, 2).unwrap();
    // Every rotation of its corners.
    for r in 0..points.len() {
        let mut rotated = points.clone();
        rotated.rotate_left(r);
        triangulate_and_check(&rotated, 3).unwrap();
    }
}

#[test]
fn a_large_convex_polygon_is_cut_in_linear_time() {
    // 200,000 corners on a parabola's convex arc, closed by one long side.
    let k = 200_000i64;
    let points: Vec<[i64; 2]> = (0..k).map(|i| [i, -(i - k / 2).pow(2)]).collect();
    let positions: Vec<[f64; 3]> = points.iter().map(|&p| embed(p, 0)).collect();
    let face: Vec<u32> = (0..k as u32).collect();
    let result = triangulate_polygons(&positions, [&face[..]]);
    assert_eq!(result.irregular, 0);
    check_triangulation(&points, &result.triangles).unwrap();
}

#[test]
fn irregular_polygons_still_give_a_triangulated_disk() {
    let twisted = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 1.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 1.0],
    ];
    // Twisted (not planar) but simple in its plane: regular, two triangles of non-zero area.
    let result = triangulate_polygons(&twisted, [&[0u32, 1, 2, 3][..]]);
    assert_eq!(result.triangles.len(), 2);
    for t in &result.triangles {
        let [a, b, c] = t.map(|v| twisted[v as usize]);
        assert!(!is_zero_area_triangle(a, b, c));
    }
    // A bow-tie (self-intersecting): the fallback cuts it, without a flat triangle.
    let bow_tie = [
        [0.0, 0.0, 0.0],
        [2.0, 2.0, 0.0],
        [2.0, 0.0, 0.0],
        [0.0, 2.0, 0.0],
        [1.0, 5.0, 0.0],
    ];
    let result = triangulate_polygons(&bow_tie, [&[0u32, 1, 2, 3, 4][..]]);
    assert_eq!(result.triangles.len(), 3);
    // Collinear corners only: every triangle is flat, the disk is still there.
    let line = [[0.0; 3], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0], [3.0, 3.0, 3.0]];
    let result = triangulate_polygons(&line, [&[0u32, 1, 2, 3][..]]);
    assert_eq!((result.triangles.len(), result.irregular), (2, 1));
    // A repeated vertex, an index out of range, a non-finite coordinate: the fan of corner 0.
    let square = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, f64::NAN],
    ];
    for face in [&[0u32, 1, 0, 2][..], &[0, 1, 2, 9], &[0, 1, 2, 3]] {
        let result = triangulate_polygons(&square, [face]);
        let fan = vec![[face[0], face[1], face[2]], [face[0], face[2], face[3]]];
        assert_eq!((result.triangles, result.irregular), (fan, 1));
    }
}

#[test]
fn extreme_magnitudes_are_exact() {
    for scale in [1e-120, 1e-30, 1.0, 1e30, 1e120] {
        let points = vec![[0, 0], [1, 0], [2, 0], [3, 0], [3, 3], [0, 3]];
        let positions: Vec<[f64; 3]> = points
            .iter()
            .map(|&p| embed(p, 1).map(|c| c * scale))
            .collect();
        let face: Vec<u32> = (0..6).collect();
        let result = triangulate_polygons(&positions, [&face[..]]);
        assert_eq!(result.irregular, 0, "scale {scale}");
        check_triangulation(&points, &result.triangles).unwrap();
    }
}

#[test]
fn a_torus_of_quads_becomes_a_closed_surface() {
    // A 6 x 4 grid of quads on a torus of revolution, with face_of naming each quad.
    let (m, n) = (6u32, 4u32);
    let mut positions = Vec::new();
    for i in 0..m {
        for j in 0..n {
            let (u, v) = (
                std::f64::consts::TAU * f64::from(i) / f64::from(m),
                std::f64::consts::TAU * f64::from(j) / f64::from(n),
            );
            let r = 3.0 + v.cos();
            positions.push([r * u.cos(), r * u.sin(), v.sin()]);
        }
    }
    let at = |i: u32, j: u32| (i % m) * n + j % n;
    let quads: Vec<[u32; 4]> = (0..m)
        .flat_map(|i| (0..n).map(move |j| [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]))
        .collect();
    let result = triangulate_polygons(&positions, quads.iter().map(|q| &q[..]));
    assert_eq!(result.polygons, quads.len());
    assert_eq!(result.triangles.len(), 2 * quads.len());
    for (t, &f) in result.triangles.iter().zip(&result.face_of) {
        assert!(t.iter().all(|v| quads[f as usize].contains(v)));
    }
    let (mesh, report) = build(positions.len(), &result.triangles).unwrap();
    assert_eq!((mesh.genus(), report.reoriented_faces), (1, 0));
}

/// The smallest relative height of the triangles (the independent formula: twice the area over
/// the longest side squared, exact for these integer corners).
fn least_shape(points: &[[i64; 2]], triangles: &[[u32; 3]]) -> f64 {
    triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|v| points[v as usize]);
            let d2 =
                |p: [i64; 2], q: [i64; 2]| ((p[0] - q[0]).pow(2) + (p[1] - q[1]).pow(2)) as f64;
            let longest = d2(a, b).max(d2(b, c)).max(d2(c, a));
            cross(a, b, c).abs() as f64 / longest
        })
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn near_degenerate_triangles_are_avoided_where_the_polygon_allows() {
    // A quadrilateral with corner 3 a hair off the diagonal 0–2: cut along 1–3.
    let quad = vec![
        [0, 0],
        [1_000_000_000, 0],
        [1_000_000_000, 1_000_000_000],
        [500_000_000, 500_000_001],
    ];
    let positions: Vec<[f64; 3]> = quad.iter().map(|&p| embed(p, 0)).collect();
    let triangles = triangulate_polygon(&positions, &[0, 1, 2, 3]);
    check_triangulation(&quad, &triangles).unwrap();
    assert!(least_shape(&quad, &triangles) > 0.1, "{triangles:?}");
    // A rectangle (embedding 0 keeps it one: the others shear it): both diagonals alike,
    // corner 0's.
    let rectangle = [[0, 0], [4, 0], [4, 2], [0, 2]];
    let positions: Vec<[f64; 3]> = rectangle.iter().map(|&p| embed(p, 0)).collect();
    assert_eq!(
        triangulate_polygon(&positions, &[0, 1, 2, 3]),
        vec![[0, 1, 2], [0, 2, 3]]
    );
    // A pentagon whose corner 1 splits side 0–2 a hair off the line (a vertex computed in
    // floating point): the fan of corner 0 would start with a needle; it is passed over.
    let pentagon = vec![
        [0, 0],
        [1_000_000_000, 1],
        [2_000_000_000, 0],
        [2_000_000_000, 1_000_000_000],
        [0, 1_000_000_000],
    ];
    let positions: Vec<[f64; 3]> = pentagon.iter().map(|&p| embed(p, 2)).collect();
    let triangles = triangulate_polygon(&positions, &[0, 1, 2, 3, 4]);
    check_triangulation(&pentagon, &triangles).unwrap();
    assert!(least_shape(&pentagon, &triangles) > 1e-3, "{triangles:?}");
}

#[test]
fn a_finely_sampled_circle_is_cut_without_search() {
    // 20,000 corners on a circle: every ear is near-degenerate, so none is passed over.
    let k = 20_000;
    let positions: Vec<[f64; 3]> = (0..k)
        .map(|i| {
            let t = std::f64::consts::TAU * f64::from(i) / f64::from(k);
            [t.cos(), t.sin(), 0.0]
        })
        .collect();
    let face: Vec<u32> = (0..k).collect();
    let result = triangulate_polygons(&positions, [&face[..]]);
    assert_eq!(
        (result.triangles.len(), result.irregular),
        (k as usize - 2, 0)
    );
    let fan: Vec<[u32; 3]> = (1..k - 1).map(|i| [0, i, i + 1]).collect();
    assert_eq!(result.triangles, fan);
}

#[test]
fn a_diagonal_that_is_already_an_edge_is_not_cut() {
    // A square whose corner-0 diagonal (0, 2) is a side of another face: cutting along it would
    // put that edge in three triangles, so the other diagonal is cut.
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.5, 0.5, 1.0],
    ];
    let faces: [&[u32]; 2] = [&[0, 1, 2, 3], &[0, 2, 4]];
    let result = triangulate_polygons(&positions, faces);
    assert_eq!(result.triangles, vec![[3, 0, 1], [1, 2, 3], [0, 2, 4]]);
    // A pentagon whose fan diagonals from corner 0 are both taken by other faces' sides: the
    // ears cut avoid them, and the disk is still a triangulation of it.
    let pentagon = vec![[0, 0], [4, 0], [5, 3], [2, 5], [-1, 3]];
    let mut positions: Vec<[f64; 3]> = pentagon.iter().map(|&p| embed(p, 0)).collect();
    positions.push([2.0, 2.0, 3.0]);
    let faces: [&[u32]; 3] = [&[0, 1, 2, 3, 4], &[0, 2, 5], &[0, 3, 5]];
    let result = triangulate_polygons(&positions, faces);
    assert_eq!(result.irregular, 0);
    let own: Vec<[u32; 3]> = result.triangles[..3].to_vec();
    check_triangulation(&pentagon, &own).unwrap();
    for t in &own {
        for d in [[0, 2], [0, 3]] {
            assert!(
                !(t.contains(&d[0]) && t.contains(&d[1])),
                "{t:?} cuts {d:?}"
            );
        }
    }
}

#[test]
fn two_quads_at_a_vertex_of_two_faces_cut_different_diagonals() {
    // Quads (0, 1, 2, 3) and (3, 4, 1, 0) share the sides 3–0 and 0–1 (vertex 0 is in these
    // two faces only) and the diagonal 1–3. Corners 3, 0, 4 are collinear, so the second quad
    // can only be cut along 1–3: the first must take its other diagonal, 0–2.
    let positions = [
        [4.5, 3.0, 0.0],
        [4.0, 2.5, 0.0],
        [3.5, 2.5, 0.0],
        [4.0, 3.0, 0.0],
        [5.0, 3.0, 0.0],
    ];
    let faces: [&[u32]; 2] = [&[0, 1, 2, 3], &[3, 4, 1, 0]];
    let result = triangulate_polygons(&positions, faces);
    assert_eq!(result.triangles[..2], [[0, 1, 2], [0, 2, 3]]);
    let mut seen = std::collections::HashSet::new();
    for t in &result.triangles {
        let [a, b, c] = t.map(|v| positions[v as usize]);
        assert!(!is_zero_area_triangle(a, b, c), "{t:?}");
        let mut key = *t;
        key.sort_unstable();
        assert!(seen.insert(key), "{t:?} twice");
    }
}

#[test]
fn quads_cut_into_a_duplicate_triangle_fall_back_to_their_fans() {
    use surftopo_mesh::{BuildError, triangulate_polygons_as_surface};
    // Two quads sharing the sides a–b and b–c (b in these two faces only), whose only cuts
    // without a flat triangle (corners a, b, d, e collinear) both make the triangle a b c.
    let [a, b, c, d, e] = [0u32, 1, 2, 3, 4];
    let positions = [
        [1.5, 5.0, 0.5],
        [1.5, 5.0, 1.0],
        [1.5, 4.5, 0.0],
        [1.5, 5.0, 0.0],
        [1.5, 5.0, 1.5],
    ];
    let faces: [&[u32]; 2] = [&[a, b, c, d], &[e, c, b, a]];
    let cut = triangulate_polygons(&positions, faces);
    let mut keys: Vec<[u32; 3]> = cut
        .triangles
        .iter()
        .map(|t| {
            let mut k = *t;
            k.sort_unstable();
            k
        })
        .collect();
    keys.sort_unstable();
    keys.dedup();
    assert_eq!(
        keys.len(),
        3,
        "the rule's cut repeats a triangle: {:?}",
        cut.triangles
    );
    let (fans, why) = triangulate_polygons_as_surface(&positions, faces);
    assert_eq!(
        fans.triangles,
        vec![[a, b, c], [a, c, d], [e, c, b], [e, b, a]]
    );
    assert_eq!(fans.face_of, vec![0, 0, 1, 1]);
    assert!(
        matches!(
            why,
            Some(BuildError::DuplicateFace {
                face: 1,
                duplicate_of: 0
            })
        ),
        "{why:?}"
    );
    // A mesh the rule cuts into a surface is returned as the rule cuts it.
    let square: [&[u32]; 1] = [&[0, 1, 2, 3]];
    let flat = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
    ];
    let (same, why) = triangulate_polygons_as_surface(&flat, square);
    assert_eq!((same, why), (triangulate_polygons(&flat, square), None));
}
