//! Wrong or inconsistent answers on hostile inputs (issue 38, item 5): "not isometric" only with
//! a proof, whatever the scale; success of the exact wave means a triangulation that is exactly
//! Delaunay, checked here by exact cotangents written without the library's predicates.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use surftopo_intrinsic::generators::random_flips;
use surftopo_intrinsic::geometry::{Point, Rational, Scalar};
use surftopo_intrinsic::{
    DelaunayInput, DelaunayMethod, DelaunayOutputs, DelaunayRequest, IntrinsicTriangulation,
    IsometryDecision, IsometryOptions, Portalgon, decide_isometry, intrinsic_delaunay,
};
use surftopo_mesh::generators::{genus_surface, icosphere, subdivide_midpoint, tetrahedron, torus};
use surftopo_mesh::{Surface, VertexId};

/// The surfaces of the fuzz: sphere-like, genus 1 and genus 2, with random simplicial flips.
fn bases() -> Vec<(&'static str, Surface)> {
    vec![
        ("icosphere", icosphere(1)),
        ("tetrahedron", subdivide_midpoint(&tetrahedron(), 1)),
        ("torus", torus(8, 5)),
        ("genus 2", genus_surface(2, 1)),
    ]
}

/// `s` with vertex `v` moved to `distance` from its neighbour `w` (a random direction), every
/// coordinate then multiplied by `scale`.
fn pinched(s: &Surface, v: VertexId, w: VertexId, distance: f64, seed: u64) -> Surface {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut u: [f64; 3] = std::array::from_fn(|_| rng.random_range(-1.0..1.0));
    let n = u.iter().map(|x| x * x).sum::<f64>().sqrt();
    u = u.map(|x| x / n);
    let mut out = s.clone();
    out.positions[v.idx()] = std::array::from_fn(|i| s.positions[w.idx()][i] + distance * u[i]);
    out
}

fn scaled(s: &Surface, scale: f64) -> Surface {
    let mut out = s.clone();
    for p in &mut out.positions {
        *p = p.map(|x| x * scale);
    }
    out
}

/// A mesh and its own intrinsic flips, one vertex within 1e-17 … 1e-5 of another: never "not
/// isometric"; the verdict is the same at scales 2^-20, 1 and 2^20 (exact scalings of the
/// input), and never "not isometric" at 1e-6 and 1e6 either. Degenerate inputs (a zero length or
/// a zero-area face after rounding) are refused, as `delaunay` refuses them.
#[test]
fn a_mesh_with_a_vertex_near_another_is_never_proven_different_from_its_flips() {
    let options = IsometryOptions::default();
    let mut decided = 0;
    for (name, base) in bases() {
        let mesh = &base.mesh;
        for seed in 0..6u64 {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let e = mesh
                .edges()
                .nth(rng.random_range(0..mesh.edge_count()))
                .unwrap();
            let [v, w] = mesh.edge_vertices(e);
            let distance = 10f64.powf(rng.random_range(-17.0..-5.0));
            let surface = pinched(&base, v, w, distance, seed);
            let mut verdicts = Vec::new();
            for scale in [1.0, 2f64.powi(-20), 2f64.powi(20), 1e-6, 1e6] {
                let s = scaled(&surface, scale);
                let Ok(a) = IntrinsicTriangulation::from_positions(s.mesh.clone(), &s.positions)
                else {
                    continue;
                };
                if a.validate().is_err() {
                    verdicts.push((scale, "refused"));
                    continue;
                }
                let mut b = a.clone();
                random_flips(&mut b, 50, seed);
                let kind = match decide_isometry(&a, &b, &options) {
                    Ok(IsometryDecision::Isometric(_)) => "isometric",
                    Ok(IsometryDecision::Undecidable(_) | IsometryDecision::Undecided(_)) => {
                        "undecidable"
                    }
                    Ok(d @ IsometryDecision::NotIsometric(_)) => {
                        panic!("{name}, seed {seed}, distance {distance:e}, scale {scale}: {d}")
                    }
                    Err(_) => "refused",
                };
                decided += usize::from(kind != "refused");
                verdicts.push((scale, kind));
            }
            let exact: Vec<_> = verdicts
                .iter()
                .filter(|(s, _)| s.log2().fract() == 0.0)
                .collect();
            assert!(
                exact.windows(2).all(|w| w[0].1 == w[1].1),
                "{name}, seed {seed}, distance {distance:e}: {verdicts:?}"
            );
        }
    }
    assert!(decided > 60, "only {decided} pairs decided");
}

/// The doubled right triangle with legs 1 and `h`: a sphere with three cone points (angle π at
/// the right angle, twice the acute angles at the others), a needle for small `h`.
fn thin_right_pillowcase(h: &Rational) -> Portalgon<Rational> {
    let (zero, one) = (Rational::zero(), Rational::one());
    let mut p = Portalgon::<Rational>::empty();
    let a = p
        .add_polygon(&[
            [zero.clone(), zero.clone()],
            [one.clone(), zero.clone()],
            [zero.clone(), h.clone()],
        ])
        .unwrap();
    let b = p
        .add_polygon(&[
            [zero.clone(), zero.clone()],
            [zero.clone(), -h.clone()],
            [one, zero],
        ])
        .unwrap();
    for (i, j) in [(0, 2), (1, 1), (2, 0)] {
        p.glue(p.side(a, i), p.side(b, j), 1e-9).unwrap();
    }
    p
}

