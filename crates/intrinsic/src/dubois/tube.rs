//! Tubes (Dubois, Section 3) and Proposition 4 (Appendix B): replacing a tube by a good biface.
//!
//! A *tube* is a triangular portalgon whose surface is an annulus, flat inside, with exactly one
//! vertex on each boundary component ([`Portalgon::tube`]). [`Portalgon::good_biface_of_tube`]
//! computes a good biface of its surface by one of two routes ([`TubeRoute`]):
//! - [`TubeRoute::Paper`], Appendix B's proof of Proposition 4: Lemma 28 (delete maximal
//!   independent sets of interior weak vertices of degree ≤ 10, re-triangulating by shortcuts,
//!   until every interior vertex is on a loop: a concatenation of fewer than 3n bifaces), Lemma 25
//!   on each biface, then Lemma 26 merging consecutive good bifaces one by one;
//! - [`TubeRoute::Direct`], docs/dubois.md §3.1(c) (a *reconstruction*): unfold the whole tube into
//!   one chart along a dual spanning tree, read the deck transformation `g` off a non-tree side,
//!   sum the angle `ψ₀` around `g`'s centre along a path of the chart, and apply the kernel of
//!   [`crate::dubois::biface`] once: O(n + log h) operations.
//!
//! Lemmas 25 and 26 delegate to exhaustive searches on portalgons of constant happiness; here both
//! are the ladder kernel [`good_biface_of_ladder`] on the unfolded biface (2 triangles) or
//! concatenation (4 triangles) — a reconstruction, checked by the random-tube tests of
//! `tests/bifaces.rs` (both routes give the same biface, which the brute-force ladder oracle
//! confirms good, of the same area, boundary lengths, holonomy and angle at `b₀`).
//!
//! **Both routes give the same biface** when the good biface is unique. With ties of lengths
//! (a rectangle, two shortest paths) several bifaces are good, and the tie rule that keeps the
//! current edges makes the answer depend on the intermediate bifaces: the routes may then return
//! different good bifaces (both good; the random-tube test counts these cases).
//!
//! **Default: [`TubeRoute::Direct`].** It does one unfolding and one kernel call, O(n) plus the
//! kernel, against Lemma 28's O(n log n) deletions and re-triangulations followed by O(n) kernel
//! calls; it also never builds the intermediate bifaces whose edges Lemma 28 only bounds by
//! `(3n)^15·L`. The paper's route is kept as the faithful variant and as a cross-check.

use std::cmp::Ordering;
use std::collections::hash_map::Entry;
use std::collections::{HashMap, HashSet};

use crate::dubois::biface::{Biface, BifaceError, GoodBiface, good_biface_of_ladder};
use crate::error::PortalgonError;
use crate::geometry::{Motion, Point, Scalar, complex_div, complex_mul, cross, dist2, dot, sub};
use crate::portalgon::{EditError, VertexInfo};
use crate::portalgon::{PolygonId, Portalgon, SideId};

/// Lemma 28 deletes interior weak vertices of degree at most this.
pub const LEMMA_28_MAX_DEGREE: u32 = 10;

/// How [`Portalgon::good_biface_of_tube`] proceeds (see the module documentation).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TubeRoute {
    /// docs/dubois.md §3.1(c): one unfolding, one kernel call (the default).
    #[default]
    Direct,
    /// Appendix B: Lemma 28, Lemma 25 on each biface, Lemma 26's merges.
    Paper,
}

