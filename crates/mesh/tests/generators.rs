//! Every generator checked against counts derived by hand or by an independent voxel model,
//! plus structural checks, closedness recomputed from the triangle soup, and determinism.

use std::collections::{HashMap, HashSet};
use surftopo_mesh::LinkScratch;
use surftopo_mesh::Surface;
use surftopo_mesh::generators::{
    CavityBox, cavity_box, genus_surface, icosphere, random_flips, random_vertex_splits,
    shuffle_faces, subdivide_midpoint, tetrahedron, torus,
};
use surftopo_mesh::geometry::Point3;

/// V, E, F and genus recomputed from the soup alone; asserts that every undirected edge lies in
/// exactly two triangles and every directed edge in exactly one (closed, consistently oriented).
fn soup_counts(surface: &Surface) -> (usize, usize, usize, i64) {
    let (positions, triangles) = surface.to_triangles();
    let mut undirected: HashMap<(u32, u32), u32> = HashMap::new();
    let mut directed: HashSet<(u32, u32)> = HashSet::new();
    let mut used = vec![false; positions.len()];
    for t in &triangles {
        for i in 0..3 {
            let (a, b) = (t[i], t[(i + 1) % 3]);
            assert_ne!(a, b, "degenerate triangle {t:?}");
            *undirected.entry((a.min(b), a.max(b))).or_default() += 1;
            assert!(directed.insert((a, b)), "directed edge {a}->{b} twice");
            used[a as usize] = true;
        }
    }
    for (e, n) in &undirected {
        assert_eq!(*n, 2, "edge {e:?} in {n} triangles");
    }
    assert!(used.iter().all(|&u| u), "unreferenced vertex");
    let (v, e, f) = (positions.len(), undirected.len(), triangles.len());
    let chi = v as i64 - e as i64 + f as i64;
    assert_eq!(chi % 2, 0);
    (v, e, f, (2 - chi) / 2)
}

/// Everything a generator promises, for expected V, E, F and genus.
fn check_surface(surface: &Surface, v: usize, e: usize, f: usize, genus: i64) {
    let mesh = &surface.mesh;
    mesh.check_invariants().unwrap();
    assert!(mesh.is_simplicial(), "not simplicial");
    assert_eq!(
        (mesh.vertex_count(), mesh.edge_count(), mesh.face_count()),
        (v, e, f),
        "V, E, F"
    );
    assert_eq!(mesh.genus(), genus);
    assert_eq!(
        (mesh.vertex_slots(), mesh.edge_slots(), mesh.face_slots()),
        (v, e, f),
        "ids not dense"
    );
    assert_eq!(surface.positions.len(), v);
    assert!(surface.positions.iter().flatten().all(|c| c.is_finite()));
    assert_eq!(soup_counts(surface), (v, e, f, genus));
}

/// Signed volume enclosed by the surface (positive when faces point outwards).
fn signed_volume(surface: &Surface) -> f64 {
    let (p, triangles) = surface.to_triangles();
    triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| p[i as usize]);
            (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                + a[2] * (b[0] * c[1] - b[1] * c[0]))
                / 6.0
        })
        .sum()
}

/// An independent voxel model of a brick (the layout rule of the module doc): occupancy of each
/// unit voxel; counts boundary lattice points and boundary squares by brute force.
struct Voxels {
    n: [usize; 3],
    solid: Vec<bool>,
}

impl Voxels {
    fn brick(b: &CavityBox) -> Self {
        let (k, s, w) = (b.grid() as usize, b.scale() as usize, b.wall() as usize);
        let (d, t) = (b.depth() as usize, b.floor() as usize);
        let width = k * s + (k + 1) * w;
        let n = [width, width, d + t];
        let mut solid = vec![true; width * width * (d + t)];
        let pits = (b.cavities() + b.holes()) as usize;
        // Pit q is a hole when the running share of holes steps up at q.
        let mut holes_so_far = 0usize;
        for q in 0..pits {
            let share = (q + 1) * b.holes() as usize / pits;
            let hole = share > holes_so_far;
            holes_so_far = share;
            let (px, py) = (q % k, q / k);
            for x in w + px * (s + w)..w + px * (s + w) + s {
                for y in w + py * (s + w)..w + py * (s + w) + s {
                    let z0 = if hole { 0 } else { t };
                    for z in z0..d + t {
                        solid[(z * width + y) * width + x] = false;
                    }
                }
            }
        }
        Self { n, solid }
    }

