//! Random flat annuli for the tube tests: a convex fundamental quadrilateral `A, D, B = g(D),
//! C = g(A)` of a translation or rotation `g`, with random points on the rung `AD` (and their
//! images on `CB`) and random interior points, triangulated by spade's planar Delaunay
//! triangulation (independent of the crate), then glued: shared sides to each other, rung sides
//! to their images under `g`. `CA` and `DB` stay unmatched: the two boundary loops. Integer
//! coordinates (exact in f64), so the same tube is built in either arithmetic.
#![allow(dead_code)]

use std::collections::HashMap;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use spade::{DelaunayTriangulation, HasPosition, Point2, Triangulation};
use surftopo_intrinsic::geometry::Scalar;
use surftopo_intrinsic::{PolygonId, Portalgon, SideId};

/// A random tube and what it was built from.
pub struct RandomTube<S: Scalar> {
    /// The portalgon (every polygon a triangle of the tube).
    pub portalgon: Portalgon<S>,
    /// The corners `A, D, B, C` of the fundamental quadrilateral (integers).
    pub quad: [[i64; 2]; 4],
    /// `g`'s rotation `ω = (a + bi)/c` as `(a, b, c)`; `(1, 0, 1)` for a translation.
    pub omega: (i64, i64, i64),
    /// The boundary sides `CA` and `DB`.
    pub boundary: [SideId; 2],
    /// Interior vertices: rung points plus interior points.
    pub interior_vertices: usize,
}

/// The gluing `g` on integer points.
type Gluing = Box<dyn Fn([i64; 2]) -> [i64; 2]>;

struct Site([f64; 2]);

impl HasPosition for Site {
    type Scalar = f64;
    fn position(&self) -> Point2<f64> {
        Point2::new(self.0[0], self.0[1])
    }
}

fn orient(a: [i64; 2], b: [i64; 2], c: [i64; 2]) -> i128 {
    let (ab, ac) = ([b[0] - a[0], b[1] - a[1]], [c[0] - a[0], c[1] - a[1]]);
    i128::from(ab[0]) * i128::from(ac[1]) - i128::from(ab[1]) * i128::from(ac[0])
}

/// The Pythagorean rotations used: `(a, b, c)` with `a² + b² = c²` (θ from 16° to 67°).
const TRIPLES: [(i64, i64, i64); 5] = [
    (3, 4, 5),
    (5, 12, 13),
    (8, 15, 17),
    (20, 21, 29),
    (24, 7, 25),
];

/// A random tube; `rotation` chooses the gluing kind.
pub fn random_tube<S: Scalar>(
    seed: u64,
    rotation: bool,
    rung_points: usize,
    inner: usize,
) -> RandomTube<S> {
    random_tube_skewed(seed, rotation, rung_points, inner, None)
}

