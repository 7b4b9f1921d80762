//! Canonical forms, isomorphism and chirality, checked against the independent vertex
//! backtracking; the face-list checks and Lutz's format.

mod verify;

use rand::seq::SliceRandom;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use surftopo_census::{
    CensusError, CensusOptions, SurfaceKind, Triangulation, canonical_form, census, is_chiral,
    isomorphic, parse_lutz, random_retriangulation, to_lutz,
};

/// `t` with its vertices permuted, its faces shuffled and each face's corners rotated or
/// reversed at random.
fn scrambled(t: &Triangulation, seed: u64) -> Triangulation {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut perm: Vec<u32> = (0..t.vertex_count() as u32).collect();
    perm.shuffle(&mut rng);
    let mut faces: Vec<[u32; 3]> = t
        .faces()
        .iter()
        .map(|f| {
            let mut g = f.map(|v| perm[v as usize]);
            g.rotate_left(rng.random_range(0..3));
            if rng.random_bool(0.5) {
                g.swap(1, 2);
            }
            g
        })
        .collect();
    faces.shuffle(&mut rng);
    Triangulation::new(faces).unwrap()
}

fn census_of(name: &str) -> Vec<Triangulation> {
    census(SurfaceKind::parse(name).unwrap(), CensusOptions::default())
        .unwrap()
        .triangulations
        .iter()
        .map(|c| c.to_triangulation())
        .collect()
}

#[test]
fn canonical_form_ignores_labels_face_order_and_mirror_images() {
    for name in ["sphere", "projective-plane", "torus"] {
        for (i, t) in census_of(name).iter().enumerate() {
            let form = canonical_form(t);
            for seed in 0..6 {
                let s = scrambled(t, seed * 31 + i as u64);
                assert_eq!(canonical_form(&s), form, "{name} {i} seed {seed}");
                assert!(isomorphic(t, &s));
                assert!(verify::isomorphic_by_backtracking(t.faces(), s.faces()));
            }
            // The mirror image: every face reversed.
            let mirror =
                Triangulation::new(t.faces().iter().map(|f| [f[0], f[2], f[1]]).collect()).unwrap();
            assert_eq!(canonical_form(&mirror), form);
            assert_eq!(is_chiral(&mirror), is_chiral(t));
        }
    }
}

#[test]
fn isomorphic_agrees_with_backtracking_on_random_triangulations() {
    // Random triangulations of the torus and the Klein bottle with equal vertex counts: pairs
    // that are often isomorphic (few splits) and often not.
    let mut agree = [0usize; 2];
    for name in ["torus", "klein-bottle"] {
        let base = &census_of(name)[0];
        let list: Vec<Triangulation> = (0..24)
            .map(|seed| random_retriangulation(base, 2, 3, seed))
            .collect();
        for a in &list {
            for b in &list {
                if a.vertex_count() != b.vertex_count() {
                    continue;
                }
                let expected = verify::isomorphic_by_backtracking(a.faces(), b.faces());
                assert_eq!(isomorphic(a, b), expected);
                agree[expected as usize] += 1;
            }
        }
    }
    assert!(
        agree[0] > 10 && agree[1] > 10,
        "both answers exercised: {agree:?}"
    );
}

#[test]
fn chirality() {
    // K7 on the torus (the 7-vertex torus) is chiral; the tetrahedron is not; non-orientable
    // surfaces have no chirality.
    let torus = census_of("torus");
    assert_eq!(torus[0].vertex_count(), 7);
    assert_eq!(is_chiral(&torus[0]), Some(true));
    assert_eq!(is_chiral(&census_of("sphere")[0]), Some(false));
    for t in census_of("projective-plane") {
        assert_eq!(is_chiral(&t), None);
    }
    // An achiral torus triangulation has an orientation-reversing automorphism: found by the
    // backtracking among the vertex maps that reverse a coherent orientation.
    for t in &torus {
        let chiral = is_chiral(t).unwrap();
        assert_eq!(chiral, !has_reversing_automorphism(t), "{:?}", t.faces());
    }
}

/// Whether some vertex permutation maps the oriented faces of `t` onto the reversed ones (an
/// orientation-reversing automorphism), by trying every image of a flag and propagating.
fn has_reversing_automorphism(t: &Triangulation) -> bool {
    let oriented = orient(t.faces());
    let reversed: std::collections::HashSet<[u32; 3]> = oriented
        .iter()
        .map(|f| rotate_min([f[0], f[2], f[1]]))
        .collect();
    let nb = verify::neighbours(t.faces());
    let f0 = oriented[0];
    for g in &oriented {
        for r in 0..3 {
            let image = [g[r], g[(r + 1) % 3], g[(r + 2) % 3]];
            // map f0 -> reversed image (a, c, b) order, then propagate across edges.
            let target = [image[0], image[2], image[1]];
            let mut map = vec![u32::MAX; t.vertex_count()];
            for i in 0..3 {
                map[f0[i] as usize] = target[i];
            }
            let mut changed = true;
            let mut ok = true;
            while changed && ok {
                changed = false;
                for f in &oriented {
                    let known: Vec<usize> =
                        (0..3).filter(|&i| map[f[i] as usize] != u32::MAX).collect();
                    if known.len() == 2 {
                        let (i, j) = (known[0], known[1]);
                        let k = 3 - i - j;
                        // The image face through the images of f[i], f[j], in the reversed set.
                        let (a, b) = (map[f[i] as usize], map[f[j] as usize]);
                        let candidates: Vec<u32> = nb[a as usize]
                            .intersection(&nb[b as usize])
                            .copied()
                            .filter(|&c| {
                                let mut w = [0u32; 3];
                                w[i] = a;
                                w[j] = b;
                                w[k] = c;
                                reversed.contains(&rotate_min(w))
                            })
                            .collect();
                        if candidates.len() != 1 || map.contains(&candidates[0]) {
                            ok = false;
                            break;
                        }
                        map[f[k] as usize] = candidates[0];
                        changed = true;
                    }
                }
            }
            if ok
                && !map.contains(&u32::MAX)
                && oriented
                    .iter()
                    .all(|f| reversed.contains(&rotate_min(f.map(|v| map[v as usize]))))
            {
                return true;
            }
        }
    }
    false
}

