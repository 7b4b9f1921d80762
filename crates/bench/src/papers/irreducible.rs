//! Irreducible-triangulations paper, Section 5: RS, S and BF on the first group (stand-ins of
//! Table 2) and on groups B (Table 3), C (Table 4) and D (Table 5), as in Section 5.2: RS and S
//! once per input (short runs repeated to accumulate CPU time), BF ten times with seeds 1..=10
//! (the paper: "executed ten times on each triangulation", its ℓ_bf and ε_bf "the average values
//! over the ten runs"), every output checked irreducible and of the input's genus.

use std::fmt::Write as _;
use std::path::Path;

use surftopo_irreducible::{Algorithm, SurfaceMesh, check_simplicial, is_irreducible, reduce};

use super::cache::Cache;
use super::inputs::{self, Described, Input, Scale};
use super::measure::{fewer_seeds, mean, seeds_for, timed};
use super::numbers::{self, value};
use super::plot::{self, Axis, Plot, Series};
use super::records::{AlgorithmRun, IrreducibleRow as Row, ratios};
use super::report::{beside, header, number, row, seconds};
use super::{Measured, Options, RunInfo, finish, measured_or_rendered, preamble};

/// BF runs per input (Section 5.2).
pub const BF_RUNS: u64 = 10;

fn min_total(scale: Scale) -> f64 {
    if scale == Scale::Tiny { 0.0 } else { 0.5 }
}

/// Runs `algorithm` on `mesh` (repeated while short), checks the output, returns the run.
fn run_one(
    mesh: &SurfaceMesh,
    algorithm: Algorithm,
    min_total: f64,
    check_cpu: f64,
) -> anyhow::Result<AlgorithmRun> {
    let t = timed(min_total, || {
        let r = reduce(mesh.clone(), algorithm).expect("input checked simplicial");
        let wall = r.counters.seconds;
        (r, wall)
    });
    let out = &t.first;
    anyhow::ensure!(
        out.mesh.genus() == mesh.genus() && is_irreducible(&out.mesh),
        "{algorithm}: output not irreducible or of another genus"
    );
    Ok(AlgorithmRun {
        link_tests: out.counters.link_tests as f64,
        edges_tested_more_than_once: out.counters.edges_tested_more_than_once as f64,
        output_vertices: out.mesh.vertex_count() as f64,
        cpu_seconds: (t.cpu - check_cpu).max(0.0),
        wall_seconds: t.wall,
        calls: t.calls,
        seeds: 1,
    })
}

fn measure_input(group: &str, input: &Input, scale: Scale) -> anyhow::Result<Row> {
    let mesh = &input.surface.mesh;
    check_simplicial(mesh).map_err(|e| anyhow::anyhow!("{}: {e}", input.name))?;
    let min = min_total(scale);
    let check = timed(min, || {
        let start = std::time::Instant::now();
        check_simplicial(mesh).expect("checked");
        ((), start.elapsed().as_secs_f64())
    });
    let rs = run_one(mesh, Algorithm::RamaswamiSiqueira, min, check.cpu)?;
    let s = run_one(mesh, Algorithm::Schipper, min, check.cpu)?;
    let seeds = seeds_for(BF_RUNS, mesh.face_count());
    let bf_runs: Vec<AlgorithmRun> = (1..=seeds)
        .map(|seed| {
            run_one(
                mesh,
                Algorithm::BruteForce { seed },
                min / seeds as f64,
                check.cpu,
            )
        })
        .collect::<anyhow::Result<_>>()?;
    let avg = |f: fn(&AlgorithmRun) -> f64| mean(bf_runs.iter().map(f));
    let bf = AlgorithmRun {
        link_tests: avg(|r| r.link_tests),
        edges_tested_more_than_once: avg(|r| r.edges_tested_more_than_once),
        output_vertices: avg(|r| r.output_vertices),
        cpu_seconds: avg(|r| r.cpu_seconds),
        wall_seconds: avg(|r| r.wall_seconds),
        calls: bf_runs.iter().map(|r| r.calls).sum(),
        seeds,
    };
    Ok(Row {
        about: Described::of(group, input),
        rs,
        s,
        bf,
    })
}

