//! Dubois' ALGORITHM (Section 4, Proposition 1) on flat closed surfaces: the happiness reduction.
//!
//! **The paper's routines and their functions** (all generic over the [`Scalar`]: exact on
//! rational input in exact mode, rounded in `f64`):
//! - the data structure of Section 4.4 (portalgon `R`, partition into regions, active region
//!   `R_A`): [`Reduction`], on [`Regions`]; its three invariants: [`Reduction::check_invariants`],
//!   asserted in debug builds after every routine;
//! - INSERTVERTICES (Section 4.1): [`Reduction::insert_vertices`];
//! - INSERTEDGES (Section 4.1): [`Reduction::insert_edges`];
//! - DELETEVERTICES (Section 4.2): [`Reduction::delete_vertices`];
//! - SIMPLIFYTUBES (Section 4.3, with Section 4.4's marking of thin bifaces):
//!   [`Reduction::simplify_tubes`];
//! - GARDENING (Section 4.4): [`Reduction::gardening`];
//! - ALGORITHM (Section 4.5) with `N = ⌈log₂(2 + L/s)⌉`: [`reduce`], reporting a
//!   [`DuboisReport`]; `N` alone: [`outer_iterations`].
//!
//! **Decisions where the paper is silent** (docs/dubois.md §3.6), each tested in `tests/dubois.rs`:
//! - INSERTVERTICES splits every pair of sides matched *inside* `R_A` (both polygons active) at
//!   its midpoint, lower side id first; separating loops (matched to an inactive region) and
//!   the boundary of `S(R)` are never split.
//! - INSERTEDGES: active polygons in increasing id order, each by
//!   [`Portalgon::triangulate_by_shortcuts`] (shortcuts compared squared, ties to the smallest
//!   corner pair).
//! - DELETEVERTICES: vertices of `S(R_A)` in the order of their lowest side id; a weak vertex of
//!   degree ≤ 6 joins the independent set unless a neighbour already did (greedy, hence
//!   maximal). Weak and interior refer to `S(R_A)` (sides matched to inactive regions are its
//!   boundary).
//! - SIMPLIFYTUBES: "`S(T)` homeomorphic to a torus" is read on the whole of `S(R_A)`: one
//!   component, closed, Euler characteristic 0. Case (a) takes the interior loop edge with the
//!   lowest side id and then the lowest one at another vertex ("disjoint" = at different
//!   vertices); case (b) takes, per interior vertex on a loop, its loop edge with the lowest side
//!   id. Cutting along `J` is done by unmatching `J`'s sides ([`Portalgon::unglue`]) and
//!   matching them again after the replacements (their ids survive [`Portalgon::splice`]).
//! - A tube that already is a good biface (two triangles, [`Biface::make_good`] leaves it
//!   unchanged) is kept as it is, not spliced again: the paper's "replace `X` by a good biface
//!   `B`" with `B = X`. This keeps ids stable, so a pass that changes nothing is recognisable.
//! - Tubes are replaced by Proposition 4 along [`ReduceOptions::route`]
//!   ([`TubeRoute::Direct`] by default, docs/dubois.md §3.1(c)).
//! - GARDENING and the inactive regions: each biface marked inactive gets a region of its own.
//!
//! **Deviations** (none changes the output):
//! - The 350 inner repetitions stop after the first repetition that changes nothing (no splice,
//!   marking, deletion or cut; debug builds check that the portalgon and the regions are then
//!   unchanged): everything is deterministic, so the remaining
//!   repetitions would change nothing either (docs/dubois.md §3.2). [`ReduceOptions::faithful`] runs
//!   all 350; the tests check both give identical results. Likewise the outer loop stops once
//!   `R_A` is empty (the routines then do nothing).
//! - [`reduce_with_boundary_until`] also stops when its caller's test succeeds, before the
//!   first outer iteration or after any (exact mode, not faithful): Proposition 2's Delaunay
//!   exit (docs/dubois.md §3.8, [`super::delaunay_exit`]).
//! - Steps that provably find nothing are skipped (not in faithful mode; debug builds check each
//!   skip). Right after GARDENING no component of `S(R_A)` is a tube (each became an inactive
//!   biface; the other components are untouched), so SIMPLIFYTUBES' step 2 with `J` empty, and
//!   the second GARDENING of a repetition whose SIMPLIFYTUBES changed nothing, would find no
//!   tube. DELETEVERTICES (interior vertices only), INSERTEDGES and INSERTVERTICES (sides matched
//!   inside `R_A` only) change neither the components of `S(R_A)`, nor their topology, nor their
//!   boundary sides, and leave every active polygon a triangle when the next GARDENING runs; so
//!   once a GARDENING has run, and since every SIMPLIFYTUBES that changes something is followed
//!   by one, the first GARDENING of a repetition would find no tube either. (In `f64` this
//!   relies on the flatness test of an interior vertex, Section 3's last tube condition, not
//!   changing its answer while the vertex survives: interior vertices of `T₁` are flat far
//!   within the tolerance.)
//! - **\[reconstruction\]** `s` for a flat torus: the paper's `s = d/(6r)` comes from the caps of
//!   Section 8; with no cone point there are no caps, and `s = d/2` (`d` the smallest height of a
//!   triangle) is below the systole (docs/dubois.md §3.3). `N` is computed exactly from squared
//!   lengths in exact mode (the least `N` with `((2^N − 2)·A)² ≥ L²·ℓ²` over the triangles, `A`
//!   their area, `ℓ` their longest side, `L` the longest side overall), so it is never
//!   underestimated; in `f64` with a relative margin of 1e-9 upward.
//!
//! **Cost.** Every routine makes passes over `R_A` (its vertices, its components); a pass
//! costs the live size: the structure is compacted once removed slots outnumber the live ones
//! (order kept, so no decision changes: [`Reduction::side_of_input`] follows the input's
//! sides), and only the components bounded by two sides, the candidates for tubes, are analysed
//! ([`Portalgon::two_sided_components`]).
//!
//! **Guarantees.** Proposition 1's bounds hold for exact input in exact mode; none is claimed in
//! `f64` (the routines then run with the tolerances of the edits they call). [`reduce`] takes a
//! closed flat input; [`reduce_with_boundary`] a flat input with boundary (every interior vertex
//! of angle 2π), Section 8's truncated surface.

