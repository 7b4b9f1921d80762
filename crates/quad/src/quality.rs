//! The shape quality of the quad made by pairing two adjacent triangles, the per-edge costs of the
//! quality-aware pairings, and the quality report of a quad mesh.
//!
//! # Measure
//! Remacle et al.'s quality (J.-F. Remacle, J. Lambrechts, B. Seny, E. Marchandise, A. Johnen,
//! C. Geuzaine, "Blossom-Quad: a non-uniform quadrilateral mesh generator using a minimum-cost
//! perfect-matching algorithm", *International Journal for Numerical Methods in Engineering*
//! 89(9) (2012), 1102–1119, Section 2, eq. (1)): for a quad with corner angles `α_1..α_4`,
//!
//! `η = max(0, 1 − (2/π) · max_k |π/2 − α_k|)`,
//!
//! 1 for a rectangle, 0 as soon as one corner is flat (π) or closed (0). Chosen because it is the
//! cost of the Blossom-Quad method that Gmsh's recombination minimises (so results compare with
//! it directly), it depends only on the corner angles (scale-invariant, no reference element),
//! and it is the worst-corner measure that the quality report counts ("bad": a corner above 170°
//! or below 10°). The pairing cost of an edge is `1 − η` of its quad.
//!
//! Decision (the paper's meshes are planar; ours are surfaces in space): the corners are measured
//! on the surface. For primal edge `a → b` with triangles `(a, b, c)` and `(b, a, d)`, the quad is
//! `[a, d, b, c]` (as the quad pipeline writes it); its corners at `c` and `d` are the triangles'
//! angles there, and its corners at `a` and `b` are the sums of the two triangles' angles at those
//! vertices. So the four corners sum to 2π, a reflex corner (a non-convex pair) reads as above π
//! rather than being folded back below it as the angle between two edge vectors in space would
//! be, and a planar pair gets exactly the paper's angles. Angles are `atan2(|u × v|, u · v)`, so
//! a zero-length edge gives a 0 angle (quality 0) rather than NaN.

use surftopo_matching::weighted::MAX_COST;
use surftopo_mesh::geometry::Point3;
use surftopo_mesh::{EdgeId, HalfedgeId, SurfaceMesh, VertexId};

/// Integer cost units per unit of real cost: the cost of an edge is `round((1 − η) · 10⁹)`
/// (see `surftopo_matching::weighted` for how this rounding bounds the gap to the real optimum:
/// at most `|M| · 10⁻⁹` in total).
pub const COST_RESOLUTION: f64 = 1e9;

/// A quad counts as bad when one of its corners is above this many degrees...
pub const BAD_CORNER_ABOVE_DEGREES: f64 = 170.0;
/// ... or below this many.
pub const BAD_CORNER_BELOW_DEGREES: f64 = 10.0;

fn sub(p: Point3, q: Point3) -> Point3 {
    [p[0] - q[0], p[1] - q[1], p[2] - q[2]]
}

/// The angle at `apex` between the directions to `p` and `q`, in radians.
fn angle(apex: Point3, p: Point3, q: Point3) -> f64 {
    let (u, v) = (sub(p, apex), sub(q, apex));
    let cross = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let sine = (cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]).sqrt();
    let cosine = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    sine.atan2(cosine)
}

/// The corner angles (radians) of the quad `[a, d, b, c]` of primal edge `e` (see the module
/// doc), in that order.
pub fn quad_corner_angles(mesh: &SurfaceMesh, positions: &[Point3], e: EdgeId) -> [f64; 4] {
    let h: HalfedgeId = e.halfedge();
    let at = |v: VertexId| positions[v.idx()];
    diagonal_quad_angles([
        at(mesh.origin(h)),
        at(mesh.opposite_vertex(h.twin())),
        at(mesh.dest(h)),
        at(mesh.opposite_vertex(h)),
    ])
}

