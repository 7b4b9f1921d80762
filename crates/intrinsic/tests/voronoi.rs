//! The Voronoi wave (Dubois, Appendix D) against independent checks: exact D_x on T_x, Gauss
//! reduction on integer-lattice tori, an exact flip algorithm written here on random rational
//! portalgons, the flip route's tessellation and Laplacian on the shared meshes; every output
//! polygon inscribed in an empty circle (exactly where the input is exact), with the input's area,
//! cone angles and Euler characteristic.

mod common;

use std::cmp::Ordering;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use surftopo_intrinsic::generators::{flat_torus_portalgon, random_flips};
use surftopo_intrinsic::geometry::{
    Motion, Point, Rational, Scalar, Tolerances, dist2, dot, incircle, orient, sub,
};
use surftopo_intrinsic::voronoi::{
    DualError, Sources, VoronoiDelaunay, VoronoiError, VoronoiOptions, is_flat_vertex, to_f64,
    voronoi_delaunay,
};
use surftopo_intrinsic::{
    DEFAULT_COCIRCULAR_TOLERANCE, DelaunayOptions, IntrinsicTriangulation, PolygonId, Portalgon,
    SideId, compare_tessellations, cotan_laplacian, delaunay_tessellation, flip_to_delaunay,
    lumped_mass,
};
use surftopo_testkit::{SharedMesh, load, shared_meshes};

fn r(x: &str) -> Rational {
    x.parse().unwrap()
}

fn options(sources: Sources) -> VoronoiOptions {
    VoronoiOptions {
        sources,
        ..VoronoiOptions::default()
    }
}

/// Checks every polygon of the output: convex, counter-clockwise, its corners on one circle
/// that holds no point of the constellation of the triangle of its Voronoi vertex strictly
/// inside, that Voronoi vertex its centre; exact in exact mode, within `tol` in f64.
fn check_empty_circles<S: Scalar>(v: &VoronoiDelaunay<S>) {
    let t = &v.tessellation;
    t.check_invariants().unwrap();
    t.check_closed().unwrap();
    for (k, q) in t.polygons().enumerate() {
        let c = t.corners(q);
        let m = c.len();
        assert!(m >= 3);
        for i in 0..m {
            let o = orient(&c[i], &c[(i + 1) % m], &c[(i + 2) % m]);
            assert_eq!(o, Ordering::Greater, "polygon {k} is not strictly convex");
        }
        let (tri, centre) = &v.diagram.vertices[k];
        let r2 = dist2(centre, &c[0]);
        for x in &c {
            assert!(
                S::lengths_match(&dist2(centre, x), &r2, 1e-8),
                "polygon {k}: corner off the circle"
            );
            if S::EXACT {
                assert_eq!(incircle(&c[0], &c[1], &c[2], x), Ordering::Equal);
            }
        }
        for x in v.wave.points(*tri) {
            let inside = if S::EXACT {
                incircle(&c[0], &c[1], &c[2], x) == Ordering::Greater
            } else {
                dist2(centre, x).to_f64() < r2.to_f64() * (1.0 - 1e-8)
            };
            assert!(
                !inside,
                "polygon {k}: a constellation point is inside its circle"
            );
        }
    }
}

/// Euler characteristic `V − E + F` of a closed portalgon.
fn euler<S: Scalar>(p: &Portalgon<S>) -> i64 {
    p.vertex_classes().1 as i64 - (p.side_count() / 2) as i64 + p.polygon_count() as i64
}

/// Angle sums per vertex class, in f64 (atan2 of the exact corners).
fn angle_sums<S: Scalar>(p: &Portalgon<S>) -> (Vec<f64>, Vec<u32>) {
    let (class, count) = p.vertex_classes();
    let mut sums = vec![0.0; count];
    for s in p.sides() {
        let v = p.start_ref(s);
        let a = sub(p.end_ref(s), v);
        let b = sub(p.start_ref(p.prev_side(s)), v);
        let cross = a[0].to_f64() * b[1].to_f64() - a[1].to_f64() * b[0].to_f64();
        sums[class[s.idx()] as usize] += cross.atan2(dot(&a, &b).to_f64());
    }
    (sums, class)
}

