//! The intrinsic Delaunay triangulation by edge flipping.
//!
//! Bobenko & Springborn, "A discrete Laplace–Beltrami operator for simplicial surfaces", Discrete
//! Comput. Geom. 38 (2007), Section 2 and Proposition 10: flipping, in any order, every edge whose
//! two opposite angles sum to more than π reaches a Delaunay triangulation of the surface with the
//! same vertex set; Indermitte, Liebling, Troyanov & Clémençon (Theor. Comput. Sci. 263, 2001)
//! proved that the process terminates. The number of flips is *not* bounded by a function of the
//! number of triangles (Dubois, Section 1.1 and Section 9: the flat torus T_x needs about x flips),
//! so every run has a flip budget and fails with a typed error instead of running on.
//!
//! Numerics (see [`crate::triangulation::trig`]): the test of an edge is `tan(γ/2) · tan(δ/2) > 1 + tolerance`
//! with the half-angle tangents from Kahan's ordered factors — relative error a few ulps, no
//! cancellation even for needles; the new length after a flip comes from a sum of non-negative
//! terms (`|cd|² = (|ac| - |ad|)² + 4|ac||ad| sin²(θ/2)`). Every new length is checked: a
//! non-finite length, or new triangles that fail the triangle inequality, stop the run with
//! [`DelaunayError::NumericalBreakdown`] — that is where double precision ends (e.g. on T_x).
//!
//! Flips that create loops or multi-edges are allowed (real intrinsic Delaunay triangulations have
//! them). An edge whose two sides are the same face is never non-Delaunay (its two opposite angles
//! are the base angles of an isosceles triangle) and is never flipped.

pub(crate) mod needle;
pub(crate) mod stats;
pub(crate) mod tessellation;

use crate::error::DelaunayError;
use crate::geometry::Tolerances;
use crate::triangulation::mollify::mollify;
use crate::triangulation::{IntrinsicTriangulation, store_tan_half_sq};
use surftopo_mesh::{EdgeId, HalfedgeId, SurfaceMesh};

/// Default [`DelaunayOptions::tolerance`], [`Tolerances::delaunay`]'s default (its doc says why
/// 1e-10), as a constant for the callers that take one.
pub const DEFAULT_TOLERANCE: f64 = Tolerances::DEFAULT.delaunay;

/// Default flip budget: `10_000_000 + 1000 · edges` (see [`DelaunayOptions::max_flips`]).
pub fn default_max_flips(edges: usize) -> u64 {
    10_000_000 + 1000 * edges as u64
}

/// Options of [`flip_to_delaunay`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DelaunayOptions {
    /// Stop with [`DelaunayError::MaxFlips`] after this many flips; `None` means
    /// [`default_max_flips`] of the edge count (so nothing ever runs unbounded).
    pub max_flips: Option<u64>,
    /// Mollify degenerate input first ([`crate::mollify()`]) with this ε relative to the mean edge
    /// length; `None` rejects degenerate input with a [`crate::GeometryError`].
    pub mollify: Option<f64>,
    /// Relative tolerance of the Delaunay test (see [`DEFAULT_TOLERANCE`]).
    pub tolerance: f64,
}

impl Default for DelaunayOptions {
    fn default() -> Self {
        Self {
            max_flips: None,
            mollify: None,
            tolerance: Tolerances::DEFAULT.delaunay,
        }
    }
}

/// What [`flip_to_delaunay`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FlipReport {
    /// Number of flips.
    pub flips: u64,
    /// The δ added to every length by mollification (`None` when not asked; `Some(0.0)` when asked
    /// but not needed).
    pub mollify_delta: Option<f64>,
    /// Edges still not Delaunay up to the tolerance at the end (0 on success; counted independently
    /// of the work queue).
    pub non_delaunay_edges: usize,
}

