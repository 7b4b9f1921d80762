//! Dubois' ALGORITHM (Section 4, `dubois` module) on flat tori, checked by verifiers written
//! here: the surface is unchanged (exact area, every vertex of angle 2π by `atan2` sums, Euler
//! characteristic 0 from a union–find of corners, every side matched), the gluings are
//! translations whose lattice (developed here along a dual spanning tree) is the input's —
//! every holonomy an integer combination of the input basis, and the 2×2 minors of the
//! holonomies' coordinates with gcd 1 — and the reduced triangulation is small.

mod common_tubes;

use std::collections::VecDeque;

use common_tubes::two_tubes;

use surftopo_intrinsic::dubois::{DuboisError, ReduceOptions, Reduction, outer_iterations, reduce};
use surftopo_intrinsic::geometry::{Rational, Scalar, cross, dot, sub};
use surftopo_intrinsic::{Portalgon, TubeRoute};

fn q(s: &str) -> Rational {
    s.parse().unwrap()
}

type P = [Rational; 2];

/// The flat torus `R²/⟨u, v⟩` as two triangles `0, u, v` and `u + v, v, u`, side i glued to side i.
fn lattice_torus(u: &P, v: &P) -> Portalgon<Rational> {
    let z = Rational::zero();
    let uv = [u[0].clone() + v[0].clone(), u[1].clone() + v[1].clone()];
    let mut p = Portalgon::<Rational>::empty();
    let d1 = p
        .add_polygon(&[[z.clone(), z], u.clone(), v.clone()])
        .unwrap();
    let d2 = p.add_polygon(&[uv, v.clone(), u.clone()]).unwrap();
    for i in 0..3 {
        p.glue(p.side(d1, i), p.side(d2, i), 0.0).unwrap();
    }
    p
}

/// Section 9's `T_x`: `u = (1, 0)`, `v = (x, 2)`.
fn t_x(x: &str) -> (Portalgon<Rational>, [P; 2]) {
    let basis = [[q("1"), q("0")], [q(x), q("2")]];
    (lattice_torus(&basis[0], &basis[1]), basis)
}

fn find(parent: &mut [usize], mut x: usize) -> usize {
    while parent[x] != x {
        x = parent[x];
    }
    x
}

/// The surface checks: closed, area `area` exactly, Euler characteristic 0, every vertex 2π.
fn check_flat_torus(p: &Portalgon<Rational>, area: &Rational) -> Result<(), String> {
    if p.unmatched_sides().next().is_some() {
        return Err("an unmatched side".into());
    }
    if p.area() != *area {
        return Err(format!("area {} instead of {area}", p.area()));
    }
    let n = p.side_slots();
    let mut parent: Vec<usize> = (0..n).collect();
    for s in p.sides() {
        let t = p.mate(s).unwrap();
        let (a, b) = (
            find(&mut parent, s.idx()),
            find(&mut parent, p.next_side(t).idx()),
        );
        parent[a.max(b)] = a.min(b);
    }
    let mut angle = vec![0.0; n];
    for s in p.sides() {
        let (o, u, w) = (p.start_ref(s), p.end_ref(s), p.start_ref(p.prev_side(s)));
        let (du, dw) = (sub(u, o), sub(w, o));
        let v = find(&mut parent, s.idx());
        angle[v] += cross(&du, &dw).to_f64().atan2(dot(&du, &dw).to_f64());
    }
    let roots: Vec<usize> = p
        .sides()
        .map(|s| s.idx())
        .filter(|&s| find(&mut parent, s) == s)
        .collect();
    for &v in &roots {
        if (angle[v] - std::f64::consts::TAU).abs() > 1e-9 {
            return Err(format!("vertex of side {v} has angle {}", angle[v]));
        }
    }
    let chi = roots.len() as i64 - p.side_count() as i64 / 2 + p.polygon_count() as i64;
    if chi != 0 {
        return Err(format!("Euler characteristic {chi}"));
    }
    Ok(())
}