/// Same area (exactly in exact mode), Euler characteristic, and cone angle at each vertex of V.
/// Labels are the input's when V is every vertex of a labelled input, indices into V otherwise.
fn check_invariants_kept<S: Scalar>(
    input: &Portalgon<S>,
    v: &VoronoiDelaunay<S>,
    sources: Sources,
) {
    let (input_class, _) = input.vertex_classes();
    let labelled = input.sides().all(|s| input.vertex_label(s).is_some());
    let mut class_of_label = std::collections::HashMap::new();
    for s in input.sides() {
        if let Some(l) = input.vertex_label(s) {
            class_of_label.insert(l as usize, input_class[s.idx()] as usize);
        }
    }
    let t = &v.tessellation;
    if S::EXACT {
        assert_eq!(t.area(), input.area());
    } else {
        let (a, b) = (t.area().to_f64(), input.area().to_f64());
        assert!((a - b).abs() <= 1e-9 * b, "area {a} vs {b}");
    }
    assert_eq!(euler(t), euler(input));
    let (input_sums, _) = angle_sums(input);
    let (sums, class) = angle_sums(t);
    assert_eq!(sums.len(), v.sources.len());
    // Each output vertex carries its source's label; compare its cone angle with the source's.
    for s in t.sides() {
        let label = t.vertex_label(s).unwrap() as usize;
        let source = if sources == Sources::All && labelled {
            class_of_label[&label]
        } else {
            v.sources[label] as usize
        };
        let (a, b) = (sums[class[s.idx()] as usize], input_sums[source]);
        assert!((a - b).abs() <= 1e-9 * b.max(1.0), "cone angle {a} vs {b}");
    }
}

/// The squared side lengths of a polygon, sorted.
fn squared_sides<S: Scalar>(p: &Portalgon<S>, q: PolygonId) -> Vec<S> {
    let mut v: Vec<S> = p
        .polygon_sides(q)
        .iter()
        .map(|&s| p.side_length2(s))
        .collect();
    v.sort_by(|a, b| a.partial_cmp(b).unwrap());
    v
}

/// D_x (Section 9, Figure 8): the 1 × 2 rectangle for integer x, otherwise two triangles congruent
/// to (0,0), (1,0), (x − ⌊x⌋, 2).
fn check_d_x(x: &Rational) {
    let p = flat_torus_portalgon(x, 1).unwrap();
    let v = voronoi_delaunay(&p, &options(Sources::Singular)).unwrap();
    check_empty_circles(&v);
    check_invariants_kept(&p, &v, Sources::Singular);
    let t = &v.tessellation;
    assert_eq!(t.vertex_classes().1, 1);
    let frac = x.clone() - x.floor();
    if frac.is_zero() {
        assert_eq!(t.polygon_count(), 1, "x = {x}");
        let q = t.polygons().next().unwrap();
        let [one, four] = [1, 4].map(Rational::from_i64);
        assert_eq!(
            squared_sides(t, q),
            vec![one.clone(), one, four.clone(), four]
        );
        let c = t.corners(q);
        for i in 0..4 {
            let (a, b) = (
                sub(&c[(i + 1) % 4], &c[i]),
                sub(&c[(i + 2) % 4], &c[(i + 1) % 4]),
            );
            assert!(dot(&a, &b).is_zero(), "x = {x}: not a right angle");
        }
        // Opposite sides glued.
        for (i, &s) in t.polygon_sides(q).iter().enumerate() {
            assert_eq!(t.mate(s), Some(t.polygon_sides(q)[(i + 2) % 4]));
        }
    } else {
        assert_eq!(t.polygon_count(), 2, "x = {x}");
        let four = Rational::from_i64(4);
        let mut expected = vec![
            Rational::one(),
            frac.clone() * frac.clone() + four.clone(),
            (Rational::one() - frac.clone()) * (Rational::one() - frac) + four,
        ];
        expected.sort();
        for q in t.polygons() {
            assert_eq!(squared_sides(t, q), expected, "x = {x}");
        }
    }
    // Events grow like x: about 2x points join the constellations.
    let bound = 4.0 * x.to_f64() + 40.0;
    assert!((v.wave.events as f64) < bound, "{} events", v.wave.events);
}