    fn at(&self, x: isize, y: isize, z: isize) -> bool {
        let [nx, ny, nz] = self.n.map(|c| c as isize);
        if x < 0 || y < 0 || z < 0 || x >= nx || y >= ny || z >= nz {
            return false;
        }
        self.solid[((z * ny + y) * nx + x) as usize]
    }

    /// Lattice points whose eight voxels are not all alike, and unit squares between a solid and
    /// an empty voxel.
    fn boundary(&self) -> (HashSet<[i64; 3]>, usize) {
        let [nx, ny, nz] = self.n.map(|c| c as isize);
        let mut points = HashSet::new();
        for x in 0..=nx {
            for y in 0..=ny {
                for z in 0..=nz {
                    let mut kinds = HashSet::new();
                    for dx in [-1, 0] {
                        for dy in [-1, 0] {
                            for dz in [-1, 0] {
                                kinds.insert(self.at(x + dx, y + dy, z + dz));
                            }
                        }
                    }
                    if kinds.len() == 2 {
                        points.insert([x as i64, y as i64, z as i64]);
                    }
                }
            }
        }
        let mut squares = 0;
        for x in -1..=nx {
            for y in -1..=ny {
                for z in -1..=nz {
                    let here = self.at(x, y, z);
                    squares += usize::from(here != self.at(x + 1, y, z));
                    squares += usize::from(here != self.at(x, y + 1, z));
                    squares += usize::from(here != self.at(x, y, z + 1));
                }
            }
        }
        (points, squares)
    }

    fn volume(&self) -> usize {
        self.solid.iter().filter(|&&s| s).count()
    }
}

/// A brick compared with its voxel model: vertex positions (scaled back to the lattice) are
/// exactly the boundary lattice points, F is twice the boundary squares, the volume matches and
/// faces point outwards.
fn check_brick_against_voxels(b: &CavityBox) {
    let surface = b.generate();
    let voxels = Voxels::brick(b);
    let (points, squares) = voxels.boundary();
    let f = 2 * squares;
    let v = points.len();
    let e = 3 * f / 2;
    check_surface(&surface, v, e, f, i64::from(b.holes()));
    assert_eq!(b.triangle_count(), f as u64);
    let s = f64::from(b.scale());
    let lattice: HashSet<[i64; 3]> = surface
        .positions
        .iter()
        .map(|p| p.map(|c| (c * s).round() as i64))
        .collect();
    assert_eq!(
        lattice, points,
        "vertex positions are not the boundary lattice points"
    );
    let volume = signed_volume(&surface) * s * s * s;
    assert!(
        (volume - voxels.volume() as f64).abs() < 1e-6 * volume.abs().max(1.0),
        "volume {volume} vs {} voxels",
        voxels.volume()
    );
}

#[test]
fn brick_counts_by_hand() {
    // One 1x1x1 cavity in a 3x3x2 box: the box has 4*4*3 - 2*2*1 = 44 boundary lattice points,
    // the pit floor adds 4; squares: 2*9 + 4*3*2 + 4 (pit walls) + 0 (pit floor replaces the top
    // square) = 46.
    let cavity = CavityBox::new(1, 0, 1, 1, 1, 1);
    let s = cavity.generate();
    check_surface(&s, 48, 138, 92, 0);
    // The same with a hole: 44 + 4 points; squares 18 - 2 + 24 + 4*2 = 48; genus 1.
    let hole = CavityBox::new(0, 1, 1, 1, 1, 1);
    check_surface(&hole.generate(), 48, 144, 96, 1);
    // No pit: a 1x1x2 box: all 2*2*3 = 12 lattice points, 2 + 4*2 = 10 squares.
    check_surface(&CavityBox::new(0, 0, 1, 1, 1, 1).generate(), 12, 30, 20, 0);
}

