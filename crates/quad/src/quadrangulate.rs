//! The quad-mesh pipeline for every pairing algorithm: initial pairing, augmenting paths, quads.
//!
//! Section 2 of the quadrangulation paper (`tri-quad-conversion-long.txt`): a perfect matching M
//! of the dual graph gives a quadrangulation with the same vertices by removing the primal edge of
//! every matched dual edge. Section 4 defines the figures reported in [`QuadStats`] (the columns
//! of Table 4.3).
//!
//! Quad orientation: for a removed edge with half-edge `h = a → b` in triangle (a, b, c) and its
//! twin in (b, a, d), the quad is `[a, d, b, c]`, counter-clockwise like the triangles.

use std::time::Instant;

use surftopo_matching::{
    AugmentError, AugmentStats, AugmentStrategy, KarpSipserOptions, KarpSipserStats, Pairing,
    PerfectPairing, augment_to_perfect, karp_sipser_perfect_with, pulli_segal, simple_greedy,
    verify_perfect_pairing,
};
use surftopo_mesh::{EdgeId, SurfaceMesh, VertexId};

use crate::QuadError;
use crate::lrs::{ExpansionCases, expand};

/// Which initial pairing [`quadrangulate`] computes before the augmenting paths.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum QuadAlgorithm {
    /// SG: simple greedy over a seeded random edge order (Section 3.1).
    SimpleGreedy {
        /// Seed of the edge shuffle.
        seed: u64,
    },
    /// PS: Pulli and Segal's priority sets over a seeded random triangle order (Section 3.1).
    PulliSegal {
        /// Seed of the triangle shuffle.
        seed: u64,
    },
    /// LRS: Ramaswami–Siqueira contractions, then the expansion of Algorithm 3.1 with flips
    /// (Section 3.3). Deterministic. The quads pair triangles of K, not of the input.
    Lrs,
    /// DS: Diks and Stanczyk's perfect matching (Section 3.2, `surftopo-matching`), on the dual
    /// materialised as a [`surftopo_matching::CubicGraph`]. Deterministic, always perfect.
    DiksStanczyk,
    /// KS: the Karp–Sipser greedy with immediate local repairs (not from the paper; see
    /// [`surftopo_matching::karp_sipser_perfect`]). Deterministic. Its repairs count as augmentation.
    KarpSipser,
}

impl QuadAlgorithm {
    /// Every algorithm, the seeded ones (SG, PS) with `seed`, in the order the CLI lists them.
    pub fn all(seed: u64) -> [QuadAlgorithm; 5] {
        [
            QuadAlgorithm::SimpleGreedy { seed },
            QuadAlgorithm::PulliSegal { seed },
            QuadAlgorithm::Lrs,
            QuadAlgorithm::DiksStanczyk,
            QuadAlgorithm::KarpSipser,
        ]
    }

    /// The algorithm whose [`Self::name`] is `name`, the seeded ones with `seed`.
    pub fn from_name(name: &str, seed: u64) -> Option<QuadAlgorithm> {
        Self::all(seed).into_iter().find(|a| a.name() == name)
    }

    /// One line on what the algorithm does (the CLI's `--algorithm` help).
    pub fn summary(&self) -> &'static str {
        match self {
            QuadAlgorithm::SimpleGreedy { .. } => {
                "Simple greedy pairing (seeded edge order), then augmenting paths"
            }
            QuadAlgorithm::PulliSegal { .. } => {
                "Pulli–Segal priority pairing (seeded triangle order), then augmenting paths"
            }
            QuadAlgorithm::Lrs => {
                "Contraction/expansion (Ramaswami–Siqueira, Algorithm 3.1 with flips), then augmenting paths"
            }
            QuadAlgorithm::DiksStanczyk => {
                "Diks–Stanczyk: a perfect matching directly, by Frink reductions"
            }
            QuadAlgorithm::KarpSipser => {
                "Karp–Sipser greedy with immediate local repairs (not from the paper), then augmenting paths; deterministic"
            }
        }
    }

    /// Short name: `sg`, `ps`, `lrs`, `ds` or `ks` (the CLI's `--algorithm` values and the
    /// `algorithm` field of [`QuadStats`]).
    pub fn name(&self) -> &'static str {
        match self {
            QuadAlgorithm::SimpleGreedy { .. } => "sg",
            QuadAlgorithm::PulliSegal { .. } => "ps",
            QuadAlgorithm::Lrs => "lrs",
            QuadAlgorithm::DiksStanczyk => "ds",
            QuadAlgorithm::KarpSipser => "ks",
        }
    }
}

