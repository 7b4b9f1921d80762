//! Diks–Stanczyk perfect matchings, each checked by the crate's verifier and by an independent
//! count in the test, on random bridgeless cubic multigraphs, mesh duals and small named graphs.

mod common;

use common::*;
use petgraph::graph::UnGraph;
use proptest::prelude::*;
use surftopo_matching::{
    CubicGraph, GraphError, PerfectPairing, diks_stanczyk as perfect_matching,
    diks_stanczyk_avoiding as perfect_matching_avoiding,
    diks_stanczyk_with_stats as perfect_matching_with_stats, verify_perfect_matching,
};

/// The matched flags of `m`, indexed by edge id of `g`.
fn flags(g: &CubicGraph, m: &PerfectPairing) -> Vec<bool> {
    m.edge_flags(g.edge_count() as usize)
}

/// Runs DS (plain and avoiding `avoid`) and checks both results twice.
fn check(n: u32, edges: Vec<[u32; 2]>, avoid: Option<u32>) {
    let g = CubicGraph::new(n, edges.clone()).expect("test graph must be valid");
    let (m, stats) = perfect_matching_with_stats(&g);
    assert_eq!(stats.reductions as u32, n / 2 - 1);
    verify_perfect_matching(&g, &flags(&g, &m)).unwrap();
    assert_perfect(n, &edges, &flags(&g, &m));
    assert_eq!(m.len() as u32, n / 2);
    assert!(!m.contains_edge(&g, 0), "default run avoids edge 0");
    if let Some(f) = avoid {
        let (m2, _) = perfect_matching_avoiding(&g, f).unwrap();
        verify_perfect_matching(&g, &flags(&g, &m2)).unwrap();
        assert_perfect(n, &edges, &flags(&g, &m2));
        assert!(!m2.contains_edge(&g, f), "edge {f} must be avoided");
    }
}

#[test]
fn theta_graph() {
    for f in 0..3 {
        check(2, vec![[0, 1], [1, 0], [0, 1]], Some(f));
    }
}

#[test]
fn named_small_graphs() {
    let k4 = vec![[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]];
    let k33 = vec![
        [0, 3],
        [0, 4],
        [0, 5],
        [1, 3],
        [1, 4],
        [1, 5],
        [2, 3],
        [2, 4],
        [2, 5],
    ];
    let prism = vec![
        [0, 1],
        [1, 2],
        [2, 0],
        [3, 4],
        [4, 5],
        [5, 3],
        [0, 3],
        [1, 4],
        [2, 5],
    ];
    let cube = vec![
        [0, 1],
        [1, 2],
        [2, 3],
        [3, 0],
        [4, 5],
        [5, 6],
        [6, 7],
        [7, 4],
        [0, 4],
        [1, 5],
        [2, 6],
        [3, 7],
    ];
    let mut petersen = Vec::new();
    for i in 0..5u32 {
        petersen.push([i, (i + 1) % 5]);
        petersen.push([i, i + 5]);
        petersen.push([5 + i, 5 + (i + 2) % 5]);
    }
    // A "necklace": a cycle of digons (every second edge doubled), the hardest case for choosing
    // a simple edge beside the avoided one.
    let mut necklace = Vec::new();
    for i in 0..6u32 {
        let (a, b) = (2 * i, 2 * i + 1);
        necklace.push([a, b]);
        necklace.push([a, b]);
        necklace.push([b, (2 * i + 2) % 12]);
    }
    for (n, edges) in [
        (4, k4),
        (6, k33),
        (6, prism),
        (8, cube),
        (10, petersen),
        (12, necklace),
    ] {
        for f in 0..edges.len() as u32 {
            check(n, edges.clone(), Some(f));
        }
    }
}

#[test]
fn necklace_needs_the_digon_fallback() {
    // A cycle of 2k nodes whose every second edge is doubled; edge 2 = 1-2 is single and has a
    // digon at both ends, so no simple edge touches it.
    for k in [2u32, 3, 10, 101] {
        let mut edges = Vec::new();
        for i in 0..k {
            let (a, b) = (2 * i, 2 * i + 1);
            edges.extend([[a, b], [a, b], [b, (2 * i + 2) % (2 * k)]]);
        }
        let g = CubicGraph::new(2 * k, edges.clone()).unwrap();
        let (m, stats) = perfect_matching_avoiding(&g, 2).unwrap();
        assert!(stats.digon_reductions > 0);
        assert!(!m.contains_edge(&g, 2));
        assert_perfect(2 * k, &edges, &flags(&g, &m));
    }
}

