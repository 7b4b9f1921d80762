//! The quality objectives on every compact surface: the maximum pairing of least total cost
//! `Σ (1 − η)` (Remacle et al.'s quad quality, [`crate::quality`]), exact with its certificate,
//! or by the fast mode; and the quality figures of any surface quadrangulation.
//!
//! On a closed orientable surface in one piece these are [`crate::quadrangulate_by_quality`]
//! and [`crate::quadrangulate_with_quality`]. Elsewhere the pairing costs are read per edge of
//! the surface's dual (a boundary side costs nothing: it is never paired), and:
//! - `quality` is the minimum-cost *maximum* matching
//!   (`surftopo_matching::min_cost_maximum_matching`): among the pairings that leave the fewest
//!   triangles, the one of least cost; its certificate (the Tutte–Berge barrier and the dual
//!   solution of the auxiliary graph) is checked by its independent verifier before the quads are
//!   built, and the pairing again by the maximum pairing's verifier;
//! - `quality-fast` is the fast mode completed to a maximum
//!   (`surftopo_matching::fast_min_cost_maximum_matching`), not of least cost in general.
//!
//! With all quads, the triangles left are moved to the boundary and split ([`super::all_quads`]),
//! which changes the pairs along the paths they move on: the optimality gap is then unknown
//! (`None`) unless nothing was added.

use std::time::Instant;

use surftopo_matching::{
    DualGraph, Pairing, SurfaceDual, augment_to_maximum, fast_min_cost_maximum_matching,
    min_cost_maximum_matching, verify_maximum_pairing, verify_min_cost_maximum_matching,
};
use surftopo_mesh::geometry::Point3;
use surftopo_mesh::{CoveredSurface, SurfaceKind};

use super::{SurfaceOptions, SurfaceQuads, quad_of_edge, quads_of_pairing};
use crate::quality::{
    COST_RESOLUTION, QualityMeasured, QualityObjective, QualityReport, cost_of_angles,
    diagonal_quad_angles, diagonal_quality_report,
};
use crate::{QuadAlgorithm, QuadError, QuadStats};

/// A quality-aware quadrangulation of a compact surface: the quads, their total cost and quality.
#[derive(Clone, Debug)]
pub struct SurfaceQualityQuads {
    /// The quads (and the triangles left, the added vertices, the figures).
    pub result: SurfaceQuads,
    /// Total cost `Σ (1 − η)` over the quads (`cost_units / COST_RESOLUTION`).
    pub cost: f64,
    /// The same in integer units.
    pub cost_units: i64,
    /// `(cost − optimum) / optimum`: 0 for the exact objective; `None` when unknown.
    pub optimality_gap: Option<f64>,
    /// The quads' quality (added vertices at their edges' midpoints).
    pub report: QualityReport,
}

impl QualityMeasured for SurfaceQualityQuads {
    fn measures(&self) -> (&QuadStats, f64, Option<f64>, &QualityReport) {
        (
            &self.result.stats,
            self.cost,
            self.optimality_gap,
            &self.report,
        )
    }
}

impl SurfaceQualityQuads {
    /// Wraps a quadrangulation with its cost and quality, measured on the quads.
    fn measured(
        result: SurfaceQuads,
        positions: &[Point3],
        optimality_gap: Option<f64>,
    ) -> SurfaceQualityQuads {
        let all = positions_with_added(positions, &result);
        let cost_units = result
            .quads
            .iter()
            .map(|q| cost_of_angles(diagonal_quad_angles(q.map(|v| all[v as usize]))))
            .sum::<i64>();
        let report = diagonal_quality_report(&all, &result.quads);
        SurfaceQualityQuads {
            result,
            cost: cost_units as f64 / COST_RESOLUTION,
            cost_units,
            optimality_gap,
            report,
        }
    }
}

/// The positions of the surface's vertices (per class), then those of the vertices added by all
/// quads (the midpoints of their edges).
pub fn positions_with_added(positions: &[Point3], result: &SurfaceQuads) -> Vec<Point3> {
    let mut all = positions[..result.vertex_count].to_vec();
    for &[a, b] in &result.added {
        let (p, q) = (positions[a as usize], positions[b as usize]);
        all.push(std::array::from_fn(|k| 0.5 * (p[k] + q[k])));
    }
    all
}

/// [`super::quadrangulate_surface`] with the quads' total cost `Σ (1 − η)` and quality (the
/// `count` objective's figures). On a closed orientable surface in one piece, the figures of
/// [`crate::quadrangulate_with_quality`].
///
/// # Errors
/// As [`super::quadrangulate_surface`].
pub fn quadrangulate_surface_with_quality(
    surface: &CoveredSurface,
    pieces: &[SurfaceKind],
    algorithm: QuadAlgorithm,
    options: &SurfaceOptions,
) -> Result<SurfaceQualityQuads, QuadError> {
    let result = super::quadrangulate_surface(&surface.cover, pieces, algorithm, options)?;
    Ok(SurfaceQualityQuads::measured(
        result,
        &surface.positions,
        None,
    ))
}

