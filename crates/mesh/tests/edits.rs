//! Random sequences of flips, contractions and splits keep every invariant; split after contract
//! gives back the identical mesh.

use proptest::prelude::*;
use surftopo_mesh::generators::{icosphere, torus};
use surftopo_mesh::{EdgeId, HalfedgeId, LinkScratch, SurfaceMesh};

/// Independent recount of V, E, F and genus from the live elements.
fn genus_by_counting(mesh: &SurfaceMesh) -> i64 {
    let v = mesh.vertices().count() as i64;
    let e = mesh.edges().count() as i64;
    let f = mesh.faces().count() as i64;
    (2 - (v - e + f)) / 2
}

/// Link condition recomputed naively: common neighbours of the endpoints are exactly the two
/// opposite vertices, and the mesh is not the tetrahedron.
fn link_condition_naive(mesh: &SurfaceMesh, h: HalfedgeId) -> bool {
    let (u, v) = (mesh.origin(h), mesh.dest(h));
    let nu: std::collections::BTreeSet<_> = mesh.neighbors(u).collect();
    let nv: std::collections::BTreeSet<_> = mesh.neighbors(v).collect();
    let common: Vec<_> = nu.intersection(&nv).collect();
    common.len() == 2 && mesh.vertex_count() > 4
}

/// Contracts edges that pass the link condition, first found first, until none is left; returns
/// the records in contraction order.
fn contract_until_irreducible(mesh: &mut SurfaceMesh) -> Vec<surftopo_mesh::Contraction> {
    let mut scratch = LinkScratch::default();
    let mut stack = Vec::new();
    loop {
        let next = mesh
            .halfedges()
            .find(|&h| mesh.satisfies_link_condition(h, &mut scratch));
        let Some(h) = next else { break };
        stack.push(mesh.contract(h, &mut scratch).unwrap());
    }
    stack
}

#[derive(Clone, Debug)]
enum Op {
    Flip(usize),
    Contract(usize),
    Split(usize, usize, usize),
}

fn op() -> impl Strategy<Value = Op> {
    prop_oneof![
        any::<usize>().prop_map(Op::Flip),
        any::<usize>().prop_map(Op::Contract),
        (any::<usize>(), any::<usize>(), any::<usize>()).prop_map(|(a, b, c)| Op::Split(a, b, c)),
    ]
}