/// The corner angles (radians) of the quad `[a, d, b, c]` made of the triangles `(a, b, c)` and
/// `(b, a, d)` glued along its diagonal from corner 0 to corner 2, measured on the surface as the
/// module doc says: at `a` and `b` the sums of the two triangles' angles, at `c` and `d` theirs.
pub fn diagonal_quad_angles([a, d, b, c]: [Point3; 4]) -> [f64; 4] {
    [
        angle(a, b, c) + angle(a, d, b),
        angle(d, b, a),
        angle(b, c, a) + angle(b, a, d),
        angle(c, a, b),
    ]
}

/// The integer pairing cost `round((1 − η) · COST_RESOLUTION)` of a quad of these corner angles.
pub fn cost_of_angles(angles: [f64; 4]) -> i64 {
    (((1.0 - quality_of_angles(angles)) * COST_RESOLUTION).round() as i64).clamp(0, MAX_COST)
}

/// The quality report of quads given by their corners, each with its diagonal from corner 0 to
/// corner 2 (as [`crate::SurfaceQuads::quads`]), corners measured on the surface
/// ([`diagonal_quad_angles`]). All zero for no quads.
pub fn diagonal_quality_report(positions: &[Point3], quads: &[[u32; 4]]) -> QualityReport {
    report_of_corners(
        quads
            .iter()
            .map(|q| diagonal_quad_angles(q.map(|v| positions[v as usize]))),
    )
}

/// Remacle et al.'s quality `η` of a quad with these corner angles (radians); 0 if one is NaN.
pub fn quality_of_angles(angles: [f64; 4]) -> f64 {
    let worst = max_angle_deviation(angles);
    let q = 1.0 - worst * std::f64::consts::FRAC_2_PI;
    if q.is_nan() { 0.0 } else { q.max(0.0) }
}

/// `max_k |α_k − π/2|` in radians (NaN if an angle is NaN).
fn max_angle_deviation(angles: [f64; 4]) -> f64 {
    angles
        .iter()
        .map(|a| (a - std::f64::consts::FRAC_PI_2).abs())
        .fold(0.0, |m: f64, d| {
            if m.is_nan() || d.is_nan() {
                f64::NAN
            } else {
                m.max(d)
            }
        })
}

/// The quality `η` of the quad of primal edge `e`.
pub fn pair_quality(mesh: &SurfaceMesh, positions: &[Point3], e: EdgeId) -> f64 {
    quality_of_angles(quad_corner_angles(mesh, positions, e))
}

/// The integer pairing cost `round((1 − η) · COST_RESOLUTION)` of every edge slot (0 for removed
/// edges and for edges with one triangle on both sides, which are never paired): the costs the
/// exact and fast quality pairings of `surftopo_matching::weighted` minimise on the mesh's dual.
pub fn pair_costs(mesh: &SurfaceMesh, positions: &[Point3]) -> Vec<i64> {
    let mut costs = vec![0i64; SurfaceMesh::edge_slots(mesh)];
    for e in mesh.edges() {
        let h = e.halfedge();
        if mesh.face(h) == mesh.face(h.twin()) {
            continue;
        }
        costs[e.idx()] = cost_of_angles(quad_corner_angles(mesh, positions, e));
    }
    costs
}

/// The quality figures of a set of quads (the columns of the quality tables).
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct QualityReport {
    /// Number of quads.
    pub quads: usize,
    /// Smallest `η`.
    pub min: f64,
    /// 5th percentile of `η` (nearest rank: the `⌈0.05 n⌉`-th smallest).
    pub p5: f64,
    /// Median of `η` (nearest rank: the `⌈0.5 n⌉`-th smallest).
    pub median: f64,
    /// Mean of `η`.
    pub mean: f64,
    /// Percentage of quads with a corner above 170° or below 10°.
    pub bad_quads_percent: f64,
    /// Median over the quads of `max_k |α_k − 90°|`, in degrees (nearest rank).
    pub median_max_angle_deviation_degrees: f64,
}

/// The value of nearest rank `⌈p n⌉` (1-based) in sorted `values`.
fn nearest_rank(sorted: &[f64], p: f64) -> f64 {
    let rank = ((p * sorted.len() as f64).ceil() as usize).clamp(1, sorted.len());
    sorted[rank - 1]
}

