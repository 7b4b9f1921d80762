//! Intrinsic Delaunay, Laplacian and mass on every surface kind: boundary loops, non-orientable
//! pieces, several components. Each result is checked by code written without the flip code:
//! angles by the law of cosines from the final lengths, a direct half-cotangent assembly from
//! the final triangles (each lift's share divided by the vertex's number of lifts), areas from
//! the input positions, and a dense LDLᵀ for positive semidefiniteness.

mod common;

use common::jitter;
use std::collections::HashMap;
use surftopo_intrinsic::{
    CoveredTriangulation, DEFAULT_COCIRCULAR_TOLERANCE, DelaunayInput, DelaunayOptions,
    DelaunayOutputs, DelaunayRequest, PortalgonDoc, SparseMatrix, intrinsic_delaunay,
};
use surftopo_mesh::generators::{
    annulus, copies, crosscaps, cut_holes, disk, icosphere, klein_bottle, mobius_band,
    projective_plane, random_flips_covered, subdivide_midpoint_covered, torus,
};
use surftopo_mesh::{CoveredSurface, FaceId, HalfedgeId};

/// Every kind `generate` makes, small, most of them jittered or randomly flipped.
fn surfaces() -> Vec<(&'static str, CoveredSurface)> {
    let sphere: CoveredSurface = icosphere(2).into();
    let torus: CoveredSurface = torus(8, 5).into();
    vec![
        ("disk", jitter(disk(6), 0.05, 0)),
        (
            "disk flipped",
            random_flips_covered(&jitter(disk(6), 0.02, 0), 40, 3),
        ),
        ("annulus", jitter(annulus(9, 3), 0.1, 0)),
        ("mobius band", jitter(mobius_band(9, 3), 0.1, 0)),
        (
            "mobius band flipped",
            random_flips_covered(&mobius_band(9, 3), 30, 5),
        ),
        (
            "projective plane",
            jitter(subdivide_midpoint_covered(&projective_plane(), 1), 0.05, 0),
        ),
        ("klein bottle", jitter(klein_bottle(8, 6), 0.1, 0)),
        (
            "klein bottle flipped",
            random_flips_covered(&klein_bottle(8, 6), 60, 7),
        ),
        ("N3", jitter(crosscaps(3), 0.05, 0)),
        (
            "sphere with holes",
            jitter(cut_holes(&sphere, 3, 11).0, 0.02, 0),
        ),
        (
            "torus with holes, flipped",
            random_flips_covered(&cut_holes(&torus, 2, 1).0, 30, 2),
        ),
        (
            "three pieces",
            copies(&jitter(mobius_band(7, 2), 0.1, 0), 3),
        ),
        ("closed pieces", copies(&jitter(sphere.clone(), 0.03, 0), 2)),
    ]
}

/// The interior angles of a triangle of sides `[a, b, c]`, opposite each (law of cosines).
fn angles(sides: [f64; 3]) -> [f64; 3] {
    let [a, b, c] = sides;
    let angle = |x: f64, y: f64, z: f64| {
        ((y * y + z * z - x * x) / (2.0 * y * z))
            .clamp(-1.0, 1.0)
            .acos()
    };
    [angle(a, b, c), angle(b, c, a), angle(c, a, b)]
}

/// The triangle area from three lengths (Heron, sorted).
fn heron(sides: [f64; 3]) -> f64 {
    let mut s = sides;
    s.sort_by(|x, y| y.total_cmp(x));
    let [a, b, c] = s;
    0.25 * ((a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c)))
        .max(0.0)
        .sqrt()
}

/// Whether dense `m` is positive semidefinite up to `tol` (LDLᵀ with symmetric pivoting-free
/// elimination after adding `tol` to the diagonal).
fn is_psd(m: &SparseMatrix, tol: f64) -> bool {
    let n = m.n;
    let mut a = vec![vec![0.0; n]; n];
    for (i, j, v) in m.triplets() {
        a[i as usize][j as usize] = v;
    }
    for (i, row) in a.iter_mut().enumerate() {
        row[i] += tol;
    }
    for k in 0..n {
        let p = a[k][k];
        if p < 0.0 {
            return false;
        }
        let pivot_row = a[k].clone();
        for row in a.iter_mut().skip(k + 1) {
            let f = row[k] / p;
            for (x, y) in row.iter_mut().zip(&pivot_row).skip(k) {
                *x -= f * y;
            }
        }
    }
    true
}