#[test]
fn brick_grid_and_clamping() {
    for (n, k) in [
        (0u32, 0u32),
        (1, 1),
        (2, 2),
        (4, 2),
        (5, 3),
        (3843, 62),
        (3844, 62),
        (3845, 63),
    ] {
        assert_eq!(
            CavityBox::new(n / 2, n - n / 2, 1, 1, 1, 1).grid(),
            k,
            "n = {n}"
        );
    }
    let b = CavityBox::new(2, 1, 0, 0, 0, 0);
    assert_eq!((b.scale(), b.wall(), b.depth(), b.floor()), (1, 1, 1, 1));
    assert_eq!((b.cavities(), b.holes()), (2, 1));
}

#[test]
fn bricks_match_their_voxel_model() {
    for (c, h, s, w, d, t) in [
        (1, 0, 2, 1, 1, 1),
        (0, 1, 1, 2, 2, 1),
        (3, 2, 1, 1, 1, 1),
        (4, 5, 2, 1, 3, 2),
        (7, 0, 1, 3, 2, 2),
        (0, 7, 3, 2, 1, 1),
        (2, 2, 2, 2, 2, 2),
        (10, 6, 1, 1, 2, 1),
    ] {
        check_brick_against_voxels(&CavityBox::new(c, h, s, w, d, t));
    }
}

/// The count formula of the module doc, written out independently.
fn brick_triangles(c: u64, h: u64, k: u64, s: u64, w: u64, d: u64, t: u64) -> u64 {
    let width = k * s + (k + 1) * w;
    let a = 2 * width * width - 2 * h * s * s
        + 4 * width * (d + t)
        + 4 * s * c * d
        + 4 * s * h * (d + t);
    2 * a
}

#[test]
fn fit_is_the_nearest_in_its_search_space() {
    for (c, h, target) in [
        (3u32, 2u32, 5_000u64),
        (9, 0, 30_000),
        (0, 4, 12_345),
        (1, 0, 0),
        (20, 5, 200_000),
    ] {
        let fit = CavityBox::fit(c, h, target);
        let k = fit.grid() as u64;
        assert!(k * k >= (c + h) as u64 && (k == 0 || (k - 1) * (k - 1) < (c + h) as u64));
        let got = fit.triangle_count();
        assert_eq!(
            got,
            brick_triangles(
                c as u64,
                h as u64,
                k,
                fit.scale() as u64,
                fit.wall() as u64,
                fit.depth() as u64,
                fit.floor() as u64
            )
        );
        let mut best = u64::MAX;
        for s in 1..=32u64 {
            for w in s.div_ceil(2)..=2 * s {
                for d in s.div_ceil(2)..=2 * s {
                    for t in s.div_ceil(2)..=2 * s {
                        let f = brick_triangles(c as u64, h as u64, k, s, w, d, t);
                        best = best.min(f.abs_diff(target));
                    }
                }
            }
        }
        assert_eq!(got.abs_diff(target), best, "fit of {c}, {h}, {target}");
    }
}

#[test]
fn papers_sizes_are_approached() {
    // Group B (Table 3) and C (Table 4): within 2% from 500k triangles up.
    for target in [4_194_296u64, 2_194_296, 1_194_296, 594_296] {
        let got = CavityBox::fit(3844, 0, target).triangle_count();
        assert!(got.abs_diff(target) * 50 < target, "{target} -> {got}");
    }
    for target in [4_222_296u64, 2_222_296, 1_222_296, 722_296] {
        let got = CavityBox::fit(344, 3500, target).triangle_count();
        assert!(got.abs_diff(target) * 50 < target, "{target} -> {got}");
    }
    // Group D (Table 5): 3,844 pits, ~4.2M triangles, any genus.
    for g in [10u32, 50, 100, 500, 1000, 3500] {
        let fit = CavityBox::fit(3844 - g, g, 4_200_000);
        assert_eq!(fit.grid(), 62);
        assert!(fit.triangle_count().abs_diff(4_200_000) < 4_200);
    }
    // The smallest reachable sizes (below them the coarsest brick is returned).
    assert_eq!(cavity_box_min(3844, 0), 95_252);
    assert_eq!(cavity_box_min(344, 3500), 109_252);
}

