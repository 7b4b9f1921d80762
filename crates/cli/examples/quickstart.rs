//! The README's Rust quick start: a genus-3 surface, its irreducible triangulation, a
//! quadrangulation and the intrinsic Delaunay Laplacian, each checked.

use surftopo_intrinsic::{DelaunayOptions, IntrinsicTriangulation, intrinsic_delaunay_laplacian};
use surftopo_irreducible::{Algorithm, is_irreducible, reduce};
use surftopo_mesh::generators::genus_surface;
use surftopo_quad::{QuadAlgorithm, quadrangulate};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // A closed surface of genus 3 (a brick with three through-holes): mesh + positions.
    let surface = genus_surface(3, 6);
    println!(
        "{} vertices, {} faces, genus {}",
        surface.mesh.vertex_count(),
        surface.mesh.face_count(),
        surface.mesh.genus()
    );

    // Irreducible triangulation (Ramaswami–Siqueira): no edge can be contracted any more.
    let reduction = reduce(surface.mesh.clone(), Algorithm::RamaswamiSiqueira)?;
    assert!(is_irreducible(&reduction.mesh));
    println!("irreducible: {} vertices", reduction.mesh.vertex_count());

    // Quadrangulation with the same vertices (Karp–Sipser pairing, verified).
    let quads = quadrangulate(&surface.mesh, QuadAlgorithm::KarpSipser)?;
    assert_eq!(2 * quads.quads.len(), surface.mesh.face_count());
    println!("{} quads", quads.quads.len());

    // Intrinsic Delaunay triangulation by flipping, and its cotan Laplacian (positive
    // semidefinite: every row sums to zero).
    let mut tri = IntrinsicTriangulation::from_positions(surface.mesh, &surface.positions)?;
    let (flips, laplacian) = intrinsic_delaunay_laplacian(&mut tri, &DelaunayOptions::default())?;
    let row_sum: f64 = (0..laplacian.n).map(|j| laplacian.get(0, j)).sum();
    assert!(row_sum.abs() < 1e-9);
    let n = laplacian.n;
    println!(
        "{} flips; Laplacian {n} x {n}, {} entries",
        flips.flips,
        laplacian.nnz()
    );
    Ok(())
}