#[test]
fn flipping_every_surface_gives_delaunay_triangulations_and_their_laplacians() {
    for (name, s) in surfaces() {
        let area: f64 = {
            let (pos, tris) = s.to_triangles();
            tris.iter()
                .map(|t| {
                    let [p, q, r] = t.map(|v| pos[v as usize]);
                    let u = [q[0] - p[0], q[1] - p[1], q[2] - p[2]];
                    let w = [r[0] - p[0], r[1] - p[1], r[2] - p[2]];
                    let c = [
                        u[1] * w[2] - u[2] * w[1],
                        u[2] * w[0] - u[0] * w[2],
                        u[0] * w[1] - u[1] * w[0],
                    ];
                    0.5 * (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt()
                })
                .sum()
        };
        let mut tri = CoveredTriangulation::from_cover(&s.cover, &s.positions).unwrap();
        let boundary_before: Vec<(u32, f64)> = tri
            .cover()
            .mesh()
            .edges()
            .filter(|&e| tri.is_boundary_edge(e))
            .map(|e| (e.0, tri.cover().length(e)))
            .collect();
        let report = tri.flip_to_delaunay(&DelaunayOptions::default()).unwrap();
        assert_eq!(report.non_delaunay_edges, 0, "{name}");
        let cover = tri.cover();
        let mesh = cover.mesh();
        let apex = |v| tri.is_apex(v);
        let real = |f: FaceId| mesh.face_vertices(f).iter().all(|&v| !apex(v));
        let opposite = |h: HalfedgeId| {
            let f = mesh.face(h);
            let hs = mesh.face_halfedges(f);
            let i = hs.iter().position(|&g| g == h).unwrap();
            angles(hs.map(|g| cover.length(g.edge())))[i]
        };
        // Boundary edges unchanged; every interior edge Delaunay by the law of cosines.
        let boundary_after: Vec<(u32, f64)> = mesh
            .edges()
            .filter(|&e| real(mesh.face(e.halfedge())) != real(mesh.face(e.halfedge().twin())))
            .map(|e| (e.0, cover.length(e)))
            .collect();
        assert_eq!(
            boundary_before, boundary_after,
            "{name}: boundary edges changed"
        );
        let mut interior = 0;
        for e in mesh.edges() {
            let h = e.halfedge();
            if real(mesh.face(h)) && real(mesh.face(h.twin())) {
                interior += 1;
                let sum = opposite(h) + opposite(h.twin());
                assert!(
                    sum <= std::f64::consts::PI + 1e-7,
                    "{name}: edge {e:?}: {sum}"
                );
            }
        }
        assert!(interior > 0);
        // The Laplacian against a direct assembly: each real triangle of the cover gives its
        // half-cotangents, divided by the number of lifts of the row's vertex.
        let n = tri.surface_vertex_count();
        let mut lifts = vec![0usize; n];
        for v in mesh.vertices().filter(|&v| !apex(v)) {
            lifts[tri.class(v) as usize] += 1;
        }
        let mut want: HashMap<(usize, usize), f64> = HashMap::new();
        let mut mass = vec![0.0; n];
        for f in mesh.faces().filter(|&f| real(f)) {
            let hs = mesh.face_halfedges(f);
            let sides = hs.map(|g| cover.length(g.edge()));
            let ang = angles(sides);
            for (k, &h) in hs.iter().enumerate() {
                let [a, b] = [mesh.origin(h), mesh.dest(h)].map(|v| tri.class(v) as usize);
                let w = 0.5 / ang[k].tan();
                if a != b {
                    for (x, y) in [(a, b), (b, a)] {
                        let d = w / lifts[x] as f64;
                        *want.entry((x, y)).or_default() -= d;
                        *want.entry((x, x)).or_default() += d;
                    }
                }
                let v = tri.class(mesh.origin(h)) as usize;
                mass[v] += heron(sides) / 3.0 / lifts[v] as f64;
            }
        }
        let l = tri.laplacian();
        assert_eq!(l.n, n);
        let scale = want.values().fold(0.0f64, |a, v| a.max(v.abs()));
        for (i, j, v) in l.triplets() {
            let (i, j) = (i as usize, j as usize);
            let expected = want.get(&(i, j)).copied().unwrap_or(0.0);
            assert!(
                (v - expected).abs() <= 1e-9 * scale,
                "{name}: L[{i}][{j}] = {v}, {expected}"
            );
            assert_eq!(v, l.get(j, i), "{name}: not symmetric at ({i}, {j})");
        }
        for (&(i, j), &v) in &want {
            assert!(
                (l.get(i, j) - v).abs() <= 1e-9 * scale,
                "{name}: missing ({i}, {j})"
            );
        }
        for i in 0..n {
            let sum: f64 = l.row(i).map(|(_, v)| v).sum();
            assert!(sum.abs() <= 1e-9 * scale, "{name}: row {i} sums to {sum}");
        }
        if n <= 400 {
            assert!(
                is_psd(&l, 1e-9 * scale),
                "{name}: not positive semidefinite"
            );
        }
        // The mass matrix: the direct one, and its trace is the input's area (flips keep it).
        let m = tri.mass();
        let trace: f64 = (0..n).map(|i| m.get(i, i)).sum();
        assert!(
            (trace - area).abs() <= 1e-9 * area,
            "{name}: area {trace} against {area}"
        );
        for (i, &want) in mass.iter().enumerate() {
            assert!(
                (m.get(i, i) - want).abs() <= 1e-12 * area,
                "{name}: mass {i}"
            );
        }
    }
}

#[test]
fn the_laplacian_from_the_flips_cache_is_the_recomputed_one_bit_for_bit() {
    // `intrinsic_delaunay` assembles the Laplacian from the half-angle tangents flipping kept up
    // to date; `laplacian()` recomputes them from the final lengths.
    let request = DelaunayRequest {
        outputs: DelaunayOutputs {
            triangulation: true,
            laplacian: true,
            mass: true,
            ..DelaunayOutputs::default()
        },
        ..DelaunayRequest::default()
    };
    for (name, s) in surfaces() {
        let tri = CoveredTriangulation::from_cover(&s.cover, &s.positions).unwrap();
        // Taking the cover's mesh gives the same triangulation as copying it.
        let taken = CoveredTriangulation::from_surface(s.clone()).unwrap();
        assert_eq!(taken, tri, "{name}");
        // An edge may flip iff no apex is among the corners of its two faces (and they are not
        // each other's mirror).
        let mesh = tri.cover().mesh();
        for e in mesh.edges() {
            let h = e.halfedge();
            let corners = [mesh.face(h), mesh.face(h.twin())].map(|f| mesh.face_vertices(f));
            let apex = corners.iter().flatten().any(|&v| tri.is_apex(v));
            let self_mirror = tri
                .mirror(h)
                .is_some_and(|m| mesh.face(m) == mesh.face(h.twin()));
            assert_eq!(tri.may_flip(e), !apex && !self_mirror, "{name}: edge {e:?}");
        }
        let out = intrinsic_delaunay(DelaunayInput::Covered(tri), &request).unwrap();
        let flipped = out.covered.expect("the triangulation is asked for");
        assert_eq!(out.laplacian, Some(flipped.laplacian()), "{name}");
        assert_eq!(out.mass, Some(flipped.mass()), "{name}");
    }
}

#[test]
fn flips_happen_and_mirrors_flip_together() {
    // The flipped inputs need flips; on doubled pieces the count is of the surface's edges.
    let s = random_flips_covered(&klein_bottle(8, 6), 60, 7);
    let mut tri = CoveredTriangulation::from_cover(&s.cover, &s.positions).unwrap();
    let report = tri.flip_to_delaunay(&DelaunayOptions::default()).unwrap();
    assert!(report.flips > 0);
    let mesh = tri.cover().mesh();
    for h in mesh.halfedges() {
        let m = tri.mirror(h).expect("the Klein bottle is doubled");
        assert_eq!(tri.mirror(m), Some(h));
        assert_eq!(tri.cover().length(h.edge()), tri.cover().length(m.edge()));
        let ends = |g: HalfedgeId| [mesh.origin(g), mesh.dest(g)].map(|v| tri.class(v));
        let [a, b] = ends(h);
        assert_eq!(
            ends(m),
            [b, a],
            "the mirror runs the other way between the same vertices"
        );
    }
}

/// The circumcentre and radius of three points (Cramer's rule).
fn circumcircle(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> ([f64; 2], f64) {
    let (bx, by, cx, cy) = (b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]);
    let det = 2.0 * (bx * cy - by * cx);
    let (b2, c2) = (bx * bx + by * by, cx * cx + cy * cy);
    let (ux, uy) = ((cy * b2 - by * c2) / det, (bx * c2 - cx * b2) / det);
    ([a[0] + ux, a[1] + uy], ux.hypot(uy))
}

/// The angle at `c` between the directions to `a` and `b`.
fn angle_at(c: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (u, v) = ([a[0] - c[0], a[1] - c[1]], [b[0] - c[0], b[1] - c[1]]);
    (u[0] * v[1] - u[1] * v[0])
        .abs()
        .atan2(u[0] * v[0] + u[1] * v[1])
}

/// What a tessellation check found, for the tests that ask more.
struct Cells {
    /// Corner count of each polygon.
    sizes: Vec<usize>,
    /// Gluings that reverse orientation.
    reversed: usize,
    /// Each polygon's label cycle, least rotation (of both directions), sorted: the cells up
    /// to renumbering of polygons and sides.
    cycles: Vec<Vec<u32>>,
}

/// Checks the Delaunay tessellation of the flipped `tri` of `s` with code written without the
/// tessellation's: the document read back by our reader; every polygon strictly convex and
/// inscribed (corners on the circle of its first three, every triangle merged into it with that
/// circumradius, abc/4A from the flipped lengths); the polygons partition K's triangles (each
/// once, k - 2 per k-gon, equal areas); every glued pair is strictly Delaunay (the inscribed
/// angles on its two sides sum to less than π), between equal sides whose ends agree with the
/// gluing's direction; the unmatched sides are exactly K's boundary edges (ends and lengths
/// from the input); V - E + F is K's Euler characteristic.
fn check_tessellation(name: &str, s: &CoveredSurface, tri: &CoveredTriangulation) -> Cells {
    let t = tri.tessellation(DEFAULT_COCIRCULAR_TOLERANCE);
    assert_eq!(t.cycle_edges, 0, "{name}");
    let mut bytes = Vec::new();
    t.portalgon.write(&mut bytes, false).unwrap();
    let doc = PortalgonDoc::from_slice(&bytes).unwrap();
    let values = |d: &PortalgonDoc| {
        let corners = d.polygons.iter().flat_map(|p| p.corners.iter().flatten());
        corners
            .map(|c| c.clone().map(|x| x.to_f64()))
            .collect::<Vec<_>>()
    };
    assert!(
        values(&doc) == values(&t.portalgon),
        "{name}: corners read back"
    );
    assert!(doc.matching == t.portalgon.matching, "{name}: read back");
    assert!(doc.reversed == t.portalgon.reversed, "{name}: read back");
    let polygons: Vec<(Vec<[f64; 2]>, Vec<u32>)> = doc
        .polygons
        .iter()
        .map(|p| {
            let corners = p.corners.as_ref().unwrap();
            let corners = corners.iter().map(|c| [c[0].to_f64(), c[1].to_f64()]);
            (corners.collect(), p.vertices.clone().unwrap())
        })
        .collect();
    // Inscribed, convex, and the triangles merged into each share its circle.
    let cover = tri.cover();
    let mut seen = vec![0u32; cover.mesh().face_slots()];
    let mut radius = Vec::new();
    for (k, (c, _)) in polygons.iter().enumerate() {
        let n = c.len();
        assert!(n >= 3, "{name}: polygon {k}");
        let (centre, r) = circumcircle(c[0], c[1], c[2]);
        for (i, x) in c.iter().enumerate() {
            let d = (x[0] - centre[0]).hypot(x[1] - centre[1]);
            assert!((d - r).abs() <= 1e-9 * r, "{name}: polygon {k} corner {i}");
            let (a, b) = (c[(i + 1) % n], c[(i + 2) % n]);
            let turn = (a[0] - x[0]) * (b[1] - a[1]) - (a[1] - x[1]) * (b[0] - a[0]);
            assert!(turn > 0.0, "{name}: polygon {k} not convex");
        }
        let faces = t.faces_of(k);
        assert_eq!(faces.len(), n - 2, "{name}: polygon {k}");
        let mut area = 0.0;
        for &f in faces {
            seen[f.idx()] += 1;
            let [a, b, d] = cover.face_sides(f);
            let heron_area = heron([a, b, d]);
            area += heron_area;
            let circum = a * b * d / (4.0 * heron_area);
            assert!((circum - r).abs() <= 1e-8 * r, "{name}: face {f:?} in {k}");
        }
        let shoelace: f64 = (0..n)
            .map(|i| c[i][0] * c[(i + 1) % n][1] - c[(i + 1) % n][0] * c[i][1])
            .sum::<f64>()
            / 2.0;
        assert!(
            (shoelace - area).abs() <= 1e-9 * area,
            "{name}: polygon {k}"
        );
        radius.push(r);
    }
    for f in cover.mesh().faces() {
        let want = u32::from(tri.is_surface_face(f));
        assert_eq!(seen[f.idx()], want, "{name}: face {f:?}");
    }
    // Glued sides: equal, ends as the direction says, strictly Delaunay.
    let corner = |p: usize, i: usize| polygons[p].0[i % polygons[p].0.len()];
    let label = |p: usize, i: usize| polygons[p].1[i % polygons[p].1.len()];
    let side_length = |p: usize, i: usize| {
        let (a, b) = (corner(p, i), corner(p, i + 1));
        (a[0] - b[0]).hypot(a[1] - b[1])
    };
    let inscribed = |p: usize, i: usize| angle_at(corner(p, i + 2), corner(p, i), corner(p, i + 1));
    let mut matched = vec![false; polygons.iter().map(|p| p.0.len()).sum::<usize>()];
    let offset: Vec<usize> = polygons
        .iter()
        .scan(0, |acc, p| {
            let o = *acc;
            *acc += p.0.len();
            Some(o)
        })
        .collect();
    let mut reversed = 0;
    for (k, &[[p, i], [q, j]]) in doc.matching.iter().enumerate() {
        let same_way = doc.reversed.get(k).copied().unwrap_or(false);
        reversed += usize::from(same_way);
        for (x, y) in [(p, i), (q, j)] {
            assert!(!matched[offset[x] + y], "{name}: side ({x}, {y}) twice");
            matched[offset[x] + y] = true;
        }
        let ends = [label(p, i), label(p, i + 1)];
        let other = [label(q, j), label(q, j + 1)];
        let want = if same_way { ends } else { [ends[1], ends[0]] };
        assert_eq!(other, want, "{name}: pair {k}");
        let (a, b) = (side_length(p, i), side_length(q, j));
        assert!((a - b).abs() <= 1e-9 * a, "{name}: pair {k}: {a} {b}");
        let sum = inscribed(p, i) + inscribed(q, j);
        assert!(
            sum < std::f64::consts::PI,
            "{name}: pair {k} not strictly Delaunay: {sum}"
        );
    }
    // The unmatched sides are the boundary edges of the input.
    let (positions, triangles) = s.to_triangles();
    let mut count: HashMap<(u32, u32), usize> = HashMap::new();
    for t in &triangles {
        for i in 0..3 {
            let (a, b) = (t[i], t[(i + 1) % 3]);
            *count.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    let length = |a: u32, b: u32| {
        let (p, q) = (positions[a as usize], positions[b as usize]);
        ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
    };
    let mut want: Vec<(u32, u32, f64)> = count
        .iter()
        .filter(|&(_, &c)| c == 1)
        .map(|(&(a, b), _)| (a, b, length(a, b)))
        .collect();
    let mut got: Vec<(u32, u32, f64)> = Vec::new();
    for (p, poly) in polygons.iter().enumerate() {
        for i in 0..poly.0.len() {
            if !matched[offset[p] + i] {
                let (a, b) = (label(p, i), label(p, i + 1));
                got.push((a.min(b), a.max(b), side_length(p, i)));
            }
        }
    }
    want.sort_by(|x, y| x.partial_cmp(y).unwrap());
    got.sort_by(|x, y| x.partial_cmp(y).unwrap());
    assert_eq!(want.len(), got.len(), "{name}: boundary sides");
    for (w, g) in want.iter().zip(&got) {
        assert_eq!((w.0, w.1), (g.0, g.1), "{name}: boundary side");
        assert!((w.2 - g.2).abs() <= 1e-12 * w.2, "{name}: boundary length");
    }
    // Euler characteristic.
    let vertices = polygons
        .iter()
        .flat_map(|p| p.1.iter())
        .collect::<std::collections::HashSet<_>>();
    let chi_cells =
        vertices.len() as i64 - (doc.matching.len() + got.len()) as i64 + polygons.len() as i64;
    let chi = positions.len() as i64 - count.len() as i64 + triangles.len() as i64;
    assert_eq!(chi_cells, chi, "{name}: Euler characteristic");
    let mut cycles: Vec<Vec<u32>> = polygons.iter().map(|p| least_rotation(&p.1)).collect();
    cycles.sort();
    Cells {
        sizes: polygons.iter().map(|p| p.0.len()).collect(),
        reversed,
        cycles,
    }
}

/// The least rotation of a cycle or of its reverse.
fn least_rotation(cycle: &[u32]) -> Vec<u32> {
    let n = cycle.len();
    let mut reverse = cycle.to_vec();
    reverse.reverse();
    (0..n)
        .flat_map(|r| {
            [cycle, reverse.as_slice()].map(|c| (0..n).map(|i| c[(i + r) % n]).collect::<Vec<_>>())
        })
        .min()
        .unwrap()
}

#[test]
fn the_tessellation_of_every_surface_is_inscribed_strictly_delaunay_and_keeps_the_boundary() {
    let mut reversed = 0;
    for (name, s) in surfaces() {
        let mut tri = CoveredTriangulation::from_cover(&s.cover, &s.positions).unwrap();
        tri.flip_to_delaunay(&DelaunayOptions::default()).unwrap();
        let cells = check_tessellation(name, &s, &tri);
        reversed += cells.reversed;
    }
    assert!(
        reversed > 0,
        "non-orientable surfaces have reversed gluings"
    );
}

/// An `m x n` grid of squares on the vertices `id(i, j)`, the squares of the first `free`
/// columns split along a diagonal chosen by `seed` (the others from `(i, j)`), each triangle
/// listed in either orientation as `seed` says (the orientation of a triangle in a file is
/// arbitrary on a non-orientable surface).
fn grid_soup(m: u32, n: u32, free: u32, id: impl Fn(u32, u32) -> u32, seed: u64) -> Vec<[u32; 3]> {
    let mut state = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
    let mut bit = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state & 1 == 1
    };
    let mut triangles = Vec::new();
    for i in 0..m {
        for j in 0..n {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            let pair = if bit() || i >= free {
                [[a, b, c], [a, c, d]]
            } else {
                [[a, b, d], [b, c, d]]
            };
            for [x, y, z] in pair {
                triangles.push(if bit() { [x, y, z] } else { [x, z, y] });
            }
        }
    }
    triangles
}

/// The tessellation of `triangles` on `positions`, checked (see [`check_tessellation`]).
fn tessellate_soup(name: &str, positions: Vec<[f64; 3]>, triangles: &[[u32; 3]]) -> Cells {
    let (s, _) = CoveredSurface::from_triangles(positions, triangles).unwrap();
    let mut tri = CoveredTriangulation::from_cover(&s.cover, &s.positions).unwrap();
    tri.flip_to_delaunay(&DelaunayOptions::default()).unwrap();
    check_tessellation(name, &s, &tri)
}

#[test]
fn regular_grids_tessellate_into_their_squares_whatever_the_diagonals() {
    // A square of 6 x 6 unit squares: 36 squares, whichever diagonals and orientations.
    let (m, n) = (6u32, 6u32);
    let positions: Vec<[f64; 3]> = (0..=m)
        .flat_map(|i| (0..=n).map(move |j| [f64::from(i), f64::from(j), 0.0]))
        .collect();
    let mut first = None;
    for seed in 1..5 {
        let triangles = grid_soup(m, n, m, |i, j| i * (n + 1) + j, seed);
        let cells = tessellate_soup("square grid", positions.clone(), &triangles);
        assert_eq!(cells.sizes, vec![4; (m * n) as usize]);
        // The same cells from every starting triangulation (uniqueness).
        assert_eq!(*first.get_or_insert(cells.cycles.clone()), cells.cycles);
    }
    // A flat Möbius band: the strip of 12 x 3 unit squares with its ends glued with a half
    // twist, (12, j) to (0, 3 - j); in space the strip lies flat, so the squares away from the
    // seam are unit squares and the seam's are long (their diagonals fixed: another diagonal
    // there is another surface). Triangles in random orientations: the
    // cover's first sheet then changes between neighbouring triangles, and cells merge across
    // gluings that reverse orientation.
    let (m, n) = (12u32, 3u32);
    let id = |i: u32, j: u32| if i == m { n - j } else { i * (n + 1) + j };
    let positions: Vec<[f64; 3]> = (0..m)
        .flat_map(|i| (0..=n).map(move |j| [f64::from(i), f64::from(j), 0.0]))
        .collect();
    let mut first = None;
    for seed in 1..5 {
        let triangles = grid_soup(m, n, m - 1, id, seed);
        let cells = tessellate_soup("flat mobius band", positions.clone(), &triangles);
        let squares = cells.sizes.iter().filter(|&&k| k == 4).count();
        assert!(squares >= ((m - 3) * n) as usize, "{squares} squares");
        assert!(cells.reversed > 0);
        assert_eq!(*first.get_or_insert(cells.cycles.clone()), cells.cycles);
    }
}

/// Holes cut in the three smallest shared meshes and in a mid-sized one, flipped and
/// tessellated, checked.
fn tessellations_of_shared_meshes_with_holes() {
    let meshes = surftopo_testkit::shared_meshes();
    let mid = meshes.iter().find(|m| m.faces >= 4000);
    for m in meshes.iter().take(3).chain(mid) {
        let s: CoveredSurface = surftopo_testkit::load(m).into();
        let (s, cut) = cut_holes(&s, 4, 3);
        assert!(cut > 0, "{}", m.file);
        let mut tri = CoveredTriangulation::from_cover(&s.cover, &s.positions).unwrap();
        tri.flip_to_delaunay(&DelaunayOptions::default()).unwrap();
        check_tessellation(&m.file, &s, &tri);
    }
}

surftopo_testkit::shared_mesh_tests!(tessellations_of_shared_meshes_with_holes);

/// What `to_doc` writes `from_doc` reads: every kind above, re-triangulated by random
/// intrinsic flips (loops, multi-edges and triangles with a repeated vertex, which no vertex
/// numbering describes), written, read back and written again gives the same document with the
/// same mass matrix; flipped to Delaunay, the file's surface and the original give the same
/// Laplacian (rows: the labels, which are the original's vertices; the Laplacian does not
/// depend on how co-circular ties are flipped, the lumped mass does).
#[test]
fn version_2_files_read_back_to_the_surface_they_were_written_from() {
    let options = DelaunayOptions::default();
    for (name, s) in surfaces() {
        let mut tri = CoveredTriangulation::from_cover(&s.cover, &s.positions).unwrap();
        tri.random_flips(400, 9);
        let doc = tri.to_doc();
        let back = CoveredTriangulation::from_doc(&doc, 1e-9).unwrap();
        assert_eq!(back.to_doc(), doc, "{name}: written again");
        assert_eq!(back.surface_vertex_count(), tri.surface_vertex_count());
        let (ma, mb) = (tri.mass(), back.mass());
        assert_eq!(ma.triplets().count(), mb.triplets().count());
        for (x, y) in ma.triplets().zip(mb.triplets()) {
            assert!(
                x.0 == y.0 && (x.2 - y.2).abs() <= 1e-12 * x.2.abs(),
                "{name}: mass"
            );
        }
        let mut flipped = [tri, back].map(|mut t| {
            t.flip_to_delaunay(&options).unwrap();
            t
        });
        let [a, b] = &mut flipped;
        let (la, lb) = (a.laplacian(), b.laplacian());
        let scale = la.triplets().map(|t| t.2.abs()).fold(0.0, f64::max);
        let dense = |m: &SparseMatrix| {
            let mut d = HashMap::new();
            for (i, j, v) in m.triplets() {
                *d.entry((i, j)).or_insert(0.0) += v;
            }
            d
        };
        let (da, db) = (dense(&la), dense(&lb));
        for key in da.keys().chain(db.keys()) {
            let (x, y) = (da.get(key).unwrap_or(&0.0), db.get(key).unwrap_or(&0.0));
            assert!((x - y).abs() <= 1e-9 * scale, "{name}: {key:?} {x} {y}");
        }
    }
}

/// The Möbius band of PORTALGON_FORMAT.md: a unit square glued to itself with a half twist,
/// two vertices; its Laplacian has zero row sums, the cotangents of the square's right angles
/// being zero and the diagonal's two 45° angles giving it weight 1 (half of cot 45° twice).
#[test]
fn the_format_documents_mobius_band_is_read() {
    let text = r#"{"format": "surftopo-portalgon", "version": 2,
      "polygons": [
        { "corners": [[0, 0], [1, 0], [1, 1]], "vertices": [0, 1, 0] },
        { "corners": [[0, 0], [1, 1], [0, 1]], "vertices": [0, 0, 1] }],
      "matching": [ [[0, 2], [1, 0]], [[0, 1], [1, 2], true] ] }"#;
    let doc = PortalgonDoc::from_json(text).unwrap();
    let mut tri = CoveredTriangulation::from_doc(&doc, 1e-9).unwrap();
    assert_eq!(tri.surface_vertex_count(), 2);
    assert_eq!(tri.surface_faces().count(), 2);
    tri.flip_to_delaunay(&DelaunayOptions::default()).unwrap();
    let mut l = [[0.0; 2]; 2];
    for (i, j, v) in tri.laplacian().triplets() {
        l[i as usize][j as usize] += v;
    }
    for row in l {
        assert!((row[0] + row[1]).abs() < 1e-12, "{l:?}");
    }
    let area: f64 = (0..2)
        .map(|v| tri.mass().triplets().nth(v).unwrap().2)
        .sum();
    assert!((area - 1.0).abs() < 1e-12);
    // The square as one polygon, its right side glued to its left with the half twist: cut
    // into two triangles, the same surface (the same Laplacian: both diagonals are Delaunay).
    let square = r#"{"version": 2,
      "polygons": [ { "corners": [[0, 0], [1, 0], [1, 1], [0, 1]] } ],
      "matching": [ [[0, 1], [0, 3], true] ] }"#;
    let mut one =
        CoveredTriangulation::from_doc(&PortalgonDoc::from_json(square).unwrap(), 1e-9).unwrap();
    assert_eq!(one.surface_faces().count(), 2);
    one.flip_to_delaunay(&DelaunayOptions::default()).unwrap();
    let mut m = [[0.0; 2]; 2];
    for (i, j, v) in one.laplacian().triplets() {
        m[i as usize][j as usize] += v;
    }
    for i in 0..2 {
        for j in 0..2 {
            assert!((m[i][j] - l[i][j]).abs() < 1e-12, "{m:?} {l:?}");
        }
    }
    // A side of the square glued to a side of another length is named by the file's polygon.
    let unequal = square
        .replace("[[0, 1], [0, 3], true]", "[[0, 0], [0, 3], true]")
        .replace("[1, 0], [1, 1], [0, 1]", "[2, 0], [2, 1], [0, 1]");
    let e = CoveredTriangulation::from_doc(&PortalgonDoc::from_json(&unequal).unwrap(), 1e-9)
        .unwrap_err();
    assert!(e.to_string().contains("(0, 0) and (0, 3)"), "{e}");
    // The same file as version 1 is refused where the reversed gluing is.
    let v1 = text.replace("\"version\": 2", "\"version\": 1");
    assert!(PortalgonDoc::from_json(&v1).is_err());
}
