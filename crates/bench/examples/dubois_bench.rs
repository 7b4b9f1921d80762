//! Dubois' Theorem 1 (exact, on rational corners) side by side with edge flipping (`f64`), and
//! `--method auto` against flipping on the shared meshes, every run through
//! `surftopo_intrinsic::intrinsic_delaunay` as `surftopo delaunay` makes it:
//!
//! 1. Section 9's `T_x`, `x = 10, 10², …, 10¹⁸`: the exact pipeline's seconds (best of 3), `N`,
//!    inner passes (total / 350·N), triangles after the reduction, wave events, the largest
//!    constellation, and whether the tessellation is `D_x` (one 1 × 2 rectangle); flipping's
//!    flips, seconds and whether it reached `D_x` (lengths 1, 2, √5 to 1e-9), or why it could not
//!    run (the `f64` lengths of `T_x` no longer describe it from about `x = 10⁵`).
//! 2. Lattice tori `⟨(1, 0), (s, 1)⟩`, `s = 10, 10³, …, 10¹⁸` (shears): the exact pipeline
//!    (its tessellation must be the unit square).
//! 3. Needles with cone points: the pillowcases of `⟨(1, 0), (s, 1)⟩`, `s = 10, …, 10¹²`
//!    (`generators::pillowcase`, two unit squares by construction): Theorem 1 with Section 8's
//!    caps (exact), the wave alone (exact, bounded events) and flipping (`f64`), each checked
//!    against the known tessellation.
//! 4. The shared meshes of 90 000 to 110 000 faces (`SURFTOPO_MESHES`): `flip` against `auto`
//!    (the needle test on the half-angle cache of flipping's first pass): the median over 101
//!    adjacent pairs of runs of the ratio within a pair.
//! 5. The shared meshes of at most 10 000 faces and three generated inputs: Theorem 1 in `f64`
//!    beside flipping, with caps (the paper's Proposition 2) and on the mesh's own metric (what
//!    `--method dubois` runs on a mesh file), paired ratios of thread CPU time and the work
//!    (flips, wave events).
//! 6. The ~100k-face shared meshes: Theorem 1 on the mesh's metric beside flipping.
//!
//! ```text
//! SURFTOPO_MESHES=../shared/meshes cargo run --release -p surftopo-bench --example dubois_bench -- [--out-dir DIR] [--only-meshes]
//! ```
//!
//! `--only-meshes` runs sections 5 and 6 alone and prints them (no file written).
//!
//! Results under `--out-dir` (default: the workspace root): `results/dubois_bench.md`,
//! `results/dubois_bench.jsonl` and the plot `results/dubois_bench.svg` (milliseconds against
//! log₁₀ x). Inputs are built before the clock starts.

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use serde_json::json;
use surftopo_bench::papers::measure::thread_cpu_seconds;
use surftopo_bench::papers::plot::{self, Axis, Plot, Series};
use surftopo_intrinsic::generators::{flat_torus, pillowcase};
use surftopo_intrinsic::geometry::Rational;
use surftopo_intrinsic::voronoi::{Sources, to_f64};
use surftopo_intrinsic::{
    AnyPortalgon, DelaunayInput, DelaunayMethod, DelaunayOutput, DelaunayOutputs, DelaunayRequest,
    IntrinsicDelaunayError, IntrinsicTriangulation, Portalgon, choose_method_for_triangulation,
    intrinsic_delaunay,
};

/// Paired runs of `flip` and `auto` per shared mesh. The two differ by one scan of a cache, far below
/// a shared machine's run-to-run noise, so the figure is the median over the pairs of the ratio
/// within a pair (the two runs of a pair are adjacent in time and see the same load; which runs
/// first alternates from pair to pair).
const AUTO_PAIRS: usize = 101;

/// The largest shared meshes of the Dubois-on-meshes table (each takes seconds to a minute).
const SMALL_MESH_FACES: usize = 10_000;

/// The median of `values` (sorted in place).
fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

fn q(s: &str) -> Rational {
    s.parse().expect("a rational")
}

/// `R²/⟨u, v⟩` as the triangles `0, u, v` and `u + v, v, u`, side i glued to side i.
fn lattice_torus(u: [Rational; 2], v: [Rational; 2]) -> Portalgon<Rational> {
    let uv = [u[0].clone() + v[0].clone(), u[1].clone() + v[1].clone()];
    let mut p = Portalgon::<Rational>::empty();
    let a = p
        .add_polygon(&[[q("0"), q("0")], u.clone(), v.clone()])
        .expect("a triangle");
    let b = p.add_polygon(&[uv, v, u]).expect("a triangle");
    for i in 0..3 {
        p.glue(p.side(a, i), p.side(b, i), 0.0)
            .expect("equal sides");
    }
    p
}

