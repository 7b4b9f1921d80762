//! ε of Schipper's algorithm (S) on reduced group-C/D bricks, counted under other identities of
//! an edge and measured on variants of S (irreducible-triangulations paper, Section 5.3;
//! `results/papers/irreducible.md`, item 6).
//!
//! Identities: contracting [u, v] into u merges [v, x] into [u, x] and [v, y] into [u, y]; ours
//! keeps the ids of [u, x] and [u, y]. From the tests of [`schipper_traced`] and the history, ε
//! is recounted with an edge identified by its id (ours), by the removed record ([v, x]'s tests
//! carry on in the merged edge), by both records (the merged edge carries the tests of both), by
//! the pair of end vertex ids at the time of the test, and, for reference, as repeated tests (ℓ
//! minus the distinct edges tested).
//!
//! Variants (a copy of S here, not the library's; `Ours` gives the library's counts): the chosen
//! vertex kept by its contraction instead of removed, or the end of the edge's first half-edge
//! kept (either end, as a half-edge structure may store it); the vertices of the removed vertex's link
//! put back into the global dictionary after each contraction, trapped or not; a vertex's edges
//! tried by increasing id or degree of the other end, or in rotation order from a position that
//! depends on the vertex; the chosen vertex chosen again at once after its contraction, its edges
//! tried afresh, while its degree is at most 6 or until it is trapped (the latter quadratic, as
//! the vertex takes in its whole region: run up to 10,000 triangles). Each variant's seconds
//! (wall-clock, one run) are printed too.
//!
//! ```sh
//! cargo run --release -p surftopo-bench --example schipper_epsilon [-- MAX_TRIANGLES]
//! ```

use std::collections::BTreeSet;

use surftopo_irreducible::{
    LinkDictionaries, LinkTest, Reduction, ramaswami_siqueira, schipper_traced,
};
use surftopo_mesh::generators::{CavityBox, random_flips};
use surftopo_mesh::{HalfedgeId, Surface, SurfaceMesh, VertexId};

/// How a merged edge is identified when ε is recounted.
#[derive(Clone, Copy)]
enum Identity {
    Kept,
    Removed,
    Both,
}

/// ε under `identity`: classes of edge records (merged as contractions go) tested twice or more.
fn epsilon(edges: usize, r: &Reduction, tests: &[LinkTest], identity: Identity) -> u64 {
    let mut parent: Vec<u32> = (0..edges as u32).collect();
    let mut count = vec![0u32; edges];
    let find = |parent: &mut Vec<u32>, mut e: u32| {
        while parent[e as usize] != e {
            let p = parent[e as usize];
            parent[e as usize] = parent[p as usize];
            e = p;
        }
        e
    };
    // alias[e]: the record that tests of edge id e now go to.
    let mut alias: Vec<u32> = (0..edges as u32).collect();
    let (mut eps, mut next) = (0u64, 0usize);
    for t in tests {
        while next < t.contractions_before {
            let k = &r.history[next];
            for (removed, kept) in k.removed_edges().into_iter().zip(k.split_edges()) {
                match identity {
                    Identity::Kept => {}
                    Identity::Removed => alias[kept.idx()] = alias[removed.idx()],
                    Identity::Both => {
                        let a = find(&mut parent, alias[removed.idx()]);
                        let b = find(&mut parent, alias[kept.idx()]);
                        if a != b {
                            let repeated = |c: u32| u64::from(c >= 2);
                            let before = repeated(count[a as usize]) + repeated(count[b as usize]);
                            parent[a as usize] = b;
                            count[b as usize] += count[a as usize];
                            eps = eps + repeated(count[b as usize]) - before;
                        }
                    }
                }
            }
            next += 1;
        }
        let class = find(&mut parent, alias[t.edge.idx()]) as usize;
        count[class] += 1;
        eps += u64::from(count[class] == 2);
    }
    eps
}

/// A variant of S (see the module doc; `Ours` is the library's S).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Variant {
    Ours,
    ChosenKept,
    EdgeOrientation,
    LinkPutBack,
    ByNeighbourId,
    ByNeighbourDegree,
    ShiftedStart,
    AgainUntilTrapped,
    AgainWhileDegreeSix,
}

/// The counts of one run: ℓ, ε, contractions.
struct Counts {
    link_tests: u64,
    eps: u64,
    contractions: u64,
}

