//! Sets the cfg `surftopo_meshes` when `SURFTOPO_MESHES` is set while the test support is built:
//! `shared_mesh_tests!` then declares plain tests, and ignored ones ("needs SURFTOPO_MESHES")
//! otherwise, so that `cargo test` lists the real-mesh tests as ignored rather than passed. Cargo
//! reruns this script, and rebuilds the tests, whenever the variable changes.

fn main() {
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rerun-if-env-changed=SURFTOPO_MESHES");
    println!("cargo::rustc-check-cfg=cfg(surftopo_meshes)");
    if std::env::var_os("SURFTOPO_MESHES").is_some() {
        println!("cargo::rustc-cfg=surftopo_meshes");
    }
}
