//! Section 8 and Theorem 1 with cone points (`dubois::caps`), checked independently.
//!
//! The needle family: the pillowcase `R²/(2L ⋊ ±1)` of the lattice `L = ⟨u, v⟩` (a sphere with
//! four cone points of angle π), triangulated from the parallelogram `0, 2u, 2u + v, v` by the
//! four triangles `(0, u, v)`, `(u, u+v, v)`, `(u, 2u, u+v)`, `(2u, 2u+v, u+v)` (the bottom and top
//! sides folded at `u` and `u + v` by half-turns, the left side glued to the right by `2u`).
//! Shearing `v` by `k·u` gives the same surface with needles of aspect ratio about `k²`. The
//! lifts of the four cone points are exactly `L`, so the Delaunay tessellation is the image of the
//! planar Delaunay tessellation of `L`: for `L = ⟨(1, 0), (p, 1)⟩`, `p = 0`, two unit squares;
//! `p = 1/3`, four triangles with squared sides `{1, 10/9, 13/9}` — known by construction, checked
//! here on the exact output's corners with rational arithmetic.

use surftopo_intrinsic::dubois::{
    CapsError, ConeDelaunay, FlatDelaunayOptions, cut_caps, delaunay_tessellation_dubois,
    delaunay_tessellation_of_mesh,
};
use surftopo_intrinsic::generators::pillowcase;
use surftopo_intrinsic::geometry::{Rational, Scalar};
use surftopo_intrinsic::voronoi::{Sources, VoronoiOptions, voronoi_delaunay};
use surftopo_intrinsic::{
    DelaunayOptions, IntrinsicTriangulation, Portalgon, cotan_laplacian, flip_to_delaunay,
};
use surftopo_testkit::{SharedMesh, load, shared_meshes};

fn q(s: &str) -> Rational {
    s.parse().unwrap()
}

type P = [Rational; 2];

fn sheared(k: &str, p: &str) -> Portalgon<Rational> {
    let u = [q("1"), q("0")];
    let v = [q(k) + q(p), q("1")];
    let t = pillowcase(&u, &v).unwrap();
    t.check_closed().unwrap();
    t
}

fn len2(a: &P, b: &P) -> Rational {
    let (x, y) = (b[0].clone() - a[0].clone(), b[1].clone() - a[1].clone());
    x.clone() * x + y.clone() * y
}

fn dot_at(a: &P, b: &P, c: &P) -> Rational {
    let (x1, y1) = (a[0].clone() - b[0].clone(), a[1].clone() - b[1].clone());
    let (x2, y2) = (c[0].clone() - b[0].clone(), c[1].clone() - b[1].clone());
    x1 * x2 + y1 * y2
}

fn sorted(mut v: Vec<Rational>) -> Vec<Rational> {
    v.sort_by(|a, b| a.partial_cmp(b).unwrap());
    v
}

/// Every polygon's squared side lengths (sorted) and whether all its corners are right angles.
fn shapes(t: &Portalgon<Rational>) -> Vec<(Vec<Rational>, bool)> {
    t.polygons()
        .map(|p| {
            let c = t.corners(p);
            let n = c.len();
            let l = (0..n).map(|i| len2(&c[i], &c[(i + 1) % n])).collect();
            let right = (0..n).all(|i| {
                dot_at(&c[(i + n - 1) % n], &c[i], &c[(i + 1) % n]).sign()
                    == std::cmp::Ordering::Equal
            });
            (sorted(l), right)
        })
        .collect()
}

/// The known tessellation of the module doc.
fn assert_known(t: &Portalgon<Rational>, p: &str, what: &str) {
    let s = shapes(t);
    if p == "0" {
        assert_eq!(s.len(), 2, "{what}: {s:?}");
        for (l, right) in s {
            assert_eq!(l, vec![q("1"); 4], "{what}");
            assert!(right, "{what}");
        }
    } else {
        assert_eq!(s.len(), 4, "{what}: {s:?}");
        for (l, _) in s {
            assert_eq!(l, vec![q("1"), q("10/9"), q("13/9")], "{what}");
        }
    }
    assert_eq!(t.area(), q("2"), "{what}: area");
}

