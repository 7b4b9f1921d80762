//! Flat vertex removal and the isometry test (Corollary 2).

mod common;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::TAU;
use surftopo_intrinsic::generators::{flat_torus, random_flips};
use surftopo_intrinsic::{
    DEFAULT_ANGLE_TOLERANCE, DelaunayOptions, IntrinsicTriangulation, IsometryOptions, Outcome,
    canonical_tessellation, isometric, remove_flat_vertices,
};
use surftopo_mesh::Surface;
use surftopo_mesh::generators::{icosphere, torus};

fn tri_of(positions: &[[f64; 3]], triangles: &[[u32; 3]]) -> IntrinsicTriangulation {
    IntrinsicTriangulation::from_soup(positions, triangles)
        .unwrap()
        .0
}

/// An icosphere with every vertex moved radially at random: a chiral surface with no symmetry.
fn bumpy_sphere(seed: u64) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let s = icosphere(2);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let positions: Vec<[f64; 3]> = s
        .positions
        .iter()
        .map(|p| {
            let r = 1.0 + rng.random_range(-0.1..0.1);
            p.map(|c| c * r)
        })
        .collect();
    let (_, triangles) = Surface {
        mesh: s.mesh,
        positions: positions.clone(),
    }
    .to_triangles();
    (positions, triangles)
}

fn cube_subdivided() -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    // Unit cube with a vertex at the centre of each face (flat, degree 4).
    let (mut positions, quads) = surftopo_testkit::unit_cube();
    let mut triangles = Vec::new();
    for q in quads {
        let c = positions.len() as u32;
        let centre =
            [0, 1, 2].map(|k| q.iter().map(|&v| positions[v as usize][k]).sum::<f64>() / 4.0);
        positions.push(centre);
        for i in 0..4 {
            triangles.push([q[i], q[(i + 1) % 4], c]);
        }
    }
    (positions, triangles)
}

#[test]
fn flat_vertices_are_removed_keeping_the_surface() {
    let (positions, triangles) = cube_subdivided();
    let mut tri = tri_of(&positions, &triangles);
    let area = common::area(&tri);
    let sums = common::angle_sums(&tri);
    let report = remove_flat_vertices(&mut tri, DEFAULT_ANGLE_TOLERANCE).unwrap();
    assert_eq!(report.removed, 6);
    assert_eq!(report.kept_flat, None);
    let m = tri.mesh();
    m.check_invariants().unwrap();
    assert_eq!(
        (m.vertex_count(), m.edge_count(), m.face_count()),
        (8, 18, 12)
    );
    tri.validate().unwrap();
    assert!((common::area(&tri) - area).abs() < 1e-12);
    common::assert_same_angle_sums(&tri, &sums, 1e-9);
    for v in m.vertices() {
        assert!((sums[v.idx()] - 1.5 * std::f64::consts::PI).abs() < 1e-12);
    }
    // A flat torus keeps exactly one vertex.
    let mut tri = flat_torus(3.5, 4).unwrap();
    let report = remove_flat_vertices(&mut tri, DEFAULT_ANGLE_TOLERANCE).unwrap();
    assert_eq!(report.removed, 15);
    assert!(report.kept_flat.is_some());
    let m = tri.mesh();
    assert_eq!(
        (m.vertex_count(), m.edge_count(), m.face_count()),
        (1, 3, 2)
    );
    assert!((common::area(&tri) - 2.0).abs() < 1e-9);
    let sums = common::angle_sums(&tri);
    let v = m.vertices().next().unwrap();
    assert!((sums[v.idx()] - TAU).abs() < 1e-9);
    // Nothing to do on a sphere without flat vertices.
    let (p, t) = bumpy_sphere(1);
    let mut tri = tri_of(&p, &t);
    let before = tri.clone();
    assert_eq!(
        remove_flat_vertices(&mut tri, DEFAULT_ANGLE_TOLERANCE)
            .unwrap()
            .removed,
        0
    );
    assert_eq!(tri, before);
}

#[test]
fn random_flips_are_isometric() {
    let (p, t) = bumpy_sphere(2);
    let a = tri_of(&p, &t);
    let mut b = a.clone();
    assert!(random_flips(&mut b, 2000, 5) > 500);
    let outcome = isometric(a, b, &IsometryOptions::default()).unwrap();
    assert!(
        matches!(
            outcome,
            Outcome::Isometric {
                reflected: false,
                ..
            }
        ),
        "{outcome}"
    );
    // Also on a torus, flipped twice independently.
    let s = torus(10, 6);
    let mut a = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap();
    let mut b = a.clone();
    random_flips(&mut a, 300, 1);
    random_flips(&mut b, 300, 2);
    assert!(
        isometric(a, b, &IsometryOptions::default())
            .unwrap()
            .is_isometric()
    );
}