/// Why a sub-portalgon is not a tube, or Proposition 4 failed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TubeError {
    /// A polygon is not a triangle.
    #[error("polygon {polygon} has {sides} sides: a tube is triangular")]
    NotTriangular {
        /// The polygon.
        polygon: usize,
        /// Its number of sides.
        sides: usize,
    },
    /// The surface is not an annulus whose two boundary components are single sides at distinct
    /// vertices.
    #[error(
        "not a tube: {components} components, Euler characteristic {euler}, boundary cycles of {cycles:?} sides"
    )]
    NotAnnulus {
        /// Connected components.
        components: usize,
        /// Euler characteristic of the first.
        euler: i64,
        /// Sides per boundary cycle of the first.
        cycles: Vec<usize>,
    },
    /// An interior vertex is a singularity (its angle is not 2π: exactly in exact mode, within
    /// the relative tolerance in f64).
    #[error("interior vertex at the start of side {side} has angle {angle} (not 2π)")]
    NotFlat {
        /// A side starting at the vertex.
        side: usize,
        /// Its angle, as a double.
        angle: f64,
    },
    /// No deck transformation maps the `b₀` side's end onto its start and the `b₁` side's start
    /// onto its end (an inconsistent chart).
    #[error("no side of the unfolded tube carries the gluing of its boundary side {side}")]
    NoHolonomy {
        /// The `b₀` boundary side.
        side: usize,
    },
    /// The kernel failed.
    #[error(transparent)]
    Biface(#[from] BifaceError),
    /// An edit failed.
    #[error(transparent)]
    Edit(#[from] EditError),
    /// A portalgon edit (Lemma 28's deletions) failed.
    #[error(transparent)]
    Portalgon(#[from] PortalgonError),
}

/// A recognised tube: its polygons and boundary sides.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Tube {
    /// Its triangles.
    pub polygons: Vec<PolygonId>,
    /// The boundary sides `[β₀, β₁]` (single-side loops at `b₀` and `b₁`; [`Portalgon::tube`]
    /// puts the lower id first).
    pub boundary: [SideId; 2],
}

/// What Proposition 4 did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TubeReport {
    /// The route taken.
    pub route: TubeRoute,
    /// Triangles of the tube.
    pub triangles: usize,
    /// Lemma 28: rounds of deletions, and vertices deleted.
    pub deletion_rounds: usize,
    /// Lemma 28: vertices deleted.
    pub deleted_vertices: usize,
    /// Bifaces of the concatenation after Lemma 28 (1 for the direct route).
    pub bifaces: usize,
    /// Lemma 26 merges.
    pub merges: usize,
}

/// One chart of a tube's universal cover: the kernel's input.
struct Chart<S: Scalar> {
    p0: Point<S>,
    p1: Point<S>,
    q0: Point<S>,
    g: Motion<S>,
    psi0: f64,
}

/// `Arg(b/a)` in `(−π, π]`, as a double from the exact quotient.
fn angle_between<S: Scalar>(a: &Point<S>, b: &Point<S>) -> f64 {
    let r = complex_div(b, a);
    r[1].to_f64().atan2(r[0].to_f64())
}

impl<S: Scalar> Portalgon<S> {
    /// Whether the sub-portalgon of `polygons` is a tube (Section 3): triangular, one component,
    /// an annulus (Euler characteristic 0, two boundary cycles) whose boundary cycles are single
    /// sides at distinct vertices, every interior vertex flat (angle 2π: exactly in exact mode by
    /// the corner angles' complex product and winding, within `tolerance · 2π` in f64).
    ///
    /// # Errors
    /// [`TubeError::NotTriangular`], [`TubeError::NotAnnulus`], [`TubeError::NotFlat`],
    /// [`TubeError::Edit`] for a removed or repeated polygon.
    pub fn tube(&self, polygons: &[PolygonId], tolerance: f64) -> Result<Tube, TubeError> {
        for &p in polygons {
            if self.is_polygon_live(p) && self.polygon_sides(p).len() != 3 {
                return Err(TubeError::NotTriangular {
                    polygon: p.idx(),
                    sides: self.polygon_sides(p).len(),
                });
            }
        }
        let components = self.components(polygons)?;
        let not_annulus = || TubeError::NotAnnulus {
            components: components.len(),
            euler: components.first().map_or(0, |c| c.euler_characteristic),
            cycles: components.first().map_or(Vec::new(), |c| {
                c.boundary_cycles.iter().map(|x| x.len()).collect()
            }),
        };
        if components.len() != 1 || !components[0].is_annulus_with_single_side_boundaries() {
            return Err(not_annulus());
        }
        let c = &components[0];
        let boundary = [c.boundary_cycles[0][0], c.boundary_cycles[1][0]];
        // Distinct boundary vertices: V = 2 + interior vertices.
        if c.vertices != 2 + c.interior_vertices.len() {
            return Err(not_annulus());
        }
        for &s in &c.interior_vertices {
            // Interior: every side around it is matched, so its star closes up.
            let sides = self.star(s).ok_or_else(not_annulus)?;
            let (full_turn, angle) = self.is_full_turn(&sides, tolerance);
            if !full_turn {
                return Err(TubeError::NotFlat {
                    side: s.idx(),
                    angle,
                });
            }
        }
        Ok(Tube {
            polygons: c.polygons.clone(),
            boundary,
        })
    }

