//! The geometric problems of a soup (`geometry::problems`) and the class counts of an
//! inspection (`ProblemCounts`).

use surftopo_mesh::geometry::{is_zero_area_face, is_zero_area_triangle, problems};
use surftopo_mesh::{BuildError, MAX_LISTED_PROBLEMS, inspect};

const TETRA: [[u32; 3]; 4] = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];

#[test]
fn zero_area_is_decided_exactly() {
    let o = [0.0; 3];
    // Collinear in space (the line x = y = z) and in a coordinate plane.
    assert!(is_zero_area_triangle(o, [0.1; 3], [0.3; 3]));
    assert!(is_zero_area_triangle(o, [1.0, 0.0, 0.0], [-7.5, 0.0, 0.0]));
    // Coincident points.
    assert!(is_zero_area_triangle(o, o, [1.0, 2.0, 3.0]));
    // Tiny but not zero.
    assert!(!is_zero_area_triangle(
        o,
        [1.0, 0.0, 0.0],
        [2.0, 1e-300, 0.0]
    ));
    // Not zero, though the cross product evaluated in f64 rounds to exactly zero:
    // (1 + e)(1 - e/2) - 1 = e/2 - e²/2 rounds to 0.
    let e = f64::EPSILON;
    let b = [1.0 + e, 1.0, 0.0];
    let c = [1.0, 1.0 - e / 2.0, 0.0];
    assert_eq!(b[0] * c[1] - b[1] * c[0], 0.0);
    assert!(!is_zero_area_triangle(o, b, c));
    // A polygon: zero when all its corners are collinear, not when one is off the line.
    let line = [
        [0.0; 3],
        [1.0, 0.0, 0.0],
        [2.0, 0.0, 0.0],
        [3.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
    ];
    assert!(is_zero_area_face(&line, &[0, 1, 2, 3]));
    assert!(!is_zero_area_face(&line, &[0, 1, 4, 3]));
}

#[test]
fn problems_lists_non_finite_coordinates_then_zero_area_faces() {
    // A tetrahedron with vertex 2 moved onto the line through 0 and 1 (face 0 = (0, 2, 1)
    // collinear) and vertex 3 given two non-finite coordinates.
    let positions = [
        [0.0; 3],
        [1.0, 0.0, 0.0],
        [2.0, 0.0, 0.0],
        [f64::NAN, 0.0, f64::NEG_INFINITY],
    ];
    let faces = TETRA.iter().map(|t| &t[..]);
    let found = problems(&positions, faces);
    assert_eq!(
        found,
        vec![
            BuildError::NonFinite {
                vertex: 3,
                axis: 0,
                value: "NaN".into()
            },
            BuildError::NonFinite {
                vertex: 3,
                axis: 2,
                value: "-inf".into()
            },
            BuildError::ZeroArea { face: 0 },
        ]
    );
    // Faces through the non-finite vertex, with an index out of range or a repeated vertex
    // are not tested for zero area.
    let bad: [&[u32]; 3] = [&[0, 1, 3], &[0, 1, 9], &[0, 1, 1]];
    assert_eq!(problems(&positions, bad).len(), 2);
}

#[test]
fn counts_sum_to_the_total_and_geometric_problems_come_first() {
    // An open tetrahedron (a disk: 3 boundary edges, not problems) with a fourth face on one
    // of its edges (a non-manifold edge), then 150 zero-area faces found by geometry.
    let ins = inspect(4, &TETRA[..3]);
    assert_eq!((ins.boundary_edges, ins.problem_count), (3, 0));
    assert_eq!(ins.surfaces[0].name(), "disk");
    assert_eq!(ins.genus(), Some(0));
    let mut fin = TETRA[..3].to_vec();
    fin.push([0, 1, 4]);
    let mut ins = inspect(5, &fin);
    assert_eq!(ins.counts.non_manifold_edges, 1);
    assert!(ins.genus().is_none() && ins.surfaces.is_empty());
    ins.add_problems_first((0..150).map(|face| BuildError::ZeroArea { face }));
    assert_eq!(ins.counts.zero_area_faces, 150);
    assert_eq!(ins.problem_count, 151);
    assert_eq!(ins.counts.total(), 151);
    assert_eq!(ins.counts.geometric(), 150);
    assert_eq!(ins.problems.len(), MAX_LISTED_PROBLEMS);
    assert!(ins.is_truncated());
    assert_eq!(ins.problems[0], BuildError::ZeroArea { face: 0 });
    // A closed tetrahedron with a geometric problem only keeps its genus.
    let mut ins = inspect(4, &TETRA);
    assert!(!ins.is_truncated());
    ins.add_problems_first([BuildError::ZeroArea { face: 1 }]);
    assert!(!ins.is_valid() && ins.is_combinatorially_valid());
    assert_eq!(ins.genus(), Some(0));
    assert_eq!(
        ins.counts.entries().iter().map(|&(_, n)| n).sum::<usize>(),
        ins.problem_count
    );
}
