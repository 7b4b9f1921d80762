//! Portalgon files of big polygons: the gluing is validated before any polygon is checked or
//! cut, and a polygon of thousands of corners is cut into triangles (O(k log k)) rather than
//! along shortcuts (a full sort of the O(k²) corner pairs per cut).

mod common;

use common::{surftopo, write};

/// A portalgon file of one convex polygon of `k` integer corners on a circle of radius 10⁹,
/// with the given `matching` (JSON array text).
fn one_polygon(k: usize, matching: &str) -> String {
    let corners: Vec<String> = (0..k)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / k as f64;
            let (x, y) = ((1e9 * a.cos()).round(), (1e9 * a.sin()).round());
            format!("[{x}, {y}]")
        })
        .collect();
    format!(
        r#"{{"format": "surftopo-portalgon", "version": 1, "polygons": [{{"corners": [{}]}}], "matching": {matching}}}"#,
        corners.join(", ")
    )
}

#[test]
fn a_missing_gluing_of_a_big_polygon_is_named_before_any_cut() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(dir.path(), "open.json", &one_polygon(2000, "[]"));
    let start = std::time::Instant::now();
    for exact in [false, true] {
        let mut command = surftopo();
        command.args(["delaunay", path.to_str().unwrap(), "--json"]);
        if exact {
            command.args(["--method", "voronoi", "--exact"]);
        }
        let out = command.output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        if !exact {
            // Free sides are a boundary: one polygon without gluing is a disk, cut into
            // triangles in O(k log k) and flipped on its cover.
            assert!(out.status.success(), "{err}");
            continue;
        }
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(err.contains("open.json"), "{err}");
        assert!(
            err.contains("side 0 of polygon 0 is unmatched"),
            "the first free side named: {err}"
        );
    }
    // Not a timing test: a generous bound that the shortcut rule (minutes) could not meet.
    assert!(start.elapsed().as_secs() < 60, "{:?}", start.elapsed());
}