#[test]
fn every_avoided_edge_on_small_random_graphs() {
    for n in (4..=16).step_by(2) {
        for seed in 0..6 {
            let edges = ear_graph(n, seed);
            let g = CubicGraph::new(n, edges.clone()).unwrap();
            for f in 0..g.edge_count() {
                let (m, _) = perfect_matching_avoiding(&g, f).unwrap();
                assert_perfect(n, &edges, &flags(&g, &m));
                assert!(!m.contains_edge(&g, f));
            }
        }
    }
}

#[test]
fn random_ear_graphs_up_to_2000_nodes() {
    let mut seed = 0;
    for n in [
        4u32, 6, 8, 10, 12, 20, 32, 50, 64, 100, 128, 250, 500, 1000, 2000,
    ] {
        for _ in 0..4 {
            seed += 1;
            let edges = ear_graph(n, seed);
            let avoid = (seed as u32 * 7) % edges.len() as u32;
            check(n, edges, Some(avoid));
        }
    }
}

#[test]
fn random_configuration_model_graphs() {
    let mut seed = 100;
    for n in [4u32, 6, 8, 10, 16, 30, 64, 128, 256, 1000, 3000] {
        for _ in 0..3 {
            seed += 1;
            check(n, pairing_graph(n, seed), Some(1));
        }
    }
}

#[test]
fn torus_and_sphere_duals() {
    for (w, h) in [(3, 3), (3, 4), (4, 3), (5, 7), (8, 8), (16, 9), (40, 25)] {
        let (n, edges) = dual_of_triangles(&torus_triangles(w, h));
        check(n, edges, Some(2));
    }
    for (rings, seg) in [(1, 3), (1, 5), (2, 3), (3, 4), (6, 11), (30, 20)] {
        let (n, edges) = dual_of_triangles(&sphere_triangles(rings, seg));
        check(n, edges, Some(0));
    }
}

#[test]
fn hundred_thousand_nodes() {
    let n = 100_000;
    let edges = ear_graph(n, 2024);
    let g = CubicGraph::new(n, edges.clone()).unwrap();
    let (m, stats) = perfect_matching_with_stats(&g);
    assert_perfect(n, &edges, &flags(&g, &m));
    verify_perfect_matching(&g, &flags(&g, &m)).unwrap();
    assert_eq!(stats.reductions, u64::from(n / 2 - 1));
}

#[test]
fn matches_petgraph_maximum_matching_on_small_graphs() {
    for seed in 0..40u64 {
        let n = 2 + 2 * (seed as u32 % 20); // 2..=40
        let edges = if seed % 2 == 0 {
            ear_graph(n, seed)
        } else {
            pairing_graph(n, seed)
        };
        let g = CubicGraph::new(n, edges.clone()).unwrap();
        let ours = perfect_matching(&g);
        let pg = UnGraph::<(), ()>::from_edges(edges.iter().map(|&[a, b]| (a, b)));
        let theirs = petgraph::algo::maximum_matching(&pg);
        assert_eq!(
            theirs.len(),
            n as usize / 2,
            "petgraph: a bridgeless cubic graph has a perfect matching"
        );
        assert_eq!(ours.len(), theirs.len());
        assert_perfect(n, &edges, &flags(&g, &ours));
    }
}

#[test]
fn deterministic() {
    let g = CubicGraph::new(600, ear_graph(600, 5)).unwrap();
    assert_eq!(perfect_matching(&g), perfect_matching(&g));
}

#[test]
fn avoiding_an_edge_out_of_range_is_an_error() {
    let g = CubicGraph::new(2, vec![[0, 1]; 3]).unwrap();
    assert_eq!(
        perfect_matching_avoiding(&g, 3).unwrap_err(),
        GraphError::EdgeOutOfRange {
            edge: 3,
            edge_count: 3
        }
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    #[test]
    fn proptest_random_graphs(half in 1u32..150, seed in any::<u64>(), ear in any::<bool>(), pick in any::<u32>()) {
        let n = 2 * half;
        let edges = if ear || n < 4 { ear_graph(n, seed) } else { pairing_graph(n, seed) };
        let avoid = pick % edges.len() as u32;
        check(n, edges, Some(avoid));
    }
}