/// Builds every input and measures it.
fn measure_all(options: &Options, cache: &Cache, meshes: Option<&Path>) -> (Vec<Row>, Vec<String>) {
    let scale = options.scale();
    let mut rows: Vec<Row> = Vec::new();
    let mut failures: Vec<String> = Vec::new();
    let mut record = |group: &str, input: Input, rows: &mut Vec<Row>| {
        if !options.runs_input(&input.name) {
            return;
        }
        match measure_input(group, &input, scale) {
            Ok(r) => {
                eprintln!(
                    "irreducible {:6} {:13} F {:>9} g {:>5}  RS {}  S {}  BF {}",
                    group,
                    r.input,
                    r.faces,
                    r.genus,
                    seconds(r.rs.cpu_seconds),
                    seconds(r.s.cpu_seconds),
                    seconds(r.bf.cpu_seconds)
                );
                rows.push(r);
            }
            Err(e) => failures.push(format!("{}: {e}", input.name)),
        }
    };
    let models = numbers::face_counts(numbers::IRREDUCIBLE_TABLE_2.iter().map(|m| (m.0, m.3)));
    let sizes = numbers::face_counts(numbers::IRREDUCIBLE_SIZES.iter().map(|s| (s.0, s.3)));
    let groups = [("B", 3844, 0), ("C", 344, 3500)];
    inputs::paper_inputs(options, cache, meshes, &models, &sizes, &groups, |g, i| {
        record(g, i, &mut rows)
    });
    for (i, (name, _, _, f, g)) in numbers::IRREDUCIBLE_SIZES
        .iter()
        .filter(|s| s.0.starts_with('D'))
        .enumerate()
    {
        if i >= scale.per_group() || !options.runs_input(name) {
            continue;
        }
        let g = value(g) as u32;
        let (made, recipe) = inputs::brick(scale, 3844 - g, g, value(f) as u64);
        record(
            "D",
            Input {
                name: name.to_string(),
                made,
                surface: cache.get(&recipe),
            },
            &mut rows,
        );
    }
    (rows, failures)
}

/// Runs the suite (or, with `--render`, reads its jsonl) and writes `irreducible.md`, `irreducible.jsonl` and
/// the plots.
pub fn run(options: &Options, cache: &Cache, meshes: Option<&Path>) -> anyhow::Result<()> {
    let Measured {
        rows,
        failures,
        load,
    } = measured_or_rendered(options, "irreducible", Some(cache), || {
        measure_all(options, cache, meshes)
    })?;
    let plots = write_plots(&options.out, &rows)?;
    let md = markdown(options, &rows, &failures, &plots, &load);
    finish(options, "irreducible", &md, &failures)
}

fn find<'a>(rows: &'a [Row], group: &str, input: &str) -> Option<&'a Row> {
    rows.iter().find(|r| r.group == group && r.input == input)
}

