//! The quality measure, and the exact and fast quality pairings on mesh duals: every exact
//! result checked by the independent certificate verifier, the quads checked to form a closed
//! oriented manifold of the input's genus from adjacent input triangles, fast ≥ exact, exact ≤ the
//! cost of any other perfect pairing (KS, LRS's when on the input), determinism. Generated
//! families and a sample of the shared meshes in the default test; every shared mesh and larger
//! generated ones in the ignored release test.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_3, PI};

use surftopo_matching::weighted::{
    fast_min_cost_perfect_matching, min_cost_perfect_matching, verify_min_cost_perfect_matching,
};
use surftopo_mesh::Surface;
use surftopo_mesh::generators::{
    CavityBox, genus_surface, icosphere, random_flips, random_vertex_splits, shuffle_faces,
    subdivide_midpoint, tetrahedron, torus,
};
use surftopo_mesh::{EdgeId, SurfaceMesh};
use surftopo_quad::quality::{
    quad_corner_angles, quality_of_angles, space_corner_angles, space_quality_report,
};
use surftopo_quad::{QuadAlgorithm, pair_costs, quadrangulate, quality_report};
use surftopo_testkit::check_closed_oriented_manifold;

#[test]
fn quality_of_known_angles() {
    assert_eq!(quality_of_angles([FRAC_PI_2; 4]), 1.0);
    let rhombus = [2.0 * FRAC_PI_3, FRAC_PI_3, 2.0 * FRAC_PI_3, FRAC_PI_3];
    assert!((quality_of_angles(rhombus) - 2.0 / 3.0).abs() < 1e-12);
    assert_eq!(quality_of_angles([PI, FRAC_PI_2, FRAC_PI_2, 0.0]), 0.0);
    assert_eq!(
        quality_of_angles([1.2 * PI, 0.3 * PI, 0.2 * PI, 0.3 * PI]),
        0.0
    );
    assert_eq!(quality_of_angles([f64::NAN, 1.0, 1.0, 1.0]), 0.0);
}

/// A unit square split along its diagonal into two triangles (plus a far-away apex closing the
/// surface): the quad of the diagonal is the square.
#[test]
fn square_pair_has_quality_one_and_corners_sum_to_two_pi() {
    // Square 0-1-2-3 split by diagonal 0-2, closed by a pyramid apex 4 below it.
    let positions = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.5, 0.5, -3.0],
    ];
    let triangles = [
        [0, 1, 2],
        [0, 2, 3],
        [1, 0, 4],
        [2, 1, 4],
        [3, 2, 4],
        [0, 3, 4],
    ];
    let surface = Surface::from_triangles(positions, &triangles).unwrap();
    let mesh = &surface.mesh;
    let diagonal = mesh
        .edges()
        .find(|&e| {
            let mut v = mesh.edge_vertices(e).map(|v| v.0);
            v.sort_unstable();
            v == [0, 2]
        })
        .unwrap();
    let angles = quad_corner_angles(mesh, &surface.positions, diagonal);
    for a in angles {
        assert!((a - FRAC_PI_2).abs() < 1e-12, "{angles:?}");
    }
    let report = quality_report(mesh, &surface.positions, &[diagonal]);
    assert!((report.min - 1.0).abs() < 1e-12);
    assert_eq!(report.bad_quads_percent, 0.0);
    assert!(report.median_max_angle_deviation_degrees < 1e-9);
    for e in mesh.edges() {
        let sum: f64 = quad_corner_angles(mesh, &surface.positions, e).iter().sum();
        assert!(
            (sum - 2.0 * PI).abs() < 1e-9,
            "edge {e:?}: corners sum to {sum}"
        );
    }
    assert_eq!(pair_costs(mesh, &surface.positions)[diagonal.idx()], 0);
}

