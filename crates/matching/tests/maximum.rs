//! Maximum pairings of the duals of surfaces with boundary, non-orientable surfaces and files of
//! several pieces: every algorithm's pairing augmented to a maximum and checked by the
//! independent verifier (its Tutte–Berge barrier), the number of unpaired triangles compared
//! with `petgraph`'s maximum matching, and the surface dual compared with the triangles.

mod common;

use std::collections::HashMap;

use petgraph::algo::maximum_matching;
use petgraph::graph::UnGraph;
use rand::seq::SliceRandom;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use surftopo_matching::{
    AugmentStrategy, DualGraph, KarpSipserOptions, MatchingError, Pairing, SurfaceDual,
    augment_to_maximum, karp_sipser_maximum_with, pulli_segal, simple_greedy,
    verify_maximum_pairing,
};
use surftopo_mesh::ClosedCover;
use surftopo_mesh::generators::{
    annulus, copies, crosscaps, cut_holes, disk, klein_bottle, mobius_band, projective_plane,
};

const STRATEGIES: [AugmentStrategy; 4] = [
    AugmentStrategy::Forest,
    AugmentStrategy::Global,
    AugmentStrategy::Local { initial_budget: 2 },
    AugmentStrategy::Local {
        initial_budget: 256,
    },
];

/// A triangle fan with an ear on each side of its middle triangle: the dual is the star K_{1,3},
/// so at least two of the four triangles stay unpaired.
fn three_ears() -> Vec<[u32; 3]> {
    vec![[0, 1, 2], [1, 0, 3], [2, 1, 4], [0, 2, 5]]
}

/// A disk of `2 n²` triangles with its last triangle removed (odd: one stays unpaired).
fn odd_disk(n: u32) -> Vec<[u32; 3]> {
    let mut triangles = disk(n).cover.surface_triangles();
    triangles.pop();
    triangles
}

/// Every kind of surface `generate` makes, small, as triangle soups (with a name).
fn surfaces() -> Vec<(String, Vec<[u32; 3]>)> {
    let mut out = vec![
        ("three ears".to_string(), three_ears()),
        ("odd disk".to_string(), odd_disk(5)),
        ("lone triangle".to_string(), vec![[0, 1, 2]]),
    ];
    for (name, surface) in [
        ("disk", disk(4)),
        ("annulus", annulus(9, 3)),
        ("Möbius band", mobius_band(9, 3)),
        ("projective plane", projective_plane()),
        ("Klein bottle", klein_bottle(8, 6)),
        ("N3", crosscaps(3)),
        ("two Möbius bands", copies(&mobius_band(7, 2), 2)),
    ] {
        out.push((name.to_string(), surface.cover.surface_triangles()));
    }
    for seed in 0..4 {
        let (holed, _) = cut_holes(&klein_bottle(12, 10), 2 + seed as usize, seed);
        out.push((
            format!("Klein bottle with holes, seed {seed}"),
            holed.cover.surface_triangles(),
        ));
        let (holed, _) = cut_holes(&annulus(14, 8), 1 + seed as usize, seed);
        out.push((
            format!("annulus with holes, seed {seed}"),
            holed.cover.surface_triangles(),
        ));
    }
    out
}

fn cover_of(triangles: &[[u32; 3]]) -> ClosedCover {
    let n = triangles.iter().flatten().max().map_or(0, |&v| v + 1) as usize;
    ClosedCover::from_triangles(n, triangles).unwrap().0
}

/// The dual read from the triangles alone: per triangle its neighbours across its edges, and its
/// boundary sides.
fn dual_from_triangles(triangles: &[[u32; 3]]) -> (Vec<Vec<u32>>, Vec<usize>) {
    let mut faces_of: HashMap<[u32; 2], Vec<u32>> = HashMap::new();
    for (f, t) in triangles.iter().enumerate() {
        for i in 0..3 {
            let (a, b) = (t[i], t[(i + 1) % 3]);
            faces_of
                .entry([a.min(b), a.max(b)])
                .or_default()
                .push(f as u32);
        }
    }
    let mut neighbours = vec![Vec::new(); triangles.len()];
    let mut boundary = vec![0; triangles.len()];
    for faces in faces_of.values() {
        match faces[..] {
            [f] => boundary[f as usize] += 1,
            [f, g] => {
                neighbours[f as usize].push(g);
                neighbours[g as usize].push(f);
            }
            _ => panic!("non-manifold edge"),
        }
    }
    for n in neighbours.iter_mut() {
        n.sort_unstable();
    }
    (neighbours, boundary)
}

