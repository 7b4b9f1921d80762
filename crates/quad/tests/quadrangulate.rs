//! All algorithms on generated families (genus 0 to high genus, regular and irregular
//! connectivity) and on every shared mesh, each result checked by the independent checks of
//! `support`.

mod support;

use support::{check_result, check_same_surface, naive_contractions};
use surftopo_mesh::Surface;
use surftopo_mesh::SurfaceMesh;
use surftopo_mesh::generators::{
    CavityBox, genus_surface, icosphere, random_flips, random_vertex_splits, shuffle_faces,
    subdivide_midpoint, tetrahedron, torus,
};
use surftopo_quad::{
    AugmentStrategy, KarpSipserOptions, QuadAlgorithm, QuadError, QuadOptions, expand,
    quadrangulate, quadrangulate_with,
};

const ALGORITHMS: [QuadAlgorithm; 6] = [
    QuadAlgorithm::SimpleGreedy { seed: 1 },
    QuadAlgorithm::SimpleGreedy { seed: 2 },
    QuadAlgorithm::PulliSegal { seed: 1 },
    QuadAlgorithm::Lrs,
    QuadAlgorithm::DiksStanczyk,
    QuadAlgorithm::KarpSipser,
];

/// A genus-7 surface with irregular connectivity, subdivided twice: a mesh written as a 1-to-4
/// subdivision whose coarsest level is not regular.
fn subdivided_genus7() -> Surface {
    subdivide_midpoint(&random_flips(&genus_surface(7, 1), 500, 3), 2)
}

fn families() -> Vec<(String, Surface)> {
    let mut out: Vec<(String, Surface)> = vec![
        ("tetrahedron".into(), tetrahedron()),
        ("icosphere0".into(), icosphere(0)),
        ("icosphere3".into(), icosphere(3)),
        ("torus3x3".into(), torus(3, 3)),
        ("torus20x7".into(), torus(20, 7)),
        (
            "cavities".into(),
            CavityBox::new(6, 3, 1, 1, 1, 1).generate(),
        ),
    ];
    for g in [1, 2, 3, 7, 20, 45, 200] {
        out.push((format!("genus{g}"), genus_surface(g, 1)));
    }
    let base: Vec<(String, Surface)> = out.clone();
    for (name, s) in &base {
        let e = s.mesh.edge_count();
        out.push((format!("{name}+flips"), random_flips(s, e, 7)));
        out.push((
            format!("{name}+splits"),
            random_vertex_splits(s, s.mesh.vertex_count(), 9),
        ));
    }
    // Face order shuffled: ids not local, so KS starts in breadth-first order.
    out.push((
        "icosphere5+shuffled".into(),
        shuffle_faces(&icosphere(5), 4),
    ));
    out.push((
        "genus200+shuffled".into(),
        shuffle_faces(&genus_surface(200, 1), 4),
    ));
    // Written as a subdivision (children of face f at 4f..4f + 4): KS lifts the coarse pairing.
    out.push(("genus7+flips+subdivided2".into(), subdivided_genus7()));
    // High genus relative to size, very irregular.
    out.push((
        "genus45+flips+flips".into(),
        random_flips(&random_flips(&genus_surface(45, 1), 5000, 1), 5000, 2),
    ));
    out
}

#[test]
fn every_algorithm_on_generated_families() {
    for (name, surface) in families() {
        let mesh = &surface.mesh;
        for algorithm in ALGORITHMS {
            let result = quadrangulate(mesh, algorithm)
                .unwrap_or_else(|e| panic!("{name} {algorithm}: {e}"));
            check_result(&format!("{name} {algorithm}"), mesh, algorithm, &result);
        }
        // KS's greedy too on the families written quad by quad (tori, genus surfaces, bricks)
        // or as subdivisions (icospheres).
        let greedy_only = QuadOptions {
            karp_sipser: KarpSipserOptions {
                file_order: false,
                subdivision: false,
                ..KarpSipserOptions::default()
            },
            ..QuadOptions::default()
        };
        let ks = QuadAlgorithm::KarpSipser;
        let result = quadrangulate_with(mesh, ks, &greedy_only)
            .unwrap_or_else(|e| panic!("{name} ks, greedy only: {e}"));
        check_result(&format!("{name} ks, greedy only"), mesh, ks, &result);
        let stats = result.karp_sipser.unwrap();
        assert!(!stats.file_order && stats.subdivision_levels == 0, "{name}");
    }
}

