//! Every mesh of the shared collection loads with exactly the manifest's V, E, F and genus.

mod common;

use common::surftopo;
use serde_json::Value;

surftopo_testkit::shared_mesh_tests!(every_shared_mesh_loads_with_the_manifest_counts);

fn every_shared_mesh_loads_with_the_manifest_counts() {
    let meshes = surftopo_testkit::shared_meshes();
    assert_eq!(meshes.len(), 47);
    for mesh in meshes {
        let mut cmd = surftopo();
        cmd.arg("info")
            .arg(&mesh.path)
            .arg("--json")
            .arg("--strict");
        if mesh.needs_weld {
            cmd.arg("--weld");
        }
        let out = cmd.output().unwrap();
        let file = &mesh.file;
        assert!(
            out.status.success(),
            "{file}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(v["vertices"], mesh.vertices, "{file}: vertices");
        assert_eq!(v["edges"], mesh.edges, "{file}: edges");
        assert_eq!(v["faces"], mesh.faces, "{file}: faces");
        assert_eq!(v["genus"], mesh.genus, "{file}: genus");
    }
}
