//! The tufted-cover Laplacian (Sharp & Crane 2020) against independent checks:
//! - on soups of acute triangles the cover is Delaunay as built (every glued pair of opposite
//!   angles sums below π), and the folded Laplacian is then the plain per-face cotan formula
//!   `L_ij = -Σ cot(opposite angle) / 2` over the faces holding edge ij, with the barycentric mass:
//!   computed here from the 3D coordinates with dot and cross products;
//! - on closed manifold meshes the cover is two copies of the surface: the result equals the
//!   intrinsic Delaunay Laplacian and mass of the surface (1e-12 relative);
//! - on any soup (obtuse, random, non-manifold): symmetric, zero row sums, non-positive
//!   off-diagonal entries, diagonally dominant (so positive semidefinite by Gershgorin), the mass
//!   summing to the area;
//! - bad input: typed errors naming the face or vertex.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::HashMap;
use surftopo_intrinsic::{
    DEFAULT_MOLLIFY_FACTOR, DelaunayOptions, GeometryError, IntrinsicTriangulation, SparseMatrix,
    TuftedError, TuftedOptions, intrinsic_delaunay_laplacian, lumped_mass, tufted_laplacian,
};
use surftopo_mesh::BuildError;
use surftopo_mesh::generators::{icosphere, random_flips, torus};

type P = [f64; 3];
/// A named soup: positions and triangles.
type Soup = (&'static str, Vec<P>, Vec<[u32; 3]>);

fn sub(a: P, b: P) -> P {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: P, b: P) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross_norm(a: P, b: P) -> f64 {
    let c = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    dot(c, c).sqrt()
}

/// The per-face cotan Laplacian and barycentric mass, as dense maps.
fn per_face_cotan(p: &[P], tris: &[[u32; 3]]) -> (HashMap<(usize, usize), f64>, Vec<f64>) {
    let mut l = HashMap::new();
    let mut m = vec![0.0; p.len()];
    for t in tris {
        let [a, b, c] = t.map(|v| v as usize);
        for (i, j, k) in [(a, b, c), (b, c, a), (c, a, b)] {
            // The angle at k, opposite edge ij.
            let (u, v) = (sub(p[i], p[k]), sub(p[j], p[k]));
            let w = 0.5 * dot(u, v) / cross_norm(u, v);
            *l.entry((i, j)).or_insert(0.0) -= w;
            *l.entry((j, i)).or_insert(0.0) -= w;
            *l.entry((i, i)).or_insert(0.0) += w;
            *l.entry((j, j)).or_insert(0.0) += w;
        }
        let area = 0.5 * cross_norm(sub(p[b], p[a]), sub(p[c], p[a]));
        for v in [a, b, c] {
            m[v] += area / 3.0;
        }
    }
    (l, m)
}

fn entries(m: &SparseMatrix) -> HashMap<(usize, usize), f64> {
    m.triplets()
        .map(|(i, j, v)| ((i as usize, j as usize), v))
        .collect()
}

fn scale(m: &SparseMatrix) -> f64 {
    m.values.iter().fold(1e-300f64, |a, v| a.max(v.abs()))
}

/// Entry by entry to `tol` relative to the largest entry (absent entries are 0).
fn assert_close(
    ours: &HashMap<(usize, usize), f64>,
    want: &HashMap<(usize, usize), f64>,
    s: f64,
    tol: f64,
    what: &str,
) {
    for key in ours.keys().chain(want.keys()) {
        let (a, b) = (
            ours.get(key).copied().unwrap_or(0.0),
            want.get(key).copied().unwrap_or(0.0),
        );
        assert!(
            (a - b).abs() <= tol * s,
            "{what}: entry {key:?} is {a}, expected {b}"
        );
    }
}

/// Symmetric, zero row sums, non-positive off the diagonal up to `tol`, diagonally dominant.
fn check_laplacian_properties(l: &SparseMatrix, what: &str) {
    let s = scale(l);
    let e = entries(l);
    for (&(i, j), &v) in &e {
        let t = e.get(&(j, i)).copied().unwrap_or(0.0);
        assert!(
            (v - t).abs() <= 1e-12 * s,
            "{what}: L[{i}][{j}] = {v}, L[{j}][{i}] = {t}"
        );
        if i != j {
            assert!(v <= 1e-9 * s, "{what}: off-diagonal L[{i}][{j}] = {v} > 0");
        }
    }
    for i in 0..l.n {
        let (mut sum, mut off) = (0.0, 0.0);
        for (j, v) in l.row(i) {
            sum += v;
            if j as usize != i {
                off += v.abs();
            }
        }
        assert!(
            sum.abs() <= 1e-12 * s * (1.0 + off / s),
            "{what}: row {i} sums to {sum}"
        );
        assert!(
            l.get(i, i) >= off - 1e-9 * s,
            "{what}: row {i} is not diagonally dominant"
        );
    }
}

fn tufted(p: &[P], t: &[[u32; 3]]) -> surftopo_intrinsic::TuftedLaplacian {
    tufted_laplacian(p, t, &TuftedOptions::default()).unwrap()
}

/// An equilateral-ish acute triangle's apex around the x axis at angle `a`.
fn around_x(a: f64, r: f64) -> P {
    [0.5, r * a.cos(), r * a.sin()]
}

/// Soups of acute triangles: fins, books, pinched vertices, duplicate faces, pieces, unreferenced
/// vertices.
fn acute_soups() -> Vec<Soup> {
    let mut cases = Vec::new();
    // One triangle: three fins.
    cases.push((
        "triangle",
        vec![[0.0, 0.0, 0.0], [1.0, 0.1, 0.0], [0.4, 0.9, 0.0]],
        vec![[0, 1, 2]],
    ));
    // Books of 3, 4 and 7 pages on the edge (0, 0, 0)-(1, 0, 0), unevenly spread, mixed orientations.
    for pages in [3usize, 4, 7] {
        let mut p = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]];
        let mut t = Vec::new();
        for k in 0..pages {
            let a = 0.3 + 5.5 * (k as f64).powf(1.1) / pages as f64;
            p.push(around_x(a, 0.8 + 0.05 * k as f64));
            let v = (k + 2) as u32;
            t.push(if k % 2 == 0 { [0, 1, v] } else { [1, 0, v] });
        }
        cases.push(("book", p, t));
    }
    // A regular tetrahedron and another one pinched to it at a vertex, with an unreferenced vertex
    // between them and a duplicate face.
    let s = 1.0 / 2f64.sqrt();
    let tet = [
        [1.0, 0.0, -s],
        [-1.0, 0.0, -s],
        [0.0, 1.0, s],
        [0.0, -1.0, s],
    ];
    let mut p: Vec<P> = tet.to_vec();
    p.push([9.0, 9.0, 9.0]); // unreferenced
    // The second one: the first reflected through vertex 0 (a point reflection keeps it regular).
    p.extend(
        tet[1..]
            .iter()
            .map(|q| [0, 1, 2].map(|c| 2.0 * tet[0][c] - q[c])),
    );
    let faces = [[0u32, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    let mut t: Vec<[u32; 3]> = faces.to_vec();
    let map = |v: u32| if v == 0 { 0 } else { v + 4 }; // vertex 0 is shared: a pinch
    t.extend(faces.iter().map(|f| f.map(map)));
    t.push([1, 3, 2]); // a duplicate of face [1, 2, 3], reversed
    cases.push(("pinched tetrahedra", p, t));
    // Two pieces and a doubled triangle.
    cases.push((
        "pieces",
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.5, 0.8, 0.0],
            [3.0, 0.0, 1.0],
            [4.0, 0.2, 1.0],
            [3.4, 1.0, 1.3],
        ],
        vec![[0, 1, 2], [3, 4, 5], [3, 5, 4], [0, 1, 2]],
    ));
    cases
}