use crate::dubois::biface::{Biface, BifaceError, BifaceKind};
use crate::dubois::tube::{Tube, TubeError, TubeRoute, sides_by_vertex};
use crate::error::PortalgonError;
use crate::geometry::{MAX_INPUT_BITS, Scalar, Tolerances};
use crate::portalgon::{EditError, VertexInfo};
use crate::portalgon::{PolygonId, Portalgon, Regions, SideId};

/// The growth limit of exact arithmetic: the most bits (numerator and denominator together) a
/// corner coordinate of ALGORITHM's portalgon may reach, 8 × [`MAX_INPUT_BITS`]. Every
/// coordinate of an input within [`MAX_INPUT_BITS`] starts below it and, with the charts moved
/// to their first corners after every outer iteration, stays within a small multiple of the
/// input's size on the inputs measured (`results/exact_growth.md`); past it the reduction
/// stops with [`DuboisError::GrowthLimit`] instead of running on with ever larger numbers.
pub const MAX_WORKING_BITS: u64 = 8 * MAX_INPUT_BITS;

/// Section 4.5: the inner loop's repetitions.
pub const INNER_REPETITIONS: u32 = 350;
/// Section 4.2: DELETEVERTICES deletes weak vertices of degree at most this.
pub const DELETE_MAX_DEGREE: u32 = 6;

/// Why the reduction failed or refused its input.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum DuboisError {
    /// The input is not a closed triangular portalgon.
    #[error("input polygon {polygon} has {sides} sides: ALGORITHM takes a triangular portalgon")]
    NotTriangular {
        /// The polygon.
        polygon: usize,
        /// Its number of sides.
        sides: usize,
    },
    /// A vertex of the input is a cone point (Section 8's caps are needed, not built here).
    #[error(
        "vertex at the start of side {side} has angle {angle} (not 2π): the surface is not flat"
    )]
    NotFlat {
        /// A side starting at the vertex.
        side: usize,
        /// Its angle, as a double.
        angle: f64,
    },
    /// The portalgon is invalid or not closed.
    #[error(transparent)]
    Portalgon(#[from] PortalgonError),
    /// An edit failed.
    #[error(transparent)]
    Edit(#[from] EditError),
    /// A tube replacement failed.
    #[error(transparent)]
    Tube(#[from] TubeError),
    /// A biface could not be built.
    #[error(transparent)]
    Biface(#[from] BifaceError),
    /// An exact coordinate grew past [`MAX_WORKING_BITS`].
    #[error(
        "exact arithmetic stopped: a corner coordinate reached {bits} bits after {routine}, past \
         the growth limit of {MAX_WORKING_BITS} bits (numerator and denominator together) on \
         the numbers of Theorem 1; give the corners with fewer digits (scale or round them), or \
         run in double precision (without --exact)"
    )]
    GrowthLimit {
        /// The size reached.
        bits: u64,
        /// The routine after which it was measured.
        routine: &'static str,
    },
    /// A Section 4.4 invariant does not hold.
    #[error("Section 4.4 invariant: {0}")]
    Invariant(String),
    /// In double precision: Section 8's caps (radius above `d/12`, `d` the smallest height)
    /// would be smaller, relative to the longest side, than the rounded wave's finest point
    /// tolerance, so the wave could not tell a cap's points from its cone point; refused before
    /// any work (exact arithmetic resolves any size).
    #[error(
        "the caps of Section 8 would have radius {cap:e} of the longest side (the smallest \
         height over 12), below the finest point tolerance {tolerance:e} of the wave in double \
         precision: double precision cannot resolve this surface"
    )]
    Unresolvable {
        /// `d / (12 L)`.
        cap: f64,
        /// The wave's finest point tolerance (relative to the longest side).
        tolerance: f64,
    },
}

/// Options of [`reduce`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReduceOptions {
    /// Run all 350 inner repetitions (Section 4.5 verbatim) instead of stopping at the first one
    /// that changes nothing.
    pub faithful: bool,
    /// How tubes become good bifaces (Proposition 4).
    pub route: TubeRoute,
    /// The tolerances of `f64` (unused in exact mode): the reduction reads
    /// [`Tolerances::length`], its relative tolerance on lengths and angles.
    pub tolerances: Tolerances,
    /// Outer iterations; `None` = [`outer_iterations`] of the input.
    pub outer_iterations: Option<u32>,
}

impl Default for ReduceOptions {
    fn default() -> Self {
        Self {
            faithful: false,
            route: TubeRoute::Direct,
            tolerances: Tolerances::DEFAULT,
            outer_iterations: None,
        }
    }
}

/// What [`reduce`] did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct DuboisReport {
    /// `N`, the outer iterations asked for.
    pub outer_iterations: u32,
    /// Inner repetitions run in each outer iteration done (fewer entries than `N` when `R_A`
    /// became empty, or, in exact mode, when an outer iteration ended in the state the previous
    /// one ended in: docs/dubois.md §3.2).
    pub inner_passes: Vec<u32>,
    /// Their total.
    pub inner_passes_total: u64,
    /// `350 · N`, the faithful total.
    pub inner_passes_bound: u64,
    /// Tubes replaced by a good thin biface (spliced; tubes already good are not counted).
    pub tubes_replaced_thin: usize,
    /// Tubes replaced by a good thick biface.
    pub tubes_replaced_thick: usize,
    /// Bifaces marked inactive (SIMPLIFYTUBES' thin ones and GARDENING's).
    pub bifaces_inactive: usize,
    /// Vertices deleted by DELETEVERTICES.
    pub vertices_deleted: usize,
    /// Midpoints inserted by INSERTVERTICES.
    pub vertices_inserted: usize,
    /// The largest number of vertices of `S(R_A)` after any routine.
    pub peak_active_vertices: usize,
    /// Triangles of the output.
    pub triangles_after_reduction: usize,
    /// `"f64"` or `"exact"`.
    pub arithmetic: &'static str,
    /// ALGORITHM did not run: the input is the metric of a mesh in ℝ³, whose happiness is 1
    /// (docs/dubois.md §8), kept as `T′` ([`super::delaunay_tessellation_of_mesh`]).
    pub mesh_metric: bool,
    /// Whether the caller's test stopped the outer loop early
    /// ([`reduce_with_boundary_until`]: Proposition 2's Delaunay exit).
    pub stopped_by_caller: bool,
}