fn cavity_box_min(c: u32, h: u32) -> u64 {
    CavityBox::fit(c, h, 0).triangle_count()
}

#[test]
fn papers_brick_at_its_coarsest() {
    // 3,844 pits on the 62 x 62 grid, with 10 or 3,500 of them holes (groups D9 and C/D0).
    for holes in [10u32, 3500] {
        let s = cavity_box(3844 - holes, holes, 0);
        let b = CavityBox::fit(3844 - holes, holes, 0);
        let f = brick_triangles(3844 - holes as u64, holes as u64, 62, 1, 1, 1, 1) as usize;
        check_surface(
            &s,
            f / 2 + 2 - 2 * holes as usize,
            3 * f / 2,
            f,
            holes as i64,
        );
        assert_eq!(b.triangle_count() as usize, f);
        assert!(signed_volume(&s) > 0.0);
    }
}

#[test]
fn genus_surfaces() {
    for g in [0u32, 1, 2, 3, 4, 5, 10, 50, 200] {
        let sizes: &[u32] = if g <= 5 { &[1, 2, 3] } else { &[1] };
        for &size in sizes {
            let s = genus_surface(g, size);
            let k = (0u64..).find(|k| k * k >= g as u64).unwrap();
            let (size, g64) = (size as u64, g as u64);
            let w = (2 * k + 1) * size;
            let f = (4 * w * w + 16 * w * size + 12 * g64 * size * size) as usize;
            check_surface(&s, f / 2 + 2 - 2 * g as usize, 3 * f / 2, f, g as i64);
            assert!(signed_volume(&s) > 0.0, "faces point inwards");
        }
    }
    assert_eq!(genus_surface(3, 0), genus_surface(3, 1));
    assert_eq!(genus_surface(4, 2), genus_surface(4, 2));
}

#[test]
fn random_flips_keep_counts_and_positions() {
    let base = torus(12, 10);
    let flipped = random_flips(&base, 500, 7);
    let (v, e, f) = (120, 360, 240);
    check_surface(&flipped, v, e, f, 1);
    assert_eq!(flipped.positions, base.positions);
    // Connectivity changed: some edge of the result is not an edge of the input.
    let edges = |s: &Surface| -> HashSet<[u32; 2]> {
        s.mesh
            .edges()
            .map(|e| {
                let [a, b] = s.mesh.edge_vertices(e).map(|x| x.0);
                [a.min(b), a.max(b)]
            })
            .collect()
    };
    let (before, after) = (edges(&base), edges(&flipped));
    assert!(after.difference(&before).count() > 50);
    // Degrees are no longer all 6.
    assert!(flipped.mesh.vertices().any(|x| flipped.mesh.degree(x) != 6));
    assert_eq!(flipped, random_flips(&base, 500, 7));
    assert_ne!(flipped, random_flips(&base, 500, 8));
    assert_eq!(random_flips(&base, 0, 7), base);
    // On a brick too (genus 3).
    let brick = genus_surface(3, 1);
    let fb = random_flips(&brick, 2000, 1);
    check_surface(
        &fb,
        brick.mesh.vertex_count(),
        brick.mesh.edge_count(),
        brick.mesh.face_count(),
        3,
    );
}

#[test]
fn random_flips_stop_when_nothing_can_flip() {
    // Every vertex of the tetrahedron has degree 3: no simplicial flip exists.
    let t = tetrahedron();
    assert_eq!(random_flips(&t, 10, 3), t);
}

