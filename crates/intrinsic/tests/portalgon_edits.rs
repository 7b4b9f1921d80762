//! The portalgon edits of Dubois' Sections 4.1–4.3 and Appendix B (`portalgon_edits.rs`): side
//! splits, components, weak and strong vertices, splices. After every edit
//! `Portalgon::check_invariants` holds and the surface is unchanged: exact area, the cone angles
//! (by an independent vertex identification and `atan2`), the boundary.

mod common_tubes;

use common_tubes::{RandomTube, random_tube, two_tubes};
use surftopo_intrinsic::geometry::{Rational, Scalar, cross, dot, sub};
use surftopo_intrinsic::{EditError, Portalgon, SideId, TubeRoute};

fn ri(v: i64) -> Rational {
    Rational::from_i64(v)
}

/// Per vertex (start corners identified through matched sides, by a union–find written here),
/// its angle; sorted, with a flag for boundary vertices.
fn cone_angles<S: Scalar>(p: &Portalgon<S>) -> Vec<(bool, f64)> {
    let n = p.side_slots();
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(parent: &mut [usize], mut x: usize) -> usize {
        while parent[x] != x {
            x = parent[x];
        }
        x
    }
    for s in p.sides() {
        if let Some(t) = p.mate(s) {
            let (a, b) = (
                find(&mut parent, s.idx()),
                find(&mut parent, p.next_side(t).idx()),
            );
            parent[a.max(b)] = a.min(b);
        }
    }
    let mut angle = vec![0.0; n];
    let mut boundary = vec![false; n];
    for s in p.sides() {
        let (o, u, w) = (p.start_ref(s), p.end_ref(s), p.start_ref(p.prev_side(s)));
        let (du, dw) = (sub(u, o), sub(w, o));
        let v = find(&mut parent, s.idx());
        angle[v] += cross(&du, &dw).to_f64().atan2(dot(&du, &dw).to_f64());
        if p.mate(s).is_none() {
            boundary[v] = true;
            let e = find(&mut parent, p.next_side(s).idx());
            boundary[e] = true;
        }
    }
    let mut out: Vec<(bool, f64)> = p
        .sides()
        .filter(|s| find(&mut parent, s.idx()) == s.idx())
        .map(|s| (boundary[s.idx()], angle[s.idx()]))
        .collect();
    out.sort_by(|a, b| a.partial_cmp(b).unwrap());
    out
}

/// The squared lengths of the unmatched sides, sorted.
fn boundary_lengths2(p: &Portalgon<Rational>) -> Vec<Rational> {
    let mut l: Vec<Rational> = p.unmatched_sides().map(|s| p.side_length2(s)).collect();
    l.sort();
    l
}

fn same_angles(a: &[(bool, f64)], b: &[(bool, f64)]) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(x, y)| x.0 == y.0 && (x.1 - y.1).abs() <= 1e-12 * x.1.max(1.0))
}

