//! All three algorithms on every mesh of $SURFTOPO_MESHES (mandatory when the variable is set; the
//! largest, igea, has 268,686 triangles), each result checked by `support::verify`, including the
//! forward replay of every contraction.

mod support;

use support::{all_algorithms, run_and_verify};
use surftopo_irreducible::Algorithm;

surftopo_testkit::shared_mesh_tests!(every_shared_mesh);

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
