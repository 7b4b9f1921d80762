//! All three algorithms on generated inputs, each result checked by `support::verify` (independent
//! of the algorithms): spheres and tori with random flips, surfaces of genus 1 to 200, the papers'
//! cavity/hole bricks, random vertex splits of small irreducible triangulations.

mod support;

use proptest::prelude::*;
use support::{all_algorithms, run_and_verify, verify};
use surftopo_irreducible::{Algorithm, brute_force, ramaswami_siqueira, schipper, schipper_traced};
use surftopo_mesh::Surface;
use surftopo_mesh::SurfaceMesh;
use surftopo_mesh::generators::{
    CavityBox, cavity_box, genus_surface, icosphere, random_flips, random_vertex_splits,
    tetrahedron, torus,
};

/// The irreducible triangulation found by RS, as a dense surface (for vertex splits).
fn irreducible_surface(input: &Surface) -> Surface {
    let red = ramaswami_siqueira(input.mesh.clone()).expect("simplicial");
    let mut s = Surface {
        positions: input.positions.clone(),
        mesh: red.mesh,
    };
    s.compact();
    s
}

/// RS's decision 5 (T4 is recognised by two degree-3 endpoints and left alone, untested).
#[test]
fn the_tetrahedron_is_returned_unchanged() {
    let t4 = tetrahedron().mesh;
    for a in all_algorithms(3) {
        let red = run_and_verify(&t4, a, true);
        assert_eq!(red.mesh, t4);
        assert!(red.history.is_empty());
        let c = red.counters;
        // RS drops every edge of T4 untested (Proposition 6); S tests the three edges of each
        // vertex (6 edges twice); BF makes one pass over the 6 edges.
        let expected = match a {
            Algorithm::RamaswamiSiqueira => (0, 0),
            Algorithm::Schipper => (12, 6),
            Algorithm::BruteForce { .. } => (6, 0),
        };
        assert_eq!((c.link_tests, c.edges_tested_more_than_once), expected);
    }
}

#[test]
fn spheres_reduce_to_the_tetrahedron() {
    let mut inputs: Vec<SurfaceMesh> = (0..=3).map(|s| icosphere(s).mesh).collect();
    for seed in 0..6 {
        inputs.push(random_flips(&icosphere(3), 2000, seed).mesh);
    }
    inputs.push(random_vertex_splits(&tetrahedron(), 500, 11).mesh);
    for (i, mesh) in inputs.iter().enumerate() {
        for a in all_algorithms(i as u64) {
            let red = run_and_verify(mesh, a, true);
            if a == Algorithm::RamaswamiSiqueira {
                // Section 4.6: on genus 0 every contraction happens while the first vertex of Q
                // is processed.
                let first = mesh.vertices().next().expect("a vertex");
                assert!(red.history.iter().all(|r| r.kept() == first));
            }
        }
    }
}

#[test]
fn tori_give_seven_to_ten_vertices() {
    let mut inputs: Vec<SurfaceMesh> = [(3, 3), (3, 7), (4, 4), (8, 5), (20, 9)]
        .map(|(m, n)| torus(m, n).mesh)
        .to_vec();
    for seed in 0..8 {
        inputs.push(random_flips(&torus(16, 12), 300 * (seed as usize + 1), seed).mesh);
    }
    for (i, mesh) in inputs.iter().enumerate() {
        for a in all_algorithms(100 + i as u64) {
            run_and_verify(mesh, a, true);
        }
    }
}

/// Includes `genus_surface(1, 1)`, which the paper's literal pseudocode (without resetting c when
/// lue is initialised, decision 3 of the RS module) leaves with 18 vertices, not irreducible.
#[test]
fn surfaces_of_genus_1_to_200() {
    for g in 1..=200u32 {
        let mesh = genus_surface(g, 1).mesh;
        run_and_verify(&mesh, Algorithm::RamaswamiSiqueira, g <= 40);
        if g <= 12 || g % 25 == 0 {
            run_and_verify(&mesh, Algorithm::Schipper, false);
            run_and_verify(&mesh, Algorithm::BruteForce { seed: u64::from(g) }, false);
        }
    }
    // A finer resolution, heavily flipped. The last three make RS meet, while processing u, a
    // new processed neighbour z closing a critical cycle (u, z, w) on an edge [u, w] of lte whose
    // counter was 0 (Algorithm 4.5, lines 33–41): without that increment RS would contract a
    // non-contractible edge.
    for (g, flips, seed) in [(2, 4000, 2), (7, 4000, 7), (30, 4000, 30), (60, 30000, 1)]
        .into_iter()
        .chain([(150, 30000, 0), (150, 30000, 1)])
    {
        let mesh = random_flips(&genus_surface(g, 2), flips, seed).mesh;
        for a in all_algorithms(seed) {
            run_and_verify(&mesh, a, true);
        }
    }
}

