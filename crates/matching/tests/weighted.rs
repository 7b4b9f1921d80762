//! The exact minimum-cost perfect matching and the fast mode: every exact result checked by the
//! independent certificate verifier; the exact optimum equal to a brute-force enumeration on
//! small graphs (multigraphs, loops, ties, graphs without a perfect matching); the verifier
//! rejecting corrupted certificates; fast cost ≥ exact cost; both deterministic.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use surftopo_matching::generators::{random_bridgeless_cubic, random_cubic_pairing, torus_dual};
use surftopo_matching::weighted::{MAX_COST, WeightedError};
use surftopo_matching::{
    Certificate, CubicGraph, DualGraph, fast_min_cost_perfect_matching, min_cost_perfect_matching,
    verify_min_cost_perfect_matching,
};

/// A cubic multigraph with loops allowed (a loop fills two slots), not necessarily connected: the
/// configuration model without redraws. Some have no perfect matching.
struct LoopyGraph {
    edges: Vec<[u32; 2]>,
    adjacency: Vec<[(u32, u32); 3]>,
}

impl LoopyGraph {
    fn random(n: u32, seed: u64) -> Self {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut half: Vec<u32> = (0..n).flat_map(|v| [v, v, v]).collect();
        for i in (1..half.len()).rev() {
            let j = rng.random_range(0..=i);
            half.swap(i, j);
        }
        let edges: Vec<[u32; 2]> = half.chunks_exact(2).map(|p| [p[0], p[1]]).collect();
        Self::new(n, edges)
    }

    fn new(n: u32, edges: Vec<[u32; 2]>) -> Self {
        let mut adjacency = vec![[(u32::MAX, u32::MAX); 3]; n as usize];
        let mut filled = vec![0usize; n as usize];
        for (e, &[a, b]) in edges.iter().enumerate() {
            adjacency[a as usize][filled[a as usize]] = (e as u32, b);
            filled[a as usize] += 1;
            adjacency[b as usize][filled[b as usize]] = (e as u32, a);
            filled[b as usize] += 1;
        }
        assert!(filled.iter().all(|&f| f == 3));
        LoopyGraph { edges, adjacency }
    }
}

impl DualGraph for LoopyGraph {
    fn node_slots(&self) -> usize {
        self.adjacency.len()
    }
    fn edge_slots(&self) -> usize {
        self.edges.len()
    }
    fn is_node(&self, v: u32) -> bool {
        (v as usize) < self.adjacency.len()
    }
    fn is_edge(&self, e: u32) -> bool {
        (e as usize) < self.edges.len()
    }
    fn node_count(&self) -> usize {
        self.adjacency.len()
    }
    fn adjacent(&self, v: u32) -> [(u32, u32); 3] {
        self.adjacency[v as usize]
    }
    fn endpoints(&self, e: u32) -> [u32; 2] {
        self.edges[e as usize]
    }
}

/// Every perfect matching of `graph` (as edge lists), by branching on the smallest exposed node.
fn all_perfect_matchings<G: DualGraph>(graph: &G) -> Vec<Vec<u32>> {
    fn go<G: DualGraph>(
        g: &G,
        used: &mut Vec<bool>,
        chosen: &mut Vec<u32>,
        out: &mut Vec<Vec<u32>>,
    ) {
        let Some(v) = (0..g.node_slots() as u32).find(|&v| g.is_node(v) && !used[v as usize])
        else {
            out.push(chosen.clone());
            return;
        };
        used[v as usize] = true;
        let mut seen = Vec::new();
        for (e, w) in g.adjacent(v) {
            if w == v || used[w as usize] || seen.contains(&e) {
                continue;
            }
            seen.push(e);
            used[w as usize] = true;
            chosen.push(e);
            go(g, used, chosen, out);
            chosen.pop();
            used[w as usize] = false;
        }
        used[v as usize] = false;
    }
    let mut out = Vec::new();
    go(
        graph,
        &mut vec![false; graph.node_slots()],
        &mut Vec::new(),
        &mut out,
    );
    out
}

fn cost_of(costs: &[i64], edges: &[u32]) -> i64 {
    edges.iter().map(|&e| costs[e as usize]).sum()
}