/// Angle sums per vertex class, in f64 (law of cosines on the exact corners, independent of the
/// crate's angle code), sorted.
fn cone_angles(t: &Portalgon<Rational>) -> Vec<f64> {
    let (class, count) = t.vertex_classes();
    let mut sum = vec![0.0; count];
    for s in t.sides() {
        let p = t.owner(s);
        let c = t.corners(p);
        let n = c.len();
        let i = t.side_index(s);
        let (a, b, cc) = (&c[(i + n - 1) % n], &c[i], &c[(i + 1) % n]);
        // atan2 of the exact cross and dot products: accurate on needles too.
        let (e1, e2) = (
            [cc[0].clone() - b[0].clone(), cc[1].clone() - b[1].clone()],
            [a[0].clone() - b[0].clone(), a[1].clone() - b[1].clone()],
        );
        let cross = e1[0].clone() * e2[1].clone() - e1[1].clone() * e2[0].clone();
        let dot = e1[0].clone() * e2[0].clone() + e1[1].clone() * e2[1].clone();
        sum[class[s.idx()] as usize] += cross.to_f64().atan2(dot.to_f64());
    }
    let mut cones: Vec<f64> = sum
        .into_iter()
        .filter(|a| (a - std::f64::consts::TAU).abs() > 1e-9)
        .collect();
    cones.sort_by(f64::total_cmp);
    cones
}

/// Euler characteristic V − E + F of a closed portalgon.
fn euler(t: &Portalgon<Rational>) -> i64 {
    let (_, v) = t.vertex_classes();
    v as i64 - (t.side_count() / 2) as i64 + t.polygon_count() as i64
}

fn check_known_tessellations(shears: &[&str]) {
    for &k in shears {
        for p in ["0", "1/3"] {
            let t = sheared(k, p);
            let what = format!("shear {k} + {p}");
            let out = delaunay_tessellation_dubois(&t, &FlatDelaunayOptions::default())
                .unwrap_or_else(|e| panic!("{what}: {e}"));
            assert_eq!(out.cone_points, 4, "{what}");
            assert_eq!(out.delaunay.sources.len(), 4, "{what}");
            assert_known(&out.delaunay.tessellation, p, &what);
        }
    }
}

#[test]
fn dubois_gives_the_known_tessellation_of_sheared_pillowcases_exactly() {
    check_known_tessellations(&["0", "7", "1000"]);
}

/// Needles of aspect ratio up to about 10²⁴ (release: `cargo test --release -p
/// surftopo-intrinsic --test caps -- --ignored`).
#[test]
#[ignore = "slow in the default profile: about 20 s in release, 145 s in debug (opt-level 1); \
            run with cargo test --release -p surftopo-intrinsic --test caps -- --ignored"]
fn dubois_gives_the_known_tessellation_of_huge_shears_exactly() {
    check_known_tessellations(&["1000000", "1000000000000"]);
}

#[test]
fn dubois_equals_the_wave_on_moderate_shears() {
    for k in ["3", "12"] {
        for p in ["0", "1/3", "2/5"] {
            let t = sheared(k, p);
            let dubois = delaunay_tessellation_dubois(&t, &FlatDelaunayOptions::default())
                .unwrap()
                .delaunay
                .tessellation;
            let wave = voronoi_delaunay(
                &t,
                &VoronoiOptions {
                    sources: Sources::Singular,
                    ..VoronoiOptions::default()
                },
            )
            .unwrap()
            .tessellation;
            let mut a = shapes(&dubois);
            let mut b = shapes(&wave);
            a.sort_by(|x, y| x.0.partial_cmp(&y.0).unwrap());
            b.sort_by(|x, y| x.0.partial_cmp(&y.0).unwrap());
            assert_eq!(a, b, "shear {k} + {p}");
            assert_eq!(dubois.area(), wave.area());
        }
    }
}