/// The quality report of the quads whose diagonals (removed primal edges of `mesh`) are given.
/// All zero for no quads.
pub fn quality_report(
    mesh: &SurfaceMesh,
    positions: &[Point3],
    diagonals: &[EdgeId],
) -> QualityReport {
    report_of_corners(
        diagonals
            .iter()
            .map(|&e| quad_corner_angles(mesh, positions, e)),
    )
}

/// The corner angles (radians) of the quad `[p0, p1, p2, p3]` measured in space: at each corner
/// the angle between the directions to its two neighbours along the boundary. This is the
/// definition that applies to any tool's quads (only the four vertices are known), the one of
/// the peer comparison. It differs from [`quad_corner_angles`] (the surface definition the
/// pairing costs use) only on a non-planar pair: there the corners at the diagonal's ends are
/// the angle between two edge vectors, at most the sum of the two triangles' angles, so a reflex
/// or folded pair reads below 180° instead of above it.
pub fn space_corner_angles(corners: [Point3; 4]) -> [f64; 4] {
    std::array::from_fn(|k| angle(corners[k], corners[(k + 3) % 4], corners[(k + 1) % 4]))
}

/// The quality report of quads given by their four vertices (indices into `positions`),
/// corners measured in space ([`space_corner_angles`]). All zero for no quads.
pub fn space_quality_report(positions: &[Point3], quads: &[[usize; 4]]) -> QualityReport {
    report_of_corners(
        quads
            .iter()
            .map(|q| space_corner_angles(q.map(|v| positions[v]))),
    )
}

/// The report of quads with these corner angles (radians). All zero for no quads.
fn report_of_corners(corners: impl Iterator<Item = [f64; 4]>) -> QualityReport {
    let mut qualities = Vec::new();
    let mut deviations = Vec::new();
    let mut bad = 0usize;
    let (above, below) = (
        BAD_CORNER_ABOVE_DEGREES.to_radians(),
        BAD_CORNER_BELOW_DEGREES.to_radians(),
    );
    for angles in corners {
        qualities.push(quality_of_angles(angles));
        let deviation = max_angle_deviation(angles);
        deviations.push(if deviation.is_nan() {
            180.0
        } else {
            deviation.to_degrees()
        });
        if angles.iter().any(|&a| !(below..=above).contains(&a)) {
            bad += 1;
        }
    }
    if qualities.is_empty() {
        return QualityReport::default();
    }
    let n = qualities.len();
    let mean = qualities.iter().sum::<f64>() / n as f64;
    qualities.sort_by(f64::total_cmp);
    deviations.sort_by(f64::total_cmp);
    QualityReport {
        quads: n,
        min: qualities[0],
        p5: nearest_rank(&qualities, 0.05),
        median: nearest_rank(&qualities, 0.5),
        mean,
        bad_quads_percent: 100.0 * bad as f64 / n as f64,
        median_max_angle_deviation_degrees: nearest_rank(&deviations, 0.5),
    }
}

/// What a quality-aware pairing minimises the total cost `Σ (1 − η)` by.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum QualityObjective {
    /// The optimum: `surftopo_matching::weighted::min_cost_perfect_matching`, its certificate
    /// checked by the independent verifier before the quads are built.
    Exact,
    /// The fast mode: `surftopo_matching::weighted::fast_min_cost_perfect_matching`.
    Fast,
}

impl QualityObjective {
    /// Both objectives, in the order the CLI lists them.
    pub const ALL: [QualityObjective; 2] = [QualityObjective::Exact, QualityObjective::Fast];

    /// One line on the objective (the CLI's `--objective` help).
    pub fn summary(&self) -> &'static str {
        match self {
            QualityObjective::Exact => {
                "The pairing of least total cost 1 − η (η: Remacle et al.'s quad quality), exact, its optimality certificate verified; `--algorithm` is not used"
            }
            QualityObjective::Fast => {
                "A low-cost pairing by the fast mode (greedy, completion, short exchanges); `--algorithm` is not used"
            }
        }
    }

    /// `quality` or `quality-fast` (the CLI's `--objective` values).
    pub fn name(&self) -> &'static str {
        match self {
            QualityObjective::Exact => "quality",
            QualityObjective::Fast => "quality-fast",
        }
    }
}