fn rotate_min(f: [u32; 3]) -> [u32; 3] {
    let i = (0..3).min_by_key(|&i| f[i]).unwrap();
    [f[i], f[(i + 1) % 3], f[(i + 2) % 3]]
}

/// A coherent orientation of an orientable face list (propagation).
fn orient(faces: &[[u32; 3]]) -> Vec<[u32; 3]> {
    let mut out: Vec<Option<[u32; 3]>> = vec![None; faces.len()];
    out[0] = Some(faces[0]);
    let mut stack = vec![0];
    while let Some(f) = stack.pop() {
        let o = out[f].unwrap();
        for i in 0..3 {
            let (a, b) = (o[i], o[(i + 1) % 3]);
            for (g, t) in faces.iter().enumerate() {
                if g != f && out[g].is_none() && t.contains(&a) && t.contains(&b) {
                    let c = *t.iter().find(|&&x| x != a && x != b).unwrap();
                    out[g] = Some([b, a, c]);
                    stack.push(g);
                }
            }
        }
    }
    out.into_iter().map(Option::unwrap).collect()
}

#[test]
fn invalid_face_lists_name_the_element() {
    let tetra = vec![[0, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0]];
    assert!(Triangulation::new(tetra.clone()).is_ok());
    assert_eq!(Triangulation::new(vec![]).unwrap_err(), CensusError::Empty);
    let mut degenerate = tetra.clone();
    degenerate[2] = [1, 1, 2];
    assert_eq!(
        Triangulation::new(degenerate).unwrap_err(),
        CensusError::DegenerateFace { face: 2, vertex: 1 }
    );
    let gap: Vec<[u32; 3]> = tetra
        .iter()
        .map(|f| f.map(|v| if v == 3 { 4 } else { v }))
        .collect();
    assert_eq!(
        Triangulation::new(gap).unwrap_err(),
        CensusError::UnusedVertex { vertex: 3 }
    );
    let mut duplicate = tetra.clone();
    duplicate.push([2, 1, 0]);
    assert_eq!(
        Triangulation::new(duplicate).unwrap_err(),
        CensusError::DuplicateFace { faces: [0, 4] }
    );
    let open = tetra[..3].to_vec();
    assert!(matches!(
        Triangulation::new(open).unwrap_err(),
        CensusError::EdgeFaceCount { faces: 1, .. }
    ));
    // Two tetrahedra sharing vertex 0: its link is two cycles.
    let mut pinched = tetra.clone();
    pinched.extend([[0, 4, 5], [0, 6, 4], [4, 6, 5], [5, 6, 0]]);
    assert_eq!(
        Triangulation::new(pinched).unwrap_err(),
        CensusError::PinchedVertex {
            vertex: 0,
            cycles: 2
        }
    );
    let mut apart = tetra.clone();
    apart.extend(tetra.iter().map(|f| f.map(|v| v + 4)));
    assert_eq!(
        Triangulation::new(apart).unwrap_err(),
        CensusError::Disconnected { vertex: 4 }
    );
    for bad in ["sfere", "genus-x", "n0", "genus--1", ""] {
        assert!(matches!(
            SurfaceKind::parse(bad).unwrap_err(),
            CensusError::UnknownSurface { .. }
        ));
    }
}

#[test]
fn lutz_format_round_trip_and_errors() {
    let c = census(SurfaceKind::orientable(1), CensusOptions::default()).unwrap();
    let text = to_lutz(&c.triangulations);
    assert_eq!(text.lines().count(), 21);
    assert!(text.starts_with("[[1,2,3],[1,2,4],"));
    let back = parse_lutz(&text).unwrap();
    for (t, form) in back.iter().zip(&c.triangulations) {
        assert_eq!(t.faces(), form.faces());
        assert_eq!(&canonical_form(t), form);
    }
    let err = parse_lutz("[[1,2,3],[1,2,4]]\n[[1,2,3],[1,2;4]]").unwrap_err();
    assert!(
        matches!(err, CensusError::InvalidLine { line: 1, .. }),
        "{err}"
    );
    let err = parse_lutz("[[1,2,3],[1,2,4],[1,3,4],[2,3,4]]\n[[1,2,3],[1 2]]").unwrap_err();
    assert_eq!(
        err,
        CensusError::Parse {
            line: 2,
            column: 13,
            message: "expected `,`".into()
        }
    );
    let err = parse_lutz("[[0,2,3]]").unwrap_err();
    assert!(
        matches!(
            err,
            CensusError::Parse {
                line: 1,
                column: 3,
                ..
            }
        ),
        "{err}"
    );
}

#[test]
fn a_huge_vertex_index_is_an_error_not_an_allocation() {
    let err = Triangulation::new(vec![[0, 1, 2], [0, 2, u32::MAX - 1], [0, 1, 3]]).unwrap_err();
    assert_eq!(err, CensusError::UnusedVertex { vertex: 4 });
}