#[test]
fn t_x_gives_exactly_d_x() {
    for x in [
        "2",
        "3",
        "7/2",
        "10",
        "101/3",
        "1000",
        "1000000001/1000000",
        "9999",
        "10000",
        "29999/3",
    ] {
        check_d_x(&r(x));
    }
}

/// A flat torus R² / (Z u + Z v) as two triangles (0, u, u+v) and (0, u+v, v).
fn lattice_torus(u: Point<Rational>, v: Point<Rational>) -> Portalgon<Rational> {
    let add = |a: &Point<Rational>, b: &Point<Rational>| {
        [a[0].clone() + b[0].clone(), a[1].clone() + b[1].clone()]
    };
    let o = [Rational::zero(), Rational::zero()];
    let w = add(&u, &v);
    let mut p = Portalgon::empty();
    let a = p.add_polygon(&[o.clone(), u, w.clone()]).unwrap();
    let b = p.add_polygon(&[o, w, v]).unwrap();
    for (i, j) in [(0, 1), (1, 2), (2, 0)] {
        p.glue(p.side(a, i), p.side(b, j), 0.0).unwrap();
    }
    p
}

/// Gauss (Lagrange) reduction of a lattice basis: |u| ≤ |v| ≤ |v ± u|.
fn gauss_reduce(mut u: [i64; 2], mut v: [i64; 2]) -> ([i64; 2], [i64; 2]) {
    let n2 = |a: [i64; 2]| a[0] * a[0] + a[1] * a[1];
    loop {
        if n2(u) > n2(v) {
            std::mem::swap(&mut u, &mut v);
        }
        let d = u[0] * v[0] + u[1] * v[1];
        let m = (d as f64 / n2(u) as f64).round() as i64;
        if m == 0 {
            return (u, v);
        }
        v = [v[0] - m * u[0], v[1] - m * u[1]];
    }
}

#[test]
fn integer_lattice_tori_give_the_gauss_reduced_basis() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let mut checked = 0;
    while checked < 40 {
        let u = [rng.random_range(-30i64..30), rng.random_range(-30i64..30)];
        let v = [rng.random_range(-300i64..300), rng.random_range(-30i64..30)];
        let det = u[0] * v[1] - u[1] * v[0];
        if det <= 0 {
            continue;
        }
        checked += 1;
        let q = |a: [i64; 2]| [Rational::from_i64(a[0]), Rational::from_i64(a[1])];
        let p = lattice_torus(q(u), q(v));
        let out = voronoi_delaunay(&p, &options(Sources::Singular)).unwrap();
        check_empty_circles(&out);
        check_invariants_kept(&p, &out, Sources::Singular);
        let (a, mut b) = gauss_reduce(u, v);
        let n2 = |x: [i64; 2]| Rational::from_i64(x[0] * x[0] + x[1] * x[1]);
        let d = a[0] * b[0] + a[1] * b[1];
        let t = &out.tessellation;
        if d == 0 {
            assert_eq!(t.polygon_count(), 1, "{u:?} {v:?}");
            let q0 = t.polygons().next().unwrap();
            let mut want = vec![n2(a), n2(a), n2(b), n2(b)];
            want.sort();
            assert_eq!(squared_sides(t, q0), want);
        } else {
            if d < 0 {
                b = [-b[0], -b[1]];
            }
            let mut want = vec![n2(a), n2(b), n2([b[0] - a[0], b[1] - a[1]])];
            want.sort();
            assert_eq!(t.polygon_count(), 2, "{u:?} {v:?}");
            for q0 in t.polygons() {
                assert_eq!(squared_sides(t, q0), want, "{u:?} {v:?}");
            }
        }
    }
}

/// The side `t` matched with `s` when it belongs to another triangle, and the motion carrying
/// `t`'s triangle next to `s`'s (footnote 2).
fn across(p: &Portalgon<Rational>, s: SideId) -> Option<(SideId, Motion<Rational>)> {
    let t = p.mate(s)?;
    (p.owner(s) != p.owner(t)).then(|| {
        let motion = Motion::taking(p.start_ref(t), p.end_ref(t), p.end_ref(s), p.start_ref(s));
        (t, motion)
    })
}

