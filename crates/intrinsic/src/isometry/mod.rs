//! The isometry test of Dubois, Corollary 2 (Appendix A.3).
//!
//! Two closed polyhedral surfaces are isometric iff their canonical Delaunay tessellations — whose
//! vertices are the singularities (one vertex for a flat torus) — are equal as portalgons: there
//! is a one-to-one correspondence φ of polygon sides mapping polygons to polygons (their boundary
//! walks, cyclically) and the matching to the matching, such that each polygon is carried onto its
//! image by a rigid motion. Appendix A.3: fix a side s of the first; for each candidate image s'
//! build φ from s ↦ s' by propagation (unique if it exists, since the surface is connected), in
//! O(n), and check the polygons; O(n²) overall.
//!
//! Here the canonical tessellation is computed by the classical route, not the paper's algorithm
//! (which comes later): flip to Delaunay ([`crate::flip_to_delaunay`]), remove the flat vertices
//! ([`crate::remove_flat_vertices`]), flip again, merge co-circular triangles
//! ([`crate::delaunay_tessellation`]). Candidates for s' are restricted by invariants: first the
//! counts (polygons, sides, vertices), the histogram of polygon sizes and the sorted side lengths
//! must agree; then s is the side of the first surface with the fewest sides of the second of the
//! same polygon size and the same length within the tolerance, and only those are tried.
//!
//! Decisions: lengths and corners are compared with an absolute tolerance `length_tolerance ·
//! (longest side)` (rounding makes exact comparison meaningless). The paper's correspondence
//! preserves orientation; isometries may also reverse it (a surface and its mirror image are
//! isometric), so with [`IsometryOptions::allow_reflection`] (default) the mirror image of the
//! second tessellation is tried too, and the outcome says which one matched.

pub(crate) mod decision;
pub(crate) mod flat_torus_lattice;
pub(crate) mod flat_vertices;
pub(crate) mod twisted;

use crate::error::{IsometryError, PortalgonError};
use crate::flip::tessellation::delaunay_tessellation;
use crate::flip::{DelaunayOptions, flip_to_delaunay};
use crate::geometry::{Motion, Tolerances};
use crate::isometry::flat_vertices::remove_flat_vertices;
use crate::portalgon::{Point2, Portalgon, SideId};
use crate::triangulation::IntrinsicTriangulation;
use crate::triangulation::quality::DEFAULT_ANGLE_TOLERANCE;
use std::fmt;

/// Options of [`isometric`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IsometryOptions {
    /// Flip algorithm options (flip budget, mollification, Delaunay tolerance).
    pub delaunay: DelaunayOptions,
    /// A vertex is flat if its angle sum is within this many radians of 2π.
    pub angle_tolerance: f64,
    /// Co-circularity tolerance of the tessellation.
    pub cocircular_tolerance: f64,
    /// Lengths and corner positions agree if within this fraction of the longest side.
    pub length_tolerance: f64,
    /// Also accept orientation-reversing isometries.
    pub allow_reflection: bool,
}

impl Default for IsometryOptions {
    fn default() -> Self {
        Self {
            delaunay: DelaunayOptions::default(),
            angle_tolerance: DEFAULT_ANGLE_TOLERANCE,
            cocircular_tolerance: Tolerances::DEFAULT.isometry_cocircular,
            length_tolerance: Tolerances::DEFAULT.isometry_length,
            allow_reflection: true,
        }
    }
}

