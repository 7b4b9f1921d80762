//! `surftopo irreducible`: an irreducible triangulation by topology-preserving edge contractions.

use crate::args::{MeshJobArgs, names};
use crate::failure::invalid;
use serde::Serialize;
use surftopo_irreducible::{Algorithm, Counters, reduce};
use surftopo_mesh::Surface;
use surftopo_mesh::{Renumbering, SurfaceMesh};

/// The arguments of `irreducible`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    pub job: MeshJobArgs,
    /// The algorithm.
    #[arg(
        long,
        default_value = Algorithm::RamaswamiSiqueira.name(),
        value_parser = names(Algorithm::all(0).map(|a| (a.name(), a.summary()))),
    )]
    pub algorithm: String,
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
    algorithm: Algorithm,
) -> anyhow::Result<(Surface, Report)> {
    reduce_surface_renumbered(surface, algorithm)
        .map(|(irreducible, report, _)| (irreducible, report))
}

/// [`reduce_surface`], also returning the renumbering from the input's vertex ids to the
/// irreducible triangulation's (dense) ones: the survivors' attributes follow it.
pub fn reduce_surface_renumbered(
    surface: &Surface,
    algorithm: Algorithm,
) -> anyhow::Result<(Surface, Report, Renumbering)> {
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
        seed: match algorithm {
            Algorithm::BruteForce { seed } => Some(seed),
            _ => None,
        },
    };
    let mut irreducible = Surface {
        mesh: reduction.mesh,
        positions: surface.positions.clone(),
    };
    let renumbering = irreducible.compact();
    Ok((irreducible, report, renumbering))
}

/// Runs `irreducible`.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let (input, output) = (args.job.mesh.as_path(), args.job.output.as_path());
    args.job.check_output()?;
    let algorithm = Algorithm::from_name(&args.algorithm, args.job.seed.seed)
        .ok_or_else(|| anyhow::anyhow!("no irreducible algorithm is called {}", args.algorithm))?;
    let loaded = args.job.read()?;
    let (irreducible, report, renumbering) = crate::progress::step("contracting", || {
        reduce_surface_renumbered(&loaded.surface, algorithm)
    })
    .map_err(|e| e.context(crate::input::name(input)))?;
    // Compacted: vertex ids are dense and in order, as `to_triangles` numbers them.
    let (positions, triangles) = irreducible.to_triangles();
    let mut soup = surftopo_io::PolygonSoup::from_triangles(positions, &triangles);
    soup.attributes = crate::attributes::renumbered(
        &loaded.attributes,
        soup.vertex_count(),
        &renumbering.vertices,
    );
    args.job.write("irreducible", &soup, &loaded)?;
    if args.job.json.json {
        crate::output::print_json(&report)?;
    } else {
        crate::output::emit(&format!(
            "{}: {} vertices, {} edges, {} faces, genus {} (from {} vertices): {} contractions, {} link tests, {} edges tested more than once, {} ({})\n",
            crate::output::name(output),
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