/// Flips side `s` (apex `c` of its triangle, `d` of the other one carried into its frame): merge
/// the two triangles, cut the quad along `c d`.
fn flip_side(p: &mut Portalgon<Rational>, s: SideId, c: &Point<Rational>, d: &Point<Rational>) {
    let q = p.merge(s).unwrap();
    let corners = p.corners(q);
    let i = corners.iter().position(|x| x == c).unwrap();
    let j = corners.iter().position(|x| x == d).unwrap();
    p.cut(q, i.min(j), i.max(j)).unwrap();
    p.check_invariants().unwrap();
}

/// The apexes of the two triangles at side `s`, in `s`'s frame, and the matched side's motion.
fn quad(p: &Portalgon<Rational>, s: SideId) -> Option<[Point<Rational>; 4]> {
    let (t, motion) = across(p, s)?;
    let d = motion.apply(p.start_ref(p.prev_side(t)));
    Some([p.start(s), p.end(s), p.start(p.prev_side(s)), d])
}

/// Applies `edit` to every live side, over and over, until a sweep changes nothing.
fn until_stable(
    p: &mut Portalgon<Rational>,
    mut edit: impl FnMut(&mut Portalgon<Rational>, SideId) -> bool,
) {
    loop {
        let sides: Vec<SideId> = p.sides().collect();
        let mut changed = false;
        for s in sides {
            if p.is_side_live(s) {
                changed |= edit(p, s);
            }
        }
        if !changed {
            break;
        }
    }
}

/// An exact flip algorithm, independent of the wave: flip every side whose two triangles fail
/// the exact in-circle test (merge, cut the other diagonal), then merge the co-circular pairs.
fn exact_flip_tessellation(mut p: Portalgon<Rational>) -> Portalgon<Rational> {
    until_stable(&mut p, |p, s| {
        let Some([a, b, c, d]) = quad(p, s) else {
            return false;
        };
        let flip = incircle(&a, &b, &c, &d) == Ordering::Greater;
        if flip {
            flip_side(p, s, &c, &d);
        }
        flip
    });
    // Merge co-circular neighbours.
    until_stable(&mut p, |p, s| {
        let Some((t, motion)) = across(p, s) else {
            return false;
        };
        let c = p.corners(p.owner(s));
        let on = p
            .corners(p.owner(t))
            .iter()
            .all(|x| incircle(&c[0], &c[1], &c[2], &motion.apply(x)) == Ordering::Equal);
        if on {
            p.merge(s).unwrap();
        }
        on
    });
    p.compacted().0
}

/// Random exact flips of a portalgon (when the quad is strictly convex): a random rational
/// re-triangulation of the same surface.
fn random_exact_flips(p: &mut Portalgon<Rational>, count: usize, rng: &mut ChaCha8Rng) {
    for _ in 0..count {
        let sides: Vec<SideId> = p.sides().collect();
        let s = sides[rng.random_range(0..sides.len())];
        let Some([a, b, c, d]) = quad(p, s) else {
            continue;
        };
        // Strictly convex quad a, d, b, c.
        if orient(&c, &d, &a) == Ordering::Greater && orient(&d, &c, &b) == Ordering::Greater {
            flip_side(p, s, &c, &d);
        }
    }
    *p = p.compacted().0;
}

/// A sphere with cone points: a rational triangle and its mirror image glued side to side.
fn doubled_triangle(c: [Point<Rational>; 3]) -> Portalgon<Rational> {
    let mirror = |x: &Point<Rational>| [x[0].clone(), -x[1].clone()];
    let mut p = Portalgon::empty();
    let a = p.add_polygon(&c).unwrap();
    let b = p
        .add_polygon(&[mirror(&c[1]), mirror(&c[0]), mirror(&c[2])])
        .unwrap();
    // Side 0 of a (c0 → c1) with side 0 of b (c1' → c0'); side 1 (c1 → c2) with side 2 of b
    // (c2' → c1'); side 2 (c2 → c0) with side 1 of b (c0' → c2').
    for (i, j) in [(0, 0), (1, 2), (2, 1)] {
        p.glue(p.side(a, i), p.side(b, j), 0.0).unwrap();
    }
    p
}

