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

#[test]
fn relative_height_is_scale_free() {
    use surftopo_mesh::geometry::relative_height;
    let equilateral = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.5, 3f64.sqrt() / 2.0, 0.0],
    ];
    let needle = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.4, 1e-9, 0.0]];
    for scale in [1e-200, 1e-30, 1.0, 1e30, 1e200, 1e307] {
        let [a, b, c] = equilateral.map(|p| p.map(|x| x * scale));
        assert!(
            (relative_height(a, b, c) - 3f64.sqrt() / 2.0).abs() < 1e-15,
            "{scale}"
        );
        let [a, b, c] = needle.map(|p| p.map(|x| x * scale));
        assert!(
            (relative_height(a, b, c) / 1e-9 - 1.0).abs() < 1e-6,
            "{scale}"
        );
    }
    // Differences beyond the largest double.
    let far = relative_height([-1e308, 0.0, 0.0], [1e308, 0.0, 0.0], [0.0, 1e308, 0.0]);
    assert!((far - 0.5).abs() < 1e-15);
    assert_eq!(relative_height([0.0; 3], [1.0; 3], [2.0; 3]), 0.0);
    assert!(relative_height([0.0; 3], [f64::NAN, 0.0, 0.0], [1.0; 3]).is_nan());
}

#[test]
fn near_degenerate_triangles_and_polygons_are_found() {
    use surftopo_mesh::geometry::{
        NEAR_DEGENERATE_RELATIVE_HEIGHT, is_near_degenerate_triangle, near_degenerate_faces,
    };
    let o = [0.0; 3];
    let x = [1.0, 0.0, 0.0];
    let at = |h: f64| [0.5, h, 0.0];
    assert!(is_near_degenerate_triangle(o, x, at(1e-7)));
    assert!(is_near_degenerate_triangle(o, x, at(1e-300)));
    assert!(!is_near_degenerate_triangle(o, x, at(1e-5)));
    assert!(
        !is_near_degenerate_triangle(o, x, at(0.0)),
        "exactly flat is a problem instead"
    );

    // Faces: a good triangle, a needle, a flat triangle (a problem, not a warning), a
    // quadrilateral whose every triangulation has a needle (a corner nearly on the diagonal), a
    // flat quadrilateral, a triangle repeating a vertex.
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.5, 1e-8, 0.0],
        [2.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [3.0, 0.0, 0.0],
        [0.5, -1e-8, 0.0],
    ];
    let faces: [&[u32]; 6] = [
        &[0, 1, 2],
        &[0, 1, 3],
        &[0, 1, 4],
        &[0, 7, 1, 3],
        &[0, 1, 4, 6],
        &[0, 1, 1],
    ];
    let cut = surftopo_mesh::triangulate_polygons(&positions, faces);
    let found: Vec<usize> = near_degenerate_faces(&positions, &cut)
        .into_iter()
        .map(|(f, h)| {
            assert!(h < NEAR_DEGENERATE_RELATIVE_HEIGHT);
            f
        })
        .collect();
    assert_eq!(found, [1, 3]);
}

#[test]
fn welding_is_suggested_when_it_closes_or_joins() {
    use surftopo_mesh::geometry::weld_effect;
    let tetra_positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ];
    // The tetrahedron as a soup: every triangle on three vertices of its own.
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    for t in TETRA {
        let base = positions.len() as u32;
        positions.extend(t.map(|v| tetra_positions[v as usize]));
        triangles.push([base, base + 1, base + 2]);
    }
    let before = inspect(positions.len(), &triangles);
    let effect = weld_effect(&positions, &triangles, &before).expect("welding closes it");
    assert_eq!(effect.merged, 8);
    assert!(effect.after.is_closed() && effect.after.components == 1);
    assert_eq!(
        effect.describe(),
        "would merge 8 vertices into others at the same position, making one closed surface (sphere)"
    );
    // A closed surface, and a soup whose positions are all distinct: nothing to suggest.
    let closed = inspect(4, &TETRA);
    assert_eq!(weld_effect(&tetra_positions, &TETRA, &closed), None);
    let apart: Vec<[f64; 3]> = (0..12).map(|i| [f64::from(i), 0.5, 0.25]).collect();
    assert_eq!(weld_effect(&apart, &triangles, &before), None);
    // Welding that would make an edge non-manifold (three triangles on one edge) is no fix.
    let fins = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, -1.0, 0.0],
        [0.0, 0.0, 1.0],
    ];
    let fin_positions: Vec<[f64; 3]> = [0, 1, 2, 0, 1, 3, 0, 1, 4].map(|i| fins[i]).to_vec();
    let fin_triangles = [[0, 1, 2], [3, 4, 5], [6, 7, 8]];
    let before = inspect(9, &fin_triangles);
    assert_eq!(weld_effect(&fin_positions, &fin_triangles, &before), None);
}

#[test]
fn the_build_report_maps_vertex_ids_back_to_the_input() {
    // The tetrahedron on vertices 1, 3, 4, 6 of seven (0, 2 and 5 unreferenced).
    let faces = TETRA.map(|t| t.map(|v| [1, 3, 4, 6][v as usize]));
    let (_, report) = surftopo_mesh::build(7, &faces).unwrap();
    assert_eq!(report.input_vertices(), [1, 3, 4, 6]);
    for (id, &input) in report.input_vertices().iter().enumerate() {
        assert_eq!(report.vertex_old_to_new[input as usize].idx(), id);
    }
}