#[test]
fn midpoint_subdivision_counts_and_midpoints() {
    for base in [tetrahedron(), torus(5, 4), genus_surface(2, 1)] {
        let (v, e, f) = (
            base.mesh.vertex_count(),
            base.mesh.edge_count(),
            base.mesh.face_count(),
        );
        let g = base.mesh.genus();
        let one = subdivide_midpoint(&base, 1);
        check_surface(&one, v + e, 2 * e + 3 * f, 4 * f, g);
        // Old vertices keep their positions; every edge midpoint is a new vertex.
        assert_eq!(one.positions[..v], base.positions[..]);
        let key = |p: &Point3| p.map(f64::to_bits);
        let have: HashSet<_> = one.positions.iter().map(key).collect();
        for ed in base.mesh.edges() {
            let [a, b] = base.mesh.edge_vertices(ed).map(|x| base.positions[x.idx()]);
            let m = [0, 1, 2].map(|k| (a[k] + b[k]) / 2.0);
            assert!(have.contains(&key(&m)));
        }
        // Two levels: apply the count recurrence twice.
        let (v1, e1, f1) = (v + e, 2 * e + 3 * f, 4 * f);
        let two = subdivide_midpoint(&base, 2);
        check_surface(&two, v1 + e1, 2 * e1 + 3 * f1, 4 * f1, g);
        assert_eq!(two, subdivide_midpoint(&one, 1));
        assert_eq!(subdivide_midpoint(&base, 0), base);
        // Every child triangle's area is a quarter of its parent's (similar triangles).
        let area = |s: &Surface, i: usize| {
            surftopo_mesh::geometry::face_area(&s.mesh, &s.positions, surftopo_mesh::FaceId::new(i))
        };
        for parent in 0..f {
            for child in 4 * parent..4 * parent + 4 {
                let (a, c) = (area(&base, parent), area(&one, child));
                assert!((4.0 * c - a).abs() <= 1e-9 * a.max(1.0));
            }
        }
    }
}

#[test]
fn random_vertex_splits_counts() {
    for (base, g) in [(tetrahedron(), 0), (icosphere(1), 0), (torus(6, 5), 1)] {
        let (v, e, f) = (
            base.mesh.vertex_count(),
            base.mesh.edge_count(),
            base.mesh.face_count(),
        );
        for k in [1usize, 10, 300] {
            let split = random_vertex_splits(&base, k, 11);
            check_surface(&split, v + k, e + 3 * k, f + 2 * k, g);
            assert_eq!(split.positions[..v], base.positions[..]);
            assert_eq!(split, random_vertex_splits(&base, k, 11));
            assert_ne!(split, random_vertex_splits(&base, k, 12));
        }
    }
    // Every new vertex lies at the midpoint of the vertex it split from and the centroid of its
    // other neighbours — checked for a single split, where those are known exactly.
    let base = icosphere(1);
    let one = random_vertex_splits(&base, 1, 5);
    let v = surftopo_mesh::VertexId::new(base.mesh.vertex_count());
    let neighbours: Vec<_> = one.mesh.neighbors(v).collect();
    let p = one.positions[v.idx()];
    let found = neighbours.iter().any(|&u| {
        let others: Vec<Point3> = neighbours
            .iter()
            .filter(|&&w| w != u)
            .map(|w| one.positions[w.idx()])
            .collect();
        let c = [0, 1, 2].map(|k| others.iter().map(|q| q[k]).sum::<f64>() / others.len() as f64);
        let pu = one.positions[u.idx()];
        (0..3).all(|k| (p[k] - (pu[k] + c[k]) / 2.0).abs() < 1e-12)
    });
    assert!(found, "new vertex not at the documented position");
}

#[test]
fn surface_compact_keeps_positions() {
    let mut s = torus(8, 7);
    let original = s.clone();
    let mut scratch = LinkScratch::default();
    let mut removed = Vec::new();
    for _ in 0..15 {
        let h = s
            .mesh
            .halfedges()
            .find(|&h| s.mesh.satisfies_link_condition(h, &mut scratch))
            .unwrap();
        removed.push(s.mesh.contract(h, &mut scratch).unwrap().removed());
    }
    let map = s.compact();
    s.mesh.check_invariants().unwrap();
    assert_eq!(s.mesh.vertex_slots(), 56 - 15);
    assert_eq!(s.positions.len(), 56 - 15);
    for (old, new) in map.vertices.iter().enumerate() {
        if new.is_valid() {
            assert_eq!(s.positions[new.idx()], original.positions[old]);
        } else {
            assert!(removed.iter().any(|r| r.idx() == old));
        }
    }
    soup_counts(&s);
}