impl DuboisReport {
    /// The counters of the edits of an inner repetition (splices, markings, deletions): equal
    /// before and after a repetition that also cut nothing iff it changed nothing.
    fn edits(&self) -> (usize, usize, usize, usize) {
        (
            self.tubes_replaced_thin,
            self.tubes_replaced_thick,
            self.bifaces_inactive,
            self.vertices_deleted,
        )
    }
}

/// Section 4.4's data structure: the portalgon `R` and its partition into regions, one active.
#[derive(Clone, Debug, PartialEq)]
pub struct Reduction<S: Scalar = f64> {
    /// `R`.
    pub portalgon: Portalgon<S>,
    /// The partition, with the active region `R_A`.
    pub regions: Regions,
    /// How tubes become good bifaces.
    pub route: TubeRoute,
    /// Relative tolerance in `f64`.
    pub tolerance: f64,
    /// Counters for the report.
    pub report: DuboisReport,
    /// Per side id of the input: its id now (`INVALID` once removed). Ids change only when the
    /// structure is compacted ([`Portalgon::compact_in_place`], which keeps their order).
    input_side: Vec<SideId>,
}

/// The longest period of outer iterations the exact-mode exit looks for
/// ([`Reduction::repeats_from_here`]).
pub const OUTER_PERIOD_MAX: usize = 4;

/// What an outer iteration ends in: the portalgon, the regions and the input's side ids.
#[derive(Clone, Debug, PartialEq)]
struct OuterState<S: Scalar> {
    portalgon: Portalgon<S>,
    regions: Regions,
    input_side: Vec<SideId>,
}

/// The two sides of an edge, lower id first.
type EdgeSides = (SideId, SideId);

impl<S: Scalar> Reduction<S> {
    /// Initialises the data structure (Section 4.5): `R = T`, `R_A = R`, no inactive region.
    pub fn new(portalgon: Portalgon<S>, route: TubeRoute, tolerance: f64) -> Self {
        let regions = Regions::new(&portalgon);
        let input_side = (0..portalgon.side_slots() as u32).map(SideId).collect();
        let mut r = Self {
            portalgon,
            regions,
            route,
            tolerance,
            report: DuboisReport {
                arithmetic: S::ARITHMETIC,
                ..DuboisReport::default()
            },
            input_side,
        };
        r.bookkeeping("initialisation", true);
        r
    }

    /// The id now of side `s` of the input (`None` once it was removed): the boundary sides of
    /// [`reduce_with_boundary`]'s input all survive.
    pub fn side_of_input(&self, s: SideId) -> Option<SideId> {
        self.input_side
            .get(s.idx())
            .copied()
            .filter(|&t| t.is_valid() && self.portalgon.is_side_live(t))
    }

    /// Compacts the portalgon ([`Portalgon::compact_in_place`]: order kept, so no decision
    /// changes) once removed slots outnumber the live ones: every routine makes whole passes over
    /// the slots, and the edits of a long run leave many times more tombstones than live sides.
    fn compact_if_sparse(&mut self) {
        let live = self.portalgon.side_count();
        if self.portalgon.side_slots() <= 2 * live + 64 {
            return;
        }
        self.compact();
    }

    /// Compacts the portalgon (order kept) and renumbers the regions and the input's sides.
    fn compact(&mut self) {
        let (side_map, polygon_map) = self.portalgon.compact_in_place();
        self.regions.renumber(&polygon_map);
        for s in &mut self.input_side {
            if s.is_valid() {
                *s = side_map[s.idx()];
            }
        }
    }

    /// The polygons of `R_A`, increasing ids.
    pub fn active_polygons(&self) -> Vec<PolygonId> {
        self.regions
            .polygons_in(&self.portalgon, self.regions.active())
    }

    fn is_active(&self, p: PolygonId) -> bool {
        self.regions.region(p) == self.regions.active()
    }

    /// Section 4.2's classification on `S(R_A)`.
    fn active_vertices(&self) -> Result<VertexInfo, DuboisError> {
        Ok(self.portalgon.vertex_info_within(&self.active_polygons())?)
    }

    /// The number of vertices of `S(R_A)`.
    pub fn active_vertex_count(&self) -> usize {
        self.active_vertices().map_or(0, |i| i.count())
    }