#[test]
fn the_surface_is_unchanged_by_every_step() {
    for (k, p) in [("0", "0"), ("1000", "1/3"), ("100000", "2/7")] {
        let t = sheared(k, p);
        let what = format!("shear {k} + {p}");
        let (area, angles, chi) = (t.area(), cone_angles(&t), euler(&t));
        assert_eq!(angles.len(), 4, "{what}");
        let cut = cut_caps(&t, 1e-9).unwrap();
        // T₀: same surface.
        assert_eq!(cut.t0.area(), area, "{what}: T₀");
        assert!(
            cut.t0
                .polygons()
                .all(|x| cut.t0.polygon_sides(x).len() == 3)
        );
        assert_eq!(euler(&cut.t0), chi, "{what}: T₀");
        let ca = cone_angles(&cut.t0);
        for (x, y) in ca.iter().zip(&angles) {
            assert!((x - y).abs() < 1e-9, "{what}: T₀ {ca:?} vs {angles:?}");
        }
        // T₁ plus the caps: the area; T₁ flat inside with one boundary cycle per cone point.
        let caps_area = cut
            .caps
            .iter()
            .fold(q("0"), |s, &c| s + cut.t0.polygon_area(c));
        assert_eq!(cut.remainder.area() + caps_area, area, "{what}: T₁");
        let comps = cut
            .remainder
            .components(&cut.remainder.polygons().collect::<Vec<_>>())
            .unwrap();
        assert_eq!(comps.len(), 1);
        assert_eq!(comps[0].boundary_cycles.len(), 4, "{what}");
        // A sphere minus four discs: χ = −2.
        assert_eq!(comps[0].euler_characteristic, -2, "{what}");
        // Every cap point within d/6 of its cone point: |radius|² ≤ d²/36, d the smallest height.
        let d2 = t
            .polygons()
            .map(|x| {
                let a = t.polygon_area(x);
                let l = t
                    .polygon_sides(x)
                    .iter()
                    .map(|&s| t.side_length2(s))
                    .fold(q("0"), |m, l| if l > m { l } else { m });
                q("4") * a.clone() * a / l
            })
            .fold(None::<Rational>, |m, h| match m {
                Some(m) if m < h => Some(m),
                _ => Some(h),
            })
            .unwrap();
        for (&c, &apex) in cut.caps.iter().zip(&cut.apex_sides) {
            assert_eq!(cut.t0.owner(apex), c);
            let prev = cut.t0.prev_side(apex);
            for s in [apex, prev] {
                let r2 = cut.t0.side_length2(s);
                assert!(r2.clone() * q("36") <= d2, "{what}: radius");
                assert!(r2 * q("144") > d2, "{what}: radius above d/12");
            }
        }
        // T′ = Proposition 2's output: same area, χ, cone angles.
        let (t_prime, report, _) =
            surftopo_intrinsic::dubois::proposition_2(&t, &FlatDelaunayOptions::default()).unwrap();
        assert!(report.outer_iterations >= 1);
        assert_eq!(t_prime.area(), area, "{what}: T′");
        assert_eq!(euler(&t_prime), chi, "{what}: T′");
        let ct = cone_angles(&t_prime);
        assert_eq!(ct.len(), 4, "{what}: T′ {ct:?}");
        for (x, y) in ct.iter().zip(&angles) {
            assert!((x - y).abs() < 1e-9, "{what}: T′ {ct:?} vs {angles:?}");
        }
    }
}

/// On a shared mesh in `f64`: Theorem 1 with caps and V = every vertex ([`Sources::All`],
/// Section 1's footnote 1) gives the flip route's Laplacian to `tolerance` relative to its
/// largest diagonal entry. Returns that relative deviation; `Err` for a typed refusal.
fn check_dubois_against_flip(mesh: &SharedMesh, tolerance: f64) -> Result<f64, String> {
    let s = load(mesh);
    let tri = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap();
    check_triangulation_against_flip(&tri, &mesh.file, tolerance)
}

/// [`check_dubois_against_flip`] on any intrinsic triangulation, named `name` in messages.
fn check_triangulation_against_flip(
    tri: &IntrinsicTriangulation,
    name: &str,
    tolerance: f64,
) -> Result<f64, String> {
    let options = FlatDelaunayOptions {
        sources: Sources::All,
        ..FlatDelaunayOptions::default()
    };
    check_triangulation_against_flip_with(tri, name, tolerance, &options)
}

/// Theorem 1 by one route: with caps ([`delaunay_tessellation_dubois`]) or on a mesh's metric
/// ([`delaunay_tessellation_of_mesh`]).
type Route = fn(&Portalgon<f64>, &FlatDelaunayOptions) -> Result<ConeDelaunay<f64>, CapsError>;

/// [`check_triangulation_against_flip`] with `options` (V must be every vertex).
fn check_triangulation_against_flip_with(
    tri: &IntrinsicTriangulation,
    name: &str,
    tolerance: f64,
    options: &FlatDelaunayOptions,
) -> Result<f64, String> {
    check_route_against_flip(tri, name, tolerance, options, delaunay_tessellation_dubois)
}