/// The exact solver, its result checked by the verifier (which must agree on the cost); `None`
/// when the solver reports no perfect matching.
fn solve_checked<G: DualGraph>(graph: &G, costs: &[i64]) -> Option<(i64, Vec<u32>, Certificate)> {
    match min_cost_perfect_matching(graph, costs) {
        Ok(result) => {
            let verified =
                verify_min_cost_perfect_matching(graph, costs, &result.edges, &result.certificate)
                    .unwrap_or_else(|err| panic!("certificate rejected: {err}"));
            assert_eq!(verified, result.cost);
            assert_eq!(cost_of(costs, &result.edges), result.cost);
            Some((result.cost, result.edges, result.certificate))
        }
        Err(WeightedError::NoPerfectMatching { .. }) => None,
        Err(err) => panic!("unexpected error: {err}"),
    }
}

fn random_costs(edges: usize, max: i64, seed: u64) -> Vec<i64> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..edges).map(|_| rng.random_range(0..=max)).collect()
}

fn check_against_brute_force<G: DualGraph>(graph: &G, costs: &[i64]) {
    let all = all_perfect_matchings(graph);
    let best = all.iter().map(|m| cost_of(costs, m)).min();
    let solved = solve_checked(graph, costs).map(|(c, _, _)| c);
    assert_eq!(solved, best, "solver and enumeration disagree");
    if let Some(fast) = solve_fast(graph, costs) {
        assert!(fast >= best.expect("fast found a matching"));
    }
}

fn solve_fast<G: DualGraph>(graph: &G, costs: &[i64]) -> Option<i64> {
    let fast = fast_min_cost_perfect_matching(graph, costs).ok()?;
    let flags: Vec<u32> = fast.edges.clone();
    assert_eq!(cost_of(costs, &flags), fast.cost);
    assert_eq!(fast.edges.len() * 2, graph.node_count());
    Some(fast.cost)
}

#[test]
fn brute_force_on_random_cubic_multigraphs() {
    for n in (2..=20).step_by(2) {
        for seed in 0..12u64 {
            let graphs: [CubicGraph; 2] = [
                random_bridgeless_cubic(n, seed),
                random_cubic_pairing(n, seed + 100),
            ];
            for (g, graph) in graphs.iter().enumerate() {
                let m = graph.edge_count() as usize;
                for (k, max) in [0i64, 2, 1000, MAX_COST].into_iter().enumerate() {
                    let costs =
                        random_costs(m, max, seed * 31 + n as u64 * 7 + k as u64 + g as u64);
                    check_against_brute_force(graph, &costs);
                }
            }
        }
    }
}

#[test]
fn brute_force_on_graphs_with_loops_and_without_perfect_matchings() {
    let mut without = 0;
    for n in (2..=18).step_by(2) {
        for seed in 0..20u64 {
            let graph = LoopyGraph::random(n, seed);
            if all_perfect_matchings(&graph).is_empty() {
                without += 1;
            }
            for max in [1i64, 50] {
                let costs =
                    random_costs(graph.edge_slots(), max, seed + 1000 * n as u64 + max as u64);
                check_against_brute_force(&graph, &costs);
            }
        }
    }
    assert!(without > 0, "some sampled graphs have no perfect matching");
}

#[test]
fn no_perfect_matching_is_reported() {
    // A centre joined to three nodes that each carry a loop.
    let graph = LoopyGraph::new(4, vec![[0, 1], [0, 2], [0, 3], [1, 1], [2, 2], [3, 3]]);
    assert!(matches!(
        min_cost_perfect_matching(&graph, &[1; 6]),
        Err(WeightedError::NoPerfectMatching { .. })
    ));
}

#[test]
fn bad_costs_are_refused() {
    let graph = random_bridgeless_cubic(6, 1);
    assert!(matches!(
        min_cost_perfect_matching(&graph, &[0; 3]),
        Err(WeightedError::CostCount {
            costs: 3,
            edge_slots: 9
        })
    ));
    let mut costs = vec![0; 9];
    costs[4] = -1;
    assert_eq!(
        min_cost_perfect_matching(&graph, &costs),
        Err(WeightedError::CostOutOfRange { edge: 4, cost: -1 })
    );
    costs[4] = MAX_COST + 1;
    assert!(fast_min_cost_perfect_matching(&graph, &costs).is_err());
}