impl std::fmt::Display for QuadAlgorithm {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// Options of [`quadrangulate_with`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct QuadOptions {
    /// How augmenting paths are searched for (default: [`AugmentStrategy::Forest`]; KS has its
    /// own searches).
    pub augment: AugmentStrategy,
    /// KS's settings (default: [`KarpSipserOptions::default`]).
    pub karp_sipser: KarpSipserOptions,
}

/// The figures of one run: the columns of Table 4.3 (what `surftopo quad --json` prints).
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct QuadStats {
    /// `sg`, `ps`, `lrs`, `ds` or `ks`.
    pub algorithm: String,
    /// Number of triangles of the input.
    pub faces: usize,
    /// (a) Seconds to compute the initial pairing (LRS: contraction, expansion and flips).
    pub initial_pairing_seconds: f64,
    /// (b) Percentage of triangles paired by the initial pairing.
    pub paired_percent: f64,
    /// (c) Triangles left unpaired by the initial pairing.
    pub unpaired: usize,
    /// (d) Seconds spent on augmenting paths.
    pub augmentation_seconds: f64,
    /// (e) Seconds for the whole call (pairing, augmentation and building the quads).
    pub total_seconds: f64,
    /// Edges of the input whose flip is in K (LRS; 0 for the other algorithms).
    pub flipped_edges: usize,
    /// KS: whether the file listed its triangles two by two as quads (triangle `2k` adjacent to
    /// `2k + 1`) and those were taken as they are (no greedy, no search). False otherwise.
    pub file_order: bool,
    /// KS: levels of 1-to-4 subdivision its pairing was lifted through (the file lists its
    /// triangles four by four as the children of coarser triangles, level after level); 0
    /// otherwise.
    pub subdivision_levels: u32,
    /// Triangles left unpaired at the end (0 on closed surfaces, and with all quads).
    pub unpaired_triangles: usize,
    /// The fewest triangles any pairing leaves, by the verified Tutte–Berge certificate (summed
    /// over the pieces).
    pub deficiency_lower_bound: usize,
    /// Vertices added on boundary edges for all quads.
    pub added_vertices: usize,
    /// The figures of every piece, when there are several (in the order of their first
    /// triangle).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub components: Vec<crate::surface::ComponentQuads>,
}

/// A quadrangulation and how it was obtained.
#[derive(Clone, Debug)]
pub struct QuadResult {
    /// The quads, counter-clockwise, as vertex ids of the input (same vertex set and positions).
    pub quads: Vec<[VertexId; 4]>,
    /// For each quad, the removed edge: its two triangles are the faces of this edge in
    /// [`QuadResult::triangulation`] (or in the input when that is `None`). Edge ids are the
    /// input's (flips keep edge ids).
    pub diagonals: Vec<EdgeId>,
    /// K, the triangulation whose triangles were paired, when it differs from the input (LRS).
    pub triangulation: Option<SurfaceMesh>,
    /// The pairing of the triangles of the paired triangulation (the input, or K), checked by
    /// the independent verifier of `surftopo-matching` for every algorithm.
    pub pairing: PerfectPairing,
    /// The Table 4.3 figures.
    pub stats: QuadStats,
    /// Details of the augmenting-path phase.
    pub augmentation: AugmentStats,
    /// Branch counts of Algorithm 3.1 (LRS only).
    pub expansion: Option<ExpansionCases>,
    /// Greedy, repair and completion figures (KS only).
    pub karp_sipser: Option<KarpSipserStats>,
}