#[test]
fn acute_soups_give_the_per_face_cotan_laplacian_without_flips() {
    for (name, p, t) in acute_soups() {
        let out = tufted(&p, &t);
        assert_eq!(
            out.report.flips, 0,
            "{name}: the cover of acute triangles is Delaunay"
        );
        assert_eq!(out.report.mollify_delta, 0.0, "{name}");
        assert_eq!(out.report.cover_faces, 2 * t.len());
        let (l, m) = per_face_cotan(&p, &t);
        let s = l.values().fold(0f64, |a, v| a.max(v.abs()));
        assert_close(&entries(&out.laplacian), &l, s, 1e-12, name);
        for (i, &want) in m.iter().enumerate() {
            let got = out.mass.get(i, i);
            assert!(
                (got - want).abs() <= 1e-12 * want.max(1.0),
                "{name}: mass {i}: {got} vs {want}"
            );
        }
        check_laplacian_properties(&out.laplacian, name);
    }
}

#[test]
fn the_cover_splits_pinched_vertices_and_counts_fins_and_books() {
    let soups = acute_soups();
    let (_, p, t) = &soups[4];
    let r = tufted(p, t).report;
    // Two tetrahedra, each covered twice, plus the duplicate face's two sides glued into the
    // first tetrahedron's book edges: 12 distinct edges, 3 books (the duplicate's edges).
    assert_eq!(
        (r.vertices, r.faces, r.edges, r.book_edges, r.fin_edges),
        (8, 9, 12, 3, 0)
    );
    assert_eq!(r.cover_faces, 18);
    assert_eq!(r.cover_edges, 27);
    // The pinched vertex 0 has a fan on each tetrahedron on each sheet.
    let (_, p, t) = &soups[0];
    let r = tufted(p, t).report;
    assert_eq!((r.fin_edges, r.cover_vertices, r.cover_edges), (3, 3, 3));
}