/// A torus written quad by quad (triangles 2k and 2k + 1 share the quad's diagonal) comes back as
/// its own quads from KS, with no greedy; without the file-order step the greedy runs.
#[test]
fn ks_gives_back_the_quads_a_file_was_written_in() {
    let surface = torus(20, 7);
    let mesh = &surface.mesh;
    let (_, triangles) = surface.to_triangles();
    let written: std::collections::HashSet<Vec<u32>> = triangles
        .chunks(2)
        .map(|pair| {
            let mut quad: Vec<u32> = pair.concat();
            quad.sort_unstable();
            quad.dedup();
            quad
        })
        .collect();
    let quads_of = |result: &surftopo_quad::QuadResult| -> std::collections::HashSet<Vec<u32>> {
        result
            .quads
            .iter()
            .map(|q| {
                let mut quad: Vec<u32> = q.iter().map(|v| v.0).collect();
                quad.sort_unstable();
                quad
            })
            .collect()
    };
    let ks = QuadAlgorithm::KarpSipser;
    let result = quadrangulate(mesh, ks).unwrap();
    check_result("torus20x7 ks", mesh, ks, &result);
    assert!(result.karp_sipser.unwrap().file_order);
    assert_eq!(result.stats.unpaired, 0);
    assert_eq!(quads_of(&result), written);
    let greedy_only = QuadOptions {
        karp_sipser: KarpSipserOptions {
            file_order: false,
            ..KarpSipserOptions::default()
        },
        ..QuadOptions::default()
    };
    let result = quadrangulate_with(mesh, ks, &greedy_only).unwrap();
    check_result("torus20x7 ks without file order", mesh, ks, &result);
    assert!(!result.karp_sipser.unwrap().file_order);
}

/// A mesh written as a 1-to-4 subdivision is paired by lifting the coarser mesh's pairing, level
/// after level; each quad is then two triangles of the same coarse quad (children of two paired
/// coarse triangles, or of one).
#[test]
fn ks_lifts_the_pairing_of_a_mesh_written_as_a_subdivision() {
    let ks = QuadAlgorithm::KarpSipser;
    for (name, surface, levels) in [
        ("icosphere4", icosphere(4), 4),
        ("genus7+flips+subdivided2", subdivided_genus7(), 2),
    ] {
        let mesh = &surface.mesh;
        let result = quadrangulate(mesh, ks).unwrap();
        check_result(name, mesh, ks, &result);
        assert_eq!(result.stats.subdivision_levels, levels, "{name}");
        // Each block of four children is joined by quads to exactly one other block, and
        // that relation pairs the blocks: the quads lie inside the coarse quads.
        let mut partner = vec![u32::MAX; mesh.face_count() / 4];
        for &e in &result.diagonals {
            let h = e.halfedge();
            let [b, c] = [mesh.face(h).0 / 4, mesh.face(h.twin()).0 / 4];
            for (x, y) in [(b, c), (c, b)] {
                if x != y {
                    assert!(partner[x as usize] == u32::MAX || partner[x as usize] == y);
                    partner[x as usize] = y;
                }
            }
        }
        for (b, &c) in partner.iter().enumerate() {
            assert_eq!(partner[c as usize], b as u32, "{name}: block {b}");
        }
    }
}

#[test]
fn both_augmenting_strategies_give_perfect_pairings() {
    let surface = random_flips(&genus_surface(5, 2), 3000, 4);
    let strategies = [
        AugmentStrategy::Forest,
        AugmentStrategy::Global,
        AugmentStrategy::Local { initial_budget: 2 },
        AugmentStrategy::Local {
            initial_budget: 1 << 30,
        },
    ];
    for augment in strategies {
        for algorithm in [
            QuadAlgorithm::SimpleGreedy { seed: 3 },
            QuadAlgorithm::PulliSegal { seed: 3 },
            QuadAlgorithm::Lrs,
        ] {
            let result = quadrangulate_with(
                &surface.mesh,
                algorithm,
                &QuadOptions {
                    augment,
                    ..QuadOptions::default()
                },
            )
            .unwrap();
            check_result(
                &format!("{algorithm} {augment:?}"),
                &surface.mesh,
                algorithm,
                &result,
            );
        }
    }
}