#[test]
fn splitting_sides_keeps_the_surface() {
    let tube: RandomTube<Rational> = random_tube(5, true, 2, 5);
    let mut p = tube.portalgon.clone();
    let (area, angles, boundary) = (p.area(), cone_angles(&p), boundary_lengths2(&p));
    let matched: Vec<SideId> = p
        .sides()
        .filter(|&s| p.mate(s).is_some_and(|t| s < t))
        .collect();
    let third = Rational::new(1, 3).unwrap();
    let full = std::f64::consts::TAU;
    for (k, &s) in matched.iter().enumerate() {
        let before = cone_angles(&p).len();
        let lambda = if k % 2 == 0 {
            ri(1).half()
        } else {
            third.clone()
        };
        let t = p.mate(s).unwrap();
        let (l_s, l_t) = (p.side_length2(s), p.side_length2(t));
        let (s2, t2) = p.split_side(s, &lambda).unwrap();
        let t2 = t2.unwrap();
        p.check_invariants().unwrap();
        assert_eq!(p.area(), area);
        assert_eq!((p.mate(s), p.mate(s2)), (Some(t2), Some(t)));
        // The halves have the lengths λ|s| and (1 − λ)|s| on both copies.
        let l = lambda.clone() * lambda.clone();
        let m = (ri(1) - lambda.clone()) * (ri(1) - lambda.clone());
        assert_eq!(
            (p.side_length2(s), p.side_length2(t2)),
            (l.clone() * l_s.clone(), l * l_t.clone())
        );
        assert_eq!(
            (p.side_length2(s2), p.side_length2(t)),
            (m.clone() * l_s, m * l_t)
        );
        let now = cone_angles(&p);
        assert_eq!(now.len(), before + 1, "one new vertex");
        assert!(
            now.iter()
                .filter(|x| !x.0)
                .all(|x| (x.1 - full).abs() < 1e-12)
        );
        assert_eq!(boundary_lengths2(&p), boundary);
    }
    // The old vertices kept their angles: the boundary ones are the same two.
    let now = cone_angles(&p);
    let old_boundary: Vec<_> = angles.iter().filter(|x| x.0).collect();
    let new_boundary: Vec<_> = now.iter().filter(|x| x.0).collect();
    assert_eq!(old_boundary.len(), new_boundary.len());
    assert!(
        old_boundary
            .iter()
            .zip(&new_boundary)
            .all(|(a, b)| (a.1 - b.1).abs() < 1e-12)
    );
    // A boundary side splits alone: one more boundary side, the same boundary length.
    let beta = tube.boundary[0];
    let before: f64 = p.unmatched_sides().map(|s| p.side_length(s)).sum();
    let (b2, none) = p.split_side(beta, &third).unwrap();
    p.check_invariants().unwrap();
    assert!(none.is_none() && p.mate(b2).is_none());
    let after: f64 = p.unmatched_sides().map(|s| p.side_length(s)).sum();
    assert!((before - after).abs() < 1e-12 * before);
    assert_eq!(p.area(), area);
    // Bad parameters and sides are refused.
    assert!(matches!(
        p.split_side(beta, &ri(0)),
        Err(EditError::SplitParameter { .. })
    ));
    assert!(matches!(
        p.split_side(beta, &ri(1)),
        Err(EditError::SplitParameter { .. })
    ));
    assert!(matches!(
        p.split_side(SideId(1 << 30), &third),
        Err(EditError::NoSuchSide(_))
    ));
}

/// `T_x` closed (Section 9): Δ₁ = (0,0),(1,0),(x,2), Δ₂ = (1+x,2),(x,2),(1,0), side i to side i.
fn t_x(x: i64) -> Portalgon<Rational> {
    let mut p = Portalgon::<Rational>::empty();
    let d1 = p
        .add_polygon(&[[ri(0), ri(0)], [ri(1), ri(0)], [ri(x), ri(2)]])
        .unwrap();
    let d2 = p
        .add_polygon(&[[ri(1 + x), ri(2)], [ri(x), ri(2)], [ri(1), ri(0)]])
        .unwrap();
    for i in 0..3 {
        p.glue(p.side(d1, i), p.side(d2, i), 0.0).unwrap();
    }
    p
}

#[test]
fn components_euler_characteristic_and_vertex_kinds() {
    // T_3: one component, χ = 0, no boundary, one vertex, strong (on loops), degree 6.
    let torus = t_x(3);
    let all: Vec<_> = torus.polygons().collect();
    let c = torus.components(&all).unwrap();
    assert_eq!(c.len(), 1);
    assert_eq!(
        (c[0].vertices, c[0].edges, c[0].euler_characteristic),
        (1, 3, 0)
    );
    assert!(c[0].boundary_cycles.is_empty());
    assert_eq!(c[0].interior_vertices.len(), 1);
    let info = torus.vertex_info();
    assert_eq!(
        (
            info.count(),
            info.degree[0],
            info.interior[0],
            info.on_loop[0]
        ),
        (1, 6, true, true)
    );
    assert!(!info.is_weak(0));
    // One triangle of it: a disk whose boundary is its three sides (χ = 3 − 3 + 1).
    let one = torus.components(&all[..1]).unwrap();
    assert_eq!(one[0].euler_characteristic, 1);
    assert_eq!(one[0].boundary_cycles.len(), 1);
    assert_eq!(one[0].boundary_cycles[0].len(), 3);
    assert!(torus.components(&[all[0], all[0]]).is_err());

    // A random tube: an annulus, two single-side boundary cycles, its interior vertices.
    for seed in 0..8 {
        let tube: RandomTube<Rational> = random_tube(seed, seed % 2 == 0, 3, 4);
        let p = &tube.portalgon;
        let polygons: Vec<_> = p.polygons().collect();
        let c = p.components(&polygons).unwrap();
        assert_eq!(c.len(), 1);
        assert!(c[0].is_annulus_with_single_side_boundaries());
        let mut boundary = tube.boundary;
        boundary.sort();
        assert_eq!(
            c[0].boundary_cycles,
            vec![vec![boundary[0]], vec![boundary[1]]]
        );
        assert_eq!(c[0].interior_vertices.len(), tube.interior_vertices);
        let info = p.vertex_info();
        assert_eq!(info.count(), tube.interior_vertices + 2);
        assert_eq!(info.interior.iter().filter(|x| !**x).count(), 2);
        // Weak: interior and no side from the vertex to itself (checked on the sides here).
        for v in 0..info.count() {
            let on_loop = p.sides().any(|s| {
                info.class[s.idx()] as usize == v && info.class[p.next_side(s).idx()] as usize == v
            });
            assert_eq!(info.is_weak(v), info.interior[v] && !on_loop);
            let sides_at = p
                .sides()
                .filter(|s| info.class[s.idx()] as usize == v)
                .count();
            let extra = if info.interior[v] { 0 } else { 1 };
            assert_eq!(info.degree[v] as usize, sides_at + extra);
        }
        assert!(p.tube(&polygons, 0.0).is_ok());
        // Without one triangle it is no longer a tube.
        assert!(p.tube(&polygons[1..], 0.0).is_err());
    }
}