/// Best of `n` runs of `intrinsic_delaunay` on `tri` by `request`, in seconds (the copy of the
/// input made before the clock starts), with the last result.
fn timed_runs(
    n: usize,
    tri: &IntrinsicTriangulation,
    request: &DelaunayRequest,
) -> (Result<DelaunayOutput, IntrinsicDelaunayError>, f64) {
    let mut best = f64::INFINITY;
    let mut out = None;
    for _ in 0..n {
        let input = DelaunayInput::Lengths(tri.clone());
        let start = Instant::now();
        let r = intrinsic_delaunay(input, request);
        best = best.min(start.elapsed().as_secs_f64());
        out = Some(r);
    }
    (out.expect("n ≥ 1"), best)
}

/// Best of `n` runs of `f`, in seconds, with the last result.
fn best_of<T>(n: usize, mut f: impl FnMut() -> T) -> (T, f64) {
    let mut best = f64::INFINITY;
    let mut out = None;
    for _ in 0..n {
        let start = Instant::now();
        let r = f();
        best = best.min(start.elapsed().as_secs_f64());
        out = Some(r);
    }
    (out.expect("n ≥ 1"), best)
}

/// The request of a run by `method` from `vertices` asking for `outputs`.
fn request(method: DelaunayMethod, vertices: Sources, outputs: DelaunayOutputs) -> DelaunayRequest {
    DelaunayRequest {
        method,
        vertices,
        outputs,
        ..DelaunayRequest::default()
    }
}

/// Only the tessellation.
const TESSELLATION: DelaunayOutputs = DelaunayOutputs {
    triangulation: false,
    tessellation: true,
    reduced: false,
    laplacian: false,
    mass: false,
    figures: false,
};

/// Theorem 1 (V the singular vertices, the canonical tessellation) on an exact portalgon.
fn dubois_exact(t: &Portalgon<Rational>) -> Result<DelaunayOutput, IntrinsicDelaunayError> {
    let request = request(DelaunayMethod::Dubois, Sources::Singular, TESSELLATION);
    intrinsic_delaunay(DelaunayInput::Exact(t.clone()), &request)
}

/// Theorem 1's exact pipeline on `⟨(1, 0), (a, b)⟩`, best of 3.
fn exact_pipeline(a: &str, b: &str) -> (DelaunayOutput, f64) {
    let t = lattice_torus([q("1"), q("0")], [q(a), q(b)]);
    best_of(3, || dubois_exact(&t).expect("flat"))
}

/// The exact tessellation of a run.
fn exact_tessellation(out: &DelaunayOutput) -> &Portalgon<Rational> {
    match &out.tessellation {
        Some(AnyPortalgon::Exact(t)) => t,
        _ => panic!("an exact tessellation is asked for"),
    }
}

/// The wave's events of a run by the wave.
fn wave_events(out: &DelaunayOutput) -> u64 {
    out.wave.expect("a run by the wave").events
}

/// The table cells `ms | N | total / 350·N | triangles after reduction | wave events`.
fn dubois_cells(out: &DelaunayOutput, seconds: f64) -> String {
    let rep = out.reduction.as_ref().expect("a dubois run");
    format!(
        "{:.3} | {} | {} / {} | {} | {}",
        seconds * 1e3,
        rep.outer_iterations,
        rep.inner_passes_total,
        rep.inner_passes_bound,
        rep.triangles_after_reduction,
        wave_events(out)
    )
}

/// Whether the exact tessellation is one quadrilateral with squared sides `a, b, a, b` and right
/// angles (the rectangle `√a × √b`).
fn is_rectangle(t: &DelaunayOutput, a: &str, b: &str) -> bool {
    are_rectangles(exact_tessellation(t), 1, a, b)
}

/// Whether the exact tessellation is `count` quadrilaterals, each with squared sides `a, b, a, b`
/// and area `√(ab)` (four such sides with that area make a rectangle).
fn are_rectangles(tess: &Portalgon<Rational>, count: usize, a: &str, b: &str) -> bool {
    let polygons: Vec<_> = tess.polygons().collect();
    let mut expected = vec![q(a), q(a), q(b), q(b)];
    expected.sort();
    polygons.len() == count
        && polygons.iter().all(|&p| {
            let sides = tess.polygon_sides(p);
            let mut lengths: Vec<Rational> = sides.iter().map(|&s| tess.side_length2(s)).collect();
            lengths.sort();
            let area = tess.polygon_area(p);
            lengths == expected && area.clone() * area == q(a) * q(b)
        })
}