    /// Section 4.4's invariants: every active polygon has at most six sides; every inactive region
    /// is a good biface (two triangles forming a tube, left unchanged by [`Biface::make_good`]);
    /// every separating edge (sides matched across two regions) is a loop of `R`, and no two
    /// separating loops share a vertex. Also [`Portalgon::check_invariants`].
    ///
    /// # Errors
    /// [`DuboisError::Invariant`] saying which invariant fails where.
    pub fn check_invariants(&self) -> Result<(), DuboisError> {
        self.portalgon.check_invariants()?;
        let fail = |what: String| Err(DuboisError::Invariant(what));
        for p in self.active_polygons() {
            let k = self.portalgon.polygon_sides(p).len();
            if k > 6 {
                return fail(format!("active polygon {} has {k} sides", p.idx()));
            }
        }
        let mut inactive: Vec<(u32, PolygonId)> = self
            .portalgon
            .polygons()
            .filter(|&p| !self.is_active(p))
            .map(|p| (self.regions.region(p), p))
            .collect();
        inactive.sort();
        for group in inactive.chunk_by(|a, b| a.0 == b.0) {
            let polygons: Vec<PolygonId> = group.iter().map(|x| x.1).collect();
            let tube = self
                .portalgon
                .tube(&polygons, self.tolerance)
                .map_err(|e| DuboisError::Invariant(format!("region {}: {e}", group[0].0)))?;
            if polygons.len() != 2 || self.already_good(&tube)?.is_none() {
                return fail(format!(
                    "inactive region {} is not a good biface",
                    group[0].0
                ));
            }
        }
        let info = self.portalgon.vertex_info();
        let mut base_of_loop: Vec<(u32, SideId)> = Vec::new();
        for s in self.portalgon.sides() {
            let Some(t) = self.portalgon.mate(s) else {
                continue;
            };
            if s > t || !self.regions.is_separating(&self.portalgon, s) {
                continue;
            }
            let v = info.class[s.idx()];
            if info.class[self.portalgon.next_side(s).idx()] != v {
                return fail(format!("separating edge of side {} is not a loop", s.idx()));
            }
            base_of_loop.push((v, s));
        }
        base_of_loop.sort();
        if let Some(w) = base_of_loop.windows(2).find(|w| w[0].0 == w[1].0) {
            return fail(format!(
                "separating loops of sides {} and {} share a vertex",
                w[0].1.idx(),
                w[1].1.idx()
            ));
        }
        Ok(())
    }

    /// Bookkeeping after each routine: compaction when sparse, the peak of active vertices, and
    /// the invariants in debug builds (a failure there is a bug of the routines, reported by a
    /// panic naming the routine). Only the initialisation and INSERTVERTICES add vertices to
    /// `S(R_A)` (INSERTEDGES adds edges; the other routines delete vertices, replace tubes by
    /// bifaces with fewer, or make regions inactive), so the peak is measured after those
    /// (`adds_vertices`); debug builds check that no other routine exceeds it.
    fn after_routine(
        &mut self,
        routine: &'static str,
        adds_vertices: bool,
    ) -> Result<(), DuboisError> {
        self.bookkeeping(routine, adds_vertices);
        self.check_growth(routine)
    }

    /// The periodic exit of the outer loop in exact mode (docs/dubois.md §3.2), called after
    /// outer iteration `k = report.inner_passes.len()` of `n`. Every routine is
    /// translation-equivariant in exact arithmetic and decides by the order of the ids, which
    /// compaction keeps; so once the charts are moved to their first corners and the structure
    /// compacted (the caller does both), the state an outer iteration ends in decides all later
    /// ones. When it equals
    /// the state of `p ≤` [`OUTER_PERIOD_MAX`] iterations before (kept in `history`), the
    /// iterations repeat with period `p`: the state after iteration `n` is then restored from
    /// `history` and `true` returned (the loop stops).
    fn repeats_from_here(
        &mut self,
        history: &mut std::collections::VecDeque<OuterState<S>>,
        n: u32,
    ) -> bool {
        let state = OuterState {
            portalgon: self.portalgon.clone(),
            regions: self.regions.clone(),
            input_side: self.input_side.clone(),
        };
        let k = self.report.inner_passes.len();
        let len = history.len();
        if let Some(p) = (1..=len).find(|&p| history[len - p] == state) {
            // s_j = s_{j−p} from here on: s_n = s_{k−p+((n−k) mod p)}.
            let target = k - p + (n as usize - k) % p;
            if target < k {
                let s = history[len - (k - target)].clone();
                self.portalgon = s.portalgon;
                self.regions = s.regions;
                self.input_side = s.input_side;
            }
            return true;
        }
        if len == OUTER_PERIOD_MAX {
            history.pop_front();
        }
        history.push_back(state);
        false
    }

    /// [`MAX_WORKING_BITS`] on the corners of `R` after `routine`: the growth limit of exact
    /// arithmetic (never reached in rounded arithmetic, whose sizes are fixed).
    ///
    /// # Errors
    /// [`DuboisError::GrowthLimit`] past the limit.
    pub fn check_growth(&self, routine: &'static str) -> Result<(), DuboisError> {
        let bits = self.portalgon.max_coordinate_bits();
        if bits > MAX_WORKING_BITS {
            return Err(DuboisError::GrowthLimit { bits, routine });
        }
        Ok(())
    }

    /// [`Self::after_routine`] without the growth limit.
    fn bookkeeping(&mut self, routine: &str, adds_vertices: bool) {
        self.compact_if_sparse();
        if adds_vertices {
            let v = self.active_vertex_count();
            self.report.peak_active_vertices = self.report.peak_active_vertices.max(v);
        }
        #[cfg(debug_assertions)]
        {
            if let Err(e) = self.check_invariants() {
                panic!("after {routine}: {e}");
            }
            let v = self.active_vertex_count();
            assert!(
                v <= self.report.peak_active_vertices,
                "after {routine}: {v} active vertices, above the peak"
            );
        }
        let _ = routine;
    }

    /// INSERTVERTICES (Section 4.1) on `R_A`: the midpoint of every side matched inside `R_A`
    /// becomes a vertex of both copies ([`Portalgon::split_side`]). Returns the number of
    /// midpoints.
    ///
    /// # Errors
    /// An edit error (not expected on a valid structure).
    pub fn insert_vertices(&mut self) -> Result<usize, DuboisError> {
        let edges: Vec<SideId> = self
            .portalgon
            .sides()
            .filter(|&s| {
                self.is_active(self.portalgon.owner(s))
                    && self
                        .portalgon
                        .mate(s)
                        .is_some_and(|t| s < t && self.is_active(self.portalgon.owner(t)))
            })
            .collect();
        let half = S::one().half();
        for &s in &edges {
            self.portalgon.split_side(s, &half)?;
        }
        self.report.vertices_inserted += edges.len();
        self.after_routine("INSERTVERTICES", true)?;
        Ok(edges.len())
    }