/// The size of a maximum matching of `graph` (its non-loop edges), by petgraph.
fn petgraph_maximum<G: DualGraph>(graph: &G) -> usize {
    let mut g = UnGraph::<(), ()>::with_capacity(graph.node_slots(), graph.edge_slots());
    for _ in 0..graph.node_slots() {
        g.add_node(());
    }
    for e in 0..graph.edge_slots() as u32 {
        let [a, b] = graph.endpoints(e);
        if graph.is_edge(e) && a != b {
            g.add_edge(a.into(), b.into(), ());
        }
    }
    maximum_matching(&g).len()
}

#[test]
fn the_surface_dual_is_the_dual_of_the_triangles() {
    for (name, triangles) in surfaces() {
        let cover = cover_of(&triangles);
        let dual = SurfaceDual::of_cover(&cover);
        let (neighbours, boundary) = dual_from_triangles(&triangles);
        assert_eq!(dual.node_count(), triangles.len(), "{name}");
        for f in 0..triangles.len() as u32 {
            assert!(dual.is_node(f), "{name}: face {f}");
            let pairs = dual.adjacent(f);
            let mut found: Vec<u32> = pairs
                .iter()
                .filter(|&&(_, w)| w != f)
                .map(|&(_, w)| w)
                .collect();
            found.sort_unstable();
            assert_eq!(found, neighbours[f as usize], "{name}: face {f}");
            let loops = pairs.iter().filter(|&&(_, w)| w == f).count();
            assert_eq!(loops, boundary[f as usize], "{name}: face {f}");
            for (e, w) in pairs {
                let ends = dual.endpoints(e);
                assert!(ends.contains(&f) && ends.contains(&w), "{name}: edge {e}");
                assert_eq!(dual.is_boundary(e), w == f);
                // The stored half-edge lies in the first end's face.
                assert_eq!(cover.mesh.face(dual.halfedge(e)).0, ends[0]);
            }
        }
        let (component, count) = dual.components();
        let expected = surftopo_mesh::inspect(
            triangles.iter().flatten().max().map_or(0, |&v| v + 1) as usize,
            &triangles,
        )
        .surfaces
        .len();
        assert_eq!(count, expected, "{name}");
        assert_eq!(component[0], 0);
        // With as many components as pieces, one per edge's two ends, numbered by first node.
        for e in (0..dual.edge_slots() as u32).filter(|&e| dual.is_edge(e)) {
            let [a, b] = dual.endpoints(e);
            assert_eq!(
                component[a as usize], component[b as usize],
                "{name}: edge {e}"
            );
        }
        let mut next = 0;
        for v in (0..dual.node_slots() as u32).filter(|&v| dual.is_node(v)) {
            let c = component[v as usize];
            assert!(c <= next, "{name}: node {v} in component {c} before {next}");
            next += u32::from(c == next);
        }
        assert_eq!(next as usize, count, "{name}");
        // The coned closure's dual is cubic: no loop, three neighbours each.
        let coned = SurfaceDual::coned(&cover);
        for v in (0..coned.node_slots() as u32).filter(|&v| coned.is_node(v)) {
            assert!(
                coned
                    .adjacent(v)
                    .iter()
                    .all(|&(_, w)| w != v && coned.is_node(w))
            );
        }
        let cones = coned.node_count() - triangles.len();
        assert_eq!(cones, boundary.iter().sum::<usize>(), "{name}");
    }
}