/// A quality-aware quadrangulation: the quads, the pairing's total cost and its quality report.
#[derive(Clone, Debug)]
pub struct QualityQuads {
    /// The quads and their diagonals, as [`crate::quadrangulate`] returns them; `stats.algorithm`
    /// is the objective's name, `initial_pairing_seconds` the pairing's time, no augmentation.
    pub result: crate::QuadResult,
    /// Total cost `Σ (1 − η)` over the quads, from the integer costs (`units / COST_RESOLUTION`).
    pub cost: f64,
    /// The same in integer units.
    pub cost_units: i64,
    /// `(cost − optimum) / optimum`: 0 for the exact objective; `None` for the fast one (the
    /// optimum is not computed).
    pub optimality_gap: Option<f64>,
    /// The quads' quality.
    pub report: QualityReport,
}

/// η's summary in [`QuadFigures`].
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct QualitySummary {
    /// Smallest η.
    pub min: f64,
    /// 5th percentile of η.
    pub p5: f64,
    /// Median of η.
    pub median: f64,
    /// Mean of η.
    pub mean: f64,
}

/// The figures of a quadrangulation as `surftopo quad --json` prints them: Table 4.3's columns
/// (the [`crate::QuadStats`]), then the objective, the pairing's cost and its quality.
#[derive(Clone, Debug, serde::Serialize)]
pub struct QuadFigures<'a> {
    /// Table 4.3's columns.
    #[serde(flatten)]
    pub stats: &'a crate::QuadStats,
    /// `count`, `quality` or `quality-fast`.
    pub objective: &'a str,
    /// Total cost `Σ (1 − η)`.
    pub cost: f64,
    /// 0 for the exact optimum; `None` when unknown.
    pub optimality_gap: Option<f64>,
    /// η's summary.
    pub quality: QualitySummary,
    /// Percentage of quads with a corner above 170° or below 10°.
    pub bad_quads_percent: f64,
    /// Median of `max_k |α_k − 90°|`, in degrees.
    pub median_max_angle_deviation: f64,
}

/// A quadrangulation measured by quality, closed ([`QualityQuads`]) or of any surface
/// ([`crate::SurfaceQualityQuads`]): where its figures are, and the figures of
/// `surftopo quad --json` read from them.
pub trait QualityMeasured {
    /// Table 4.3's columns, the total cost `Σ (1 − η)`, the optimality gap and the quality.
    fn measures(&self) -> (&crate::QuadStats, f64, Option<f64>, &QualityReport);

    /// The figures of `surftopo quad --json`, for the objective named `objective`.
    fn figures<'a>(&'a self, objective: &'a str) -> QuadFigures<'a> {
        let (stats, cost, optimality_gap, r) = self.measures();
        QuadFigures {
            stats,
            objective,
            cost,
            optimality_gap,
            quality: QualitySummary {
                min: r.min,
                p5: r.p5,
                median: r.median,
                mean: r.mean,
            },
            bad_quads_percent: r.bad_quads_percent,
            median_max_angle_deviation: r.median_max_angle_deviation_degrees,
        }
    }
}

impl QualityMeasured for QualityQuads {
    fn measures(&self) -> (&crate::QuadStats, f64, Option<f64>, &QualityReport) {
        (
            &self.result.stats,
            self.cost,
            self.optimality_gap,
            &self.report,
        )
    }
}

/// The quads of `algorithm` (any perfect pairing: `--objective count`) with their total cost
/// `Σ (1 − η)` and quality, in the same form as [`quadrangulate_by_quality`] returns (the
/// optimality gap unknown). The cost and quality are measured on the paired triangulation (K
/// for LRS).
///
/// # Errors
/// As [`crate::quadrangulate`].
pub fn quadrangulate_with_quality(
    mesh: &SurfaceMesh,
    positions: &[Point3],
    algorithm: crate::QuadAlgorithm,
) -> Result<QualityQuads, crate::QuadError> {
    let result = crate::quadrangulate(mesh, algorithm)?;
    let paired = result.triangulation.as_ref().unwrap_or(mesh);
    let costs = pair_costs(paired, positions);
    let cost_units: i64 = result.diagonals.iter().map(|e| costs[e.idx()]).sum();
    let report = quality_report(paired, positions, &result.diagonals);
    Ok(QualityQuads {
        result,
        cost: cost_units as f64 / COST_RESOLUTION,
        cost_units,
        optimality_gap: None,
        report,
    })
}