/// [`check_triangulation_against_flip_with`] by `route`.
fn check_route_against_flip(
    tri: &IntrinsicTriangulation,
    name: &str,
    tolerance: f64,
    options: &FlatDelaunayOptions,
    route: Route,
) -> Result<f64, String> {
    let (p, _) = tri.to_portalgon();
    let out = route(&p, options).map_err(|e| format!("{name}: {e}"))?;
    assert_eq!(
        out.delaunay.sources.len(),
        tri.mesh().vertex_count(),
        "{name}: V is every vertex",
    );
    let ours = out.delaunay.triangulation().unwrap();
    let mut flipped = tri.clone();
    flip_to_delaunay(&mut flipped, &DelaunayOptions::default()).unwrap();
    let (la, lb) = (cotan_laplacian(&ours), cotan_laplacian(&flipped));
    assert_eq!(la.n, lb.n, "{name}");
    let scale = (0..lb.n).map(|i| lb.get(i, i).abs()).fold(0.0, f64::max);
    let mut deviation = 0.0f64;
    for i in 0..la.n {
        for (j, x) in la.row(i).chain(lb.row(i)) {
            let (a, b) = (la.get(i, j as usize), lb.get(i, j as usize));
            deviation = deviation.max((a - b).abs() / scale);
            assert!(
                (a - b).abs() <= tolerance * scale,
                "{name}: L[{i}][{j}] {a} vs {b} ({x})"
            );
        }
    }
    eprintln!(
        "{}: {} faces, {} cone points, N = {}, {} triangles after reduction, {} events, \
         Laplacian within {deviation:.1e} of flipping's",
        name,
        tri.mesh().face_count(),
        out.cone_points,
        out.reduction.outer_iterations,
        out.reduction.triangles_after_reduction,
        out.delaunay.wave.events
    );
    Ok(deviation)
}

/// The three smallest shared meshes, to 1e-12: table.off (92 faces: the case of the degenerate
/// shortcut candidates of `Portalgon::shortcut`), sledge.off (212 faces), both with flat
/// vertices, and chair_soup.off (512 faces, genus 6), whose wave on `T′` ran out of its budget
/// when it told points apart to 1e-9 (`T′` closes up only to the f64 closing tolerance). With
/// the reduction in double-double they agree to 1e-14 or better; in `f64` it gave 1.8e-11
/// (table) and 2.4e-10 (chair_soup).
fn dubois_with_caps_equals_flip_on_the_smallest_shared_meshes() {
    let mut meshes = shared_meshes();
    meshes.sort_by_key(|m| m.faces);
    for m in meshes.iter().take(3) {
        let tolerance = 1e-12;
        check_dubois_against_flip(m, tolerance).unwrap();
    }
}

surftopo_testkit::shared_mesh_tests!(
    dubois_with_caps_equals_flip_on_the_smallest_shared_meshes,
    dubois_on_a_mesh_metric_equals_flip
);

/// Surfaces the tolerances were never tuned on, made here: a torus whose grid diagonals wind
/// around the tube, an icosphere and a thin torus re-triangulated by random intrinsic flips
/// (edges crossing the mesh's, vertices of degree 3 to 12), and the icosahedron: Theorem 1 in
/// `f64` gives the flip route's Laplacian to 1e-12.
#[test]
fn dubois_with_caps_equals_flip_on_generated_surfaces() {
    use surftopo_intrinsic::generators::{random_flips, sheared_torus};
    use surftopo_mesh::generators::{icosphere, torus};
    let from = |s: surftopo_mesh::Surface| {
        IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap()
    };
    let mut cases = vec![
        ("sheared torus", from(sheared_torus(24, 8, 3))),
        ("icosahedron", from(icosphere(0))),
    ];
    for (k, (name, surface)) in [("icosphere", icosphere(2)), ("thin torus", torus(5, 30))]
        .into_iter()
        .enumerate()
    {
        let mut tri = from(surface);
        random_flips(&mut tri, 300, k as u64 + 7);
        cases.push((name, tri));
    }
    for (name, tri) in &cases {
        check_triangulation_against_flip(tri, name, 1e-12).unwrap();
    }
}

