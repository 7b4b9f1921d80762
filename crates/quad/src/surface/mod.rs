//! Quadrangulations of every compact surface: boundary loops, non-orientable pieces, several
//! pieces, each piece on its own.
//!
//! The quadrangulation paper (Section 2) pairs the triangles of a closed orientable surface: its
//! dual is cubic and bridgeless, so a perfect pairing exists (Petersen) and every triangle ends in
//! a quad. The pairing is a question about the dual graph alone, and the same holds on any closed
//! surface, orientable or not (a closed simplicial surface's dual is cubic and bridgeless
//! whatever its orientability). With a boundary it is not so: a triangle with boundary sides has
//! fewer neighbours, and a piece with an odd number of triangles, or a triangle with three ears,
//! cannot be paired entirely. What is ours, beyond the paper:
//!
//! - **The dual** of the surface is read from its cover (`surftopo_matching::SurfaceDual`): one
//!   node per triangle, a boundary side as a half-loop (never matched).
//! - **A maximum pairing** instead of a perfect one: every algorithm's pairing is completed by
//!   augmenting paths until none is left (`surftopo_matching::augment_to_maximum`; KS by its own
//!   completion, `surftopo_matching::karp_sipser_maximum_with`), so the triangles left unpaired
//!   are the fewest any pairing leaves. The proof is the Tutte–Berge barrier of the last search,
//!   checked by the independent verifier (`surftopo_matching::verify_maximum_pairing`) before the
//!   quads are built, piece by piece: its bound is [`ComponentQuads::deficiency_lower_bound`].
//!   On a closed piece the pairing is perfect and the barrier empty.
//! - **Where a paper's algorithm needs a closed surface**: Diks–Stanczyk's reductions need a
//!   bridgeless cubic graph, which the dual of a piece with boundary is not; DS pairs the dual of
//!   the piece's *coned closure* (each boundary loop closed by a cone: cubic and bridgeless), its
//!   pairs with a cone triangle are dropped, and augmenting paths complete the rest to a maximum
//!   ([`coned`]). A closed piece, orientable or not, is paired by DS directly (its dual is cubic
//!   and bridgeless). LRS runs its contraction on the cover and its expansion with a guard that
//!   keeps the boundary, on orientable pieces; it refuses non-orientable ones (`lrs_surface.rs`).
//! - **All quads** ([`SurfaceOptions::all_quads`], [`all_quads`]): each triangle left unpaired
//!   becomes part of a quad by one vertex added on a boundary edge, the fewest vertices any
//!   refinement by boundary-edge vertices needs.
//!
//! A closed orientable surface in one piece takes the closed pipeline unchanged
//! ([`crate::quadrangulate_with`]).
//!
//! Quads: a pair of triangles `(a, b, c)` and `(b, a, d)` across the edge from `a` to `b` of the
//! first triangle (the one the dual met first: the smaller face id) is the quad `[a, d, b, c]`,
//! its diagonal from corner 0 to corner 2, its corners in the order of that triangle, as the
//! cover orients it: the consistent orientation of an orientable piece (the input's where it is
//! consistent), the input's own order on a non-orientable piece, which has no consistent one.

mod all_quads;
mod coned;
mod polygon_input;
mod quality;

use std::time::Instant;

use surftopo_matching::{
    AugmentStats, DualGraph, KarpSipserStats, MaximumPairing, Pairing, SurfaceDual,
    augment_to_maximum, karp_sipser_maximum_with, pulli_segal, simple_greedy,
    verify_maximum_pairing,
};
use surftopo_mesh::{ClosedCover, FaceId, Lifting, SurfaceKind};

use crate::lrs::ExpansionCases;
use crate::quadrangulate::PairingRun;
use crate::{QuadAlgorithm, QuadError, QuadOptions, QuadStats};

pub use all_quads::{AllQuads, all_quads};
pub use polygon_input::{OwnQuads, PolygonQuads, quadrangulate_polygons};
pub use quality::{
    SurfaceQualityQuads, positions_with_added, quadrangulate_surface_by_quality,
    quadrangulate_surface_with_quality, surface_pair_costs,
};

/// Options of [`quadrangulate_surface`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SurfaceOptions {
    /// The pairing's options (as for [`crate::quadrangulate_with`]).
    pub quad: QuadOptions,
    /// Turn the triangles left unpaired into quads by vertices added on boundary edges
    /// ([`all_quads`]).
    pub all_quads: bool,
}

