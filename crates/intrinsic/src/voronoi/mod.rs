//! Delaunay tessellations by a Voronoi wave (Dubois, Appendix D: Proposition 3 = Propositions 11
//! and 12), in exact and in double arithmetic; a second algorithm for the Delaunay tessellation of
//! a closed portalgon, independent of edge flipping.
//!
//! The pieces, each in its own file with the paper's statements and the deviations:
//! - [`singular`]: V, the singular vertices (Section 2.2), exactly in exact mode; one vertex for a
//!   flat torus (Proof of Proposition 3);
//! - [`wave`]: the multi-source wave of Appendix D.2 (Propositions 11, 13, 14; Lemmas 40, 41),
//!   giving the constellations X_Δ;
//! - [`dual`]: the Delaunay tessellation as the dual of the Voronoi diagram (Appendix C,
//!   Lemmas 29–31; Proposition 12 by docs/dubois.md §3.7's route), and the Voronoi diagram itself;
//! - `flat`: where the wave keeps its many small lists (constellations, side lists): one vector
//!   per kind instead of an allocation per triangle or side.
//!
//! [`voronoi_delaunay`] runs them in order on a closed triangular portalgon in any [`Scalar`]:
//! `f64`, or [`crate::geometry::Rational`] for exact results (then every predicate and
//! construction is exact and dates are compared squared). The output tessellation is a portalgon,
//! like [`crate::delaunay_tessellation`]'s, with vertex labels numbering V; its Delaunay
//! triangulation ([`VoronoiDelaunay::triangulation`], the polygons cut by shortcuts) feeds the
//! Laplacian. The cotan Laplacian does not depend on the diagonals cut into co-circular polygons,
//! so it is the flip route's; the lumped mass does (only its total, the area, is the same).
//!
//! Deviations from the paper, all listed in the files' docs: V may be every vertex of T
//! ([`Sources::All`], the flip algorithm's vertex set) as well as the singular ones; the Voronoi
//! diagram is output as polylines in T instead of a refined portalgon T′ (Proposition 11); the
//! polygons are read off the constellations (docs/dubois.md §3.7) instead of Proposition 12's
//! unfoldings; Lemma 41's lists are vectors (O(k) splices) instead of search trees; `f64` compares
//! with tolerances (exact mode compares exactly). Decided by the tests against a first design
//! (docs/dubois.md §3.7): closed cells with ties in `f64` (see [`wave`]); crossings of the
//! side lists taken at the bisector of consecutive cells, not at their (overlapping) ends.
//!
//! Limits: the `f64` mode can refuse a surface with a typed [`DualError`] when rounding makes the
//! traced Voronoi edges inconsistent (two shared meshes, chassis_upright and wheel, where
//! near-co-circular sites put two Voronoi vertices closer than the tolerance: merged, they make a
//! polygon the flip route does not make; kept apart, the edge between them is too short to follow;
//! and T_x for large x, where doubles cannot hold the needle; [`VoronoiError::is_numerical`] tells
//! these from bad input); it never returns an unchecked polygon (each is validated by
//! [`Portalgon::add_polygon`], each gluing by [`Portalgon::glue`]). The exact mode has no
//! tolerance.

pub mod dual;
mod flat;
pub mod singular;
pub mod wave;

pub use dual::{DualError, Segment, VoronoiDiagram};
pub use singular::{is_flat_vertex, wave_sources};
pub use wave::{SideCell, Wave, WaveError, WaveOptions, run_wave};

use crate::error::PortalgonError;
use crate::geometry::{Scalar, Tolerances};
use crate::portalgon::Portalgon;
use crate::triangulation::IntrinsicTriangulation;

/// The vertex set V the wave starts from.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Sources {
    /// Every vertex of T: the Delaunay tessellation with T's vertices, the one the flip algorithm
    /// computes (its triangulation has a Laplacian row per vertex).
    #[default]
    All,
    /// The singular vertices (one vertex for a flat torus): the canonical tessellation of
    /// Theorem 1 and Corollary 2 ([`wave_sources`]).
    Singular,
}

/// Options of [`voronoi_delaunay`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct VoronoiOptions {
    /// V: every vertex, or the singular ones.
    pub sources: Sources,
    /// The wave's budget.
    pub wave: WaveOptions,
    /// In `f64` (exact mode decides exactly): flat vertices ([`Tolerances::angle`]), points of
    /// the wave ([`Tolerances::point`]), sites of the dual ([`Tolerances::dual`]), and the
    /// retries when the traced Voronoi edges do not close up: the dual again pooling the sites of
    /// Voronoi vertices taken for one (see the dual's module doc), then at
    /// [`Tolerances::dual_retry`]; then the wave and the dual again at
    /// [`Tolerances::finer_retry`] times their tolerances. The first error is reported when
    /// every attempt fails.
    pub tolerances: Tolerances,
}

