//! The dynamic connectivity structure against recomputation from scratch (union-find, bridge DFS,
//! BFS paths in the reported spanning forest) on random insert / delete / query sequences.

mod common;

use common::*;
use proptest::prelude::*;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use surftopo_matching::DynamicConnectivity;

/// The current edge set, as the test sees it.
struct Shadow {
    n: u32,
    edges: Vec<Option<[u32; 2]>>,
}

impl Shadow {
    fn present(&self) -> Vec<u32> {
        (0..self.edges.len() as u32)
            .filter(|&e| self.edges[e as usize].is_some())
            .collect()
    }

    fn list(&self) -> (Vec<[u32; 2]>, Vec<u32>) {
        let ids = self.present();
        (
            ids.iter()
                .map(|&e| self.edges[e as usize].unwrap())
                .collect(),
            ids,
        )
    }

    fn component_labels(&self, allowed: impl Fn(u32) -> bool) -> Vec<u32> {
        let mut label: Vec<u32> = (0..self.n).collect();
        fn find(l: &mut [u32], mut x: u32) -> u32 {
            while l[x as usize] != x {
                x = l[x as usize];
            }
            x
        }
        for (e, ab) in self.edges.iter().enumerate() {
            if let Some([a, b]) = *ab
                && allowed(e as u32)
            {
                let (ra, rb) = (find(&mut label, a), find(&mut label, b));
                label[ra as usize] = rb;
            }
        }
        (0..self.n).map(|v| find(&mut label, v)).collect()
    }
}

/// Vertices of the path a..b in the forest made of `tree` edges, or None if not connected.
fn forest_path(n: u32, tree: &[[u32; 2]], a: u32, b: u32) -> Option<Vec<u32>> {
    let mut adj = vec![Vec::new(); n as usize];
    for &[x, y] in tree {
        adj[x as usize].push(y);
        adj[y as usize].push(x);
    }
    let mut parent = vec![u32::MAX; n as usize];
    parent[a as usize] = a;
    let mut queue = std::collections::VecDeque::from([a]);
    while let Some(x) = queue.pop_front() {
        for &y in &adj[x as usize] {
            if parent[y as usize] == u32::MAX {
                parent[y as usize] = x;
                queue.push_back(y);
            }
        }
    }
    if parent[b as usize] == u32::MAX {
        return None;
    }
    let mut path = vec![b];
    let mut x = b;
    while x != a {
        x = parent[x as usize];
        path.push(x);
    }
    Some(path)
}