/// Pairs the triangles of a closed mesh into quads minimising (exactly, or by the fast mode) the
/// total cost `1 − η` of [`pair_costs`], and reports the result's quality.
///
/// # Errors
/// [`crate::QuadError::Empty`] for no faces; [`crate::QuadError::NoPerfectPairing`] when the dual
/// has no perfect matching (a non-simplicial mesh); [`crate::QuadError::Internal`] if the exact
/// result's certificate is rejected (a bug).
pub fn quadrangulate_by_quality(
    mesh: &SurfaceMesh,
    positions: &[Point3],
    objective: QualityObjective,
) -> Result<QualityQuads, crate::QuadError> {
    use surftopo_matching::weighted::{
        WeightedError, fast_min_cost_perfect_matching, min_cost_perfect_matching,
        verify_min_cost_perfect_matching,
    };
    let start = std::time::Instant::now();
    if mesh.face_count() == 0 {
        return Err(crate::QuadError::Empty);
    }
    let costs = pair_costs(mesh, positions);
    // Without a perfect pairing, the count pipeline's search names the obstruction.
    let no_pairing = |err: WeightedError| match err {
        WeightedError::NoPerfectMatching { .. }
        | WeightedError::OddNodeCount { .. }
        | WeightedError::Augment(_) => {
            match crate::quadrangulate(mesh, crate::QuadAlgorithm::KarpSipser) {
                Err(count) => count,
                Ok(_) => crate::QuadError::Internal(format!(
                    "quality pairing failed where a perfect pairing exists: {err}"
                )),
            }
        }
        other => crate::QuadError::Internal(format!("quality pairing: {other}")),
    };
    let (edges, cost_units, optimality_gap) = match objective {
        QualityObjective::Exact => {
            let exact = min_cost_perfect_matching(mesh, &costs).map_err(no_pairing)?;
            verify_min_cost_perfect_matching(mesh, &costs, &exact.edges, &exact.certificate)
                .map_err(|err| {
                    crate::QuadError::Internal(format!("optimality certificate rejected: {err}"))
                })?;
            (exact.edges, exact.cost, Some(0.0))
        }
        QualityObjective::Fast => {
            let fast = fast_min_cost_perfect_matching(mesh, &costs).map_err(no_pairing)?;
            (fast.edges, fast.cost, None)
        }
    };
    let pairing_seconds = start.elapsed().as_secs_f64();
    let pairing = surftopo_matching::Pairing::from_edges(mesh, edges.iter().copied())
        .map_err(|err| crate::QuadError::Internal(format!("quality pairing: {err}")))?;
    let pairing = surftopo_matching::verify_perfect_pairing(mesh, pairing)
        .map_err(|err| crate::QuadError::Internal(format!("quality pairing: {err}")))?;
    let (quads, diagonals) = crate::quadrangulate::quads_of(mesh, &pairing);
    let report = quality_report(mesh, positions, &diagonals);
    let stats = crate::QuadStats {
        algorithm: objective.name().to_string(),
        faces: mesh.face_count(),
        initial_pairing_seconds: pairing_seconds,
        paired_percent: 100.0,
        total_seconds: start.elapsed().as_secs_f64(),
        ..crate::QuadStats::default()
    };
    Ok(QualityQuads {
        result: crate::QuadResult {
            quads,
            diagonals,
            triangulation: None,
            pairing,
            stats,
            augmentation: surftopo_matching::AugmentStats::default(),
            expansion: None,
            karp_sipser: None,
        },
        cost: cost_units as f64 / COST_RESOLUTION,
        cost_units,
        optimality_gap,
        report,
    })
}
