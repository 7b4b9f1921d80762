//! Polygons glued along their sides where some gluings reverse orientation and some sides are
//! glued to nothing (boundary sides): the Delaunay tessellation of a surface of any kind
//! ([`crate::CoveredTriangulation`]'s, per component), and whether two of them are equal up to
//! rigid motions and renaming.
//!
//! Dubois' Appendix A.3 compares closed oriented portalgons ([`crate::compare_tessellations`]):
//! fix a side s of the first, and for each candidate image s' propagate the correspondence
//! through polygons and gluings, checking that each polygon lies on its image by a rigid
//! motion. Extending it to these maps is ours:
//!
//! - **A sense per polygon.** A correspondence lays each polygon of the first onto one of the
//!   second either keeping the counter-clockwise order of its sides (a proper motion) or
//!   reversing it (a motion with a reflection: side `i + m` goes to side `j - m`, the start
//!   corner of side `i` to the end corner of side `j`). Crossing a gluing, the sense of the
//!   neighbour is the sense of the polygon, changed once for each of the two gluings (the
//!   first's and the second's) that runs start to start. On an orientable surface whose
//!   gluings are all plain, the sense is that of the seed, so trying both senses at the seed is
//!   the mirror image of the closed case; on a non-orientable one the sense changes along
//!   orientation-reversing loops, as an isometry's local sense does.
//! - **Boundary sides are marked.** A boundary side must go to a boundary side (an isometry
//!   takes boundary to boundary), an interior side to an interior side.
//!
//! A correspondence that covers every polygon is an isometry of the surfaces (the polygons are
//! laid onto each other by rigid motions and glued alike). It exists for isometric surfaces
//! exactly when their tessellations are canonical (the caller's argument, see
//! [`crate::decide_isometry_on_cover`]). Propagation from one seed is O(n); the seed is the side
//! of the first with the fewest candidates of the same polygon size, boundary mark and length
//! (within the tolerance), each tried in both senses: O(n²) in the worst case, as the paper's.

use std::fmt;

/// No side: the mate of a boundary side.
const NONE: u32 = u32::MAX;

/// Polygons (counter-clockwise, each in its own plane) and a partial gluing of their sides,
/// each gluing plain (the sides run opposite ways, as in an oriented portalgon) or reversed
/// (start to start). See the module doc.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TwistedMap {
    /// Polygon `p` owns the sides `start[p]..start[p + 1]`; side `start[p] + i` runs from
    /// corner `i` to corner `i + 1`.
    start: Vec<u32>,
    /// The start corner of each side.
    corner: Vec<[f64; 2]>,
    /// The polygon of each side.
    owner: Vec<u32>,
    /// The side each side is glued to ([`NONE`]: a boundary side).
    mate: Vec<u32>,
    /// Whether the gluing of each side runs start to start.
    reversed: Vec<bool>,
}

impl TwistedMap {
    /// An empty map.
    pub fn new() -> Self {
        Self {
            start: vec![0],
            ..Self::default()
        }
    }

    /// Adds a polygon given by its corners (counter-clockwise); returns its first side.
    pub fn push_polygon(&mut self, corners: &[[f64; 2]]) -> u32 {
        let first = self.corner.len() as u32;
        let polygon = self.start.len() as u32 - 1;
        self.corner.extend_from_slice(corners);
        self.owner.extend(corners.iter().map(|_| polygon));
        self.mate.extend(corners.iter().map(|_| NONE));
        self.reversed.extend(corners.iter().map(|_| false));
        self.start.push(self.corner.len() as u32);
        first
    }

    /// Glues sides `s` and `t` (running start to start when `reversed`).
    pub fn glue(&mut self, s: u32, t: u32, reversed: bool) {
        self.mate[s as usize] = t;
        self.mate[t as usize] = s;
        self.reversed[s as usize] = reversed;
        self.reversed[t as usize] = reversed;
    }

    /// The number of polygons.
    pub fn polygon_count(&self) -> usize {
        self.start.len() - 1
    }

    /// The number of sides.
    pub fn side_count(&self) -> usize {
        self.corner.len()
    }

    /// The number of boundary sides (glued to nothing).
    pub fn boundary_side_count(&self) -> usize {
        self.mate.iter().filter(|&&m| m == NONE).count()
    }

    /// The sides of polygon `p`, counter-clockwise.
    pub fn polygon_sides(&self, p: u32) -> std::ops::Range<u32> {
        self.start[p as usize]..self.start[p as usize + 1]
    }

    /// The polygon of side `s`.
    pub fn polygon_of(&self, s: u32) -> u32 {
        self.owner[s as usize]
    }

