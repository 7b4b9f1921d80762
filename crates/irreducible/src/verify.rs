//! An independent irreducibility check (it shares no code with the algorithms).

use surftopo_mesh::SurfaceMesh;

/// Whether `mesh` is an irreducible triangulation: it is simplicial and every edge fails the link
/// condition, i.e. its endpoints have a common neighbour besides the two vertices opposite it — or
/// the mesh is the tetrahedron boundary T4 (the one simplicial closed surface with 4 vertices),
/// where every edge fails by definition. Non-simplicial meshes give `false`.
///
/// Works on neighbour sets only (marks over the vertex ids), not on the algorithms' code.
/// O(Σ deg(v)²) time.
pub fn is_irreducible(mesh: &SurfaceMesh) -> bool {
    if !mesh.is_simplicial() {
        return false;
    }
    if mesh.vertex_count() == 4 {
        return true;
    }
    let mut mark = vec![u32::MAX; mesh.vertex_slots()];
    for a in mesh.vertices() {
        for b in mesh.neighbors(a) {
            mark[b.idx()] = a.0;
        }
        for b in mesh.neighbors(a).filter(|&b| b > a) {
            let common = mesh.neighbors(b).filter(|w| mark[w.idx()] == a.0).count();
            // Two common neighbours are the vertices opposite [a, b]; a third makes a critical cycle.
            if common <= 2 {
                return false;
            }
        }
    }
    true
}