/// The figures of one piece of the surface (a connected component), in the order of its first
/// triangle (as `surftopo info` lists the pieces).
#[derive(Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct ComponentQuads {
    /// What it is, as `surftopo info` names it (sphere, Möbius band, "genus 2 with 3 boundary
    /// loops", ...), when the classification of the pieces was given.
    pub name: String,
    /// Its triangles.
    pub faces: usize,
    /// Its quads.
    pub quads: usize,
    /// Its triangles left unpaired (0 with all quads).
    pub unpaired_triangles: usize,
    /// The fewest triangles any pairing of the piece leaves unpaired, by the verified Tutte–Berge
    /// certificate (equal to the triangles left by the maximum pairing, before any vertex is
    /// added).
    pub deficiency_lower_bound: usize,
    /// Vertices added on its boundary edges for all quads.
    pub added_vertices: usize,
}

/// A quadrangulation of a compact surface (see the module doc).
#[derive(Clone, Debug)]
pub struct SurfaceQuads {
    /// The quads, as surface vertex ids (the cover's classes: the input's vertex ids; added
    /// vertices follow them), each with its diagonal from corner 0 to corner 2, corners in the
    /// order of its first triangle.
    pub quads: Vec<[u32; 4]>,
    /// The triangles left unpaired, as surface vertex ids in the cover's corner order (empty
    /// with [`SurfaceOptions::all_quads`]).
    pub triangles: Vec<[u32; 3]>,
    /// The vertices added for all quads, in order (vertex id `vertex_count + i` for the `i`-th):
    /// each the midpoint of the boundary edge between the two surface vertices given.
    pub added: Vec<[u32; 2]>,
    /// The surface's vertex ids are `0..vertex_count` (the cover's classes, the apexes'
    /// excluded).
    pub vertex_count: usize,
    /// The Table 4.3 figures, with the unpaired triangles, the certificate's bound and the
    /// added vertices, over all pieces (and per piece when there are several).
    pub stats: QuadStats,
    /// The figures of every piece.
    pub components: Vec<ComponentQuads>,
    /// The paired triangulation when it is not the input (LRS flips edges).
    pub triangulation: Option<ClosedCover>,
    /// Details of the augmenting-path phase.
    pub augmentation: AugmentStats,
    /// Branch counts of Algorithm 3.1 (LRS only).
    pub expansion: Option<ExpansionCases>,
    /// Greedy, repair and completion figures (KS only).
    pub karp_sipser: Option<KarpSipserStats>,
}

/// The number of surface vertex ids of a cover: its classes but the apexes' (which come after
/// the surface's vertex ids).
pub fn surface_vertex_count(cover: &ClosedCover) -> usize {
    cover
        .sheets
        .apex_class()
        .map_or(cover.sheets.class_count(), |a| a as usize)
}

/// Quadrangulates a compact surface (its cover, and the classification of its pieces as the
/// cover's [`surftopo_mesh::BuildReport::surfaces`] lists them) with `algorithm`: a maximum
/// pairing of the triangles of every piece, each piece on its own, verified by its Tutte–Berge
/// certificate; with [`SurfaceOptions::all_quads`], the triangles left are turned into quads by
/// added vertices. A closed orientable surface in one piece goes through
/// [`crate::quadrangulate_with`] unchanged (`pieces` only tells whether the surface is in one
/// piece; the figures per piece are computed).
///
/// # Errors
/// [`QuadError::Empty`] without faces; [`QuadError::Internal`] when the certificate is refused or
/// an invariant breaks (a bug, never a partial result); LRS's errors.
pub fn quadrangulate_surface(
    cover: &ClosedCover,
    pieces: &[SurfaceKind],
    algorithm: QuadAlgorithm,
    options: &SurfaceOptions,
) -> Result<SurfaceQuads, QuadError> {
    let start = Instant::now();
    if cover.is_plain() && pieces.len() <= 1 {
        return plain(cover, pieces, algorithm, &options.quad);
    }
    if cover.surface_faces().next().is_none() {
        return Err(QuadError::Empty);
    }
    let Paired {
        cover: flipped,
        dual,
        pairing,
        barrier,
        run,
    } = pair_surface(cover, pieces, algorithm, &options.quad, start)?;
    let paired_cover = flipped.as_ref().unwrap_or(cover);
    let verified = verify_maximum_pairing(&dual, pairing, &barrier).map_err(|err| {
        QuadError::Internal(format!(
            "the {algorithm} pairing is not proven maximum by its barrier: {err}"
        ))
    })?;
    let mut result = quads_of_pairing(paired_cover, &dual, &verified);
    result.name_pieces(pieces);
    if options.all_quads {
        result.complete(paired_cover, &dual, verified)?;
    }
    let faces = dual.node_count();
    result.stats = run.stats(algorithm, faces, start);
    result.fill_totals();
    result.triangulation = flipped;
    result.augmentation = run.augmentation;
    result.expansion = run.expansion;
    result.karp_sipser = run.karp_sipser;
    Ok(result)
}

