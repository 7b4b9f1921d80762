//! One test per malformed-input class of `build` / `inspect` / `Surface::from_triangles`, each
//! asserting the exact typed error and the element it names; plus the fixable cases (orientation,
//! unreferenced vertices, welding) and `inspect`'s counts on broken soups.

use std::collections::HashMap;
use surftopo_mesh::Surface;
use surftopo_mesh::generators::PROJECTIVE_PLANE_6 as RP2_6;
use surftopo_mesh::geometry::{Point3, weld_exact};
use surftopo_mesh::{BuildError, FaceId, VertexId, build, build_topology, inspect};

/// The tetrahedron, consistently oriented.
const TETRA: [[u32; 3]; 4] = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];

fn tetra_positions() -> Vec<Point3> {
    vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ]
}

/// `TETRA` with its vertices shifted by `offset`.
fn tetra_at(offset: u32) -> Vec<[u32; 3]> {
    TETRA.iter().map(|t| t.map(|v| v + offset)).collect()
}

/// The boundary of the octahedron on vertices `offset..offset + 6` (±x, ±y, ±z = 0..6),
/// consistently oriented.
fn octahedron_at(offset: u32) -> Vec<[u32; 3]> {
    let (px, nx, py, ny, pz, nz) = (0, 1, 2, 3, 4, 5);
    [
        [px, py, pz],
        [py, nx, pz],
        [nx, ny, pz],
        [ny, px, pz],
        [py, px, nz],
        [nx, py, nz],
        [ny, nx, nz],
        [px, ny, nz],
    ]
    .iter()
    .map(|t| t.map(|v| v + offset))
    .collect()
}