/// Why two tessellations are, or are not, equal. Polygon and side ids are those of the compacted
/// tessellations; the reasons ([`Outcome::reason`]) say in words which polygon, side or length
/// differs.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// A correspondence was found mapping side `side_a` of the first to side `side_b` of the
    /// second (of its mirror image when `reflected`).
    Isometric {
        /// Seed side of the first tessellation.
        side_a: u32,
        /// Its image.
        side_b: u32,
        /// Whether the second tessellation was mirrored.
        reflected: bool,
        /// The polygon of `side_a` and of `side_b`.
        polygons: [u32; 2],
        /// The number of sides of those polygons.
        sides: usize,
        /// The length of `side_a`.
        length: f64,
        /// `[polygons, sides, vertices]` of either tessellation.
        counts: [usize; 3],
    },
    /// Different numbers of polygons, sides or vertices.
    Counts {
        /// `[polygons, sides, vertices]` of the first.
        a: [usize; 3],
        /// `[polygons, sides, vertices]` of the second.
        b: [usize; 3],
    },
    /// The numbers of polygons with k sides differ for some k.
    PolygonSizes {
        /// The polygon size.
        sides: usize,
        /// How many in the first.
        a: usize,
        /// How many in the second.
        b: usize,
    },
    /// With sides sorted by (polygon size, length), the lengths differ at some rank.
    Lengths {
        /// Rank in the sorted order.
        rank: usize,
        /// Length in the first.
        a: f64,
        /// Length in the second.
        b: f64,
        /// The size of the polygons of those sides.
        sides: usize,
        /// The absolute tolerance (the relative one times the longest side).
        tolerance: f64,
    },
    /// Some side of the first has no side of the second with the same length and polygon size.
    NoCandidate {
        /// The side of the first.
        side_a: u32,
        /// Its polygon.
        polygon_a: u32,
        /// The polygon's number of sides.
        sides: usize,
        /// The side's length.
        length: f64,
    },
    /// Every candidate correspondence failed.
    NoCorrespondence {
        /// Number of candidate seeds tried (both orientations).
        candidates: usize,
        /// Where the candidate that matched the most polygons failed.
        closest: Mismatch,
    },
}

/// Where a candidate correspondence failed: laying polygon `polygon_a` of the first onto
/// `polygon_b` of the second, after `polygons_matched` polygons had been laid.
#[derive(Clone, Debug, PartialEq)]
pub struct Mismatch {
    /// Polygons laid onto their images before the failure.
    pub polygons_matched: usize,
    /// All polygons of the first.
    pub polygons: usize,
    /// The polygon of the first.
    pub polygon_a: u32,
    /// The polygon of the second it was to lie on.
    pub polygon_b: u32,
    /// What did not fit.
    pub what: MismatchKind,
    /// Whether the second tessellation was mirrored.
    pub reflected: bool,
}

/// What did not fit in a [`Mismatch`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MismatchKind {
    /// The polygons have different numbers of sides.
    Sides {
        /// Sides of the first's polygon.
        a: usize,
        /// Sides of the second's.
        b: usize,
    },
    /// The sides laid onto each other have different lengths.
    Length {
        /// Length in the first.
        a: f64,
        /// Length in the second.
        b: f64,
    },
    /// A corner, moved by the rigid motion that lays the first side onto its image, lands this
    /// far from the second's corner.
    Corner {
        /// The corner's index in the first's polygon.
        corner: usize,
        /// The distance.
        distance: f64,
    },
    /// A side would be glued to a different neighbour than the correspondence already chose.
    Gluing,
}

/// "1st", "2nd", "3rd", "4th", ..., "11th", "12th", "13th", "21st", ...
pub(crate) fn ordinal(n: usize) -> String {
    let suffix = match (n % 10, n % 100) {
        (_, 11..=13) => "th",
        (1, _) => "st",
        (2, _) => "nd",
        (3, _) => "rd",
        _ => "th",
    };
    format!("{n}{suffix}")
}

/// "triangle", "quadrilateral", or "k-gon".
pub(crate) fn polygon_name(sides: usize) -> String {
    match sides {
        3 => "triangle".into(),
        4 => "quadrilateral".into(),
        k => format!("{k}-gon"),
    }
}

/// "P polygons, E edges, V vertices" of `[polygons, sides, vertices]` (E = sides / 2: closed).
fn sizes(counts: [usize; 3]) -> String {
    format!(
        "{} polygons, {} edges, {} vertices",
        counts[0],
        counts[1] / 2,
        counts[2]
    )
}