/// A closed orientable surface in one piece: the closed pipeline, its quads as vertex ids.
fn plain(
    cover: &ClosedCover,
    pieces: &[SurfaceKind],
    algorithm: QuadAlgorithm,
    options: &QuadOptions,
) -> Result<SurfaceQuads, QuadError> {
    let result = crate::quadrangulate_with(&cover.mesh, algorithm, options)?;
    let faces = result.stats.faces;
    let name = pieces.first().map(SurfaceKind::name).unwrap_or_default();
    let mut quads = SurfaceQuads {
        quads: result.quads.iter().map(|q| q.map(|v| v.0)).collect(),
        triangles: Vec::new(),
        added: Vec::new(),
        vertex_count: surface_vertex_count(cover),
        stats: result.stats,
        components: vec![ComponentQuads {
            name,
            faces,
            quads: result.quads.len(),
            ..ComponentQuads::default()
        }],
        triangulation: result.triangulation.map(ClosedCover::plain),
        augmentation: result.augmentation,
        expansion: result.expansion,
        karp_sipser: result.karp_sipser,
    };
    quads.fill_totals();
    Ok(quads)
}

/// A maximum pairing of the paired triangulation's dual, with its barrier, and how it was reached.
struct Paired {
    /// The paired triangulation when it is not the input (LRS).
    cover: Option<ClosedCover>,
    dual: SurfaceDual,
    pairing: Pairing,
    barrier: Vec<u32>,
    run: PairingRun,
}

/// The initial pairing of `algorithm` on the surface's dual, then augmenting paths to a maximum
/// (KS: its own completion).
fn pair_surface(
    cover: &ClosedCover,
    pieces: &[SurfaceKind],
    algorithm: QuadAlgorithm,
    options: &QuadOptions,
    start: Instant,
) -> Result<Paired, QuadError> {
    let mut flipped_cover = None;
    let mut flipped_edges = 0;
    let mut expansion = None;
    let (dual, mut pairing) = match algorithm {
        QuadAlgorithm::SimpleGreedy { seed } => {
            let dual = SurfaceDual::of_cover(cover);
            let pairing = simple_greedy(&dual, seed);
            (dual, pairing)
        }
        QuadAlgorithm::PulliSegal { seed } => {
            let dual = SurfaceDual::of_cover(cover);
            let pairing = pulli_segal(&dual, seed);
            (dual, pairing)
        }
        QuadAlgorithm::DiksStanczyk => {
            let dual = SurfaceDual::of_cover(cover);
            let pairing = coned::diks_stanczyk_on_closure(cover, &dual)?;
            (dual, pairing)
        }
        QuadAlgorithm::Lrs => {
            let expanded = crate::lrs_surface::pair(cover, pieces)?;
            flipped_edges = expanded.flipped_edges;
            expansion = Some(expanded.cases);
            let dual = SurfaceDual::of_cover(&expanded.cover);
            let pairing = expanded.pairing_on(&dual)?;
            flipped_cover = Some(expanded.cover);
            (dual, pairing)
        }
        QuadAlgorithm::KarpSipser => {
            let dual = SurfaceDual::of_cover(cover);
            let (pairing, ks, barrier) = karp_sipser_maximum_with(&dual, &options.karp_sipser);
            return Ok(Paired {
                cover: None,
                dual,
                pairing,
                barrier,
                run: PairingRun::karp_sipser(ks),
            });
        }
    };
    let (run, barrier) = PairingRun::augment(
        start,
        &mut pairing,
        flipped_edges,
        expansion,
        |p| p.unmatched_count(&dual),
        |p| {
            augment_to_maximum(&dual, p, options.augment)
                .map_err(|err| QuadError::Internal(format!("augmenting to a maximum: {err}")))
        },
    )?;
    Ok(Paired {
        cover: flipped_cover,
        dual,
        pairing,
        barrier,
        run,
    })
}