/// Flipping in `f64` on the lengths of an exact portalgon whose Delaunay tessellation is unit
/// squares: (flips, seconds, verdict).
fn flip_to_unit_squares(p: &Portalgon<Rational>) -> (Option<u64>, Option<f64>, String) {
    match IntrinsicTriangulation::from_portalgon(&to_f64(p), 1e-9) {
        Ok(tri) => flip_and_check(&tri, 1, [1.0, 1.0, 2f64.sqrt()], "unit squares"),
        Err(e) => (None, None, format!("cannot run: {e}")),
    }
}

/// Flipping on the `f64` `T_x`: (flips, seconds, verdict).
fn flip_t_x(x: f64) -> (Option<u64>, Option<f64>, String) {
    match flat_torus(x, 1) {
        Ok(tri) => flip_and_check(
            &tri,
            if x <= 1e4 { 3 } else { 1 },
            [1.0, 2.0, 5f64.sqrt()],
            "D_x",
        ),
        Err(e) => (None, None, format!("cannot run: {e}")),
    }
}

/// Flips `tri` to Delaunay (best of `runs`, at most 10⁷ flips): (flips, seconds, verdict), the
/// verdict `name` when every triangle's sorted sides are `expected` to 1e-9, else how far off.
fn flip_and_check(
    tri: &IntrinsicTriangulation,
    runs: usize,
    expected: [f64; 3],
    name: &str,
) -> (Option<u64>, Option<f64>, String) {
    let request = DelaunayRequest {
        max_flips: Some(10_000_000),
        ..request(
            DelaunayMethod::Flip,
            Sources::All,
            DelaunayOutputs {
                triangulation: true,
                figures: true,
                ..DelaunayOutputs::default()
            },
        )
    };
    let (result, seconds) = best_of(runs, || {
        intrinsic_delaunay(DelaunayInput::Lengths(tri.clone()), &request)
    });
    match result {
        Err(e) => (None, Some(seconds), format!("error: {e}")),
        Ok(out) => {
            let flips = out.stats.expect("asked for").flips;
            let tri = out.triangulation.expect("asked for");
            let error = tri
                .mesh()
                .faces()
                .map(|f| {
                    let mut s = tri.face_sides(f);
                    s.sort_by(f64::total_cmp);
                    (0..3)
                        .map(|i| (s[i] - expected[i]).abs())
                        .fold(0.0, f64::max)
                })
                .fold(0.0, f64::max);
            let verdict = if error <= 1e-9 {
                name.to_string()
            } else {
                format!("wrong: lengths off by {error:.1e}")
            };
            (Some(flips), Some(seconds), verdict)
        }
    }
}

/// Paired rounds of the Dubois-on-meshes tables: flipping and Theorem 1 on the mesh's metric,
/// adjacent in time, once per round; the figure is the median over the rounds of the ratio within
/// a round.
const MESH_ROUNDS: usize = 3;

/// The least wall-clock seconds of the runs a CPU time is averaged over (flipping takes a fraction
/// of a millisecond at 1k–10k faces, below the scheduler tick the thread CPU clock advances by).
const MIN_BATCH_SECONDS: f64 = 0.3;

/// One input of the Dubois-on-meshes tables: its name, faces, lengths, and whether its triangles
/// are faces of a mesh in ℝ³ (`DelaunayRequest::mesh_metric`; not after intrinsic flips).
struct MeshInput {
    name: String,
    faces: usize,
    tri: IntrinsicTriangulation,
    mesh_metric: bool,
}

/// The mean thread CPU seconds of runs of `request` on `tri`, as many as take `min_seconds` of wall
/// clock (at least one), each on a copy made before its clock starts, with the last result.
/// Each run's CPU time is read from a clock that advances by scheduler ticks; the runs start at
/// times unrelated to the ticks, so the sum over many runs estimates their CPU time without bias.
fn cpu_mean(
    tri: &IntrinsicTriangulation,
    request: &DelaunayRequest,
    min_seconds: f64,
) -> (Result<DelaunayOutput, IntrinsicDelaunayError>, f64) {
    let (mut cpu, mut wall, mut runs) = (0.0, 0.0, 0u32);
    loop {
        let input = DelaunayInput::Lengths(tri.clone());
        let (start, cpu_start) = (Instant::now(), thread_cpu_seconds());
        let r = intrinsic_delaunay(input, request);
        cpu += thread_cpu_seconds() - cpu_start;
        wall += start.elapsed().as_secs_f64();
        runs += 1;
        if wall >= min_seconds {
            return (r, cpu / f64::from(runs));
        }
    }
}

/// Flipping's mean thread CPU seconds ([`cpu_mean`] over [`MIN_BATCH_SECONDS`]) and its flips.
fn flip_cpu(tri: &IntrinsicTriangulation, request: &DelaunayRequest) -> (u64, f64) {
    let (out, cpu) = cpu_mean(tri, request, MIN_BATCH_SECONDS);
    let flips = out
        .expect("flipping a mesh")
        .stats
        .expect("figures asked for")
        .flips;
    (flips, cpu)
}