/// Flips `tri` to an intrinsic Delaunay triangulation of the same surface with the same vertices.
///
/// Takes any closed intrinsic triangulation; on success every edge satisfies
/// `tan(γ/2) tan(δ/2) <= 1 + tolerance`, the surface (total area, every vertex's angle sum) is
/// unchanged up to rounding, and edge ids are kept (a flip keeps its edge id). Work: one test per
/// edge (a sweep in id order), then O(1) per flip (each flip re-queues the four edges of its quad
/// on a stack, emptied before the sweep moves on); the number of flips is finite but unbounded in
/// the input size.
///
/// # Errors
/// [`DelaunayError::Geometry`] for unusable input (zero or non-finite length, violated triangle
/// inequality, zero-area face) unless `mollify` is set; [`DelaunayError::MaxFlips`] when the budget
/// is exhausted (the triangulation is left valid, partly flipped);
/// [`DelaunayError::NumericalBreakdown`] when double precision no longer yields valid triangles;
/// [`DelaunayError::InvalidMollify`], [`DelaunayError::InvalidTolerance`].
pub fn flip_to_delaunay(
    tri: &mut IntrinsicTriangulation,
    options: &DelaunayOptions,
) -> Result<FlipReport, DelaunayError> {
    flip_keeping_tan_half_sq(tri, options).map(|(report, _)| report)
}

/// [`flip_to_delaunay`], also returning the half-angle cache it keeps up to date: `tan²(θ/2)` of
/// the angle θ opposite every half-edge of the final triangulation (by half-edge id), equal bit for
/// bit to [`IntrinsicTriangulation::halfedge_tan_half_sq`] of the result.
pub(crate) fn flip_keeping_tan_half_sq(
    tri: &mut IntrinsicTriangulation,
    options: &DelaunayOptions,
) -> Result<(FlipReport, Vec<f64>), DelaunayError> {
    let flipped = flip_unless(tri, options, false)?;
    Ok(flipped.expect("no face is refused"))
}

/// [`flip_to_delaunay`] for `--method auto` ([`crate::choose_method`]): `Ok(None)`, before any
/// flip and with the triangulation unchanged (mollified first when `options.mollify` asks), when
/// some triangle's aspect ratio exceeds [`needle::AUTO_ASPECT_LIMIT`] (a degenerate
/// one counts). The needle test reads the half-angle cache flipping's own first pass fills
/// (`needle::has_needle_given_half_angles`), so `auto` costs flipping next to
/// nothing on the inputs it flips.
///
/// # Errors
/// As [`flip_to_delaunay`].
pub fn flip_to_delaunay_unless_needle(
    tri: &mut IntrinsicTriangulation,
    options: &DelaunayOptions,
) -> Result<Option<FlipReport>, DelaunayError> {
    let flipped = flip_unless(tri, options, true)?;
    Ok(flipped.map(|(report, _)| report))
}

/// The flip algorithm; with `stop_at_needle`, `Ok(None)` when some face is a needle after the
/// first pass (before any flip: [`needle::has_needle_given_half_angles`], one scan
/// of the half-angle cache that pass fills). A flag rather than a closure: `flip` and `auto` run
/// the same machine code, which differs only by that scan.
pub(crate) fn flip_unless(
    tri: &mut IntrinsicTriangulation,
    options: &DelaunayOptions,
    stop_at_needle: bool,
) -> Result<Option<(FlipReport, Vec<f64>)>, DelaunayError> {
    flip_glued(tri, options, stop_at_needle, &mut Closed)
}

/// What the flip algorithm asks of the surface beyond the mesh: which edges may flip, and which
/// edge flips together with one (see [`crate::covered`]). [`Closed`] is a closed oriented surface,
/// the mesh itself: every edge may flip, none has a partner; monomorphised with it the algorithm
/// is the plain one.
pub(crate) trait Gluing {
    /// Whether edge `e` may flip (the mesh's own rule, two distinct faces, is checked apart).
    fn may_flip(&self, mesh: &SurfaceMesh, e: EdgeId) -> bool;
    /// The half-edge whose edge flips together with the edge of `h`, seen as `h` is (the same
    /// quad up to an isometry, `h`'s ends and left face matching), if any.
    fn partner(&self, h: HalfedgeId) -> Option<HalfedgeId>;
    /// Called after the edge of `h` and its partner `p` flipped.
    fn flipped(&mut self, mesh: &SurfaceMesh, h: HalfedgeId, p: HalfedgeId);
}