/// [`quadrangulate_with`] with default options.
///
/// # Errors
/// See [`quadrangulate_with`].
pub fn quadrangulate(
    mesh: &SurfaceMesh,
    algorithm: QuadAlgorithm,
) -> Result<QuadResult, QuadError> {
    quadrangulate_with(mesh, algorithm, &QuadOptions::default())
}

/// Converts a closed triangle mesh into a quad mesh on the same vertices: an initial pairing by
/// `algorithm`, completed into a perfect pairing by augmenting paths (Section 3), then one quad per
/// pair.
///
/// Takes any closed mesh (tombstones allowed; LRS needs a simplicial one). Guarantees: every live
/// triangle of the paired triangulation (the input, or K for LRS) is in exactly one quad (the
/// pairing of every algorithm goes through the independent verifier, O(n), before the quads are
/// built: [`QuadResult::pairing`]); the quads
/// are consistently oriented and form a closed manifold quad mesh of the input's genus on all its
/// vertices (when the input is simplicial). For LRS, the number of triangles the expansion leaves
/// unpaired is checked against the paper's bound `max(4, 56g − 12)`.
///
/// KS reads only `options.karp_sipser` (its repairs and completion are its own, see
/// [`surftopo_matching::karp_sipser_perfect`]); the other algorithms only `options.augment`.
///
/// Complexity: SG, PS and KS O(n) plus the augmentation (see [`surftopo_matching::augment_to_perfect`]); LRS
/// O(g n + g²) (Theorem 3.2) plus the augmentation; DS O(n log² n) amortized.
///
/// # Errors
/// - [`QuadError::Empty`]: no faces.
/// - [`QuadError::NotSimplicial`]: LRS on a non-simplicial mesh.
/// - [`QuadError::NoPerfectPairing`]: a non-simplicial mesh whose dual has no perfect matching.
/// - [`QuadError::Internal`]: a broken invariant (a bug), with diagnostics; never a partial result.
pub fn quadrangulate_with(
    mesh: &SurfaceMesh,
    algorithm: QuadAlgorithm,
    options: &QuadOptions,
) -> Result<QuadResult, QuadError> {
    let start = Instant::now();
    let faces = mesh.face_count();
    if faces == 0 {
        return Err(QuadError::Empty);
    }
    let paired = pair(mesh, algorithm, options, start)?;
    let paired_mesh = paired.triangulation.as_ref().unwrap_or(mesh);
    let pairing = verify_perfect_pairing(paired_mesh, paired.pairing).map_err(|err| {
        QuadError::Internal(format!(
            "the {algorithm} pairing is not a perfect matching of the dual: {err}"
        ))
    })?;
    let (quads, diagonals) = quads_of(paired_mesh, &pairing);
    let stats = paired.run.stats(algorithm, faces, start);
    Ok(QuadResult {
        quads,
        diagonals,
        triangulation: paired.triangulation,
        pairing,
        stats,
        augmentation: paired.run.augmentation,
        expansion: paired.run.expansion,
        karp_sipser: paired.run.karp_sipser,
    })
}

/// A perfect pairing of the paired triangulation (the input, or K) and how it was reached.
struct Paired {
    triangulation: Option<SurfaceMesh>,
    pairing: Pairing,
    run: PairingRun,
}

/// How a pairing was reached, as both pipelines report it (closed here, every surface in
/// [`crate::surface`]).
#[derive(Debug)]
pub(crate) struct PairingRun {
    /// Triangles the initial pairing left unpaired.
    pub(crate) unpaired: usize,
    pub(crate) initial_pairing_seconds: f64,
    pub(crate) augmentation_seconds: f64,
    pub(crate) augmentation: AugmentStats,
    /// Edges LRS's expansion flipped (0 for the others).
    pub(crate) flipped_edges: usize,
    pub(crate) expansion: Option<ExpansionCases>,
    pub(crate) karp_sipser: Option<KarpSipserStats>,
}

