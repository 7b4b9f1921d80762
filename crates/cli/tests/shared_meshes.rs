//! Every mesh of the shared collection loads with exactly the manifest's V, E, F and genus.

mod common;

use common::{shared_meshes, surftopo};
use serde_json::Value;

#[test]
fn every_shared_mesh_loads_with_the_manifest_counts() {
    let Some(dir) = shared_meshes() else { return };
    let manifest: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("manifest.json")).unwrap()).unwrap();
    let meshes = manifest["meshes"].as_array().expect("meshes array");
    assert_eq!(meshes.len(), 47);
    for entry in meshes {
        let file = entry["file"].as_str().unwrap();
        let mut cmd = surftopo();
        cmd.arg("info")
            .arg(dir.join(file))
            .arg("--json")
            .arg("--strict");
        if entry["passes_without_vertex_welding"] == Value::Bool(false) {
            cmd.arg("--weld");
        }
        let out = cmd.output().unwrap();
        assert!(
            out.status.success(),
            "{file}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: Value = serde_json::from_slice(&out.stdout).unwrap();
        for (ours, theirs) in [
            ("vertices", "V"),
            ("edges", "E"),
            ("faces", "F"),
            ("genus", "genus"),
        ] {
            assert_eq!(v[ours], entry[theirs], "{file}: {ours}");
        }
    }
}