    /// The start corner of side `s`, in its polygon's plane.
    pub fn corner(&self, s: u32) -> [f64; 2] {
        self.corner[s as usize]
    }

    /// The number of sides of polygon `p`.
    pub fn polygon_size(&self, p: u32) -> usize {
        (self.start[p as usize + 1] - self.start[p as usize]) as usize
    }

    /// The side of polygon `p` at (cyclic) index `i`.
    fn side(&self, p: u32, i: isize) -> u32 {
        let k = self.polygon_size(p) as isize;
        self.start[p as usize] + i.rem_euclid(k) as u32
    }

    /// The index of side `s` in its polygon.
    fn index(&self, s: u32) -> isize {
        (s - self.start[self.owner[s as usize] as usize]) as isize
    }

    /// The end corner of side `s`.
    fn end(&self, s: u32) -> [f64; 2] {
        self.corner[self.side(self.owner[s as usize], self.index(s) + 1) as usize]
    }

    /// The length of side `s`.
    pub fn side_length(&self, s: u32) -> f64 {
        let (p, q) = (self.corner[s as usize], self.end(s));
        (q[0] - p[0]).hypot(q[1] - p[1])
    }

    /// The mate of side `s` and whether the gluing runs start to start; `None` on the boundary.
    pub fn mate(&self, s: u32) -> Option<(u32, bool)> {
        let m = self.mate[s as usize];
        (m != NONE).then(|| (m, self.reversed[s as usize]))
    }

    /// `[polygons, sides, boundary sides]`.
    pub fn counts(&self) -> [usize; 3] {
        [
            self.polygon_count(),
            self.side_count(),
            self.boundary_side_count(),
        ]
    }

    /// Each side's (polygon size, on the boundary, length), sorted, with the side.
    fn keyed(&self) -> Vec<(SideKey, u32)> {
        let mut keyed: Vec<(SideKey, u32)> = (0..self.side_count() as u32)
            .map(|s| {
                let key = SideKey {
                    sides: self.polygon_size(self.owner[s as usize]),
                    boundary: self.mate[s as usize] == NONE,
                    length: self.side_length(s),
                };
                (key, s)
            })
            .collect();
        keyed.sort_by(|x, y| x.0.cmp(&y.0));
        keyed
    }
}

/// What must agree between a side and its image, in the order sides are sorted.
#[derive(Clone, Copy, Debug, PartialEq)]
struct SideKey {
    sides: usize,
    boundary: bool,
    length: f64,
}

impl SideKey {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        (self.sides, self.boundary)
            .cmp(&(other.sides, other.boundary))
            .then(self.length.total_cmp(&other.length))
    }

    /// "an interior side of a triangle", "a boundary side of a 5-gon".
    fn describe(&self) -> String {
        let kind = if self.boundary {
            "boundary"
        } else {
            "interior"
        };
        format!("{kind} side of a {}", super::polygon_name(self.sides))
    }
}

/// A correspondence found by [`compare_twisted`].
#[derive(Clone, Debug, PartialEq)]
pub struct MapMatch {
    /// The seed side of the first map.
    pub side_a: u32,
    /// Its image.
    pub side_b: u32,
    /// Whether the seed polygon is laid with a reflection.
    pub reflected: bool,
    /// `[polygons, sides, boundary sides]` of either map.
    pub counts: [usize; 3],
    /// Side `s` of the first goes to side `image[s]` of the second.
    pub image: Vec<u32>,
}

impl MapMatch {
    /// The correspondence in words.
    pub fn reason(&self) -> String {
        let [polygons, sides, boundary] = self.counts;
        format!(
            "the Delaunay tessellations ({polygons} polygons, {sides} sides, {boundary} on the \
             boundary) correspond: side {} of the first lies on side {} of the second{}, and \
             every polygon on one of the second",
            self.side_a,
            self.side_b,
            if self.reflected {
                " with a reflection"
            } else {
                ""
            }
        )
    }
}

/// Why two maps are not equal ([`compare_twisted`]).
#[derive(Clone, Debug, PartialEq)]
pub enum MapDifference {
    /// Different numbers of polygons, sides or boundary sides.
    Counts {
        /// `[polygons, sides, boundary sides]` of the first.
        a: [usize; 3],
        /// Of the second.
        b: [usize; 3],
    },
    /// With sides sorted by (polygon size, boundary mark, length), the kinds or lengths differ
    /// at some rank.
    Sides {
        /// The rank.
        rank: usize,
        /// The side of the first there.
        a: String,
        /// Of the second.
        b: String,
    },
    /// Some side of the first has no candidate image.
    NoCandidate {
        /// The side.
        side: u32,
        /// What it is.
        what: String,
    },
    /// No seed's correspondence covers the surface.
    NoCorrespondence {
        /// The seeds tried (both senses).
        candidates: usize,
        /// Where the candidate that went furthest failed.
        closest: String,
    },
}