#[test]
fn splicing_a_good_biface_keeps_the_surface_and_the_boundary_ids() {
    for seed in 0..6 {
        let (mut p, first, ends, joint) = two_tubes::<Rational>(seed);
        p.check_invariants().unwrap();
        let (area, angles, boundary) = (p.area(), cone_angles(&p), boundary_lengths2(&p));
        let all: Vec<_> = p.polygons().collect();
        assert!(p.tube(&all, 0.0).is_ok(), "two tubes glued make a tube");
        let (_, good, _) = p
            .replace_tube_by_good_biface(&first, TubeRoute::Direct, 0.0)
            .unwrap();
        p.check_invariants().unwrap();
        assert!(good.biface.is_good().unwrap());
        assert_eq!(p.area(), area);
        assert_eq!(boundary_lengths2(&p), boundary);
        // The interior vertices of the first tube are gone; the others kept their angles.
        let now = cone_angles(&p);
        let full = std::f64::consts::TAU;
        assert!(
            now.iter()
                .filter(|x| !x.0)
                .all(|x| (x.1 - full).abs() < 1e-12)
        );
        assert!(same_angles(
            &angles.iter().filter(|x| x.0).copied().collect::<Vec<_>>(),
            &now.iter().filter(|x| x.0).copied().collect::<Vec<_>>()
        ));
        // The glued side and the outer boundary sides keep their ids and their mates.
        assert!(p.is_side_live(joint) && p.mate(joint).is_some());
        assert!(
            ends.iter()
                .all(|&s| p.is_side_live(s) && p.mate(s).is_none())
        );
        // Still a tube; Proposition 4 on the whole.
        let all: Vec<_> = p.polygons().collect();
        let (whole, _) = p.good_biface_of_tube(&all, TubeRoute::Paper, 0.0).unwrap();
        assert_eq!(whole.biface.twice_area(), area.clone() + area);
    }
}

#[test]
fn splice_refuses_a_wrong_boundary() {
    let (mut p, first, ends, joint) = two_tubes::<Rational>(1);
    let tube = p.tube(&first, 0.0).unwrap();
    let (good, _) = p
        .good_biface_of_tube(&first, TubeRoute::Direct, 0.0)
        .unwrap();
    let (biface, [ca, db]) = surftopo_intrinsic::biface_portalgon(&good.biface, [0, 1]);
    let before = p.clone();
    // Too few pairs, a side that is not on the boundary, sides out of order.
    for pairs in [
        vec![(ca, tube.boundary[0])],
        vec![(ca, tube.boundary[0]), (db, p.side(first[0], 0))],
        vec![(ca, ends[1]), (db, joint)],
    ] {
        assert!(matches!(
            p.splice(&first, &biface, &pairs, 0.0),
            Err(EditError::Boundary(_))
        ));
        assert_eq!(p, before, "a refused splice changes nothing");
    }
}

#[test]
fn vertex_info_within_a_subset_treats_sides_matched_outside_as_boundary() {
    let p = t_x(10);
    let all: Vec<_> = p.polygons().collect();
    assert_eq!(p.vertex_info_within(&all).unwrap(), p.vertex_info());
    // One triangle of T_10: its sides are all matched to the other one, so its surface is a
    // triangle: three boundary vertices of degree 2, no loop; the other triangle's sides have no
    // class.
    let info = p.vertex_info_within(&all[..1]).unwrap();
    assert_eq!(info.count(), 3);
    assert_eq!(info.degree, vec![2, 2, 2]);
    assert!(info.interior.iter().all(|&i| !i));
    assert!(info.on_loop.iter().all(|&l| !l));
    for &s in p.polygon_sides(all[1]) {
        assert_eq!(info.class[s.idx()], u32::MAX);
    }
    // The whole T_10: one vertex, interior, on loops, degree 6.
    let whole = p.vertex_info();
    assert_eq!(
        (
            whole.count(),
            whole.degree[0],
            whole.interior[0],
            whole.on_loop[0]
        ),
        (1, 6, true, true)
    );
    assert!(matches!(
        p.vertex_info_within(&[all[0], all[0]]),
        Err(EditError::NoSuchPolygon(_))
    ));
}