#[test]
fn small_metric_changes_are_not_isometric() {
    let (p, t) = bumpy_sphere(3);
    let a = tri_of(&p, &t);
    for (vertex, amount) in [(0usize, 1e-3), (17, 1e-4), (100, 1e-5)] {
        let mut q = p.clone();
        q[vertex] = q[vertex].map(|c| c * (1.0 + amount));
        let mut b = tri_of(&q, &t);
        random_flips(&mut b, 1000, 9);
        let outcome = isometric(a.clone(), b, &IsometryOptions::default()).unwrap();
        assert!(!outcome.is_isometric(), "moved by {amount}: {outcome}");
    }
    // Different combinatorics altogether.
    let (s, u) = (torus(8, 5), torus(8, 6));
    let a = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap();
    let b = IntrinsicTriangulation::from_positions(u.mesh, &u.positions).unwrap();
    assert!(matches!(
        isometric(a, b, &IsometryOptions::default()).unwrap(),
        Outcome::Counts { .. }
    ));
}

#[test]
fn mirror_images_are_isometric_by_a_reflection() {
    let (p, t) = bumpy_sphere(4);
    let a = tri_of(&p, &t);
    let q: Vec<[f64; 3]> = p.iter().map(|x| [-x[0], x[1], x[2]]).collect();
    let reversed: Vec<[u32; 3]> = t.iter().map(|&[x, y, z]| [x, z, y]).collect();
    let b = tri_of(&q, &reversed);
    let outcome = isometric(a.clone(), b.clone(), &IsometryOptions::default()).unwrap();
    assert!(
        matches!(
            outcome,
            Outcome::Isometric {
                reflected: true,
                ..
            }
        ),
        "{outcome}"
    );
    let strict = IsometryOptions {
        allow_reflection: false,
        ..IsometryOptions::default()
    };
    assert!(!isometric(a, b, &strict).unwrap().is_isometric());
}

#[test]
fn flat_vertices_do_not_matter() {
    // A cube and the cube with flat vertices added are the same surface.
    let (positions, triangles) = cube_subdivided();
    let subdivided = tri_of(&positions, &triangles);
    let plain = tri_of(
        &positions[..8],
        &[
            [0, 2, 3],
            [0, 3, 1],
            [4, 5, 7],
            [4, 7, 6],
            [0, 1, 5],
            [0, 5, 4],
            [2, 6, 7],
            [2, 7, 3],
            [0, 4, 6],
            [0, 6, 2],
            [1, 3, 7],
            [1, 7, 5],
        ],
    );
    let outcome = isometric(plain, subdivided, &IsometryOptions::default()).unwrap();
    assert!(outcome.is_isometric(), "{outcome}");
    // A bumpy sphere with a face split at its centroid.
    let (p, t) = bumpy_sphere(5);
    let mut q = p.clone();
    let [x, y, z] = t[10];
    q.push([0, 1, 2].map(|k| (p[x as usize][k] + p[y as usize][k] + p[z as usize][k]) / 3.0));
    let c = (q.len() - 1) as u32;
    let mut u = t.clone();
    u[10] = [x, y, c];
    u.extend([[y, z, c], [z, x, c]]);
    let outcome = isometric(tri_of(&p, &t), tri_of(&q, &u), &IsometryOptions::default()).unwrap();
    assert!(outcome.is_isometric(), "{outcome}");
}

#[test]
fn flat_tori_t_x_with_integer_x_are_all_the_same_torus() {
    let opts = IsometryOptions::default();
    let same = isometric(
        flat_torus(3.0, 1).unwrap(),
        flat_torus(7.0, 1).unwrap(),
        &opts,
    )
    .unwrap();
    assert!(same.is_isometric(), "{same}");
    let refined = isometric(
        flat_torus(3.0, 3).unwrap(),
        flat_torus(2.0, 1).unwrap(),
        &opts,
    )
    .unwrap();
    assert!(refined.is_isometric(), "{refined}");
    let different = isometric(
        flat_torus(3.0, 1).unwrap(),
        flat_torus(3.5, 1).unwrap(),
        &opts,
    )
    .unwrap();
    assert!(!different.is_isometric(), "{different}");
    // The canonical tessellation of an integer T_x is the 1 x 2 rectangle.
    let p = canonical_tessellation(flat_torus(6.0, 2).unwrap(), &opts, 0).unwrap();
    assert_eq!(
        (p.polygon_count(), p.side_count(), p.vertex_classes().1),
        (1, 4, 1)
    );
}

