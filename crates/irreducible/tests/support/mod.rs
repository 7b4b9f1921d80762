//! Independent checks of a reduction, shared by the integration tests. Nothing here calls the
//! algorithms' code: irreducibility and the link condition are recomputed from neighbour sets.

#![allow(dead_code)]

use std::collections::HashSet;

use surftopo_irreducible::{Algorithm, Reduction, SurfaceMesh, is_irreducible, reduce};
use surftopo_mesh::VertexId;

/// Neighbour set of `v` (the mesh is simplicial, so no repetition is lost).
fn neighbour_set(mesh: &SurfaceMesh, v: VertexId) -> HashSet<VertexId> {
    mesh.neighbors(v).collect()
}

/// Naive link condition of the edge [a, b] in a simplicial mesh: the common neighbours of a and b
/// are exactly the two vertices opposite the edge, and the mesh is not T4.
fn naive_contractible(mesh: &SurfaceMesh, a: VertexId, b: VertexId) -> bool {
    let (na, nb) = (neighbour_set(mesh, a), neighbour_set(mesh, b));
    assert!(na.contains(&b), "{a:?} and {b:?} are not adjacent");
    na.intersection(&nb).count() == 2 && mesh.vertex_count() > 4
}

/// Naive irreducibility: every edge fails the naive link condition.
pub fn naive_irreducible(mesh: &SurfaceMesh) -> bool {
    mesh.edges().all(|e| {
        let [a, b] = mesh.edge_vertices(e);
        !naive_contractible(mesh, a, b)
    })
}

/// Heawood's lower bound on the vertices of a triangulation of genus g.
fn heawood(g: i64) -> usize {
    ((7.0 + ((1 + 48 * g) as f64).sqrt()) / 2.0).ceil() as usize
}

/// Checks everything the issue asks of a reduction of `input`, independently of the algorithm.
/// `forward` also replays the contractions forward, checking the link condition before each.
pub fn verify(input: &SurfaceMesh, red: &Reduction, algorithm: Algorithm, forward: bool) {
    let out = &red.mesh;
    let tag = algorithm.name();
    out.check_invariants()
        .unwrap_or_else(|e| panic!("{tag}: output invariants: {e}"));
    assert!(out.is_simplicial(), "{tag}: output is not simplicial");
    let g = input.genus();
    assert_eq!(out.genus(), g, "{tag}: genus changed");
    assert!(
        naive_irreducible(out),
        "{tag}: an output edge passes the link condition"
    );
    assert!(is_irreducible(out), "{tag}: is_irreducible disagrees");
    let v = out.vertex_count();
    match g {
        0 => assert_eq!(
            (v, out.edge_count(), out.face_count()),
            (4, 6, 4),
            "{tag}: genus 0 must give the tetrahedron"
        ),
        1 => assert!((7..=10).contains(&v), "{tag}: torus with {v} vertices"),
        _ => assert!(
            v >= heawood(g) && v as i64 <= 26 * g - 4,
            "{tag}: genus {g} with {v} vertices"
        ),
    }
    // Surviving vertices keep their input ids.
    assert_eq!(out.vertex_slots(), input.vertex_slots());
    assert!(out.vertices().all(|w| input.is_vertex_live(w)));
    // Counters.
    let c = &red.counters;
    assert_eq!(c.contractions as usize, red.history.len(), "{tag}");
    assert_eq!(input.vertex_count() - v, red.history.len(), "{tag}");
    assert!(c.seconds >= 0.0);
    assert!(c.edges_tested_more_than_once <= c.link_tests);
    if algorithm == Algorithm::RamaswamiSiqueira {
        assert_eq!(c.edges_tested_more_than_once, 0, "RS tested an edge twice");
        assert!(c.link_tests as usize <= input.edge_count());
    }
    // The history replays back to the input exactly.
    let mut back = out.clone();
    for record in red.history.iter().rev() {
        back.split_vertex(record);
    }
    assert_eq!(&back, input, "{tag}: splits do not give back the input");
    if forward {
        replay_forward(input, red, tag);
    }
}

/// Replays the history forward on a copy of the input, checking with neighbour marks that each
/// contracted edge satisfied the link condition then, and that the records match.
fn replay_forward(input: &SurfaceMesh, red: &Reduction, tag: &str) {
    let mut mesh = input.clone();
    let mut mark = vec![0u32; mesh.vertex_slots()];
    for (i, record) in red.history.iter().enumerate() {
        let h = record.halfedge_uv();
        let (u, v) = (mesh.origin(h), mesh.dest(h));
        assert_eq!(
            (u, v),
            (record.kept(), record.removed()),
            "{tag}: record {i}"
        );
        let stamp = i as u32 + 1;
        for w in mesh.neighbors(u) {
            mark[w.idx()] = stamp;
        }
        let common: Vec<VertexId> = mesh
            .neighbors(v)
            .filter(|w| mark[w.idx()] == stamp)
            .collect();
        let opposite = [mesh.opposite_vertex(h), mesh.opposite_vertex(h.twin())];
        assert!(
            common.len() == 2
                && common.iter().all(|w| opposite.contains(w))
                && mesh.vertex_count() > 4,
            "{tag}: contraction {i} of [{u:?}, {v:?}] breaks the link condition"
        );
        let again = mesh.contract_unchecked(h);
        assert_eq!(&again, record, "{tag}: record {i} differs");
    }
    assert_eq!(&mesh, &red.mesh, "{tag}: forward replay differs");
}

/// Runs `algorithm` on a copy of `mesh` and verifies the result; returns it.
pub fn run_and_verify(mesh: &SurfaceMesh, algorithm: Algorithm, forward: bool) -> Reduction {
    let red = reduce(mesh.clone(), algorithm)
        .unwrap_or_else(|e| panic!("{}: refused: {e}", algorithm.name()));
    verify(mesh, &red, algorithm, forward);
    red
}

/// The three algorithms (BF with the given seed).
pub fn all_algorithms(seed: u64) -> [Algorithm; 3] {
    [
        Algorithm::RamaswamiSiqueira,
        Algorithm::Schipper,
        Algorithm::BruteForce { seed },
    ]
}