    /// INSERTEDGES (Section 4.1) on `R_A`: every active polygon that is not a triangle is cut
    /// along shortcuts until only triangles remain; the pieces stay active. Returns the number of
    /// cuts.
    ///
    /// # Errors
    /// [`PortalgonError::NotAnArc`] for a polygon with no arc (one overlapping itself).
    pub fn insert_edges(&mut self) -> Result<usize, DuboisError> {
        let mut cuts = 0;
        for p in self.active_polygons() {
            let k = self.portalgon.polygon_sides(p).len();
            if k > 3 {
                let pieces = self.portalgon.triangulate_by_shortcuts(p)?;
                cuts += pieces.len() - 1;
                let active = self.regions.active();
                for q in pieces {
                    self.regions.assign(q, active);
                }
            }
        }
        self.after_routine("INSERTEDGES", false)?;
        Ok(cuts)
    }

    /// DELETEVERTICES (Section 4.2) on `R_A`: a maximal independent set of weak vertices of
    /// `S(R_A)` of degree ≤ 6 (greedy in the order of their lowest side id), each deleted by
    /// [`Portalgon::delete_vertex`] (its star merged into one polygon by footnote 2's motions).
    /// Returns the number of vertices deleted.
    ///
    /// # Errors
    /// [`PortalgonError::NotFlat`] when a vertex is not flat; other edit errors.
    pub fn delete_vertices(&mut self) -> Result<usize, DuboisError> {
        self.delete_vertices_with(None)
    }

    /// [`Self::delete_vertices`] from `info` when given: the classification of `S(R_A)` as it
    /// stands (debug builds check it).
    fn delete_vertices_with(&mut self, info: Option<VertexInfo>) -> Result<usize, DuboisError> {
        let info = match info {
            Some(info) => {
                debug_assert!(info == self.active_vertices()?, "a stale classification");
                info
            }
            None => self.active_vertices()?,
        };
        let sides_at = sides_by_vertex(&self.portalgon, &info);
        let mut blocked = vec![false; info.count()];
        let mut chosen: Vec<SideId> = Vec::new();
        // Classes are numbered by their lowest side id, so vertex order is lowest-id order.
        for v in 0..info.count() {
            if blocked[v] || !info.is_weak(v) || info.degree[v] > DELETE_MAX_DEGREE {
                continue;
            }
            chosen.push(info.side[v]);
            blocked[v] = true;
            for &s in &sides_at[v] {
                let w = info.class[self.portalgon.next_side(s).idx()] as usize;
                blocked[w] = true;
            }
        }
        for &s in &chosen {
            self.portalgon.delete_vertex(s, self.tolerance)?;
        }
        self.report.vertices_deleted += chosen.len();
        self.after_routine("DELETEVERTICES", false)?;
        Ok(chosen.len())
    }

    /// The interior loop edges of `S(R_A)`, one per vertex (its lowest side id), in the order of
    /// that side id.
    fn interior_loops(&self, info: &VertexInfo) -> Vec<EdgeSides> {
        let mut taken = vec![false; info.count()];
        let mut loops = Vec::new();
        for s in self.portalgon.sides() {
            if info.class[s.idx()] == u32::MAX {
                continue;
            }
            let v = info.class[s.idx()] as usize;
            if taken[v] || !info.interior[v] {
                continue;
            }
            if info.class[self.portalgon.next_side(s).idx()] as usize == v {
                let t = self.portalgon.mate(s).expect("interior sides are matched");
                taken[v] = true;
                loops.push((s.min(t), s.max(t)));
            }
        }
        loops
    }

    /// Whether `S(R_A)` is homeomorphic to a torus: one component, no boundary, `χ = 0`.
    fn active_is_torus(&self) -> Result<bool, DuboisError> {
        let active = self.active_polygons();
        // A boundary side (unmatched, or matched outside R_A) settles it without the components.
        let closed = active.iter().all(|&p| {
            self.portalgon.polygon_sides(p).iter().all(|&s| {
                self.portalgon
                    .mate(s)
                    .is_some_and(|t| self.is_active(self.portalgon.owner(t)))
            })
        });
        if !closed {
            return Ok(false);
        }
        let comps = self.portalgon.components(&active)?;
        Ok(comps.len() == 1
            && comps[0].boundary_cycles.is_empty()
            && comps[0].euler_characteristic == 0)
    }

    /// SIMPLIFYTUBES (Section 4.3) on `R_A`, thin bifaces marked inactive (Section 4.4). Step 1
    /// builds `J` (case (a) on a torus, case (b) otherwise, `J′` then `J`); step 2 cuts along `J`
    /// and replaces each tube component by a good biface. Returns `(thin, thick)` bifaces
    /// produced (tubes already good included).
    ///
    /// # Errors
    /// A tube or edit error.
    pub fn simplify_tubes(&mut self) -> Result<(usize, usize), DuboisError> {
        Ok(self.simplify_tubes_after(false)?.0)
    }