/// Larger graphs (no enumeration): certificate verified, fast ≥ exact, both deterministic.
#[test]
fn larger_graphs_verified_fast_not_below_exact_and_deterministic() {
    let mut graphs: Vec<CubicGraph> = vec![torus_dual(30, 20), torus_dual(7, 3)];
    for (n, seed) in [(200u32, 1u64), (2000, 2), (5000, 3)] {
        graphs.push(random_bridgeless_cubic(n, seed));
        graphs.push(random_cubic_pairing(n, seed));
    }
    let mut blossoms = 0;
    for (i, graph) in graphs.iter().enumerate() {
        for max in [3i64, 1_000_000_000] {
            let costs = random_costs(graph.edge_count() as usize, max, 77 + i as u64);
            let (exact, edges, certificate) = solve_checked(graph, &costs).expect("perfect");
            blossoms += certificate.blossoms.len();
            let again = min_cost_perfect_matching(graph, &costs).unwrap();
            assert_eq!((again.edges, again.certificate), (edges, certificate));
            let fast = fast_min_cost_perfect_matching(graph, &costs).unwrap();
            assert!(fast.cost >= exact, "fast {} below exact {exact}", fast.cost);
            assert!(fast.cost <= fast.stats.cost_before_improvement);
            let fast_again = fast_min_cost_perfect_matching(graph, &costs).unwrap();
            assert_eq!((fast_again.edges, fast_again.cost), (fast.edges, fast.cost));
        }
    }
    assert!(blossoms > 0, "the sample exercises blossoms");
}

/// A solved instance whose certificate has blossoms with positive duals.
fn instance_with_blossoms() -> (CubicGraph, Vec<i64>, Vec<u32>, Certificate) {
    for seed in 0..200u64 {
        let graph = random_bridgeless_cubic(40, seed);
        let costs = random_costs(graph.edge_count() as usize, 100, seed);
        let (_, edges, certificate) = solve_checked(&graph, &costs).unwrap();
        if certificate.blossoms.iter().any(|b| b.dual > 0) {
            return (graph, costs, edges, certificate);
        }
    }
    panic!("no instance with a positive blossom dual");
}

#[test]
fn verifier_rejects_corrupted_certificates() {
    let (graph, costs, edges, certificate) = instance_with_blossoms();
    let verify = |edges: &[u32], cert: &Certificate| {
        verify_min_cost_perfect_matching(&graph, &costs, edges, cert)
    };
    assert!(verify(&edges, &certificate).is_ok());
    for v in [0usize, 7, 39] {
        for delta in [1i64, -1] {
            let mut bad = certificate.clone();
            bad.node_duals[v] += delta;
            assert!(verify(&edges, &bad).is_err(), "node dual {v} {delta:+}");
        }
    }
    let positive = certificate
        .blossoms
        .iter()
        .position(|b| b.dual > 0)
        .unwrap();
    for delta in [1i64, -1] {
        let mut bad = certificate.clone();
        bad.blossoms[positive].dual += delta;
        assert!(verify(&edges, &bad).is_err(), "blossom dual {delta:+}");
    }
    let mut bad = certificate.clone();
    bad.blossoms[positive].dual = -1;
    assert!(verify(&edges, &bad).is_err());
    // A cycle of parents.
    let mut bad = certificate.clone();
    bad.blossoms[positive].parent = positive as u32;
    assert!(verify(&edges, &bad).is_err());
    // An even set: one node moved out of its set.
    let mut bad = certificate.clone();
    let v = bad
        .node_blossom
        .iter()
        .position(|&s| s != u32::MAX)
        .unwrap();
    bad.node_blossom[v] = u32::MAX;
    assert!(verify(&edges, &bad).is_err());
    // Matched edges: one dropped, one replaced by a neighbour's.
    assert!(verify(&edges[1..], &certificate).is_err());
    let mut replaced = edges.clone();
    let [a, _] = graph.endpoints(edges[0]);
    let other = graph
        .incident_edges(a)
        .into_iter()
        .find(|&e| e != edges[0])
        .unwrap();
    replaced[0] = other;
    assert!(verify(&replaced, &certificate).is_err());
    // Any costlier perfect matching is rejected with the optimum's certificate.
    let optimum = cost_of(&costs, &edges);
    let small = random_bridgeless_cubic(16, 5);
    let small_costs = random_costs(small.edge_count() as usize, 20, 5);
    let (best, _, small_cert) = solve_checked(&small, &small_costs).unwrap();
    for m in all_perfect_matchings(&small) {
        let accepted = verify_min_cost_perfect_matching(&small, &small_costs, &m, &small_cert);
        assert_eq!(accepted.is_ok(), cost_of(&small_costs, &m) == best);
    }
    assert!(optimum >= 0);
}
