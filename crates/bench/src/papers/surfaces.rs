//! Irreducible triangulations beyond the paper's closed orientable surfaces: RS's time and
//! counters on a doubling series of non-orientable surfaces (the paper's Theorem 12 bound in
//! the Euler genus h, O(h² + h·n), as its conclusion states for non-orientable surfaces), and
//! the vertex counts that RS, S and BF reach on the projective plane, the Klein bottle, the
//! Möbius band and the disk against the known irreducible triangulations (Barnette; Lawrencenko
//! and Negami, Sulanke; Chávez, Lawrencenko, Quintero and Villar; a lone triangle). Every
//! output is checked irreducible (Dey et al.'s rule on its triangles) and of the input's
//! topology.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use serde::{Deserialize, Serialize};
use surftopo_irreducible::{Algorithm, is_irreducible_surface, reduce_surface};
use surftopo_mesh::generators::{
    self, crosscaps, disk, klein_bottle, mobius_band, projective_plane,
};
use surftopo_mesh::{CoveredSurface, inspect};

use super::inputs::Scale;
use super::measure::timed;
use super::plot::{self, Axis, Plot, Series};
use super::report::{header, number, row, seconds};
use super::{Measured, Options, finish, measured_or_rendered};

/// One run of RS on a non-orientable surface of the series.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct SeriesRow {
    /// Crosscaps (the Euler genus h).
    pub crosscaps: u32,
    /// Triangles n.
    pub triangles: usize,
    /// Least wall-clock seconds of RS alone over the calls.
    pub wall_seconds: f64,
    /// Mean CPU seconds per call (the cover's copy included).
    pub cpu_seconds: f64,
    /// ℓ.
    pub link_tests: u64,
    /// ε.
    pub edges_tested_more_than_once: u64,
    /// Contractions.
    pub contractions: u64,
    /// Vertices of the irreducible output.
    pub output_vertices: usize,
}

/// The vertex counts one algorithm reached on many random triangulations of one surface.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct CountsRow {
    /// The surface.
    pub surface: String,
    /// `rs`, `schipper`, `brute-force`.
    pub algorithm: String,
    /// Output vertex count -> runs.
    pub counts: BTreeMap<usize, usize>,
    /// The vertex counts of the surface's irreducible triangulations in the literature.
    pub known: String,
}

/// The vertices of a covered surface's triangles.
fn vertices(s: &CoveredSurface) -> usize {
    let mut v: Vec<u32> = s.cover.surface_triangles().concat();
    v.sort_unstable();
    v.dedup();
    v.len()
}

/// `(χ, orientable, boundary loops)` of each piece.
fn topology(triangles: &[[u32; 3]]) -> Vec<(i64, bool, usize)> {
    let n = triangles
        .iter()
        .flatten()
        .max()
        .map_or(0, |&v| v as usize + 1);
    inspect(n, triangles)
        .surfaces
        .iter()
        .map(|k| (k.euler_characteristic, k.orientable, k.boundary_loops))
        .collect()
}

/// Reduces `input`, checks the output, returns it with the counters.
fn reduce_checked(
    input: &CoveredSurface,
    algorithm: Algorithm,
) -> anyhow::Result<(CoveredSurface, surftopo_irreducible::Counters)> {
    let red = reduce_surface(input.cover.clone(), algorithm)?;
    let out = CoveredSurface {
        cover: red.cover,
        positions: input.positions.clone(),
    };
    let triangles = out.cover.surface_triangles();
    anyhow::ensure!(
        is_irreducible_surface(&triangles),
        "{}: output reducible",
        algorithm.name()
    );
    anyhow::ensure!(
        topology(&triangles) == topology(&input.cover.surface_triangles()),
        "{}: topology changed",
        algorithm.name()
    );
    Ok((out, red.counters))
}

/// N_h refined to about `n` triangles by random vertex splits, then flipped (3 flips a
/// triangle): irregular connectivity.
fn series_input(h: u32, n: usize, seed: u64) -> CoveredSurface {
    let base = crosscaps(h);
    let faces = base.cover.surface_faces().count();
    let split = generators::random_vertex_splits_covered(&base, n.saturating_sub(faces) / 2, seed);
    generators::random_flips_covered(&split, 3 * n, seed + 1)
}