    /// [`Self::simplify_tubes`], also returning the classification of `S(R_A)` it started from
    /// (still that of `S(R_A)` when it changed nothing); `after_gardening` says that GARDENING
    /// ran last, so that no component of `S(R_A)` is a tube (each became an inactive biface, and
    /// the other components are untouched): when `J` is empty step 2 then finds nothing, and is
    /// skipped.
    fn simplify_tubes_after(
        &mut self,
        after_gardening: bool,
    ) -> Result<((usize, usize), VertexInfo), DuboisError> {
        let info = self.active_vertices()?;
        let loops = self.interior_loops(&info);
        let j: Vec<EdgeSides> = if self.active_is_torus()? {
            // Case (a): two loops at distinct vertices, or none.
            match loops.as_slice() {
                [first, second, ..] => vec![*first, *second],
                _ => Vec::new(),
            }
        } else {
            // Case (b): J′ = `loops`; drop every loop between two distinct tube components.
            self.cut(&loops);
            // The tube components (only two-sided components can be), by polygon.
            let mut tube_of = std::collections::HashMap::new();
            if !loops.is_empty() {
                let comps = self
                    .portalgon
                    .two_sided_components(&self.active_polygons())?;
                for (k, c) in comps.iter().enumerate() {
                    if c.is_annulus_with_single_side_boundaries()
                        && self.portalgon.tube(&c.polygons, self.tolerance).is_ok()
                    {
                        tube_of.extend(c.polygons.iter().map(|&p| (p, k)));
                    }
                }
            }
            let mut kept = Vec::new();
            for &(s, t) in &loops {
                let (cs, ct) = (
                    tube_of.get(&self.portalgon.owner(s)),
                    tube_of.get(&self.portalgon.owner(t)),
                );
                if cs.is_some() && ct.is_some() && cs != ct {
                    self.portalgon.glue(s, t, self.tolerance)?;
                } else {
                    kept.push((s, t));
                }
            }
            // The kept loops stay cut for step 2.
            kept
        };
        if j.is_empty() && after_gardening {
            #[cfg(debug_assertions)]
            assert_eq!(
                self.clone().replace_tube_components(false)?,
                (0, 0),
                "a tube component right after GARDENING"
            );
            self.after_routine("SIMPLIFYTUBES", false)?;
            return Ok(((0, 0), info));
        }
        self.cut(&j);
        let produced = self.replace_tube_components(false);
        self.glue_back(&j)?;
        let produced = produced?;
        self.after_routine("SIMPLIFYTUBES", false)?;
        Ok((produced, info))
    }

    /// GARDENING (Section 4.4): every component of `S(R_A)` that is a tube becomes a good biface
    /// marked inactive (thin or thick). Returns the number of bifaces marked.
    ///
    /// # Errors
    /// A tube or edit error.
    pub fn gardening(&mut self) -> Result<usize, DuboisError> {
        let (thin, thick) = self.replace_tube_components(true)?;
        self.after_routine("GARDENING", false)?;
        Ok(thin + thick)
    }

    /// Unmatches the sides of `edges` (cutting `S(R)` along them).
    fn cut(&mut self, edges: &[EdgeSides]) {
        for &(s, _) in edges {
            self.portalgon.unglue(s);
        }
    }

    /// Matches the sides of `edges` again.
    fn glue_back(&mut self, edges: &[EdgeSides]) -> Result<(), DuboisError> {
        for &(s, t) in edges {
            self.portalgon.glue(s, t, self.tolerance)?;
        }
        Ok(())
    }

    /// Step 2 of SIMPLIFYTUBES / GARDENING: each component of `R_A` (as currently matched) that is
    /// a tube becomes a good biface; marked inactive when thin, or always with `mark_all`.
    fn replace_tube_components(&mut self, mark_all: bool) -> Result<(usize, usize), DuboisError> {
        let comps = self
            .portalgon
            .two_sided_components(&self.active_polygons())?;
        let (mut thin, mut thick) = (0, 0);
        for c in comps {
            // The tube test starts with this (Section 3: an annulus bounded by two sides).
            if !c.is_annulus_with_single_side_boundaries() {
                continue;
            }
            let Ok(tube) = self.portalgon.tube(&c.polygons, self.tolerance) else {
                continue;
            };
            let (triangles, kind) = match self.already_good(&tube)? {
                Some(kind) => (tube.polygons.clone(), kind),
                None => {
                    let (created, good, _) = self.portalgon.replace_tube_by_good_biface(
                        &tube.polygons,
                        self.route,
                        self.tolerance,
                    )?;
                    let kind = good.biface.kind()?;
                    if kind == BifaceKind::Thin {
                        self.report.tubes_replaced_thin += 1;
                    } else {
                        self.report.tubes_replaced_thick += 1;
                    }
                    let active = self.regions.active();
                    for p in created {
                        self.regions.assign(p, active);
                    }
                    (created.to_vec(), kind)
                }
            };
            let is_thin = kind == BifaceKind::Thin;
            if is_thin {
                thin += 1;
            } else {
                thick += 1;
            }
            if mark_all || is_thin {
                let r = self.regions.new_region();
                for &p in &triangles {
                    self.regions.assign(p, r);
                }
                self.report.bifaces_inactive += 1;
            }
        }
        Ok((thin, thick))
    }

    /// When the tube is two triangles forming a good biface, its kind (thin or thick); `None`
    /// when it is not a good biface as it stands. The biface is charted from `β₀`'s triangle
    /// `(A, B, C)` (`β₀ = CA`) and the other triangle laid across `AB` by footnote 2's motion.
    fn already_good(&self, tube: &Tube) -> Result<Option<BifaceKind>, DuboisError> {
        let p = &self.portalgon;
        if tube.polygons.len() != 2 {
            return Ok(None);
        }
        let beta0 = tube.boundary[0];
        let e = p.next_side(beta0);
        let Some(e_mate) = p.mate(e) else {
            return Ok(None);
        };
        if p.owner(e_mate) == p.owner(e) || p.next_side(p.next_side(e_mate)) != tube.boundary[1] {
            return Ok(None);
        }
        let (c, a, b) = (p.start(beta0), p.end(beta0), p.end(e));
        let motion =
            crate::geometry::Motion::gluing(p.start_ref(e_mate), p.end_ref(e_mate), &b, &a);
        let d = motion.apply(p.end_ref(p.next_side(e_mate)));
        let Ok(biface) = Biface::new(a, d, b, c, self.tolerance) else {
            return Ok(None);
        };
        let good = biface.make_good()?;
        if !good.unchanged {
            return Ok(None);
        }
        Ok(Some(biface.kind()?))
    }
}