/// Runs `ops` random operations, checking every answer against recomputation from scratch.
fn run_sequence(n: u32, ops: usize, seed: u64, initial: usize, check_every: usize) -> u8 {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut shadow = Shadow {
        n,
        edges: Vec::new(),
    };
    for _ in 0..initial {
        let a = rng.random_range(0..n);
        let b = rng.random_range(0..n);
        shadow.edges.push(Some([a, b]));
    }
    let init: Vec<[u32; 2]> = shadow.edges.iter().map(|e| e.unwrap()).collect();
    let mut dc = DynamicConnectivity::from_edges(n, &init);
    dc.check_invariants().unwrap();
    let mut free_ids: Vec<u32> = Vec::new();
    for step in 0..ops {
        let present = shadow.present();
        let roll = rng.random_range(0..100);
        if roll < 30 || present.is_empty() {
            // insert, sometimes reusing a freed id, sometimes a loop or a parallel edge
            let a = rng.random_range(0..n);
            let b = if rng.random_range(0..20) == 0 {
                a
            } else if !present.is_empty() && rng.random_range(0..5) == 0 {
                let e = present[rng.random_range(0..present.len())];
                shadow.edges[e as usize].unwrap()[1]
            } else {
                rng.random_range(0..n)
            };
            let id = if !free_ids.is_empty() && rng.random_bool(0.5) {
                free_ids.swap_remove(rng.random_range(0..free_ids.len()))
            } else {
                shadow.edges.push(None);
                shadow.edges.len() as u32 - 1
            };
            shadow.edges[id as usize] = Some([a, b]);
            dc.insert_edge(id, a, b);
        } else if roll < 60 {
            // delete, preferring forest edges (the interesting case)
            let tree: Vec<u32> = present
                .iter()
                .copied()
                .filter(|&e| dc.is_tree_edge(e))
                .collect();
            let e = if !tree.is_empty() && rng.random_bool(0.7) {
                tree[rng.random_range(0..tree.len())]
            } else {
                present[rng.random_range(0..present.len())]
            };
            dc.delete_edge(e);
            shadow.edges[e as usize] = None;
            free_ids.push(e);
        } else if roll < 75 {
            let labels = shadow.component_labels(|_| true);
            for _ in 0..4 {
                let a = rng.random_range(0..n);
                let b = rng.random_range(0..n);
                assert_eq!(
                    dc.connected(a, b),
                    labels[a as usize] == labels[b as usize],
                    "step {step}: connected({a},{b})"
                );
            }
        } else if roll < 88 {
            let (list, ids) = shadow.list();
            let (_, bridges) = bridges_and_components(n, &list);
            let bridge_ids: Vec<u32> = bridges.iter().map(|&k| ids[k]).collect();
            for _ in 0..3 {
                let e = present[rng.random_range(0..present.len())];
                assert_eq!(
                    dc.is_bridge(e),
                    bridge_ids.contains(&e),
                    "step {step}: is_bridge({e})"
                );
            }
        } else {
            // the reported forest spans the graph, and path intersection matches BFS paths in it
            let graph_labels = shadow.component_labels(|_| true);
            let tree_ids: Vec<u32> = shadow
                .present()
                .into_iter()
                .filter(|&e| dc.is_tree_edge(e))
                .collect();
            let tree: Vec<[u32; 2]> = tree_ids
                .iter()
                .map(|&e| shadow.edges[e as usize].unwrap())
                .collect();
            let forest_labels = shadow.component_labels(|e| dc.is_tree_edge(e));
            let comps = |l: &[u32]| {
                l.iter()
                    .enumerate()
                    .filter(|&(v, &r)| v as u32 == r)
                    .count()
            };
            assert_eq!(
                comps(&forest_labels),
                comps(&graph_labels),
                "forest does not span"
            );
            assert_eq!(
                tree.len() as u32 + comps(&graph_labels) as u32,
                n,
                "forest has a cycle"
            );
            for _ in 0..4 {
                let q: [u32; 4] = std::array::from_fn(|_| rng.random_range(0..n));
                let expected = match (
                    forest_path(n, &tree, q[0], q[1]),
                    forest_path(n, &tree, q[2], q[3]),
                ) {
                    (Some(p1), Some(p2))
                        if graph_labels[q[0] as usize] == graph_labels[q[2] as usize] =>
                    {
                        Some(p1.iter().any(|x| p2.contains(x)))
                    }
                    _ => None,
                };
                assert_eq!(
                    dc.tree_paths_intersect(q[0], q[1], q[2], q[3]),
                    expected,
                    "step {step}: paths {q:?}"
                );
            }
        }
        assert_eq!(dc.edge_count(), shadow.present().len());
        if step % check_every == 0 {
            dc.check_invariants()
                .unwrap_or_else(|msg| panic!("step {step}: {msg}"));
        }
    }
    dc.check_invariants().unwrap();
    dc.stats().max_level
}

#[test]
fn small_dense_sequences() {
    for seed in 0..30 {
        run_sequence(6 + (seed as u32 % 10), 400, seed, 12, 1);
    }
}

#[test]
fn medium_sequences_reach_high_levels() {
    let mut top = 0;
    for seed in 0..4 {
        top = top.max(run_sequence(120, 3000, 1000 + seed, 300, 50));
    }
    eprintln!("highest level reached: {top}");
    assert!(
        top >= 2,
        "the sequences should push edges up several levels"
    );
}