impl fmt::Display for Mismatch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "after {} of {} polygons matched, polygon {} of the first does not lie on polygon {} \
             of the second{}: ",
            self.polygons_matched,
            self.polygons,
            self.polygon_a,
            self.polygon_b,
            if self.reflected { " (mirrored)" } else { "" }
        )?;
        match self.what {
            MismatchKind::Sides { a, b } => write!(
                f,
                "one is a {}, the other a {}",
                polygon_name(a),
                polygon_name(b)
            ),
            MismatchKind::Length { a, b } => {
                write!(f, "a side {a} long would lie on a side {b} long")
            }
            MismatchKind::Corner { corner, distance } => write!(
                f,
                "its corner {corner} lands {distance:e} away from the other's corner"
            ),
            MismatchKind::Gluing => write!(
                f,
                "a side is glued to a different neighbour than the correspondence already chose"
            ),
        }
    }
}

impl Outcome {
    /// Whether the outcome is [`Outcome::Isometric`].
    pub fn is_isometric(&self) -> bool {
        matches!(self, Outcome::Isometric { .. })
    }

    /// The reason in words (without the verdict): which counts, polygon, side or length
    /// differs, or which polygons a correspondence lays onto each other.
    pub fn reason(&self) -> String {
        match self {
            Outcome::Isometric {
                reflected,
                polygons,
                sides,
                length,
                counts,
                ..
            } => format!(
                "the canonical Delaunay tessellations ({}) correspond: an isometry{} lays polygon \
                 {} of the first, a {}, onto polygon {} of the second, its side {length} long on \
                 theirs, and every other polygon onto one of the second",
                sizes(*counts),
                if *reflected {
                    " reversing orientation"
                } else {
                    ""
                },
                polygons[0],
                polygon_name(*sides),
                polygons[1],
            ),
            Outcome::Counts { a, b } => format!(
                "the canonical Delaunay tessellations differ in size: {} against {}",
                sizes(*a),
                sizes(*b)
            ),
            Outcome::PolygonSizes { sides, a, b } => format!(
                "the canonical Delaunay tessellations have {a} and {b} {}s",
                polygon_name(*sides)
            ),
            Outcome::Lengths {
                rank,
                a,
                b,
                sides,
                tolerance,
            } => format!(
                "the edge lengths differ: the {} shortest side of a {} is {a} long in the \
                 first and {b} in the second (more than the tolerance {tolerance:e} apart)",
                ordinal(rank + 1),
                polygon_name(*sides)
            ),
            Outcome::NoCandidate {
                side_a,
                polygon_a,
                sides,
                length,
            } => format!(
                "side {side_a} of the first (in polygon {polygon_a}, a {}) is {length} long; no \
                 {} of the second has a side of that length",
                polygon_name(*sides),
                polygon_name(*sides)
            ),
            Outcome::NoCorrespondence {
                candidates,
                closest,
            } => format!(
                "the counts, polygon sizes and edge lengths agree, but none of the {candidates} \
                 ways of laying one polygon onto another extends to the whole surface; the \
                 closest: {closest}"
            ),
        }
    }
}

impl fmt::Display for Outcome {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let verdict = if self.is_isometric() {
            "isometric"
        } else {
            "not isometric"
        };
        write!(f, "{verdict}: {}", self.reason())
    }
}

/// The canonical Delaunay tessellation of a closed surface (Dubois, Section 1.2): flip to
/// Delaunay, remove flat vertices, flip again, merge co-circular triangles. Consumes the
/// triangulation (it is flipped in place). Returns the tessellation's portalgon.
///
/// # Errors
/// [`IsometryError::Delaunay`] or [`IsometryError::Removal`] (with `surface` = `surface`).
pub fn canonical_tessellation(
    mut tri: IntrinsicTriangulation,
    options: &IsometryOptions,
    surface: usize,
) -> Result<Portalgon, IsometryError> {
    let delaunay = |tri: &mut IntrinsicTriangulation, options: &DelaunayOptions| {
        flip_to_delaunay(tri, options).map_err(|source| IsometryError::Delaunay { surface, source })
    };
    delaunay(&mut tri, &options.delaunay)?;
    remove_flat_vertices(&mut tri, options.angle_tolerance)
        .map_err(|source| IsometryError::Removal { surface, source })?;
    let again = DelaunayOptions {
        mollify: None,
        ..options.delaunay
    };
    delaunay(&mut tri, &again)?;
    Ok(delaunay_tessellation(&tri, options.cocircular_tolerance).portalgon)
}