/// `N = ⌈log₂(2 + L/s)⌉` (Section 4.5) for a flat torus with `s = d/2` **\[reconstruction\]**
/// (see the module doc): the least `N ≥ 1` with `((2^N − 2)·A_Δ)² ≥ L²·ℓ_Δ²` for every triangle
/// `Δ` (area `A_Δ`, longest side `ℓ_Δ`; `L` the longest side), i.e. `2^N ≥ 2 + L/(d/2)` with
/// `d = min 2A_Δ/ℓ_Δ`. Exact in exact mode; in `f64` the right side is enlarged by a relative
/// 1e-9 so that `N` is not underestimated. Polygons that are not triangles are measured the
/// same way (their smallest height bounded by `2A/ℓ`). Capped at 65536, never reached on an
/// input within [`MAX_INPUT_BITS`]: its lengths are below `2^4096` and its areas above
/// `2^−16384` (four denominators of at most 4096 bits), so `L/s < 2^24600`.
pub fn outer_iterations<S: Scalar>(portalgon: &Portalgon<S>) -> u32 {
    let lengths2 = |q: PolygonId| {
        portalgon
            .polygon_sides(q)
            .iter()
            .map(|&s| portalgon.side_length2(s))
            .fold(S::zero(), |m, l| if l > m { l } else { m })
    };
    let longest2 = portalgon
        .polygons()
        .map(lengths2)
        .fold(S::zero(), |m, l| if l > m { l } else { m });
    let margin = if S::EXACT {
        S::one()
    } else {
        S::one() + S::from_f64(1e-9).expect("finite")
    };
    // `enough` is monotone in N: a doubling search, then bisection (O(log N) evaluations).
    let enough = |n: u32| {
        let factor = power_of_two::<S>(n) - S::from_i64(2);
        portalgon.polygons().all(|q| {
            let lhs = factor.clone() * portalgon.polygon_area(q);
            lhs.clone() * lhs >= longest2.clone() * lengths2(q) * margin.clone()
        })
    };
    let mut high = 1u32;
    while high < OUTER_ITERATIONS_MAX && !enough(high) {
        high = (2 * high).min(OUTER_ITERATIONS_MAX);
    }
    if high == OUTER_ITERATIONS_MAX && !enough(high) {
        return high;
    }
    // The least N in (high / 2, high] with `enough(N)`.
    let mut low = high / 2; // not enough (or 0)
    while high - low > 1 {
        let mid = low + (high - low) / 2;
        if enough(mid) {
            high = mid;
        } else {
            low = mid;
        }
    }
    high
}

/// The cap of [`outer_iterations`].
const OUTER_ITERATIONS_MAX: u32 = 65536;

/// `2^n`, by squaring.
fn power_of_two<S: Scalar>(n: u32) -> S {
    let (mut result, mut base, mut e) = (S::one(), S::from_i64(2), n);
    while e > 0 {
        if e & 1 == 1 {
            result = result * base.clone();
        }
        e >>= 1;
        if e > 0 {
            base = base.clone() * base;
        }
    }
    result
}

/// Checks ALGORITHM's input: valid, closed unless `bounded`, triangular, every interior vertex
/// flat.
fn check_input<S: Scalar>(
    t: &Portalgon<S>,
    tolerance: f64,
    bounded: bool,
) -> Result<(), DuboisError> {
    t.check_invariants()?;
    if !bounded {
        t.check_closed()?;
    }
    if let Some(p) = t.polygons().find(|&p| t.polygon_sides(p).len() != 3) {
        return Err(DuboisError::NotTriangular {
            polygon: p.idx(),
            sides: t.polygon_sides(p).len(),
        });
    }
    let info = t.vertex_info();
    for (v, sides) in sides_by_vertex(t, &info).iter().enumerate() {
        if !info.interior[v] {
            continue;
        }
        let (flat, angle) = t.is_full_turn(sides, tolerance);
        if !flat {
            return Err(DuboisError::NotFlat {
                side: sides[0].idx(),
                angle,
            });
        }
    }
    Ok(())
}

/// ALGORITHM (Section 4.5) on a closed flat triangular portalgon: `N` outer iterations of
/// INSERTVERTICES and INSERTEDGES on `R_A`, each followed by up to 350 repetitions of GARDENING,
/// SIMPLIFYTUBES (thin bifaces marked inactive), GARDENING, DELETEVERTICES and INSERTEDGES
/// (stopping at the first repetition that changes nothing unless [`ReduceOptions::faithful`]).
/// Returns the final data structure `R` (its portalgon is triangular, same surface) with the
/// report in [`Reduction::report`].
///
/// # Errors
/// [`DuboisError::NotTriangular`], [`DuboisError::NotFlat`], [`DuboisError::Portalgon`] for bad
/// input; the routines' errors.
pub fn reduce<S: Scalar>(
    t: &Portalgon<S>,
    options: &ReduceOptions,
) -> Result<Reduction<S>, DuboisError> {
    check_input(t, options.tolerances.length, false)?;
    reduce_checked(t, options, &mut |_| Ok(false))
}

/// ALGORITHM (Section 4.5, Proposition 1) on a flat triangular portalgon that may have boundary
/// (Section 8's truncated surface `T₁`): as [`reduce`], with every *interior* vertex flat. The
/// boundary sides are never split nor removed and keep their identity through every routine
/// (the splice keeps boundary ids; compaction renumbers them, [`Reduction::side_of_input`]
/// follows), so the caller can glue back what it cut off ([`super::put_caps_back`]).
///
/// # Errors
/// As [`reduce`] (a boundary is allowed).
pub fn reduce_with_boundary<S: Scalar>(
    t: &Portalgon<S>,
    options: &ReduceOptions,
) -> Result<Reduction<S>, DuboisError> {
    check_input(t, options.tolerances.length, true)?;
    reduce_checked(t, options, &mut |_| Ok(false))
}

/// [`reduce_with_boundary`] that also stops, in exact mode and unless
/// [`ReduceOptions::faithful`], as soon as `done` says the current structure is good enough:
/// `done` is asked before the first outer iteration and after each one (Proposition 2's Delaunay
/// exit, [`super::caps`]). [`DuboisReport::stopped_by_caller`] records it.
///
/// # Errors
/// As [`reduce_with_boundary`], and `done`'s.
pub fn reduce_with_boundary_until<S: Scalar>(
    t: &Portalgon<S>,
    options: &ReduceOptions,
    done: &mut dyn FnMut(&Reduction<S>) -> Result<bool, DuboisError>,
) -> Result<Reduction<S>, DuboisError> {
    check_input(t, options.tolerances.length, true)?;
    reduce_checked(t, options, done)
}