/// The requests of the Dubois-on-meshes tables: flipping, Theorem 1 with caps (Proposition 2 as
/// the paper builds it), Theorem 1 on the mesh's metric.
fn mesh_requests() -> [DelaunayRequest; 3] {
    let figures = DelaunayOutputs {
        figures: true,
        ..DelaunayOutputs::default()
    };
    let flip = request(DelaunayMethod::Flip, Sources::All, figures);
    let caps = request(
        DelaunayMethod::Dubois,
        Sources::All,
        DelaunayOutputs::default(),
    );
    let mesh = DelaunayRequest {
        mesh_metric: true,
        ..caps
    };
    [flip, caps, mesh]
}

/// The inputs of section 5: the shared meshes of at most [`SMALL_MESH_FACES`] faces and surfaces
/// generated here (not tuned on): a genus-9 brick, a torus of thin triangles (needles of aspect about 10), and an icosphere
/// re-triangulated by random intrinsic flips (no longer a mesh's faces).
fn small_mesh_inputs() -> Vec<MeshInput> {
    use surftopo_mesh::generators::{genus_surface, icosphere, torus};
    let mesh = |name: &str, s: surftopo_mesh::Surface| MeshInput {
        name: name.into(),
        faces: s.mesh.face_count(),
        tri: IntrinsicTriangulation::from_positions(s.mesh, &s.positions).expect("a mesh"),
        mesh_metric: true,
    };
    let mut inputs: Vec<MeshInput> = surftopo_testkit::shared_meshes()
        .into_iter()
        .filter(|m| m.faces <= SMALL_MESH_FACES)
        .map(|m| mesh(&m.file, surftopo_testkit::load(&m)))
        .collect();
    inputs.push(mesh("generated: genus 9 brick", genus_surface(9, 2)));
    inputs.push(mesh("generated: thin torus 8 × 300", torus(8, 300)));
    let mut flipped = mesh(
        "generated: icosphere(4) + 6000 intrinsic flips (seed 55121)",
        icosphere(4),
    );
    surftopo_intrinsic::generators::random_flips(&mut flipped.tri, 6000, 55121);
    flipped.mesh_metric = false;
    inputs.push(flipped);
    inputs
}