/// The holonomies of the translation structure: every gluing must be a translation (matched
/// sides with opposite vectors); polygons are developed along a breadth-first dual spanning tree
/// and each non-tree gluing gives a lattice vector.
fn holonomies(p: &Portalgon<Rational>) -> Result<Vec<P>, String> {
    let zero = || [Rational::zero(), Rational::zero()];
    let mut offset: Vec<Option<P>> = vec![None; p.polygon_slots()];
    let first = p.polygons().next().ok_or("empty")?;
    offset[first.idx()] = Some(zero());
    let mut queue = VecDeque::from([first]);
    let mut out = Vec::new();
    let mut tree_sides = std::collections::HashSet::new();
    while let Some(a) = queue.pop_front() {
        let oa = offset[a.idx()].clone().unwrap();
        for &s in p.polygon_sides(a) {
            let t = p.mate(s).ok_or("unmatched side")?;
            let vs = sub(p.end_ref(s), p.start_ref(s));
            let vt = sub(p.end_ref(t), p.start_ref(t));
            if vs[0] != -vt[0].clone() || vs[1] != -vt[1].clone() {
                return Err(format!("gluing of side {} is not a translation", s.idx()));
            }
            let b = p.owner(t);
            let shift = sub(p.end_ref(s), p.start_ref(t));
            let ob = [
                oa[0].clone() + shift[0].clone(),
                oa[1].clone() + shift[1].clone(),
            ];
            match &offset[b.idx()] {
                None => {
                    offset[b.idx()] = Some(ob);
                    tree_sides.insert(t);
                    queue.push_back(b);
                }
                Some(existing) if !tree_sides.contains(&s) => {
                    let h = sub(&ob, existing);
                    if !h[0].is_zero() || !h[1].is_zero() {
                        out.push(h);
                    }
                }
                Some(_) => {}
            }
        }
    }
    Ok(out)
}

fn gcd(a: i128, b: i128) -> i128 {
    if b == 0 { a.abs() } else { gcd(b, a % b) }
}

/// Whether the holonomies of `p` generate exactly the lattice of `basis`.
fn same_lattice(p: &Portalgon<Rational>, basis: &[P; 2]) -> Result<(), String> {
    let [u, v] = basis;
    let det = cross(u, v);
    let mut coords: Vec<[i128; 2]> = Vec::new();
    for h in holonomies(p)? {
        // h = a u + b v: a = (h × v)/(u × v), b = (u × h)/(u × v).
        let (a, b) = (cross(&h, v) / det.clone(), cross(u, &h) / det.clone());
        if !a.is_integer() || !b.is_integer() {
            return Err(format!(
                "holonomy ({}, {}) is not in the lattice",
                h[0], h[1]
            ));
        }
        coords.push([
            a.to_string().parse().unwrap(),
            b.to_string().parse().unwrap(),
        ]);
    }
    let mut g = 0i128;
    for i in 0..coords.len() {
        for j in i + 1..coords.len() {
            let m = coords[i][0] * coords[j][1] - coords[i][1] * coords[j][0];
            g = gcd(g, m);
        }
    }
    if g != 1 {
        return Err(format!("the holonomies generate a sublattice of index {g}"));
    }
    Ok(())
}

fn check_reduced(x: &str, max_triangles: usize) {
    let (t, basis) = t_x(x);
    let area = t.area();
    let r = reduce(&t, &ReduceOptions::default()).unwrap();
    let p = &r.portalgon;
    check_flat_torus(p, &area).unwrap_or_else(|e| panic!("x = {x}: {e}"));
    same_lattice(p, &basis).unwrap_or_else(|e| panic!("x = {x}: {e}"));
    r.check_invariants().unwrap();
    assert!(
        p.polygon_count() <= max_triangles,
        "x = {x}: {} triangles; report {:?}",
        p.polygon_count(),
        r.report
    );
    assert_eq!(r.report.triangles_after_reduction, p.polygon_count());
    // The geometry is reduced: every side at most as long as D_x's longest side (√5, the
    // diagonal of the 1 × 2 rectangle), against |(x, 2)| in the input.
    let longest2 = p
        .sides()
        .map(|s| p.side_length2(s))
        .fold(q("0"), |m, l| if l > m { l } else { m });
    assert!(longest2 <= q("5"), "x = {x}: longest side² {longest2}");
    assert_eq!(r.report.arithmetic, "exact");
    assert_eq!(
        r.report.inner_passes_total,
        r.report
            .inner_passes
            .iter()
            .map(|&k| u64::from(k))
            .sum::<u64>()
    );
}