#[test]
fn cavity_and_hole_bricks() {
    // The papers' families at small scale: cavities only (group B, genus 0), cavities and holes
    // (groups C and D, genus = holes), at two resolutions.
    let boxes = [
        CavityBox::new(9, 0, 1, 1, 1, 1),
        CavityBox::new(16, 0, 2, 1, 2, 1),
        CavityBox::new(5, 4, 1, 1, 1, 1),
        CavityBox::new(0, 9, 2, 2, 1, 1),
        CavityBox::new(12, 13, 1, 1, 2, 1),
        CavityBox::new(30, 34, 1, 1, 1, 1),
    ];
    for (i, b) in boxes.iter().enumerate() {
        let mesh = b.generate().mesh;
        assert_eq!(mesh.genus(), i64::from(b.holes()));
        for a in all_algorithms(i as u64) {
            run_and_verify(&mesh, a, true);
        }
    }
    // The coarsest brick of group B itself (3,844 cavities, 95,252 triangles), RS only here (the
    // three algorithms run on it in the benchmark).
    let b = cavity_box(3844, 0, 0).mesh;
    assert_eq!(b.face_count(), 95_252);
    run_and_verify(&b, Algorithm::RamaswamiSiqueira, true);
}

#[test]
fn random_vertex_splits_of_small_irreducible_triangulations() {
    let mut bases = vec![tetrahedron()];
    for g in 1..=6 {
        bases.push(irreducible_surface(&genus_surface(g, 1)));
    }
    bases.push(irreducible_surface(&random_flips(&torus(9, 7), 200, 5)));
    for (i, base) in bases.iter().enumerate() {
        // An irreducible input is left alone by all three.
        for a in all_algorithms(i as u64) {
            let red = run_and_verify(&base.mesh, a, false);
            assert!(
                red.history.is_empty(),
                "{a}: contracted an irreducible input"
            );
        }
        for seed in 0..4u64 {
            let mesh = random_vertex_splits(base, 10 + 150 * seed as usize, seed).mesh;
            for a in all_algorithms(seed) {
                run_and_verify(&mesh, a, true);
            }
        }
    }
}

#[test]
fn inputs_with_tombstones_are_accepted() {
    // A mesh that already went through contractions (removed ids are tombstones).
    let mut mesh = random_flips(&torus(10, 8), 100, 4).mesh;
    let mut scratch = surftopo_mesh::LinkScratch::default();
    let mut done = 0;
    for e in mesh.edges().collect::<Vec<_>>() {
        if done < 20 && mesh.contract(e.halfedge(), &mut scratch).is_ok() {
            done += 1;
        }
    }
    assert_eq!(done, 20);
    for a in all_algorithms(9) {
        run_and_verify(&mesh, a, true);
    }
}

#[test]
fn same_seed_same_result() {
    let mesh = random_flips(&genus_surface(3, 2), 3000, 1).mesh;
    let (a, b) = (
        brute_force(mesh.clone(), 42).expect("simplicial"),
        brute_force(mesh.clone(), 42).expect("simplicial"),
    );
    assert_eq!(a.mesh, b.mesh);
    assert_eq!(a.history, b.history);
    assert_eq!(a.counters.link_tests, b.counters.link_tests);
    let c = brute_force(mesh.clone(), 43).expect("simplicial");
    assert_ne!(
        a.history, c.history,
        "the seed changes the contraction order"
    );
    for f in [ramaswami_siqueira, schipper] {
        let (x, y) = (f(mesh.clone()).expect("ok"), f(mesh.clone()).expect("ok"));
        assert_eq!((x.mesh, x.history), (y.mesh, y.history));
    }
}

#[test]
fn schipper_traced_lists_every_test_of_schipper() {
    for b in [
        CavityBox::new(5, 4, 1, 1, 1, 1),
        CavityBox::new(2, 7, 2, 2, 2, 1),
    ] {
        let mesh = b.generate().mesh;
        let plain = schipper(mesh.clone()).expect("simplicial");
        let (traced, tests) = schipper_traced(mesh.clone()).expect("simplicial");
        assert_eq!(
            (&plain.mesh, &plain.history),
            (&traced.mesh, &traced.history)
        );
        assert_eq!(tests.len() as u64, plain.counters.link_tests);
        // ε recounted from the trace: edge ids tested more than once.
        let mut count = vec![0u32; mesh.edge_slots()];
        for t in &tests {
            count[t.edge.idx()] += 1;
        }
        let eps = count.iter().filter(|&&c| c > 1).count() as u64;
        assert_eq!(eps, plain.counters.edges_tested_more_than_once);
        // Each test names the edge's ends at that moment, the chosen vertex first; a contraction
        // follows only a passed test, so the contraction counts never fall and end at the history.
        let mut replay = mesh.clone();
        let mut done = 0;
        for t in &tests {
            assert!(t.contractions_before >= done);
            while done < t.contractions_before {
                let k = &traced.history[done];
                let h = k.halfedge_uv();
                replay.contract_unchecked(h);
                done += 1;
            }
            let h = t.edge.halfedge();
            let ends = [replay.origin(h), replay.dest(h)];
            assert!(ends == t.ends || ends == [t.ends[1], t.ends[0]]);
        }
        assert_eq!(
            tests.last().map(|t| t.contractions_before),
            Some(traced.history.len())
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// Random irregular inputs of genus 0 to 4: every algorithm's result passes every check.
    #[test]
    fn random_inputs_reduce_correctly(
        genus in 0u32..5,
        flips in 0usize..3000,
        splits in 0usize..300,
        seed in any::<u64>(),
    ) {
        let base = if genus == 0 { icosphere(2) } else { genus_surface(genus, 1) };
        let surface = random_flips(&random_vertex_splits(&base, splits, seed), flips, seed);
        for a in all_algorithms(seed) {
            let red = surftopo_irreducible::reduce(surface.mesh.clone(), a).expect("simplicial");
            verify(&surface.mesh, &red, a, true);
        }
    }
}