/// S as `crates/irreducible/src/schipper.rs` (`Variant::Ours` gives its counts), with `variant`.
fn run_variant(mut mesh: SurfaceMesh, variant: Variant) -> Counts {
    let mut dict = LinkDictionaries::new(&mesh);
    let key = |dict: &LinkDictionaries, z: VertexId| (dict.degree(z), z.0);
    let mut by_degree: BTreeSet<(u32, u32)> = mesh.vertices().map(|v| key(&dict, v)).collect();
    let mut tests = vec![0u8; mesh.edge_slots()];
    let mut c = Counts {
        link_tests: 0,
        eps: 0,
        contractions: 0,
    };
    let mut fan: Vec<HalfedgeId> = Vec::new();
    let mut current: Option<VertexId> = None;
    while let Some(&(first_degree, first)) = by_degree.first() {
        if variant == Variant::AgainWhileDegreeSix && current.is_some_and(|v| dict.degree(v) > 6) {
            current = None;
        }
        let (degree, vi) = match current {
            Some(v) => key(&dict, v),
            None => (first_degree, first),
        };
        let v = VertexId(vi);
        fan.clear();
        fan.extend(mesh.outgoing(v));
        match variant {
            Variant::ByNeighbourId => fan.sort_by_key(|&h| mesh.dest(h).0),
            Variant::ByNeighbourDegree => fan.sort_by_key(|&h| key(&dict, mesh.dest(h))),
            Variant::ShiftedStart => {
                let n = fan.len();
                fan.rotate_left(vi as usize * 7919 % n);
            }
            _ => {}
        }
        let found = fan.iter().copied().find(|&h| {
            c.link_tests += 1;
            let t = &mut tests[h.edge().idx()];
            c.eps += u64::from(*t == 1);
            *t = t.saturating_add(1);
            dict.link_condition(&mesh, h)
        });
        let Some(h) = found else {
            by_degree.remove(&(degree, vi));
            current = None;
            continue;
        };
        if variant == Variant::AgainUntilTrapped {
            current = Some(v);
        }
        if variant == Variant::AgainWhileDegreeSix {
            current = Some(v);
        }
        // Kept k, removed r; x, y opposite the edge.
        let keep_chosen = match variant {
            Variant::ChosenKept | Variant::AgainWhileDegreeSix | Variant::AgainUntilTrapped => true,
            Variant::EdgeOrientation => mesh.origin(h.edge().halfedge()) == v,
            _ => false,
        };
        let (k, r, kept_to_removed) = if keep_chosen {
            (v, mesh.dest(h), h)
        } else {
            (mesh.dest(h), v, h.twin())
        };
        let (x, y) = (mesh.opposite_vertex(h), mesh.opposite_vertex(h.twin()));
        let old = [k, x, y].map(|z| key(&dict, z));
        let removed_key = key(&dict, r);
        mesh.contract_unchecked(kept_to_removed);
        c.contractions += 1;
        let link = dict.contract(r, k, [x, y]);
        by_degree.remove(&removed_key);
        for (old_key, z) in old.into_iter().zip([k, x, y]) {
            if by_degree.remove(&old_key) || variant == Variant::LinkPutBack {
                by_degree.insert(key(&dict, z));
            }
        }
        if variant == Variant::LinkPutBack {
            for &z in link.iter().filter(|&&z| z != k.0) {
                by_degree.insert(key(&dict, VertexId(z)));
            }
        }
    }
    c
}

/// The inputs: reduced bricks of groups C and D (60 pits, the paper's 3,844 / 64), and others.
fn inputs() -> Vec<(String, Surface)> {
    let d0 = CavityBox::fit(5, 55, 66_000);
    let bricks = [
        (
            "small D0-like: 55 holes, 110 triangles per pit",
            CavityBox::fit(5, 55, 6_600),
        ),
        ("D0-like: 55 holes, 1,100 triangles per pit", d0),
        (
            "D9-like: 5 holes, 1,100 triangles per pit",
            CavityBox::fit(55, 5, 66_000),
        ),
        (
            "C7-like: 55 holes, coarsest",
            CavityBox::new(5, 55, 1, 1, 1, 1),
        ),
        (
            "55 holes, 11,000 triangles per pit",
            CavityBox::fit(5, 55, 660_000),
        ),
        (
            "55 one-square holes in wide walls",
            CavityBox::new(5, 55, 1, 13, 1, 1),
        ),
        (
            "55 long holes (floor 100)",
            CavityBox::new(5, 55, 6, 6, 5, 100),
        ),
    ];
    let mut list: Vec<(String, Surface)> = bricks
        .into_iter()
        .map(|(name, b)| (name.to_string(), b.generate()))
        .collect();
    list.push((
        "D0-like, 200,000 random flips".into(),
        random_flips(&d0.generate(), 200_000, 1),
    ));
    list
}

