//! Independent checks of quadrangulation results, written without the pipeline's code: they read
//! only the input mesh (and K for LRS) through the basic mesh accessors, the quads, and the
//! pairing reported per quad.
#![allow(dead_code)]

use std::collections::{HashMap, HashSet};

use surftopo_matching::{DualGraph, verify_perfect_matching_on};
use surftopo_mesh::{Contraction, LinkScratch, SurfaceMesh};
use surftopo_quad::{QuadAlgorithm, QuadResult};
use surftopo_testkit::check_closed_oriented_manifold;

/// A triangle as its vertices rotated so that the smallest comes first (orientation kept).
fn canonical(t: [u32; 3]) -> [u32; 3] {
    let i = (0..3).min_by_key(|&i| t[i]).unwrap();
    [t[i], t[(i + 1) % 3], t[(i + 2) % 3]]
}

fn triangles(mesh: &SurfaceMesh) -> HashMap<[u32; 3], u32> {
    mesh.faces()
        .map(|f| (canonical(mesh.face_vertices(f).map(|v| v.0)), f.0))
        .collect()
}

/// Checks that `mesh_k` is a triangulation of the same surface as `input` on the same vertices.
pub fn check_same_surface(input: &SurfaceMesh, mesh_k: &SurfaceMesh) {
    mesh_k
        .check_invariants()
        .expect("K passes check_invariants");
    assert!(mesh_k.is_simplicial(), "K is simplicial");
    assert_eq!(mesh_k.genus(), input.genus(), "K has the input's genus");
    assert_eq!(mesh_k.face_count(), input.face_count());
    assert_eq!(mesh_k.edge_count(), input.edge_count());
    let a: Vec<u32> = input.vertices().map(|v| v.0).collect();
    let b: Vec<u32> = mesh_k.vertices().map(|v| v.0).collect();
    assert_eq!(a, b, "K has the input's vertex ids");
}