fn markdown(
    options: &Options,
    rows: &[Row],
    failures: &[String],
    plots: &[(String, String)],
    load: &RunInfo,
) -> String {
    let mut md = preamble(
        "Irreducible triangulations: RS, Schipper (S) and brute force (BF) — Section 5",
        options,
        load,
    );
    let fewer: Vec<&str> = rows
        .iter()
        .filter(|r| r.bf.seeds < BF_RUNS)
        .map(|r| r.input.as_str())
        .collect();
    let _ = writeln!(
        md,
        "RS and S: one run per input (runs under 0.5 s repeated, CPU time the mean); BF: ten \
         runs, seeds 1..=10 (each shuffles the edges), ℓ_bf, ε_bf and t_bf the means, as in \
         the paper{}. Every output is checked irreducible and of the input's genus.\n",
        fewer_seeds(&fewer)
    );
    for f in failures {
        let _ = writeln!(md, "**Failed**: {f}\n");
    }

    md += "## First group (Table 2, Figure 15): the papers' models and their stand-ins\n\n\
           Only Casting and Socket are the paper's own models; the others are stand-ins (the \
           shared mesh of closest genus and size), so their sizes are not the paper's.\n\n";
    md += &header(
        &[
            "model",
            "made",
            "V",
            "E",
            "F",
            "g",
            "t_RS s",
            "t_S s",
            "t_BF s",
            "t_s/t_rs",
            "t_bf/t_rs",
            "t_s/t_bf",
        ],
        2,
    );
    for (m, v, e, f, g) in numbers::IRREDUCIBLE_TABLE_2
        .iter()
        .flat_map(|p| [(p.0.to_string(), p), (format!("{} (simplified)", p.0), p)])
        .filter(|(name, p)| *name == p.0 || find(rows, "first", name).is_some())
        .map(|(name, p)| (name, p.1, p.2, p.3, p.4))
    {
        let ours = find(rows, "first", &m);
        let model = m.split(" (").next().unwrap_or(&m);
        let paper_ratios = numbers::IRREDUCIBLE_FIRST_GROUP_RATIOS
            .iter()
            .find(|r| r.0 == model);
        let r = ours.map(ratios);
        let ratio_cell = |i: usize, paper: Option<&str>| match paper {
            Some(p) => beside(r.map(|r| r[i]), p, 2),
            None => r.map_or("–".into(), |r| number(r[i], 2)),
        };
        md += &row(&[
            m.clone(),
            ours.map_or("not run".into(), |o| o.made.clone()),
            beside(ours.map(|o| o.vertices as f64), v, 0),
            beside(ours.map(|o| o.edges as f64), e, 0),
            beside(ours.map(|o| o.faces as f64), f, 0),
            beside(ours.map(|o| o.genus as f64), g, 0),
            ours.map_or("–".into(), |o| seconds(o.rs.cpu_seconds)),
            ours.map_or("–".into(), |o| seconds(o.s.cpu_seconds)),
            ours.map_or("–".into(), |o| seconds(o.bf.cpu_seconds)),
            ratio_cell(3, paper_ratios.map(|p| p.1)),
            ratio_cell(4, paper_ratios.map(|p| p.2)),
            ratio_cell(5, None),
        ]);
    }
    md += "\nThe paper (Section 5.2): t_s/t_bf \"is always greater than 1.9 and its largest value \
           is 2.97\" on this group.\n\n";

    for (group, title) in [
        (
            "B",
            "Group B (Tables 3, 6, 7; Figure 16): genus 0, 3,844 cavities",
        ),
        ("C", "Group C (Tables 4, 8, 9; Figure 17): genus 3,500"),
        (
            "D",
            "Group D (Tables 5, 10, 11; Figure 18): about 4.2M triangles, genus 10 to 3,500",
        ),
    ] {
        let _ = writeln!(md, "## {title}\n");
        md += &group_tables(rows, group);
    }
    md += &delta_analysis(rows);
    md += &plot::section(plots);
    md += &differences(rows);
    md
}