#[test]
fn sparse_sequences() {
    for seed in 0..6 {
        run_sequence(200, 1500, 2000 + seed, 150, 100);
    }
}

#[test]
fn insertions_one_by_one_match_bulk_build() {
    let edges = ear_graph(300, 9);
    let mut one = DynamicConnectivity::new(300);
    for (e, &[a, b]) in edges.iter().enumerate() {
        one.insert_edge(e as u32, a, b);
    }
    one.check_invariants().unwrap();
    let mut bulk = DynamicConnectivity::from_edges(300, &edges);
    bulk.check_invariants().unwrap();
    for e in 0..edges.len() as u32 {
        assert!(!one.is_bridge(e));
        assert!(!bulk.is_bridge(e));
    }
}

/// Frink's choice as the structure answers it: on random bridgeless cubic graphs, remove a simple
/// edge u-v with its four neighbouring edges, pick H1 or H2 by connectivity / tree-path
/// intersection, and check with a bridge DFS from scratch that the chosen graph is connected and
/// bridgeless.
#[test]
fn frink_choice_is_always_bridgeless() {
    let mut rng = ChaCha8Rng::seed_from_u64(77);
    for trial in 0..400u64 {
        let n = 4 + 2 * (trial as u32 % 40);
        let edges = if trial % 2 == 0 {
            ear_graph(n, trial)
        } else {
            pairing_graph(n, trial)
        };
        let other = |e: usize, v: u32| {
            if edges[e][0] == v {
                edges[e][1]
            } else {
                edges[e][0]
            }
        };
        // a simple edge
        let simple: Vec<usize> = (0..edges.len())
            .filter(|&e| {
                let [a, b] = edges[e];
                edges
                    .iter()
                    .filter(|&&[x, y]| (x == a && y == b) || (x == b && y == a))
                    .count()
                    == 1
            })
            .collect();
        let e = simple[rng.random_range(0..simple.len())];
        let [u, v] = edges[e];
        let at = |x: u32| -> Vec<usize> {
            (0..edges.len())
                .filter(|&g| g != e && (edges[g][0] == x || edges[g][1] == x))
                .collect()
        };
        let (ue, ve) = (at(u), at(v));
        let (x1, x2, x3, x4) = (
            other(ue[0], u),
            other(ue[1], u),
            other(ve[0], v),
            other(ve[1], v),
        );
        let mut dc = DynamicConnectivity::from_edges(n, &edges);
        for g in [e, ue[0], ue[1], ve[0], ve[1]] {
            dc.delete_edge(g as u32);
        }
        let take_h1 = if !dc.connected(x1, x2) {
            !dc.connected(x1, x3)
        } else {
            dc.tree_paths_intersect(x1, x3, x2, x4).unwrap()
        };
        let new = if take_h1 {
            [[x1, x3], [x2, x4]]
        } else {
            [[x1, x4], [x2, x3]]
        };
        assert!(new.iter().all(|p| p[0] != p[1]), "trial {trial}: loop");
        // Reduced graph, relabelled without u and v.
        let relabel = |x: u32| x - u32::from(x > u.min(v)) - u32::from(x > u.max(v));
        let mut reduced: Vec<[u32; 2]> = (0..edges.len())
            .filter(|&g| ![e, ue[0], ue[1], ve[0], ve[1]].contains(&g))
            .map(|g| [relabel(edges[g][0]), relabel(edges[g][1])])
            .collect();
        reduced.extend(new.iter().map(|p| [relabel(p[0]), relabel(p[1])]));
        let (comps, bridges) = bridges_and_components(n - 2, &reduced);
        assert_eq!(
            (comps, bridges.len()),
            (1, 0),
            "trial {trial}: chose a bad reduction"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn proptest_sequences(n in 2u32..40, ops in 50usize..300, seed in any::<u64>(), initial in 0usize..60) {
        run_sequence(n, ops, seed, initial, 7);
    }
}