/// Section 5 of the report: Theorem 1 in `f64` (V = every vertex, as `surftopo delaunay
/// --method dubois` runs it) side by side with flipping, where flipping is cheap: with caps
/// (Proposition 2 as the paper builds it, a cap at every vertex; one run) and on the mesh's own
/// metric (happiness 1, docs/dubois.md §8; [`MESH_ROUNDS`] rounds paired with flipping).
fn dubois_on_small_meshes(md: &mut String, jsonl: &mut String) {
    let inputs = small_mesh_inputs();
    write!(
        md,
        "\n## Dubois where flipping is cheap: meshes of at most {SMALL_MESH_FACES} faces\n\n\
         Theorem 1 in `f64` from every vertex beside flipping, thread CPU time. **With caps**: \
         Proposition 2 as the paper builds it (a cap at every vertex, ALGORITHM in double-double, \
         the wave on `T′`; `--method dubois --faithful` on a mesh file, without the 350 repetitions; \
         one run, beside the first round's flipping). **On the mesh**: `--method dubois` on a mesh \
         file, the mesh kept as `T′` (a mesh has happiness 1, docs/dubois.md §8; the caps only \
         when the wave refuses it, `caps` in the last column); {MESH_ROUNDS} rounds, each \
         flipping then Dubois (each the mean over runs taking {MIN_BATCH_SECONDS} s), the ratio the \
         median over the rounds of the ratio within a round. Work: flipping's flips and the wave's events. `T′ / F`: the \
         triangles the caps route hands to the wave, per input face. The last three inputs are \
         generated here with seeds used nowhere else; the flipped icosphere is no mesh's faces, \
         so only the caps route applies.\n\n\
         | input | F | flips | flip CPU ms | caps: CPU ms | caps / flip | N | T′ / F | caps: wave events | mesh: CPU ms | mesh / flip | mesh: wave events | route |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n"
    )
    .expect("write to a string");
    let [flip, caps, mesh] = mesh_requests();
    for m in &inputs {
        let mut mesh_ratios = Vec::new();
        let (mut mesh_cells, mut mesh_json) = (String::from("| | | n/a"), json!(null));
        let mut first_flip = None;
        for round in 0..MESH_ROUNDS {
            let (flips, flip_cpu) = flip_cpu(&m.tri, &flip);
            first_flip.get_or_insert((flips, flip_cpu));
            if !m.mesh_metric {
                break;
            }
            let (out, cpu) = cpu_mean(&m.tri, &mesh, MIN_BATCH_SECONDS);
            mesh_ratios.push(cpu / flip_cpu);
            if round == MESH_ROUNDS - 1 {
                let ratio = median(&mut mesh_ratios);
                (mesh_cells, mesh_json) = match out {
                    Ok(out) => {
                        let rep = out.reduction.as_ref().expect("a dubois run");
                        let route = if rep.mesh_metric { "mesh" } else { "caps" };
                        (
                            format!(
                                "| {:.1} | {ratio:.0} | {} | {route}",
                                cpu * 1e3,
                                wave_events(&out)
                            ),
                            json!({"cpu_seconds": cpu, "median_round_ratio": ratio,
                                   "wave_events": wave_events(&out), "route": route}),
                        )
                    }
                    Err(e) => (
                        format!("| error: {e} | | |"),
                        json!({"error": e.to_string()}),
                    ),
                };
            }
        }
        let (flips, flip_cpu) = first_flip.expect("one round");
        let (out, cpu) = cpu_mean(&m.tri, &caps, 0.0);
        let (caps_cells, caps_json) = match out {
            Ok(out) => {
                let rep = out.reduction.as_ref().expect("a dubois run");
                (
                    format!(
                        "{:.0} | {:.0} | {} | {:.1} | {}",
                        cpu * 1e3,
                        cpu / flip_cpu,
                        rep.outer_iterations,
                        rep.triangles_after_reduction as f64 / m.faces as f64,
                        wave_events(&out)
                    ),
                    json!({"cpu_seconds": cpu, "ratio": cpu / flip_cpu,
                           "outer_iterations": rep.outer_iterations,
                           "inner_passes_total": rep.inner_passes_total,
                           "triangles_after_reduction": rep.triangles_after_reduction,
                           "wave_events": wave_events(&out)}),
                )
            }
            Err(e) => (
                format!("error: {e} | | | |"),
                json!({"error": e.to_string()}),
            ),
        };
        writeln!(
            md,
            "| {} | {} | {flips} | {:.3} | {caps_cells} {mesh_cells} |",
            m.name,
            m.faces,
            flip_cpu * 1e3
        )
        .expect("write to a string");
        let line = json!({
            "kind": "dubois_on_mesh", "input": m.name, "faces": m.faces, "flips": flips,
            "flip_cpu_seconds": flip_cpu, "caps": caps_json, "mesh": mesh_json,
        });
        writeln!(jsonl, "{line}").expect("write to a string");
        eprintln!(
            "{}: caps {:.0} ms, flip {:.3} ms {mesh_cells}",
            m.name,
            cpu * 1e3,
            flip_cpu * 1e3
        );
    }
}

/// Section 6 of the report: Theorem 1 on the mesh's metric on the ~100k-face shared meshes (the
/// caps route takes minutes there and is not run), one run beside flipping's mean.
fn dubois_on_large_meshes(md: &mut String, jsonl: &mut String) {
    let meshes: Vec<_> = surftopo_testkit::shared_meshes()
        .into_iter()
        .filter(|m| (90_000..=110_000).contains(&m.faces))
        .collect();
    if meshes.is_empty() {
        return;
    }
    md.push_str(
        "\n## Dubois on the ~100k-face shared meshes\n\n\
         `--method dubois` on a mesh file (the mesh kept as `T′`), one run, thread CPU time, beside \
         flipping (mean of its runs, just before). With caps these meshes take minutes \
         (results/dubois-every-mesh.txt): not run.\n\n\
         | mesh | F | flip CPU ms | Dubois CPU s | Dubois / flip | wave events | route |\n\
         |---|---:|---:|---:|---:|---:|---|\n",
    );
    let [flip, _, mesh] = mesh_requests();
    for m in &meshes {
        let s = surftopo_testkit::load(m);
        let tri = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).expect("a mesh");
        let (_, flip_cpu) = flip_cpu(&tri, &flip);
        let (out, cpu) = cpu_mean(&tri, &mesh, 0.0);
        let cells = match &out {
            Ok(out) => {
                let rep = out.reduction.as_ref().expect("a dubois run");
                format!(
                    "{:.2} | {:.0} | {} | {}",
                    cpu,
                    cpu / flip_cpu,
                    wave_events(out),
                    if rep.mesh_metric { "mesh" } else { "caps" }
                )
            }
            Err(e) => format!("error: {e} | | |"),
        };
        writeln!(
            md,
            "| {} | {} | {:.2} | {cells} |",
            m.file,
            m.faces,
            flip_cpu * 1e3
        )
        .expect("write to a string");
        let line = json!({"kind": "dubois_on_large_mesh", "mesh": m.file, "faces": m.faces,
            "flip_cpu_seconds": flip_cpu, "cpu_seconds": cpu,
            "error": out.as_ref().err().map(ToString::to_string)});
        writeln!(jsonl, "{line}").expect("write to a string");
        eprintln!(
            "{}: Dubois {cpu:.2} s, flip {:.2} ms",
            m.file,
            flip_cpu * 1e3
        );
    }
}

