//! Quadrangulation paper (long version), Section 4: SG and PS with ten seeds each (the paper
//! randomises their edge and triangle orders and averages ten runs), DS and LRS once, on the
//! stand-ins of Table 4.1 and on groups A (genus 0) and B (genus 3,500) of Table 4.2, with the
//! default augmenting search; columns (a)–(e) of Tables 4.3 and 4.4, LRS's flipped edges, and the
//! work of the augmenting searches (nodes reached).

use std::fmt::Write as _;
use std::path::Path;

use surftopo_quad::{AugmentStrategy, QuadAlgorithm, QuadOptions, quadrangulate_with};

use super::cache::Cache;
use super::inputs::{self, Described, Input, Scale};
use super::measure::{fewer_seeds, mean, seeds_for, thread_cpu_seconds};
use super::numbers::{self, value};
use super::plot::{self, Axis, Plot, Series};
use super::records::QuadRecord as Record;
use super::report::{beside, header, number, row, seconds};
use super::{Measured, Options, RunInfo, finish, measured_or_rendered, preamble};

/// Seeds of SG and PS (the paper: ten executions).
pub const SEEDS: u64 = 10;

/// The paper's algorithms, in its order.
pub const ALGORITHMS: [&str; 4] = ["SG", "PS", "DS", "LRS"];

fn algorithm(name: &str, seed: u64) -> QuadAlgorithm {
    match name {
        "SG" => QuadAlgorithm::SimpleGreedy { seed },
        "PS" => QuadAlgorithm::PulliSegal { seed },
        "DS" => QuadAlgorithm::DiksStanczyk,
        _ => QuadAlgorithm::Lrs,
    }
}

/// Largest unpaired/2 × faces for which the global search is run (its work is about that).
pub const GLOBAL_MAX_WORK: f64 = 3e9;

fn measure_one(
    group: &str,
    input: &Input,
    name: &str,
    augment: AugmentStrategy,
) -> anyhow::Result<Record> {
    let mesh = &input.surface.mesh;
    let runs = if matches!(name, "SG" | "PS") {
        seeds_for(SEEDS, mesh.face_count())
    } else {
        1
    };
    let mut r = Record {
        about: Described::of(group, input),
        algorithm: name.into(),
        augment: match augment {
            AugmentStrategy::Global => "global".into(),
            _ => "forest".into(),
        },
        runs,
        ..Record::default()
    };
    let mut all = Vec::new();
    let cpu_start = thread_cpu_seconds();
    for seed in 1..=runs {
        let options = QuadOptions {
            augment,
            ..QuadOptions::default()
        };
        let result = quadrangulate_with(mesh, algorithm(name, seed), &options)
            .map_err(|e| anyhow::anyhow!("{} {name}: {e}", input.name))?;
        anyhow::ensure!(
            2 * result.quads.len() == mesh.face_count(),
            "{} {name}: {} quads for {} triangles",
            input.name,
            result.quads.len(),
            mesh.face_count()
        );
        all.push((result.stats, result.augmentation));
    }
    r.cpu_seconds = (thread_cpu_seconds() - cpu_start) / runs as f64;
    r.initial_pairing_seconds = mean(all.iter().map(|s| s.0.initial_pairing_seconds));
    r.paired_percent = mean(all.iter().map(|s| s.0.paired_percent));
    r.unpaired = mean(all.iter().map(|s| s.0.unpaired as f64));
    r.augmentation_seconds = mean(all.iter().map(|s| s.0.augmentation_seconds));
    r.total_seconds = mean(all.iter().map(|s| s.0.total_seconds));
    r.flipped_edges = mean(all.iter().map(|s| s.0.flipped_edges as f64));
    r.augment_reached = mean(all.iter().map(|s| s.1.reached as f64));
    r.augment_searches = mean(all.iter().map(|s| s.1.searches as f64));
    Ok(r)
}