#[test]
fn random_rational_portalgons_agree_with_an_exact_flip_algorithm() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let small = |rng: &mut ChaCha8Rng| {
        Rational::new(rng.random_range(-40..40), rng.random_range(1..9)).unwrap()
    };
    for case in 0..24 {
        let mut p = if case % 2 == 0 {
            let x = Rational::new(rng.random_range(1..400), rng.random_range(1..7)).unwrap();
            flat_torus_portalgon(&x, rng.random_range(1..4)).unwrap()
        } else {
            let c = loop {
                let c = [0, 1, 2].map(|_| [small(&mut rng), small(&mut rng)]);
                if orient(&c[0], &c[1], &c[2]) == Ordering::Greater {
                    break c;
                }
            };
            doubled_triangle(c)
        };
        random_exact_flips(&mut p, 20, &mut rng);
        p.check_invariants().unwrap();
        for sources in [Sources::All, Sources::Singular] {
            let v = voronoi_delaunay(&p, &options(sources)).unwrap();
            check_empty_circles(&v);
            check_invariants_kept(&p, &v, sources);
            // The exact flip algorithm works with every vertex of T; for Singular, compare with
            // the flat vertices' count instead (a flat torus: one vertex).
            if sources == Sources::All {
                let reference = exact_flip_tessellation(p.clone());
                let mut a: Vec<Vec<Rational>> = v
                    .tessellation
                    .polygons()
                    .map(|q| squared_sides(&v.tessellation, q))
                    .collect();
                let mut b: Vec<Vec<Rational>> = reference
                    .polygons()
                    .map(|q| squared_sides(&reference, q))
                    .collect();
                a.sort();
                b.sort();
                assert_eq!(a, b, "case {case}: the polygons differ");
                let (ta, tb) = (to_f64(&v.tessellation), to_f64(&reference));
                ta.check_invariants().unwrap();
                tb.check_invariants().unwrap();
                let outcome = compare_tessellations(&ta, &tb, 1e-9, false).unwrap();
                assert!(outcome.is_isometric(), "case {case}: {outcome}");
            } else {
                let flat = p
                    .sides()
                    .filter(|&s| is_flat_vertex(&p, s, 0.0))
                    .map(|s| p.vertex_classes().0[s.idx()])
                    .collect::<std::collections::BTreeSet<_>>();
                let all = p.vertex_classes().1;
                let want = if flat.len() == all {
                    1
                } else {
                    all - flat.len()
                };
                assert_eq!(v.sources.len(), want, "case {case}");
            }
        }
    }
}

/// Checks the voronoi output of `tri` (as the portalgon `p`, V = every vertex) and that it is the
/// flip route's tessellation; returns the flipped triangulation.
fn assert_same_as_flip(
    tri: &IntrinsicTriangulation,
    p: &Portalgon,
    v: &VoronoiDelaunay<f64>,
    what: &str,
) -> IntrinsicTriangulation {
    check_empty_circles(v);
    check_invariants_kept(p, v, Sources::All);
    let mut flipped = tri.clone();
    flip_to_delaunay(&mut flipped, &DelaunayOptions::default()).unwrap();
    let t = delaunay_tessellation(&flipped, DEFAULT_COCIRCULAR_TOLERANCE);
    let outcome = compare_tessellations(&v.tessellation, &t.portalgon, 1e-7, false).unwrap();
    assert!(outcome.is_isometric(), "{what}: {outcome}");
    flipped
}