/// Whether two closed surfaces are isometric (Corollary 2), with the reason.
///
/// # Errors
/// As [`canonical_tessellation`] for either surface.
pub fn isometric(
    a: IntrinsicTriangulation,
    b: IntrinsicTriangulation,
    options: &IsometryOptions,
) -> Result<Outcome, IsometryError> {
    let ta = canonical_tessellation(a, options, 0)?;
    let tb = canonical_tessellation(b, options, 1)?;
    compare_tessellations(&ta, &tb, options.length_tolerance, options.allow_reflection)
        .map_err(|(surface, source)| IsometryError::Portalgon { surface, source })
}

/// Whether two closed portalgons are equal up to rigid motions of their polygons and renaming
/// (Appendix A.3), with `tolerance` relative to the longest side. O(n) per candidate seed, O(n²)
/// in the worst case.
///
/// # Errors
/// `(0 or 1, PortalgonError::Unmatched or Empty)` if a portalgon is not closed.
pub fn compare_tessellations(
    a: &Portalgon,
    b: &Portalgon,
    tolerance: f64,
    allow_reflection: bool,
) -> Result<Outcome, (usize, PortalgonError)> {
    let dense =
        |p: &Portalgon| p.polygon_slots() == p.polygon_count() && p.side_slots() == p.side_count();
    let (a_copy, b_copy);
    let a = if dense(a) {
        a
    } else {
        a_copy = a.compacted().0;
        &a_copy
    };
    let b = if dense(b) {
        b
    } else {
        b_copy = b.compacted().0;
        &b_copy
    };
    a.check_closed().map_err(|e| (0, e))?;
    b.check_closed().map_err(|e| (1, e))?;
    let counts = |p: &Portalgon| [p.polygon_count(), p.side_count(), p.vertex_classes().1];
    if counts(a) != counts(b) {
        return Ok(Outcome::Counts {
            a: counts(a),
            b: counts(b),
        });
    }
    let histogram = |p: &Portalgon| {
        let mut h = vec![0usize; p.side_count() + 1];
        for q in p.polygons() {
            h[p.polygon_sides(q).len()] += 1;
        }
        h
    };
    let (ha, hb) = (histogram(a), histogram(b));
    if let Some(k) = (0..ha.len()).find(|&k| ha[k] != hb[k]) {
        return Ok(Outcome::PolygonSizes {
            sides: k,
            a: ha[k],
            b: hb[k],
        });
    }
    // Sides sorted by (polygon size, length): with equal size histograms the two lists align
    // rank by rank, and their lengths must agree (this also seeds the search below).
    let keyed = |p: &Portalgon| {
        let mut v: Vec<(usize, f64, SideId)> = p
            .sides()
            .map(|s| (p.polygon_sides(p.owner(s)).len(), p.side_length(s), s))
            .collect();
        v.sort_by(|x, y| x.0.cmp(&y.0).then(x.1.total_cmp(&y.1)));
        v
    };
    let (keyed_a, keyed_b) = (keyed(a), keyed(b));
    let longest = keyed_a
        .iter()
        .chain(&keyed_b)
        .fold(0.0f64, |m, x| m.max(x.1));
    let eps = tolerance * longest;
    if let Some(rank) = (0..keyed_a.len()).find(|&k| (keyed_a[k].1 - keyed_b[k].1).abs() > eps) {
        return Ok(Outcome::Lengths {
            rank,
            a: keyed_a[rank].1,
            b: keyed_b[rank].1,
            sides: keyed_a[rank].0,
            tolerance: eps,
        });
    }
    let mut tried = 0usize;
    let (seed, candidates) = seed_side(&keyed_a, &keyed_b, eps);
    let seed_sides = a.polygon_sides(a.owner(seed)).len();
    if candidates.is_empty() {
        return Ok(Outcome::NoCandidate {
            side_a: seed.0,
            polygon_a: a.owner(seed).0,
            sides: seed_sides,
            length: a.side_length(seed),
        });
    }
    let mut closest: Option<Mismatch> = None;
    for reflected in [false, true] {
        if reflected && !allow_reflection {
            break;
        }
        let mirrored;
        let target = if reflected {
            mirrored = b.mirrored();
            &mirrored
        } else {
            b
        };
        for &(_, _, s_b) in &keyed_b[candidates.clone()] {
            // The mirror keeps polygon ids; side i of a k-gon becomes side k - 1 - i.
            let s_t = if reflected {
                let p = b.owner(s_b);
                let k = b.polygon_sides(p).len();
                target.side(p, k - 1 - b.side_index(s_b))
            } else {
                s_b
            };
            tried += 1;
            match correspondence(a, target, seed, s_t, eps) {
                Ok(()) => {
                    return Ok(Outcome::Isometric {
                        side_a: seed.0,
                        side_b: s_b.0,
                        reflected,
                        polygons: [a.owner(seed).0, b.owner(s_b).0],
                        sides: seed_sides,
                        length: a.side_length(seed),
                        counts: counts(a),
                    });
                }
                Err(mut mismatch) => {
                    mismatch.reflected = reflected;
                    if closest
                        .as_ref()
                        .is_none_or(|c| mismatch.polygons_matched > c.polygons_matched)
                    {
                        closest = Some(mismatch);
                    }
                }
            }
        }
    }
    Ok(Outcome::NoCorrespondence {
        candidates: tried,
        closest: closest.expect("at least one candidate was tried"),
    })
}

