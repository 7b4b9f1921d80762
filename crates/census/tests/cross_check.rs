//! The census cross-checks itself: random triangulations of each surface (random vertex splits
//! and flips of its census members), each reduced to an irreducible triangulation by the
//! library's Ramaswami–Siqueira and brute force (`surftopo_irreducible::reduce_surface`, on every
//! surface, non-orientable ones through their double cover) and by this crate's random reducer,
//! land only on classes the census lists.

mod verify;

use std::collections::{HashMap, HashSet};
use surftopo_census::{
    CanonicalForm, CensusOptions, SurfaceKind, Triangulation, canonical_form, census,
    random_reduction, random_retriangulation,
};
use surftopo_irreducible::{Algorithm, reduce_surface};
use surftopo_mesh::ClosedCover;

/// `t` reduced by the library's `algorithm`, as a triangulation (vertices renumbered densely).
fn library_reduction(t: &Triangulation, algorithm: Algorithm) -> Triangulation {
    let cover = ClosedCover::from_triangles(t.vertex_count(), t.faces())
        .unwrap()
        .0;
    let reduced = reduce_surface(cover, algorithm).unwrap().cover;
    let mut index: HashMap<u32, u32> = HashMap::new();
    let faces: Vec<[u32; 3]> = reduced
        .surface_triangles()
        .into_iter()
        .map(|face| {
            face.map(|v| {
                let next = index.len() as u32;
                *index.entry(v).or_insert(next)
            })
        })
        .collect();
    Triangulation::new(faces).unwrap()
}

fn run(name: &str, samples: u64, library: bool) {
    let surface = SurfaceKind::parse(name).unwrap();
    let c = census(surface, CensusOptions::default()).unwrap();
    let classes: HashSet<CanonicalForm> = c.triangulations.iter().cloned().collect();
    let mut hit: HashSet<CanonicalForm> = HashSet::new();
    for (i, member) in c.triangulations.iter().enumerate() {
        let member = member.to_triangulation();
        for s in 0..samples {
            let seed = 1000 * i as u64 + s;
            let t = random_retriangulation(&member, 6 + (s as usize % 10), 30, seed);
            let chi = verify::closed_surface(t.faces()).unwrap();
            assert_eq!(chi.euler_characteristic, surface.euler_characteristic());
            assert_eq!(chi.orientable, surface.orientable);
            let mut reduced = vec![random_reduction(&t, seed)];
            if library {
                for algorithm in [Algorithm::RamaswamiSiqueira, Algorithm::BruteForce { seed }] {
                    reduced.push(library_reduction(&t, algorithm));
                }
            }
            for r in reduced {
                assert!(verify::is_irreducible(r.faces()));
                let form = canonical_form(&r);
                assert!(
                    classes.contains(&form),
                    "{name}: a reduction outside the census: {:?}",
                    r.faces()
                );
                hit.insert(form);
            }
        }
    }
    eprintln!("{name}: {} of {} classes reached", hit.len(), classes.len());
}

#[test]
fn sphere_reductions_land_in_the_census() {
    run("sphere", 40, true);
}

#[test]
fn torus_reductions_land_in_the_census() {
    run("torus", 6, true);
}

#[test]
fn projective_plane_reductions_land_in_the_census() {
    run("projective-plane", 30, true);
}

#[test]
fn klein_bottle_reductions_land_in_the_census() {
    run("klein-bottle", 4, true);
}

/// For surfaces whose census is run only up to `max` vertices (N3, the double torus): every
/// reduction with at most `max` vertices is in the census up to `max`; larger ones are counted.
fn run_cut(name: &str, max: usize, samples: u64, library: bool) {
    let surface = SurfaceKind::parse(name).unwrap();
    let c = census(
        surface,
        CensusOptions {
            max_vertices: Some(max),
            ..Default::default()
        },
    )
    .unwrap();
    let classes: HashSet<CanonicalForm> = c.triangulations.iter().cloned().collect();
    let (mut checked, mut larger) = (0, 0);
    for (i, member) in c.triangulations.iter().enumerate().step_by(37) {
        let member = member.to_triangulation();
        for s in 0..samples {
            let seed = 7919 * i as u64 + s;
            let t = random_retriangulation(&member, 8, 30, seed);
            let mut reduced = vec![random_reduction(&t, seed)];
            if library {
                reduced.push(library_reduction(&t, Algorithm::RamaswamiSiqueira));
            }
            for r in reduced {
                assert!(verify::is_irreducible(r.faces()));
                if r.vertex_count() <= max {
                    assert!(
                        classes.contains(&canonical_form(&r)),
                        "{name}: {:?}",
                        r.faces()
                    );
                    checked += 1;
                } else {
                    larger += 1;
                }
            }
        }
    }
    eprintln!("{name}: {checked} reductions checked, {larger} with more than {max} vertices");
    assert!(checked > 20);
}

#[test]
fn n3_reductions_up_to_10_vertices_land_in_the_census() {
    run_cut("n3", 10, 3, true);
}

#[test]
fn double_torus_reductions_up_to_10_vertices_land_in_the_census() {
    run_cut("genus-2", 10, 4, true);
}

/// The same up to 11 vertices (release: `cargo test --release -p surftopo-census --test
/// cross_check -- --ignored`).
#[test]
#[ignore = "release sweep: N3 and the double torus up to 11 vertices"]
fn reductions_up_to_11_vertices_land_in_the_census() {
    run_cut("n3", 11, 3, false);
    run_cut("genus-2", 11, 2, true);
}