impl PairingRun {
    /// KS, timed by its own clocks: greedy = initial pairing, repairs and completion =
    /// augmentation.
    pub(crate) fn karp_sipser(ks: KarpSipserStats) -> Self {
        PairingRun {
            unpaired: ks.isolated,
            initial_pairing_seconds: ks.greedy_seconds,
            augmentation_seconds: ks.augmentation_seconds,
            augmentation: ks.augment,
            flipped_edges: 0,
            expansion: None,
            karp_sipser: Some(ks),
        }
    }

    /// Times the augmenting paths that follow an initial pairing begun at `start` (the initial
    /// pairing's time ends here): `unpaired` counts the triangles it left, `augment` runs the
    /// paths on it. `flipped_edges` and `expansion` are LRS's (0 and `None` for the others).
    pub(crate) fn augment<T>(
        start: Instant,
        pairing: &mut Pairing,
        flipped_edges: usize,
        expansion: Option<ExpansionCases>,
        unpaired: impl FnOnce(&Pairing) -> usize,
        augment: impl FnOnce(&mut Pairing) -> Result<(AugmentStats, T), QuadError>,
    ) -> Result<(Self, T), QuadError> {
        let initial_pairing_seconds = start.elapsed().as_secs_f64();
        let unpaired = unpaired(pairing);
        let augment_start = Instant::now();
        let (augmentation, more) = augment(pairing)?;
        let run = PairingRun {
            unpaired,
            initial_pairing_seconds,
            augmentation_seconds: augment_start.elapsed().as_secs_f64(),
            augmentation,
            flipped_edges,
            expansion,
            karp_sipser: None,
        };
        Ok((run, more))
    }

    /// The figures of `faces` triangles paired by `algorithm`, the total timed from `start`.
    pub(crate) fn stats(
        &self,
        algorithm: QuadAlgorithm,
        faces: usize,
        start: Instant,
    ) -> QuadStats {
        QuadStats {
            algorithm: algorithm.name().to_string(),
            faces,
            initial_pairing_seconds: self.initial_pairing_seconds,
            paired_percent: 100.0 * (faces - self.unpaired) as f64 / faces as f64,
            unpaired: self.unpaired,
            augmentation_seconds: self.augmentation_seconds,
            total_seconds: start.elapsed().as_secs_f64(),
            flipped_edges: self.flipped_edges,
            file_order: self.karp_sipser.is_some_and(|ks| ks.file_order),
            subdivision_levels: self.karp_sipser.map_or(0, |ks| ks.subdivision_levels),
            ..QuadStats::default()
        }
    }
}

/// The initial pairing by `algorithm`, then augmenting paths (KS: its own repairs and completion,
/// timed by its own clocks: greedy = initial pairing, repairs and completion = augmentation).
fn pair(
    mesh: &SurfaceMesh,
    algorithm: QuadAlgorithm,
    options: &QuadOptions,
    start: Instant,
) -> Result<Paired, QuadError> {
    let mut flipped_edges = 0;
    let mut expansion = None;
    let (triangulation, mut pairing) = match algorithm {
        QuadAlgorithm::SimpleGreedy { seed } => (None, simple_greedy(mesh, seed)),
        QuadAlgorithm::PulliSegal { seed } => (None, pulli_segal(mesh, seed)),
        QuadAlgorithm::Lrs => {
            let genus = mesh.genus();
            let reduction = surftopo_irreducible::ramaswami_siqueira(mesh.clone())?;
            let expanded = expand(reduction.mesh, &reduction.history)?;
            let unpaired = expanded.pairing.unmatched_count(&expanded.mesh);
            let bound = (56 * genus - 12).max(4);
            if unpaired as i64 > bound {
                return Err(QuadError::Internal(format!(
                    "LRS left {unpaired} triangles unpaired, above the bound max(4, 56g - 12) = \
                     {bound} for genus {genus}"
                )));
            }
            flipped_edges = expanded.flipped_edges;
            expansion = Some(expanded.cases);
            (Some(expanded.mesh), expanded.pairing)
        }
        QuadAlgorithm::DiksStanczyk => (None, diks_stanczyk_pairing(mesh)?),
        QuadAlgorithm::KarpSipser => {
            let (pairing, ks) = karp_sipser_perfect_with(mesh, &options.karp_sipser)
                .map_err(|err| augmentation_error(mesh, err))?;
            return Ok(Paired {
                triangulation: None,
                pairing,
                run: PairingRun::karp_sipser(ks),
            });
        }
    };
    let paired_mesh = triangulation.as_ref().unwrap_or(mesh);
    let (run, ()) = PairingRun::augment(
        start,
        &mut pairing,
        flipped_edges,
        expansion,
        |p| p.unmatched_count(paired_mesh),
        |p| match augment_to_perfect(paired_mesh, p, options.augment) {
            Ok(augmentation) => Ok((augmentation, ())),
            Err(err) => Err(augmentation_error(paired_mesh, err)),
        },
    )?;
    Ok(Paired {
        triangulation,
        pairing,
        run,
    })
}