fn main() {
    let mut out_dir = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    let mut only_meshes = false;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out-dir" => out_dir = PathBuf::from(args.next().expect("--out-dir DIR")),
            "--only-meshes" => only_meshes = true,
            other => panic!("unknown argument {other}"),
        }
    }
    if only_meshes {
        let (mut md, mut jsonl) = (String::new(), String::new());
        dubois_on_small_meshes(&mut md, &mut jsonl);
        dubois_on_large_meshes(&mut md, &mut jsonl);
        print!("{md}");
        return;
    }
    let command = "SURFTOPO_MESHES=../shared/meshes cargo run --release -p surftopo-bench --example dubois_bench";
    let mut md = format!(
        "# Dubois' Theorem 1 (exact) side by side with flipping (f64)\n\nProduced by `{command}`. \
         Times in milliseconds, best of 3 (flipping beyond x = 10⁴: one run); inputs built before \
         the clock starts.\n\n## T_x (Section 9)\n\n\
         | x | Dubois ms | N | inner passes (total / 350·N) | triangles after reduction | wave events | max constellation | D_x | flips | flip ms | flipping |\n\
         |---|---:|---:|---:|---:|---:|---:|---|---:|---:|---|\n"
    );
    let mut jsonl = String::new();
    let (mut dubois_points, mut flip_points) = (Vec::new(), Vec::new());
    for k in 1..=18 {
        let x = format!("1{}", "0".repeat(k));
        let (out, seconds) = exact_pipeline(&x, "2");
        let rep = out.reduction.as_ref().expect("a dubois run");
        let d_x = is_rectangle(&out, "1", "4");
        let (flips, flip_seconds, verdict) = flip_t_x(10f64.powi(k as i32));
        let ms = |s: Option<f64>| s.map_or(String::new(), |s| format!("{:.3}", s * 1e3));
        writeln!(
            md,
            "| 1e{k} | {} | {} | {} | {} | {} | {verdict} |",
            dubois_cells(&out, seconds),
            out.wave.expect("a run by the wave").max_constellation,
            if d_x { "yes" } else { "NO" },
            flips.map_or(String::new(), |f| f.to_string()),
            ms(flip_seconds),
        )
        .expect("write to a string");
        dubois_points.push((k as f64, seconds * 1e3));
        if let (Some(s), true) = (flip_seconds, verdict == "D_x") {
            flip_points.push((k as f64, s * 1e3));
        }
        let line = json!({
            "kind": "t_x", "x": x, "seconds": seconds, "outer_iterations": rep.outer_iterations,
            "inner_passes": rep.inner_passes, "inner_passes_total": rep.inner_passes_total,
            "inner_passes_bound": rep.inner_passes_bound,
            "tubes_replaced": {"thin": rep.tubes_replaced_thin, "thick": rep.tubes_replaced_thick},
            "peak_active_vertices": rep.peak_active_vertices,
            "triangles_after_reduction": rep.triangles_after_reduction,
            "wave_events": wave_events(&out),
            "max_constellation": out.wave.expect("a run by the wave").max_constellation,
            "d_x": d_x, "flips": flips, "flip_seconds": flip_seconds, "flipping": verdict,
            "arithmetic": rep.arithmetic,
        });
        writeln!(jsonl, "{line}").expect("write to a string");
        eprintln!("T_1e{k}: {:.3} ms", seconds * 1e3);
    }

    md.push_str(
        "\n## Lattice tori ⟨(1, 0), (s, 1)⟩ (shear s)\n\n\
         | s | Dubois ms | N | inner passes (total / 350·N) | triangles after reduction | wave events | unit square |\n\
         |---|---:|---:|---:|---:|---:|---|\n",
    );
    for k in [1, 3, 6, 9, 12, 18] {
        let s = format!("1{}", "0".repeat(k));
        let (out, seconds) = exact_pipeline(&s, "1");
        let rep = out.reduction.as_ref().expect("a dubois run");
        let square = is_rectangle(&out, "1", "1");
        writeln!(
            md,
            "| 1e{k} | {} | {} |",
            dubois_cells(&out, seconds),
            if square { "yes" } else { "NO" },
        )
        .expect("write to a string");
        let line = json!({
            "kind": "shear", "s": s, "seconds": seconds,
            "outer_iterations": rep.outer_iterations, "inner_passes_total": rep.inner_passes_total,
            "triangles_after_reduction": rep.triangles_after_reduction, "unit_square": square,
        });
        writeln!(jsonl, "{line}").expect("write to a string");
    }

    md.push_str(
        "\n## Needles with cone points: pillowcases of ⟨(1, 0), (s, 1)⟩ (shear s)\n\n\
         `generators::pillowcase`: a sphere with four cone points of angle π whose four triangles \
         are needles of aspect about s²; its Delaunay tessellation is two unit squares by \
         construction. Dubois = Theorem 1 with Section 8's caps, exact; the wave = Proposition 3 \
         alone on the needles from the cone points, exact, at most 10⁶ events, up to s = 10³ (its \
         work grows like s); flipping in f64 on \
         the lengths. One run each beyond s = 10³.\n\n\
         | s | Dubois ms | N | inner passes (total / 350·N) | triangles after reduction | wave events | Dubois: squares | wave ms | wave events | wave: squares | flips | flip ms | flipping |\n\
         |---|---:|---:|---:|---:|---:|---|---:|---:|---|---:|---:|---|\n",
    );
    for k in [1, 2, 3, 6, 9, 12] {
        let s = format!("1{}", "0".repeat(k));
        let t = pillowcase(&[q("1"), q("0")], &[q(&s), q("1")]).expect("a basis");
        let runs = if k <= 3 { 3 } else { 1 };
        let (out, seconds) = best_of(runs, || dubois_exact(&t).expect("closed"));
        let rep = out.reduction.as_ref().expect("a dubois run");
        let squares = are_rectangles(exact_tessellation(&out), 2, "1", "1");
        let wave_request = DelaunayRequest {
            max_wave_events: Some(1_000_000),
            ..request(DelaunayMethod::Voronoi, Sources::Singular, TESSELLATION)
        };
        // The wave alone does work growing with s (its constellations grow like the flips):
        // run up to s = 10³ only.
        let (wave_ms, wave_alone_events, wave_verdict) = if k <= 3 {
            let (wave, wave_seconds) = best_of(runs, || {
                intrinsic_delaunay(DelaunayInput::Exact(t.clone()), &wave_request)
            });
            match &wave {
                Ok(w) => {
                    let known = are_rectangles(exact_tessellation(w), 2, "1", "1");
                    let verdict = if known { "yes" } else { "NO" };
                    (
                        format!("{:.3}", wave_seconds * 1e3),
                        wave_events(w).to_string(),
                        verdict.to_string(),
                    )
                }
                Err(e) => (String::new(), String::new(), format!("error: {e}")),
            }
        } else {
            (String::new(), String::new(), "not run".to_string())
        };
        let (flips, flip_seconds, flipping) = flip_to_unit_squares(&t);
        writeln!(
            md,
            "| 1e{k} | {:.3} | {} | {} / {} | {} | {} | {} | {wave_ms} | {wave_alone_events} | {wave_verdict} | {} | {} | {flipping} |",
            seconds * 1e3,
            rep.outer_iterations,
            rep.inner_passes_total,
            rep.inner_passes_bound,
            rep.triangles_after_reduction,
            wave_events(&out),
            if squares { "yes" } else { "NO" },
            flips.map_or(String::new(), |f| f.to_string()),
            flip_seconds.map_or(String::new(), |s| format!("{:.3}", s * 1e3)),
        )
        .expect("write to a string");
        let line = json!({
            "kind": "pillowcase", "s": s, "seconds": seconds,
            "outer_iterations": rep.outer_iterations, "inner_passes_total": rep.inner_passes_total,
            "triangles_after_reduction": rep.triangles_after_reduction,
            "wave_events": wave_events(&out), "unit_squares": squares,
            "wave_alone_ms": wave_ms, "wave_alone": wave_verdict,
            "flips": flips, "flip_seconds": flip_seconds, "flipping": flipping,
        });
        writeln!(jsonl, "{line}").expect("write to a string");
        eprintln!("pillowcase 1e{k}: {:.3} ms", seconds * 1e3);
    }

    let meshes: Vec<_> = surftopo_testkit::shared_meshes()
        .into_iter()
        .filter(|m| (90_000..=110_000).contains(&m.faces))
        .collect();
    if meshes.is_empty() {
        eprintln!("no shared meshes (set SURFTOPO_MESHES): the auto-vs-flip table is skipped");
    } else {
        md.push_str(
            "\n## `auto` against `flip` on the ~100k-face shared meshes\n\n\
             `auto` = `intrinsic_delaunay` with `DelaunayMethod::Auto` (flipping with the needle test on \
             the half-angle cache of its first pass), as `surftopo delaunay` runs it. 101 pairs of runs (flip then auto, auto \
             then flip, alternately); flip ms and auto ms are medians, `auto / flip` is the median over \
             the pairs of the ratio within a pair (robust to the machine's load, which both runs of a \
             pair share). `choice / flip` is what the rule's test costs as a pass of its own \
             (`choose_method_for_triangulation`, best of 25) against flipping's median. `flip / flip` \
             is the same measurement of flipping against itself (the method's noise).\n\n\
             | mesh | F | auto chose | choice ms | flip ms | auto ms | choice / flip | auto / flip | flip / flip |\n|---|---:|---|---:|---:|---:|---:|---:|---:|\n",
        );
        let flip = request(
            DelaunayMethod::Flip,
            Sources::All,
            DelaunayOutputs::default(),
        );
        let auto = request(
            DelaunayMethod::Auto,
            Sources::All,
            DelaunayOutputs::default(),
        );
        let mut worst_ratio: f64 = 0.0;
        let mut noise_range = (f64::INFINITY, 0.0f64);
        for m in &meshes {
            let s = surftopo_testkit::load(m);
            let tri = IntrinsicTriangulation::from_positions(s.mesh, &s.positions).expect("a mesh");
            let mut chosen = DelaunayMethod::Flip;
            let run_flip = || timed_runs(1, &tri, &flip).1;
            let mut run_auto = || {
                let (out, seconds) = timed_runs(1, &tri, &auto);
                chosen = out.expect("flips").method;
                seconds
            };
            let (mut flips, mut autos, mut ratios) = (Vec::new(), Vec::new(), Vec::new());
            let mut same = Vec::new();
            for pair in 0..AUTO_PAIRS {
                let (f, a) = if pair % 2 == 0 {
                    let f = run_flip();
                    (f, run_auto())
                } else {
                    let a = run_auto();
                    (run_flip(), a)
                };
                flips.push(f);
                autos.push(a);
                ratios.push(a / f);
                // The same measurement of flip against itself: the method's own noise.
                let (first, second) = (run_flip(), run_flip());
                same.push(if pair % 2 == 0 {
                    second / first
                } else {
                    first / second
                });
            }
            let (flip_ms, auto_ms) = (median(&mut flips) * 1e3, median(&mut autos) * 1e3);
            let ratio = median(&mut ratios);
            let noise = median(&mut same);
            worst_ratio = worst_ratio.max(ratio);
            noise_range = (noise_range.0.min(noise), noise_range.1.max(noise));
            let (_, choice_seconds) = best_of(25, || choose_method_for_triangulation(&tri));
            writeln!(
                md,
                "| {} | {} | {chosen:?} | {:.2} | {flip_ms:.2} | {auto_ms:.2} | {:.3} | {ratio:.3} | {noise:.3} |",
                m.file,
                m.faces,
                choice_seconds * 1e3,
                choice_seconds * 1e3 / flip_ms,
            )
            .expect("write to a string");
            let line = json!({
                "kind": "auto_vs_flip", "mesh": m.file, "faces": m.faces,
                "chosen": format!("{chosen:?}"), "choice_seconds": choice_seconds,
                "flip_median_seconds": flip_ms / 1e3, "auto_median_seconds": auto_ms / 1e3,
                "pairs": AUTO_PAIRS, "median_pair_ratio": ratio, "flip_against_flip": noise,
            });
            writeln!(jsonl, "{line}").expect("write to a string");
            eprintln!("{}: auto / flip = {ratio:.3}", m.file);
        }
        writeln!(
            md,
            "\nLargest median `auto / flip`: {worst_ratio:.3} (target: at most 1.05); \
             `flip / flip` from {:.3} to {:.3}.",
            noise_range.0, noise_range.1
        )
        .expect("write to a string");
    }

    dubois_on_small_meshes(&mut md, &mut jsonl);
    dubois_on_large_meshes(&mut md, &mut jsonl);

    let results = out_dir.join("results");
    std::fs::create_dir_all(&results).expect("results directory");
    let drawn = plot::write(
        &results.join("dubois_bench.svg"),
        &Plot {
            title: "T_x: exact Theorem 1 (Dubois) and f64 flipping (while it gives D_x)",
            x_label: "log10 x",
            y_label: "milliseconds",
            x_axis: Axis::Linear,
            y_axis: Axis::Log,
            scatter: false,
        },
        &[
            Series {
                name: "Dubois, exact".into(),
                points: dubois_points,
            },
            Series {
                name: "flipping, f64".into(),
                points: flip_points,
            },
        ],
    )
    .expect("write dubois_bench.svg");
    if drawn {
        md.push_str(
            "\nPlot: [dubois_bench.svg](dubois_bench.svg) (milliseconds against log₁₀ x).\n",
        );
    }
    print!("{md}");
    std::fs::write(results.join("dubois_bench.md"), md).expect("write dubois_bench.md");
    std::fs::write(results.join("dubois_bench.jsonl"), jsonl).expect("write dubois_bench.jsonl");
}