/// What [`Portalgon::components`] says of a component, without ids: vertices, edges, χ, the
/// lengths of its boundary cycles, its interior vertices and polygons counted.
fn shape(c: &surftopo_intrinsic::Component) -> (usize, usize, i64, Vec<usize>, usize, usize) {
    let cycles = c.boundary_cycles.iter().map(Vec::len).collect();
    (
        c.vertices,
        c.edges,
        c.euler_characteristic,
        cycles,
        c.interior_vertices.len(),
        c.polygons.len(),
    )
}

#[test]
fn components_of_a_subset_match_those_of_its_copy() {
    // Random subsets of random tubes, small (the set searched by id) and large (indexed per
    // slot): the components must be those of the subset copied into a portalgon of its own.
    for seed in 0..12 {
        let tube: RandomTube<Rational> = random_tube(seed, seed % 3 == 0, 4, 12);
        let p = &tube.portalgon;
        let all: Vec<_> = p.polygons().collect();
        for keep in [5, 50, 95] {
            let subset: Vec<_> = all
                .iter()
                .copied()
                .enumerate()
                .filter(|(i, _)| (i * 7919 + seed as usize * 31) % 100 < keep)
                .map(|(_, q)| q)
                .collect();
            let ours = p.components(&subset).unwrap();
            let (copy, _) = p.sub_portalgon(&subset);
            let theirs = copy
                .components(&copy.polygons().collect::<Vec<_>>())
                .unwrap();
            let mut a: Vec<_> = ours.iter().map(shape).collect();
            let mut b: Vec<_> = theirs.iter().map(shape).collect();
            a.sort();
            b.sort();
            assert_eq!(a, b, "seed {seed}, {keep}%");
            // The two-sided ones are those with two boundary sides in all, in the same order.
            let two_sided: Vec<_> = ours
                .iter()
                .filter(|c| c.boundary_cycles.iter().map(Vec::len).sum::<usize>() == 2)
                .cloned()
                .collect();
            assert_eq!(p.two_sided_components(&subset).unwrap(), two_sided);
        }
        // The whole tube is one two-sided component.
        assert_eq!(p.two_sided_components(&all).unwrap().len(), 1);
        assert!(p.two_sided_components(&[all[0], all[0]]).is_err());
    }
}

#[test]
fn compaction_keeps_the_surface_and_the_order_of_ids() {
    for seed in 0..6 {
        let (mut p, first, ends, joint) = two_tubes::<Rational>(seed);
        p.replace_tube_by_good_biface(&first, TubeRoute::Direct, 0.0)
            .unwrap();
        assert!(
            p.side_slots() > p.side_count(),
            "the splice left tombstones"
        );
        let before = p.clone();
        let mut regions = surftopo_intrinsic::Regions::new(&p);
        let live: Vec<_> = p.polygons().collect();
        let marked = regions.new_region();
        regions.assign(live[live.len() / 2], marked);
        let (sides, polygons) = p.compact_in_place();
        regions.renumber(&polygons);
        p.check_invariants().unwrap();
        assert_eq!(p.side_slots(), p.side_count());
        assert_eq!(p.polygon_slots(), p.polygon_count());
        assert_eq!(
            (p.side_count(), p.polygon_count()),
            (before.side_count(), before.polygon_count())
        );
        assert_eq!(p.area(), before.area());
        assert!(same_angles(&cone_angles(&p), &cone_angles(&before)));
        // Live ids keep their order; corners, labels and mates follow their sides.
        let mapped: Vec<SideId> = before.sides().map(|s| sides[s.idx()]).collect();
        assert!(mapped.windows(2).all(|w| w[0] < w[1]));
        for s in before.sides() {
            let n = sides[s.idx()];
            assert_eq!(p.start(n), before.start(s));
            assert_eq!(p.vertex_label(n), before.vertex_label(s));
            assert_eq!(p.mate(n), before.mate(s).map(|t| sides[t.idx()]));
        }
        for q in before.polygons() {
            let n = polygons[q.idx()];
            assert_eq!(regions.region(n), u32::from(q == live[live.len() / 2]));
        }
        for s in ends.into_iter().chain([joint]) {
            assert!(sides[s.idx()].is_valid());
        }
    }
}