impl fmt::Display for MapDifference {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MapDifference::Counts { a, b } => write!(
                f,
                "the Delaunay tessellations differ in size: {} polygons, {} sides ({} on the \
                 boundary) against {}, {} ({})",
                a[0], a[1], a[2], b[0], b[1], b[2]
            ),
            MapDifference::Sides { rank, a, b } => write!(
                f,
                "with sides sorted by polygon size, boundary and length, the {}th is {a} in the \
                 first and {b} in the second",
                rank + 1
            ),
            MapDifference::NoCandidate { side, what } => write!(
                f,
                "side {side} of the first ({what}) has no side of the second of the same kind \
                 and length"
            ),
            MapDifference::NoCorrespondence {
                candidates,
                closest,
            } => write!(
                f,
                "the sizes and side lengths agree, but none of the {candidates} ways of laying \
                 one polygon onto another extends to the whole surface; the closest: {closest}"
            ),
        }
    }
}

/// Whether two maps are equal up to rigid motions (with reflections) of their polygons and
/// renaming, gluings and boundary marks kept; `tolerance` relative to the longest side. The
/// seed is tried in both senses when `both_senses`, in the proper sense only otherwise (an
/// orientation-preserving isometry of oriented maps). See the module doc.
///
/// # Errors
/// Where the maps differ, in words ([`MapDifference`]).
pub fn compare_twisted(
    a: &TwistedMap,
    b: &TwistedMap,
    tolerance: f64,
    both_senses: bool,
) -> Result<MapMatch, MapDifference> {
    if a.counts() != b.counts() {
        return Err(MapDifference::Counts {
            a: a.counts(),
            b: b.counts(),
        });
    }
    let (keyed_a, keyed_b) = (a.keyed(), b.keyed());
    let longest = keyed_a
        .iter()
        .chain(&keyed_b)
        .fold(0.0f64, |m, x| m.max(x.0.length));
    let eps = tolerance * longest;
    let describe = |k: &SideKey| format!("an {} {} long", k.describe(), k.length);
    for (rank, (x, y)) in keyed_a.iter().zip(&keyed_b).enumerate() {
        let (x, y) = (&x.0, &y.0);
        if (x.sides, x.boundary) != (y.sides, y.boundary) || (x.length - y.length).abs() > eps {
            return Err(MapDifference::Sides {
                rank,
                a: describe(x),
                b: describe(y),
            });
        }
    }
    // The seed: the side of the first with the fewest candidates of its kind and length.
    let range = |k: &SideKey| {
        let lo = SideKey {
            length: k.length - eps,
            ..*k
        };
        let hi = SideKey {
            length: k.length + eps,
            ..*k
        };
        let from = keyed_b.partition_point(|x| x.0.cmp(&lo).is_lt());
        let to = keyed_b.partition_point(|x| x.0.cmp(&hi).is_le());
        from..to.max(from)
    };
    let (key, seed) = *keyed_a
        .iter()
        .min_by_key(|(k, s)| (range(k).len(), *s))
        .expect("compared maps have sides");
    let candidates = range(&key);
    if candidates.is_empty() {
        return Err(MapDifference::NoCandidate {
            side: seed,
            what: key.describe(),
        });
    }
    let mut closest: Option<Failure> = None;
    let mut tried = 0usize;
    for reflected in [false, true] {
        if reflected && !both_senses {
            break;
        }
        for &(_, image) in &keyed_b[candidates.clone()] {
            tried += 1;
            match correspondence(a, b, seed, image, reflected, eps) {
                Ok(map) => {
                    return Ok(MapMatch {
                        side_a: seed,
                        side_b: image,
                        reflected,
                        counts: a.counts(),
                        image: map,
                    });
                }
                Err(failure) => {
                    if closest.as_ref().is_none_or(|c| failure.matched > c.matched) {
                        closest = Some(failure);
                    }
                }
            }
        }
    }
    let closest = closest.expect("a candidate was tried");
    Err(MapDifference::NoCorrespondence {
        candidates: tried,
        closest: format!(
            "after {} of {} polygons laid, polygon {} of the first does not lie on polygon {} of \
             the second: {}",
            closest.matched,
            a.polygon_count(),
            closest.polygons[0],
            closest.polygons[1],
            closest.what
        ),
    })
}

/// Where a correspondence failed.
struct Failure {
    matched: usize,
    polygons: [u32; 2],
    what: String,
}