/// Why [`voronoi_delaunay`] failed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum VoronoiError {
    /// The wave could not run (input, budget).
    #[error(transparent)]
    Wave(#[from] WaveError),
    /// The dual could not be built.
    #[error(transparent)]
    Dual(#[from] DualError),
}

impl VoronoiError {
    /// Whether this is a numerical refusal of an `f64` run rather than bad input: the dual's
    /// refusals (rounding made the traced Voronoi edges inconsistent) and the event budget (a run
    /// that does not settle). In exact mode the same errors mean a bug or an input beyond the
    /// budget, so callers decide by the arithmetic; [`WaveError::Input`] is always bad input.
    pub fn is_numerical(&self) -> bool {
        matches!(self, Self::Dual(_) | Self::Wave(WaveError::Budget(_)))
    }
}

/// The Delaunay tessellation of (S(T), V) computed by the wave, with the wave's data.
#[derive(Clone, Debug)]
pub struct VoronoiDelaunay<S: Scalar> {
    /// The Delaunay tessellation: convex polygons inscribed in empty circles, dense ids. Corners
    /// are labelled with the input's vertex labels when V is every vertex and the input is
    /// labelled (so the triangulation's vertex ids are the input's), otherwise with the index in
    /// [`Self::sources`] of their vertex.
    pub tessellation: Portalgon<S>,
    /// The Voronoi diagram of V (its vertices dual to the polygons, its edges as polylines).
    pub diagram: VoronoiDiagram<S>,
    /// The wave: constellations X_Δ, side diagrams, event counts.
    pub wave: Wave<S>,
    /// V, as vertex classes of the input ([`Portalgon::vertex_classes`]).
    pub sources: Vec<u32>,
}

impl<S: Scalar> VoronoiDelaunay<S> {
    /// A Delaunay triangulation of the tessellation (each polygon cut along shortcuts, INSERTEDGES
    /// of Section 4.1), as an intrinsic triangulation in `f64` whose vertex ids are the labels:
    /// the input of [`crate::cotan_laplacian`] and [`crate::lumped_mass`].
    ///
    /// # Errors
    /// A [`PortalgonError`] if a polygon cannot be cut (it would not be convex).
    pub fn triangulation(&self) -> Result<IntrinsicTriangulation, PortalgonError> {
        let t = &self.tessellation;
        // A tessellation of triangles (no co-circular polygon; dense ids as built) is its own
        // triangulation: no copy to cut.
        if t.polygons().all(|q| t.polygon_sides(q).len() == 3)
            && t.polygon_count() == t.polygon_slots()
            && t.side_count() == t.side_slots()
        {
            return IntrinsicTriangulation::from_portalgon(t, 1e-6);
        }
        IntrinsicTriangulation::from_portalgon(&self.triangulated()?, 1e-6)
    }

    /// The tessellation with every polygon cut along shortcuts into triangles, in `S` (exact
    /// corners in exact mode), dense ids, labels kept.
    ///
    /// # Errors
    /// As [`Self::triangulation`].
    pub fn triangulated(&self) -> Result<Portalgon<S>, PortalgonError> {
        self.tessellation.triangulated()
    }
}

/// The portalgon with its corners rounded to doubles, compacted (dense ids, labels and matching
/// kept).
pub fn to_f64<S: Scalar>(p: &Portalgon<S>) -> Portalgon<f64> {
    let (p, _) = p.compacted();
    let mut out = Portalgon::new();
    for q in p.polygons() {
        let corners: Vec<[f64; 2]> = p
            .corners(q)
            .iter()
            .map(|c| [c[0].to_f64(), c[1].to_f64()])
            .collect();
        let labels: Vec<u32> = p
            .polygon_sides(q)
            .iter()
            .map(|&s| p.vertex_label(s).unwrap_or(u32::MAX))
            .collect();
        out.push_polygon(&corners, Some(&labels));
    }
    for s in p.sides() {
        if let Some(t) = p.mate(s) {
            out.set_mates(s, t);
        }
    }
    out
}

/// Proposition 3 by its proof: V ([`wave_sources`]), the wave ([`run_wave`], Proposition 11),
/// then the dual ([`dual`], Proposition 12), on a closed triangular portalgon with dense ids.
///
/// # Errors
/// [`VoronoiError`].
pub fn voronoi_delaunay<S: Scalar>(
    p: &Portalgon<S>,
    options: &VoronoiOptions,
) -> Result<VoronoiDelaunay<S>, VoronoiError> {
    wave::check_input(p)?;
    let (sources, class) = match options.sources {
        Sources::Singular => wave_sources(p, options.tolerances.angle),
        Sources::All => {
            let (class, count) = p.vertex_classes();
            ((0..count as u32).collect(), class)
        }
    };
    wave_and_dual(p, sources, &class, options, options.sources == Sources::All)
}

/// Proposition 3 from a given V: `sources`, vertex classes of `p` ([`Portalgon::vertex_classes`],
/// increasing, containing every singular vertex; a class out of range is ignored), e.g. the
/// input's vertices among those of a refined portalgon (Section 1's footnote 1: V any finite set
/// containing the singularities). The tessellation's corners are labelled with the index of
/// their source in `sources`.
///
/// # Errors
/// [`VoronoiError`].
pub fn voronoi_delaunay_from<S: Scalar>(
    p: &Portalgon<S>,
    sources: Vec<u32>,
    options: &VoronoiOptions,
) -> Result<VoronoiDelaunay<S>, VoronoiError> {
    wave::check_input(p)?;
    let (class, _) = p.vertex_classes();
    wave_and_dual(p, sources, &class, options, false)
}

/// The wave from `sources` and its dual; corners labelled with the source index, or with `p`'s
/// labels when `input_labels` and every corner of `p` has one. In `f64`, a numerical refusal
/// runs both again with [`Tolerances::finer_retry`]'s tolerances, when set.
fn wave_and_dual<S: Scalar>(
    p: &Portalgon<S>,
    sources: Vec<u32>,
    class: &[u32],
    options: &VoronoiOptions,
    input_labels: bool,
) -> Result<VoronoiDelaunay<S>, VoronoiError> {
    let (wave, tolerances) = (&options.wave, &options.tolerances);
    let factor = tolerances.finer_retry.filter(|_| !S::EXACT);
    let retry_sources = factor.map(|_| sources.clone());
    match wave_and_dual_at(p, sources, class, wave, tolerances, input_labels) {
        Err(first) if first.is_numerical() => {
            let (Some(factor), Some(sources)) = (factor, retry_sources) else {
                return Err(first);
            };
            let finer = tolerances.finer_wave(factor);
            wave_and_dual_at(p, sources, class, wave, &finer, input_labels).map_err(|_| first)
        }
        result => result,
    }
}

/// [`wave_and_dual`] at the given tolerances (the dual retried as they say).
fn wave_and_dual_at<S: Scalar>(
    p: &Portalgon<S>,
    sources: Vec<u32>,
    class: &[u32],
    wave_options: &WaveOptions,
    tolerances: &Tolerances,
    input_labels: bool,
) -> Result<VoronoiDelaunay<S>, VoronoiError> {
    let wave = run_wave(p, &sources, class, wave_options, tolerances)?;
    let mut labels = vec![u32::MAX; class.iter().map(|&c| c as usize + 1).max().unwrap_or(0)];
    let labelled = p.sides().all(|s| p.vertex_label(s).is_some());
    for (k, &c) in sources.iter().enumerate() {
        if let Some(l) = labels.get_mut(c as usize) {
            *l = k as u32;
        }
    }
    if input_labels && labelled {
        for s in p.sides() {
            labels[class[s.idx()] as usize] = p.vertex_label(s).expect("labelled");
        }
    }
    let tolerance = tolerances.dual;
    // |V|: the sources that are vertex classes of `p` (others are ignored).
    let in_v = sources
        .iter()
        .filter(|&&c| (c as usize) < labels.len())
        .count();
    let out = match dual::build_dual(p, &wave, &labels, tolerance, false, in_v) {
        Err(first) if !S::EXACT => match tolerances.dual_retry {
            Some(t) => dual::build_dual(p, &wave, &labels, tolerance, true, in_v)
                .or_else(|_| dual::build_dual(p, &wave, &labels, t, false, in_v))
                .map_err(|_| first)?,
            None => return Err(first.into()),
        },
        built => built?,
    };
    Ok(VoronoiDelaunay {
        tessellation: out.portalgon,
        diagram: out.diagram,
        wave,
        sources,
    })
}