    /// Whether the corner angles at the start corners of `sides` (one vertex) add up to 2π, and
    /// their sum as a double. Exact
    /// mode: the product of the corners' complex ratios is a positive real after exactly one turn
    /// (docs/dubois.md §3.5); f64: the `atan2` sum within `tolerance · 2π`.
    pub(crate) fn is_full_turn(&self, sides: &[SideId], tolerance: f64) -> (bool, f64) {
        let mut z: Point<S> = [S::one(), S::zero()];
        let (mut turns, mut angle) = (0u32, 0.0);
        // Arguments in [0, 2π): class 0 = 0, 1 = (0, π), 2 = π, 3 = (π, 2π).
        let class = |z: &Point<S>| match (z[1].sign(), z[0].sign()) {
            (Ordering::Equal, Ordering::Greater) => 0,
            (Ordering::Greater, _) => 1,
            (Ordering::Equal, _) => 2,
            (Ordering::Less, _) => 3,
        };
        let below = |a: &Point<S>, b: &Point<S>| {
            let (ca, cb) = (class(a), class(b));
            ca < cb || (ca == cb && (ca == 1 || ca == 3) && cross(a, b).sign() == Ordering::Greater)
        };
        for &s in sides {
            let o = self.start_ref(s);
            let (u, w) = (self.end_ref(s), self.start_ref(self.prev_side(s)));
            let (du, dw) = (sub(u, o), sub(w, o));
            angle += cross(&du, &dw).to_f64().atan2(dot(&du, &dw).to_f64());
            // w/u up to the positive factor |u|².
            let ratio = [
                dw[0].clone() * du[0].clone() + dw[1].clone() * du[1].clone(),
                dw[1].clone() * du[0].clone() - dw[0].clone() * du[1].clone(),
            ];
            let next = complex_mul(&z, &ratio);
            if below(&next, &z) || (class(&next) == 0 && class(&z) != 0) {
                turns += 1;
            }
            z = next;
        }
        let full = std::f64::consts::TAU;
        let ok = if S::EXACT {
            turns == 1 && class(&z) == 0
        } else {
            (angle - full).abs() <= tolerance * full
        };
        (ok, angle)
    }

    /// Proposition 4: a good biface of the tube of `polygons` (recognised by [`Self::tube`]),
    /// by `route`. The biface's boundary side `CA` is a copy of the tube's `β₀` (same direction)
    /// and `DB` of `β₁`. The portalgon is not changed ([`Self::replace_tube_by_good_biface`]
    /// splices the result in). `tolerance`: relative, on angles and lengths in f64.
    ///
    /// # Errors
    /// [`Self::tube`]'s; the kernel's ([`TubeError::Biface`]); [`TubeError::NoHolonomy`] when the
    /// unfolding finds no gluing taking the `b₀` side's end to its start (up to the tolerance in
    /// f64); Lemma 28's deletions ([`TubeError::Portalgon`]).
    pub fn good_biface_of_tube(
        &self,
        polygons: &[PolygonId],
        route: TubeRoute,
        tolerance: f64,
    ) -> Result<(GoodBiface<S>, TubeReport), TubeError> {
        let tube = self.tube(polygons, tolerance)?;
        let mut report = TubeReport {
            route,
            triangles: tube.polygons.len(),
            bifaces: 1,
            ..TubeReport::default()
        };
        match route {
            TubeRoute::Direct => Ok((self.ladder_kernel(&tube, tolerance)?, report)),
            TubeRoute::Paper => {
                let good = self.paper_route(&tube, tolerance, &mut report)?;
                Ok((good, report))
            }
        }
    }

    /// Proposition 4 in place: replaces the tube of `polygons` by a good biface
    /// ([`Self::good_biface_of_tube`]) with [`Self::splice`], the boundary sides keeping their ids.
    /// Returns the biface's two triangles (`(A, B, C)`, `(A, D, B)`), the biface and the report.
    ///
    /// # Errors
    /// As [`Self::good_biface_of_tube`]; [`TubeError::Edit`] from the splice.
    pub fn replace_tube_by_good_biface(
        &mut self,
        polygons: &[PolygonId],
        route: TubeRoute,
        tolerance: f64,
    ) -> Result<([PolygonId; 2], GoodBiface<S>, TubeReport), TubeError> {
        let tube = self.tube(polygons, tolerance)?;
        let (good, report) = self.good_biface_of_tube(&tube.polygons, route, tolerance)?;
        let labels = tube.boundary.map(|s| self.label[s.idx()]);
        let created = self.splice_biface(&tube, &good.biface, labels, tolerance)?;
        Ok((created, good, report))
    }