/// Checks a maximum pairing: the verifier accepts it with its barrier, and it leaves as many
/// nodes unmatched as petgraph's maximum matching does. Returns the unmatched nodes.
fn check_maximum<G: DualGraph>(name: &str, graph: &G, pairing: Pairing, barrier: &[u32]) -> usize {
    let verified =
        verify_maximum_pairing(graph, pairing, barrier).unwrap_or_else(|e| panic!("{name}: {e}"));
    let best = graph.node_count() - 2 * petgraph_maximum(graph);
    assert_eq!(verified.unmatched(), best, "{name}");
    for c in verified.components() {
        assert_eq!(c.unmatched, c.deficiency_lower_bound, "{name}");
    }
    assert_eq!(
        verified.components().iter().map(|c| c.nodes).sum::<usize>(),
        graph.node_count()
    );
    best
}

#[test]
fn every_pairing_augments_to_a_verified_maximum() {
    let mut deficient = 0;
    for (name, triangles) in surfaces() {
        let cover = cover_of(&triangles);
        let dual = SurfaceDual::of_cover(&cover);
        for seed in 0..3 {
            for (label, start) in [
                ("sg", simple_greedy(&dual, seed)),
                ("ps", pulli_segal(&dual, seed)),
                ("empty", Pairing::empty(dual.node_slots())),
            ] {
                for strategy in STRATEGIES {
                    let mut pairing = start.clone();
                    let (_, barrier) = augment_to_maximum(&dual, &mut pairing, strategy).unwrap();
                    let name = format!("{name}, {label}, seed {seed}, {strategy:?}");
                    check_maximum(&name, &dual, pairing, &barrier);
                }
            }
        }
        for options in ks_options() {
            let (pairing, stats, barrier) = karp_sipser_maximum_with(&dual, &options);
            let left = check_maximum(&format!("{name}, ks {options:?}"), &dual, pairing, &barrier);
            deficient += usize::from(left > 0);
            assert!(stats.augment.augmentations <= dual.node_count());
        }
    }
    assert!(deficient >= 6, "{deficient} deficient inputs");
}

fn ks_options() -> [KarpSipserOptions; 3] {
    let default = KarpSipserOptions::default();
    [
        default,
        KarpSipserOptions {
            repair_budget: 0,
            guided_completion: false,
            ..default
        },
        KarpSipserOptions {
            repair_budget: 8,
            ..default
        },
    ]
}

/// A random graph of maximum degree 3 with half-loops where edges were removed: a bridgeless
/// cubic graph built by ears, then each edge dropped with probability `drop` (its two slots
/// become loops).
#[derive(Clone, Debug)]
struct Sparse {
    adjacency: Vec<[(u32, u32); 3]>,
    ends: Vec<[u32; 2]>,
}

impl Sparse {
    fn random(n: u32, drop: f64, seed: u64) -> Self {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let (mut edges, next) = common::ears(n, &mut rng);
        edges.shuffle(&mut rng);
        let mut adjacency = vec![Vec::new(); next as usize];
        let mut ends = Vec::new();
        for [a, b] in edges {
            if rng.random_bool(drop) {
                for v in [a, b] {
                    let e = ends.len() as u32;
                    ends.push([v, v]);
                    adjacency[v as usize].push((e, v));
                }
            } else {
                let e = ends.len() as u32;
                ends.push([a, b]);
                adjacency[a as usize].push((e, b));
                adjacency[b as usize].push((e, a));
            }
        }
        Sparse {
            adjacency: adjacency.into_iter().map(|p| [p[0], p[1], p[2]]).collect(),
            ends,
        }
    }
}

impl DualGraph for Sparse {
    fn node_slots(&self) -> usize {
        self.adjacency.len()
    }
    fn edge_slots(&self) -> usize {
        self.ends.len()
    }
    fn is_node(&self, v: u32) -> bool {
        (v as usize) < self.adjacency.len()
    }
    fn is_edge(&self, e: u32) -> bool {
        (e as usize) < self.ends.len()
    }
    fn node_count(&self) -> usize {
        self.adjacency.len()
    }
    fn adjacent(&self, v: u32) -> [(u32, u32); 3] {
        self.adjacency[v as usize]
    }
    fn endpoints(&self, e: u32) -> [u32; 2] {
        self.ends[e as usize]
    }
}