fn group_tables(rows: &[Row], group: &str) -> String {
    let mut md = String::new();
    let sizes_name = numbers::sizes_table(group);
    let _ = writeln!(md, "### Sizes ({sizes_name})\n");
    md += &header(&["input", "made", "V", "E", "F", "g"], 2);
    for (i, v, e, f, g) in numbers::IRREDUCIBLE_SIZES
        .iter()
        .filter(|s| s.0.starts_with(group))
    {
        let o = find(rows, group, i);
        md += &row(&[
            i.to_string(),
            o.map_or("not run".into(), |o| o.made.clone()),
            beside(o.map(|o| o.vertices as f64), v, 0),
            beside(o.map(|o| o.edges as f64), e, 0),
            beside(o.map(|o| o.faces as f64), f, 0),
            beside(o.map(|o| o.genus as f64), g, 0),
        ]);
    }
    let _ = writeln!(
        md,
        "\n### Link-condition tests ({})\n",
        numbers::counts_table(group)
    );
    md += &header(&["input", "ℓ_rs", "ℓ_s", "ℓ_bf", "ε_s", "ε_bf"], 1);
    for (i, a, b, c, d, e) in numbers::IRREDUCIBLE_COUNTS
        .iter()
        .filter(|s| s.0.starts_with(group))
    {
        let o = find(rows, group, i);
        md += &row(&[
            i.to_string(),
            beside(o.map(|o| o.rs.link_tests), a, 0),
            beside(o.map(|o| o.s.link_tests), b, 0),
            beside(o.map(|o| o.bf.link_tests), c, 1),
            beside(o.map(|o| o.s.edges_tested_more_than_once), d, 0),
            beside(o.map(|o| o.bf.edges_tested_more_than_once), e, 1),
        ]);
    }
    let _ = writeln!(
        md,
        "\n### Ratios ({}; times are CPU times)\n",
        numbers::ratios_table(group)
    );
    let mut columns = vec!["input"];
    columns.extend(numbers::RATIO_COLUMNS);
    md += &header(&columns, 1);
    for (i, paper) in numbers::IRREDUCIBLE_RATIOS
        .iter()
        .filter(|s| s.0.starts_with(group))
    {
        let o = find(rows, group, i).map(ratios);
        let mut cells = vec![i.to_string()];
        cells.extend((0..6).map(|k| beside(o.map(|r| r[k]), paper[k], 2)));
        md += &row(&cells);
    }
    md += "\n### Times (ours; the paper gives them only as Figures 15–18)\n\n";
    md += &header(
        &[
            "input",
            "F",
            "g",
            "t_RS CPU s",
            "t_S CPU s",
            "t_BF CPU s (mean over its seeds)",
            "t_RS wall s",
            "t_S wall s",
            "t_BF wall s",
        ],
        1,
    );
    for o in rows.iter().filter(|r| r.group == group) {
        md += &row(&[
            o.input.clone(),
            o.faces.to_string(),
            o.genus.to_string(),
            seconds(o.rs.cpu_seconds),
            seconds(o.s.cpu_seconds),
            seconds(o.bf.cpu_seconds),
            seconds(o.rs.wall_seconds),
            seconds(o.s.wall_seconds),
            seconds(o.bf.wall_seconds),
        ]);
    }
    md += "\n";
    md
}

/// Section 5.3: δt_i / (δf_i · δg_i) on group D, relative to D9, which the paper finds about
/// constant on D0–D4.
fn delta_analysis(rows: &[Row]) -> String {
    let mut md = String::from(
        "## RS time against g·n_f (Section 5.3)\n\nδf_i = (n_f,i − n_f,9)/n_f,9, δg_i = (g_i − \
         g_9)/g_9, δt_i = (t_i − t_9)/t_9 for RS on D_i; the paper finds δt_i/(δf_i·δg_i) \
         \"approximately constant for triangulations D0-D4\" (it prints no value).\n\n",
    );
    let Some(d9) = find(rows, "D", "D9") else {
        md += "D9 not run.\n\n";
        return md;
    };
    md += &header(&["input", "g", "F", "δf", "δg", "δt", "δt/(δf·δg)"], 1);
    for o in rows.iter().filter(|r| r.group == "D" && r.input != "D9") {
        let df = (o.faces as f64 - d9.faces as f64) / d9.faces as f64;
        let dg = (o.genus as f64 - d9.genus as f64) / d9.genus as f64;
        let dt = (o.rs.cpu_seconds - d9.rs.cpu_seconds) / d9.rs.cpu_seconds;
        md += &row(&[
            o.input.clone(),
            o.genus.to_string(),
            o.faces.to_string(),
            format!("{df:.2e}"),
            format!("{dg:.1}"),
            format!("{dt:.3}"),
            format!("{:.2}", dt / (df * dg)),
        ]);
    }
    md += "\n";
    md
}

/// A quantity read from a row.
type Measure = fn(&Row) -> f64;

