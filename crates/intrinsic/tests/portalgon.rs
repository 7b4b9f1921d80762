//! Portalgons: the JSON format (round trips, typed errors) and the elementary edits (cut, merge,
//! shortcuts, sub-portalgons, regions, mirror images).

mod common;

use surftopo_intrinsic::generators::{flat_torus, flat_torus_portalgon};
use surftopo_intrinsic::geometry::{Rational, Scalar};
use surftopo_intrinsic::{
    DEFAULT_LENGTH_TOLERANCE, DelaunayOptions, IntrinsicTriangulation, PolygonId, Portalgon,
    PortalgonDoc, PortalgonError, Regions, TriangleStyle, check_polygon, flip_to_delaunay,
    signed_area,
};
use surftopo_mesh::generators::icosphere;

const T3: &str = r#"{
  "format": "surftopo-portalgon",
  "version": 1,
  "comment": "the flat torus T_3 of Dubois, Section 9",
  "polygons": [
    { "corners": [[0, 0], [1, 0], [3, 2]], "vertices": [0, 0, 0] },
    { "lengths": [1, 2.8284271247461903, 3.605551275463989], "vertices": [0, 0, 0] }
  ],
  "matching": [ [[0, 0], [1, 0]], [[0, 1], [1, 1]], [[0, 2], [1, 2]] ]
}"#;

#[test]
fn the_documented_example_is_t_3() {
    let doc = PortalgonDoc::from_json(T3).unwrap();
    let mut tri = doc.to_triangulation(DEFAULT_LENGTH_TOLERANCE).unwrap();
    let m = tri.mesh();
    assert_eq!(
        (m.vertex_count(), m.edge_count(), m.face_count()),
        (1, 3, 2)
    );
    assert!((common::area(&tri) - 2.0).abs() < 1e-12);
    let report = flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
    assert_eq!(report.flips, 2);
    // As a general portalgon too.
    let p = doc.to_portalgon(DEFAULT_LENGTH_TOLERANCE).unwrap();
    assert_eq!((p.polygon_count(), p.side_count()), (2, 6));
    assert_eq!(p.vertex_classes().1, 1);
    assert!((p.area() - 2.0).abs() < 1e-12);
    p.check_closed().unwrap();
}

#[test]
fn triangulations_round_trip_through_json() {
    let s = icosphere(2);
    let mut tri = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap();
    flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
    let text = PortalgonDoc::from_triangulation(&tri, TriangleStyle::Lengths)
        .to_json()
        .unwrap();
    let back = PortalgonDoc::from_json(&text)
        .unwrap()
        .to_triangulation(DEFAULT_LENGTH_TOLERANCE)
        .unwrap();
    // Same ids, same orientation, bit-identical lengths.
    assert_same_faces(&back, &tri, 0.0);
    assert_eq!(back.lengths(), tri.lengths());
    for e in tri.mesh().edges() {
        assert_eq!(back.mesh().edge_vertices(e), tri.mesh().edge_vertices(e));
    }
    // With corners: same combinatorics, lengths up to the layout's rounding.
    let mut bytes = Vec::new();
    tri.write_json(&mut bytes, TriangleStyle::Corners).unwrap();
    let back = IntrinsicTriangulation::read_json(&bytes[..], DEFAULT_LENGTH_TOLERANCE).unwrap();
    assert_same_faces(&back, &tri, 1e-14);
    for e in tri.mesh().edges() {
        assert_eq!(back.mesh().edge_vertices(e), tri.mesh().edge_vertices(e));
    }
    // Through the general portalgon as well (edges are then numbered by the portalgon's sides).
    let (p, _) = tri.to_portalgon();
    let back = IntrinsicTriangulation::from_portalgon(&p, DEFAULT_LENGTH_TOLERANCE).unwrap();
    assert_same_faces(&back, &tri, 1e-14);
}

#[test]
fn loops_and_multi_edges_round_trip() {
    for (x, m) in [(3.0, 1), (2.5, 2)] {
        let mut tri = flat_torus(x, m).unwrap();
        flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
        let text = PortalgonDoc::from_triangulation(&tri, TriangleStyle::Lengths)
            .to_json()
            .unwrap();
        let back = IntrinsicTriangulation::read_json(text.as_bytes(), 0.0).unwrap();
        assert_same_faces(&back, &tri, 0.0);
        assert_eq!(back.lengths(), tri.lengths());
    }
}