/// A closed oriented surface: the mesh itself (see [`Gluing`]).
pub(crate) struct Closed;

impl Gluing for Closed {
    #[inline(always)]
    fn may_flip(&self, _: &SurfaceMesh, _: EdgeId) -> bool {
        true
    }
    #[inline(always)]
    fn partner(&self, _: HalfedgeId) -> Option<HalfedgeId> {
        None
    }
    #[inline(always)]
    fn flipped(&mut self, _: &SurfaceMesh, _: HalfedgeId, _: HalfedgeId) {}
}

/// [`flip_unless`] on a surface glued as `gluing` says: edges it forbids are never flipped (nor
/// counted as non-Delaunay), and an edge's partner flips with it.
pub(crate) fn flip_glued<G: Gluing>(
    tri: &mut IntrinsicTriangulation,
    options: &DelaunayOptions,
    stop_at_needle: bool,
    gluing: &mut G,
) -> Result<Option<(FlipReport, Vec<f64>)>, DelaunayError> {
    let tol = options.tolerance;
    if !(tol.is_finite() && tol >= 0.0) {
        return Err(DelaunayError::InvalidTolerance(tol));
    }
    let mut report = FlipReport::default();
    if let Some(eps) = options.mollify {
        report.mollify_delta = Some(mollify(tri, eps)?);
    }
    // Validation and the half-angle cache in one pass: t2[h] = tan²(θ/2) of the angle opposite h.
    for e in tri.mesh().edges() {
        let value = tri.length(e);
        if !(value.is_finite() && value > 0.0) {
            tri.validate()?;
        }
    }
    let mut t2 = vec![f64::NAN; tri.mesh().halfedge_slots()];
    for f in tri.mesh().faces() {
        let halfedges = tri.mesh().face_halfedges(f);
        let sides = halfedges.map(|h| tri.halfedge_length(h));
        let smallest = store_tan_half_sq(halfedges, sides, &mut t2);
        if smallest.is_nan() || smallest <= 0.0 {
            // A degenerate triangle counts as a needle ([`needle::is_needle`]).
            if stop_at_needle {
                return Ok(None);
            }
            tri.validate()?;
        }
    }
    if stop_at_needle && needle::has_needle_given_half_angles(tri, &t2) {
        return Ok(None);
    }
    let max_flips = options
        .max_flips
        .unwrap_or_else(|| default_max_flips(tri.mesh().edge_count()));
    let bound = product_bound(tol);

    // A sweep over the edges in id order; each flip pushes the four edges of its quad on a stack,
    // emptied before the sweep goes on. Every edge is thus tested after its last change.
    let slots = tri.mesh().edge_slots();
    let mut queued = vec![false; slots];
    let mut stack: Vec<EdgeId> = Vec::new();
    let mut ticker = surftopo_mesh::stop::Ticker::default();
    for sweep in 0..slots {
        let first = EdgeId::new(sweep);
        if !tri.mesh().is_edge_live(first) {
            continue;
        }
        let mut next = Some(first);
        while let Some(e) = next {
            ticker.tick();
            let h = e.halfedge();
            let t = h.twin();
            let mesh = tri.mesh();
            let product = t2[h.idx()] * t2[t.idx()];
            if product > bound && mesh.face(h) != mesh.face(t) && gluing.may_flip(mesh, e) {
                if report.flips >= max_flips {
                    return Err(DelaunayError::MaxFlips {
                        flips: report.flips,
                        pending: stack.len() + 1,
                    });
                }
                let partner = gluing.partner(h);
                let sides = flip_one(tri, &mut t2, h, report.flips)?;
                report.flips += 1;
                for g in sides {
                    let ge = g.edge();
                    if !queued[ge.idx()] {
                        queued[ge.idx()] = true;
                        stack.push(ge);
                    }
                }
                if let Some(p) = partner {
                    for g in flip_one(tri, &mut t2, p, report.flips)? {
                        let ge = g.edge();
                        if !queued[ge.idx()] {
                            queued[ge.idx()] = true;
                            stack.push(ge);
                        }
                    }
                    gluing.flipped(tri.mesh(), h, p);
                }
            }
            next = stack.pop();
            if let Some(e) = next {
                queued[e.idx()] = false;
            }
        }
    }
    // Counted afresh over every edge, independently of the work queue.
    let mesh = tri.mesh();
    report.non_delaunay_edges = mesh
        .edges()
        .filter(|&e| left_non_delaunay(mesh, &t2, bound, e) && gluing.may_flip(mesh, e))
        .count();
    Ok(Some((report, t2)))
}

