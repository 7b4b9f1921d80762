//! Intrinsic-Delaunay paper, Section 9: the flat torus T_x (two triangles, corners (0, 0),
//! (1, 0), (x, 2)), whose Delaunay tessellation D_x is, for integer x, the 1 × 2 rectangle
//! (Figure 8; split by a diagonal: lengths 1, 2 and √5), and whose aspect ratio is O(x²): the
//! flip algorithm needs x − 1 flips there ([`surftopo_intrinsic::generators::flat_torus`]).
//! Also sheared tori and the stand-in meshes. The project has one Delaunay method (edge flips);
//! the report lists it alone.

use std::fmt::Write as _;
use std::path::Path;
use std::time::Instant;

use surftopo_intrinsic::generators::{flat_torus, sheared_torus};
use surftopo_intrinsic::{DelaunayOptions, IntrinsicTriangulation, flip_to_delaunay};

use super::inputs::{self, Scale};
use super::plot::{self, Axis, Plot, Series};
use super::records::IntrinsicRecord as Record;
use super::report::{header, row, seconds};
use super::{Measured, Options, RunInfo, finish, measured_or_rendered, preamble};

fn flip(tri: &mut IntrinsicTriangulation) -> (Result<surftopo_intrinsic::FlipReport, String>, f64) {
    let start = Instant::now();
    let r = flip_to_delaunay(tri, &DelaunayOptions::default()).map_err(|e| e.to_string());
    (r, start.elapsed().as_secs_f64())
}

/// The values of x measured at a scale (the powers of ten up to where double precision breaks).
pub fn xs(scale: Scale) -> Vec<f64> {
    let all = [10.0, 30.0, 100.0, 300.0, 1e3, 3e3, 1e4, 3e4, 1e5, 3e5, 1e6];
    match scale {
        Scale::Tiny => all[..5].to_vec(),
        _ => all.to_vec(),
    }
}

/// Builds every input and measures it.
fn measure_all(options: &Options, meshes: Option<&Path>) -> (Vec<Record>, Vec<String>) {
    let scale = options.scale();
    let mut records = Vec::new();
    let mut failures = Vec::new();
    for x in xs(scale) {
        let mut tri = match flat_torus(x, 1) {
            Ok(t) => t,
            Err(e) => {
                // Refused in double precision (rounded sides off the torus's areas): a measured
                // outcome of f64 at this x, reported in the table, not a failure of the run.
                records.push(Record {
                    kind: "flat_torus".into(),
                    input: format!("T_{x:e}"),
                    parameter: x,
                    edges: 3,
                    expected_flips: Some(x as u64 - 1),
                    status: format!("not built: {e}"),
                    ..Record::default()
                });
                continue;
            }
        };
        let (result, secs) = flip(&mut tri);
        let mut l = tri.lengths().to_vec();
        l.sort_by(f64::total_cmp);
        let error = l
            .iter()
            .zip([1.0, 2.0, 5f64.sqrt()])
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        records.push(Record {
            kind: "flat_torus".into(),
            input: format!("T_{x:e}"),
            parameter: x,
            edges: 3,
            flips: result.as_ref().map_or(0, |r| r.flips),
            expected_flips: Some(x as u64 - 1),
            length_error: Some(error),
            non_delaunay_edges: result.as_ref().map_or(0, |r| r.non_delaunay_edges),
            seconds: secs,
            status: result.map_or_else(|e| e, |_| "ok".into()),
        });
    }
    let (m, n) = match scale {
        Scale::Tiny => (32, 16),
        _ => (128, 64),
    };
    for shear in 1..=16u32 {
        let s = sheared_torus(m, n, shear);
        let mut tri = match IntrinsicTriangulation::from_positions(s.mesh, &s.positions) {
            Ok(t) => t,
            Err(e) => {
                failures.push(format!("sheared torus {shear}: {e}"));
                continue;
            }
        };
        let edges = tri.mesh().edge_count();
        let (result, secs) = flip(&mut tri);
        records.push(Record {
            kind: "sheared_torus".into(),
            input: format!("{m} x {n}, shear {shear}"),
            parameter: f64::from(shear),
            edges,
            flips: result.as_ref().map_or(0, |r| r.flips),
            non_delaunay_edges: result.as_ref().map_or(0, |r| r.non_delaunay_edges),
            seconds: secs,
            status: result.map_or_else(|e| e, |_| "ok".into()),
            ..Record::default()
        });
    }
    // Intrinsic runs the stand-ins as they are (the paper has no mesh experiments to match).
    let models: Vec<(&str, u64)> = inputs::STAND_INS.iter().map(|s| (s.0, u64::MAX)).collect();
    inputs::stand_ins(scale, meshes, &models, |i| {
        let s = i.surface;
        let Ok(mut tri) = IntrinsicTriangulation::from_positions(s.mesh, &s.positions) else {
            return;
        };
        let edges = tri.mesh().edge_count();
        let (result, secs) = flip(&mut tri);
        records.push(Record {
            kind: "mesh".into(),
            input: format!("{} ({})", i.name, i.made),
            edges,
            flips: result.as_ref().map_or(0, |r| r.flips),
            non_delaunay_edges: result.as_ref().map_or(0, |r| r.non_delaunay_edges),
            seconds: secs,
            status: result.map_or_else(|e| e, |_| "ok".into()),
            ..Record::default()
        });
    });
    (records, failures)
}