/// Every check of the issue on one result. `name` labels failures.
pub fn check_result(
    name: &str,
    input: &SurfaceMesh,
    algorithm: QuadAlgorithm,
    result: &QuadResult,
) {
    let is_lrs = matches!(algorithm, QuadAlgorithm::Lrs);
    let paired = match (&result.triangulation, is_lrs) {
        (Some(k), true) => {
            check_same_surface(input, k);
            k
        }
        (None, false) => input,
        _ => panic!("{name}: K must be given for LRS and only for LRS"),
    };
    // Quad mesh: closed, oriented, manifold, connected, genus, every vertex.
    let polygons: Vec<Vec<u32>> = result
        .quads
        .iter()
        .map(|q| q.iter().map(|v| v.0).collect())
        .collect();
    assert_eq!(2 * polygons.len(), input.face_count(), "{name}: F/2 quads");
    let chi = check_closed_oriented_manifold(&polygons)
        .unwrap_or_else(|e| panic!("{name}: quad mesh is not a closed oriented manifold: {e}"));
    assert_eq!(chi, input.euler_characteristic(), "{name}: genus kept");
    let used: HashSet<u32> = polygons.iter().flatten().copied().collect();
    let live: HashSet<u32> = input.vertices().map(|v| v.0).collect();
    assert_eq!(
        used, live,
        "{name}: the quads use exactly the input's vertices"
    );
    assert_connected(name, &polygons);
    // Each quad is two triangles of the paired triangulation glued along the reported diagonal,
    // and every triangle is in exactly one quad.
    let tris = triangles(paired);
    let mut used_tri: HashSet<[u32; 3]> = HashSet::new();
    assert_eq!(result.diagonals.len(), result.quads.len());
    let mut flags = vec![false; paired.edge_slots()];
    for (q, &diag) in polygons.iter().zip(&result.diagonals) {
        let splits = [
            ([q[0], q[1], q[2]], [q[2], q[3], q[0]], (q[0], q[2])),
            ([q[1], q[2], q[3]], [q[3], q[0], q[1]], (q[1], q[3])),
        ];
        let [p, r] = paired.edge_vertices(diag).map(|v| v.0);
        let split = splits
            .iter()
            .find(|(s, t, (a, b))| {
                ((p, r) == (*a, *b) || (p, r) == (*b, *a))
                    && tris.contains_key(&canonical(*s))
                    && tris.contains_key(&canonical(*t))
            })
            .unwrap_or_else(|| {
                panic!(
                    "{name}: quad {q:?} is not two triangles glued along its diagonal e{}",
                    diag.0
                )
            });
        for t in [split.0, split.1] {
            assert!(
                used_tri.insert(canonical(t)),
                "{name}: triangle {t:?} in two quads"
            );
        }
        let faces_of_diag = [diag.halfedge(), diag.halfedge().twin()].map(|h| paired.face(h).0);
        let mut expected = [tris[&canonical(split.0)], tris[&canonical(split.1)]];
        let mut got = faces_of_diag;
        expected.sort_unstable();
        got.sort_unstable();
        assert_eq!(
            got, expected,
            "{name}: diagonal e{} is not between the quad's triangles",
            diag.0
        );
        flags[diag.idx()] = true;
    }
    assert_eq!(used_tri.len(), tris.len(), "{name}: every triangle paired");
    // The pairing, as per-edge flags, is the one the result reports and a perfect matching of the
    // dual (the crate's counting verifier).
    assert!(
        result.pairing.edge_flags(paired.edge_slots()) == flags,
        "{name}: the quads' diagonals are the reported pairing"
    );
    let dense = paired.face_slots() == paired.face_count();
    if dense {
        verify_perfect_matching_on(paired.face_count() as u32, &paired.edge_list(), &flags)
            .unwrap_or_else(|e| panic!("{name}: not a perfect matching: {e}"));
    }
    // Figures.
    let s = &result.stats;
    assert_eq!(s.algorithm, algorithm.name());
    assert_eq!(s.faces, input.face_count());
    assert!(s.unpaired <= s.faces);
    let pct = 100.0 * (s.faces - s.unpaired) as f64 / s.faces as f64;
    assert!((s.paired_percent - pct).abs() < 1e-9);
    assert!(s.initial_pairing_seconds >= 0.0 && s.augmentation_seconds >= 0.0);
    assert!(s.total_seconds >= s.initial_pairing_seconds + s.augmentation_seconds - 1e-9);
    if let Some(ks) = &result.karp_sipser {
        // KS: every isolated triangle is repaired (one augmenting path to a free triangle each)
        // or deferred; the guided completion and then the Forest completion pair the deferred
        // ones still unpaired two by two.
        assert!(matches!(algorithm, QuadAlgorithm::KarpSipser), "{name}");
        assert_eq!(ks.isolated, s.unpaired, "{name}");
        assert_eq!(ks.repaired + ks.deferred, ks.isolated, "{name}");
        assert!(ks.completed.is_multiple_of(2), "{name}");
        assert!(2 * ks.guided + ks.completed <= ks.deferred, "{name}");
        assert!(ks.guided_by_edmonds <= ks.guided, "{name}");
        assert_eq!(
            result.augmentation.augmentations,
            ks.repaired + ks.guided + ks.completed / 2,
            "{name}"
        );
    } else {
        assert!(!matches!(algorithm, QuadAlgorithm::KarpSipser), "{name}");
        assert!(s.unpaired.is_multiple_of(2), "{name}");
        assert_eq!(result.augmentation.augmentations, s.unpaired / 2);
    }
    if is_lrs {
        // flipped_edges counts the edge ids whose endpoints differ between the input and K.
        let differ = input
            .edges()
            .filter(|&e| {
                let mut a = input.edge_vertices(e);
                let mut b = paired.edge_vertices(e);
                a.sort();
                b.sort();
                a != b
            })
            .count();
        assert_eq!(s.flipped_edges, differ, "{name}: flipped_edges");
        let bound = (56 * input.genus() - 12).max(4);
        assert!(
            s.unpaired as i64 <= bound,
            "{name}: {} unpaired > {bound}",
            s.unpaired
        );
    } else {
        assert_eq!(s.flipped_edges, 0);
    }
}

