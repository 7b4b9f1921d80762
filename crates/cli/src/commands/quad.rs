//! `surftopo quad`: a quadrangulation with the same vertices, by a perfect pairing of triangles.

use crate::failure::invalid;
use surftopo_io::PolygonSoup;
use surftopo_mesh::generators::Surface;
use surftopo_quad::quality::QualityObjective;
use surftopo_quad::{
    QuadAlgorithm, QuadError, QuadResult, QualityQuads, quadrangulate, quadrangulate_by_quality,
    quadrangulate_with_quality,
};

/// The `--objective` values.
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Objective {
    /// Any perfect pairing, by `--algorithm` (the fastest).
    #[default]
    Count,
    /// The pairing of least total cost 1 − η (η: Remacle et al.'s quad quality), exact, its
    /// optimality certificate verified; `--algorithm` is not used.
    Quality,
    /// A low-cost pairing by the fast mode (greedy, completion, short exchanges); `--algorithm`
    /// is not used.
    QualityFast,
}

impl Objective {
    fn name(self) -> &'static str {
        match self {
            Objective::Count => "count",
            Objective::Quality => "quality",
            Objective::QualityFast => "quality-fast",
        }
    }
}

/// The `--algorithm` values.
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default)]
pub enum AlgorithmName {
    /// Simple greedy pairing (seeded edge order), then augmenting paths.
    Sg,
    /// Pulli–Segal priority pairing (seeded triangle order), then augmenting paths.
    Ps,
    /// Contraction/expansion (Ramaswami–Siqueira, Algorithm 3.1 with flips), then augmenting paths.
    Lrs,
    /// Diks–Stanczyk: a perfect matching directly, by Frink reductions.
    Ds,
    /// Karp–Sipser greedy with immediate local repairs (not from the paper), then augmenting
    /// paths; deterministic, and the default.
    #[default]
    Ks,
}

/// The library's algorithm of an `--algorithm` value.
fn algorithm_of(name: AlgorithmName, seed: u64) -> QuadAlgorithm {
    match name {
        AlgorithmName::Sg => QuadAlgorithm::SimpleGreedy { seed },
        AlgorithmName::Ps => QuadAlgorithm::PulliSegal { seed },
        AlgorithmName::Lrs => QuadAlgorithm::Lrs,
        AlgorithmName::Ds => QuadAlgorithm::DiksStanczyk,
        AlgorithmName::Ks => QuadAlgorithm::KarpSipser,
    }
}

/// Quadrangulates `surface`; quads use its vertex ids.
pub fn quadrangulate_surface(
    surface: &Surface,
    name: AlgorithmName,
    seed: u64,
) -> anyhow::Result<QuadResult> {
    quadrangulate(&surface.mesh, algorithm_of(name, seed)).map_err(|e| match e {
        QuadError::Internal(_) => anyhow::Error::new(e),
        other => invalid(other.to_string()),
    })
}

/// The quad mesh as a polygon soup on the surface's vertex list (same order, same positions).
pub fn quad_soup(surface: &Surface, result: &QuadResult) -> PolygonSoup {
    let mut soup = PolygonSoup::new();
    soup.positions = surface.positions.clone();
    for quad in &result.quads {
        soup.push_face(&quad.map(|v| v.0));
    }
    soup
}

/// The quads of `objective`, with their total cost, optimality gap (when known) and quality.
fn pair(
    surface: &Surface,
    name: AlgorithmName,
    seed: u64,
    objective: Objective,
) -> anyhow::Result<QualityQuads> {
    let quality = match objective {
        Objective::Count => {
            let algorithm = algorithm_of(name, seed);
            let q = quadrangulate_with_quality(&surface.mesh, &surface.positions, algorithm)
                .map_err(|e| match e {
                    QuadError::Internal(_) => anyhow::Error::new(e),
                    other => invalid(other.to_string()),
                })?;
            return Ok(q);
        }
        Objective::Quality => QualityObjective::Exact,
        Objective::QualityFast => QualityObjective::Fast,
    };
    let q =
        quadrangulate_by_quality(&surface.mesh, &surface.positions, quality).map_err(
            |e| match e {
                QuadError::Internal(_) => anyhow::Error::new(e),
                other => invalid(other.to_string()),
            },
        )?;
    Ok(q)
}

/// Runs `quad`.
pub fn run(
    job: &crate::input::MeshJob,
    name: AlgorithmName,
    objective: Objective,
) -> anyhow::Result<()> {
    let (input, output, seed) = (job.mesh.as_path(), job.output.as_path(), job.seed);
    let loaded = crate::input::read_surface(input, job.weld)?;
    if !loaded.report.dropped_vertices.is_empty() {
        eprintln!(
            "note: the quad mesh's vertex list is the input's without its unreferenced vertices"
        );
    }
    let paired = crate::progress::step("pairing triangles", || {
        pair(&loaded.surface, name, seed, objective)
    })
    .map_err(|e| e.context(crate::failure::shown(input)))?;
    let (result, report, cost) = (&paired.result, &paired.report, paired.cost);
    crate::output::write_soup(output, &quad_soup(&loaded.surface, result))?;
    let stats = &result.stats;
    if job.json {
        crate::output::print_json(&paired.figures(objective.name()))?;
    } else {
        // KS's shortcuts, said in words (the JSON has them as keys).
        let how = if stats.file_order {
            ", the file's own quads".to_string()
        } else if stats.subdivision_levels > 0 {
            format!(
                ", lifted through {} levels of 1-to-4 subdivision",
                stats.subdivision_levels
            )
        } else {
            String::new()
        };
        crate::output::emit(&format!(
            "{}: {} quads from {} triangles ({}{how}): initial pairing {:.1}% in {}, {} unpaired, augmentation {}, total {}, {} flipped edges; cost {cost:.3}, quality median {:.3}, {:.2}% bad quads\n",
            crate::failure::shown(output),
            result.quads.len(),
            stats.faces,
            stats.algorithm,
            stats.paired_percent,
            crate::output::format_seconds(stats.initial_pairing_seconds),
            stats.unpaired,
            crate::output::format_seconds(stats.augmentation_seconds),
            crate::output::format_seconds(stats.total_seconds),
            stats.flipped_edges,
            report.median,
            report.bad_quads_percent
        ))?;
    }
    Ok(())
}