/// Random positions for a closed mesh's vertices and random flips: a non-Delaunay input.
fn closed_meshes() -> Vec<(String, Vec<P>, Vec<[u32; 3]>)> {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let mut out = Vec::new();
    for (name, s) in [("icosphere", icosphere(2)), ("torus", torus(8, 5))] {
        let s = random_flips(&s, 60, 3);
        let mut p = s.positions.clone();
        for q in &mut p {
            for c in q.iter_mut() {
                *c += rng.random_range(-0.05..0.05);
            }
        }
        let t: Vec<[u32; 3]> = s
            .mesh
            .faces()
            .map(|f| s.mesh.face_vertices(f).map(|v| v.0))
            .collect();
        out.push((name.to_string(), p, t));
    }
    out
}

/// On a closed oriented manifold the tufted Laplacian and mass are the surface's own.
///
/// The lumped mass of a Delaunay triangulation depends on which one is taken where four or more
/// vertices are co-circular (the Laplacian does not: Bobenko & Springborn); the cover's copies
/// and the surface, flipped in different orders, may take different ones. So with `generic`
/// (jittered positions: no co-circular quads) the mass is compared entry by entry, else its
/// trace (the area).
fn equals_plain_intrinsic_delaunay(name: &str, p: &[P], t: &[[u32; 3]], generic: bool) {
    let out = tufted(p, t);
    let (mut tri, report) = IntrinsicTriangulation::from_soup(p, t).unwrap();
    assert!(report.dropped_vertices.is_empty(), "{name}");
    // Mollified as the tufted cover is (robust_laplacian's default factor, the same mean edge).
    let options = DelaunayOptions {
        mollify: Some(DEFAULT_MOLLIFY_FACTOR),
        ..DelaunayOptions::default()
    };
    let (flips, l) = intrinsic_delaunay_laplacian(&mut tri, &options).unwrap();
    let m = lumped_mass(&tri);
    // Vertex ids are input indices (none dropped).
    let rows: Vec<u32> = tri.matrix_rows();
    assert!(
        rows.iter().enumerate().all(|(i, &r)| r as usize == i),
        "{name}"
    );
    assert_eq!(out.report.cover_vertices, 2 * p.len(), "{name}: two copies");
    assert_eq!(
        out.report.mollify_delta,
        flips.mollify_delta.unwrap(),
        "{name}"
    );
    assert_close(
        &entries(&out.laplacian),
        &entries(&l),
        scale(&l),
        1e-12,
        name,
    );
    if generic {
        assert_close(&entries(&out.mass), &entries(&m), scale(&m), 1e-12, name);
    } else {
        let trace = |m: &SparseMatrix| (0..m.n).map(|i| m.get(i, i)).sum::<f64>();
        let (a, b) = (trace(&out.mass), trace(&m));
        assert!((a - b).abs() <= 1e-12 * b, "{name}: mass trace {a}, {b}");
    }
}

#[test]
fn closed_manifolds_give_the_intrinsic_delaunay_laplacian() {
    for (name, p, t) in closed_meshes() {
        equals_plain_intrinsic_delaunay(&name, &p, &t, true);
    }
}

/// A random soup: faces on random triples of few points (non-manifold edges and vertices,
/// duplicates, obtuse and needle triangles), some points unreferenced.
fn random_soup(seed: u64) -> (Vec<P>, Vec<[u32; 3]>) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let n = 12;
    let p: Vec<P> = (0..n)
        .map(|_| [0, 1, 2].map(|_| rng.random_range(-1.0..1.0)))
        .collect();
    let mut t = Vec::new();
    while t.len() < 30 {
        let f = [0, 1, 2].map(|_| rng.random_range(0..n as u32 - 2));
        if f[0] != f[1] && f[1] != f[2] && f[0] != f[2] {
            t.push(f);
        }
    }
    (p, t)
}

