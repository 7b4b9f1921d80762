//! `surftopo irreducible`: an irreducible triangulation by topology-preserving edge contractions.

use crate::failure::invalid;
use serde::Serialize;
use surftopo_irreducible::{Algorithm, Counters, reduce};
use surftopo_mesh::SurfaceMesh;
use surftopo_mesh::generators::Surface;

/// The `--algorithm` values.
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default)]
pub enum AlgorithmName {
    /// Ramaswami–Siqueira (Section 4): O(g² + gn), linear for genus 0.
    #[default]
    Rs,
    /// Schipper's algorithm (Section 3).
    Schipper,
    /// Randomised brute force (Section 5), seeded by `--seed`.
    BruteForce,
}

/// V, E, F and genus of a mesh.
#[derive(Serialize)]
pub struct Counts {
    /// Vertices.
    pub vertices: usize,
    /// Edges.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// Genus.
    pub genus: i64,
}

impl Counts {
    /// The counts of a mesh's live elements.
    pub fn of(mesh: &SurfaceMesh) -> Self {
        Self {
            vertices: mesh.vertex_count(),
            edges: mesh.edge_count(),
            faces: mesh.face_count(),
            genus: mesh.genus(),
        }
    }
}

/// What `--json` prints.
#[derive(Serialize)]
pub struct Report {
    /// `rs`, `schipper` or `brute-force`.
    pub algorithm: &'static str,
    /// The input's counts.
    pub input: Counts,
    /// The irreducible triangulation's counts.
    pub output: Counts,
    /// ℓ: link-condition tests.
    pub link_tests: u64,
    /// ε: edges tested more than once (0 for RS).
    pub edges_tested_more_than_once: u64,
    /// Edge contractions.
    pub contractions: u64,
    /// Seconds in the algorithm alone (not reading or building).
    pub seconds: f64,
    /// Seed of the brute force's shuffle.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
}

/// Reduces `surface` to an irreducible triangulation; returns it (its vertices are the surviving
/// input vertices with their positions) and the report.
pub fn reduce_surface(
    surface: &Surface,
    name: AlgorithmName,
    seed: u64,
) -> anyhow::Result<(Surface, Report)> {
    let algorithm = match name {
        AlgorithmName::Rs => Algorithm::RamaswamiSiqueira,
        AlgorithmName::Schipper => Algorithm::Schipper,
        AlgorithmName::BruteForce => Algorithm::BruteForce { seed },
    };
    let input = Counts::of(&surface.mesh);
    let reduction = reduce(surface.mesh.clone(), algorithm).map_err(|e| invalid(e.to_string()))?;
    let Counters {
        link_tests,
        edges_tested_more_than_once,
        contractions,
        seconds,
    } = reduction.counters;
    let report = Report {
        algorithm: algorithm.name(),
        input,
        output: Counts::of(&reduction.mesh),
        link_tests,
        edges_tested_more_than_once,
        contractions,
        seconds,
        seed: matches!(name, AlgorithmName::BruteForce).then_some(seed),
    };
    let mut irreducible = Surface {
        mesh: reduction.mesh,
        positions: surface.positions.clone(),
    };
    irreducible.compact();
    Ok((irreducible, report))
}

/// Runs `irreducible`.
pub fn run(job: &crate::input::MeshJob, name: AlgorithmName) -> anyhow::Result<()> {
    let (input, output, seed) = (job.mesh.as_path(), job.output.as_path(), job.seed);
    let loaded = crate::input::read_surface(input, job.weld)?;
    let (irreducible, report) = crate::progress::step("contracting", || {
        reduce_surface(&loaded.surface, name, seed)
    })
    .map_err(|e| e.context(crate::failure::shown(input)))?;
    crate::output::write_surface(output, &irreducible)?;
    if job.json {
        crate::output::print_json(&report)?;
    } else {
        crate::output::emit(&format!(
            "{}: {} vertices, {} edges, {} faces, genus {} (from {} vertices): {} contractions, {} link tests, {} edges tested more than once, {} ({})\n",
            crate::failure::shown(output),
            report.output.vertices,
            report.output.edges,
            report.output.faces,
            report.output.genus,
            report.input.vertices,
            report.contractions,
            report.link_tests,
            report.edges_tested_more_than_once,
            crate::output::format_seconds(report.seconds),
            report.algorithm
        ))?;
    }
    Ok(())
}