#[test]
fn random_sparse_graphs_pair_to_petgraph_maximum() {
    for seed in 0..40u64 {
        let n = 10 + 2 * (seed as u32 % 30);
        let drop = [0.1, 0.3, 0.5][seed as usize % 3];
        let graph = Sparse::random(n, drop, seed);
        for options in ks_options() {
            let (pairing, _, barrier) = karp_sipser_maximum_with(&graph, &options);
            check_maximum(&format!("seed {seed}, ks"), &graph, pairing, &barrier);
        }
        for strategy in STRATEGIES {
            let mut pairing = simple_greedy(&graph, seed);
            let (_, barrier) = augment_to_maximum(&graph, &mut pairing, strategy).unwrap();
            check_maximum(
                &format!("seed {seed}, {strategy:?}"),
                &graph,
                pairing,
                &barrier,
            );
        }
    }
}

#[test]
fn the_verifier_refuses_what_is_not_proven() {
    let triangles = three_ears();
    let cover = cover_of(&triangles);
    let dual = SurfaceDual::of_cover(&cover);
    let (pairing, _, barrier) = karp_sipser_maximum_with(&dual, &KarpSipserOptions::default());
    // The middle triangle is the barrier: the three ears are odd components.
    assert_eq!(barrier, vec![0]);
    let verified = verify_maximum_pairing(&dual, pairing.clone(), &barrier).unwrap();
    assert_eq!(verified.components()[0].deficiency_lower_bound, 2);
    assert_eq!(verified.components()[0].odd_components, 3);
    // Without the barrier, nothing is proven.
    assert!(matches!(
        verify_maximum_pairing(&dual, pairing.clone(), &[]),
        Err(MatchingError::NotProvenMaximum {
            unmatched: 2,
            bound: 0,
            ..
        })
    ));
    // An empty pairing is not maximum, whatever the barrier.
    assert!(matches!(
        verify_maximum_pairing(&dual, Pairing::empty(dual.node_slots()), &barrier),
        Err(MatchingError::NotProvenMaximum { unmatched: 4, .. })
    ));
    // A barrier node out of range, or twice.
    for bad in [vec![9], vec![0, 0]] {
        assert!(matches!(
            verify_maximum_pairing(&dual, pairing.clone(), &bad),
            Err(MatchingError::BadBarrier { .. })
        ));
    }
    // A half-loop is never matched.
    let boundary = (0..dual.edge_slots() as u32)
        .find(|&e| dual.is_boundary(e))
        .unwrap();
    assert!(Pairing::from_edges(&dual, [boundary]).is_err());
}

#[test]
fn closed_pieces_pair_perfectly_with_an_empty_barrier() {
    for surface in [projective_plane(), klein_bottle(10, 8), crosscaps(4)] {
        let dual = SurfaceDual::of_cover(&surface.cover);
        let (pairing, _, barrier) = karp_sipser_maximum_with(&dual, &KarpSipserOptions::default());
        assert!(barrier.is_empty());
        let verified = verify_maximum_pairing(&dual, pairing, &barrier).unwrap();
        assert!(verified.is_perfect());
    }
}

/// The least cost and the size of a maximum matching, by enumerating every matching (small
/// graphs only): each node is left unmatched or matched to a free neighbour of larger id.
fn brute_force_min_cost_maximum<G: DualGraph>(graph: &G, costs: &[i64]) -> (usize, i64) {
    fn go<G: DualGraph>(
        g: &G,
        costs: &[i64],
        v: u32,
        used: &mut Vec<bool>,
        size: usize,
        cost: i64,
        best: &mut (usize, i64),
    ) {
        if v as usize == g.node_slots() {
            if size > best.0 || (size == best.0 && cost < best.1) {
                *best = (size, cost);
            }
            return;
        }
        if used[v as usize] || !g.is_node(v) {
            return go(g, costs, v + 1, used, size, cost, best);
        }
        go(g, costs, v + 1, used, size, cost, best);
        used[v as usize] = true;
        for (e, w) in g.adjacent(v) {
            if w != v && w != u32::MAX && !used[w as usize] {
                used[w as usize] = true;
                go(
                    g,
                    costs,
                    v + 1,
                    used,
                    size + 1,
                    cost + costs[e as usize],
                    best,
                );
                used[w as usize] = false;
            }
        }
        used[v as usize] = false;
    }
    let mut best = (0, i64::MAX);
    go(
        graph,
        costs,
        0,
        &mut vec![false; graph.node_slots()],
        0,
        0,
        &mut best,
    );
    best
}