/// A failed augmentation is the input's fault only when the mesh is not simplicial.
fn augmentation_error(mesh: &SurfaceMesh, err: AugmentError) -> QuadError {
    match err {
        AugmentError::NoAugmentingPath { .. } if !mesh.is_simplicial() => {
            QuadError::NoPerfectPairing(err)
        }
        _ => QuadError::Internal(format!(
            "augmenting paths on the dual of a simplicial closed surface (which has a perfect \
             matching by Petersen's theorem): {err}"
        )),
    }
}

/// DS on the materialised dual (a compacted copy when the mesh has tombstones), mapped back to
/// the mesh's face and edge ids.
fn diks_stanczyk_pairing(mesh: &SurfaceMesh) -> Result<Pairing, QuadError> {
    let compacted;
    let (dense, map) = if mesh.face_slots() == mesh.face_count()
        && SurfaceMesh::edge_slots(mesh) == mesh.edge_count()
    {
        (mesh, None)
    } else {
        let mut copy = mesh.clone();
        let map = copy.compact();
        compacted = copy;
        (&compacted, Some(map))
    };
    let graph = surftopo_matching::mesh_dual_graph(dense).map_err(|err| {
        QuadError::Internal(format!("the dual graph is not cubic and bridgeless: {err}"))
    })?;
    let matching = surftopo_matching::diks_stanczyk(&graph);
    let mut new_to_old = vec![u32::MAX; dense.edge_count()];
    match &map {
        Some(map) => {
            for (old, new) in map.edges.iter().enumerate() {
                if new.is_valid() {
                    new_to_old[new.idx()] = old as u32;
                }
            }
        }
        None => new_to_old
            .iter_mut()
            .enumerate()
            .for_each(|(e, o)| *o = e as u32),
    }
    let edges = (0..graph.edge_count())
        .filter(|&e| matching.contains_edge(&graph, e))
        .map(|e| new_to_old[e as usize]);
    Pairing::from_edges(mesh, edges)
        .map_err(|err| QuadError::Internal(format!("DS result is not a matching: {err}")))
}

/// One counter-clockwise quad per matched edge, in increasing edge id order (one sequential pass
/// over the edges); a perfect pairing makes one quad of every two triangles.
pub(crate) fn quads_of(
    mesh: &SurfaceMesh,
    pairing: &PerfectPairing,
) -> (Vec<[VertexId; 4]>, Vec<EdgeId>) {
    let flags = pairing.matched_flags();
    let mut quads = Vec::with_capacity(mesh.face_count() / 2);
    let mut diagonals = Vec::with_capacity(mesh.face_count() / 2);
    for (e, _) in flags.iter().enumerate().filter(|&(_, &m)| m) {
        let e = EdgeId::new(e);
        let h = e.halfedge();
        let (a, b) = (mesh.origin(h), mesh.dest(h));
        let (c, d) = (mesh.opposite_vertex(h), mesh.opposite_vertex(h.twin()));
        quads.push([a, d, b, c]);
        diagonals.push(e);
    }
    (quads, diagonals)
}