#[test]
fn outer_iterations_follow_the_aspect_ratio() {
    // T_x: L = |(x, 2)|, triangle areas 1, so 2L/d = L·ℓ/A = x² + 4 (for x ≥ 1).
    // N = ⌈log₂(2 + x² + 4)⌉.
    for (x, n) in [("10", 7), ("1000", 20), ("1000000000", 60)] {
        assert_eq!(outer_iterations(&t_x(x).0), n, "x = {x}");
    }
    // The unit square torus: L = ℓ = √2, A = ½, so L·ℓ/A = 4 and N = ⌈log₂ 6⌉ = 3.
    let square = lattice_torus(&[q("1"), q("0")], &[q("0"), q("1")]);
    assert_eq!(outer_iterations(&square), 3);
}

#[test]
fn t_x_reduces_to_a_small_triangulation_of_the_same_torus() {
    for x in ["1000", "1000000000", "1000000000000000000", "3000000001/3"] {
        check_reduced(x, 8);
    }
}

#[test]
fn a_huge_shear_reduces_to_the_same_lattice() {
    let basis = [[q("1"), q("0")], [q("1000000"), q("1")]];
    let t = lattice_torus(&basis[0], &basis[1]);
    let area = t.area();
    let r = reduce(&t, &ReduceOptions::default()).unwrap();
    check_flat_torus(&r.portalgon, &area).unwrap();
    same_lattice(&r.portalgon, &basis).unwrap();
    assert!(r.portalgon.polygon_count() <= 8, "{:?}", r.report);
    // The unit square's sides and diagonals: at most √2.
    let p = &r.portalgon;
    assert!(p.sides().all(|s| p.side_length2(s) <= q("2")));
}

/// Runs ALGORITHM's routines by hand (N outer iterations, `inner` inner ones) and checks the
/// surface and the Section 4.4 invariants after every routine.
fn routine_by_routine(t: &Portalgon<Rational>, basis: &[P; 2], outer: u32, inner: u32) {
    let area = t.area();
    let mut r = Reduction::new(t.clone(), TubeRoute::Direct, 0.0);
    let check = |r: &Reduction<Rational>, what: &str| {
        r.check_invariants()
            .unwrap_or_else(|e| panic!("after {what}: {e}"));
        check_flat_torus(&r.portalgon, &area).unwrap_or_else(|e| panic!("after {what}: {e}"));
        same_lattice(&r.portalgon, basis).unwrap_or_else(|e| panic!("after {what}: {e}"));
        for p in r.active_polygons() {
            assert!(r.portalgon.polygon_sides(p).len() <= 6, "after {what}");
        }
    };
    for _ in 0..outer {
        r.insert_vertices().unwrap();
        check(&r, "INSERTVERTICES");
        r.insert_edges().unwrap();
        check(&r, "INSERTEDGES");
        for p in r.active_polygons() {
            assert_eq!(r.portalgon.polygon_sides(p).len(), 3);
        }
        for _ in 0..inner {
            r.gardening().unwrap();
            check(&r, "GARDENING");
            r.simplify_tubes().unwrap();
            check(&r, "SIMPLIFYTUBES");
            r.gardening().unwrap();
            check(&r, "GARDENING");
            r.delete_vertices().unwrap();
            check(&r, "DELETEVERTICES");
            r.insert_edges().unwrap();
            check(&r, "INSERTEDGES");
        }
    }
}