    /// Splices `biface` in place of `tube` (its `CA` on `β₀`, its `DB` on `β₁`).
    fn splice_biface(
        &mut self,
        tube: &Tube,
        biface: &Biface<S>,
        labels: [u32; 2],
        tolerance: f64,
    ) -> Result<[PolygonId; 2], TubeError> {
        let (portalgon, [ca, db]) = biface_portalgon(biface, labels);
        let pairs = [(ca, tube.boundary[0]), (db, tube.boundary[1])];
        let created = self.splice(&tube.polygons, &portalgon, &pairs, tolerance)?;
        Ok([created[0], created[1]])
    }

    /// docs/dubois.md §3.1(c) on a tube: unfold, find `g` and `ψ₀`, run the kernel.
    fn ladder_kernel(&self, tube: &Tube, tolerance: f64) -> Result<GoodBiface<S>, TubeError> {
        let chart = self.unfold(tube, tolerance)?;
        Ok(good_biface_of_ladder(
            chart.p0, chart.q0, chart.p1, &chart.g, chart.psi0,
        )?)
    }

    /// Unfolds the tube along a breadth-first dual spanning tree from `β₀`'s triangle (each
    /// triangle placed by footnote 2's motion across its tree side), takes `g` among the
    /// non-tree sides' deck transformations (and their inverses) as the one taking `p₀` (end of
    /// `β₀`) closest to `p₁` (its start), and sums `ψ₀` along the corners shared by the tree path
    /// from `β₀`'s triangle to `β₁`'s.
    fn unfold(&self, tube: &Tube, tolerance: f64) -> Result<Chart<S>, TubeError> {
        // Hash maps, not per-id arrays: unfolding costs the size of the tube, not of `self`.
        let in_tube: HashSet<PolygonId> = tube.polygons.iter().copied().collect();
        let mut placed: HashMap<PolygonId, Motion<S>> = HashMap::with_capacity(in_tube.len());
        let mut parent: HashMap<PolygonId, (PolygonId, SideId)> = HashMap::new();
        let [beta0, beta1] = tube.boundary;
        let root = self.owner(beta0);
        placed.insert(root, Motion::identity());
        let mut queue = std::collections::VecDeque::from([root]);
        let mut non_tree: Vec<(SideId, SideId)> = Vec::new();
        while let Some(p) = queue.pop_front() {
            let mp = placed[&p].clone();
            for &s in self.polygon_sides(p) {
                let Some(t) = self.mate(s).filter(|&t| in_tube.contains(&self.owner(t))) else {
                    continue;
                };
                let q = self.owner(t);
                let tree_side = |x: PolygonId| parent.get(&x).map(|e| e.1);
                if let Entry::Vacant(slot) = placed.entry(q) {
                    let across = Motion::gluing(
                        self.start_ref(t),
                        self.end_ref(t),
                        self.end_ref(s),
                        self.start_ref(s),
                    );
                    slot.insert(mp.compose(&across));
                    parent.insert(q, (p, s));
                    queue.push_back(q);
                } else if s < t && tree_side(q) != Some(s) && tree_side(p) != Some(t) {
                    non_tree.push((s, t));
                }
            }
        }
        let chart_of = |s: SideId| placed[&self.owner(s)].clone();
        let m0 = chart_of(beta0);
        let (p1, p0) = (
            m0.apply(self.start_ref(beta0)),
            m0.apply(self.end_ref(beta0)),
        );
        let m1 = chart_of(beta1);
        let q0 = m1.apply(self.start_ref(beta1));
        // Deck transformations of the non-tree sides: M_P ∘ (t onto s) ∘ M_Q⁻¹.
        let mut best: Option<(S, Motion<S>)> = None;
        for &(s, t) in &non_tree {
            let across = Motion::gluing(
                self.start_ref(t),
                self.end_ref(t),
                self.end_ref(s),
                self.start_ref(s),
            );
            let h = chart_of(s).compose(&across).compose(&chart_of(t).inverse());
            for g in [h.inverse(), h] {
                let e = dist2(&g.apply(&p0), &p1);
                if best.as_ref().is_none_or(|(b, _)| e < *b) {
                    best = Some((e, g));
                }
            }
        }
        let scale2 = dist2(&p0, &p1);
        let Some((err, g)) = best else {
            return Err(TubeError::NoHolonomy { side: beta0.idx() });
        };
        // g must also take the b₁ side's start to its end (docs/dubois.md §3.1(c), step 2).
        let q1 = m1.apply(self.end_ref(beta1));
        let err_b1 = dist2(&g.apply(&q0), &q1);
        // Squared errors: zero exactly; rounded, within the tolerance at the sides' scale.
        let limit = || (tolerance * tolerance) * scale2.to_f64().max(dist2(&q0, &q1).to_f64());
        let acceptable = S::at_most_zero(&err, limit) && S::at_most_zero(&err_b1, limit);
        if !acceptable {
            return Err(TubeError::NoHolonomy { side: beta0.idx() });
        }
        let psi0 = if g.is_translation() {
            0.0
        } else {
            // The centre c = b/(1 − ω), and the tree path from β₁'s triangle up to the root.
            let one_minus = [S::one() - g.rotation[0].clone(), -g.rotation[1].clone()];
            let centre = complex_div(&g.translation, &one_minus);
            let mut points = vec![q0.clone()];
            let mut p = self.owner(beta1);
            while p != root {
                let (up, s) = parent[&p];
                points.push(placed[&up].apply(self.start_ref(s)));
                p = up;
            }
            points.push(p0.clone());
            points
                .windows(2)
                .map(|w| angle_between(&sub(&w[1], &centre), &sub(&w[0], &centre)))
                .sum::<f64>()
        };
        Ok(Chart {
            p0,
            p1,
            q0,
            g,
            psi0,
        })
    }