fn run_ops(mut mesh: SurfaceMesh, ops: &[Op]) {
    let genus = mesh.genus();
    let mut scratch = LinkScratch::default();
    let mut history = Vec::new();
    for op in ops {
        let live: Vec<EdgeId> = mesh.edges().collect();
        match *op {
            Op::Flip(i) => {
                let e = live[i % live.len()];
                if mesh.can_flip_simplicial(e) {
                    mesh.flip(e).unwrap();
                    history.clear();
                }
            }
            Op::Contract(i) => {
                let h = live[i % live.len()].halfedge();
                let h = if i % 2 == 0 { h } else { h.twin() };
                let expected = link_condition_naive(&mesh, h);
                let before = mesh.clone();
                match mesh.contract(h, &mut scratch) {
                    Ok(record) => {
                        assert!(
                            expected,
                            "contracted an edge failing the naive link condition"
                        );
                        mesh.check_invariants().unwrap();
                        assert!(mesh.is_simplicial());
                        let mut undone = mesh.clone();
                        undone.split_vertex(&record);
                        assert_eq!(undone, before, "split after contract differs");
                        history.push((record, before));
                    }
                    Err(_) => assert!(
                        !expected,
                        "refused an edge passing the naive link condition"
                    ),
                }
            }
            Op::Split(i, a, b) => {
                let vs: Vec<_> = mesh.vertices().collect();
                let v = vs[i % vs.len()];
                let out: Vec<_> = mesh.outgoing(v).collect();
                let (y, x) = (out[a % out.len()], out[b % out.len()]);
                if x != y {
                    mesh.split_vertex_new(y, x).unwrap();
                    history.clear();
                }
            }
        }
        mesh.check_invariants().unwrap();
        assert!(mesh.is_simplicial());
        assert_eq!(genus_by_counting(&mesh), genus);
    }
    // Replaying the contraction history backwards restores each earlier mesh exactly.
    while let Some((record, before)) = history.pop() {
        mesh.split_vertex(&record);
        assert_eq!(mesh, before);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn random_edits_on_sphere(ops in prop::collection::vec(op(), 1..120)) {
        run_ops(icosphere(1).mesh, &ops);
    }

    #[test]
    fn random_edits_on_torus(ops in prop::collection::vec(op(), 1..120)) {
        run_ops(torus(6, 5).mesh, &ops);
    }
}

#[test]
fn contracting_a_sphere_down_to_the_tetrahedron() {
    let mut mesh = icosphere(2).mesh;
    let original = mesh.clone();
    let mut stack = contract_until_irreducible(&mut mesh);
    assert_eq!(
        (mesh.vertex_count(), mesh.edge_count(), mesh.face_count()),
        (4, 6, 4)
    );
    mesh.check_invariants().unwrap();
    while let Some(r) = stack.pop() {
        mesh.split_vertex(&r);
    }
    assert_eq!(mesh, original);
}

#[test]
fn compaction_keeps_the_surface() {
    let mut mesh = torus(8, 7).mesh;
    let mut scratch = LinkScratch::default();
    for _ in 0..20 {
        let h = mesh
            .halfedges()
            .find(|&h| mesh.satisfies_link_condition(h, &mut scratch))
            .unwrap();
        mesh.contract(h, &mut scratch).unwrap();
    }
    let (v, e, f) = (mesh.vertex_count(), mesh.edge_count(), mesh.face_count());
    let map = mesh.compact();
    mesh.check_invariants().unwrap();
    assert_eq!(
        (mesh.vertex_slots(), mesh.edge_slots(), mesh.face_slots()),
        (v, e, f)
    );
    assert_eq!(map.vertices.iter().filter(|x| x.is_valid()).count(), v);
    assert_eq!(mesh.genus(), 1);
}

#[test]
fn morton_reordering_keeps_the_surface_and_its_geometry() {
    use surftopo_mesh::geometry::{edge_lengths, reorder_morton};
    let surface = torus(12, 9);
    let (mut mesh, mut positions) = (surface.mesh.clone(), surface.positions.clone());
    let sorted = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v
    };
    let before = sorted(edge_lengths(&mesh, &positions));
    let map = reorder_morton(&mut mesh, &mut positions);
    mesh.check_invariants().unwrap();
    assert_eq!(mesh.genus(), 1);
    assert_eq!(sorted(edge_lengths(&mesh, &positions)), before);
    for v in surface.mesh.vertices() {
        assert_eq!(
            positions[map.vertices[v.idx()].idx()],
            surface.positions[v.idx()]
        );
    }
    for f in surface.mesh.faces() {
        let old = surface.mesh.face_vertices(f).map(|v| map.vertices[v.idx()]);
        let new = mesh.face_vertices(map.faces[f.idx()]);
        let rotations = [[0, 1, 2], [1, 2, 0], [2, 0, 1]];
        assert!(
            rotations.iter().any(|r| r.map(|i| new[i]) == old),
            "face {f:?} changed"
        );
    }
}

/// LRS-style replay: contract down, then split back while flipping edges in between that are not
/// split edges of pending records; every intermediate mesh keeps its invariants.
#[test]
fn splits_stay_valid_when_edges_are_flipped_in_between() {
    use surftopo_mesh::generators::{genus_surface, random_flips};
    for seed in 0..6 {
        let mut mesh = random_flips(&genus_surface(2, 2), 500, seed).mesh;
        let mut stack = contract_until_irreducible(&mut mesh);
        let mut k = seed as usize;
        while let Some(record) = stack.pop() {
            mesh.split_vertex(&record);
            mesh.check_invariants().unwrap();
            let pending: std::collections::HashSet<EdgeId> =
                stack.iter().flat_map(|r| r.split_edges()).collect();
            let edges: Vec<EdgeId> = mesh.edges().collect();
            for _ in 0..3 {
                k = (k * 7919 + 13) % edges.len();
                let e = edges[k];
                if !pending.contains(&e) && mesh.can_flip_simplicial(e) {
                    mesh.flip(e).unwrap();
                }
            }
            mesh.check_invariants().unwrap();
            assert!(mesh.is_simplicial());
        }
        assert_eq!(mesh.genus(), 2);
    }
}