/// Builds every input and measures it.
fn measure_all(
    options: &Options,
    cache: &Cache,
    meshes: Option<&Path>,
) -> (Vec<Record>, Vec<String>) {
    let mut records: Vec<Record> = Vec::new();
    let mut failures = Vec::new();
    let mut record = |group: &str, input: Input, records: &mut Vec<Record>| {
        if !options.runs_input(&input.name) {
            return;
        }
        let forest = AugmentStrategy::Forest;
        for a in ALGORITHMS {
            match measure_one(group, &input, a, forest) {
                Ok(r) => {
                    eprintln!(
                        "quad {:5} {:13} F {:>9} g {:>5} {:3} (c) {:>10.1} (e) {} flipped {:.0}",
                        group,
                        r.input,
                        r.faces,
                        r.genus,
                        a,
                        r.unpaired,
                        seconds(r.total_seconds),
                        r.flipped_edges
                    );
                    records.push(r);
                }
                Err(e) => failures.push(e.to_string()),
            }
        }
        for a in ["PS", "LRS"] {
            let affordable = records.iter().any(|r| {
                r.input == input.name
                    && r.algorithm == a
                    && r.unpaired / 2.0 * r.faces as f64 <= GLOBAL_MAX_WORK
            });
            if affordable {
                match measure_one(group, &input, a, AugmentStrategy::Global) {
                    Ok(r) => records.push(r),
                    Err(e) => failures.push(e.to_string()),
                }
            }
        }
    };
    let models = numbers::face_counts(numbers::QUAD_TABLE_4_1.iter().map(|m| (m.0, m.3)));
    let sizes = numbers::face_counts(numbers::QUAD_TABLE_4_2.iter().map(|s| (s.0, s.3)));
    let groups = [("A", 3844, 0), ("B", 344, 3500)];
    inputs::paper_inputs(options, cache, meshes, &models, &sizes, &groups, |g, i| {
        record(g, i, &mut records)
    });
    (records, failures)
}

/// Runs the suite (or, with `--render`, reads its jsonl) and writes `quad.md`, `quad.jsonl` and
/// the plots.
pub fn run(options: &Options, cache: &Cache, meshes: Option<&Path>) -> anyhow::Result<()> {
    let Measured {
        rows: records,
        failures,
        load,
    } = measured_or_rendered(options, "quad", Some(cache), || {
        measure_all(options, cache, meshes)
    })?;
    let forest: Vec<Record> = records
        .iter()
        .filter(|r| r.augment == "forest")
        .cloned()
        .collect();
    let plots = write_plots(&options.out, &forest)?;
    let md = markdown(options, &records, &failures, &plots, &load, options.scale());
    finish(options, "quad", &md, &failures)
}

/// The record of `algorithm` on `input` with the default (`forest`) search.
fn find<'a>(records: &'a [Record], input: &str, algorithm: &str) -> Option<&'a Record> {
    records
        .iter()
        .find(|r| r.input == input && r.algorithm == algorithm && r.augment == "forest")
}

/// (d) with the paper's global search beside the paper's (d), and ours with the default search.
fn global_table(records: &[Record]) -> String {
    let mut md = String::from(
        "\n## Augmentation with the paper's search (Section 3.1's procedure)\n\n(d) \
         augmentation seconds with `AugmentStrategy::Global` (a forest from all unpaired \
         triangles, restarted after each augmenting path, as the paper's), run where \
         unpaired/2 × faces ≤ 3e9, beside the paper's (d) and ours with the default `forest` \
         search.\n\n",
    );
    md += &header(
        &[
            "input",
            "alg.",
            "(c)",
            "(d) global",
            "(d) forest",
            "global / forest",
        ],
        2,
    );
    for g in records.iter().filter(|r| r.augment == "global") {
        let model = g.input.split(" (").next().unwrap_or(&g.input);
        let paper = numbers::QUAD_RUNS
            .iter()
            .find(|p| p.0 == model && p.1 == g.algorithm);
        let f = find(records, &g.input, &g.algorithm);
        md += &row(&[
            g.input.clone(),
            g.algorithm.clone(),
            number(g.unpaired, 1),
            match paper {
                Some(p) => beside(Some(g.augmentation_seconds), p.2[3], 5),
                None => number(g.augmentation_seconds, 5),
            },
            f.map_or("–".into(), |f| number(f.augmentation_seconds, 5)),
            f.map_or("–".into(), |f| {
                number(
                    g.augmentation_seconds / f.augmentation_seconds.max(1e-12),
                    2,
                )
            }),
        ]);
    }
    md
}