    /// Appendix B's route: Lemma 28, Lemma 25 on each biface, Lemma 26's merges, on a copy.
    fn paper_route(
        &self,
        tube: &Tube,
        tolerance: f64,
        report: &mut TubeReport,
    ) -> Result<GoodBiface<S>, TubeError> {
        let (mut x, map) = self.sub_portalgon(&tube.polygons);
        let beta = tube.boundary.map(|s| map[s.idx()]);
        lemma_28(&mut x, tolerance, report)?;
        // The chain of bifaces from β₀ to β₁: cut along the interior loops.
        let info = x.vertex_info();
        let is_loop = |s: SideId| {
            x.mate(s).is_some() && info.class[s.idx()] == info.class[x.next_side(s).idx()]
        };
        // Each biface with its boundary sides toward b₀ and toward b₁ (ids that every splice
        // keeps), so the steps below need no tube recognition and cost O(1) each.
        let mut chain: Vec<Tube> = Vec::new();
        let mut entry = beta[0];
        loop {
            let p = x.owner(entry);
            let other = x
                .polygon_sides(p)
                .iter()
                .filter(|&&s| !is_loop(s) && s != entry)
                .find_map(|&s| x.mate(s).map(|t| x.owner(t)))
                .expect("a biface has two triangles");
            let polygons = vec![p.min(other), p.max(other)];
            let exit = polygons
                .iter()
                .flat_map(|&q| x.polygon_sides(q).iter().copied())
                .find(|&s| s != entry && (is_loop(s) || s == beta[1]))
                .expect("a biface has two boundary sides");
            chain.push(Tube {
                polygons,
                boundary: [entry, exit],
            });
            if exit == beta[1] {
                break;
            }
            entry = x.mate(exit).expect("interior loop");
        }
        report.bifaces = chain.len();
        // Lemma 25 on each biface, spliced in so that the loops keep their ids.
        let mut bifaces: Vec<Tube> = Vec::new();
        for t in &chain {
            let good = x.ladder_kernel(t, tolerance)?;
            let labels = t.boundary.map(|s| x.label[s.idx()]);
            let polygons = x
                .splice_biface(t, &good.biface, labels, tolerance)?
                .to_vec();
            bifaces.push(Tube {
                polygons,
                boundary: t.boundary,
            });
        }
        // Lemma 26: merge the first good biface with the next, until one is left.
        let mut current = bifaces[0].clone();
        for next in &bifaces[1..] {
            let mut polygons = current.polygons.clone();
            polygons.extend(&next.polygons);
            let t = Tube {
                polygons,
                boundary: [current.boundary[0], next.boundary[1]],
            };
            let good = x.ladder_kernel(&t, tolerance)?;
            let labels = t.boundary.map(|s| x.label[s.idx()]);
            current = Tube {
                polygons: x
                    .splice_biface(&t, &good.biface, labels, tolerance)?
                    .to_vec(),
                boundary: t.boundary,
            };
            report.merges += 1;
        }
        x.ladder_kernel(&current, tolerance)
    }
}

