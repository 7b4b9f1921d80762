//! `surftopo irreducible`: an irreducible triangulation of any compact surface by
//! topology-preserving edge contractions.

use crate::args::{MeshJobArgs, names};
use crate::failure::invalid;
use serde::Serialize;
use surftopo_io::PolygonSoup;
use surftopo_irreducible::{Algorithm, Counters};
use surftopo_mesh::{CoveredSurface, VertexId};

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
    /// Write only the surviving vertices, numbered densely in input order (by default the
    /// output keeps the input's whole vertex list, so its vertex numbers are the input's).
    #[arg(long)]
    pub compact: bool,
}

/// V, E, F, genus and the classification of a triangulated surface.
#[derive(Serialize)]
pub struct Counts {
    /// Vertices.
    pub vertices: usize,
    /// Edges.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// Genus, when the surface is one orientable piece (closed or not).
    pub genus: Option<i64>,
    /// V − E + F.
    pub euler_characteristic: i64,
    /// One classification per connected component.
    pub surfaces: Vec<crate::commands::info::SurfaceJson>,
}

impl Counts {
    /// The counts of a surface's triangles (any vertex ids).
    pub fn of(triangles: &[[u32; 3]]) -> Self {
        let vertices = triangles
            .iter()
            .flatten()
            .max()
            .map_or(0, |&v| v as usize + 1);
        Self::of_pieces(&surftopo_mesh::inspect(vertices, triangles).surfaces)
    }

    /// The counts of a surface from the classification of its pieces.
    pub fn of_pieces(pieces: &[surftopo_mesh::SurfaceKind]) -> Self {
        let sum = |f: fn(&surftopo_mesh::SurfaceKind) -> usize| pieces.iter().map(f).sum();
        let (vertices, edges, faces): (usize, usize, usize) =
            (sum(|k| k.vertices), sum(|k| k.edges), sum(|k| k.faces));
        Self {
            vertices,
            edges,
            faces,
            genus: match pieces {
                [one] => one.genus.map(|g| g as i64),
                _ => None,
            },
            euler_characteristic: vertices as i64 - edges as i64 + faces as i64,
            surfaces: pieces.iter().map(Into::into).collect(),
        }
    }

    /// The surfaces' names ([`crate::input::piece_names`]).
    pub fn names(&self) -> String {
        crate::input::piece_names(self.surfaces.iter().map(|s| s.name.clone()))
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

/// Reduces `surface` (any compact surface, whose pieces are classified as `pieces`: the
/// [`surftopo_mesh::BuildReport::surfaces`] of its building) to an irreducible triangulation;
/// returns its triangles on the surface's vertex ids (the surviving ones) and the report.
pub fn reduce_covered(
    surface: &CoveredSurface,
    pieces: &[surftopo_mesh::SurfaceKind],
    algorithm: Algorithm,
) -> anyhow::Result<(Vec<[u32; 3]>, Report)> {
    let input = Counts::of_pieces(pieces);
    let reduction = surftopo_irreducible::reduce_surface(surface.cover.clone(), algorithm)
        .map_err(|e| invalid(e.to_string()))?;
    let Counters {
        link_tests,
        edges_tested_more_than_once,
        contractions,
        seconds,
    } = reduction.counters;
    let triangles = reduction.cover.surface_triangles();
    let report = Report {
        algorithm: algorithm.name(),
        input,
        output: Counts::of(&triangles),
        link_tests,
        edges_tested_more_than_once,
        contractions,
        seconds,
        seed: match algorithm {
            Algorithm::BruteForce { seed } => Some(seed),
            _ => None,
        },
    };
    Ok((triangles, report))
}

/// The output mesh of triangles given by indices into `input`'s vertex list: on that whole
/// list (the input's numbering, unreferenced vertices kept), or with `compact` on the vertices
/// the triangles use, numbered densely in input order; per-vertex attributes follow.
pub fn on_input_vertices(
    input: &PolygonSoup,
    triangles: &[[u32; 3]],
    compact: bool,
) -> PolygonSoup {
    if !compact {
        let mut soup = PolygonSoup::from_triangles(input.positions.clone(), triangles);
        soup.attributes.vertex = input.attributes.vertex.clone();
        return soup;
    }
    let mut old_to_new = vec![VertexId::INVALID; input.positions.len()];
    for &v in triangles.iter().flatten() {
        old_to_new[v as usize] = VertexId(0);
    }
    let mut positions = Vec::new();
    for (old, new) in old_to_new.iter_mut().enumerate() {
        if new.is_valid() {
            *new = VertexId(positions.len() as u32);
            positions.push(input.positions[old]);
        }
    }
    let dense: Vec<[u32; 3]> = triangles
        .iter()
        .map(|t| t.map(|v| old_to_new[v as usize].0))
        .collect();
    let mut soup = PolygonSoup::from_triangles(positions, &dense);
    soup.attributes =
        crate::attributes::renumbered(&input.attributes, soup.vertex_count(), &old_to_new);
    soup
}

/// Runs `irreducible`.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let (input, output) = (args.job.mesh.as_path(), args.job.output.as_path());
    args.job.check_output()?;
    let algorithm = Algorithm::from_name(&args.algorithm, args.job.seed.seed)
        .ok_or_else(|| anyhow::anyhow!("no irreducible algorithm is called {}", args.algorithm))?;
    let loaded = args.job.read_covered()?;
    let (triangles, report) = crate::progress::step("contracting", || {
        reduce_covered(&loaded.surface, &loaded.report.surfaces, algorithm)
    })
    .map_err(|e| e.context(crate::input::name(input)))?;
    let input_vertices = loaded.report.input_vertices();
    let triangles: Vec<[u32; 3]> = triangles
        .iter()
        .map(|t| t.map(|v| input_vertices[v as usize]))
        .collect();
    let soup = on_input_vertices(&loaded.soup, &triangles, args.compact);
    args.job
        .write("irreducible", &soup, &loaded.soup.attributes)?;
    if args.job.json.json {
        crate::output::print_json(&report)?;
    } else {
        crate::output::emit(&format!(
            "{}: {} vertices, {} edges, {} faces, {} (from {} vertices): {} contractions, {} link tests, {} edges tested more than once, {} ({})\n",
            crate::output::name(output),
            report.output.vertices,
            report.output.edges,
            report.output.faces,
            report.output.names(),
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