#[test]
fn every_routine_keeps_the_surface_and_the_invariants() {
    for x in ["1000", "7/3"] {
        let (t, basis) = t_x(x);
        routine_by_routine(&t, &basis, 6, 6);
    }
    let basis = [[q("1"), q("0")], [q("1000000"), q("1")]];
    routine_by_routine(&lattice_torus(&basis[0], &basis[1]), &basis, 6, 6);
}

#[test]
fn insert_vertices_splits_only_sides_matched_inside_the_active_region() {
    let (t, _) = t_x("10");
    let mut r = Reduction::new(t, TubeRoute::Direct, 0.0);
    // T_10: three edges, all inside R_A: three midpoints, six sides per triangle.
    assert_eq!(r.insert_vertices().unwrap(), 3);
    for p in r.active_polygons() {
        assert_eq!(r.portalgon.polygon_sides(p).len(), 6);
    }
}

#[test]
fn faithful_and_default_give_identical_results() {
    let inputs = [
        t_x("10").0,
        t_x("7/3").0,
        lattice_torus(&[q("1"), q("0")], &[q("5"), q("1")]),
    ];
    for t in &inputs {
        let fast = reduce(t, &ReduceOptions::default()).unwrap();
        let faithful = reduce(
            t,
            &ReduceOptions {
                faithful: true,
                ..ReduceOptions::default()
            },
        )
        .unwrap();
        assert_eq!(fast.portalgon, faithful.portalgon);
        assert_eq!(fast.regions, faithful.regions);
        assert_eq!(
            faithful.report.inner_passes_total,
            faithful.report.inner_passes_bound
        );
        assert!(fast.report.inner_passes_total < faithful.report.inner_passes_total);
        // Fewer when the outer iterations repeat (the periodic exit, docs/dubois.md §3.2).
        assert!(fast.report.vertices_deleted <= faithful.report.vertices_deleted);
        assert!(fast.report.inner_passes.len() <= faithful.report.inner_passes.len());
    }
}

#[test]
fn the_same_input_gives_the_same_output() {
    let (t, _) = t_x("3000000001/3");
    let a = reduce(&t, &ReduceOptions::default()).unwrap();
    let b = reduce(&t, &ReduceOptions::default()).unwrap();
    assert_eq!(a, b);
}

#[test]
fn bad_input_is_refused() {
    // Not triangular: the unit square torus as one square.
    let z = Rational::zero;
    let o = Rational::one;
    let mut sq = Portalgon::<Rational>::empty();
    let p = sq
        .add_polygon(&[[z(), z()], [o(), z()], [o(), o()], [z(), o()]])
        .unwrap();
    sq.glue(sq.side(p, 0), sq.side(p, 2), 0.0).unwrap();
    sq.glue(sq.side(p, 1), sq.side(p, 3), 0.0).unwrap();
    assert!(matches!(
        reduce(&sq, &ReduceOptions::default()),
        Err(DuboisError::NotTriangular { sides: 4, .. })
    ));
    // Not closed.
    let mut open = t_x("10").0;
    let s = open.sides().next().unwrap();
    open.unglue(s);
    assert!(matches!(
        reduce(&open, &ReduceOptions::default()),
        Err(DuboisError::Portalgon(_))
    ));
    // A cone point: a doubled right triangle (a sphere with cone angles π, π/2, π/2).
    let mut pillow = Portalgon::<Rational>::empty();
    let a = pillow
        .add_polygon(&[[z(), z()], [o(), z()], [z(), o()]])
        .unwrap();
    let b = pillow
        .add_polygon(&[[z(), z()], [z(), -o()], [o(), z()]])
        .unwrap();
    for (i, j) in [(0, 2), (1, 1), (2, 0)] {
        pillow
            .glue(pillow.side(a, i), pillow.side(b, j), 0.0)
            .unwrap();
    }
    assert!(matches!(
        reduce(&pillow, &ReduceOptions::default()),
        Err(DuboisError::NotFlat { .. })
    ));
}

