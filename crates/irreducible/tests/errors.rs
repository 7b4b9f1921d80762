//! Inputs that are not simplicial are refused with a typed error naming the element, before any
//! work, by all three algorithms.

use surftopo_irreducible::{Algorithm, IrreducibleError, check_simplicial, reduce};
use surftopo_mesh::generators::{icosphere, random_vertex_splits, tetrahedron};
use surftopo_mesh::{EdgeId, SurfaceMesh, VertexId};

const ALL: [Algorithm; 3] = [
    Algorithm::RamaswamiSiqueira,
    Algorithm::Schipper,
    Algorithm::BruteForce { seed: 0 },
];

/// The endpoints of every edge joining the same two vertices as another edge.
fn parallel_edges(mesh: &SurfaceMesh) -> Vec<(EdgeId, [VertexId; 2])> {
    let mut seen = std::collections::HashMap::new();
    let mut out = Vec::new();
    for e in mesh.edges() {
        let [a, b] = mesh.edge_vertices(e);
        let key = (a.min(b), a.max(b));
        if let Some(&first) = seen.get(&key) {
            out.push((first, [key.0, key.1]));
            out.push((e, [key.0, key.1]));
        } else {
            seen.insert(key, e);
        }
    }
    out
}

#[test]
fn a_multi_edge_made_by_a_flip_is_refused() {
    // Vertex splits make degree-3 vertices; flipping an edge from one of them to a neighbour joins
    // the two other neighbours a second time.
    let mut mesh = random_vertex_splits(&icosphere(1), 6, 2).mesh;
    let e = mesh
        .edges()
        .find(|&e| mesh.can_flip(e) && !mesh.can_flip_simplicial(e))
        .expect("an edge whose flip makes a multi-edge");
    mesh.flip(e).expect("can_flip");
    let parallel = parallel_edges(&mesh);
    assert!(parallel.iter().any(|&(p, _)| p == e));
    for a in ALL {
        let err = reduce(mesh.clone(), a).expect_err("multi-edge");
        let IrreducibleError::MultiEdge { edges, vertices } = err.clone() else {
            panic!("{a}: wrong error {err:?}");
        };
        assert_ne!(edges[0], edges[1]);
        for edge in edges {
            let [x, y] = mesh.edge_vertices(edge);
            assert!(
                (x, y) == (vertices[0], vertices[1]) || (y, x) == (vertices[0], vertices[1]),
                "{a}: {edge:?} does not join {vertices:?}"
            );
        }
        let text = err.to_string();
        assert!(text.contains(&edges[0].to_string()) && text.contains(&edges[1].to_string()));
    }
}

#[test]
fn a_loop_is_refused() {
    // Flip sequences on the tetrahedron (allowed by can_flip, not simplicial) until a loop appears.
    let mut mesh = tetrahedron().mesh;
    let mut found = None;
    'search: for _ in 0..100 {
        for e in mesh.edges().collect::<Vec<_>>() {
            if mesh.can_flip(e) {
                mesh.flip(e).expect("can_flip");
                if let Some(l) = mesh.edges().find(|&l| {
                    let [a, b] = mesh.edge_vertices(l);
                    a == b
                }) {
                    found = Some(l);
                    break 'search;
                }
            }
        }
    }
    let l = found.expect("flips of the tetrahedron eventually make a loop");
    let [v, w] = mesh.edge_vertices(l);
    assert_eq!(v, w);
    for a in ALL {
        let err = reduce(mesh.clone(), a).expect_err("loop");
        let IrreducibleError::Loop { edge, vertex } = err.clone() else {
            panic!("{a}: wrong error {err:?}");
        };
        let [x, y] = mesh.edge_vertices(edge);
        assert_eq!((x, y), (vertex, vertex));
        assert!(err.to_string().contains(&edge.to_string()));
    }
}

#[test]
fn the_two_triangle_sphere_is_refused() {
    // Contracting an edge of the tetrahedron (which fails the link condition) leaves two faces on
    // the same three vertices.
    let mut mesh = tetrahedron().mesh;
    let h = mesh.edges().next().expect("an edge").halfedge();
    mesh.contract_unchecked(h);
    assert_eq!(mesh.face_count(), 2);
    let faces: Vec<_> = mesh.faces().collect();
    for a in ALL {
        match reduce(mesh.clone(), a) {
            Err(IrreducibleError::DuplicateFace { faces: f }) => assert_eq!(f.to_vec(), faces),
            other => panic!("{a}: wrong result {other:?}"),
        }
    }
}

#[test]
fn simplicial_inputs_pass_the_check() {
    assert_eq!(check_simplicial(&tetrahedron().mesh), Ok(()));
    assert_eq!(check_simplicial(&icosphere(2).mesh), Ok(()));
}
