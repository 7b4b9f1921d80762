//! Surfaces glued from triangles: loops and multi-edges, checked against Euler's formula.

use surftopo_mesh::{BuildError, Side, SurfaceMesh};

fn side(face: u32, side: u8) -> Side {
    Side { face, side }
}

#[test]
fn two_triangles_glued_side_to_side_in_order_make_a_one_vertex_torus() {
    let pairs = [
        (side(0, 0), side(1, 0)),
        (side(0, 1), side(1, 1)),
        (side(0, 2), side(1, 2)),
    ];
    let (mesh, corners) = SurfaceMesh::from_gluing(2, &pairs).unwrap();
    mesh.check_invariants().unwrap();
    assert_eq!(
        (mesh.vertex_count(), mesh.edge_count(), mesh.face_count()),
        (1, 3, 2)
    );
    assert_eq!(mesh.genus(), 1);
    assert!(corners.iter().all(|&v| v == corners[0]));
    assert!(!mesh.is_simplicial());
    // Every edge is a loop; every edge can still be flipped (two distinct faces).
    for e in mesh.edges() {
        let [a, b] = mesh.edge_vertices(e);
        assert_eq!(a, b);
        assert!(mesh.can_flip(e));
    }
}

#[test]
fn two_triangles_glued_reversed_make_a_sphere() {
    let pairs = [
        (side(0, 0), side(1, 2)),
        (side(0, 1), side(1, 1)),
        (side(0, 2), side(1, 0)),
    ];
    let (mesh, _) = SurfaceMesh::from_gluing(2, &pairs).unwrap();
    mesh.check_invariants().unwrap();
    assert_eq!(
        (mesh.vertex_count(), mesh.edge_count(), mesh.face_count()),
        (3, 3, 2)
    );
    assert_eq!(mesh.genus(), 0);
}

#[test]
fn gluing_errors_name_the_side() {
    let unglued =
        SurfaceMesh::from_gluing(2, &[(side(0, 0), side(1, 0)), (side(0, 1), side(1, 1))]);
    assert_eq!(
        unglued.unwrap_err(),
        BuildError::SideUnglued { face: 0, side: 2 }
    );
    let twice = SurfaceMesh::from_gluing(2, &[(side(0, 0), side(1, 0)), (side(0, 0), side(1, 1))]);
    assert_eq!(
        twice.unwrap_err(),
        BuildError::SideGluedTwice { face: 0, side: 0 }
    );
    let out_of_range = SurfaceMesh::from_gluing(1, &[(side(0, 0), side(3, 0))]);
    assert_eq!(
        out_of_range.unwrap_err(),
        BuildError::SideGluedTwice { face: 3, side: 0 }
    );
    let two_spheres = [
        (side(0, 0), side(1, 2)),
        (side(0, 1), side(1, 1)),
        (side(0, 2), side(1, 0)),
        (side(2, 0), side(3, 2)),
        (side(2, 1), side(3, 1)),
        (side(2, 2), side(3, 0)),
    ];
    assert_eq!(
        SurfaceMesh::from_gluing(4, &two_spheres).unwrap_err(),
        BuildError::Disconnected {
            components: 2,
            face: 2
        }
    );
    assert_eq!(
        SurfaceMesh::from_gluing(0, &[]).unwrap_err(),
        BuildError::Empty
    );
}