/// The seed of [`compare_tessellations`]' search: the side of `a` with the fewest candidates in
/// `b` (same polygon size, same length within `eps`; ties to the lower side id), and the range of
/// `keyed_b` holding those candidates, found by sweeping both lists (sorted by polygon size,
/// then length) with two pointers.
fn seed_side(
    keyed_a: &[(usize, f64, SideId)],
    keyed_b: &[(usize, f64, SideId)],
    eps: f64,
) -> (SideId, std::ops::Range<usize>) {
    let (mut lo, mut hi) = (0usize, 0usize);
    let mut best: Option<(usize, SideId, std::ops::Range<usize>)> = None;
    for &(k, l, s) in keyed_a {
        while lo < keyed_b.len() && (keyed_b[lo].0, keyed_b[lo].1) < (k, l - eps) {
            lo += 1;
        }
        hi = hi.max(lo);
        while hi < keyed_b.len() && (keyed_b[hi].0, keyed_b[hi].1) <= (k, l + eps) {
            hi += 1;
        }
        if best
            .as_ref()
            .is_none_or(|(count, s0, _)| (hi - lo, s.0) < (*count, s0.0))
        {
            best = Some((hi - lo, s, lo..hi));
        }
    }
    let (_, seed, candidates) = best.expect("a closed portalgon has sides");
    (seed, candidates)
}

