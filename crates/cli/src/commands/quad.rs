//! `surftopo quad`: a quadrangulation with the same vertices, by a maximum pairing of triangles
//! (perfect on closed surfaces), on any compact surface.

use crate::args::{MeshJobArgs, names};
use crate::failure::invalid;
use surftopo_io::PolygonSoup;
use surftopo_quad::quality::{QualityMeasured, QualityObjective};
use surftopo_quad::{
    OwnQuads, QuadAlgorithm, QuadError, QuadResult, SurfaceQuads, quadrangulate_polygons,
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

/// The quad mesh on the input's vertex list (same order, same positions and per-vertex
/// attributes, unreferenced vertices kept): the quads on the surface's vertex ids mapped back
/// through `input_vertices` ([`surftopo_mesh::BuildReport::input_vertices`]).
pub fn quad_soup(input: &PolygonSoup, input_vertices: &[u32], result: &QuadResult) -> PolygonSoup {
    let mut soup = PolygonSoup::new();
    soup.positions = input.positions.clone();
    soup.attributes.vertex = input.attributes.vertex.clone();
    for quad in &result.quads {
        soup.push_face(&quad.map(|v| input_vertices[v.idx()]));
    }
    soup
}

/// The quadrangulation of a compact surface on the input's vertex list (same order, same
/// positions and per-vertex attributes, unreferenced vertices kept), then the vertices added for
/// all quads (midpoints of their boundary edges; per-vertex attributes: the mean of the edge's
/// ends, rounded for integer columns); the quads, then the triangles left unpaired. Surface
/// vertex ids are mapped back through `input_vertices`
/// ([`surftopo_mesh::BuildReport::input_vertices`]).
pub fn surface_quad_soup(
    input: &PolygonSoup,
    input_vertices: &[u32],
    result: &SurfaceQuads,
) -> PolygonSoup {
    let mut soup = PolygonSoup::new();
    let base = input.positions.len() as u32;
    let index = |v: u32| {
        if (v as usize) < result.vertex_count {
            input_vertices[v as usize]
        } else {
            base + (v - result.vertex_count as u32)
        }
    };
    let ends: Vec<[usize; 2]> = result
        .added
        .iter()
        .map(|e| e.map(|v| index(v) as usize))
        .collect();
    soup.positions = input.positions.clone();
    for &[a, b] in &ends {
        let (p, q) = (input.positions[a], input.positions[b]);
        soup.positions
            .push(std::array::from_fn(|k| 0.5 * (p[k] + q[k])));
    }
    soup.attributes.vertex = input
        .attributes
        .vertex
        .iter()
        .map(|p| {
            let mut values = p.values.clone();
            for &[a, b] in &ends {
                let mean = 0.5 * (p.values[a] + p.values[b]);
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
        .collect();
    for quad in &result.quads {
        soup.push_face(&quad.map(index));
    }
    for triangle in &result.triangles {
        soup.push_face(&triangle.map(index));
    }
    soup
}

/// Runs `quad`.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let (input, output) = (args.job.mesh.as_path(), args.job.output.as_path());
    args.job.check_output()?;
    let algorithm = algorithm_named(&args.algorithm, args.job.seed.seed)?;
    let objective = objective_named(&args.objective)?;
    let loaded = args.job.read_covered()?;
    let input_vertices = loaded.report.input_vertices();
    let paired = crate::progress::step("pairing triangles", || {
        quadrangulate_polygons(
            &loaded.surface,
            &loaded.report.surfaces,
            loaded.soup.faces(),
            &input_vertices,
            algorithm,
            objective,
            args.all_quads,
        )
    })
    .map_err(|e| match e {
        QuadError::Internal(_) => anyhow::Error::new(e),
        other => invalid(other.to_string()),
    })
    .map_err(|e| e.context(crate::input::name(input)))?;
    let objective_name = paired.objective_name(&args.objective);
    let (result, report, cost) = (
        &paired.quads.result,
        &paired.quads.report,
        paired.quads.cost,
    );
    let own = match &paired.own {
        OwnQuads::Kept(quads) => {
            stderr_println!(
                "note: {}: every face is a quad: its own quads are written (the two triangles \
                 cut from each paired back by `ks`; --algorithm and --objective do not apply)",
                crate::input::name(input)
            );
            Some(quads)
        }
        OwnQuads::NotPairedBack => {
            stderr_println!(
                "note: {}: every face is a quad, but the triangles cut from them do not pair \
                 back in file order: `ks`'s quads are written",
                crate::input::name(input)
            );
            None
        }
        OwnQuads::NotQuadOnly => None,
    };
    let mut soup = surface_quad_soup(&loaded.soup, &input_vertices, result);
    if let Some(quads) = own {
        soup.face_indices.clear();
        soup.face_offsets.truncate(1);
        for quad in quads {
            soup.push_face(quad);
        }
    }
    args.job.write("quad", &soup, &loaded.soup.attributes)?;
    let stats = &result.stats;
    if args.job.json.json {
        crate::output::print_json(&paired.quads.figures(objective_name))?;
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