/// Independent check: every undirected edge of the soup is in exactly two triangles.
fn edges_in_two_faces(triangles: &[[u32; 3]]) -> bool {
    let mut count: HashMap<(u32, u32), u32> = HashMap::new();
    for t in triangles {
        for i in 0..3 {
            let (a, b) = (t[i], t[(i + 1) % 3]);
            *count.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    count.values().all(|&n| n == 2)
}

/// Whether `t` is a cyclic rotation of `u`.
fn same_cycle(t: [u32; 3], u: [u32; 3]) -> bool {
    (0..3).any(|r| (0..3).all(|i| t[i] == u[(i + r) % 3]))
}

#[test]
fn empty() {
    assert_eq!(build(0, &[]).unwrap_err(), BuildError::Empty);
    assert_eq!(build(4, &[]).unwrap_err(), BuildError::Empty);
    assert_eq!(inspect(4, &[]).problems, vec![BuildError::Empty]);
    assert_eq!(
        Surface::from_triangles(tetra_positions(), &[]).unwrap_err(),
        BuildError::Empty
    );
}

#[test]
fn index_out_of_range() {
    let mut t = TETRA.to_vec();
    t[2] = [1, 9, 3];
    assert_eq!(
        build(4, &t).unwrap_err(),
        BuildError::IndexOutOfRange {
            face: 2,
            index: 9,
            vertex_count: 4
        }
    );
    // Through Surface: the vertex count is the number of positions.
    assert_eq!(
        Surface::from_triangles(tetra_positions()[..3].to_vec(), &TETRA).unwrap_err(),
        BuildError::IndexOutOfRange {
            face: 1,
            index: 3,
            vertex_count: 3
        }
    );
    assert_eq!(
        build(4, &[[0, 1, u32::MAX]]).unwrap_err(),
        BuildError::IndexOutOfRange {
            face: 0,
            index: u32::MAX,
            vertex_count: 4
        }
    );
}

#[test]
fn repeated_vertex() {
    for (face, vertex) in [([1, 1, 3], 1), ([1, 3, 3], 3), ([3, 1, 3], 3)] {
        let mut t = TETRA.to_vec();
        t[2] = face;
        assert_eq!(
            build(4, &t).unwrap_err(),
            BuildError::RepeatedVertex { face: 2, vertex }
        );
    }
}

#[test]
fn duplicate_face_two_triangles() {
    // The two-triangle "sphere": same vertex set, both orientations.
    assert_eq!(
        build(3, &[[0, 1, 2], [0, 2, 1]]).unwrap_err(),
        BuildError::DuplicateFace {
            face: 1,
            duplicate_of: 0
        }
    );
    assert_eq!(
        build(3, &[[0, 1, 2], [1, 2, 0]]).unwrap_err(),
        BuildError::DuplicateFace {
            face: 1,
            duplicate_of: 0
        }
    );
}

#[test]
fn duplicate_face_in_a_closed_surface() {
    // A tetrahedron with face 1 repeated, in either orientation: the duplicate is the cause (each
    // of its edges is then in three faces, but that is a consequence).
    for dup in [[3, 0, 1], [1, 0, 3]] {
        let mut t = TETRA.to_vec();
        t.push(dup);
        assert_eq!(
            build(4, &t).unwrap_err(),
            BuildError::DuplicateFace {
                face: 4,
                duplicate_of: 1
            },
            "duplicate {dup:?}"
        );
    }
}

#[test]
fn boundary_edge() {
    // The open tetrahedron: face [1, 2, 3] missing, so edges 1-2, 2-3, 1-3 are boundary edges.
    let t: Vec<[u32; 3]> = TETRA.iter().copied().filter(|f| *f != [1, 2, 3]).collect();
    let err = build(4, &t).unwrap_err();
    assert_eq!(
        err,
        BuildError::BoundaryEdge {
            edge: [1, 2],
            face: 0
        }
    );
    // Not a problem for `inspect`: a disk with one boundary loop.
    let ins = inspect(4, &t);
    assert_eq!(ins.boundary_edges, 3);
    assert_eq!((ins.boundary_loops, ins.problem_count), (1, 0));
    assert_eq!(ins.surfaces[0].name(), "disk");
}

#[test]
fn non_manifold_edge() {
    // A fin: triangle [0, 1, 4] on edge 0-1 of a tetrahedron (three faces on that edge).
    let mut t = TETRA.to_vec();
    t.push([0, 1, 4]);
    assert_eq!(
        build(5, &t).unwrap_err(),
        BuildError::NonManifoldEdge {
            edge: [0, 1],
            face_count: 3,
            face: 0
        }
    );
    // Two tetrahedra sharing edge 0-1: four faces on it, every other edge manifold.
    let mut t = TETRA.to_vec();
    t.extend(
        TETRA
            .iter()
            .map(|f| f.map(|v| if v >= 2 { v + 2 } else { v })),
    );
    assert!(!edges_in_two_faces(&t));
    let ins = inspect(6, &t);
    assert_eq!((ins.non_manifold_edges, ins.boundary_edges), (1, 0));
    assert_eq!(
        build(6, &t).unwrap_err(),
        BuildError::NonManifoldEdge {
            edge: [0, 1],
            face_count: 4,
            face: 0
        }
    );
}

/// A pinched torus: a tube of `m` x `rings` vertices whose two end circles are both coned to the
/// same apex (last vertex). Every edge is in two faces and the faces are edge-connected, but the
/// apex's faces form two fans of `m` faces.
fn pinched_torus(m: u32, rings: u32) -> (u32, Vec<[u32; 3]>) {
    let id = |i: u32, j: u32| j * m + i % m;
    let apex = m * rings;
    let mut t = Vec::new();
    for j in 0..rings - 1 {
        for i in 0..m {
            t.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            t.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    for i in 0..m {
        t.push([apex, id(i + 1, 0), id(i, 0)]);
        t.push([apex, id(i, rings - 1), id(i + 1, rings - 1)]);
    }
    (apex, t)
}

#[test]
fn non_manifold_vertex_pinched_torus() {
    let (apex, t) = pinched_torus(5, 3);
    assert!(edges_in_two_faces(&t));
    let err = build(apex as usize + 1, &t).unwrap_err();
    assert_eq!(
        err,
        BuildError::NonManifoldVertex {
            vertex: apex,
            faces: 10,
            first_fan: 5
        }
    );
    let ins = inspect(apex as usize + 1, &t);
    assert_eq!(
        (ins.non_manifold_vertices, ins.components, ins.problem_count),
        (1, 1, 1)
    );
}

#[test]
fn non_manifold_vertex_two_tetrahedra_at_a_vertex() {
    // Tetrahedra on {0,1,2,3} and {0,4,5,6}: they share vertex 0 only. One connected space whose
    // vertex 0 has two fans of three faces: a non-manifold vertex, not two components.
    let mut t = TETRA.to_vec();
    t.extend(
        TETRA
            .iter()
            .map(|f| f.map(|v| if v == 0 { 0 } else { v + 3 })),
    );
    assert!(edges_in_two_faces(&t));
    assert_eq!(
        build(7, &t).unwrap_err(),
        BuildError::NonManifoldVertex {
            vertex: 0,
            faces: 6,
            first_fan: 3
        }
    );
    let ins = inspect(7, &t);
    assert_eq!(ins.non_manifold_vertices, 1);
}

#[test]
fn non_manifold_vertex_two_octahedra_at_a_vertex() {
    // Octahedra on 0..6 and 6..12 with vertex 6 of the second identified with vertex 0 (+x).
    let mut t = octahedron_at(0);
    t.extend(
        octahedron_at(6)
            .iter()
            .map(|f| f.map(|v| if v == 6 { 0 } else { v })),
    );
    assert!(edges_in_two_faces(&t));
    assert_eq!(
        build(12, &t).unwrap_err(),
        BuildError::NonManifoldVertex {
            vertex: 0,
            faces: 8,
            first_fan: 4
        }
    );
}

#[test]
fn fixable_orientation_is_fixed_and_reported() {
    // Face 2 reversed: the majority (faces 0, 1, 3) wins.
    let mut t = TETRA.to_vec();
    t[2] = [1, 3, 2];
    let (mesh, report) = build(4, &t).unwrap();
    assert_eq!(report.reoriented_faces, 1);
    mesh.check_invariants().unwrap();
    assert_eq!(mesh.genus(), 0);
    for (f, original) in TETRA.iter().enumerate() {
        let got = mesh.face_vertices(FaceId::new(f)).map(|v| v.0);
        assert!(same_cycle(got, *original), "face {f}: {got:?}");
    }
    // Three faces reversed: now they are the majority and face 0 is the one turned.
    let t: Vec<[u32; 3]> = TETRA
        .iter()
        .enumerate()
        .map(|(f, &[a, b, c])| if f == 0 { [a, b, c] } else { [a, c, b] })
        .collect();
    let (mesh, report) = build(4, &t).unwrap();
    assert_eq!(report.reoriented_faces, 1);
    mesh.check_invariants().unwrap();
    for (f, &[a, b, c]) in t.iter().enumerate() {
        let want = if f == 0 { [a, c, b] } else { [a, b, c] };
        assert!(same_cycle(
            mesh.face_vertices(FaceId::new(f)).map(|v| v.0),
            want
        ));
    }
    assert_eq!(inspect(4, &t).reoriented_faces, 1);
}

/// A Klein bottle: an `m x n` grid, columns glued straight, rows glued with a flip.
fn klein_bottle(m: u32, n: u32) -> Vec<[u32; 3]> {
    let id = |i: u32, j: u32| {
        if i == m {
            (n - j % n) % n
        } else {
            i * n + j % n
        }
    };
    let mut t = Vec::new();
    for i in 0..m {
        for j in 0..n {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
    }
    t
}

fn assert_non_orientable(vertex_count: usize, t: &[[u32; 3]]) {
    assert!(edges_in_two_faces(t));
    match build(vertex_count, t).unwrap_err() {
        BuildError::NonOrientable { edge, face } => {
            assert!(
                edge[0] != edge[1] && edge.iter().all(|v| t[face].contains(v)),
                "edge {edge:?} is not an edge of the named face {face} {:?}",
                t[face]
            );
        }
        other => panic!("expected NonOrientable, got {other:?}"),
    }
    let ins = inspect(vertex_count, t);
    assert!(!ins.orientable);
    assert!(ins.is_closed());
}

#[test]
fn non_orientable_projective_plane() {
    assert_non_orientable(6, &RP2_6);
    assert_eq!(inspect(6, &RP2_6).euler_characteristic(), 1);
}

#[test]
fn non_orientable_klein_bottle() {
    let t = klein_bottle(5, 5);
    assert_non_orientable(25, &t);
    assert_eq!(inspect(25, &t).euler_characteristic(), 0);
}

#[test]
fn disconnected() {
    let mut t = tetra_at(0);
    t.extend(tetra_at(4));
    assert_eq!(
        build(8, &t).unwrap_err(),
        BuildError::Disconnected {
            components: 2,
            face: 4
        }
    );
    let mut t = tetra_at(0);
    t.extend(tetra_at(4));
    t.extend(octahedron_at(8));
    assert_eq!(inspect(14, &t).components, 3);
}

#[test]
fn non_finite_positions() {
    for (value, text) in [
        (f64::NAN, "NaN"),
        (f64::INFINITY, "inf"),
        (f64::NEG_INFINITY, "-inf"),
    ] {
        let mut p = tetra_positions();
        p[2][1] = value;
        assert_eq!(
            Surface::from_triangles(p, &TETRA).unwrap_err(),
            BuildError::NonFinite {
                vertex: 2,
                axis: 1,
                value: text.to_string()
            }
        );
    }
}

#[test]
fn unreferenced_vertices_are_dropped_and_mapped() {
    // Six positions; 1 and 4 unused. Faces use 0, 2, 3, 5.
    let rename = [0u32, 2, 3, 5];
    let t: Vec<[u32; 3]> = TETRA
        .iter()
        .map(|f| f.map(|v| rename[v as usize]))
        .collect();
    let (mesh, report) = build(6, &t).unwrap();
    assert_eq!(report.dropped_vertices, vec![1, 4]);
    assert_eq!(
        report.vertex_old_to_new,
        vec![
            VertexId(0),
            VertexId::INVALID,
            VertexId(1),
            VertexId(2),
            VertexId::INVALID,
            VertexId(3)
        ]
    );
    assert_eq!(report.reoriented_faces, 0);
    mesh.check_invariants().unwrap();
    assert_eq!(mesh.vertex_count(), 4);
    assert_eq!(inspect(6, &t).dropped_vertices, 2);
    // Surface::from_triangles keeps each position with its vertex.
    let positions: Vec<Point3> = (0..6).map(|i| [i as f64, 10.0 * i as f64, 0.5]).collect();
    let s = Surface::from_triangles(positions.clone(), &t).unwrap();
    assert_eq!(s.positions.len(), 4);
    for (old, new) in report.vertex_old_to_new.iter().enumerate() {
        if new.is_valid() {
            assert_eq!(s.positions[new.idx()], positions[old]);
        }
    }
}

#[test]
fn welding_an_unwelded_soup() {
    // The tetrahedron as a soup of 12 corners; some zero coordinates written as -0.0.
    let corners = tetra_positions();
    let mut positions = Vec::new();
    let mut t = Vec::new();
    for (f, face) in TETRA.iter().enumerate() {
        let base = positions.len() as u32;
        for (i, &v) in face.iter().enumerate() {
            let mut p = corners[v as usize];
            if (f + i) % 2 == 1 {
                p = p.map(|c| if c == 0.0 { -0.0 } else { c });
            }
            positions.push(p);
        }
        t.push([base, base + 1, base + 2]);
    }
    assert!(
        positions
            .iter()
            .flatten()
            .any(|c| *c == 0.0 && c.is_sign_negative())
    );
    assert!(matches!(
        build(12, &t).unwrap_err(),
        BuildError::BoundaryEdge { .. }
    ));
    assert_eq!(inspect(12, &t).boundary_edges, 12);
    let (welded, map) = weld_exact(&positions);
    assert_eq!(welded.len(), 4);
    let t: Vec<[u32; 3]> = t.iter().map(|f| f.map(|v| map[v as usize])).collect();
    let s = Surface::from_triangles(welded, &t).unwrap();
    s.mesh.check_invariants().unwrap();
    assert_eq!(
        (
            s.mesh.vertex_count(),
            s.mesh.edge_count(),
            s.mesh.face_count()
        ),
        (4, 6, 4)
    );
    assert_eq!(s.mesh.genus(), 0);
    // Each welded vertex is at one of the corners; every corner is present.
    for c in &corners {
        assert!(s.positions.iter().any(|p| p == c));
    }
}

#[test]
fn inspect_counts_on_a_broken_soup() {
    // An open tetrahedron (3 boundary edges), a separate closed tetrahedron, and a fin on its
    // edge 4-5 (one non-manifold edge, two more boundary edges).
    let mut t: Vec<[u32; 3]> = TETRA.iter().copied().filter(|f| *f != [1, 2, 3]).collect();
    t.extend(tetra_at(4));
    t.push([4, 5, 8]);
    let ins = inspect(10, &t);
    assert_eq!(ins.vertices, 9);
    assert_eq!(ins.dropped_vertices, 1);
    assert_eq!(ins.faces, 8);
    assert_eq!(ins.edges, 14);
    assert_eq!(ins.boundary_edges, 5);
    assert_eq!(ins.non_manifold_edges, 1);
    assert_eq!(ins.components, 2);
    assert!(!ins.is_closed());
    assert_eq!(ins.problem_count, ins.problems.len());
    // Boundary edges and components are facts, not problems; no classification without a
    // surface.
    assert_eq!(ins.problems.len(), 1);
    assert!(matches!(
        ins.problems[0],
        BuildError::NonManifoldEdge { .. }
    ));
    assert!(ins.surfaces.is_empty() && ins.boundary_loops == 0);
    // A valid surface: counts and no problems.
    let ok = inspect(6, &octahedron_at(0));
    assert_eq!(
        (ok.vertices, ok.edges, ok.faces, ok.components),
        (6, 12, 8, 1)
    );
    assert!(ok.problems.is_empty() && ok.is_closed() && ok.orientable);
    assert_eq!(ok.euler_characteristic(), 2);
}

/// `build_topology` takes a soup only as given: a face to reorient or a vertex to drop is its own
/// error, naming how many, where `build` fixes both.
#[test]
fn build_topology_refuses_what_build_would_fix() {
    assert!(build_topology(4, &TETRA).is_ok());
    let mut reversed = TETRA;
    reversed[2].swap(1, 2);
    assert_eq!(
        build_topology(4, &reversed).unwrap_err(),
        BuildError::NotAsGiven {
            reoriented_faces: 1,
            dropped_vertices: 0
        }
    );
    assert_eq!(
        build_topology(6, &TETRA).unwrap_err(),
        BuildError::NotAsGiven {
            reoriented_faces: 0,
            dropped_vertices: 2
        }
    );
    assert!(build(6, &reversed).is_ok());
}
