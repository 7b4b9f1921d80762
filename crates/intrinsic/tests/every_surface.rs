//! Intrinsic Delaunay, Laplacian and mass on every surface kind: boundary loops, non-orientable
//! pieces, several components. Each result is checked by code written without the flip code:
//! angles by the law of cosines from the final lengths, a direct half-cotangent assembly from
//! the final triangles (each lift's share divided by the vertex's number of lifts), areas from
//! the input positions, and a dense LDLᵀ for positive semidefiniteness.

use std::collections::HashMap;
use surftopo_intrinsic::{CoveredTriangulation, DelaunayOptions, SparseMatrix};
use surftopo_mesh::generators::{
    annulus, copies, crosscaps, cut_holes, disk, icosphere, klein_bottle, mobius_band,
    projective_plane, random_flips_covered, subdivide_midpoint_covered, torus,
};
use surftopo_mesh::{CoveredSurface, FaceId, HalfedgeId};

/// Moves every vertex by a deterministic pseudo-random offset of relative size `amount`, so
/// the input is not Delaunay.
fn jitter(mut s: CoveredSurface, amount: f64) -> CoveredSurface {
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    for p in &mut s.positions {
        for x in p.iter_mut() {
            *x += amount * next();
        }
    }
    s
}

/// Every kind `generate` makes, small, most of them jittered or randomly flipped.
fn surfaces() -> Vec<(&'static str, CoveredSurface)> {
    let sphere: CoveredSurface = icosphere(2).into();
    let torus: CoveredSurface = torus(8, 5).into();
    vec![
        ("disk", jitter(disk(6), 0.05)),
        (
            "disk flipped",
            random_flips_covered(&jitter(disk(6), 0.02), 40, 3),
        ),
        ("annulus", jitter(annulus(9, 3), 0.1)),
        ("mobius band", jitter(mobius_band(9, 3), 0.1)),
        (
            "mobius band flipped",
            random_flips_covered(&mobius_band(9, 3), 30, 5),
        ),
        (
            "projective plane",
            jitter(subdivide_midpoint_covered(&projective_plane(), 1), 0.05),
        ),
        ("klein bottle", jitter(klein_bottle(8, 6), 0.1)),
        (
            "klein bottle flipped",
            random_flips_covered(&klein_bottle(8, 6), 60, 7),
        ),
        ("N3", jitter(crosscaps(3), 0.05)),
        (
            "sphere with holes",
            jitter(cut_holes(&sphere, 3, 11).0, 0.02),
        ),
        (
            "torus with holes, flipped",
            random_flips_covered(&cut_holes(&torus, 2, 1).0, 30, 2),
        ),
        ("three pieces", copies(&jitter(mobius_band(7, 2), 0.1), 3)),
        ("closed pieces", copies(&jitter(sphere.clone(), 0.03), 2)),
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
