//! `surftopo quad`: a quadrangulation with the same vertices, by a maximum pairing of triangles
//! (perfect on closed surfaces), on any compact surface.

use crate::args::{MeshJobArgs, names};
use crate::failure::invalid;
use surftopo_io::PolygonSoup;
use surftopo_mesh::geometry::Point3;
use surftopo_mesh::{CoveredSurface, Surface, SurfaceKind};
use surftopo_quad::quality::QualityObjective;
use surftopo_quad::{
    QuadAlgorithm, QuadError, QuadResult, SurfaceOptions, SurfaceQuads, SurfaceQualityQuads,
    positions_with_added, quadrangulate_surface_by_quality, quadrangulate_surface_with_quality,
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
    /// On a surface with boundary, turn the triangles no pairing can pair into quads, each by one
    /// vertex added at the midpoint of a boundary edge (the fewest such vertices).
    #[arg(long)]
    pub all_quads: bool,
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

/// The quadrangulation of a compact surface as a polygon soup: the surface's vertices (same
/// order, same positions), then the vertices added for all quads (midpoints of their boundary
/// edges); the quads, then the triangles left unpaired.
pub fn surface_quad_soup(positions: &[Point3], result: &SurfaceQuads) -> PolygonSoup {
    let mut soup = PolygonSoup::new();
    soup.positions = positions_with_added(positions, result);
    for quad in &result.quads {
        soup.push_face(quad);
    }
    for triangle in &result.triangles {
        soup.push_face(triangle);
    }
    soup
}

/// The input's per-vertex attributes for the output's vertex list: the surface's vertices
/// keep theirs; an added vertex gets the mean of its edge's two ends (rounded for integer
/// columns).
fn attributes_with_added(
    attributes: &surftopo_io::Attributes,
    result: &SurfaceQuads,
) -> Vec<surftopo_io::VertexProperty> {
    attributes
        .vertex
        .iter()
        .map(|p| {
            let mut values = p.values[..result.vertex_count.min(p.values.len())].to_vec();
            values.resize(result.vertex_count, 0.0);
            for &[a, b] in &result.added {
                let mean = 0.5 * (p.values[a as usize] + p.values[b as usize]);
                values.push(if p.scalar.is_int() {
                    mean.round()
                } else {
                    mean
                });
            }
            surftopo_io::VertexProperty {
                name: p.name.clone(),
                scalar: p.scalar,
                values,
            }
        })
        .collect()
}

/// The quads of `objective` on any compact surface, with their total cost, optimality gap (when
/// known) and quality.
fn pair(
    surface: &CoveredSurface,
    pieces: &[SurfaceKind],
    algorithm: QuadAlgorithm,
    objective: Option<QualityObjective>,
    all_quads: bool,
) -> anyhow::Result<SurfaceQualityQuads> {
    let done = match objective {
        None => {
            let options = SurfaceOptions {
                all_quads,
                ..SurfaceOptions::default()
            };
            quadrangulate_surface_with_quality(surface, pieces, algorithm, &options)
        }
        Some(quality) => quadrangulate_surface_by_quality(surface, pieces, quality, all_quads),
    };
    done.map_err(|e| match e {
        QuadError::Internal(_) => anyhow::Error::new(e),
        other => invalid(other.to_string()),
    })
}

/// Runs `quad`.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let (input, output) = (args.job.mesh.as_path(), args.job.output.as_path());
    args.job.check_output()?;
    let algorithm = algorithm_named(&args.algorithm, args.job.seed.seed)?;
    let objective = objective_named(&args.objective)?;
    let loaded = args.job.read_covered()?;
    if !loaded.report.dropped_vertices.is_empty() {
        stderr_println!(
            "note: the quad mesh's vertex list is the input's without its unreferenced vertices"
        );
    }
    let pieces = &loaded.report.surfaces;
    let paired = crate::progress::step("pairing triangles", || {
        pair(
            &loaded.surface,
            pieces,
            algorithm,
            objective,
            args.all_quads,
        )
    })
    .map_err(|e| e.context(crate::input::name(input)))?;
    let (result, report, cost) = (&paired.result, &paired.report, paired.cost);
    let mut soup = surface_quad_soup(&loaded.surface.positions, result);
    soup.attributes.vertex = attributes_with_added(&loaded.attributes, result);
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
        // What a surface with boundary leaves (said only when it is not all quads).
        let left = if stats.unpaired_triangles > 0 {
            format!(
                "; {} triangles left (no pairing leaves fewer)",
                stats.unpaired_triangles
            )
        } else if stats.added_vertices > 0 {
            format!(
                "; {} vertices added on boundary edges (one per triangle no pairing could pair)",
                stats.added_vertices
            )
        } else {
            String::new()
        };
        crate::output::emit(&format!(
            "{}: {} quads from {} triangles ({}{how}): initial pairing {:.1}% in {}, {} unpaired, augmentation {}, total {}, {} flipped edges; cost {cost:.3}, quality median {:.3}, {:.2}% bad quads{left}\n",
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