#[test]
fn same_seed_same_quads() {
    let mesh = &random_flips(&torus(12, 9), 200, 5).mesh;
    for algorithm in [
        QuadAlgorithm::SimpleGreedy { seed: 9 },
        QuadAlgorithm::PulliSegal { seed: 9 },
        QuadAlgorithm::Lrs,
        QuadAlgorithm::DiksStanczyk,
        QuadAlgorithm::KarpSipser,
    ] {
        let a = quadrangulate(mesh, algorithm).unwrap();
        let b = quadrangulate(mesh, algorithm).unwrap();
        assert_eq!(a.quads, b.quads, "{algorithm}");
    }
    let a = quadrangulate(mesh, QuadAlgorithm::PulliSegal { seed: 1 }).unwrap();
    let b = quadrangulate(mesh, QuadAlgorithm::PulliSegal { seed: 2 }).unwrap();
    assert_ne!(a.quads, b.quads);
}

/// The expansion on a contraction history made by the tests' own contraction step: K is a
/// triangulation of the same surface, M matches every triangle except those of T′.
#[test]
fn expansion_of_an_independent_contraction_sequence() {
    let mut seen = surftopo_quad::ExpansionCases::default();
    for (name, surface) in families() {
        let input = &surface.mesh;
        let (reduced, history) = naive_contractions(input);
        let irreducible_faces = reduced.face_count();
        let expansion = expand(reduced, &history).unwrap_or_else(|e| panic!("{name}: {e}"));
        check_same_surface(input, &expansion.mesh);
        let unmatched = expansion.pairing.unmatched_count(&expansion.mesh);
        assert_eq!(
            unmatched, irreducible_faces,
            "{name}: only T' triangles unmatched"
        );
        assert!(
            unmatched as i64 <= (56 * input.genus() - 12).max(4),
            "{name}"
        );
        // M pairs triangles of K along unflipped edges.
        for e in 0..input.edge_slots() {
            if let Some(m) = expansion.pairing.mate_edge(
                expansion
                    .mesh
                    .face(surftopo_mesh::EdgeId::new(e).halfedge())
                    .0,
            ) && m as usize == e
            {
                assert!(
                    !expansion.flipped[e],
                    "{name}: matched edge e{e} is flipped"
                );
                let mut a = input.edge_vertices(surftopo_mesh::EdgeId::new(e));
                let mut b = expansion.mesh.edge_vertices(surftopo_mesh::EdgeId::new(e));
                a.sort();
                b.sort();
                assert_eq!(a, b, "{name}: matched edge e{e} differs from the input's");
            }
        }
        let cases = expansion.cases;
        let total = cases.neither_split_edge_matched
            + cases.degree3
            + cases.degree4
            + cases.degree4_with_flipped_edge
            + cases.degree_above4;
        assert_eq!(
            total as usize,
            history.len(),
            "{name}: one branch per record"
        );
        seen.neither_split_edge_matched += cases.neither_split_edge_matched;
        seen.degree3 += cases.degree3;
        seen.degree3_unflips += cases.degree3_unflips;
        seen.degree4 += cases.degree4;
        seen.degree4_with_flipped_edge += cases.degree4_with_flipped_edge;
        seen.degree_above4 += cases.degree_above4;
    }
    // Every branch of Algorithms 3.1-3.4 was exercised.
    eprintln!("{seen:?}");
    assert!(seen.neither_split_edge_matched > 0 && seen.degree3 > 0 && seen.degree4 > 0);
    assert!(seen.degree3_unflips > 0, "{seen:?}");
    assert!(
        seen.degree4_with_flipped_edge > 0 && seen.degree_above4 > 0,
        "{seen:?}"
    );
}

#[test]
fn a_history_that_does_not_replay_is_an_internal_error() {
    let surface = icosphere(1);
    let (reduced, history) = naive_contractions(&surface.mesh);
    // Dropping the last record leaves a vertex removed that the earlier records do not restore.
    let err = expand(reduced, &history[..history.len() - 1]).unwrap_err();
    assert!(matches!(err, QuadError::Internal(_)), "{err}");
}