/// A frame on a side: its origin, the side's unit direction, and +1 or -1 (a reflection) for
/// the sense of the normal.
struct Frame {
    origin: [f64; 2],
    u: [f64; 2],
    sense: f64,
}

impl Frame {
    fn new(from: [f64; 2], to: [f64; 2], sense: f64) -> Self {
        let (dx, dy) = (to[0] - from[0], to[1] - from[1]);
        let norm = dx.hypot(dy);
        Self {
            origin: from,
            u: [dx / norm, dy / norm],
            sense,
        }
    }

    /// The point's coordinates along and across the side.
    fn local(&self, x: [f64; 2]) -> [f64; 2] {
        let (dx, dy) = (x[0] - self.origin[0], x[1] - self.origin[1]);
        [
            dx * self.u[0] + dy * self.u[1],
            self.u[0] * dy - self.u[1] * dx,
        ]
    }

    /// The point at these coordinates.
    fn point(&self, [s, t]: [f64; 2]) -> [f64; 2] {
        let t = t * self.sense;
        [
            self.origin[0] + s * self.u[0] - t * self.u[1],
            self.origin[1] + s * self.u[1] + t * self.u[0],
        ]
    }
}

/// Propagates `seed_a ↦ seed_b` (reflected or not) through polygons and gluings; returns the
/// side map, or where it failed.
fn correspondence(
    a: &TwistedMap,
    b: &TwistedMap,
    seed_a: u32,
    seed_b: u32,
    reflected: bool,
    eps: f64,
) -> Result<Vec<u32>, Failure> {
    let mut image = vec![NONE; a.side_count()];
    let mut preimage = vec![NONE; b.side_count()];
    let mut sense: Vec<Option<bool>> = vec![None; a.polygon_count()];
    let mut stack = vec![(seed_a, seed_b, reflected)];
    let mut matched = 0usize;
    while let Some((sa, sb, flip)) = stack.pop() {
        let (pa, pb) = (a.owner[sa as usize], b.owner[sb as usize]);
        let fail = |what: String| Failure {
            matched,
            polygons: [pa, pb],
            what,
        };
        if let Some(laid) = sense[pa as usize] {
            if image[sa as usize] != sb || laid != flip {
                return Err(fail(
                    "a side is glued to a different neighbour than the correspondence already \
                     chose"
                        .into(),
                ));
            }
            continue;
        }
        let k = a.polygon_size(pa);
        if b.polygon_size(pb) != k {
            return Err(fail(format!(
                "one is a {}, the other a {}",
                super::polygon_name(k),
                super::polygon_name(b.polygon_size(pb))
            )));
        }
        let (ia, ib) = (a.index(sa), b.index(sb));
        let from = Frame::new(a.corner[sa as usize], a.end(sa), 1.0);
        let to = if flip {
            Frame::new(b.end(sb), b.corner[sb as usize], -1.0)
        } else {
            Frame::new(b.corner[sb as usize], b.end(sb), 1.0)
        };
        for m in 0..k as isize {
            let xa = a.side(pa, ia + m);
            let (xb, corner_b) = if flip {
                (b.side(pb, ib - m), b.side(pb, ib + 1 - m))
            } else {
                let x = b.side(pb, ib + m);
                (x, x)
            };
            if preimage[xb as usize] != NONE {
                return Err(fail("a polygon of the second would be used twice".into()));
            }
            let p = to.point(from.local(a.corner[xa as usize]));
            let q = b.corner[corner_b as usize];
            let distance = (p[0] - q[0]).hypot(p[1] - q[1]);
            if distance > 4.0 * eps {
                return Err(fail(format!(
                    "its corner {} lands {distance:e} away from the other's corner",
                    (ia + m).rem_euclid(k as isize)
                )));
            }
            image[xa as usize] = xb;
            preimage[xb as usize] = xa;
        }
        sense[pa as usize] = Some(flip);
        for m in 0..k as isize {
            let xa = a.side(pa, ia + m);
            let xb = image[xa as usize];
            match (a.mate(xa), b.mate(xb)) {
                (None, None) => {}
                (Some((ma, ra)), Some((mb, rb))) => stack.push((ma, mb, flip ^ ra ^ rb)),
                _ => {
                    return Err(fail(
                        "a boundary side would lie on an interior side".to_string(),
                    ));
                }
            }
        }
        matched += 1;
    }
    if matched == a.polygon_count() {
        Ok(image)
    } else {
        Err(Failure {
            matched,
            polygons: [a.owner[seed_a as usize], b.owner[seed_b as usize]],
            what: "the correspondence does not reach every polygon (the first is not connected)"
                .into(),
        })
    }
}