fn main() {
    let max_faces: usize = std::env::args()
        .nth(1)
        .map_or(usize::MAX, |a| a.parse().expect("a triangle count"));
    for (name, surface) in inputs() {
        if surface.mesh.face_count() > max_faces {
            continue;
        }
        let mesh = surface.mesh;
        let (v, f, g, edges) = (
            mesh.vertex_count(),
            mesh.face_count(),
            mesh.genus(),
            mesh.edge_slots(),
        );
        let per_g = |x: u64| x as f64 / g.max(1) as f64;
        let rs = ramaswami_siqueira(mesh.clone()).expect("simplicial");
        let (r, tests) = schipper_traced(mesh.clone()).expect("simplicial");
        let failed = r.counters.link_tests - r.counters.contractions;
        let edges_out = r.mesh.edge_count() as u64;
        println!(
            "{name}: V {v}, F {f}, g {g}; RS (ℓ_rs − V)/g {:.0}; S: failed tests {:.1}·g, \
             output edges {:.1}·g",
            (rs.counters.link_tests as f64 - v as f64) / g.max(1) as f64,
            per_g(failed),
            per_g(edges_out)
        );
        let mut pairs = std::collections::HashMap::<(u32, u32), u32>::new();
        let mut distinct = vec![false; edges];
        for t in &tests {
            distinct[t.edge.idx()] = true;
            let [a, b] = t.ends.map(|x| x.0);
            *pairs.entry((a.min(b), a.max(b))).or_default() += 1;
        }
        let distinct = distinct.iter().filter(|&&d| d).count() as u64;
        let identities = [
            ("edge id (ours)", epsilon(edges, &r, &tests, Identity::Kept)),
            (
                "removed record",
                epsilon(edges, &r, &tests, Identity::Removed),
            ),
            ("both records", epsilon(edges, &r, &tests, Identity::Both)),
            (
                "end-vertex pair",
                pairs.values().filter(|&&c| c >= 2).count() as u64,
            ),
            ("repeated tests", r.counters.link_tests - distinct),
        ];
        assert_eq!(identities[0].1, r.counters.edges_tested_more_than_once);
        let line: Vec<String> = identities
            .iter()
            .map(|(what, eps)| format!("{what} {:.1}·g", per_g(*eps)))
            .collect();
        println!("  ε counted by {}", line.join(", "));
        let mut first_choice = std::collections::HashMap::new();
        let again = tests
            .iter()
            .filter(|t| {
                let first = *first_choice
                    .entry(t.ends[0])
                    .or_insert(t.contractions_before);
                first < t.contractions_before
            })
            .map(|t| t.ends[0])
            .collect::<std::collections::HashSet<_>>()
            .len();
        println!("  vertices chosen again after a contraction: {again}");
        for variant in [
            Variant::Ours,
            Variant::ChosenKept,
            Variant::EdgeOrientation,
            Variant::LinkPutBack,
            Variant::ByNeighbourId,
            Variant::ByNeighbourDegree,
            Variant::ShiftedStart,
            Variant::AgainWhileDegreeSix,
            Variant::AgainUntilTrapped,
        ] {
            if variant == Variant::AgainUntilTrapped && f > 10_000 {
                continue; // quadratic: the kept vertex takes in its whole region
            }
            let start = std::time::Instant::now();
            let c = run_variant(mesh.clone(), variant);
            let seconds = start.elapsed().as_secs_f64();
            let failed = c.link_tests - c.contractions;
            if variant == Variant::Ours {
                assert_eq!(c.link_tests, r.counters.link_tests);
                assert_eq!(c.eps, r.counters.edges_tested_more_than_once);
            }
            println!(
                "  {variant:?}: failed {:.1}·g, ε {:.1}·g, ε / failed {:.2}, {seconds:.2} s",
                per_g(failed),
                per_g(c.eps),
                c.eps as f64 / failed.max(1) as f64
            );
        }
    }
}