/// Theorem 1 on a mesh's own metric (docs/dubois.md §8: a mesh has happiness 1, so it serves as
/// Proposition 2's output, no cap and no ALGORITHM): the flip route's Laplacian to 1e-12 on the
/// three smallest shared meshes and on generated meshes (not re-triangulated: their triangles
/// are faces in space), with the report saying that ALGORITHM did not run, except where the
/// wave refuses the mesh in `f64` and the caps are built after all.
fn dubois_on_a_mesh_metric_equals_flip() {
    use surftopo_intrinsic::generators::sheared_torus;
    use surftopo_mesh::generators::{icosphere, torus};
    let from = |s: surftopo_mesh::Surface| {
        IntrinsicTriangulation::from_positions(s.mesh, &s.positions).unwrap()
    };
    let mut cases = vec![
        ("sheared torus".to_string(), from(sheared_torus(24, 8, 3))),
        ("icosphere".to_string(), from(icosphere(2))),
        ("thin torus".to_string(), from(torus(5, 30))),
    ];
    let mut meshes = shared_meshes();
    meshes.sort_by_key(|m| m.faces);
    for m in meshes.iter().take(3) {
        let s = load(m);
        cases.push((m.file.clone(), from(s)));
    }
    let options = FlatDelaunayOptions {
        sources: Sources::All,
        ..FlatDelaunayOptions::default()
    };
    for (name, tri) in &cases {
        check_route_against_flip(tri, name, 1e-12, &options, delaunay_tessellation_of_mesh)
            .unwrap();
        let (p, _) = tri.to_portalgon();
        let out = delaunay_tessellation_of_mesh(&p, &options).unwrap();
        // The thin torus's grid is near-co-circular everywhere: the wave's dual refuses the
        // mesh in f64, and the route falls back to the caps (checked against flipping above).
        let kept = name != "thin torus";
        assert_eq!(out.reduction.mesh_metric, kept, "{name}");
        assert_eq!(out.reduction.outer_iterations == 0, kept, "{name}");
        assert_eq!(out.cap_triangles == 0, kept, "{name}");
        assert_eq!(out.reduced == p, kept, "{name}: T′ is the input");
    }
}

/// When the wave's point tolerance is coarse for the surface's features, its dual fails and
/// Theorem 1 in `f64` runs the wave again at a finer tolerance (`Tolerances::with_retries`, whose `finer_retry` is 1e-3):
/// here an icosphere whose faces at one vertex are split at a hundredth of the way to their
/// centroids, with the wave told points apart only to 1e-3 of the longest side (the dual then
/// misses a Voronoi vertex, as on `seahorse2_100K.off` at the default 1e-9), gives flipping's
/// Laplacian to 1e-12 through the retry at 1e-6.
#[test]
fn a_wave_tolerance_too_coarse_for_the_features_is_retried_finer() {
    use surftopo_mesh::Surface;
    use surftopo_mesh::generators::icosphere;
    let s = icosphere(1);
    let mut positions = s.positions.clone();
    let mut triangles = Vec::new();
    for f in s.mesh.faces() {
        let t = s.mesh.face_vertices(f).map(|v| v.0);
        if !t.contains(&0) {
            triangles.push(t);
            continue;
        }
        let at = |k: usize| t.map(|v| positions[v as usize][k]);
        let w = [0, 1, 2].map(|k| {
            let c = at(k).iter().sum::<f64>() / 3.0;
            positions[0][k] + 0.01 * (c - positions[0][k])
        });
        positions.push(w);
        let n = (positions.len() - 1) as u32;
        triangles.extend([[t[0], t[1], n], [t[1], t[2], n], [t[2], t[0], n]]);
    }
    let surface = Surface::from_triangles(positions, &triangles).unwrap();
    let tri = IntrinsicTriangulation::from_positions(surface.mesh, &surface.positions).unwrap();
    let mut options = FlatDelaunayOptions {
        sources: Sources::All,
        ..FlatDelaunayOptions::default()
    };
    options.tolerances.point = 1e-3;
    check_triangulation_against_flip_with(&tri, "clustered icosphere", 1e-12, &options).unwrap();
}

/// The variable naming the mesh [`dubois_against_flip_on_one_shared_mesh`] checks.
const ONE_MESH_VARIABLE: &str = "SURFTOPO_DUBOIS_MESH";