#[test]
fn space_corners_of_known_quads() {
    // Planar unit square: four right angles, quality 1.
    let square = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
    ];
    for a in space_corner_angles(square) {
        assert!((a - FRAC_PI_2).abs() < 1e-12);
    }
    // Planar dart with a reflex corner at p2 (interior 233.13°): in space the angle between
    // its two edge vectors is the other side, acos(−0.6) = 126.87°; the corners at p1 and p3
    // are atan(1/3), at p0 a right angle.
    let dart = [
        [0.0, 0.0, 0.0],
        [2.0, 0.0, 0.0],
        [0.5, 0.5, 0.0],
        [0.0, 2.0, 0.0],
    ];
    let angles = space_corner_angles(dart);
    let third = (1.0f64 / 3.0).atan();
    let expected = [FRAC_PI_2, third, (-0.6f64).acos(), third];
    for (a, e) in angles.iter().zip(expected) {
        assert!((a - e).abs() < 1e-12, "{angles:?}");
    }
    // A flat corner (p1 on segment p0 p2): 180°, a bad quad of quality 0.
    let flat = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [2.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
    ];
    let positions: Vec<_> = square.iter().chain(&flat).copied().collect();
    let report = space_quality_report(&positions, &[[0, 1, 2, 3], [4, 5, 6, 7]]);
    assert_eq!(report.quads, 2);
    assert_eq!(report.bad_quads_percent, 50.0);
    assert!(report.min.abs() < 1e-12 && (report.mean - 0.5).abs() < 1e-12);
    assert!(space_quality_report(&positions, &[]).quads == 0);
}

/// The quads `[a, d, b, c]` of the matched diagonals, checked independently: a closed oriented
/// manifold of the input's Euler characteristic in which every triangle is used once.
fn check_quads(name: &str, mesh: &SurfaceMesh, diagonals: &[u32]) {
    assert_eq!(2 * diagonals.len(), mesh.face_count(), "{name}: F/2 quads");
    let mut used = vec![false; mesh.face_slots()];
    let mut polygons = Vec::with_capacity(diagonals.len());
    for &e in diagonals {
        let h = EdgeId(e).halfedge();
        for f in [mesh.face(h), mesh.face(h.twin())] {
            assert!(!used[f.idx()], "{name}: triangle {f:?} in two quads");
            used[f.idx()] = true;
        }
        let (a, b) = (mesh.origin(h), mesh.dest(h));
        let (c, d) = (mesh.opposite_vertex(h), mesh.opposite_vertex(h.twin()));
        polygons.push(vec![a.0, d.0, b.0, c.0]);
    }
    let chi = check_closed_oriented_manifold(&polygons)
        .unwrap_or_else(|e| panic!("{name}: quads are not a closed oriented manifold: {e}"));
    assert_eq!(chi, mesh.euler_characteristic(), "{name}: genus kept");
}

/// Exact and fast quality pairings of one surface with every check; returns (exact, fast) costs.
fn check_surface(name: &str, surface: &Surface, deterministic: bool) -> (i64, i64) {
    let mesh = &surface.mesh;
    let costs = pair_costs(mesh, &surface.positions);
    let exact =
        min_cost_perfect_matching(mesh, &costs).unwrap_or_else(|e| panic!("{name}: exact: {e}"));
    let verified = verify_min_cost_perfect_matching(mesh, &costs, &exact.edges, &exact.certificate)
        .unwrap_or_else(|e| panic!("{name}: certificate rejected: {e}"));
    assert_eq!(verified, exact.cost, "{name}");
    check_quads(name, mesh, &exact.edges);
    let fast = fast_min_cost_perfect_matching(mesh, &costs)
        .unwrap_or_else(|e| panic!("{name}: fast: {e}"));
    check_quads(&format!("{name} fast"), mesh, &fast.edges);
    assert!(
        fast.cost >= exact.cost,
        "{name}: fast {} < exact {}",
        fast.cost,
        exact.cost
    );
    // Any other perfect pairing of the input costs at least the optimum.
    let ks = quadrangulate(mesh, QuadAlgorithm::KarpSipser).unwrap();
    let ks_cost: i64 = ks.diagonals.iter().map(|e| costs[e.idx()]).sum();
    assert!(
        ks_cost >= exact.cost,
        "{name}: KS {ks_cost} < exact {}",
        exact.cost
    );
    // The report over the optimum's quads: consistent with its cost.
    let diagonals: Vec<EdgeId> = exact.edges.iter().map(|&e| EdgeId(e)).collect();
    let report = quality_report(mesh, &surface.positions, &diagonals);
    let mean_from_cost = 1.0 - exact.cost as f64 / 1e9 / diagonals.len() as f64;
    assert!(
        (report.mean - mean_from_cost).abs() < 1e-6,
        "{name}: mean quality"
    );
    if deterministic {
        let again = min_cost_perfect_matching(mesh, &costs).unwrap();
        assert_eq!(again.edges, exact.edges, "{name}: exact deterministic");
        let fast_again = fast_min_cost_perfect_matching(mesh, &costs).unwrap();
        assert_eq!(fast_again.edges, fast.edges, "{name}: fast deterministic");
    }
    (exact.cost, fast.cost)
}