/// A random tube; for a translation, `skew` (when given) is the rung's horizontal extent in units
/// of `rung_points + 1` (the height is 16 to 64 such units and `|t|` at most 68, all times
/// `1 + √(inner/100)` to leave room for the interior points): the shortest offset, and with it
/// the happiness, grows like `skew/|t|`.
pub fn random_tube_skewed<S: Scalar>(
    seed: u64,
    rotation: bool,
    rung_points: usize,
    inner: usize,
    skew: Option<i64>,
) -> RandomTube<S> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    // The rung's vector is a multiple of k, so it divides into k equal integer steps; the other
    // coordinates are free integers, so that ties between lengths are rare.
    let k = rung_points as i64 + 1;
    // Room for the interior points: lengths grow like √inner.
    let lambda = 1 + ((inner / 100) as f64).sqrt() as i64;
    loop {
        let (quad, omega, g): ([[i64; 2]; 4], (i64, i64, i64), Gluing) = if rotation {
            let (a, b, c) = TRIPLES[rng.random_range(0..TRIPLES.len())];
            let b = if rng.random_range(0..2) == 0 { b } else { -b };
            // g(z) = ωz around the origin; A, D multiples of c (so ω·A, ω·D are integers).
            let r1 = rng.random_range(8..24) * c * k * lambda;
            let r2 = r1 + rng.random_range(8..32) * c * k * lambda;
            let skew = rng.random_range(-12..=12) * c * k * lambda;
            let (pa, pd) = ([r1, 0], [r2, skew]);
            let g = move |z: [i64; 2]| [(a * z[0] - b * z[1]) / c, (b * z[0] + a * z[1]) / c];
            let quad = if b > 0 {
                [pa, pd, g(pd), g(pa)]
            } else {
                // A clockwise rotation: the rung runs inward so that A, D, B, C turns
                // counter-clockwise.
                [pd, pa, g(pa), g(pd)]
            };
            (quad, (a, b, c), Box::new(g))
        } else {
            let t = [
                rng.random_range(-64..=-8) * lambda,
                rng.random_range(-24..=24) * lambda,
            ];
            let h = rng.random_range(16..=64) * k * lambda;
            let skew = skew.unwrap_or_else(|| rng.random_range(-240..=240)) * k * lambda;
            let (pa, pd) = ([0, 0], [skew, h]);
            let g = move |z: [i64; 2]| [z[0] + t[0], z[1] + t[1]];
            ([pa, pd, g(pd), g(pa)], (1, 0, 1), Box::new(g))
        };
        let [a, d, b, c] = quad;
        // Convex and counter-clockwise.
        if (0..4).any(|i| orient(quad[i], quad[(i + 1) % 4], quad[(i + 2) % 4]) <= 0) {
            continue;
        }
        // Rung points: A + i(D − A)/k.
        let step = [d[0] - a[0], d[1] - a[1]];
        let rung: Vec<[i64; 2]> = (1..k)
            .map(|i| [a[0] + step[0] * i / k, a[1] + step[1] * i / k])
            .collect();
        let images: Vec<[i64; 2]> = rung.iter().map(|&p| g(p)).collect();
        // Interior points: random integer points strictly inside.
        let (lo, hi) = (
            [
                quad.iter().map(|p| p[0]).min().unwrap(),
                quad.iter().map(|p| p[1]).min().unwrap(),
            ],
            [
                quad.iter().map(|p| p[0]).max().unwrap(),
                quad.iter().map(|p| p[1]).max().unwrap(),
            ],
        );
        let mut points: Vec<[i64; 2]> = vec![a, d, b, c];
        points.extend(&rung);
        points.extend(&images);
        let mut taken: std::collections::HashSet<[i64; 2]> = points.iter().copied().collect();
        let mut added = 0;
        let mut tries = 0;
        while added < inner && tries < 100 * (inner + 1) {
            tries += 1;
            let p = [
                rng.random_range(lo[0]..=hi[0]),
                rng.random_range(lo[1]..=hi[1]),
            ];
            if (0..4).all(|i| orient(quad[i], quad[(i + 1) % 4], p) > 0) && taken.insert(p) {
                points.push(p);
                added += 1;
            }
        }
        if added < inner {
            continue;
        }
        let sites: Vec<Site> = points
            .iter()
            .map(|p| Site([p[0] as f64, p[1] as f64]))
            .collect();
        let dt = DelaunayTriangulation::<Site>::bulk_load(sites).unwrap();
        let mut portalgon = Portalgon::<S>::empty();
        let mut side_at: HashMap<([i64; 2], [i64; 2]), SideId> = HashMap::new();
        let conv = |p: [i64; 2]| [S::from_i64(p[0]), S::from_i64(p[1])];
        for face in dt.inner_faces() {
            let v = face.vertices().map(|x| {
                let q = x.data().0;
                [q[0] as i64, q[1] as i64]
            });
            let poly: PolygonId = portalgon
                .add_polygon(&v.map(conv))
                .expect("a Delaunay triangle is counter-clockwise");
            for i in 0..3 {
                side_at.insert((v[i], v[(i + 1) % 3]), portalgon.side(poly, i));
            }
        }
        // Shared sides, then rung sides to their images.
        let mut pairs: Vec<(SideId, SideId)> = Vec::new();
        for (&(u, v), &s) in &side_at {
            if let Some(&t) = side_at.get(&(v, u))
                && s < t
            {
                pairs.push((s, t));
            }
        }
        let mut chain = vec![a];
        chain.extend(&rung);
        chain.push(d);
        for w in chain.windows(2) {
            let (u, v) = (w[0], w[1]);
            let s = side_at
                .get(&(u, v))
                .or_else(|| side_at.get(&(v, u)))
                .copied()
                .unwrap();
            let forward = side_at.contains_key(&(u, v));
            let (gu, gv) = (g(u), g(v));
            let t = if forward {
                side_at[&(gv, gu)]
            } else {
                side_at[&(gu, gv)]
            };
            pairs.push((s, t));
        }
        pairs.sort();
        for (s, t) in pairs {
            portalgon.glue(s, t, 0.0).expect("equal lengths");
        }
        let boundary = [side_at[&(c, a)], side_at[&(d, b)]];
        return RandomTube {
            portalgon,
            quad,
            omega,
            boundary,
            interior_vertices: rung.len() + inner,
        };
    }
}