#[test]
fn random_flips_on_flat_regions_make_no_flat_triangles() {
    use surftopo_mesh::generators::{genus_surface, random_flips, subdivide_midpoint};
    let brick = subdivide_midpoint(&genus_surface(2, 2), 1);
    let flipped = random_flips(&brick, 5000, 11);
    assert_ne!(flipped.mesh, brick.mesh);
    for f in flipped.mesh.faces() {
        let area = surftopo_mesh::geometry::face_area(&flipped.mesh, &flipped.positions, f);
        assert!(area > 1e-9, "face {f:?} has area {area}");
    }
}

/// Whether no edge of the soup satisfies the link condition (recomputed from the triangles):
/// every edge has a common neighbour besides its two opposite vertices, or the soup is the
/// tetrahedron.
fn soup_is_irreducible(surface: &Surface) -> bool {
    let (positions, triangles) = surface.to_triangles();
    if positions.len() == 4 {
        return true;
    }
    let mut adjacent = vec![HashSet::new(); positions.len()];
    for t in &triangles {
        for i in 0..3 {
            adjacent[t[i] as usize].insert(t[(i + 1) % 3]);
            adjacent[t[(i + 1) % 3] as usize].insert(t[i]);
        }
    }
    triangles.iter().all(|t| {
        (0..3).all(|i| {
            let (a, b) = (t[i] as usize, t[(i + 1) % 3] as usize);
            adjacent[a].intersection(&adjacent[b]).count() > 2
        })
    })
}

#[test]
fn simplify_reaches_the_target_and_keeps_the_genus() {
    use surftopo_mesh::generators::simplify;
    // torus(20, 20): V 400, E 1200, F 800; 300 contractions down to 200 faces.
    let torus = torus(20, 20);
    let s = simplify(&torus, 200, 3);
    check_surface(&s, 100, 300, 200, 1);
    let input: HashSet<[u64; 3]> = torus
        .positions
        .iter()
        .map(|p| p.map(f64::to_bits))
        .collect();
    assert!(
        s.positions
            .iter()
            .all(|p| input.contains(&p.map(f64::to_bits))),
        "a kept vertex moved"
    );
    // An odd target ends one face below it; genus 3 is kept.
    let slab = genus_surface(3, 3);
    let f = slab.mesh.face_count();
    let s = simplify(&slab, f / 2 + 1, 5);
    let contractions = (f - f / 2) / 2;
    assert_eq!(s.mesh.face_count(), f - 2 * contractions);
    assert!(s.mesh.face_count() <= f / 2 + 1 && s.mesh.face_count() + 2 > f / 2 + 1);
    check_surface(
        &s,
        slab.mesh.vertex_count() - contractions,
        slab.mesh.edge_count() - 3 * contractions,
        f - 2 * contractions,
        3,
    );
    assert!(!soup_is_irreducible(&s));
}

#[test]
fn simplify_stops_at_an_irreducible_triangulation() {
    use surftopo_mesh::generators::simplify;
    let sphere = simplify(&icosphere(2), 0, 7);
    check_surface(&sphere, 4, 6, 4, 0);
    let t = simplify(&torus(12, 9), 0, 7);
    let (v, e, f, g) = soup_counts(&t);
    assert_eq!(g, 1);
    check_surface(&t, v, e, f, 1);
    assert!(soup_is_irreducible(&t), "an edge is still contractible");
    // Nothing to do: a compacted copy of the input.
    let same = simplify(&torus(6, 5), 60, 1);
    assert_eq!(same, torus(6, 5));
}

#[test]
fn simplify_is_deterministic_per_seed() {
    use surftopo_mesh::generators::simplify;
    let input = random_flips(&torus(16, 12), 200, 2);
    let a = simplify(&input, 150, 9);
    assert_eq!(a, simplify(&input, 150, 9));
    assert_ne!(a.mesh, simplify(&input, 150, 10).mesh);
    // torus(16, 12): V 192, E 576, F 384; 117 contractions down to 150 faces.
    check_surface(&a, 192 - 117, 576 - 3 * 117, 150, 1);
}