#[test]
fn delaunay_failures_are_reported_per_surface() {
    let opts = IsometryOptions {
        delaunay: DelaunayOptions {
            max_flips: Some(3),
            ..DelaunayOptions::default()
        },
        ..IsometryOptions::default()
    };
    let err = isometric(
        flat_torus(2.0, 1).unwrap(),
        flat_torus(50.0, 1).unwrap(),
        &opts,
    )
    .unwrap_err();
    assert!(matches!(
        err,
        surftopo_intrinsic::IsometryError::Delaunay { surface: 1, .. }
    ));
}

#[test]
fn delete_vertices_then_insert_edges_on_the_portalgon() {
    // The paper's DELETEVERTICES + INSERTEDGES on a portalgon: delete the six flat face centres
    // of the subdivided cube, cut the squares left along shortcuts, and get a cube back.
    let (positions, triangles) = cube_subdivided();
    let tri = tri_of(&positions, &triangles);
    let (mut p, _) = tri.to_portalgon();
    let area = p.area();
    // A cube corner (angle 3π/2) cannot be deleted.
    let corner = p.sides().find(|&s| p.vertex_label(s) == Some(0)).unwrap();
    let mut q = p.clone();
    assert!(matches!(
        q.delete_vertex(corner, 1e-9),
        Err(surftopo_intrinsic::PortalgonError::NotFlat { .. })
    ));
    for centre in 8..14 {
        let s = p
            .sides()
            .find(|&s| p.vertex_label(s) == Some(centre))
            .unwrap();
        let square = p.delete_vertex(s, 1e-9).unwrap();
        assert_eq!(p.polygon_sides(square).len(), 4);
        for &x in p.polygon_sides(square) {
            assert!((p.side_length(x) - 1.0).abs() < 1e-12);
            assert_ne!(p.vertex_label(x), Some(centre));
        }
        let pieces = p.triangulate_by_shortcuts(square).unwrap();
        assert_eq!(pieces.len(), 2);
    }
    assert_eq!((p.polygon_count(), p.side_count()), (12, 36));
    assert!((p.area() - area).abs() < 1e-12);
    p.check_closed().unwrap();
    // Labels 0..8 remain on the corners: reading back gives the cube with the same vertex ids.
    let cube = IntrinsicTriangulation::from_portalgon(&p, 1e-9).unwrap();
    let m = cube.mesh();
    assert_eq!(
        (m.vertex_count(), m.edge_count(), m.face_count()),
        (8, 18, 12)
    );
    let sums = common::angle_sums(&cube);
    assert!(
        sums.iter()
            .all(|s| (s - 1.5 * std::f64::consts::PI).abs() < 1e-12)
    );
    let plain = tri_of(&positions, &triangles);
    assert!(
        isometric(cube, plain, &IsometryOptions::default())
            .unwrap()
            .is_isometric()
    );
}

#[test]
fn reasons_say_in_words_which_polygon_or_length_differs() {
    let (p, t) = bumpy_sphere(2);
    let a = tri_of(&p, &t);
    let mut b = a.clone();
    random_flips(&mut b, 500, 3);
    let same = isometric(a.clone(), b, &IsometryOptions::default()).unwrap();
    let text = same.reason();
    assert!(same.is_isometric(), "{text}");
    assert!(
        text.contains("lays polygon") && text.contains("of the first, a "),
        "{text}"
    );
    let mut q = p.clone();
    q[17] = q[17].map(|c| c * (1.0 + 1e-3));
    let moved = isometric(a, tri_of(&q, &t), &IsometryOptions::default()).unwrap();
    let text = moved.reason();
    assert!(!moved.is_isometric(), "{text}");
    // Whichever invariant catches it, the reason names a length, a polygon kind or the sizes.
    let words = match &moved {
        Outcome::Lengths { .. } => "the edge lengths differ",
        Outcome::NoCandidate { .. } => "no triangle of the second has a side of that length",
        Outcome::NoCorrespondence { .. } => "does not lie on polygon",
        Outcome::Counts { .. } => "differ in size",
        Outcome::PolygonSizes { .. } => "the canonical Delaunay tessellations have",
        Outcome::Isometric { .. } => unreachable!(),
    };
    assert!(text.contains(words), "{text}");
    let (s, u) = (torus(8, 5), torus(8, 6));
    let a = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap();
    let b = IntrinsicTriangulation::from_positions(u.mesh, &u.positions).unwrap();
    let text = isometric(a, b, &IsometryOptions::default())
        .unwrap()
        .reason();
    assert!(
        text.contains("differ in size: ") && text.contains(" edges, "),
        "{text}"
    );
}