/// `cot` of the angle at `o` between `p` and `q`, exactly: dot over cross.
fn cot(o: &Point<Rational>, p: &Point<Rational>, q: &Point<Rational>) -> Rational {
    let (u, v) = (
        [p[0].clone() - o[0].clone(), p[1].clone() - o[1].clone()],
        [q[0].clone() - o[0].clone(), q[1].clone() - o[1].clone()],
    );
    let dot = u[0].clone() * v[0].clone() + u[1].clone() * v[1].clone();
    let cross = u[0].clone() * v[1].clone() - u[1].clone() * v[0].clone();
    dot / cross
}

/// Exact Delaunay check of a portalgon of triangles: for every glued pair, the cotangents of the
/// two angles opposite the side add up to at least 0 (the angles to at most π).
fn non_delaunay_pairs(p: &Portalgon<Rational>) -> usize {
    let opposite = |s| {
        let (next, prev) = (p.next_side(s), p.prev_side(s));
        assert_eq!(p.next_side(next), prev, "a triangle");
        cot(&p.start(prev), &p.start(s), &p.start(next))
    };
    p.sides()
        .filter(|&s| {
            let t = p.mate(s).expect("closed");
            s.0 < t.0 && opposite(s) + opposite(t) < Rational::zero()
        })
        .count()
}

#[test]
fn the_exact_wave_on_a_thin_right_pillowcase_is_exactly_delaunay() {
    for h in [
        "1/10",
        "1/1000",
        "1/1000000000000",
        "1/10000000000000000000000000000000",
    ] {
        let h: Rational = h.parse().unwrap();
        let request = DelaunayRequest {
            method: DelaunayMethod::Voronoi,
            outputs: DelaunayOutputs {
                triangulation: true,
                figures: true,
                ..DelaunayOutputs::default()
            },
            ..DelaunayRequest::default()
        };
        let out =
            intrinsic_delaunay(DelaunayInput::Exact(thin_right_pillowcase(&h)), &request).unwrap();
        let exact = out.exact_triangulation.expect("asked for");
        assert_eq!(non_delaunay_pairs(&exact), 0, "h = {h}");
        assert_eq!(out.stats.unwrap().non_delaunay_edges, 0, "h = {h}");
    }
}

/// The wave's work on T_x grows as x² (the constellations grow as x, the events as x): past its
/// work budget it stops with a typed error that names the method that finishes (Theorem 1).
#[test]
fn the_wave_stops_at_its_work_budget_and_names_dubois() {
    use surftopo_intrinsic::generators::flat_torus_portalgon;
    use surftopo_intrinsic::voronoi::{
        VoronoiError, VoronoiOptions, WaveError, WaveOptions, voronoi_delaunay,
    };
    let work = |x: i64, max_work: Option<u64>| {
        let t = flat_torus_portalgon(&Rational::from_i64(x), 1).unwrap();
        let options = VoronoiOptions {
            wave: WaveOptions {
                max_work,
                ..WaveOptions::default()
            },
            ..VoronoiOptions::default()
        };
        voronoi_delaunay(&t, &options)
    };
    // Within the budget: the same tessellation as without one.
    let free = work(200, None).unwrap();
    assert_eq!(
        work(200, Some(1_000_000)).unwrap().tessellation,
        free.tessellation
    );
    match work(200, Some(1_000)) {
        Err(e @ VoronoiError::Wave(WaveError::Work(1_000))) => {
            assert!(!e.is_numerical());
            assert!(e.to_string().contains("--method dubois"), "{e}");
        }
        other => panic!("{other:?}"),
    }
}

/// Theorem 1's own wave past its work budget says so (`CapsError::WaveWork`), without the wave's
/// advice to run Theorem 1 (what ran): on T_200 with a work budget of 10, exactly and on the
/// pillowcase of `pillowcase` with cone points.
#[test]
fn theorem_1s_wave_past_its_budget_does_not_advise_theorem_1() {
    use surftopo_intrinsic::dubois::{
        CapsError, FlatDelaunayOptions, delaunay_tessellation_dubois,
    };
    use surftopo_intrinsic::generators::{flat_torus_portalgon, pillowcase};
    use surftopo_intrinsic::voronoi::WaveOptions;
    let options = FlatDelaunayOptions {
        wave: WaveOptions {
            max_work: Some(10),
            ..WaveOptions::default()
        },
        ..FlatDelaunayOptions::default()
    };
    let q = |x: i64| Rational::from_i64(x);
    let torus = flat_torus_portalgon(&q(200), 1).unwrap();
    let pillow = pillowcase(&[q(1), q(0)], &[q(1000), q(1)]).unwrap();
    for t in [torus, pillow] {
        match delaunay_tessellation_dubois(&t, &options) {
            Err(e @ CapsError::WaveWork(10)) => {
                let text = e.to_string();
                assert!(text.contains("Theorem 1's wave"), "{text}");
                assert!(!text.contains("--method dubois"), "{text}");
            }
            other => panic!("{other:?}"),
        }
    }
}
