//! Test helpers written independently of the crate: graph generators, a bridge finder and a
//! matching check. Nothing here calls into `surftopo-matching`.
#![allow(dead_code)]

use rand::seq::SliceRandom;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Random bridgeless cubic multigraph grown from the theta graph: each step subdivides two random
/// edges (maybe the same one) and joins the two new nodes (an "ear"). Ids shuffled.
pub fn ear_graph(n: u32, seed: u64) -> Vec<[u32; 2]> {
    assert!(n >= 2 && n.is_multiple_of(2));
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5eed_0001);
    let (mut edges, _) = ears(n, &mut rng);
    let mut perm: Vec<u32> = (0..n).collect();
    perm.shuffle(&mut rng);
    for e in edges.iter_mut() {
        *e = [perm[e[0] as usize], perm[e[1] as usize]];
        if rng.random_bool(0.5) {
            e.swap(0, 1);
        }
    }
    edges.shuffle(&mut rng);
    edges
}

/// The growth of [`ear_graph`]: from the theta graph on nodes 0 and 1, each step subdivides two
/// edges drawn from `rng` (maybe the same one) and joins the two new nodes, until there are at
/// least `n` nodes. Returns the edges (ids in order of creation) and the node count.
pub fn ears(n: u32, rng: &mut ChaCha8Rng) -> (Vec<[u32; 2]>, u32) {
    let mut edges = vec![[0u32, 1u32]; 3];
    let mut next = 2u32;
    while next < n {
        let i = rng.random_range(0..edges.len());
        let j = rng.random_range(0..edges.len());
        let (s, t) = (next, next + 1);
        next += 2;
        let [a, b] = edges[i];
        edges[i] = [a, s];
        edges.push([s, b]);
        // Re-read j after the change above: if j == i, the edge is now [a, s].
        let [c, d] = edges[j];
        edges[j] = [c, t];
        edges.push([t, d]);
        edges.push([s, t]);
    }
    (edges, next)
}

/// Configuration-model cubic multigraph, redrawn until loop-free, connected and bridgeless.
pub fn pairing_graph(n: u32, seed: u64) -> Vec<[u32; 2]> {
    assert!(n >= 2 && n.is_multiple_of(2));
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5eed_0002);
    let mut half: Vec<u32> = (0..n).flat_map(|v| [v, v, v]).collect();
    loop {
        half.shuffle(&mut rng);
        let edges: Vec<[u32; 2]> = half.chunks(2).map(|p| [p[0], p[1]]).collect();
        if edges.iter().any(|e| e[0] == e[1]) {
            continue;
        }
        let (components, bridges) = bridges_and_components(n, &edges);
        if components == 1 && bridges.is_empty() {
            return edges;
        }
    }
}

/// Dual graph of a closed triangulated surface given by its triangles (each undirected edge must
/// bound exactly two triangles): node = triangle, edge = primal edge.
pub fn dual_of_triangles(tris: &[[u32; 3]]) -> (u32, Vec<[u32; 2]>) {
    let mut keyed: Vec<(u32, u32, u32)> = Vec::with_capacity(tris.len() * 3);
    for (f, t) in tris.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            keyed.push((a.min(b), a.max(b), f as u32));
        }
    }
    keyed.sort_unstable();
    let mut edges = Vec::with_capacity(keyed.len() / 2);
    for pair in keyed.chunks(2) {
        assert!(
            pair.len() == 2 && pair[0].0 == pair[1].0 && pair[0].1 == pair[1].1,
            "not closed manifold"
        );
        edges.push([pair[0].2, pair[1].2]);
    }
    (tris.len() as u32, edges)
}

/// Triangles of a `w × h` grid torus, each square cut along an alternating diagonal.
pub fn torus_triangles(w: u32, h: u32) -> Vec<[u32; 3]> {
    let id = |i: u32, j: u32| (j % h) * w + (i % w);
    let mut t = Vec::new();
    for j in 0..h {
        for i in 0..w {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            if (i + j) % 2 == 0 {
                t.push([a, b, c]);
                t.push([a, c, d]);
            } else {
                t.push([a, b, d]);
                t.push([b, c, d]);
            }
        }
    }
    t
}

/// Triangles of a sphere: a `rings × seg` cylinder grid closed by two cone caps.
pub fn sphere_triangles(rings: u32, seg: u32) -> Vec<[u32; 3]> {
    assert!(rings >= 1 && seg >= 3);
    let id = |r: u32, s: u32| r * seg + (s % seg);
    let south = rings * seg;
    let north = south + 1;
    let mut t = Vec::new();
    for s in 0..seg {
        t.push([south, id(0, s + 1), id(0, s)]);
        t.push([north, id(rings - 1, s), id(rings - 1, s + 1)]);
    }
    for r in 0..rings - 1 {
        for s in 0..seg {
            let (a, b, c, d) = (id(r, s), id(r, s + 1), id(r + 1, s + 1), id(r + 1, s));
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
    }
    t
}

/// Number of connected components and the list of bridges (lowpoint DFS over a CSR adjacency,
/// iterative, parallel edges told apart by id). Loops are ignored (never bridges).
pub fn bridges_and_components(n: u32, edges: &[[u32; 2]]) -> (usize, Vec<usize>) {
    let n = n as usize;
    let mut adj: Vec<Vec<(usize, usize)>> = vec![Vec::new(); n];
    for (e, &[a, b]) in edges.iter().enumerate() {
        if a != b {
            adj[a as usize].push((b as usize, e));
            adj[b as usize].push((a as usize, e));
        }
    }
    let mut order = vec![usize::MAX; n];
    let mut low = vec![0usize; n];
    let mut clock = 0;
    let mut comps = 0;
    let mut bridges = Vec::new();
    for root in 0..n {
        if order[root] != usize::MAX {
            continue;
        }
        comps += 1;
        order[root] = clock;
        low[root] = clock;
        clock += 1;
        let mut stack = vec![(root, usize::MAX, 0usize)];
        while !stack.is_empty() {
            let top = stack.len() - 1;
            let (v, pe, k) = stack[top];
            if k < adj[v].len() {
                stack[top].2 += 1;
                let (w, e) = adj[v][k];
                if e == pe {
                    continue;
                }
                if order[w] == usize::MAX {
                    order[w] = clock;
                    low[w] = clock;
                    clock += 1;
                    stack.push((w, e, 0));
                } else {
                    low[v] = low[v].min(order[w]);
                }
            } else {
                stack.pop();
                if let Some(&(p, _, _)) = stack.last() {
                    low[p] = low[p].min(low[v]);
                    if low[v] > order[p] {
                        bridges.push(pe);
                    }
                }
            }
        }
    }
    bridges.sort_unstable();
    (comps, bridges)
}

/// Panics unless `flags` select exactly one edge at every node.
pub fn assert_perfect(n: u32, edges: &[[u32; 2]], flags: &[bool]) {
    assert_eq!(flags.len(), edges.len());
    let mut deg = vec![0u32; n as usize];
    for (e, &[a, b]) in edges.iter().enumerate() {
        if flags[e] {
            deg[a as usize] += 1;
            deg[b as usize] += 1;
        }
    }
    for (v, &d) in deg.iter().enumerate() {
        assert_eq!(d, 1, "node {v} covered {d} times");
    }
    assert_eq!(flags.iter().filter(|&&f| f).count() * 2, n as usize);
}