/// On a shared mesh: the voronoi tessellation (V = every vertex, f64) is the flip route's, and the
/// Laplacians of their triangulations agree to 1e-9 relative. `Err` when the f64 dual refuses the
/// mesh with its typed error (exactly co-circular configurations, see the dual's module doc);
/// any other failure, or a different answer, panics.
fn check_against_flip(mesh: &SharedMesh) -> Result<(), String> {
    let s = load(mesh);
    let tri = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap();
    let (p, _) = tri.to_portalgon();
    let v = match voronoi_delaunay(&p, &VoronoiOptions::default()) {
        Ok(v) => v,
        Err(e @ VoronoiError::Dual(DualError::Trace { .. })) => {
            return Err(format!("{}: {e}", mesh.file));
        }
        Err(e) => panic!("{}: {e}", mesh.file),
    };
    let flipped = assert_same_as_flip(&tri, &p, &v, &mesh.file);
    let ours = v.triangulation().unwrap();
    let (la, lb) = (cotan_laplacian(&ours), cotan_laplacian(&flipped));
    assert_eq!(la.n, lb.n);
    let scale = (0..lb.n).map(|i| lb.get(i, i).abs()).fold(0.0, f64::max);
    for i in 0..la.n {
        for (j, x) in la.row(i) {
            let y = lb.get(i, j as usize);
            assert!(
                (x - y).abs() <= 1e-9 * scale,
                "{}: L[{i}][{j}] {x} vs {y}",
                mesh.file
            );
        }
        for (j, y) in lb.row(i) {
            let x = la.get(i, j as usize);
            assert!(
                (x - y).abs() <= 1e-9 * scale,
                "{}: L[{i}][{j}] {x} vs {y}",
                mesh.file
            );
        }
    }
    // The lumped mass depends on the diagonals cut into co-circular polygons, so only its total
    // (the area) is the same for the two triangulations.
    let (ma, mb) = (lumped_mass(&ours), lumped_mass(&flipped));
    let total = |m: &surftopo_intrinsic::SparseMatrix| (0..m.n).map(|i| m.get(i, i)).sum::<f64>();
    assert!(
        (total(&ma) - total(&mb)).abs() <= 1e-9 * total(&mb),
        "{}",
        mesh.file
    );
    eprintln!(
        "{}: {} faces, {} polygons, {} events, max |X| {}",
        mesh.file,
        mesh.faces,
        v.tessellation.polygon_count(),
        v.wave.events,
        v.wave.max_constellation()
    );
    Ok(())
}

surftopo_testkit::shared_mesh_tests!(voronoi_equals_flip_on_a_sample_of_shared_meshes);

fn voronoi_equals_flip_on_a_sample_of_shared_meshes() {
    let meshes = shared_meshes();
    let sample: Vec<&SharedMesh> = meshes.iter().filter(|m| m.faces <= 6_000).take(8).collect();
    assert_eq!(sample.len(), 8);
    let refused: Vec<String> = sample
        .iter()
        .filter_map(|m| check_against_flip(m).err())
        .collect();
    eprintln!("refused: {refused:#?}");
    assert!(refused.len() * 2 <= sample.len(), "{refused:#?}");
}

#[test]
#[ignore = "every shared mesh: run in release (cargo test --release -- --ignored)"]
fn voronoi_equals_flip_on_every_shared_mesh() {
    // Each mesh on its own thread, given up on after two minutes (a slow f64 wave on a needle
    // mesh is reported, not waited for; a wrong answer panics the thread and fails the test).
    surftopo_testkit::require_shared_meshes();
    let meshes = shared_meshes();
    let mut refused = Vec::new();
    for m in &meshes {
        let (tx, rx) = std::sync::mpsc::channel();
        let mesh = m.clone();
        std::thread::spawn(move || {
            let result = std::panic::catch_unwind(|| check_against_flip(&mesh));
            let _ = tx.send(result);
        });
        match rx.recv_timeout(std::time::Duration::from_secs(120)) {
            Ok(Ok(Ok(()))) => {}
            Ok(Ok(Err(why))) => refused.push(why),
            Ok(Err(_)) => panic!(
                "{}: the voronoi route disagrees with the flip route",
                m.file
            ),
            Err(_) => refused.push(format!("{}: did not finish within 120 s", m.file)),
        }
    }
    eprintln!("refused by the f64 dual: {refused:#?}");
    assert!(refused.len() * 3 <= meshes.len(), "{refused:#?}");
}

#[test]
fn random_intrinsic_retriangulations_and_sheared_tori() {
    let sheared = surftopo_intrinsic::generators::sheared_torus(24, 8, 3);
    let mut tris =
        vec![IntrinsicTriangulation::from_positions(sheared.mesh, &sheared.positions).unwrap()];
    let ico = surftopo_mesh::generators::icosphere(2);
    let mut t = IntrinsicTriangulation::from_positions(ico.mesh, &ico.positions).unwrap();
    random_flips(&mut t, 300, 5);
    tris.push(t);
    for tri in tris {
        let (p, _) = tri.to_portalgon();
        let v = voronoi_delaunay(&p, &VoronoiOptions::default()).unwrap();
        assert_same_as_flip(&tri, &p, &v, "a re-triangulation");
    }
}