/// Tries to build the side correspondence from `seed_a ↦ seed_b` by propagation through polygons
/// and the matching; checks each polygon is congruent to its image (corners within `eps`).
/// Returns where it failed otherwise (`reflected` is the caller's to set).
fn correspondence(
    a: &Portalgon,
    b: &Portalgon,
    seed_a: SideId,
    seed_b: SideId,
    eps: f64,
) -> Result<(), Mismatch> {
    let mut phi = vec![SideId::INVALID; a.side_slots()];
    let mut inverse = vec![SideId::INVALID; b.side_slots()];
    let mut stack = vec![(seed_a, seed_b)];
    let mut polygons_done = 0usize;
    let (mut pa, mut pb) = (a.owner(seed_a), b.owner(seed_b));
    let fail = |pa: crate::portalgon::PolygonId,
                pb: crate::portalgon::PolygonId,
                done: usize,
                what: MismatchKind| Mismatch {
        polygons_matched: done,
        polygons: a.polygon_count(),
        polygon_a: pa.0,
        polygon_b: pb.0,
        what,
        reflected: false,
    };
    while let Some((sa, sb)) = stack.pop() {
        if phi[sa.idx()].is_valid() {
            if phi[sa.idx()] != sb {
                return Err(fail(
                    a.owner(sa),
                    b.owner(sb),
                    polygons_done,
                    MismatchKind::Gluing,
                ));
            }
            continue;
        }
        (pa, pb) = (a.owner(sa), b.owner(sb));
        let (sides_a, sides_b) = (a.polygon_sides(pa), b.polygon_sides(pb));
        let k = sides_a.len();
        if sides_b.len() != k {
            let what = MismatchKind::Sides {
                a: k,
                b: sides_b.len(),
            };
            return Err(fail(pa, pb, polygons_done, what));
        }
        let (la, lb) = (a.side_length(sa), b.side_length(sb));
        if (la - lb).abs() > eps {
            let what = MismatchKind::Length { a: la, b: lb };
            return Err(fail(pa, pb, polygons_done, what));
        }
        let (ia, ib) = (a.side_index(sa), b.side_index(sb));
        // The motion is taken from the polygon's longest side (with its image), not from the side
        // the propagation arrived by: a side much shorter than its polygon fixes the rotation only
        // up to (rounding of its ends) / (its length), which can move the far corners by more
        // than the tolerance (a vertex 1e-12 from another makes such a side).
        let m = (0..k)
            .max_by(|&x, &y| {
                let length = |m: usize| a.side_length(sides_a[(ia + m) % k]);
                length(x).total_cmp(&length(y))
            })
            .expect("a polygon has sides");
        let (xa, xb) = (sides_a[(ia + m) % k], sides_b[(ib + m) % k]);
        let motion = Motion::gluing(
            a.start_ref(xa),
            a.end_ref(xa),
            b.start_ref(xb),
            b.end_ref(xb),
        );
        let moved = |x: Point2| motion.apply(&x);
        for m in 0..k {
            let (xa, xb) = (sides_a[(ia + m) % k], sides_b[(ib + m) % k]);
            if phi[xa.idx()].is_valid() || inverse[xb.idx()].is_valid() {
                return Err(fail(pa, pb, polygons_done, MismatchKind::Gluing));
            }
            let (p, q) = (moved(a.start(xa)), b.start(xb));
            let distance = (p[0] - q[0]).hypot(p[1] - q[1]);
            if distance > 4.0 * eps {
                let what = MismatchKind::Corner {
                    corner: (ia + m) % k,
                    distance,
                };
                return Err(fail(pa, pb, polygons_done, what));
            }
            phi[xa.idx()] = xb;
            inverse[xb.idx()] = xa;
        }
        for m in 0..k {
            let (xa, xb) = (sides_a[(ia + m) % k], sides_b[(ib + m) % k]);
            match (a.mate(xa), b.mate(xb)) {
                (Some(ma), Some(mb)) => {
                    if phi[ma.idx()].is_valid() {
                        if phi[ma.idx()] != mb {
                            return Err(fail(pa, pb, polygons_done, MismatchKind::Gluing));
                        }
                    } else {
                        stack.push((ma, mb));
                    }
                }
                (None, None) => {}
                _ => return Err(fail(pa, pb, polygons_done, MismatchKind::Gluing)),
            }
        }
        polygons_done += 1;
    }
    if polygons_done == a.polygon_count() {
        Ok(())
    } else {
        // The propagation stopped short: the first is not connected the way the second is.
        Err(fail(pa, pb, polygons_done, MismatchKind::Gluing))
    }
}