fn random_costs(edges: usize, seed: u64) -> Vec<i64> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0xc057);
    (0..edges)
        .map(|_| {
            if rng.random_bool(0.2) {
                7
            } else {
                rng.random_range(0..1000)
            }
        })
        .collect()
}

/// The exact pairing of least cost among the maximum ones equals a brute-force enumeration, its
/// certificate passes the verifier, and the fast mode is as large and no cheaper.
#[test]
fn min_cost_maximum_matchings_are_optimal_and_certified() {
    use surftopo_matching::{
        fast_min_cost_maximum_matching, min_cost_maximum_matching, verify_min_cost_maximum_matching,
    };
    let mut small: Vec<(String, Sparse)> = Vec::new();
    for seed in 0..60u64 {
        let n = 6 + 2 * (seed as u32 % 5);
        small.push((format!("sparse {seed}"), Sparse::random(n, 0.35, seed)));
    }
    let mut deficient = 0;
    for (name, graph) in &small {
        let costs = random_costs(graph.edge_slots(), name.len() as u64 * 31);
        let exact = min_cost_maximum_matching(graph, &costs).unwrap();
        let (size, cost) = brute_force_min_cost_maximum(graph, &costs);
        assert_eq!(exact.edges.len(), size, "{name}");
        assert_eq!(exact.cost, cost, "{name}");
        assert_eq!(exact.unmatched, graph.node_count() - 2 * size, "{name}");
        deficient += usize::from(exact.unmatched > 0);
        let verified =
            verify_min_cost_maximum_matching(graph, &costs, &exact.edges, &exact.certificate)
                .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(verified, cost, "{name}");
        let fast = fast_min_cost_maximum_matching(graph, &costs).unwrap();
        assert_eq!(fast.edges.len(), size, "{name}");
        assert!(fast.cost >= cost, "{name}");
    }
    assert!(deficient > 20, "{deficient}");
    // Surface duals.
    for (name, triangles) in surfaces() {
        let cover = cover_of(&triangles);
        let dual = SurfaceDual::of_cover(&cover);
        let costs = random_costs(dual.edge_slots(), triangles.len() as u64);
        let exact = min_cost_maximum_matching(&dual, &costs).unwrap();
        verify_min_cost_maximum_matching(&dual, &costs, &exact.edges, &exact.certificate)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let best = dual.node_count() - 2 * petgraph_maximum(&dual);
        assert_eq!(exact.unmatched, best, "{name}");
        if dual.node_count() <= 14 {
            assert_eq!(
                exact.cost,
                brute_force_min_cost_maximum(&dual, &costs).1,
                "{name}"
            );
        }
    }
}

/// The verifier refuses a certificate whose parts are wrong: a matching that is not maximum, a
/// dual raised, an exposure moved, a matching of larger cost.
#[test]
fn min_cost_maximum_certificates_are_checked() {
    use surftopo_matching::weighted::CertificateError;
    use surftopo_matching::{min_cost_maximum_matching, verify_min_cost_maximum_matching};
    let mut checked = 0;
    for seed in 0..40u64 {
        let graph = Sparse::random(10 + 2 * (seed as u32 % 4), 0.35, seed + 100);
        let costs = random_costs(graph.edge_slots(), seed);
        let exact = min_cost_maximum_matching(&graph, &costs).unwrap();
        if exact.unmatched == 0 {
            continue;
        }
        checked += 1;
        let verify = |edges: &[u32], certificate: &surftopo_matching::MaximumCertificate| {
            verify_min_cost_maximum_matching(&graph, &costs, edges, certificate)
        };
        assert!(verify(&exact.edges, &exact.certificate).is_ok());
        // One pair dropped: not maximum.
        assert!(matches!(
            verify(&exact.edges[1..], &exact.certificate),
            Err(CertificateError::NotMaximum(_))
        ));
        // A node dual raised: some edge becomes infeasible or the objectives differ.
        let mut raised = exact.certificate.clone();
        raised.duals.node_duals[exact.certificate.exposed[0].0 as usize] += 2;
        assert!(verify(&exact.edges, &raised).is_err());
        // The exposure given to a node that is matched.
        let mut moved = exact.certificate.clone();
        let [a, _] = graph.endpoints(exact.edges[0]);
        moved.exposed[0].0 = a;
        assert!(verify(&exact.edges, &moved).is_err());
    }
    assert!(checked > 10, "{checked}");
}

