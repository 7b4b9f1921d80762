//! The isometry test on every surface kind `generate` makes: boundary loops, non-orientable
//! pieces, several pieces. Each isometric verdict is checked by code written without the
//! comparison's: the side correspondence it returns maps every side to one of the same length
//! and boundary mark, glued sides to glued sides with the sense rule, and every polygon onto its
//! image with the same distances between all pairs of corners (so a rigid motion lays one on
//! the other).

mod common;

use common::jitter;
use surftopo_intrinsic::{
    CoveredTriangulation, IsometryDecision, IsometryOptions, TwistedMap, compare_twisted,
    decide_isometry, decide_isometry_on_cover, piece_tessellations,
};
use surftopo_mesh::CoveredSurface;
use surftopo_mesh::generators::{
    annulus, copies, crosscaps, cut_holes, disk, icosphere, klein_bottle, mobius_band,
    projective_plane, subdivide_midpoint_covered, torus,
};
use surftopo_mesh::geometry::Point3;

/// The surface with positions mapped by `f`.
fn moved(s: &CoveredSurface, f: impl Fn(Point3) -> Point3) -> CoveredSurface {
    let (positions, triangles) = s.to_triangles();
    let positions = positions.into_iter().map(f).collect();
    CoveredSurface::from_triangles(positions, &triangles)
        .expect("a moved surface is a surface")
        .0
}

/// The pieces of `parts` side by side, in this order, as one surface.
fn side_by_side(parts: &[&CoveredSurface]) -> CoveredSurface {
    let (mut positions, mut triangles) = (Vec::new(), Vec::new());
    for (k, part) in parts.iter().enumerate() {
        let (p, t) = part.to_triangles();
        let offset = positions.len() as u32;
        positions.extend(p.into_iter().map(|x| [x[0] + 10.0 * k as f64, x[1], x[2]]));
        triangles.extend(t.into_iter().map(|f| f.map(|v| v + offset)));
    }
    CoveredSurface::from_triangles(positions, &triangles)
        .expect("pieces side by side are a surface")
        .0
}

fn covered(s: &CoveredSurface) -> CoveredTriangulation {
    CoveredTriangulation::from_cover(&s.cover, &s.positions).expect("finite lengths")
}

/// Every kind, small, jittered so that no vertex is flat.
fn kinds() -> Vec<(&'static str, CoveredSurface)> {
    let sphere: CoveredSurface = icosphere(2).into();
    let torus: CoveredSurface = torus(8, 5).into();
    vec![
        ("disk", jitter(disk(5), 0.05, 1)),
        ("annulus", jitter(annulus(9, 3), 0.1, 2)),
        ("mobius band", jitter(mobius_band(9, 3), 0.1, 3)),
        (
            "projective plane",
            jitter(subdivide_midpoint_covered(&projective_plane(), 1), 0.05, 4),
        ),
        ("klein bottle", jitter(klein_bottle(8, 6), 0.1, 5)),
        ("N3", jitter(crosscaps(3), 0.05, 6)),
        (
            "sphere with holes",
            jitter(cut_holes(&sphere, 3, 11).0, 0.02, 7),
        ),
        (
            "torus with holes",
            jitter(cut_holes(&torus, 2, 1).0, 0.02, 8),
        ),
        (
            "three pieces",
            copies(&jitter(mobius_band(7, 2), 0.1, 9), 3),
        ),
        ("two spheres", copies(&jitter(sphere, 0.03, 10), 2)),
    ]
}

fn decide(a: &CoveredTriangulation, b: &CoveredTriangulation) -> IsometryDecision {
    decide_isometry_on_cover(a, b, &IsometryOptions::default()).expect("valid surfaces")
}

/// The sides of a polygon after `s`, cyclically.
fn next_side(m: &TwistedMap, s: u32) -> u32 {
    let r = m.polygon_sides(m.polygon_of(s));
    if s + 1 == r.end { r.start } else { s + 1 }
}