#[test]
fn f64_mode_reduces_t_x() {
    let mut t = Portalgon::new();
    let x = 1000.0;
    let d1 = t.add_polygon(&[[0.0, 0.0], [1.0, 0.0], [x, 2.0]]).unwrap();
    let d2 = t
        .add_polygon(&[[1.0 + x, 2.0], [x, 2.0], [1.0, 0.0]])
        .unwrap();
    for i in 0..3 {
        t.glue(t.side(d1, i), t.side(d2, i), 1e-12).unwrap();
    }
    let r = reduce(&t, &ReduceOptions::default()).unwrap();
    assert_eq!(r.report.arithmetic, "f64");
    assert!(r.portalgon.check_closed().is_ok());
    assert!((r.portalgon.area() - 2.0).abs() < 1e-9);
    assert!(r.portalgon.polygon_count() <= 8, "{:?}", r.report);
}

#[test]
fn inactive_bifaces_and_separating_loops_are_left_alone() {
    // T_{3000000001/3} ends with R_A empty: two thin good bifaces, each an inactive region,
    // glued along separating loops.
    let (t, basis) = t_x("3000000001/3");
    let mut r = reduce(&t, &ReduceOptions::default()).unwrap();
    assert!(r.active_polygons().is_empty(), "{:?}", r.report);
    assert_eq!(r.report.bifaces_inactive, 2);
    r.check_invariants().unwrap();
    let separating = r
        .portalgon
        .sides()
        .filter(|&s| r.regions.is_separating(&r.portalgon, s))
        .count();
    assert!(separating > 0);
    // INSERTVERTICES splits nothing outside R_A; the other routines change nothing either.
    let before = r.clone();
    assert_eq!(r.insert_vertices().unwrap(), 0);
    assert_eq!(r.insert_edges().unwrap(), 0);
    assert_eq!(r.gardening().unwrap(), 0);
    assert_eq!(r.simplify_tubes().unwrap(), (0, 0));
    assert_eq!(r.delete_vertices().unwrap(), 0);
    assert_eq!(r.portalgon, before.portalgon);
    assert_eq!(r.regions, before.regions);
    same_lattice(&r.portalgon, &basis).unwrap();
}

#[test]
fn the_lattice_verifier_tells_lattices_apart() {
    // Index 2: ⟨(1, 0), (10, 4)⟩ inside ⟨(1, 0), (10, 2)⟩ ... and the other way round.
    let (t10, basis10) = t_x("10");
    same_lattice(&t10, &basis10).unwrap();
    let doubled = lattice_torus(&[q("1"), q("0")], &[q("10"), q("4")]);
    assert!(same_lattice(&doubled, &basis10).is_err());
    let coarse = [[q("1"), q("0")], [q("10"), q("4")]];
    assert!(same_lattice(&t10, &coarse).is_err());
    // A different basis of the same lattice passes.
    let other = [[q("1"), q("0")], [q("-3"), q("2")]];
    same_lattice(&t10, &other).unwrap();
}

/// `R²/⟨u, v⟩` cut into the `m × m` grid of parallelograms spanned by `u/m` and `v/m`, each split
/// along its `u/m → v/m` diagonal (as `generators::flat_torus`), in exact coordinates: `m²`
/// vertices, all flat.
fn refined_lattice_torus(u: &P, v: &P, m: i64) -> Portalgon<Rational> {
    let mq = Rational::from_i64(m);
    let point = |i: i64, j: i64| -> P {
        let (a, b) = (
            Rational::from_i64(i) / mq.clone(),
            Rational::from_i64(j) / mq.clone(),
        );
        [
            a.clone() * u[0].clone() + b.clone() * v[0].clone(),
            a * u[1].clone() + b * v[1].clone(),
        ]
    };
    let mut p = Portalgon::<Rational>::empty();
    let mut tri = Vec::new();
    for j in 0..m {
        for i in 0..m {
            let a = p
                .add_polygon(&[point(i, j), point(i + 1, j), point(i, j + 1)])
                .unwrap();
            let b = p
                .add_polygon(&[point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)])
                .unwrap();
            tri.push((a, b));
        }
    }
    let cell = |i: i64, j: i64| (j.rem_euclid(m) * m + i.rem_euclid(m)) as usize;
    for j in 0..m {
        for i in 0..m {
            let (a, b) = tri[cell(i, j)];
            p.glue(p.side(a, 1), p.side(b, 2), 0.0).unwrap();
            p.glue(p.side(a, 0), p.side(tri[cell(i, j - 1)].1, 1), 0.0)
                .unwrap();
            p.glue(p.side(a, 2), p.side(tri[cell(i - 1, j)].1, 0), 0.0)
                .unwrap();
        }
    }
    p
}