fn assert_connected(name: &str, polygons: &[Vec<u32>]) {
    let n = polygons
        .iter()
        .flatten()
        .copied()
        .max()
        .map_or(0, |m| m as usize + 1);
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(p: &mut [usize], mut x: usize) -> usize {
        while p[x] != x {
            p[x] = p[p[x]];
            x = p[x];
        }
        x
    }
    for q in polygons {
        for w in q.windows(2) {
            let (a, b) = (
                find(&mut parent, w[0] as usize),
                find(&mut parent, w[1] as usize),
            );
            parent[a] = b;
        }
    }
    let roots: HashSet<usize> = polygons
        .iter()
        .flatten()
        .map(|&v| find(&mut parent, v as usize))
        .collect();
    assert_eq!(roots.len(), 1, "{name}: quad mesh is not connected");
}

/// A contraction sequence written for the tests, independent of `surftopo-irreducible`: vertices
/// in increasing id order, each contracting its edges that satisfy the link condition (into it)
/// until none does (it is trapped), as Section 3.3.1 describes the contraction step. Quadratic in
/// the degree; for small meshes.
pub fn naive_contractions(mesh: &SurfaceMesh) -> (SurfaceMesh, Vec<Contraction>) {
    let mut mesh = mesh.clone();
    let mut history = Vec::new();
    let mut scratch = LinkScratch::default();
    for u in 0..mesh.vertex_slots() {
        let u = surftopo_mesh::VertexId::new(u);
        if !mesh.is_vertex_live(u) {
            continue;
        }
        loop {
            let next = mesh
                .outgoing(u)
                .find(|&h| mesh.satisfies_link_condition(h, &mut scratch));
            match next {
                Some(h) => history.push(mesh.contract_unchecked(h)),
                None => break,
            }
        }
    }
    (mesh, history)
}