fn reduce_checked<S: Scalar>(
    t: &Portalgon<S>,
    options: &ReduceOptions,
    done: &mut dyn FnMut(&Reduction<S>) -> Result<bool, DuboisError>,
) -> Result<Reduction<S>, DuboisError> {
    let mut r = Reduction::new(t.clone(), options.route, options.tolerances.length);
    r.check_growth("reading the input")?;
    let n = options
        .outer_iterations
        .unwrap_or_else(|| outer_iterations(t));
    r.report.outer_iterations = n;
    r.report.inner_passes_bound = u64::from(INNER_REPETITIONS) * u64::from(n);
    // Exact mode: the caller's exit, before the first outer iteration and after each one.
    let ask = S::EXACT && !options.faithful;
    if ask && done(&r)? {
        r.report.stopped_by_caller = true;
        r.report.triangles_after_reduction = r.portalgon.polygon_count();
        return Ok(r);
    }
    // Exact mode: the states the last outer iterations ended in (`Reduction::repeats_from_here`).
    let mut history = std::collections::VecDeque::new();
    // No component of S(R_A) is a tube: true after a GARDENING (each tube component became an
    // inactive biface), kept by the routines that change neither the components of S(R_A) nor
    // their boundary sides, and renewed by the GARDENING after every SIMPLIFYTUBES that changes
    // something.
    let mut tube_free = false;
    // Vertices and genus of the input, for Lemma 3's and Proposition 5's bounds (debug builds).
    let m = t.vertex_info().count();
    // g + b of Proposition 5 (an upper bound: (2 − χ)/2 + b per component, b its boundaries).
    let genus = {
        let comps = t.components(&t.polygons().collect::<Vec<_>>())?;
        let chi: i64 = comps.iter().map(|c| c.euler_characteristic).sum();
        let b: usize = comps.iter().map(|c| c.boundary_cycles.len()).sum();
        usize::try_from((2 - chi).max(0) / 2).unwrap_or(0) + b
    };
    for _ in 0..n {
        if r.active_polygons().is_empty() && !options.faithful {
            break;
        }
        #[cfg(debug_assertions)]
        let active_before = r.active_vertex_count();
        r.insert_vertices()?;
        // Lemma 3: INSERTVERTICES leaves fewer than 7(g + m_A) vertices (g ≥ the genus of S(R_A)).
        #[cfg(debug_assertions)]
        assert!(
            active_before == 0 || r.active_vertex_count() < 7 * (genus + active_before),
            "Lemma 3"
        );
        r.insert_edges()?;
        let mut passes = 0;
        for _ in 0..INNER_REPETITIONS {
            surftopo_mesh::stop::check();
            #[cfg(debug_assertions)]
            let before = (r.portalgon.clone(), r.regions.clone());
            let edits_before = r.report.edits();
            // Right after GARDENING no component of S(R_A) is a tube, so SIMPLIFYTUBES' step 2
            // with `J` empty, and a second GARDENING after a SIMPLIFYTUBES that changed nothing,
            // find nothing: the default skips them (faithful runs them; the tests compare).
            // The classification SIMPLIFYTUBES read is then also DELETEVERTICES' (the side ids
            // are unchanged too: no edit, hence no compaction). And `tube_free` stays true
            // through DELETEVERTICES, INSERTEDGES and INSERTVERTICES, so the first GARDENING of a
            // repetition is skipped once any GARDENING has run (see the module doc).
            let skip = !options.faithful;
            if skip && tube_free {
                #[cfg(debug_assertions)]
                assert_eq!(
                    r.clone().gardening()?,
                    0,
                    "a tube component after DELETEVERTICES and INSERTEDGES"
                );
            } else {
                r.gardening()?;
            }
            tube_free = true;
            let edits_before_tubes = r.report.edits();
            let slots_before_tubes = r.portalgon.side_slots();
            let (_, info) = r.simplify_tubes_after(skip)?;
            let unchanged = r.report.edits() == edits_before_tubes
                && r.portalgon.side_slots() == slots_before_tubes;
            let info = if !skip || !unchanged {
                r.gardening()?;
                None
            } else {
                #[cfg(debug_assertions)]
                assert_eq!(
                    r.clone().gardening()?,
                    0,
                    "a tube component after SIMPLIFYTUBES"
                );
                Some(info)
            };
            r.delete_vertices_with(info)?;
            let cuts = r.insert_edges()?;
            passes += 1;
            // Every edit of a repetition is counted: a splice (tubes replaced), a marking
            // (bifaces inactive), a deletion, or a cut. SIMPLIFYTUBES' cut along J is glued back.
            let unchanged = cuts == 0 && r.report.edits() == edits_before;
            #[cfg(debug_assertions)]
            assert!(
                !unchanged || (before.0 == r.portalgon && before.1 == r.regions),
                "an inner repetition changed the structure without counting an edit"
            );
            if unchanged && !options.faithful {
                break;
            }
        }
        r.report.inner_passes.push(passes);
        r.report.inner_passes_total += u64::from(passes);
        // Proposition 5 (Section 5.5): after the inner loop R_A has at most 3000(g + b + m)
        // vertices (b = 0: the surface is closed).
        debug_assert!(
            r.active_vertex_count() <= 3000 * (genus + m),
            "Proposition 5"
        );
        if S::EXACT {
            // Charts at their first corners, slots compacted: the canonical state (also in
            // faithful runs, so that both give the same bytes).
            r.portalgon.translate_to_first_corners();
            r.compact();
            if !options.faithful && r.repeats_from_here(&mut history, n) {
                break;
            }
            if ask && done(&r)? {
                r.report.stopped_by_caller = true;
                break;
            }
        }
    }
    r.report.triangles_after_reduction = r.portalgon.polygon_count();
    Ok(r)
}
