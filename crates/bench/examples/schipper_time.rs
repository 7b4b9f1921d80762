//! t_s/t_rs against n on one surface (irreducible-triangulations paper, Table 2 and Figure 15;
//! `results/papers/irreducible.md`, item 5): the mesh is simplified (random link-condition
//! contractions, seed 1) or midpoint-subdivided and then simplified to each triangle count asked
//! for (the mesh itself when the count is its own), and RS and S are timed on each as `surftopo-bench papers` times them (mean CPU seconds
//! over repeated calls for at least half a second, the input check excluded).
//!
//! ```sh
//! cargo run --release -p surftopo-bench --example schipper_time -- MESH TRIANGLES...
//! ```

use surftopo_bench::papers::measure::timed;
use surftopo_irreducible::{Algorithm, LinkDictionaries, check_simplicial, reduce};
use surftopo_mesh::generators::{simplify, subdivide_midpoint};
use surftopo_mesh::{Surface, SurfaceMesh};

use std::collections::BTreeSet;

/// CPU seconds per call of S's set-up alone (as `schipper`'s first lines: its
/// [`LinkDictionaries`] and the global dictionary by degree).
fn set_up_time(mesh: &SurfaceMesh) -> f64 {
    let t = timed(0.5, || {
        let start = std::time::Instant::now();
        let dict = LinkDictionaries::new(mesh);
        let by_degree: BTreeSet<(u32, u32)> =
            mesh.vertices().map(|v| (dict.degree(v), v.0)).collect();
        ((dict, by_degree), start.elapsed().as_secs_f64())
    });
    t.cpu
}

/// CPU seconds per call of `algorithm` on `mesh`, and its ℓ.
fn time(mesh: &SurfaceMesh, algorithm: Algorithm, check_cpu: f64) -> (f64, u64) {
    let t = timed(0.5, || {
        let r = reduce(mesh.clone(), algorithm).expect("simplicial");
        let wall = r.counters.seconds;
        (r.counters.link_tests, wall)
    });
    ((t.cpu - check_cpu).max(0.0), t.first)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let path = args.first().expect("usage: MESH TRIANGLES...");
    let soup = surftopo_io::read_path(std::path::Path::new(path)).expect("readable");
    let triangles = soup.triangles().expect("triangles");
    let surface = Surface::from_triangles(soup.positions, &triangles).expect("a closed surface");
    println!(
        "| F | V | g | ℓ_s/ℓ_rs | t_rs (s) | t_s (s) | t_s/t_rs | S's set-up / t_s |\n\
         |---|---|---|---|---|---|---|---|"
    );
    for target in args[1..]
        .iter()
        .map(|a| a.parse::<usize>().expect("a number"))
    {
        let mut levels = 0;
        while surface.mesh.face_count() << (2 * levels) < target {
            levels += 1;
        }
        let fine = subdivide_midpoint(&surface, levels);
        let input = if fine.mesh.face_count() > target {
            simplify(&fine, target, 1)
        } else {
            fine
        };
        let mesh = &input.mesh;
        let check = timed(0.5, || {
            let start = std::time::Instant::now();
            check_simplicial(mesh).expect("simplicial");
            ((), start.elapsed().as_secs_f64())
        });
        let (t_rs, l_rs) = time(mesh, Algorithm::RamaswamiSiqueira, check.cpu);
        let (t_s, l_s) = time(mesh, Algorithm::Schipper, check.cpu);
        let set_up = set_up_time(mesh);
        println!(
            "| {} | {} | {} | {:.2} | {:.4} | {:.4} | {:.2} | {:.2} |",
            mesh.face_count(),
            mesh.vertex_count(),
            mesh.genus(),
            l_s as f64 / l_rs as f64,
            t_rs,
            t_s,
            t_s / t_rs,
            set_up / t_s
        );
    }
}