/// One shared mesh (its file name in [`ONE_MESH_VARIABLE`]): the child process of
/// [`dubois_with_caps_equals_flip_on_every_shared_mesh`], which can then stop it at its time
/// limit. Prints `RESULT agrees DEVIATION` or `RESULT refused WHY`; a disagreement beyond 1e-6 fails.
#[test]
#[ignore = "run by dubois_with_caps_equals_flip_on_every_shared_mesh"]
fn dubois_against_flip_on_one_shared_mesh() {
    let Ok(file) = std::env::var(ONE_MESH_VARIABLE) else {
        return;
    };
    let mesh = shared_meshes()
        .into_iter()
        .find(|m| m.file == file)
        .unwrap_or_else(|| panic!("no shared mesh {file}"));
    match check_dubois_against_flip(&mesh, 1e-6) {
        Ok(deviation) => println!("RESULT agrees {deviation:.1e}"),
        Err(why) => println!("RESULT refused {why}"),
    }
}

/// Every shared mesh (of at least `SURFTOPO_SWEEP_MIN_FACES` faces, default 0), smallest first,
/// each in a child process stopped after `SURFTOPO_SWEEP_SECONDS` (default 300): the Laplacian
/// within 1e-6 of flipping's (the deviation
/// of each is printed), or a typed refusal (a numerical failure in `f64`), listed at the end.
/// Times grow with the faces: after two timeouts in a row the larger meshes are not run.
#[test]
#[ignore = "every shared mesh: run in release (cargo test --release -p surftopo-intrinsic --test caps -- --ignored)"]
fn dubois_with_caps_equals_flip_on_every_shared_mesh() {
    if std::env::var(ONE_MESH_VARIABLE).is_ok() {
        return;
    }
    let limit = std::env::var("SURFTOPO_SWEEP_SECONDS")
        .ok()
        .and_then(|s| s.parse::<u64>().ok())
        .unwrap_or(300);
    let min_faces = std::env::var("SURFTOPO_SWEEP_MIN_FACES")
        .ok()
        .and_then(|s| s.parse::<usize>().ok())
        .unwrap_or(0);
    let mut meshes = shared_meshes();
    meshes.retain(|m| m.faces >= min_faces);
    meshes.sort_by_key(|m| m.faces);
    let (mut agreed, mut skipped, mut disagreed) = (0, Vec::new(), Vec::new());
    let mut timeouts_in_a_row = 0;
    for m in &meshes {
        if timeouts_in_a_row == 2 {
            skipped.push(format!("{}: not run (two timeouts before it)", m.file));
            continue;
        }
        let start = std::time::Instant::now();
        let mut child = std::process::Command::new(std::env::current_exe().unwrap())
            .args([
                "dubois_against_flip_on_one_shared_mesh",
                "--exact",
                "--ignored",
                "--nocapture",
            ])
            .env(ONE_MESH_VARIABLE, &m.file)
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        let finished = loop {
            if let Some(status) = child.try_wait().unwrap() {
                break Some(status);
            }
            if start.elapsed().as_secs() >= limit {
                child.kill().unwrap();
                child.wait().unwrap();
                break None;
            }
            std::thread::sleep(std::time::Duration::from_millis(100));
        };
        let mut stdout = String::new();
        std::io::Read::read_to_string(&mut child.stdout.take().unwrap(), &mut stdout).unwrap();
        let result = stdout
            .lines()
            .find_map(|l| l.strip_prefix("RESULT "))
            .map(str::to_string);
        timeouts_in_a_row = if finished.is_none() {
            timeouts_in_a_row + 1
        } else {
            0
        };
        let outcome = match (finished, result) {
            (None, _) => {
                skipped.push(format!("{}: did not finish within {limit} s", m.file));
                "timeout".to_string()
            }
            (Some(_), Some(r)) if r.starts_with("agrees ") => {
                agreed += 1;
                r.replace("agrees ", "agrees to ")
            }
            (Some(_), Some(r)) => {
                let why = r.trim_start_matches("refused ").to_string();
                skipped.push(why.clone());
                format!("not compared: {why}")
            }
            (Some(_), None) => {
                disagreed.push(m.file.clone());
                "DISAGREES (or panicked)".to_string()
            }
        };
        eprintln!(
            "{} ({} faces): {outcome}, {:.1} s",
            m.file,
            m.faces,
            start.elapsed().as_secs_f64()
        );
    }
    eprintln!(
        "{agreed} of {} agree with the flip route; not compared: {skipped:#?}",
        meshes.len()
    );
    assert!(
        disagreed.is_empty(),
        "disagree with flipping: {disagreed:?}"
    );
}