#[test]
fn any_soup_gives_a_symmetric_psd_laplacian_with_zero_row_sums_and_the_area_as_mass() {
    let mut flips = 0;
    for seed in 0..20 {
        let (p, t) = random_soup(seed);
        let out = tufted(&p, &t);
        flips += out.report.flips;
        check_laplacian_properties(&out.laplacian, &format!("seed {seed}"));
        let area: f64 = t
            .iter()
            .map(|f| {
                0.5 * cross_norm(
                    sub(p[f[1] as usize], p[f[0] as usize]),
                    sub(p[f[2] as usize], p[f[0] as usize]),
                )
            })
            .sum();
        let trace: f64 = (0..out.mass.n).map(|i| out.mass.get(i, i)).sum();
        // Mollification lengthens the sides a little; nothing else changes the area.
        let tol = if out.report.mollify_delta == 0.0 {
            1e-12
        } else {
            1e-3
        };
        assert!(
            (trace - area).abs() <= tol * area,
            "seed {seed}: mass {trace}, area {area}"
        );
        // The two unreferenced points: zero rows and mass.
        for v in [p.len() - 2, p.len() - 1] {
            assert!(out.laplacian.row(v).all(|(_, x)| x == 0.0) && out.mass.get(v, v) == 0.0);
        }
        // Deterministic.
        assert_eq!(out, tufted(&p, &t));
    }
    assert!(flips > 0, "the random soups needed flips");
}

#[test]
fn degenerate_faces_are_mollified_or_named() {
    // A collinear face in a book: mollified by default, named without mollification.
    let p = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.5, 1.0, 0.0],
        [0.5, 0.0, 0.0],
        [0.5, -1.0, 0.3],
    ];
    let t = vec![[0, 1, 2], [0, 1, 3], [1, 0, 4]];
    let out = tufted(&p, &t);
    assert!(out.report.mollify_delta > 0.0);
    check_laplacian_properties(&out.laplacian, "collinear");
    let none = TuftedOptions {
        mollify_factor: 0.0,
        ..TuftedOptions::default()
    };
    let err = tufted_laplacian(&p, &t, &none).unwrap_err();
    assert!(
        matches!(
            err,
            TuftedError::Degenerate(GeometryError::ZeroArea { face: 1, .. })
        ),
        "{err}"
    );
}

#[test]
fn bad_input_is_a_typed_error_naming_the_element() {
    let p = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let run = |p: &[P], t: &[[u32; 3]], factor: f64| {
        tufted_laplacian(
            p,
            t,
            &TuftedOptions {
                mollify_factor: factor,
                max_flips: None,
            },
        )
        .unwrap_err()
    };
    assert_eq!(run(&p, &[], 1e-5), TuftedError::Input(BuildError::Empty));
    assert!(matches!(
        run(&p, &[[0, 1, 2], [0, 1, 3]], 1e-5),
        TuftedError::Input(BuildError::IndexOutOfRange {
            face: 1,
            index: 3,
            ..
        })
    ));
    assert!(matches!(
        run(&p, &[[0, 1, 2], [2, 1, 2]], 1e-5),
        TuftedError::Input(BuildError::RepeatedVertex { face: 1, vertex: 2 })
    ));
    let mut nan = p.clone();
    nan[1][2] = f64::NAN;
    assert!(matches!(
        run(&nan, &[[0, 1, 2]], 1e-5),
        TuftedError::Input(BuildError::NonFinite { vertex: 1, .. })
    ));
    for factor in [-1e-5, f64::NAN, 2.0] {
        assert!(matches!(
            run(&p, &[[0, 1, 2]], factor),
            TuftedError::InvalidMollifyFactor(_)
        ));
    }
    // All points at one place: nothing to mollify against.
    let same = vec![[1.0, 1.0, 1.0]; 3];
    assert!(matches!(
        run(&same, &[[0, 1, 2]], 1e-5),
        TuftedError::Degenerate(_)
    ));
    // The flip budget.
    let (p, t) = random_soup(3);
    let options = TuftedOptions {
        max_flips: Some(0),
        ..TuftedOptions::default()
    };
    assert!(matches!(
        tufted_laplacian(&p, &t, &options),
        Err(TuftedError::Flip(_))
    ));
}

surftopo_testkit::shared_mesh_tests!(shared_meshes_equal_their_intrinsic_delaunay_laplacian);

/// The smallest shared meshes: the tufted Laplacian of a closed manifold is its own.
fn shared_meshes_equal_their_intrinsic_delaunay_laplacian() {
    for mesh in surftopo_testkit::shared_meshes_up_to(20_000)
        .into_iter()
        .take(6)
    {
        let s = surftopo_testkit::load(&mesh);
        let t: Vec<[u32; 3]> = s
            .mesh
            .faces()
            .map(|f| s.mesh.face_vertices(f).map(|v| v.0))
            .collect();
        equals_plain_intrinsic_delaunay(&mesh.file, &s.positions, &t, false);
    }
}