/// Same faces (ids, corner vertices, side lengths within `tol` relative), whatever the edge ids
/// and the stored half-edges.
fn assert_same_faces(a: &IntrinsicTriangulation, b: &IntrinsicTriangulation, tol: f64) {
    let (ma, mb) = (a.mesh(), b.mesh());
    assert_eq!(ma.face_slots(), mb.face_slots());
    assert_eq!(ma.edge_count(), mb.edge_count());
    for f in ma.faces() {
        assert_eq!(ma.face_vertices(f), mb.face_vertices(f), "face {f:?}");
        let (la, lb) = (common::sides(a, f), common::sides(b, f));
        for k in 0..3 {
            assert!(
                (la[k] - lb[k]).abs() <= tol * la[k],
                "face {f:?}: {la:?} vs {lb:?}"
            );
        }
        // Neighbours across each side are the same faces.
        for (ha, hb) in ma.face_halfedges(f).into_iter().zip(mb.face_halfedges(f)) {
            assert_eq!(ma.face(ha.twin()), mb.face(hb.twin()));
        }
    }
}

fn error_of(text: &str) -> PortalgonError {
    match PortalgonDoc::from_json(text).and_then(|d| d.to_triangulation(1e-9)) {
        Err(e) => e,
        Ok(_) => panic!("accepted: {text}"),
    }
}