/// Every check of a quadrangulation of a compact surface, written from the input's triangles
/// (vertex ids, one per input face) alone: each input triangle is a leftover triangle or half of
/// exactly one quad, glued to an adjacent triangle along the quad's diagonal (corner 0 to corner
/// 2), or (all quads) the union of a quad's two halves at an added boundary vertex; the quads'
/// corners run in the order of their first triangle; the triangles left are as few as
/// petgraph's maximum matching of the dual allows; the figures add up. For the triangles of the
/// paired triangulation, `paired` (LRS's K) replaces `input` in the covering checks.
pub fn check_surface_result(
    name: &str,
    input: &[[u32; 3]],
    paired: &[[u32; 3]],
    result: &surftopo_quad::SurfaceQuads,
    all_quads: bool,
) {
    use petgraph::algo::maximum_matching;
    use petgraph::graph::UnGraph;
    let key = |t: [u32; 3]| {
        let mut k = t;
        k.sort_unstable();
        k
    };
    let index: HashMap<[u32; 3], usize> = paired
        .iter()
        .enumerate()
        .map(|(f, &t)| (key(t), f))
        .collect();
    assert_eq!(index.len(), paired.len(), "{name}: duplicate triangles");
    let mut edge_faces: HashMap<[u32; 2], Vec<usize>> = HashMap::new();
    for (f, t) in paired.iter().enumerate() {
        for i in 0..3 {
            let (a, b) = (t[i], t[(i + 1) % 3]);
            edge_faces.entry([a.min(b), a.max(b)]).or_default().push(f);
        }
    }
    let boundary: HashSet<[u32; 2]> = edge_faces
        .iter()
        .filter(|(_, f)| f.len() == 1)
        .map(|(&e, _)| e)
        .collect();
    let cyclic = |q: &[u32], t: [u32; 3]| (0..3).any(|r| (0..3).all(|i| q[i] == t[(i + r) % 3]));
    let n = result.vertex_count as u32;
    let mut used = vec![0u32; paired.len()];
    let mut added_seen = HashSet::new();
    for q in &result.quads {
        let [a, d, b, c] = *q;
        if let Some(k) = q.iter().position(|&v| v >= n) {
            // A split triangle: [w, y, z, x] with w the midpoint of boundary edge xy.
            assert!(all_quads, "{name}: added vertex without all quads");
            assert_eq!(k, 0, "{name}: quad {q:?}: the added vertex is not corner 0");
            let [x, y] = result.added[(q[0] - n) as usize];
            assert_eq!((q[1], q[3]), (y, x), "{name}: quad {q:?}");
            assert!(boundary.contains(&[x.min(y), x.max(y)]), "{name}: {q:?}");
            assert!(
                added_seen.insert(q[0]),
                "{name}: vertex {} added twice",
                q[0]
            );
            let f = index[&key([x, y, q[2]])];
            assert!(
                cyclic(&[x, y, q[2]], paired[f]),
                "{name}: {q:?} not in order"
            );
            used[f] += 1;
            continue;
        }
        let first = index
            .get(&key([a, b, c]))
            .unwrap_or_else(|| panic!("{name}: quad {q:?}: no triangle {a} {b} {c}"));
        let second = index
            .get(&key([b, a, d]))
            .unwrap_or_else(|| panic!("{name}: quad {q:?}: no triangle {b} {a} {d}"));
        assert_ne!(first, second);
        assert!(
            cyclic(&[a, b, c], paired[*first]),
            "{name}: quad {q:?} does not run in its first triangle's order {:?}",
            paired[*first]
        );
        used[*first] += 1;
        used[*second] += 1;
    }
    for t in &result.triangles {
        used[index[&key(*t)]] += 1;
    }
    assert!(
        used.iter().all(|&u| u == 1),
        "{name}: a triangle is not used once"
    );
    assert_eq!(added_seen.len(), result.added.len(), "{name}");
    // Maximum: as few triangles left as petgraph's maximum matching of the input's dual leaves.
    let mut graph = UnGraph::<(), ()>::with_capacity(paired.len(), 0);
    for _ in paired {
        graph.add_node(());
    }
    for faces in edge_faces.values() {
        if let [f, g] = faces[..] {
            graph.add_edge((f as u32).into(), (g as u32).into(), ());
        }
    }
    let fewest = paired.len() - 2 * maximum_matching(&graph).len();
    let s = &result.stats;
    assert_eq!(
        s.deficiency_lower_bound, fewest,
        "{name}: the certificate's bound"
    );
    if all_quads {
        assert!(result.triangles.is_empty(), "{name}");
        assert_eq!(
            result.added.len(),
            fewest,
            "{name}: one vertex per leftover"
        );
        assert_eq!(2 * result.quads.len(), paired.len() + fewest, "{name}");
    } else {
        assert_eq!(result.triangles.len(), fewest, "{name}: not maximum");
        assert_eq!(2 * result.quads.len() + fewest, paired.len(), "{name}");
    }
    assert_eq!(s.unpaired_triangles, result.triangles.len(), "{name}");
    assert_eq!(s.added_vertices, result.added.len(), "{name}");
    assert_eq!(s.faces, input.len(), "{name}");
    let sum = |f: fn(&surftopo_quad::ComponentQuads) -> usize| -> usize {
        result.components.iter().map(f).sum()
    };
    assert_eq!(sum(|c| c.faces), input.len(), "{name}");
    assert_eq!(sum(|c| c.quads), result.quads.len(), "{name}");
    assert_eq!(sum(|c| c.added_vertices), result.added.len(), "{name}");
    assert_eq!(sum(|c| c.deficiency_lower_bound), fewest, "{name}");
    assert_eq!(
        s.components.len(),
        if result.components.len() > 1 {
            result.components.len()
        } else {
            0
        },
        "{name}"
    );
    // Every vertex of the input is a corner of the output.
    let corners: HashSet<u32> = result
        .quads
        .iter()
        .flatten()
        .chain(result.triangles.iter().flatten())
        .copied()
        .collect();
    for &v in input.iter().flatten() {
        assert!(corners.contains(&v), "{name}: vertex {v} lost");
    }
}