/// Columns (a)–(e) of a record.
fn columns(r: &Record) -> [f64; 5] {
    [
        r.initial_pairing_seconds,
        r.paired_percent,
        r.unpaired,
        r.augmentation_seconds,
        r.total_seconds,
    ]
}

const DECIMALS: [usize; 5] = [5, 4, 1, 5, 5];

fn runs_table(records: &[Record], inputs: &[&str], with_flips: bool) -> String {
    let mut md = header(
        &[
            "input",
            "made",
            "alg.",
            "(a)",
            "(b) %",
            "(c)",
            "(d)",
            "(e)",
            "flipped edges",
        ],
        3,
    );
    let names = inputs
        .iter()
        .flat_map(|i| [i.to_string(), format!("{i} (simplified)")])
        .filter(|n| !n.ends_with(" (simplified)") || records.iter().any(|r| r.input == *n));
    for input in names {
        let model = input.split(" (").next().unwrap_or(&input);
        for a in ALGORITHMS {
            let paper = numbers::QUAD_RUNS.iter().find(|p| p.0 == model && p.1 == a);
            let ours = find(records, &input, a);
            if paper.is_none() && ours.is_none() {
                continue;
            }
            let mut cells = vec![
                input.to_string(),
                ours.map_or("not run".into(), |o| o.made.clone()),
                a.to_string(),
            ];
            let c = ours.map(columns);
            for k in 0..5 {
                cells.push(match paper {
                    Some(p) => beside(c.map(|c| c[k]), p.2[k], DECIMALS[k]),
                    None => c.map_or("–".into(), |c| number(c[k], DECIMALS[k])),
                });
            }
            cells.push(match (with_flips, ours) {
                (true, Some(o)) if a == "LRS" => format!(
                    "{} of {} ({:.1}%)",
                    number(o.flipped_edges, 0),
                    number(o.edges as f64, 0),
                    100.0 * o.flipped_edges / o.edges as f64
                ),
                _ => String::new(),
            });
            md += &row(&cells);
        }
    }
    md
}