#[test]
fn bad_files_get_typed_errors_naming_the_element() {
    let tri = |a: &str, b: &str, matching: &str| {
        format!(r#"{{"polygons": [{a}, {b}], "matching": {matching}}}"#)
    };
    let p0 = r#"{"lengths": [1, 2.8284271247461903, 3.605551275463989]}"#;
    let ok_matching = "[[[0,0],[1,0]], [[0,1],[1,1]], [[0,2],[1,2]]]";
    // Unequal matched sides: polygon 1 side 1 is a bit longer.
    let p1 = r#"{"lengths": [1, 2.83, 3.605551275463989]}"#;
    match error_of(&tri(p0, p1, ok_matching)) {
        PortalgonError::UnequalSides {
            polygon_a: 0,
            side_a: 1,
            polygon_b: 1,
            side_b: 1,
            ..
        } => {}
        e => panic!("{e}"),
    }
    // An unmatched side.
    match error_of(&tri(p0, p0, "[[[0,0],[1,0]], [[0,1],[1,1]]]")) {
        PortalgonError::Unmatched {
            polygon: 0,
            side: 2,
        } => {}
        e => panic!("{e}"),
    }
    // A side matched twice.
    match error_of(&tri(
        p0,
        p0,
        "[[[0,0],[1,0]], [[0,0],[1,1]], [[0,2],[1,2]]]",
    )) {
        PortalgonError::MatchedTwice {
            polygon: 0,
            side: 0,
        } => {}
        e => panic!("{e}"),
    }
    // A side that does not exist.
    match error_of(&tri(p0, p0, "[[[0,0],[1,3]]]")) {
        PortalgonError::NoSuchSide {
            polygon: 1,
            side: 3,
        } => {}
        e => panic!("{e}"),
    }
    // A quadrilateral where a triangulation is needed, and lengths for it.
    let quad = r#"{"corners": [[0,0],[1,0],[1,1],[0,1]]}"#;
    assert!(matches!(
        error_of(&tri(p0, quad, "[]")),
        PortalgonError::NotTriangle {
            polygon: 1,
            sides: 4
        }
    ));
    let four = r#"{"lengths": [1, 1, 1, 1]}"#;
    assert!(matches!(
        error_of(&tri(p0, four, "[]")),
        PortalgonError::LengthsNotTriangle {
            polygon: 1,
            count: 4
        }
    ));
    // A clockwise triangle.
    let cw = r#"{"corners": [[0,0],[3,2],[1,0]]}"#;
    assert!(matches!(
        error_of(&tri(p0, cw, ok_matching)),
        PortalgonError::NotCounterClockwise { polygon: 1, .. }
    ));
    // Labels that contradict the gluing (T_3 has one vertex).
    let l0 = r#"{"lengths": [1, 2.8284271247461903, 3.605551275463989], "vertices": [0, 1, 0]}"#;
    assert!(matches!(
        error_of(&tri(l0, l0, ok_matching)),
        PortalgonError::VertexLabels { .. }
    ));
    // Labels on some polygons only.
    let l1 = r#"{"lengths": [1, 2.8284271247461903, 3.605551275463989], "vertices": [0, 0, 0]}"#;
    assert!(matches!(
        error_of(&tri(l1, p0, ok_matching)),
        PortalgonError::VertexLabels { polygon: 1, .. }
    ));
    // Not JSON, a typo'd field, another format, no polygons, both shapes.
    assert!(matches!(error_of("{"), PortalgonError::Json(_)));
    assert!(matches!(
        error_of(r#"{"polygons": [], "matchings": []}"#),
        PortalgonError::Json(_)
    ));
    assert!(matches!(
        error_of(r#"{"format": "obj", "polygons": []}"#),
        PortalgonError::Version { .. }
    ));
    assert!(matches!(
        error_of(r#"{"polygons": []}"#),
        PortalgonError::Empty
    ));
    let both = r#"{"corners": [[0,0],[1,0],[0,1]], "lengths": [1,1,1]}"#;
    assert!(matches!(
        error_of(&tri(p0, both, ok_matching)),
        PortalgonError::Shape { polygon: 1 }
    ));
    // Two components.
    let four_tris = r#"{"polygons": [{"lengths":[1,1,1]},{"lengths":[1,1,1]},{"lengths":[1,1,1]},{"lengths":[1,1,1]}],
        "matching": [[[0,0],[1,2]],[[0,1],[1,1]],[[0,2],[1,0]],[[2,0],[3,2]],[[2,1],[3,1]],[[2,2],[3,0]]]}"#;
    assert!(matches!(error_of(four_tris), PortalgonError::Gluing(_)));
}

#[test]
fn degenerate_triangles_are_read_and_left_to_validation() {
    // A zero-area triangle given by lengths is read (it may still be mollified).
    let text = r#"{"polygons": [{"lengths": [1, 1, 2]}, {"lengths": [1, 1, 2]}],
        "matching": [[[0,0],[1,1]], [[0,1],[1,0]], [[0,2],[1,2]]]}"#;
    let tri = PortalgonDoc::from_json(text)
        .unwrap()
        .to_triangulation(1e-9)
        .unwrap();
    assert!(tri.validate().is_err());
    // The general portalgon refuses it outright.
    assert!(matches!(
        PortalgonDoc::from_json(text).unwrap().to_portalgon(1e-9),
        Err(PortalgonError::TriangleInequality { polygon: 0, .. })
    ));
}

#[test]
fn polygon_validation() {
    assert!(check_polygon(0, &[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]).is_ok());
    assert!(matches!(
        check_polygon(3, &[[0.0, 0.0], [0.0, 1.0], [1.0, 0.0]]),
        Err(PortalgonError::NotCounterClockwise { polygon: 3, .. })
    ));
    // A bow tie with positive signed area.
    let bow = [[0.0, 0.0], [2.0, 0.0], [0.0, 1.0], [3.0, 1.0]];
    assert!(matches!(
        check_polygon(0, &bow),
        Err(PortalgonError::NotSimple { .. }) | Err(PortalgonError::NotCounterClockwise { .. })
    ));
    let bow = [[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [1.0, -1.0], [0.0, 3.0]];
    assert!(matches!(
        check_polygon(0, &bow),
        Err(PortalgonError::NotSimple { .. })
    ));
    assert!(matches!(
        check_polygon(0, &[[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [0.0, 1.0]]),
        Err(PortalgonError::ZeroSide { side: 1, .. })
    ));
    assert!(matches!(
        check_polygon(0, &[[0.0, 0.0], [f64::NAN, 0.0], [0.0, 1.0]]),
        Err(PortalgonError::NonFinite { index: 1, .. })
    ));
    assert!(matches!(
        check_polygon(0, &[[0.0, 0.0], [1.0, 0.0]]),
        Err(PortalgonError::TooFewCorners { corners: 2, .. })
    ));
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

#[test]
fn cut_and_merge_are_inverse() {
    let mut p = Portalgon::new();
    let square = p
        .add_polygon(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])
        .unwrap();
    p.check_invariants().unwrap();
    let before = p.corners(square);
    // 0-1 is a side, not an arc; 0-2 is a diagonal.
    assert!(!p.is_arc(square, 0, 1));
    assert!(p.is_arc(square, 0, 2) && p.is_arc(square, 3, 1));
    let (in_p, in_q) = p.cut(square, 0, 2).unwrap();
    p.check_invariants().unwrap();
    assert_eq!(p.mate(in_p), Some(in_q));
    assert_eq!((p.polygon_count(), p.side_count()), (2, 6));
    let q = p.owner(in_q);
    assert_eq!(p.polygon_sides(square).len(), 3);
    assert_eq!(p.polygon_sides(q).len(), 3);
    assert!((p.area() - 4.0).abs() < 1e-15);
    assert!((p.side_length(in_p) - 8f64.sqrt()).abs() < 1e-15);
    // Displace q (another representation of the same portalgon), then merge back.
    let merged = p.merge(in_p).unwrap();
    p.check_invariants().unwrap();
    assert_eq!(merged, square);
    assert_eq!((p.polygon_count(), p.side_count()), (1, 4));
    let after = p.corners(square);
    for (a, b) in before.iter().zip(&after) {
        assert!(dist(*a, *b) < 1e-15, "{before:?} vs {after:?}");
    }
    // Merging across an unmatched side is refused.
    let s0 = p.side(square, 0);
    assert!(matches!(
        p.merge(s0),
        Err(PortalgonError::CannotMerge { .. })
    ));
    p.check_invariants().unwrap();
}

#[test]
fn merge_displaces_the_other_polygon_rigidly() {
    // Two unit right triangles in unrelated positions, glued along their hypotenuses.
    let mut p = Portalgon::new();
    let a = p
        .add_polygon(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
        .unwrap();
    let b = p
        .add_polygon(&[[10.0, 10.0], [10.0, 9.0], [11.0, 10.0]])
        .unwrap();
    p.check_invariants().unwrap();
    // a: side 1 from (1,0) to (0,1); b: side 1 from (10,9) to (11,10), also √2 long.
    p.glue(p.side(a, 1), p.side(b, 1), 1e-12).unwrap();
    p.check_invariants().unwrap();
    let merged = p.merge(p.side(a, 1)).unwrap();
    p.check_invariants().unwrap();
    let c = p.corners(merged);
    assert_eq!(c.len(), 4);
    // A unit square: sides 1, diagonals √2.
    for i in 0..4 {
        assert!((dist(c[i], c[(i + 1) % 4]) - 1.0).abs() < 1e-14, "{c:?}");
    }
    assert!((dist(c[0], c[2]) - 2f64.sqrt()).abs() < 1e-14);
    assert!((p.polygon_area(merged) - 1.0).abs() < 1e-14);
}

#[test]
fn merge_in_f64_stays_rigid_across_a_short_side_whose_lengths_differ() {
    // Two long thin triangles glued along a short side (length 1e-4) whose two copies differ by
    // 1e-12 in length (rounding of an earlier computation): footnote 2's quotient would scale
    // the moved triangle by 1 + 1e-8; the f64 gluing is a rotation, so its long sides keep their
    // lengths.
    let mut p = Portalgon::new();
    let a = p
        .add_polygon(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1e-4]])
        .unwrap();
    let short = 1e-4 + 1e-12;
    let b = p
        .add_polygon(&[[5.0, 5.0], [5.0 + short, 5.0], [5.0, 6.0]])
        .unwrap();
    let long_b = p.side_length(p.side(b, 1));
    p.glue(p.side(a, 1), p.side(b, 0), 1e-6).unwrap();
    let merged = p.merge(p.side(a, 1)).unwrap();
    let lengths: Vec<f64> = p
        .polygon_sides(merged)
        .iter()
        .map(|&s| p.side_length(s))
        .collect();
    assert!(
        lengths.iter().any(|l| (l - long_b).abs() < 1e-14),
        "the moved triangle's long side keeps its length {long_b}: {lengths:?}"
    );
}

#[test]
fn glue_at_scale_accepts_a_short_side_off_by_rounding_at_its_polygons_scale() {
    // Sides of length 1e-4 and 1e-4 + 1e-11: 1e-7 apart relative to themselves, 1e-11 relative
    // to a unit polygon.
    let mut p = Portalgon::new();
    let a = p
        .add_polygon(&[[0.0, 0.0], [1e-4, 0.0], [0.0, 1.0]])
        .unwrap();
    let b = p
        .add_polygon(&[[0.0, 0.0], [1e-4 + 1e-11, 0.0], [0.0, 1.0]])
        .unwrap();
    let (s, t) = (p.side(a, 0), p.side(b, 0));
    assert!(matches!(
        p.glue(s, t, 1e-9),
        Err(PortalgonError::UnequalSides { .. })
    ));
    assert!(matches!(
        p.glue_at_scale(s, t, 1e-9, 1e-3),
        Err(PortalgonError::UnequalSides { .. })
    ));
    p.glue_at_scale(s, t, 1e-9, 1.0).unwrap();
    assert_eq!(p.mate(s), Some(t));
    // Exact mode ignores the scale: lengths must be equal.
    let r = |x: &str| x.parse::<Rational>().unwrap();
    let mut e = Portalgon::<Rational>::empty();
    let a = e
        .add_polygon(&[[r("0"), r("0")], [r("1/10000"), r("0")], [r("0"), r("1")]])
        .unwrap();
    let b = e
        .add_polygon(&[
            [r("0"), r("0")],
            [r("1/10000") + r("1/100000000000"), r("0")],
            [r("0"), r("1")],
        ])
        .unwrap();
    assert!(
        e.glue_at_scale(e.side(a, 0), e.side(b, 0), 1e-9, 1.0)
            .is_err()
    );
}

#[test]
fn shortcuts_and_insert_edges() {
    let mut p = Portalgon::new();
    // A kite: the diagonal 1-3 (length 2) is shorter than 0-2 (length 4).
    let kite = p
        .add_polygon(&[[0.0, 0.0], [1.0, 1.0], [0.0, 4.0], [-1.0, 1.0]])
        .unwrap();
    assert_eq!(p.shortcut(kite), Some((1, 3)));
    // An arrowhead (reflex corner 2): 0-2 lies inside, 1-3 passes outside.
    let arrow = p
        .add_polygon(&[[0.0, 0.0], [2.0, -1.0], [0.5, 0.0], [2.0, 1.0]])
        .unwrap();
    p.check_invariants().unwrap();
    assert!(!p.is_arc(arrow, 1, 3));
    assert!(p.is_arc(arrow, 0, 2));
    assert_eq!(p.shortcut(arrow), Some((0, 2)));
    // A regular hexagon: INSERTEDGES gives 4 triangles, 3 new matched pairs, same area.
    let hex: Vec<[f64; 2]> = (0..6)
        .map(|k| {
            let t = std::f64::consts::PI / 3.0 * f64::from(k);
            [t.cos(), t.sin()]
        })
        .collect();
    let h = p.add_polygon(&hex).unwrap();
    p.check_invariants().unwrap();
    let area = p.polygon_area(h);
    let tris = p.triangulate_by_shortcuts(h).unwrap();
    p.check_invariants().unwrap();
    assert_eq!(tris.len(), 4);
    let total: f64 = tris.iter().map(|&t| p.polygon_area(t)).sum();
    assert!((total - area).abs() < 1e-14);
    let matched = tris
        .iter()
        .flat_map(|&t| p.polygon_sides(t).to_vec())
        .filter(|&s| p.mate(s).is_some())
        .count();
    assert_eq!(matched, 6);
    // The first shortcut of a regular hexagon is a short diagonal (√3), not a long one (2); the
    // greedy sequence may then be left with a rectangle whose diagonals are both long.
    let mut q = Portalgon::new();
    let h = q.add_polygon(&hex).unwrap();
    q.check_invariants().unwrap();
    let (i, j) = q.shortcut(h).unwrap();
    assert!((dist(hex[i], hex[j]) - 3f64.sqrt()).abs() < 1e-12);
    for &t in &tris {
        for &s in p.polygon_sides(t) {
            let l = p.side_length(s);
            assert!(
                [1.0, 3f64.sqrt(), 2.0]
                    .iter()
                    .any(|w| (l - w).abs() < 1e-12),
                "{l}"
            );
        }
    }
}

#[test]
fn sub_portalgons_regions_and_vertex_classes() {
    let mut tri = flat_torus(2.5, 3).unwrap();
    flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
    let (p, _) = tri.to_portalgon();
    assert_eq!(p.vertex_classes().1, 9);
    p.check_closed().unwrap();
    // Half of the triangles as one region.
    let mut regions = Regions::new(&p);
    let r = regions.new_region();
    let half: Vec<PolygonId> = p.polygons().take(9).collect();
    for &q in &half {
        regions.assign(q, r);
    }
    let (sub, map) = regions.sub_portalgon(&p, r);
    sub.check_invariants().unwrap();
    assert_eq!(sub.polygon_count(), 9);
    // A side of the sub-portalgon is boundary iff it was matched across the region border.
    for s in p.sides() {
        if !map[s.idx()].is_valid() {
            continue;
        }
        let boundary = sub.mate(map[s.idx()]).is_none();
        assert_eq!(boundary, regions.is_separating(&p, s));
    }
    assert!(sub.unmatched_sides().count() > 0);
    assert!(sub.check_closed().is_err());
    assert!((sub.area() + regions.sub_portalgon(&p, 0).0.area() - 2.0).abs() < 1e-12);
    // Ungluing and gluing back.
    let mut q = p.clone();
    let s = q.sides().next().unwrap();
    let t = q.unglue(s).unwrap();
    q.check_invariants().unwrap();
    assert!(q.check_closed().is_err());
    q.glue(s, t, 1e-12).unwrap();
    q.check_invariants().unwrap();
    assert_eq!(q, p);
}

#[test]
fn the_mirror_image_of_the_mirror_image_is_the_original() {
    let s = icosphere(1);
    let tri = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap();
    let (p, _) = tri.to_portalgon();
    p.check_invariants().unwrap();
    let m = p.mirrored();
    m.check_invariants().unwrap();
    assert_eq!(m.vertex_classes().1, p.vertex_classes().1);
    assert!((m.area() - p.area()).abs() < 1e-12);
    assert_ne!(m, p);
    assert_eq!(m.mirrored(), p);
}

/// The edits in exact arithmetic: footnote 2's motion keeps rational corners exact, so cutting,
/// merging and deleting a flat vertex give back exactly the corners expected.
#[test]
fn exact_edits_stay_exact() {
    let r = |x: &str| x.parse::<Rational>().unwrap();
    let pt = |x: &str, y: &str| [r(x), r(y)];
    // Four triangles around the centre (1/3, 1/3) of a kite-shaped quadrilateral, each in its own
    // displaced copy of the plane (translated by rational vectors).
    let quad = [
        pt("0", "0"),
        pt("1", "0"),
        pt("5/3", "7/5"),
        pt("-1/2", "1"),
    ];
    let centre = pt("1/3", "1/3");
    let mut p: Portalgon<Rational> = Portalgon::empty();
    let mut tris = Vec::new();
    for i in 0..4 {
        let shift = [Rational::from_i64(10 * i), r("1/7")];
        let moved = |c: &[Rational; 2]| {
            [
                c[0].clone() + shift[0].clone(),
                c[1].clone() + shift[1].clone(),
            ]
        };
        let t = p
            .add_polygon(&[
                moved(&centre),
                moved(&quad[i as usize]),
                moved(&quad[(i as usize + 1) % 4]),
            ])
            .unwrap();
        p.check_invariants().unwrap();
        tris.push(t);
    }
    // Side 2 of triangle i (from quad[i+1] to the centre) is glued to side 0 of triangle i+1.
    for i in 0..4 {
        p.glue(p.side(tris[i], 2), p.side(tris[(i + 1) % 4], 0), 0.0)
            .unwrap();
        p.check_invariants().unwrap();
    }
    assert_eq!(p.area(), signed_area(&quad));
    let merged = p.merge(p.side(tris[0], 2)).unwrap();
    p.check_invariants().unwrap();
    assert_eq!(p.polygon_sides(merged).len(), 4);
    let square = p.delete_vertex(p.side(merged, 0), 0.0).unwrap();
    p.check_invariants().unwrap();
    let corners = p.corners(square);
    assert_eq!(corners.len(), 4);
    // The quadrilateral, exactly, translated as triangle 0 was.
    let shift = [Rational::zero(), r("1/7")];
    let expected: Vec<[Rational; 2]> = quad
        .iter()
        .map(|c| {
            [
                c[0].clone() + shift[0].clone(),
                c[1].clone() + shift[1].clone(),
            ]
        })
        .collect();
    let start = expected.iter().position(|c| *c == corners[0]).unwrap();
    for (k, c) in corners.iter().enumerate() {
        assert_eq!(*c, expected[(start + k) % 4]);
    }
    // Lengths are compared exactly: a side one part in 10^30 longer is refused.
    let mut q: Portalgon<Rational> = Portalgon::empty();
    let a = q
        .add_polygon(&[pt("0", "0"), pt("1", "0"), pt("0", "1")])
        .unwrap();
    let b = q
        .add_polygon(&[
            pt("0", "0"),
            pt(
                "1000000000000000000000000000001/1000000000000000000000000000000",
                "0",
            ),
            pt("0", "1"),
        ])
        .unwrap();
    assert!(matches!(
        q.glue(q.side(a, 0), q.side(b, 0), 1e-9),
        Err(PortalgonError::UnequalSides { .. })
    ));
    q.check_invariants().unwrap();
}

/// Exact numbers in the JSON: strings hold decimals and fractions, numbers are the doubles they
/// parse to; the exact writer writes a number exactly when the value is a double.
#[test]
fn exact_coordinates_round_trip_through_json() {
    let text = r#"{
      "polygons": [
        { "corners": [[0, 0], ["3000000001/3", "0"], ["1000000000.333", 2]] },
        { "corners": [["3000000001/3", 0], ["6000000001/3", 2], ["1000000000.333", 2]] }
      ],
      "matching": [ [[0, 1], [1, 2]] ]
    }"#;
    let doc = PortalgonDoc::from_json(text).unwrap();
    let p = doc.to_portalgon_in::<Rational>(0.0).unwrap();
    p.check_invariants().unwrap();
    let r = |x: &str| x.parse::<Rational>().unwrap();
    assert_eq!(
        p.start(p.side(PolygonId(0), 1)),
        [r("3000000001/3"), r("0")]
    );
    assert_eq!(p.start(p.side(PolygonId(0), 2))[0], r("1000000000333/1000"));
    // The exact writer: integers and doubles as numbers, the rest as "p/q" strings.
    let written = PortalgonDoc::from_portalgon(&p).to_json().unwrap();
    assert!(written.contains(r#"["3000000001/3",0.0]"#), "{written}");
    assert!(
        written.contains(r#"["1000000000333/1000",2.0]"#),
        "{written}"
    );
    let back = PortalgonDoc::from_json(&written)
        .unwrap()
        .to_portalgon_in::<Rational>(0.0)
        .unwrap();
    assert_eq!(back, p);
    // The same file in f64: the nearest doubles.
    let f = doc.to_portalgon(1e-9).unwrap();
    assert_eq!(f.start(f.side(PolygonId(0), 1))[0], 3000000001.0 / 3.0);
    // A JSON number literal is the decimal it spells in exact mode (0.1 is 1/10), its nearest
    // double in f64.
    let tenth =
        PortalgonDoc::from_json(r#"{"polygons": [{"corners": [[0, 0], [0.1, 0], [0, 1]]}]}"#)
            .unwrap();
    let exact = tenth.to_portalgon_in::<Rational>(0.0).unwrap();
    assert_eq!(exact.start(exact.side(PolygonId(0), 1))[0], r("1/10"));
    let double = tenth.to_portalgon(1e-9).unwrap();
    assert_eq!(double.start(double.side(PolygonId(0), 1))[0], 0.1);
    // The double nearest 1/10, written exactly, is a string (its shortest text would be 1/10).
    let near_tenth = Rational::from_f64(0.1).unwrap();
    let mut q = surftopo_intrinsic::Portalgon::<Rational>::empty();
    q.add_polygon(&[
        [r("0"), r("0")],
        [near_tenth.clone(), r("0")],
        [r("0"), r("1")],
    ])
    .unwrap();
    let written = PortalgonDoc::from_portalgon(&q).to_json().unwrap();
    assert!(
        written.contains(r#"["3602879701896397/36028797018963968",0.0]"#),
        "{written}"
    );
    let back = PortalgonDoc::from_json(&written)
        .unwrap()
        .to_portalgon_in::<Rational>(0.0)
        .unwrap();
    assert_eq!(back.start(back.side(PolygonId(0), 1))[0], near_tenth);
    // Version-1 files are read as before; lengths are refused in exact mode.
    let t3 = PortalgonDoc::from_json(T3).unwrap();
    assert!(matches!(
        t3.to_portalgon_in::<Rational>(0.0),
        Err(PortalgonError::LengthsNotExact { polygon: 1 })
    ));
    assert!(!t3.has_corners_only());
    // Bad strings are JSON errors with a position.
    for bad in [r#""1/0""#, r#""abc""#, r#""1e""#, "true"] {
        let text = format!(r#"{{"polygons": [{{"corners": [[0, 0], [{bad}, 0], [0, 1]]}}]}}"#);
        match PortalgonDoc::from_json(&text) {
            Err(PortalgonError::Json(m)) => assert!(m.contains("line 1"), "{m}"),
            other => panic!("{bad}: {other:?}"),
        }
    }
}

/// T_x by exact corners: for x = 10⁴ + 1/3 the two triangles, glued exactly, area 2, one vertex;
/// written and read back as the same portalgon. In double precision its lengths (exact, rounded
/// once) make triangles whose area is off by 2·10⁻⁵, beyond `Tolerances::exact_rounding`: refused
/// as beyond doubles; at x = 333 + 2/3 (off by 3·10⁻¹¹) read as a triangulation close to
/// [`flat_torus`].
#[test]
fn exact_flat_torus_by_corners() {
    let x: Rational = "30001/3".parse().unwrap();
    let doc = PortalgonDoc::from_portalgon(&flat_torus_portalgon(&x, 1).unwrap());
    match doc.to_triangulation(1e-9) {
        Err(PortalgonError::BeyondDoubles {
            polygon: 0,
            exact_area,
            rounded_area,
        }) => {
            assert_eq!(exact_area, 1.0);
            assert!((rounded_area - 1.0).abs() > 1e-6, "{rounded_area}");
        }
        other => panic!("{other:?}"),
    }
    let x: Rational = "1001/3".parse().unwrap();
    for m in [1, 3] {
        let p = flat_torus_portalgon(&x, m).unwrap();
        p.check_invariants().unwrap();
        p.check_closed().unwrap();
        assert_eq!(p.area(), Rational::from_i64(2));
        assert_eq!(p.vertex_classes().1, (m * m) as usize);
        let doc = PortalgonDoc::from_portalgon(&p);
        let text = doc.to_json().unwrap();
        let back = PortalgonDoc::from_json(&text).unwrap();
        assert_eq!(back.to_portalgon_in::<Rational>(0.0).unwrap(), p);
        let tri = back.to_triangulation(1e-9).unwrap();
        let reference = flat_torus(x.to_f64(), m).unwrap();
        // Same faces, lengths and neighbours; vertices the same up to renumbering.
        let (mt, mr) = (tri.mesh(), reference.mesh());
        assert_eq!(mt.face_slots(), mr.face_slots());
        let mut rename = std::collections::HashMap::new();
        for f in mt.faces() {
            let (lt, lr) = (common::sides(&tri, f), common::sides(&reference, f));
            for k in 0..3 {
                assert!((lt[k] - lr[k]).abs() <= 1e-12 * lr[k], "{lt:?} vs {lr:?}");
            }
            for (vt, vr) in mt.face_vertices(f).into_iter().zip(mr.face_vertices(f)) {
                assert_eq!(*rename.entry(vt).or_insert(vr), vr);
            }
            for (ht, hr) in mt.face_halfedges(f).into_iter().zip(mr.face_halfedges(f)) {
                assert_eq!(mt.face(ht.twin()), mr.face(hr.twin()));
            }
        }
        assert_eq!(rename.len(), (m * m) as usize);
    }
}

/// `Portalgon::shortcut`'s f64 decision: a corner that should be straight (a midpoint) rounded
/// an ulp off its line makes the segment across it an arc by exact signs, whose piece has zero
/// area in f64; that candidate is skipped in f64, while exact mode keeps the paper's rule.
#[test]
fn degenerate_shortcut_candidates_are_skipped_in_f64() {
    // a, m, b, c counter-clockwise; m is 1e-17 below the midpoint of ab (a convex corner by
    // exact signs), so ab (length 1) is the shortest arc, shorter than mc (about 2).
    let corners = [[0.0, 0.0], [0.5, -1e-17], [1.0, 0.0], [0.5, 2.0]];
    let mut p = Portalgon::new();
    let quad = p.add_polygon(&corners).unwrap();
    assert!(p.is_arc(quad, 0, 2), "an arc by exact signs");
    assert_eq!(p.shortcut(quad), Some((1, 3)));
    let pieces = p.triangulate_by_shortcuts(quad).unwrap();
    p.check_invariants().unwrap();
    for q in pieces {
        assert!(p.polygon_area(q) > 0.0);
    }
    // The same corners as exact rationals: the shortest arc, as the paper says.
    let exact: Vec<[Rational; 2]> = corners
        .iter()
        .map(|c| {
            [
                Rational::from_f64(c[0]).unwrap(),
                Rational::from_f64(c[1]).unwrap(),
            ]
        })
        .collect();
    let mut r = Portalgon::<Rational>::empty();
    let quad = r.add_polygon(&exact).unwrap();
    assert_eq!(r.shortcut(quad), Some((0, 2)));
}

/// The ```json blocks of PORTALGON_FORMAT.md.
fn documented_examples() -> Vec<String> {
    let text = include_str!("../PORTALGON_FORMAT.md");
    text.split("```json\n")
        .skip(1)
        .map(|block| block.split("```").next().unwrap().to_string())
        .collect()
}

#[test]
fn the_format_examples_round_trip_and_reversed_gluings_are_refused_where_orientation_is_needed() {
    let examples = documented_examples();
    assert_eq!(examples.len(), 2, "T_3 and the Möbius band");
    for text in &examples {
        let doc = PortalgonDoc::from_json(text).unwrap();
        // Writers write what they read: the same document, compact and pretty.
        for pretty in [false, true] {
            let mut out = Vec::new();
            doc.write(&mut out, pretty).unwrap();
            let back = PortalgonDoc::from_slice(&out).unwrap();
            assert_eq!(back, doc);
        }
        assert_eq!(doc.to_json().unwrap().contains(",true]"), doc.version == 2);
    }
    let mobius = PortalgonDoc::from_json(&examples[1]).unwrap();
    assert_eq!(mobius.version, 2);
    assert_eq!(mobius.reversed, [false, true]);
    let refused = PortalgonError::ReversedGluing {
        polygon: 0,
        side: 1,
    };
    assert_eq!(
        mobius.to_portalgon(DEFAULT_LENGTH_TOLERANCE).unwrap_err(),
        refused
    );
    assert_eq!(
        mobius
            .to_triangulation(DEFAULT_LENGTH_TOLERANCE)
            .unwrap_err(),
        refused
    );
    // A reversed gluing needs version 2; `false` is the plain gluing (written without a flag).
    let v1 = examples[1].replace("\"version\": 2", "\"version\": 1");
    let e = PortalgonDoc::from_json(&v1).unwrap_err();
    assert!(e.to_string().contains("needs \"version\": 2"), "{e}");
    let plain = examples[1].replace(", true]", ", false]");
    let doc = PortalgonDoc::from_json(&plain).unwrap();
    assert!(doc.reversed.is_empty());
    assert!(
        doc.to_json()
            .unwrap()
            .starts_with(r#"{"format":"surftopo-portalgon","version":2"#)
    );
    let mut v = doc.clone();
    v.version = 1;
    assert!(!v.to_json().unwrap().contains("false"));
    // Versions beyond 2 are refused.
    let v3 = examples[0].replace("\"version\": 1", "\"version\": 3");
    assert!(matches!(
        PortalgonDoc::from_json(&v3),
        Err(PortalgonError::Version { version: 3, .. })
    ));
}
