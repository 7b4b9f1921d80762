//! Every pairing loop stops when asked (`surftopo_mesh::stop`, what Ctrl-C sets from Python): SG,
//! Pulli–Segal, the augmenting paths (each strategy), Karp–Sipser and the minimum-cost matchings
//! (the blossom and the fast mode), each run under `run_stoppable` with the flag already set on a
//! bridgeless cubic graph of 100,000 nodes (far more than `CHECK_EVERY` steps of work), unwind
//! within their first `CHECK_EVERY` steps: `None`, whatever the machine's speed. With the flag
//! unset the same calls return their result (a perfect matching for the perfect ones, checked by
//! the independent verifier).

use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use surftopo_matching::generators::random_bridgeless_cubic;
use surftopo_matching::{
    AugmentStrategy, CubicGraph, DualGraph, augment_to_perfect, fast_min_cost_perfect_matching,
    karp_sipser_perfect, min_cost_perfect_matching, pulli_segal, simple_greedy,
    verify_perfect_matching,
};
use surftopo_mesh::stop::run_stoppable;

fn stopped<T>(work: impl FnOnce() -> T) -> bool {
    run_stoppable(Arc::new(AtomicBool::new(true)), work).is_none()
}

fn unstopped<T>(work: impl FnOnce() -> T) -> T {
    run_stoppable(Arc::new(AtomicBool::new(false)), work).expect("the flag is not set")
}

/// A perfect matching of `graph` given as its matched edges, checked independently.
fn check_perfect(graph: &CubicGraph, edges: &[u32]) {
    let mut matched = vec![false; graph.edges().len()];
    for &e in edges {
        matched[e as usize] = true;
    }
    verify_perfect_matching(graph, &matched).unwrap();
}

#[test]
fn every_pairing_loop_stops_when_asked() {
    let graph = random_bridgeless_cubic(100_000, 7);
    assert!(stopped(|| simple_greedy(&graph, 1)), "SG");
    assert!(stopped(|| pulli_segal(&graph, 1)), "PS");
    let greedy = unstopped(|| simple_greedy(&graph, 1));
    assert!(greedy.unmatched_count(&graph) > 2_000);
    for strategy in [
        AugmentStrategy::Forest,
        AugmentStrategy::Global,
        AugmentStrategy::Local { initial_budget: 2 },
    ] {
        let mut pairing = greedy.clone();
        assert!(
            stopped(|| augment_to_perfect(&graph, &mut pairing, strategy)),
            "{strategy:?}"
        );
        let mut pairing = greedy.clone();
        unstopped(|| augment_to_perfect(&graph, &mut pairing, strategy)).unwrap();
        check_perfect(&graph, &pairing.matched_edges(&graph));
    }
    assert!(stopped(|| karp_sipser_perfect(&graph)), "KS");
    let (pairing, _) = unstopped(|| karp_sipser_perfect(&graph)).unwrap();
    check_perfect(&graph, &pairing.matched_edges(&graph));
    let costs: Vec<i64> = (0..graph.edge_slots() as i64)
        .map(|e| e * 7919 % 1000)
        .collect();
    assert!(
        stopped(|| min_cost_perfect_matching(&graph, &costs)),
        "blossom"
    );
    assert!(
        stopped(|| fast_min_cost_perfect_matching(&graph, &costs)),
        "fast"
    );
    let fast = unstopped(|| fast_min_cost_perfect_matching(&graph, &costs)).unwrap();
    check_perfect(&graph, &fast.edges);
}
