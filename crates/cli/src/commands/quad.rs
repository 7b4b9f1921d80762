//! `surftopo quad`: a quadrangulation with the same vertices, by a perfect pairing of triangles.

use crate::failure::invalid;
use surftopo_io::PolygonSoup;
use surftopo_mesh::generators::Surface;
use surftopo_quad::{QuadAlgorithm, QuadError, QuadResult, quadrangulate};

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
    /// paths: the fastest on every input we measured (README).
    #[default]
    Ks,
}

/// Quadrangulates `surface`; quads use its vertex ids.
pub fn quadrangulate_surface(
    surface: &Surface,
    name: AlgorithmName,
    seed: u64,
) -> anyhow::Result<QuadResult> {
    let algorithm = match name {
        AlgorithmName::Sg => QuadAlgorithm::SimpleGreedy { seed },
        AlgorithmName::Ps => QuadAlgorithm::PulliSegal { seed },
        AlgorithmName::Lrs => QuadAlgorithm::Lrs,
        AlgorithmName::Ds => QuadAlgorithm::DiksStanczyk,
        AlgorithmName::Ks => QuadAlgorithm::KarpSipser,
    };
    quadrangulate(&surface.mesh, algorithm).map_err(|e| match e {
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

/// Runs `quad`.
pub fn run(job: &crate::input::MeshJob, name: AlgorithmName) -> anyhow::Result<()> {
    let (input, output, seed) = (job.mesh.as_path(), job.output.as_path(), job.seed);
    let loaded = crate::input::read_surface(input, job.weld)?;
    if !loaded.report.dropped_vertices.is_empty() {
        eprintln!(
            "note: the quad mesh's vertex list is the input's without its unreferenced vertices"
        );
    }
    let result = crate::progress::step("pairing triangles", || {
        quadrangulate_surface(&loaded.surface, name, seed)
    })
    .map_err(|e| e.context(crate::failure::shown(input)))?;
    crate::output::write_soup(output, &quad_soup(&loaded.surface, &result))?;
    let stats = &result.stats;
    if job.json {
        crate::output::print_json(stats)?;
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
            "{}: {} quads from {} triangles ({}{how}): initial pairing {:.1}% in {:.3} s, {} unpaired, augmentation {:.3} s, total {:.3} s, {} flipped edges\n",
            crate::failure::shown(output),
            result.quads.len(),
            stats.faces,
            stats.algorithm,
            stats.paired_percent,
            stats.initial_pairing_seconds,
            stats.unpaired,
            stats.augmentation_seconds,
            stats.total_seconds,
            stats.flipped_edges
        ))?;
    }
    Ok(())
}