/// The series: h in {1, 2, 4, 8, 16}, n doubling.
fn measure_series(scale: Scale) -> (Vec<SeriesRow>, Vec<String>) {
    let sizes: &[usize] = match scale {
        Scale::Tiny => &[500, 1_000],
        Scale::Quick => &[2_000, 4_000, 8_000, 16_000, 32_000],
        Scale::Full => &[4_000, 8_000, 16_000, 32_000, 64_000, 128_000, 256_000],
    };
    let min_total = if scale == Scale::Tiny { 0.0 } else { 0.3 };
    let (mut rows, mut failures) = (Vec::new(), Vec::new());
    for h in [1u32, 2, 4, 8, 16] {
        for &n in sizes {
            let input = series_input(h, n, 2 * n as u64 + u64::from(h));
            let triangles = input.cover.surface_faces().count();
            let run = timed(min_total, || {
                let r = reduce_checked(&input, Algorithm::RamaswamiSiqueira);
                let wall = r.as_ref().map_or(0.0, |(_, c)| c.seconds);
                (r, wall)
            });
            match run.first {
                Ok((out, counters)) => rows.push(SeriesRow {
                    crosscaps: h,
                    triangles,
                    wall_seconds: run.wall,
                    cpu_seconds: run.cpu,
                    link_tests: counters.link_tests,
                    edges_tested_more_than_once: counters.edges_tested_more_than_once,
                    contractions: counters.contractions,
                    output_vertices: vertices(&out),
                }),
                Err(e) => failures.push(format!("N_{h}, {n} triangles: {e}")),
            }
        }
    }
    (rows, failures)
}

/// A random triangulation of `s` (subdivided once, flipped, split).
fn random_triangulation(s: &CoveredSurface, seed: u64) -> CoveredSurface {
    let sub = generators::subdivide_midpoint_covered(s, 1);
    let flips = 3 * sub.cover.surface_faces().count();
    let flipped = generators::random_flips_covered(&sub, flips, seed);
    generators::random_vertex_splits_covered(&flipped, 30, seed + 1)
}

/// The vertex counts reached on many random triangulations of each surface.
fn measure_counts(scale: Scale) -> (Vec<CountsRow>, Vec<String>) {
    let runs = match scale {
        Scale::Tiny => 5,
        Scale::Quick => 50,
        Scale::Full => 200,
    };
    let surfaces: [(&str, CoveredSurface, &str); 5] = [
        ("projective plane", projective_plane(), "6, 7 (Barnette)"),
        (
            "Klein bottle",
            klein_bottle(6, 5),
            "8 to 11 (Lawrencenko–Negami, Sulanke)",
        ),
        (
            "Möbius band",
            mobius_band(6, 2),
            "5, 6 (Chávez, Lawrencenko, Quintero, Villar)",
        ),
        ("disk", disk(3), "3 (one triangle)"),
        (
            "torus",
            generators::torus(6, 5).into(),
            "7 to 10 (Lawrencenko)",
        ),
    ];
    let (mut rows, mut failures) = (Vec::new(), Vec::new());
    for (name, surface, known) in surfaces {
        for algorithm in Algorithm::all(0) {
            let mut counts = BTreeMap::new();
            for seed in 0..runs {
                let input = random_triangulation(&surface, 7_000 + 2 * seed);
                let algorithm = match algorithm {
                    Algorithm::BruteForce { .. } => Algorithm::BruteForce { seed },
                    other => other,
                };
                match reduce_checked(&input, algorithm) {
                    Ok((out, _)) => *counts.entry(vertices(&out)).or_insert(0) += 1,
                    Err(e) => failures.push(format!("{name}, seed {seed}: {e}")),
                }
            }
            rows.push(CountsRow {
                surface: name.to_string(),
                algorithm: algorithm.name().to_string(),
                counts,
                known: known.to_string(),
            });
        }
    }
    (rows, failures)
}

