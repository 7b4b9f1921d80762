//! All three algorithms on every mesh of $SURFTOPO_MESHES (mandatory when the variable is set; the
//! largest, igea, has 268,686 triangles), each result checked by `support::verify`, including the
//! forward replay of every contraction.

mod support;

use support::{all_algorithms, run_and_verify};
use surftopo_irreducible::{Algorithm, is_irreducible_surface, reduce_surface};
use surftopo_mesh::CoveredSurface;
use surftopo_testkit::classify_surface;

surftopo_testkit::shared_mesh_tests!(every_shared_mesh, shared_meshes_with_holes);

fn every_shared_mesh() {
    let meshes = surftopo_testkit::shared_meshes();
    assert_eq!(meshes.len(), 47, "expected the 47 shared meshes");
    for (i, shared) in meshes.iter().enumerate() {
        let mesh = surftopo_testkit::load(shared).mesh;
        let path = &shared.path;
        let genus = mesh.genus();
        for a in all_algorithms(i as u64) {
            let red = run_and_verify(&mesh, a, true);
            eprintln!(
                "{:28} g={genus:2} {:9} V {} -> {}, ℓ {} ε {}",
                path.file_name().unwrap_or_default().to_string_lossy(),
                a.name(),
                mesh.vertex_count(),
                red.mesh.vertex_count(),
                red.counters.link_tests,
                red.counters.edges_tested_more_than_once,
            );
            if a == Algorithm::RamaswamiSiqueira && genus == 0 {
                let first = mesh.vertices().next().expect("a vertex");
                assert!(red.history.iter().all(|r| r.kept() == first), "Section 4.6");
            }
        }
    }
}

/// Open real meshes: holes cut into every shared mesh of at most 30,000 faces (five each, where
/// they fit), each reduced by the three algorithms; the output checked independently (the
/// pieces' χ, orientability and boundary loops; Dey et al.'s rule on its triangles).
fn shared_meshes_with_holes() {
    surftopo_testkit::require_shared_meshes();
    let meshes = surftopo_testkit::shared_meshes_up_to(30_000);
    assert!(meshes.len() >= 20, "expected the small shared meshes");
    for (i, shared) in meshes.iter().enumerate() {
        let surface: CoveredSurface = surftopo_testkit::load(shared).into();
        let (open, cut) = surftopo_mesh::generators::cut_holes(&surface, 5, i as u64);
        assert!(cut > 0, "{}: no hole fits", shared.file);
        let input = open.cover.surface_triangles();
        let want = classify_surface(&input).unwrap();
        assert_eq!(want[0].boundary_loops, cut, "{}", shared.file);
        for algorithm in all_algorithms(i as u64) {
            let red = reduce_surface(open.cover.clone(), algorithm).unwrap();
            let output = red.cover.surface_triangles();
            assert_eq!(classify_surface(&output).unwrap(), want, "{}", shared.file);
            assert!(
                is_irreducible_surface(&output),
                "{}: reducible",
                shared.file
            );
            eprintln!(
                "{:28} {cut} holes {:11} F {} -> {}",
                shared.file,
                algorithm.name(),
                input.len(),
                output.len()
            );
        }
    }
}