fn distance(p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

/// Checks a side correspondence `image` from `a` to `b` without the comparison's code (see the
/// module doc); `tol` absolute.
fn check_correspondence(a: &TwistedMap, b: &TwistedMap, image: &[u32], tol: f64) {
    assert_eq!(image.len(), a.side_count());
    let mut hit = vec![false; b.side_count()];
    for &t in image {
        assert!(!hit[t as usize], "side {t} of the second is hit twice");
        hit[t as usize] = true;
    }
    // Each polygon's sides go to one polygon's, cyclically forwards (+1) or backwards (-1).
    let mut sense = vec![0i8; a.polygon_count()];
    for p in 0..a.polygon_count() as u32 {
        let sides: Vec<u32> = a.polygon_sides(p).collect();
        let q = b.polygon_of(image[sides[0] as usize]);
        let forwards =
            next_side(b, image[sides[0] as usize]) == image[sides[1 % sides.len()] as usize];
        sense[p as usize] = if forwards { 1 } else { -1 };
        for (k, &s) in sides.iter().enumerate() {
            let t = image[s as usize];
            assert_eq!(b.polygon_of(t), q, "polygon {p} is split");
            let after = image[sides[(k + 1) % sides.len()] as usize];
            let (from, to) = if forwards { (t, after) } else { (after, t) };
            assert_eq!(next_side(b, from), to, "polygon {p}: sides out of order");
            assert!(
                (a.side_length(s) - b.side_length(t)).abs() <= tol,
                "side {s}: lengths"
            );
        }
        // Corners: side s starts at corner(s); its image starts (forwards) or ends (backwards)
        // at the image corner. All pairwise distances agree.
        let corner_image = |s: u32| {
            let t = image[s as usize];
            if forwards {
                b.corner(t)
            } else {
                b.corner(next_side(b, t))
            }
        };
        for &s in &sides {
            for &u in &sides {
                let da = distance(a.corner(s), a.corner(u));
                let db = distance(corner_image(s), corner_image(u));
                assert!(
                    (da - db).abs() <= 4.0 * tol,
                    "polygon {p}: corners {s}, {u}: {da} vs {db}"
                );
            }
        }
    }
    // Gluings: glued sides go to glued sides; the sense changes once per reversed gluing.
    for s in 0..a.side_count() as u32 {
        let t = image[s as usize];
        match (a.mate(s), b.mate(t)) {
            (None, None) => {}
            (Some((m, ra)), Some((n, rb))) => {
                assert_eq!(
                    image[m as usize], n,
                    "side {s}: its mate's image is not glued to its image"
                );
                let (p, q) = (a.polygon_of(s), a.polygon_of(m));
                let flip = (sense[p as usize] != sense[q as usize]) as u8;
                assert_eq!(
                    flip,
                    ra as u8 ^ rb as u8,
                    "side {s}: sense across the gluing"
                );
            }
            _ => panic!("side {s}: boundary against interior"),
        }
    }
}

/// When `decision` says isometric, pairs the pieces of `a` and `b` (in order, or by trying each
/// for several) and checks a correspondence of each pair independently.
fn check_isometric(a: &CoveredTriangulation, b: &CoveredTriangulation) {
    let options = IsometryOptions::default();
    let (ma, mb) = (
        piece_tessellations(a, &options).unwrap(),
        piece_tessellations(b, &options).unwrap(),
    );
    assert_eq!(ma.len(), mb.len());
    let mut used = vec![false; mb.len()];
    for x in &ma {
        let (j, found) = (0..mb.len())
            .filter(|&j| !used[j])
            .find_map(|j| {
                compare_twisted(x, &mb[j], options.length_tolerance, true)
                    .ok()
                    .map(|f| (j, f))
            })
            .expect("every piece of the first has an isometric piece in the second");
        used[j] = true;
        let longest = (0..x.side_count() as u32)
            .map(|s| x.side_length(s))
            .fold(0.0, f64::max);
        check_correspondence(x, &mb[j], &found.image, 1e-6 * longest);
    }
}

fn assert_isometric(name: &str, a: &CoveredTriangulation, b: &CoveredTriangulation) {
    let d = decide(a, b);
    assert!(matches!(d, IsometryDecision::Isometric(_)), "{name}: {d}");
    check_isometric(a, b);
}

fn assert_not_isometric(name: &str, a: &CoveredTriangulation, b: &CoveredTriangulation, why: &str) {
    let d = decide(a, b);
    match &d {
        IsometryDecision::NotIsometric(reason) => {
            assert!(reason.contains(why), "{name}: {reason} (expected {why:?})")
        }
        other => panic!("{name}: {other}"),
    }
}

#[test]
fn every_kind_is_isometric_to_its_intrinsic_flips() {
    for (name, s) in kinds() {
        let a = covered(&s);
        let mut b = a.clone();
        let flips = b.random_flips(200, 17);
        assert!(flips > 20, "{name}: {flips} flips");
        assert_ne!(a, b, "{name}");
        assert_isometric(name, &a, &b);
    }
}

#[test]
fn every_kind_is_isometric_to_its_mirror_image() {
    for (name, s) in kinds() {
        let mirror = moved(&s, |p| [-p[0], p[1], p[2]]);
        assert_isometric(name, &covered(&s), &covered(&mirror));
    }
}

#[test]
fn scaled_and_perturbed_copies_are_not_isometric_with_a_proof() {
    for (name, s) in kinds() {
        let a = covered(&s);
        let scaled = covered(&moved(&s, |p| p.map(|x| 1.001 * x)));
        assert_not_isometric(name, &a, &scaled, "areas");
        // One vertex moved off the surface: the area of its triangles changes.
        let (mut positions, triangles) = s.to_triangles();
        let v = triangles[0][0] as usize;
        positions[v][2] += 0.05;
        let bumped = CoveredSurface::from_triangles(positions, &triangles)
            .unwrap()
            .0;
        let d = decide(&a, &covered(&bumped));
        assert!(
            matches!(d, IsometryDecision::NotIsometric(_)),
            "{name}: {d}"
        );
    }
}

#[test]
fn pieces_in_swapped_order_are_isometric() {
    let band = jitter(mobius_band(7, 2), 0.1, 21);
    let ring = jitter(annulus(8, 2), 0.1, 22);
    let bottle = jitter(klein_bottle(6, 4), 0.1, 23);
    let a = covered(&side_by_side(&[&band, &ring, &bottle]));
    let b = covered(&side_by_side(&[&bottle, &band, &ring]));
    assert_isometric("swapped pieces", &a, &b);
    // The same pieces but one mirrored and one re-flipped.
    let mut c = covered(&side_by_side(&[
        &ring,
        &moved(&bottle, |p| [p[0], -p[1], p[2]]),
        &band,
    ]));
    c.random_flips(100, 3);
    assert_isometric("swapped, mirrored, flipped", &a, &c);
}

#[test]
fn pieces_of_different_kinds_or_counts_are_not_isometric() {
    let band = jitter(mobius_band(7, 2), 0.1, 31);
    let ring = jitter(annulus(8, 2), 0.1, 32);
    let a = covered(&side_by_side(&[&band, &ring]));
    let b = covered(&side_by_side(&[&band, &band]));
    assert_not_isometric("kinds", &a, &b, "different surfaces");
    let c = covered(&side_by_side(&[&band, &ring, &ring]));
    assert_not_isometric("counts", &a, &c, "connected pieces");
}

#[test]
fn a_different_boundary_length_is_not_isometric() {
    // A cylinder of radius 1 and height 1 against one of radius 2 and height 1/2: the same
    // area, boundary loops twice as long.
    let thin = annulus(12, 3);
    let wide = moved(&thin, |p| [2.0 * p[0], 2.0 * p[1], 0.5 * p[2]]);
    assert_not_isometric(
        "cylinders",
        &covered(&thin),
        &covered(&wide),
        "boundary loops",
    );
    // As one piece among others.
    let disk = jitter(disk(4), 0.05, 41);
    let a = covered(&side_by_side(&[&disk, &thin]));
    let b = covered(&side_by_side(&[&wide, &disk]));
    assert_not_isometric("with a disk", &a, &b, "boundary loops");
}

/// A flat `m x n` strip of unit squares (each cut along a diagonal) glued end to end, straight
/// (an annulus) or with a half twist (a Möbius band): every triangle has sides 1, 1, √2.
fn flat_strip(m: u32, n: u32, twisted: bool) -> CoveredTriangulation {
    let id = |i: u32, j: u32| {
        if i == m {
            if twisted { n - j } else { j }
        } else {
            i * (n + 1) + j
        }
    };
    let mut triangles = Vec::new();
    for i in 0..m {
        for j in 0..n {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    let positions = vec![[0.0; 3]; (m * (n + 1)) as usize];
    let s = CoveredSurface::from_triangles(positions, &triangles)
        .unwrap()
        .0;
    // A vertex's places in the strip: (i, j), and (m, j') for i = 0.
    let places = |v: u32| {
        let (i, j) = ((v / (n + 1)) as f64, (v % (n + 1)) as f64);
        let mut p = vec![[i, j]];
        if i == 0.0 {
            p.push([m as f64, if twisted { n as f64 - j } else { j }]);
        }
        p
    };
    CoveredTriangulation::from_cover_lengths(&s.cover, |a, b| {
        let mut best = f64::INFINITY;
        for p in places(a) {
            for q in places(b) {
                best = best.min((p[0] - q[0]).hypot(p[1] - q[1]));
            }
        }
        best
    })
    .unwrap()
}

#[test]
fn a_mobius_band_is_not_an_annulus_with_the_same_triangles() {
    let (band, ring) = (flat_strip(7, 2, true), flat_strip(7, 2, false));
    assert_not_isometric("flat strips", &band, &ring, "different surfaces");
    // Each against its own intrinsic flips (every vertex flat: the vertices are kept).
    for strip in [band, ring] {
        let mut flipped = strip.clone();
        assert!(flipped.random_flips(60, 5) > 10);
        assert_isometric("flat strip", &strip, &flipped);
    }
}

#[test]
fn flat_vertices_make_a_difference_undecidable_rather_than_a_proof() {
    // The unit square with an interior vertex moved inside the plane: the same square
    // (isometric), but the flat vertex sets differ; the answer must not be "not isometric".
    let square = disk(4);
    let (mut positions, triangles) = square.to_triangles();
    let centre = positions
        .iter()
        .position(|p| (p[0] - 0.5).abs() < 1e-9 && (p[1] - 0.5).abs() < 1e-9)
        .unwrap();
    positions[centre][0] += 0.05;
    let moved_centre = CoveredSurface::from_triangles(positions, &triangles)
        .unwrap()
        .0;
    let d = decide(&covered(&square), &covered(&moved_centre));
    assert!(matches!(d, IsometryDecision::Undecided(_)), "{d}");
    assert!(d.to_string().contains("flat"), "{d}");
}

#[test]
fn closed_orientable_surfaces_agree_with_the_closed_test() {
    let sphere: CoveredSurface = jitter(icosphere(2).into(), 0.03, 51);
    let a = covered(&sphere);
    let mut b = a.clone();
    b.random_flips(150, 9);
    assert_isometric("sphere", &a, &b);
    let closed = |t: &CoveredTriangulation| t.cover().clone();
    let old = decide_isometry(&closed(&a), &closed(&b), &IsometryOptions::default()).unwrap();
    assert!(old.is_isometric(), "{old}");
    let bigger = covered(&moved(&sphere, |p| p.map(|x| 1.01 * x)));
    let old = decide_isometry(&closed(&a), &closed(&bigger), &IsometryOptions::default()).unwrap();
    assert!(matches!(old, IsometryDecision::NotIsometric(_)));
    assert_not_isometric("bigger sphere", &a, &bigger, "areas");
}

/// The area of a surface in space, from its triangles' positions.
fn area_in_space(s: &CoveredSurface) -> f64 {
    let (p, triangles) = s.to_triangles();
    triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|v| p[v as usize]);
            let (u, w) = (
                [b[0] - a[0], b[1] - a[1], b[2] - a[2]],
                [c[0] - a[0], c[1] - a[1], c[2] - a[2]],
            );
            let n = [
                u[1] * w[2] - u[2] * w[1],
                u[2] * w[0] - u[0] * w[2],
                u[0] * w[1] - u[1] * w[0],
            ];
            0.5 * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt()
        })
        .sum()
}

#[test]
fn closed_non_orientable_surfaces_of_equal_area_are_told_apart_by_their_tessellations() {
    let shapes = [
        (
            "projective plane",
            subdivide_midpoint_covered(&projective_plane(), 1),
            0.05,
        ),
        ("klein bottle", klein_bottle(8, 6), 0.1),
        ("N3", crosscaps(3), 0.05),
    ];
    for (name, shape, amount) in shapes {
        let a = jitter(shape.clone(), amount, 61);
        let b = jitter(shape, amount, 62);
        // The second scaled to the first's area: no invariant tells them apart.
        let k = (area_in_space(&a) / area_in_space(&b)).sqrt();
        let b = moved(&b, |p| p.map(|x| k * x));
        let d = decide(&covered(&a), &covered(&b));
        match &d {
            IsometryDecision::NotIsometric(reason) => {
                assert!(
                    reason.contains("tessellations") || reason.contains("sides"),
                    "{name}: {reason}"
                )
            }
            other => panic!("{name}: {other}"),
        }
    }
}
