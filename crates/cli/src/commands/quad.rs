//! `surftopo quad`: a quadrangulation with the same vertices, by a perfect pairing of triangles.

use crate::args::{MeshJobArgs, names};
use crate::failure::invalid;
use surftopo_io::PolygonSoup;
use surftopo_mesh::Surface;
use surftopo_quad::quality::QualityObjective;
use surftopo_quad::{
    QuadAlgorithm, QuadError, QuadResult, QualityQuads, quadrangulate_by_quality,
    quadrangulate_with_quality,
};

/// The arguments of `quad`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    pub job: MeshJobArgs,
    /// The initial pairing (for `--objective count`).
    #[arg(
        long,
        default_value = QuadAlgorithm::KarpSipser.name(),
        value_parser = names(QuadAlgorithm::all(0).map(|a| (a.name(), a.summary()))),
    )]
    pub algorithm: String,
    /// What the pairing optimises.
    #[arg(
        long,
        default_value = COUNT,
        value_parser = names(
            std::iter::once((COUNT, COUNT_HELP))
                .chain(QualityObjective::ALL.map(|o| (o.name(), o.summary())))
        ),
    )]
    pub objective: String,
}

/// The `--objective` of any perfect pairing by `--algorithm` (the others are
/// [`QualityObjective`]s).
const COUNT: &str = "count";
/// The help of `--objective count`.
const COUNT_HELP: &str = "Any perfect pairing, by `--algorithm` (the fastest)";

/// The library's algorithm of an `--algorithm` value.
pub fn algorithm_named(name: &str, seed: u64) -> anyhow::Result<QuadAlgorithm> {
    QuadAlgorithm::from_name(name, seed)
        .ok_or_else(|| anyhow::anyhow!("no quad algorithm is called {name}"))
}

/// The quality objective of an `--objective` value (`None` for `count`).
fn objective_named(name: &str) -> anyhow::Result<Option<QualityObjective>> {
    if name == COUNT {
        return Ok(None);
    }
    QualityObjective::ALL
        .into_iter()
        .find(|o| o.name() == name)
        .map(Some)
        .ok_or_else(|| anyhow::anyhow!("no quad objective is called {name}"))
}

/// The quad mesh as a polygon soup on the surface's vertex list (same order, same positions; no
/// attributes: `run` adds the input's per-vertex ones, which follow the vertex list).
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
    algorithm: QuadAlgorithm,
    objective: Option<QualityObjective>,
) -> anyhow::Result<QualityQuads> {
    let quality = match objective {
        None => {
            let q = quadrangulate_with_quality(&surface.mesh, &surface.positions, algorithm)
                .map_err(|e| match e {
                    QuadError::Internal(_) => anyhow::Error::new(e),
                    other => invalid(other.to_string()),
                })?;
            return Ok(q);
        }
        Some(quality) => quality,
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
pub fn run(args: &Args) -> anyhow::Result<()> {
    let (input, output) = (args.job.mesh.as_path(), args.job.output.as_path());
    args.job.check_output()?;
    let algorithm = algorithm_named(&args.algorithm, args.job.seed.seed)?;
    let objective = objective_named(&args.objective)?;
    let loaded = args.job.read()?;
    if !loaded.report.dropped_vertices.is_empty() {
        stderr_println!(
            "note: the quad mesh's vertex list is the input's without its unreferenced vertices"
        );
    }
    let paired = crate::progress::step("pairing triangles", || {
        pair(&loaded.surface, algorithm, objective)
    })
    .map_err(|e| e.context(crate::input::name(input)))?;
    let (result, report, cost) = (&paired.result, &paired.report, paired.cost);
    let mut soup = quad_soup(&loaded.surface, result);
    soup.attributes.vertex = loaded.attributes.vertex.clone();
    args.job.write("quad", &soup, &loaded.attributes)?;
    let stats = &result.stats;
    if args.job.json.json {
        crate::output::print_json(&paired.figures(&args.objective))?;
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
            crate::output::name(output),
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