fn markdown(
    options: &Options,
    records: &[Record],
    failures: &[String],
    plots: &[(String, String)],
    load: &RunInfo,
    scale: Scale,
) -> String {
    let all = records;
    let forest: Vec<Record> = all
        .iter()
        .filter(|r| r.augment == "forest")
        .cloned()
        .collect();
    let records = &forest[..];
    let mut md = preamble(
        "Quadrangulation by triangle pairing: SG, PS, DS, LRS — Section 4",
        options,
        load,
    );
    let fewer: Vec<String> = records
        .iter()
        .filter(|r| matches!(r.algorithm.as_str(), "SG" | "PS") && r.runs < SEEDS)
        .map(|r| r.input.clone())
        .fold(Vec::new(), |mut v, i| {
            if !v.contains(&i) {
                v.push(i);
            }
            v
        });
    let _ = write!(
        md,
        "Columns as in the paper: (a) initial pairing seconds, (b) % paired, (c) unpaired \
         triangles, (d) augmentation seconds, (e) total seconds — here wall-clock seconds (the \
         paper's own measure), means over the runs (SG and PS: seeds 1..=10{}; DS and LRS: one \
         run, as in the paper); CPU seconds are in the jsonl.",
        fewer_seeds(&fewer)
    );
    md += " Augmenting paths: the \
           library's default search (`forest`); the paper's is a BFS from one unpaired triangle \
           at a time. Every run is checked to give F/2 quads. The project's own Karp–Sipser \
           pairing against LEMON is measured by `quad_tables` (see `../quad.md`).\n\n";
    for f in failures {
        let _ = writeln!(md, "**Failed**: {f}\n");
    }
    md += "## First group (Tables 4.1 and 4.3): stand-ins\n\nNone of the paper's models is in \
           the shared meshes: each row is a stand-in (closest genus and size).\n\n";
    md += &header(&["model", "made", "V", "E", "F", "g"], 2);
    for (m, v, e, f, g) in numbers::QUAD_TABLE_4_1
        .iter()
        .flat_map(|p| [(p.0.to_string(), p), (format!("{} (simplified)", p.0), p)])
        .filter(|(name, p)| *name == p.0 || records.iter().any(|r| r.input == *name))
        .map(|(name, p)| (name, p.1, p.2, p.3, p.4))
    {
        let o = records.iter().find(|r| r.input == m);
        md += &row(&[
            m.clone(),
            o.map_or("not run".into(), |o| o.made.clone()),
            beside(o.map(|o| o.vertices as f64), v, 0),
            beside(o.map(|o| o.edges as f64), e, 0),
            beside(o.map(|o| o.faces as f64), f, 0),
            beside(o.map(|o| o.genus as f64), g, 0),
        ]);
    }
    md += "\n### Table 4.3\n\n";
    let models: Vec<&str> = numbers::QUAD_TABLE_4_1.iter().map(|m| m.0).collect();
    md += &runs_table(records, &models, true);
    let (flips, edges) = numbers::QUAD_BOTIJO_FLIPS;
    let (lo, hi) = numbers::QUAD_FLIPPED_PERCENT_RANGE;
    let _ = writeln!(
        md,
        "\nLRS's flipped edges (Section 5): the paper flips {flips} of Botijo's {edges} edges \
         ({:.1}%), \"between {lo} and {hi} percent of the edges\" on the meshes of Table 4.3. Ours: \
         {}.\n",
        100.0 * value(flips) / value(edges),
        flipped_summary(records)
    );
    md += "## Groups A and B (Tables 4.2 and 4.4)\n\n### Sizes (Table 4.2)\n\n";
    md += &header(&["input", "made", "V", "E", "F", "g"], 2);
    for (i, v, e, f) in numbers::QUAD_TABLE_4_2 {
        let o = records.iter().find(|r| r.input == i && r.group != "first");
        let g = if i.starts_with('A') { "0" } else { "3,500" };
        md += &row(&[
            i.to_string(),
            o.map_or("not run".into(), |o| o.made.clone()),
            beside(o.map(|o| o.vertices as f64), v, 0),
            beside(o.map(|o| o.edges as f64), e, 0),
            beside(o.map(|o| o.faces as f64), f, 0),
            beside(o.map(|o| o.genus as f64), g, 0),
        ]);
    }
    md += "\n### Table 4.4 (the paper omits SG and DS there; ours are shown without a paper \
           number)\n\n";
    let ab: Vec<&str> = numbers::QUAD_TABLE_4_2.iter().map(|s| s.0).collect();
    md += &runs_table(records, &ab, false);
    md += "\nDS against LRS on group B (end of Section 4: DS \"was 1.12 and 3.7 times faster on \
           B1 and B5\"), total times:\n\n";
    md += &header(&["input", "t_LRS / t_DS"], 1);
    for (i, paper) in numbers::QUAD_DS_OVER_LRS_SPEEDUP {
        let q = match (find(records, i, "LRS"), find(records, i, "DS")) {
            (Some(l), Some(d)) if d.total_seconds > 0.0 => Some(l.total_seconds / d.total_seconds),
            _ => None,
        };
        md += &row(&[i.to_string(), beside(q, paper, 2)]);
    }
    md += &global_table(all);
    md += &alpha_table(records);
    md += &bound_table(records);
    md += &clustering_table(records);
    md += &ds_table(records);
    md += &plot::section(plots);
    md += &super::differences::quad(records, scale);
    md
}

