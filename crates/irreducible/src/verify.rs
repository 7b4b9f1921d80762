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

/// Whether no edge of the triangulated surface `triangles` (a compact surface: closed or with
/// boundary, orientable or not, in any number of pieces) can be contracted keeping its topology:
/// an independent check of [`crate::reduce_surface`], written from the triangles alone (no mesh,
/// no cover).
///
/// The rule is Dey, Edelsbrunner, Guha and Nekhayev's ("Topology preserving edge contraction",
/// 1999): cone the boundary over one new vertex ω (a triangle ω-x-y on every boundary edge xy);
/// an edge ab contracts keeping the topology iff Lk(a) ∩ Lk(b) = Lk(ab) in that complex, on
/// vertices (the common neighbours of a and b are exactly the vertices opposite ab) and on edges
/// (no edge wz with both a-w-z and b-w-z triangles). O(n log n).
pub fn is_irreducible_surface(triangles: &[[u32; 3]]) -> bool {
    use std::collections::{BTreeMap, BTreeSet};
    const OMEGA: u32 = u32::MAX;
    let key = |a: u32, b: u32| (a.min(b), a.max(b));
    let mut opposite: BTreeMap<(u32, u32), Vec<u32>> = BTreeMap::new();
    for t in triangles {
        for i in 0..3 {
            let (a, b, c) = (t[i], t[(i + 1) % 3], t[(i + 2) % 3]);
            opposite.entry(key(a, b)).or_default().push(c);
        }
    }
    let mut faces: BTreeSet<[u32; 3]> = triangles
        .iter()
        .map(|t| {
            let mut s = *t;
            s.sort_unstable();
            s
        })
        .collect();
    let boundary: Vec<(u32, u32)> = opposite
        .iter()
        .filter(|(_, o)| o.len() == 1)
        .map(|(&e, _)| e)
        .collect();
    let mut neighbours: BTreeMap<u32, BTreeSet<u32>> = BTreeMap::new();
    for &(a, b) in opposite.keys() {
        neighbours.entry(a).or_default().insert(b);
        neighbours.entry(b).or_default().insert(a);
    }
    for &(a, b) in &boundary {
        opposite.get_mut(&(a, b)).expect("listed").push(OMEGA);
        faces.insert([a, b, OMEGA]);
        for v in [a, b] {
            neighbours.entry(v).or_default().insert(OMEGA);
        }
    }
    let original: Vec<((u32, u32), Vec<u32>)> = opposite
        .into_iter()
        .filter(|((_, b), _)| *b != OMEGA)
        .collect();
    let is_face = |a: u32, b: u32, c: u32| {
        let mut s = [a, b, c];
        s.sort_unstable();
        faces.contains(&s)
    };
    for ((a, b), link) in original {
        let link: BTreeSet<u32> = link.into_iter().collect();
        let common: BTreeSet<u32> = neighbours[&a]
            .intersection(&neighbours[&b])
            .copied()
            .collect();
        if common != link {
            continue;
        }
        let shared_edge = common.iter().any(|&w| {
            common
                .iter()
                .any(|&z| w < z && is_face(a, w, z) && is_face(b, w, z))
        });
        if !shared_edge {
            return false;
        }
    }
    true
}