/// The quad `[a, d, b, c]` of dual edge `e` (see the module doc), as surface vertex ids.
pub(crate) fn quad_of_edge(cover: &ClosedCover, dual: &SurfaceDual, e: u32) -> [u32; 4] {
    let mesh = &cover.mesh;
    let h = dual.halfedge(e);
    let class = |v| cover.class(v);
    [
        class(mesh.origin(h)),
        class(mesh.opposite_vertex(h.twin())),
        class(mesh.dest(h)),
        class(mesh.opposite_vertex(h)),
    ]
}

/// The triangle of node `f`, as surface vertex ids in the cover's corner order.
pub(crate) fn triangle_of(cover: &ClosedCover, f: u32) -> [u32; 3] {
    cover.mesh.face_vertices(FaceId(f)).map(|v| cover.class(v))
}

/// The quads and the triangles left of a verified maximum pairing, with the figures per piece.
fn quads_of_pairing(
    cover: &ClosedCover,
    dual: &SurfaceDual,
    pairing: &MaximumPairing,
) -> SurfaceQuads {
    let flags = pairing.matched_flags();
    let quads: Vec<[u32; 4]> = (0..dual.edge_slots() as u32)
        .filter(|&e| flags[e as usize])
        .map(|e| quad_of_edge(cover, dual, e))
        .collect();
    let triangles: Vec<[u32; 3]> = (0..dual.node_slots() as u32)
        .filter(|&f| dual.is_node(f) && pairing.mate_edge(f).is_none())
        .map(|f| triangle_of(cover, f))
        .collect();
    let components = pairing
        .components()
        .iter()
        .map(|c| ComponentQuads {
            name: String::new(),
            faces: c.nodes,
            quads: (c.nodes - c.unmatched) / 2,
            unpaired_triangles: c.unmatched,
            deficiency_lower_bound: c.deficiency_lower_bound,
            added_vertices: 0,
        })
        .collect();
    SurfaceQuads {
        quads,
        triangles,
        added: Vec::new(),
        vertex_count: surface_vertex_count(cover),
        stats: QuadStats::default(),
        components,
        triangulation: None,
        augmentation: AugmentStats::default(),
        expansion: None,
        karp_sipser: None,
    }
}

impl SurfaceQuads {
    /// Names the pieces after their classification (in the same order: first triangle).
    pub(crate) fn name_pieces(&mut self, pieces: &[SurfaceKind]) {
        if pieces.len() == self.components.len() {
            for (c, kind) in self.components.iter_mut().zip(pieces) {
                c.name = kind.name();
            }
        }
    }

    /// Sums the pieces' figures into the stats (and lists the pieces there when there are
    /// several).
    pub(crate) fn fill_totals(&mut self) {
        let sum = |f: fn(&ComponentQuads) -> usize| self.components.iter().map(f).sum();
        self.stats.unpaired_triangles = sum(|c| c.unpaired_triangles);
        self.stats.deficiency_lower_bound = sum(|c| c.deficiency_lower_bound);
        self.stats.added_vertices = sum(|c| c.added_vertices);
        self.stats.components = if self.components.len() > 1 {
            self.components.clone()
        } else {
            Vec::new()
        };
    }

    /// Turns the triangles left into quads by added vertices ([`all_quads`]).
    fn complete(
        &mut self,
        cover: &ClosedCover,
        dual: &SurfaceDual,
        pairing: MaximumPairing,
    ) -> Result<(), QuadError> {
        let done = all_quads(cover, dual, pairing)?;
        self.quads = done.quads;
        self.triangles.clear();
        self.added = done.added;
        for (c, added) in self.components.iter_mut().zip(done.added_per_component) {
            c.added_vertices = added;
            c.quads = (c.faces + added) / 2;
            c.unpaired_triangles = 0;
        }
        Ok(())
    }
}