/// Runs the suite (or, with `--render`, reads its jsonl) and writes `intrinsic.md`, `intrinsic.jsonl` and
/// the plots.
pub fn run(options: &Options, meshes: Option<&Path>) -> anyhow::Result<()> {
    let Measured {
        rows: records,
        failures,
        load,
    } = measured_or_rendered(options, "intrinsic", None, || measure_all(options, meshes))?;
    let plots = write_plots(&options.out, &records)?;
    let md = markdown(options, &records, &plots, &load);
    finish(options, "intrinsic", &md, &failures)
}

fn markdown(
    options: &Options,
    records: &[Record],
    plots: &[(String, String)],
    load: &RunInfo,
) -> String {
    let mut md = preamble(
        "Intrinsic Delaunay triangulations by edge flipping — Section 9 (T_x)",
        options,
        load,
    );
    md += "## The flat torus T_x (Section 9, Figure 8)\n\nThe paper: D_x, the Delaunay \
           tessellation of T_x, is for integer x the 1 × 2 rectangle (one polygon; our \
           triangulation splits it by a diagonal: lengths 1, 2 and √5), and the aspect ratio \
           of T_x is O(x²). The flip count x − 1 is not printed in the paper: it follows from \
           its construction (each flip is one unit step of Euclid's algorithm on (u, w); \
           docs/dubois.md §3.1(a)). Length error: max |ℓ − exact| over the three final lengths. \
           Double precision, Delaunay tolerance 1e-10.\n\n";
    md += &header(
        &[
            "x",
            "flips",
            "x − 1",
            "final lengths 1, 2, √5: error",
            "flip s",
            "verdict",
        ],
        0,
    );
    let mut first_wrong = None;
    for r in records.iter().filter(|r| r.kind == "flat_torus") {
        let exact = r.status == "ok"
            && Some(r.flips) == r.expected_flips
            && r.length_error.is_some_and(|e| e < 1e-6);
        if !exact && first_wrong.is_none() {
            first_wrong = Some(r.parameter);
        }
        md += &row(&[
            format!("{:e}", r.parameter),
            r.flips.to_string(),
            r.expected_flips.map_or("–".into(), |e| e.to_string()),
            format!("{:.1e}", r.length_error.unwrap_or(f64::NAN)),
            seconds(r.seconds),
            if exact {
                "as the paper".to_string()
            } else if r.status != "ok" {
                format!("error: {}", r.status)
            } else {
                "differs (double precision)".into()
            },
        ]);
    }
    if let Some(x) = first_wrong {
        let _ = writeln!(
            md,
            "\nFrom x = {x:e} on, double precision no longer gives D_x exactly: the lengths \
             of T_x are O(x) while D_x's are O(1), so the cancellations of the flips lose \
             about log10(x²) digits (the aspect ratio O(x²) of Theorem 2)."
        );
    }
    md += "\n## Sheared tori\n\nTorus of revolution whose grid quads join (i, j) to (i+1, \
           j+shear); no paper number.\n\n";
    md += &header(
        &["input", "edges", "flips", "flips / E", "flip s", "status"],
        1,
    );
    for r in records.iter().filter(|r| r.kind == "sheared_torus") {
        md += &row(&[
            r.input.clone(),
            r.edges.to_string(),
            r.flips.to_string(),
            format!("{:.3}", r.flips as f64 / r.edges as f64),
            seconds(r.seconds),
            r.status.clone(),
        ]);
    }
    md += "\n## Stand-in meshes\n\nNo paper number (the paper has no experiments on meshes).\n\n";
    md += &header(
        &[
            "input",
            "edges",
            "flips",
            "flips / E",
            "not Delaunay at the end",
            "flip s",
        ],
        1,
    );
    for r in records.iter().filter(|r| r.kind == "mesh") {
        md += &row(&[
            r.input.clone(),
            r.edges.to_string(),
            r.flips.to_string(),
            format!("{:.3}", r.flips as f64 / r.edges as f64),
            r.non_delaunay_edges.to_string(),
            seconds(r.seconds),
        ]);
    }
    md += &plot::section(plots);
    md += &super::differences::intrinsic(records);
    md
}

fn write_plots(out: &Path, records: &[Record]) -> anyhow::Result<Vec<(String, String)>> {
    let tx: Vec<&Record> = records.iter().filter(|r| r.kind == "flat_torus").collect();
    let mut gallery = plot::Gallery::new(out);
    let title = "T_x: flips against x";
    let file = "intrinsic-tx-flips.svg";
    let plot = Plot {
        title,
        x_label: "x",
        y_label: "flips",
        x_axis: Axis::Log,
        y_axis: Axis::Log,
        scatter: false,
    };
    let series = [
        Series {
            name: "flips".into(),
            points: tx.iter().map(|r| (r.parameter, r.flips as f64)).collect(),
        },
        Series {
            name: "x − 1".into(),
            points: tx
                .iter()
                .map(|r| (r.parameter, r.parameter - 1.0))
                .collect(),
        },
    ];
    gallery.add(file, &plot, &series)?;
    let title = "T_x: error of the final lengths against x";
    let file = "intrinsic-tx-length-error.svg";
    let plot = Plot {
        title,
        x_label: "x",
        y_label: "max length error (0 plotted as 1e-17)",
        x_axis: Axis::Log,
        y_axis: Axis::Log,
        scatter: false,
    };
    let series = [Series {
        name: "length error".into(),
        points: tx
            .iter()
            .map(|r| (r.parameter, r.length_error.unwrap_or(0.0).max(1e-17)))
            .collect(),
    }];
    gallery.add(file, &plot, &series)?;
    Ok(gallery.written)
}
