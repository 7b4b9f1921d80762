//! `surftopo quad --objective`: quality and quality-fast write a closed quad mesh of the input's
//! genus, their JSON carries the objective, cost, gap and quality keys, the exact cost is at most
//! the fast one and the count objective's, and the same input gives the same bytes.

mod common;

use common::{json_of, surftopo};

fn quad_json(
    input: &std::path::Path,
    output: &std::path::Path,
    objective: &str,
) -> serde_json::Value {
    let mut quad = surftopo();
    quad.args(["quad"])
        .arg(input)
        .arg("-o")
        .arg(output)
        .args(["--objective", objective, "--json"]);
    json_of(&mut quad, &[])
}

#[test]
fn quality_objectives_write_certified_quads_with_their_figures() {
    let dir = tempfile::tempdir().unwrap();
    let input = common::generated_genus_surface(dir.path(), "g2.obj", 2);
    let mut costs = std::collections::HashMap::new();
    for objective in ["count", "quality", "quality-fast"] {
        let output = dir.path().join(format!("q-{objective}.obj"));
        let v = quad_json(&input, &output, objective);
        for key in [
            "objective",
            "cost",
            "optimality_gap",
            "quality",
            "bad_quads_percent",
            "median_max_angle_deviation",
            "faces",
        ] {
            assert!(v.get(key).is_some(), "{objective}: no key {key}");
        }
        assert_eq!(v["objective"], objective);
        for key in ["min", "p5", "median", "mean"] {
            let q = v["quality"][key].as_f64().unwrap();
            assert!((0.0..=1.0).contains(&q), "{objective}: quality {key} {q}");
        }
        if objective == "quality" {
            assert_eq!(v["optimality_gap"].as_f64(), Some(0.0));
        }
        costs.insert(objective, v["cost"].as_f64().unwrap());
        let quads = surftopo_io::read_path(&output).unwrap();
        let polygons: Vec<Vec<u32>> = quads.faces().map(<[u32]>::to_vec).collect();
        assert!(
            polygons.iter().all(|p| p.len() == 4),
            "{objective}: not all quads"
        );
        let chi = surftopo_testkit::check_closed_oriented_manifold(&polygons)
            .unwrap_or_else(|e| panic!("{objective}: {e}"));
        assert_eq!(chi, -2, "{objective}: genus changed");
        // Deterministic: the same bytes again.
        let again = dir.path().join(format!("again-{objective}.obj"));
        quad_json(&input, &again, objective);
        assert_eq!(
            std::fs::read(&output).unwrap(),
            std::fs::read(&again).unwrap()
        );
    }
    assert!(costs["quality"] <= costs["quality-fast"] + 1e-9);
    assert!(costs["quality"] <= costs["count"] + 1e-9);
}

#[test]
fn unknown_objective_is_a_usage_error() {
    let out = surftopo()
        .args(["quad", "x.obj", "-o", "y.obj", "--objective", "beauty"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}