/// KS proves a pairing maximum by parity alone (an empty barrier) when it leaves one triangle
/// in each piece of odd size and none elsewhere, and searches for a barrier otherwise; the
/// verifier accepts both.
#[test]
fn ks_proves_maximum_by_parity_when_it_can() {
    let cases = [
        ("odd disk", odd_disk(6), 1, true),
        (
            "two odd disks",
            {
                let mut t = odd_disk(4);
                let shift = t.iter().flatten().max().unwrap() + 1;
                t.extend(odd_disk(3).iter().map(|f| f.map(|v| v + shift)));
                t
            },
            2,
            true,
        ),
        ("three ears", three_ears(), 2, false),
    ];
    for (name, triangles, unmatched, by_parity) in cases {
        let dual = SurfaceDual::of_cover(&cover_of(&triangles));
        let (pairing, _, barrier) = karp_sipser_maximum_with(&dual, &KarpSipserOptions::default());
        assert_eq!(pairing.unmatched_count(&dual), unmatched, "{name}");
        assert_eq!(barrier.is_empty(), by_parity, "{name}: {barrier:?}");
        check_maximum(name, &dual, pairing, &barrier);
    }
}

/// Surfaces with many holes (one per ~170 triangles, as `open_peers` cuts 600 into 100k), cut
/// around random vertices of randomly flipped spheres: boundary-heavy pieces whose triangle
/// counts are odd or even, where KS without repairs defers many triangles to its completion.
/// The completion stops at the floor of Tutte–Berge with an empty barrier (one triangle per odd
/// piece) instead of searching the whole piece again, twice (the pass that finds nothing and
/// the barrier's search); above the floor its barrier is the last pass's. Each result is checked
/// by the verifier and against petgraph.
#[test]
fn ks_completion_stops_at_the_parity_floor_on_boundary_heavy_pieces() {
    use surftopo_mesh::CoveredSurface;
    use surftopo_mesh::generators::{icosphere, random_flips_covered};
    let sphere: CoveredSurface = icosphere(3).into();
    let without_repairs = KarpSipserOptions {
        repair_budget: 0,
        guided_completion: false,
        ..KarpSipserOptions::default()
    };
    let (mut odd, mut searched) = (0, 0);
    for seed in 0..12u64 {
        let flipped = random_flips_covered(&sphere, 600, seed);
        let (holed, cut) = cut_holes(&flipped, 8, seed);
        let triangles = holed.cover.surface_triangles();
        let dual = SurfaceDual::of_cover(&cover_of(&triangles));
        let nodes = dual.node_count();
        let odd_pieces = {
            let (component, count) = dual.components();
            let mut sizes = vec![0usize; count];
            for v in (0..dual.node_slots() as u32).filter(|&v| dual.is_node(v)) {
                sizes[component[v as usize] as usize] += 1;
            }
            sizes.iter().filter(|&&s| s % 2 == 1).count()
        };
        for options in [without_repairs, KarpSipserOptions::default()] {
            let name = format!("sphere with {cut} holes, seed {seed}, {options:?}");
            let (pairing, stats, barrier) = karp_sipser_maximum_with(&dual, &options);
            let left = check_maximum(&name, &dual, pairing, &barrier);
            if left == odd_pieces {
                assert!(barrier.is_empty(), "{name}: {barrier:?}");
            }
            if options == without_repairs && stats.completed > 1 && odd_pieces > 0 {
                // Before the floor, the lone root's pass and the barrier's search alone reached
                // every node of its piece twice.
                assert!(
                    stats.completion_reached < nodes as u64,
                    "{name}: {} nodes reached, {nodes} nodes",
                    stats.completion_reached
                );
                searched += 1;
            }
        }
        odd += usize::from(odd_pieces > 0);
    }
    assert!(
        odd >= 3 && searched >= 3,
        "{odd} odd inputs, {searched} searched"
    );
}