fn write_plots(out: &Path, rows: &[Row]) -> anyhow::Result<Vec<(String, String)>> {
    let mut gallery = plot::Gallery::new(out);
    let algorithms: [(&str, Measure); 3] = [
        ("RS", |r| r.rs.cpu_seconds),
        ("S", |r| r.s.cpu_seconds),
        ("BF", |r| r.bf.cpu_seconds),
    ];
    let series = |group: &str, x: fn(&Row) -> f64| -> Vec<Series> {
        algorithms
            .iter()
            .map(|(name, y)| {
                let mut points: Vec<(f64, f64)> = rows
                    .iter()
                    .filter(|r| r.group == group)
                    .map(|r| (x(r), y(r)))
                    .collect();
                points.sort_by(|a, b| a.0.total_cmp(&b.0));
                Series {
                    name: name.to_string(),
                    points,
                }
            })
            .collect()
    };
    let faces = |r: &Row| r.faces as f64;
    for (file, title, group, x_label, x, x_axis) in [
        (
            "irreducible-fig15-first-group.svg",
            "Figure 15 analogue: time against triangles, stand-ins of Table 2",
            "first",
            "triangles",
            faces as fn(&Row) -> f64,
            Axis::Log,
        ),
        (
            "irreducible-fig16-group-B.svg",
            "Figure 16 analogue: time against triangles, group B (genus 0)",
            "B",
            "triangles",
            faces,
            Axis::Log,
        ),
        (
            "irreducible-fig17-group-C.svg",
            "Figure 17 analogue: time against triangles, group C (genus 3,500)",
            "C",
            "triangles",
            faces,
            Axis::Log,
        ),
        (
            "irreducible-fig18-group-D.svg",
            "Figure 18 analogue: time against genus, group D",
            "D",
            "genus",
            |r: &Row| r.genus as f64,
            Axis::Linear,
        ),
    ] {
        let plot = Plot {
            title,
            x_label,
            y_label: "CPU seconds",
            x_axis,
            y_axis: Axis::Log,
            scatter: group == "first",
        };
        gallery.add(file, &plot, &series(group, x))?;
    }
    // ℓ per triangle, groups B and C.
    let mut per_triangle = Vec::new();
    for group in ["B", "C"] {
        for (name, l) in [
            ("RS", (|r: &Row| r.rs.link_tests) as fn(&Row) -> f64),
            ("S", |r: &Row| r.s.link_tests),
            ("BF", |r: &Row| r.bf.link_tests),
        ] {
            let mut points: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r.group == group)
                .map(|r| (r.faces as f64, l(r) / r.faces as f64))
                .collect();
            points.sort_by(|a, b| a.0.total_cmp(&b.0));
            per_triangle.push(Series {
                name: format!("{name} ({group})"),
                points,
            });
        }
    }
    let title = "Link-condition tests per triangle, groups B and C";
    let file = "irreducible-link-tests-per-triangle.svg";
    let plot = Plot {
        title,
        x_label: "triangles",
        y_label: "ℓ / n_f",
        x_axis: Axis::Log,
        y_axis: Axis::Linear,
        scatter: false,
    };
    gallery.add(file, &plot, &per_triangle)?;
    let title = "RS time against g·n_f, group D";
    let file = "irreducible-rs-time-against-g-nf.svg";
    let mut points: Vec<(f64, f64)> = rows
        .iter()
        .filter(|r| r.group == "D")
        .map(|r| (r.genus as f64 * r.faces as f64, r.rs.cpu_seconds))
        .collect();
    points.sort_by(|a, b| a.0.total_cmp(&b.0));
    let plot = Plot {
        title,
        x_label: "g · n_f",
        y_label: "RS CPU seconds",
        x_axis: Axis::Linear,
        y_axis: Axis::Linear,
        scatter: false,
    };
    gallery.add(
        file,
        &plot,
        &[Series {
            name: "RS".into(),
            points,
        }],
    )?;
    Ok(gallery.written)
}

/// "Where we differ from the paper": the measured facts behind each disagreement.
fn differences(rows: &[Row]) -> String {
    super::differences::irreducible(rows)
}
