//! The shared real meshes (SURFTOPO_MESHES): every one up to 30k faces ends Delaunay (checked
//! independently), keeps its area and angle sums, and gets a well-formed Laplacian and
//! tessellation; random re-triangulations of a few are found isometric to them. Built without the
//! variable, these tests are ignored.

mod common;

use surftopo_intrinsic::generators::random_flips;
use surftopo_intrinsic::{
    DEFAULT_COCIRCULAR_TOLERANCE, DelaunayOptions, IntrinsicTriangulation, IsometryOptions,
    cotan_laplacian, delaunay_tessellation, flip_to_delaunay, isometric, lumped_mass,
};
use surftopo_testkit::{load, shared_meshes, shared_meshes_up_to};

fn triangulation(mesh: &surftopo_testkit::SharedMesh) -> IntrinsicTriangulation {
    let s = load(mesh);
    IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap()
}

surftopo_testkit::shared_mesh_tests!(
    shared_meshes_end_delaunay,
    random_retriangulations_of_shared_meshes_are_isometric
);

fn shared_meshes_end_delaunay() {
    let meshes = shared_meshes_up_to(30_000);
    assert!(!meshes.is_empty());
    for m in &meshes {
        let mut tri = triangulation(m);
        let area = common::area(&tri);
        let sums = common::angle_sums(&tri);
        let report = flip_to_delaunay(&mut tri, &DelaunayOptions::default())
            .unwrap_or_else(|e| panic!("{}: {e}", m.file));
        assert_eq!(report.non_delaunay_edges, 0, "{}", m.file);
        common::check_delaunay(&tri, 1e-8).unwrap_or_else(|e| panic!("{}: {e}", m.file));
        assert!(
            (common::area(&tri) - area).abs() <= 1e-9 * area,
            "{}",
            m.file
        );
        common::assert_same_angle_sums(&tri, &sums, 1e-7);
        assert_eq!(tri.mesh().genus(), m.genus);

        let l = cotan_laplacian(&tri);
        let mass = lumped_mass(&tri);
        let mut trace = 0.0;
        for i in 0..l.n {
            let (mut sum, mut scale) = (0.0f64, 0.0f64);
            for (j, v) in l.row(i) {
                sum += v;
                scale += v.abs();
                if j as usize != i {
                    // Intrinsic Delaunay weights are non-negative (off-diagonal entries <= 0).
                    assert!(v <= 1e-8 * scale.max(1.0), "{}: L[{i}][{j}] = {v}", m.file);
                }
            }
            assert!(
                sum.abs() <= 1e-10 * scale,
                "{}: row {i} sums to {sum}",
                m.file
            );
            trace += mass.get(i, i);
        }
        assert!((trace - area).abs() <= 1e-9 * area, "{}", m.file);

        let t = delaunay_tessellation(&tri, DEFAULT_COCIRCULAR_TOLERANCE);
        t.portalgon.check_closed().unwrap();
        assert_eq!(t.portalgon.vertex_classes().1, tri.mesh().vertex_count());
        assert!(
            (t.portalgon.area() - area).abs() <= 1e-8 * area,
            "{}",
            m.file
        );
        eprintln!(
            "{}: {} faces, {} flips, {} tessellation polygons",
            m.file,
            m.faces,
            report.flips,
            t.portalgon.polygon_count()
        );
    }
}

fn random_retriangulations_of_shared_meshes_are_isometric() {
    let wanted = [
        "fandisk.obj.gz",
        "spot.obj.gz",
        "torus_288.off.gz",
        "sledge.off.gz",
    ];
    let meshes: Vec<_> = shared_meshes()
        .into_iter()
        .filter(|m| wanted.contains(&m.file.as_str()))
        .collect();
    assert_eq!(meshes.len(), wanted.len(), "missing shared meshes");
    for m in &meshes {
        let a = triangulation(m);
        let mut b = a.clone();
        let flips = random_flips(&mut b, a.mesh().edge_count() as u64, 17);
        assert!(flips > 0);
        let outcome = isometric(a.clone(), b, &IsometryOptions::default())
            .unwrap_or_else(|e| panic!("{}: {e}", m.file));
        assert!(outcome.is_isometric(), "{}: {outcome}", m.file);
        // Stretching the surface a little is noticed.
        let (mesh, mut lengths) = a.clone().into_parts();
        for l in lengths.iter_mut().take(1) {
            *l *= 1.0 + 1e-4;
        }
        let c = IntrinsicTriangulation::from_parts(mesh, lengths).unwrap();
        let outcome = isometric(a, c, &IsometryOptions::default())
            .unwrap_or_else(|e| panic!("{}: {e}", m.file));
        assert!(!outcome.is_isometric(), "{}: {outcome}", m.file);
    }
}
