//! Reads every mesh of `$SURFTOPO_MESHES/manifest.json` and checks its
//! counts. Ignored when the tests are built without the variable.

use serde_json::Value;
use surftopo_io::read_path;

surftopo_testkit::shared_mesh_tests!(manifest_meshes_have_expected_counts);

fn manifest_meshes_have_expected_counts() {
    let dir = surftopo_testkit::shared_meshes_dir().expect("SURFTOPO_MESHES is set");
    let manifest = std::fs::read_to_string(dir.join("manifest.json"))
        .unwrap_or_else(|e| panic!("{}/manifest.json: {e}", dir.display()));
    let manifest: Value = serde_json::from_str(&manifest).expect("manifest.json is not JSON");
    let meshes = manifest["meshes"]
        .as_array()
        .expect("manifest has no 'meshes' list");
    assert!(!meshes.is_empty());
    let mut checked = 0;
    for m in meshes {
        let file = m["file"].as_str().expect("mesh without 'file'");
        let path = dir.join(file);
        let soup = read_path(&path).unwrap_or_else(|e| panic!("{e}"));
        // Raw counts are what the file stores; V/F are after welding, which
        // only changes V (chair_soup.off.gz stores 857 corners, V = 246).
        let faces = m
            .get("raw_face_count_in_file")
            .or_else(|| m.get("F"))
            .and_then(Value::as_u64)
            .expect("no face count");
        assert_eq!(soup.face_count() as u64, faces, "{file}: faces");
        if let Some(v) = m.get("raw_vertex_count_in_file").and_then(Value::as_u64) {
            assert_eq!(soup.positions.len() as u64, v, "{file}: vertices");
        }
        assert!(soup.is_all_triangles(), "{file}: not all triangles");
        soup.validate().unwrap_or_else(|e| panic!("{file}: {e}"));
        if file == "igea.ply.gz" {
            assert_eq!(soup.face_count(), 268_686);
        }
        checked += 1;
    }
    eprintln!("read {checked} real meshes from {}", dir.display());
}