fn flipped_summary(records: &[Record]) -> String {
    let mut pct: Vec<(String, f64)> = records
        .iter()
        .filter(|r| r.algorithm == "LRS" && r.group == "first")
        .map(|r| (r.input.clone(), 100.0 * r.flipped_edges / r.edges as f64))
        .collect();
    if pct.is_empty() {
        return "no stand-in run".into();
    }
    pct.sort_by(|a, b| a.1.total_cmp(&b.1));
    pct.iter()
        .map(|(i, p)| format!("{i} {p:.1}%"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn alpha_table(records: &[Record]) -> String {
    let (sg_lo, sg_hi) = numbers::QUAD_SG_ALPHA;
    let (ps_lo, ps_hi) = numbers::QUAD_PS_ALPHA;
    let mut md = format!(
        "\n## α = k / n_f (Sections 4 and 5)\n\nThe paper: SG leaves k = α·n_f unpaired with α \
         in [{sg_lo}, {sg_hi}]; PS with α in [{ps_lo}, {ps_hi}] (Section 5), growing with the \
         genus.\n\n"
    );
    md += &header(&["input", "F", "g", "α SG", "α PS"], 1);
    let mut seen = Vec::new();
    for r in records {
        if seen.contains(&(&r.group, &r.input)) {
            continue;
        }
        seen.push((&r.group, &r.input));
        let a = |alg: &str| {
            records
                .iter()
                .find(|x| x.group == r.group && x.input == r.input && x.algorithm == alg)
                .map_or("–".into(), |x| {
                    format!("{:.5}", x.unpaired / x.faces as f64)
                })
        };
        md += &row(&[
            r.input.clone(),
            r.faces.to_string(),
            r.genus.to_string(),
            a("SG"),
            a("PS"),
        ]);
    }
    md
}

/// Section 3.3: LRS leaves 4 unpaired triangles on genus 0 and at most 56g − 12 otherwise.
pub fn lrs_bound(genus: i64) -> f64 {
    (56 * genus - 12).max(4) as f64
}

fn bound_table(records: &[Record]) -> String {
    let mut md = String::from(
        "\n## LRS unpaired triangles against the bound max(4, 56g − 12) (Section 3.3)\n\n",
    );
    md += &header(&["input", "g", "LRS unpaired", "bound", "within"], 1);
    for r in records.iter().filter(|r| r.algorithm == "LRS") {
        let b = lrs_bound(r.genus);
        md += &row(&[
            r.input.clone(),
            r.genus.to_string(),
            number(r.unpaired, 0),
            number(b, 0),
            if r.unpaired <= b { "yes" } else { "**no**" }.into(),
        ]);
    }
    md
}

fn clustering_table(records: &[Record]) -> String {
    let mut md = String::from(
        "\n## How clustered the unpaired triangles are (Section 4)\n\nThe paper: \"the \
         triangles left unpaired by the initial pairing produced by LRS are 'closer' to each \
         other than those of the initial pairing from PS\". Measure: nodes the augmenting \
         searches reach per unpaired triangle.\n\n",
    );
    md += &header(
        &[
            "input",
            "g",
            "LRS reached / unpaired",
            "PS reached / unpaired",
            "PS / LRS",
        ],
        1,
    );
    for l in records.iter().filter(|r| r.algorithm == "LRS") {
        let Some(p) = records
            .iter()
            .find(|r| r.group == l.group && r.input == l.input && r.algorithm == "PS")
        else {
            continue;
        };
        let per = |r: &Record| {
            if r.unpaired > 0.0 {
                r.augment_reached / r.unpaired
            } else {
                f64::NAN
            }
        };
        md += &row(&[
            l.input.clone(),
            l.genus.to_string(),
            number(per(l), 1),
            number(per(p), 1),
            number(per(p) / per(l), 2),
        ]);
    }
    md
}

fn ds_table(records: &[Record]) -> String {
    let mut md = String::from(
        "\n## DS time / (n log² n) (Section 3.2: O(n lg² n))\n\nn = triangles, log base 2; \
         nanoseconds.\n\n",
    );
    md += &header(&["input", "F", "DS total s", "ns / (n log² n)"], 1);
    for r in records.iter().filter(|r| r.algorithm == "DS") {
        let n = r.faces as f64;
        md += &row(&[
            r.input.clone(),
            r.faces.to_string(),
            seconds(r.total_seconds),
            format!("{:.3}", 1e9 * r.total_seconds / (n * n.log2().powi(2))),
        ]);
    }
    md
}

fn write_plots(out: &Path, records: &[Record]) -> anyhow::Result<Vec<(String, String)>> {
    let mut gallery = plot::Gallery::new(out);
    for (group, file, title) in [
        (
            "A",
            "quad-total-time-group-A.svg",
            "Total time against triangles, group A (genus 0)",
        ),
        (
            "B",
            "quad-total-time-group-B.svg",
            "Total time against triangles, group B (genus 3,500)",
        ),
    ] {
        let series: Vec<Series> = ALGORITHMS
            .iter()
            .map(|a| {
                let mut points: Vec<(f64, f64)> = records
                    .iter()
                    .filter(|r| r.group == group && r.algorithm == *a)
                    .map(|r| (r.faces as f64, r.total_seconds))
                    .collect();
                points.sort_by(|x, y| x.0.total_cmp(&y.0));
                Series {
                    name: a.to_string(),
                    points,
                }
            })
            .collect();
        let plot = Plot {
            title,
            x_label: "triangles",
            y_label: "total seconds (e)",
            x_axis: Axis::Log,
            y_axis: Axis::Log,
            scatter: false,
        };
        gallery.add(file, &plot, &series)?;
    }
    let lrs: Vec<&Record> = records.iter().filter(|r| r.algorithm == "LRS").collect();
    let title = "LRS unpaired triangles against max(4, 56g − 12)";
    let file = "quad-lrs-unpaired-against-bound.svg";
    let mut bound_line: Vec<(f64, f64)> = lrs
        .iter()
        .map(|r| (lrs_bound(r.genus), lrs_bound(r.genus)))
        .collect();
    bound_line.sort_by(|a, b| a.0.total_cmp(&b.0));
    let series = [
        Series {
            name: "LRS unpaired".into(),
            points: lrs
                .iter()
                .map(|r| (lrs_bound(r.genus), r.unpaired.max(0.5)))
                .collect(),
        },
        Series {
            name: "bound".into(),
            points: bound_line,
        },
    ];
    let plot = Plot {
        title,
        x_label: "max(4, 56g − 12)",
        y_label: "unpaired",
        x_axis: Axis::Log,
        y_axis: Axis::Log,
        scatter: false,
    };
    gallery.add(file, &plot, &series)?;
    let title = "Nodes reached per unpaired triangle: LRS and PS";
    let file = "quad-reached-per-unpaired.svg";
    let series: Vec<Series> = ["LRS", "PS"]
        .iter()
        .map(|a| Series {
            name: a.to_string(),
            points: records
                .iter()
                .filter(|r| r.algorithm == *a && r.unpaired > 0.0)
                .map(|r| (r.faces as f64, r.augment_reached / r.unpaired))
                .collect(),
        })
        .collect();
    let plot = Plot {
        title,
        x_label: "triangles",
        y_label: "nodes reached / unpaired",
        x_axis: Axis::Log,
        y_axis: Axis::Log,
        scatter: true,
    };
    gallery.add(file, &plot, &series)?;
    let title = "DS total time / (n log² n)";
    let file = "quad-ds-time-over-n-log2n.svg";
    let mut points: Vec<(f64, f64)> = records
        .iter()
        .filter(|r| r.algorithm == "DS")
        .map(|r| {
            let n = r.faces as f64;
            (n, 1e9 * r.total_seconds / (n * n.log2().powi(2)))
        })
        .collect();
    points.sort_by(|a, b| a.0.total_cmp(&b.0));
    let plot = Plot {
        title,
        x_label: "triangles",
        y_label: "ns / (n log² n)",
        x_axis: Axis::Log,
        y_axis: Axis::Linear,
        scatter: true,
    };
    gallery.add(
        file,
        &plot,
        &[Series {
            name: "DS".into(),
            points,
        }],
    )?;
    Ok(gallery.written)
}

impl std::ops::Deref for Record {
    type Target = Described;

    /// The input's description, so that `row.faces` reads as a field of the row.
    fn deref(&self) -> &Described {
        &self.about
    }
}