#[test]
fn non_simplicial_input() {
    // A flipped tetrahedron edge doubles an edge: a closed mesh with a multi-edge.
    let mut mesh = surftopo_mesh::SurfaceMesh::tetrahedron();
    mesh.flip(surftopo_mesh::EdgeId(0)).unwrap();
    mesh.check_invariants().unwrap();
    assert!(!mesh.is_simplicial());
    for algorithm in [
        QuadAlgorithm::SimpleGreedy { seed: 0 },
        QuadAlgorithm::PulliSegal { seed: 0 },
        QuadAlgorithm::KarpSipser,
    ] {
        let result = quadrangulate(&mesh, algorithm).unwrap();
        assert_eq!(result.quads.len(), 2);
    }
    assert!(matches!(
        quadrangulate(&mesh, QuadAlgorithm::Lrs),
        Err(QuadError::NotSimplicial(_))
    ));
}

#[test]
fn tombstoned_input_is_paired_on_live_faces() {
    let mut mesh: SurfaceMesh = icosphere(2).mesh;
    let mut scratch = surftopo_mesh::LinkScratch::default();
    let h = mesh.vertex_halfedge(surftopo_mesh::VertexId(5));
    mesh.contract(h, &mut scratch).unwrap();
    for algorithm in ALGORITHMS {
        let result = quadrangulate(&mesh, algorithm).unwrap();
        assert_eq!(2 * result.quads.len(), mesh.face_count());
        let polygons: Vec<Vec<u32>> = result
            .quads
            .iter()
            .map(|q| q.iter().map(|v| v.0).collect())
            .collect();
        assert_eq!(
            surftopo_testkit::check_closed_oriented_manifold(&polygons),
            Ok(2),
            "{algorithm}"
        );
    }
}

/// Every shared mesh with SG, PS, LRS and KS; DS (slower, tested in its own crate) on the small ones.
fn shared_meshes(keep: impl Fn(usize) -> bool) {
    for shared in surftopo_testkit::shared_meshes() {
        if !keep(shared.faces) {
            continue;
        }
        let surface = surftopo_testkit::load(&shared);
        let mesh = &surface.mesh;
        let mut algorithms = vec![
            QuadAlgorithm::SimpleGreedy { seed: 1 },
            QuadAlgorithm::PulliSegal { seed: 1 },
            QuadAlgorithm::Lrs,
            QuadAlgorithm::KarpSipser,
        ];
        if shared.faces <= 20_000 {
            algorithms.push(QuadAlgorithm::DiksStanczyk);
        }
        for algorithm in algorithms {
            let result = quadrangulate(mesh, algorithm)
                .unwrap_or_else(|e| panic!("{} {algorithm}: {e}", shared.file));
            check_result(
                &format!("{} {algorithm}", shared.file),
                mesh,
                algorithm,
                &result,
            );
        }
    }
}

surftopo_testkit::shared_mesh_tests!(
    every_shared_mesh_up_to_60k_faces,
    every_shared_mesh_above_60k_faces
);

fn every_shared_mesh_up_to_60k_faces() {
    shared_meshes(|faces| faces <= 60_000);
}

fn every_shared_mesh_above_60k_faces() {
    shared_meshes(|faces| faces > 60_000);
}

#[test]
fn stats_serialise_with_the_table_columns() {
    let result = quadrangulate(&torus(6, 5).mesh, QuadAlgorithm::Lrs).unwrap();
    let json = serde_json::to_value(&result.stats).unwrap();
    let keys: Vec<&str> = json
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    let mut expected = vec![
        "algorithm",
        "faces",
        "initial_pairing_seconds",
        "paired_percent",
        "unpaired",
        "augmentation_seconds",
        "total_seconds",
        "flipped_edges",
        "file_order",
        "subdivision_levels",
        "unpaired_triangles",
        "deficiency_lower_bound",
        "added_vertices",
    ];
    let mut got = keys.clone();
    got.sort_unstable();
    expected.sort_unstable();
    assert_eq!(got, expected);
    assert_eq!(json["algorithm"], "lrs");
    assert_eq!(json["faces"], 60);
    assert_eq!(json["file_order"], false);
    assert_eq!(json["subdivision_levels"], 0);
    // `components` is listed only for several pieces.
    assert!(json.get("components").is_none());
}