/// Runs the suite (or, with `--render`, reads its jsonl) and writes `surfaces.md`, the jsonl
/// files and the plot.
pub fn run(options: &Options) -> anyhow::Result<()> {
    let scale = options.scale();
    let series: Measured<SeriesRow> =
        measured_or_rendered(options, "surfaces-series", None, || measure_series(scale))?;
    let counts: Measured<CountsRow> =
        measured_or_rendered(options, "surfaces-counts", None, || measure_counts(scale))?;
    let mut gallery = plot::Gallery::new(&options.out);
    let lines: Vec<Series> = [1u32, 2, 4, 8, 16]
        .iter()
        .map(|&h| Series {
            name: format!("N_{h}"),
            points: series
                .rows
                .iter()
                .filter(|r| r.crosscaps == h)
                .map(|r| (f64::from(h) * r.triangles as f64, r.wall_seconds))
                .collect(),
        })
        .collect();
    let plot = Plot {
        title: "RS on non-orientable surfaces: time against h·n",
        x_label: "h · n (Euler genus × triangles)",
        y_label: "seconds (RS alone, least over calls)",
        x_axis: Axis::Log,
        y_axis: Axis::Log,
        scatter: false,
    };
    gallery.add("surfaces-rs-time.svg", &plot, &lines)?;
    let mut md = format!(
        "# Irreducible triangulations of non-orientable surfaces and surfaces with boundary\n\n\
         Generated by `{}`. Scale: {scale:?}. Times: RS alone (its own clock, the least over \
         repeated calls on this shared 2-core machine). {}\n\n",
        options.command(),
        series.load.describe()
    );
    md += &markdown(&series.rows, &counts.rows);
    md += &plot::section(&gallery.written);
    let failures: Vec<String> = series.failures.into_iter().chain(counts.failures).collect();
    for f in &failures {
        let _ = writeln!(md, "- failed: {f}");
    }
    finish(options, "surfaces", &md, &failures)
}

fn markdown(series: &[SeriesRow], counts: &[CountsRow]) -> String {
    let mut md = String::from(
        "## RS on N_h, n doubling\n\nThe paper proves O(g² + g·n) for closed orientable \
         surfaces of genus g and states that its algorithm keeps the same bounds in the Euler \
         genus h on non-orientable ones; here RS runs on the orientable double cover with the \
         vertex classes of the surface (each contraction made on both sheets). Inputs: N_h \
         (connected sums of 6-vertex projective planes) grown by random vertex splits to n \
         triangles, then 3n random flips. `time / (h·n)` should stay flat where h·n dominates; ℓ \
         (link tests) and ε (edges tested twice: 0) are the paper's counters. Random flips leave \
         no memory locality in the vertex order, so wall-clock time also steps up where the \
         input leaves the caches.\n\n",
    );
    md += &header(
        &[
            "h",
            "triangles n",
            "RS seconds",
            "µs / (h·n)",
            "ℓ",
            "ε",
            "contractions",
            "output vertices",
            "13h − 4",
        ],
        1,
    );
    for r in series {
        let hn = f64::from(r.crosscaps) * r.triangles as f64;
        md += &row(&[
            r.crosscaps.to_string(),
            number(r.triangles as f64, 0),
            seconds(r.wall_seconds),
            format!("{:.4}", 1e6 * r.wall_seconds / hn),
            number(r.link_tests as f64, 0),
            r.edges_tested_more_than_once.to_string(),
            number(r.contractions as f64, 0),
            r.output_vertices.to_string(),
            (13 * r.crosscaps - 4).to_string(),
        ]);
    }
    md += "\n## Vertex counts reached\n\nEach surface subdivided once, randomly flipped and split \
           (a fresh seed per run), reduced by each algorithm; the counts of output vertices, \
           against the irreducible triangulations known.\n\n";
    md += &header(
        &["surface", "algorithm", "output vertices: runs", "known"],
        2,
    );
    for r in counts {
        let reached: Vec<String> = r.counts.iter().map(|(v, n)| format!("{v}: {n}")).collect();
        md += &row(&[
            r.surface.clone(),
            r.algorithm.clone(),
            reached.join(", "),
            r.known.clone(),
        ]);
    }
    md + "\n"
}