#[test]
fn refined_tori_lose_their_extra_vertices() {
    let cases = [
        ([[q("1"), q("0")], [q("1000"), q("2")]], 3),
        ([[q("1"), q("0")], [q("1000000"), q("1")]], 4),
        ([[q("1"), q("0")], [q("1001/3"), q("2")]], 3),
    ];
    for (basis, m) in cases {
        let t = refined_lattice_torus(&basis[0], &basis[1], m);
        let area = t.area();
        check_flat_torus(&t, &area).unwrap();
        same_lattice(&t, &basis).unwrap();
        for route in [TubeRoute::Direct, TubeRoute::Paper] {
            let r = reduce(
                &t,
                &ReduceOptions {
                    route,
                    ..ReduceOptions::default()
                },
            )
            .unwrap();
            let p = &r.portalgon;
            check_flat_torus(p, &area).unwrap();
            same_lattice(p, &basis).unwrap();
            r.check_invariants().unwrap();
            assert!(r.report.vertices_deleted > 0);
            assert!(p.polygon_count() <= 8, "m = {m}: {:?}", r.report);
        }
    }
}

#[test]
fn simplify_tubes_case_b_merges_a_concatenation_of_tubes_into_one_biface() {
    for seed in 0..4 {
        // Two copies of a random translation tube, the first's DB glued to the second's CA: an
        // annulus (not a torus: case (b)) whose middle loop joins two tubes, so J′ keeps it and J
        // drops it, and the whole annulus becomes one good biface.
        let (p, _, outer, _) = two_tubes::<Rational>(seed);
        let area = p.area();
        let all: Vec<_> = p.polygons().collect();
        let (expected, _) = p.good_biface_of_tube(&all, TubeRoute::Direct, 0.0).unwrap();
        // GARDENING: the annulus is one tube component, always marked inactive.
        let mut garden = Reduction::new(p.clone(), TubeRoute::Direct, 0.0);
        assert_eq!(garden.gardening().unwrap(), 1);
        assert!(garden.active_polygons().is_empty());
        assert_eq!(garden.portalgon.polygon_count(), 2);
        assert_eq!(garden.portalgon.area(), area);
        garden.check_invariants().unwrap();
        let mut r = Reduction::new(p, TubeRoute::Direct, 0.0);
        let (thin, thick) = r.simplify_tubes().unwrap();
        assert_eq!(thin + thick, 1, "seed {seed}");
        let q = &r.portalgon;
        assert_eq!(q.polygon_count(), 2, "seed {seed}");
        assert_eq!(q.area(), area);
        for s in outer {
            let s = r.side_of_input(s).expect("boundary sides survive");
            assert!(q.is_side_live(s) && q.mate(s).is_none(), "seed {seed}");
        }
        let mut got: Vec<Rational> = q
            .sides()
            .filter(|&s| q.mate(s).is_some())
            .map(|s| q.side_length2(s))
            .collect();
        got.sort_by(|a, b| a.partial_cmp(b).unwrap());
        got.dedup();
        let mut want = expected.biface.interior_lengths2().to_vec();
        want.sort_by(|a, b| a.partial_cmp(b).unwrap());
        want.dedup();
        assert_eq!(got, want, "seed {seed}");
        r.check_invariants().unwrap();
        // Thin bifaces become inactive, thick ones stay active.
        assert_eq!(r.active_polygons().len(), if thin == 1 { 0 } else { 2 });
    }
}