/// The pairing cost of every edge of `dual` (0 for boundary half-loops): `round((1 − η) · 10⁹)`
/// of the quad the two triangles make ([`crate::quality::pair_costs`] on a surface's dual).
pub fn surface_pair_costs(surface: &CoveredSurface, dual: &SurfaceDual) -> Vec<i64> {
    (0..dual.edge_slots() as u32)
        .map(|e| {
            if dual.is_boundary(e) {
                0
            } else {
                let quad = quad_of_edge(&surface.cover, dual, e);
                cost_of_angles(diagonal_quad_angles(
                    quad.map(|v| surface.positions[v as usize]),
                ))
            }
        })
        .collect()
}

/// Pairs the triangles of a compact surface into quads by a quality objective (see the module
/// doc): on every piece a maximum pairing, of least total cost `Σ (1 − η)` (exact, certified) or
/// by the fast mode; with all quads, the triangles left are turned into quads by added vertices.
///
/// # Errors
/// [`QuadError::Empty`] without faces; [`QuadError::Internal`] when a certificate is refused (a
/// bug); [`QuadError::QualityTooLarge`] when the exact auxiliary graph would be too large.
pub fn quadrangulate_surface_by_quality(
    surface: &CoveredSurface,
    pieces: &[SurfaceKind],
    objective: QualityObjective,
    all_quads: bool,
) -> Result<SurfaceQualityQuads, QuadError> {
    let start = Instant::now();
    let cover = &surface.cover;
    if cover.is_plain() && pieces.len() <= 1 {
        let closed = crate::quadrangulate_by_quality(&cover.mesh, &surface.positions, objective)?;
        let faces = closed.result.stats.faces;
        let mut result = SurfaceQuads {
            quads: closed.result.quads.iter().map(|q| q.map(|v| v.0)).collect(),
            triangles: Vec::new(),
            added: Vec::new(),
            vertex_count: super::surface_vertex_count(cover),
            stats: closed.result.stats,
            components: vec![super::ComponentQuads {
                name: pieces.first().map(SurfaceKind::name).unwrap_or_default(),
                faces,
                quads: faces / 2,
                ..Default::default()
            }],
            triangulation: None,
            augmentation: closed.result.augmentation,
            expansion: None,
            karp_sipser: None,
        };
        result.fill_totals();
        return Ok(SurfaceQualityQuads {
            result,
            cost: closed.cost,
            cost_units: closed.cost_units,
            optimality_gap: closed.optimality_gap,
            report: closed.report,
        });
    }
    if cover.surface_faces().next().is_none() {
        return Err(QuadError::Empty);
    }
    let dual = SurfaceDual::of_cover(cover);
    let costs = surface_pair_costs(surface, &dual);
    let internal =
        |what: &'static str| move |err: String| QuadError::Internal(format!("{what}: {err}"));
    let (edges, barrier, gap) = match objective {
        QualityObjective::Exact => {
            let exact = min_cost_maximum_matching(&dual, &costs).map_err(|err| match err {
                surftopo_matching::WeightedError::AuxiliaryTooLarge { .. } => {
                    QuadError::QualityTooLarge(err.to_string())
                }
                other => QuadError::Internal(format!("quality pairing: {other}")),
            })?;
            verify_min_cost_maximum_matching(&dual, &costs, &exact.edges, &exact.certificate)
                .map_err(|err| internal("optimality certificate rejected")(err.to_string()))?;
            (exact.edges, exact.certificate.barrier, Some(0.0))
        }
        QualityObjective::Fast => {
            let fast = fast_min_cost_maximum_matching(&dual, &costs)
                .map_err(|err| internal("quality pairing")(err.to_string()))?;
            (fast.edges, Vec::new(), None)
        }
    };
    let pairing_seconds = start.elapsed().as_secs_f64();
    let mut pairing = Pairing::from_edges(&dual, edges)
        .map_err(|err| internal("quality pairing")(err.to_string()))?;
    let barrier = if objective == QualityObjective::Fast {
        // The fast mode's pairing is maximum; the barrier's search proves it.
        let (stats, barrier) = augment_to_maximum(
            &dual,
            &mut pairing,
            surftopo_matching::AugmentStrategy::Forest,
        )
        .map_err(|err| internal("quality pairing")(err.to_string()))?;
        if stats.augmentations > 0 {
            return Err(QuadError::Internal(
                "the fast quality pairing was not maximum".into(),
            ));
        }
        barrier
    } else {
        barrier
    };
    let verified = verify_maximum_pairing(&dual, pairing, &barrier)
        .map_err(|err| internal("quality pairing")(err.to_string()))?;
    let mut result = quads_of_pairing(cover, &dual, &verified);
    result.name_pieces(pieces);
    if all_quads {
        result.complete(cover, &dual, verified)?;
    }
    let faces = dual.node_count();
    result.stats = crate::QuadStats {
        algorithm: objective.name().to_string(),
        faces,
        initial_pairing_seconds: pairing_seconds,
        paired_percent: 100.0 * (faces - result.triangles.len() - result.added.len()) as f64
            / faces as f64,
        total_seconds: start.elapsed().as_secs_f64(),
        ..crate::QuadStats::default()
    };
    result.fill_totals();
    let gap = if result.added.is_empty() { gap } else { None };
    Ok(SurfaceQualityQuads::measured(
        result,
        &surface.positions,
        gap,
    ))
}