/// A named generator of a test surface.
type Maker = fn() -> Surface;

fn small_families() -> Vec<(String, Surface)> {
    let makers: [(&str, Maker); 7] = [
        ("tetrahedron", tetrahedron),
        ("icosphere0", || icosphere(0)),
        ("icosphere4", || icosphere(4)),
        ("torus3x3", || torus(3, 3)),
        ("torus40x11", || torus(40, 11)),
        ("cavities", || CavityBox::new(6, 3, 1, 1, 1, 1).generate()),
        ("genus45", || genus_surface(45, 1)),
    ];
    let mut out: Vec<(String, Surface)> = makers
        .iter()
        .map(|(name, make)| (name.to_string(), make()))
        .collect();
    // Irregular connectivity: each one with random flips, and with random vertex splits.
    let irregular: Vec<(String, Surface)> = out
        .iter()
        .flat_map(|(name, s)| {
            [
                (
                    format!("{name}+flips"),
                    random_flips(s, s.mesh.edge_count(), 7),
                ),
                (
                    format!("{name}+splits"),
                    random_vertex_splits(s, s.mesh.vertex_count(), 9),
                ),
            ]
        })
        .collect();
    out.extend(irregular);
    out.push((
        "genus7+flips+subdivided".into(),
        subdivide_midpoint(&random_flips(&genus_surface(7, 1), 500, 3), 1),
    ));
    out.push((
        "icosphere4+shuffled".into(),
        shuffle_faces(&icosphere(4), 4),
    ));
    out
}

#[test]
fn exact_and_fast_on_generated_families() {
    for (name, surface) in small_families() {
        check_surface(&name, &surface, true);
    }
}

surftopo_testkit::shared_mesh_tests!(exact_and_fast_on_a_sample_of_shared_meshes);

/// A sample of the shared meshes up to 50k triangles (every third, smallest first).
fn exact_and_fast_on_a_sample_of_shared_meshes() {
    for mesh in surftopo_testkit::shared_meshes_up_to(50_000)
        .iter()
        .step_by(3)
    {
        let surface = surftopo_testkit::load(mesh);
        check_surface(&mesh.file, &surface, false);
    }
}

/// Every shared mesh and larger generated families, high genus included (release:
/// `cargo test --release -p surftopo-quad --test quality -- --ignored`).
#[test]
#[ignore = "every shared mesh (needs SURFTOPO_MESHES) and large families: run in release"]
fn exact_and_fast_on_every_shared_mesh_and_large_families() {
    surftopo_testkit::require_shared_meshes();
    for mesh in surftopo_testkit::shared_meshes() {
        let surface = surftopo_testkit::load(&mesh);
        let (exact, fast) = check_surface(&mesh.file, &surface, true);
        eprintln!("{}: exact {exact} fast {fast}", mesh.file);
    }
    let large: Vec<(String, Surface)> = vec![
        ("icosphere7".into(), icosphere(7)),
        (
            "icosphere6+shuffled".into(),
            shuffle_faces(&icosphere(6), 4),
        ),
        ("genus200".into(), genus_surface(200, 1)),
        (
            "genus200+flips".into(),
            random_flips(&genus_surface(200, 1), 100_000, 5),
        ),
        (
            "genus45+subdivided2".into(),
            subdivide_midpoint(&genus_surface(45, 1), 2),
        ),
        (
            "cavity-box".into(),
            CavityBox::new(20, 10, 2, 2, 2, 2).generate(),
        ),
    ];
    for (name, surface) in large {
        let (exact, fast) = check_surface(&name, &surface, true);
        eprintln!("{name}: exact {exact} fast {fast}");
    }
}