/// Lemma 28: as long as some interior weak vertex has degree ≤ 10, delete a maximal independent
/// set of them (lowest side ids first) and re-triangulate each hole by shortcuts (INSERTEDGES'
/// arcs stand for the lemma's "arbitrary vertex-to-vertex arcs").
fn lemma_28<S: Scalar>(
    x: &mut Portalgon<S>,
    tolerance: f64,
    report: &mut TubeReport,
) -> Result<(), TubeError> {
    loop {
        let info = x.vertex_info();
        let sides_at = sides_by_vertex(x, &info);
        let mut blocked = vec![false; info.count()];
        let mut chosen = Vec::new();
        for v in 0..info.count() {
            if blocked[v] || !info.is_weak(v) || info.degree[v] > LEMMA_28_MAX_DEGREE {
                continue;
            }
            chosen.push(info.side[v]);
            blocked[v] = true;
            for &s in &sides_at[v] {
                blocked[info.class[x.next_side(s).idx()] as usize] = true;
            }
        }
        if chosen.is_empty() {
            return Ok(());
        }
        report.deletion_rounds += 1;
        report.deleted_vertices += chosen.len();
        for s in chosen {
            let hole = x.delete_vertex(s, tolerance)?;
            x.triangulate_by_shortcuts(hole)?;
        }
    }
}

/// The sides starting at each vertex, increasing ids per vertex, in one allocation (the
/// routines that need them run on every vertex of large portalgons, many times): `at[v]`.
pub(crate) struct SidesByVertex {
    offset: Vec<u32>,
    sides: Vec<SideId>,
}

impl std::ops::Index<usize> for SidesByVertex {
    type Output = [SideId];
    fn index(&self, v: usize) -> &[SideId] {
        &self.sides[self.offset[v] as usize..self.offset[v + 1] as usize]
    }
}

impl SidesByVertex {
    /// The vertices' sides, by vertex.
    pub(crate) fn iter(&self) -> impl Iterator<Item = &[SideId]> {
        (0..self.offset.len() - 1).map(|v| &self[v])
    }
}

/// The sides starting at each vertex (of the set `info` classifies).
pub(crate) fn sides_by_vertex<S: Scalar>(p: &Portalgon<S>, info: &VertexInfo) -> SidesByVertex {
    // Sides outside the classified set (`vertex_info_within`) have no class.
    let class = |s: SideId| Some(info.class[s.idx()] as usize).filter(|&v| v < info.count());
    let mut offset = vec![0u32; info.count() + 1];
    for v in p.sides().filter_map(class) {
        offset[v + 1] += 1;
    }
    for v in 0..info.count() {
        offset[v + 1] += offset[v];
    }
    let mut next = offset.clone();
    let mut sides = vec![SideId::INVALID; offset[info.count()] as usize];
    for s in p.sides() {
        if let Some(v) = class(s) {
            sides[next[v] as usize] = s;
            next[v] += 1;
        }
    }
    SidesByVertex { offset, sides }
}

/// The two triangles of a biface as a portalgon (`(A, B, C)` then `(A, D, B)`, matched as in
/// [`Biface::triangles`]), with the boundary corners labelled `labels[0]` (`b₀`) and
/// `labels[1]` (`b₁`); returns it and its boundary sides `CA`, `DB`.
pub fn biface_portalgon<S: Scalar>(
    biface: &Biface<S>,
    labels: [u32; 2],
) -> (Portalgon<S>, [SideId; 2]) {
    let [t0, t1] = biface.triangles();
    let mut p = Portalgon::empty();
    let a = p.push_polygon(&t0, Some(&[labels[0], labels[1], labels[0]]));
    let b = p.push_polygon(&t1, Some(&[labels[0], labels[1], labels[1]]));
    p.set_mates(p.side(a, 0), p.side(b, 2));
    p.set_mates(p.side(a, 1), p.side(b, 0));
    let boundary = [p.side(a, 2), p.side(b, 1)];
    (p, boundary)
}