/// A wave stopped by its event budget is a numerical refusal; an open portalgon is bad input.
#[test]
fn numerical_refusals_are_told_from_bad_input() {
    let sheared = surftopo_intrinsic::generators::sheared_torus(24, 8, 3);
    let tri = IntrinsicTriangulation::from_positions(sheared.mesh, &sheared.positions).unwrap();
    let (p, _) = tri.to_portalgon();
    let mut options = VoronoiOptions::default();
    options.wave.max_events = Some(1);
    let e = voronoi_delaunay(&p, &options).unwrap_err();
    assert!(matches!(e, VoronoiError::Wave(_)), "{e}");
    assert!(e.is_numerical(), "{e}");
    let mut open = Portalgon::<f64>::empty();
    open.add_polygon(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
        .unwrap();
    let e = voronoi_delaunay(&open, &VoronoiOptions::default()).unwrap_err();
    assert!(!e.is_numerical(), "{e}");
}

/// The flat 1 × 2 torus cut into the `m × m` grid of rectangles (each split by a diagonal: exactly
/// co-circular quadrilaterals), every vertex moved by a random vector of length at most `jitter`:
/// nearly co-circular quadrilaterals whose Voronoi vertices lie within rounding distance of
/// each other. Lengths from the moved positions (vertex `j m + i` at `(i, 2j) / m`).
fn jittered_rectangle_torus(m: u32, jitter: f64, seed: u64) -> IntrinsicTriangulation {
    let grid =
        IntrinsicTriangulation::from_portalgon(&flat_torus_portalgon(&0.0, m).unwrap(), 1e-12)
            .unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let moved: Vec<[f64; 2]> = (0..m * m)
        .map(|_| {
            let (r, a) = (
                jitter * rng.random::<f64>(),
                std::f64::consts::TAU * rng.random::<f64>(),
            );
            [r * a.cos(), r * a.sin()]
        })
        .collect();
    let (mi, mf) = (i64::from(m), f64::from(m));
    let cell = |v: u32| (i64::from(v) % mi, i64::from(v) / mi);
    let (mesh, lengths) = grid.into_parts();
    let mut jittered = lengths.clone();
    for e in mesh.edges() {
        let [a, b] = mesh.edge_vertices(e);
        let ((ia, ja), (ib, jb)) = (cell(a.0), cell(b.0));
        // The edge's grid step from a to b, told by its length (1, 2 or √5, over m).
        let (di, dj) = [(1, 0), (0, 1), (-1, 1), (1, -1), (-1, 0), (0, -1)]
            .into_iter()
            .find(|&(di, dj): &(i64, i64)| {
                let expected = (di as f64).hypot(2.0 * dj as f64) / mf;
                (ia + di).rem_euclid(mi) == ib
                    && (ja + dj).rem_euclid(mi) == jb
                    && (expected - lengths[e.0 as usize]).abs() < 1e-12
            })
            .expect("an edge of the rectangle grid");
        let (da, db) = (moved[a.0 as usize], moved[b.0 as usize]);
        let dx = di as f64 / mf + db[0] - da[0];
        let dy = 2.0 * dj as f64 / mf + db[1] - da[1];
        jittered[e.0 as usize] = dx.hypot(dy);
    }
    IntrinsicTriangulation::from_parts(mesh, jittered).unwrap()
}

/// Nearly co-circular sites in `f64`, around the dual's tolerance (1e-9 of the longest side) and
/// on both sides of it: the dual gives a tessellation whose polygons have empty circles and whose
/// Laplacian is the flip route's (to 1e-6: one route may merge a nearly co-circular polygon that
/// the other splits), or refuses with its typed error; exactly co-circular and well separated
/// sites are answered. The retry that pools the sites of Voronoi vertices taken for one (as
/// Dubois' route runs it) answers where the first attempt refused.
#[test]
fn nearly_co_circular_sites_in_f64_give_the_flip_route_or_a_typed_refusal() {
    // Retried at the same tolerance: only the pooling can answer differently.
    let retried = VoronoiOptions {
        tolerances: Tolerances {
            dual_retry: Some(Tolerances::DEFAULT.dual),
            ..Tolerances::DEFAULT
        },
        ..VoronoiOptions::default()
    };
    let mut rescued = 0;
    for (seed, jitter) in [0.0, 1e-9, 3e-9, 1e-8, 3e-8, 1e-7, 1e-6]
        .into_iter()
        .enumerate()
    {
        for m in [5, 8] {
            let what = format!("m = {m}, jitter {jitter:e}");
            let tri = jittered_rectangle_torus(m, jitter, seed as u64);
            let (p, _) = tri.to_portalgon();
            let must_answer = jitter == 0.0 || jitter >= 1e-6;
            let first = match voronoi_delaunay(&p, &VoronoiOptions::default()) {
                Ok(v) => {
                    check_empty_circles(&v);
                    assert_laplacian_close(&tri, &v, 1e-6, &what);
                    if must_answer {
                        assert_same_as_flip(&tri, &p, &v, &what);
                    }
                    true
                }
                Err(VoronoiError::Dual(DualError::Trace { .. })) if !must_answer => false,
                Err(e) => panic!("{what}: {e}"),
            };
            match voronoi_delaunay(&p, &retried) {
                Ok(v) => {
                    assert_laplacian_close(&tri, &v, 1e-6, &what);
                    rescued += usize::from(!first);
                }
                Err(VoronoiError::Dual(DualError::Trace { .. })) if !must_answer => {}
                Err(e) => panic!("{what}: {e}"),
            }
        }
    }
    assert!(
        rescued > 0,
        "the retry answered nowhere the first attempt refused"
    );
}

/// The cotan Laplacians of `v`'s triangulation and of the flip route's agree to `tolerance`
/// relative to the largest diagonal entry.
fn assert_laplacian_close(
    tri: &IntrinsicTriangulation,
    v: &VoronoiDelaunay<f64>,
    tolerance: f64,
    what: &str,
) {
    let mut flipped = tri.clone();
    flip_to_delaunay(&mut flipped, &DelaunayOptions::default()).unwrap();
    let (la, lb) = (
        cotan_laplacian(&v.triangulation().unwrap()),
        cotan_laplacian(&flipped),
    );
    let scale = (0..lb.n).map(|i| lb.get(i, i).abs()).fold(0.0, f64::max);
    for i in 0..la.n {
        for (j, _) in la.row(i).chain(lb.row(i)) {
            let (a, b) = (la.get(i, j as usize), lb.get(i, j as usize));
            assert!(
                (a - b).abs() <= tolerance * scale,
                "{what}: L[{i}][{j}] {a} vs {b}"
            );
        }
    }
}

/// When the wave's and the dual's tolerances are coarse for the surface's features they can
/// refuse it; [`Tolerances::finer_retry`] runs both again finer, which answers with the flip
/// route's tessellation: rectangle-grid tori jittered by 1e-4 to 3e-4 of their side, told apart
/// to 1e-4 (the jitter is then near-co-circularity at the tolerance, as the default 1e-9 meets
/// on meshes with features 10⁴ times smaller than their longest side), retried at 1e-7.
#[test]
fn coarse_tolerances_are_retried_finer_when_asked() {
    let mut coarse = VoronoiOptions::default();
    coarse.tolerances.point = 1e-4;
    coarse.tolerances.dual = 1e-4;
    let mut finer = coarse;
    finer.tolerances.finer_retry = Some(1e-3);
    let mut rescued = 0;
    for (seed, jitter) in [1e-4, 2e-4, 3e-4].into_iter().enumerate() {
        for m in [5, 8] {
            let tri = jittered_rectangle_torus(m, jitter, seed as u64);
            let (p, _) = tri.to_portalgon();
            if voronoi_delaunay(&p, &coarse).is_ok() {
                continue;
            }
            let what = format!("m = {m}, jitter {jitter:e}, retried finer");
            let v = voronoi_delaunay(&p, &finer).unwrap_or_else(|e| panic!("{what}: {e}"));
            assert_same_as_flip(&tri, &p, &v, &what);
            rescued += 1;
        }
    }
    eprintln!("{rescued} refused at 1e-4 and answered at 1e-7");
    assert!(rescued > 0, "no case refused at the coarse tolerance");
}