/// The bound on `tan²(γ/2) tan²(δ/2)` of a Delaunay edge: `(1 + tolerance)²`.
#[inline]
pub(crate) fn product_bound(tolerance: f64) -> f64 {
    (1.0 + tolerance) * (1.0 + tolerance)
}

/// Whether flipping left edge `e` non-Delaunay: `tan²(γ/2) tan²(δ/2)` from the half-angle cache
/// `t2` above `bound` ([`product_bound`]) or not a number, with two distinct faces.
#[inline]
pub(crate) fn left_non_delaunay(mesh: &SurfaceMesh, t2: &[f64], bound: f64, e: EdgeId) -> bool {
    let h = e.halfedge();
    let p = t2[h.idx()] * t2[h.twin().idx()];
    (p.is_nan() || p > bound) && mesh.face(h) != mesh.face(h.twin())
}

/// Flips the edge of `h = a -> b` (the caller decided it), sets its new length and the half-angle
/// cache `t2` of its two new triangles; returns the four sides of the quad. `flips` is the count
/// so far, for the error.
///
/// # Errors
/// [`DelaunayError::NumericalBreakdown`] when the new length is not a positive finite number or
/// the new triangles fail the triangle inequality as rounded.
#[inline(always)]
fn flip_one(
    tri: &mut IntrinsicTriangulation,
    t2: &mut [f64],
    h: HalfedgeId,
    flips: u64,
) -> Result<[HalfedgeId; 4], DelaunayError> {
    let e = h.edge();
    let t = h.twin();
    let mesh = tri.mesh();
    // Quad a -> b with c on the left, d on the right: h1 = b -> c, h2 = c -> a, t1 = a -> d,
    // t2 = d -> b. The angles at a are opposite h1 (in the left triangle) and t2 (in the right
    // one).
    let (h1, h2) = (mesh.next(h), mesh.prev(h));
    let (t1, t2h) = (mesh.next(t), mesh.prev(t));
    let [bc, ca, ad, db] = [h1, h2, t1, t2h].map(|g| tri.halfedge_length(g));
    let length = crate::triangulation::trig::chord(t2[h1.idx()], t2[t2h.idx()], ca, ad);
    if !(length.is_finite() && length > 0.0) {
        return Err(DelaunayError::NumericalBreakdown {
            edge: e.0,
            flips,
            length,
        });
    }
    tri.apply_flip(e, length);
    // The new triangles are (h: d -> c, h2, t1) and (t: c -> d, t2, h1).
    let s0 = store_tan_half_sq([h, h2, t1], [length, ca, ad], t2);
    let s1 = store_tan_half_sq([t, t2h, h1], [length, db, bc], t2);
    if s0.is_nan() || s0 <= 0.0 || s1.is_nan() || s1 <= 0.0 {
        // The new triangles fail the triangle inequality: rounding has taken over.
        return Err(DelaunayError::NumericalBreakdown {
            edge: e.0,
            flips,
            length,
        });
    }
    Ok([h2, t1, t2h, h1])
}