/// Shuffling keeps the triangles (as oriented vertex triples, up to rotation), the positions and
/// the genus; it changes their order, the same way for the same seed.
#[test]
fn shuffled_faces_are_the_same_surface_in_another_order() {
    let rotated = |t: [u32; 3]| {
        let k = (0..3).min_by_key(|&k| t[k]).expect("three corners");
        [t[k], t[(k + 1) % 3], t[(k + 2) % 3]]
    };
    let surface = torus(12, 9);
    let (positions, triangles) = surface.to_triangles();
    let shuffled = shuffle_faces(&surface, 5);
    let (shuffled_positions, shuffled_triangles) = shuffled.to_triangles();
    assert_eq!(shuffled_positions, positions);
    assert_eq!(shuffled.mesh.genus(), 1);
    assert_ne!(shuffled_triangles, triangles, "the order changed");
    let set = |ts: &[[u32; 3]]| {
        let mut v: Vec<[u32; 3]> = ts.iter().map(|&t| rotated(t)).collect();
        v.sort_unstable();
        v
    };
    assert_eq!(set(&shuffled_triangles), set(&triangles));
    assert_eq!(
        shuffle_faces(&surface, 5).to_triangles().1,
        shuffled_triangles
    );
    assert_ne!(
        shuffle_faces(&surface, 6).to_triangles().1,
        shuffled_triangles
    );
}

/// The smallest height over longest side (twice the area over the longest side squared) of the
/// faces around `w`, 0 when one has exactly zero area (the exact predicate).
fn star_height(s: &Surface, w: surftopo_mesh::VertexId) -> f64 {
    use surftopo_mesh::geometry::{distance, is_zero_area_triangle, triangle_area};
    s.mesh
        .outgoing(w)
        .map(|h| {
            let [a, b, c] = s
                .mesh
                .face_vertices(s.mesh.face(h))
                .map(|v| s.positions[v.idx()]);
            if is_zero_area_triangle(a, b, c) {
                return 0.0;
            }
            let l = distance(a, b).max(distance(b, c)).max(distance(c, a));
            2.0 * triangle_area(a, b, c) / (l * l)
        })
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn random_vertex_splits_are_not_made_without_a_non_flat_placement() {
    // Every vertex on one line: every placement of a new vertex makes a flat triangle, so no
    // split is made, whatever the seed (each split's 8 draws all fail).
    let mut line = tetrahedron();
    for (i, p) in line.positions.iter_mut().enumerate() {
        *p = [i as f64, 2.0 * i as f64, 0.0];
    }
    for seed in 0..20 {
        assert_eq!(random_vertex_splits(&line, 30, seed), line, "seed {seed}");
    }
    // Half an icosphere collapsed onto one point: splits there have no non-flat placement and
    // are redrawn; the splits made elsewhere leave no flat triangle at a new vertex.
    let mut half = icosphere(1);
    for p in half.positions.iter_mut().filter(|p| p[2] > 0.0) {
        *p = [0.0, 0.0, 1.0];
    }
    let (v, g) = (half.mesh.vertex_count(), 0);
    for seed in 0..20 {
        let split = random_vertex_splits(&half, 40, seed);
        let added = split.mesh.vertex_count() - v;
        assert!(added > 0, "seed {seed}: no split made");
        check_surface(
            &split,
            v + added,
            half.mesh.edge_count() + 3 * added,
            half.mesh.face_count() + 2 * added,
            g,
        );
        assert_eq!(split.positions[..v], half.positions[..]);
        for w in (v..v + added).map(surftopo_mesh::VertexId::new) {
            let h = star_height(&split, w);
            assert!(
                h > 1e-12,
                "seed {seed}: new vertex {w:?} has a face of height {h}"
            );
        }
        assert_eq!(split, random_vertex_splits(&half, 40, seed));
    }
}
