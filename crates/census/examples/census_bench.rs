//! The census's figures: the four published censuses timed (median of `--runs`), and the
//! moonshots (N3, the double torus) measured job by job, resumably, with Knuth's estimates of the
//! jobs not run. Writes `results/census.md` from `results/census.jsonl` (one line per timed run
//! or finished moonshot job; a rerun skips the moonshot jobs already there).
//!
//! ```sh
//! cargo run --release -p surftopo-census --example census_bench -- --runs 5
//! cargo run --release -p surftopo-census --example census_bench -- --runs 0 --moonshot n3 --max-vertices 12
//! cargo run --release -p surftopo-census --example census_bench -- --runs 0 --moonshot genus-2 --max-vertices 11
//! ```
//!
//! `--past-bound` also runs the torus and the Klein bottle up to 12 vertices (none is expected
//! past the published largest vertex counts, 10 and 11). `--skip-above NODES` leaves out the moonshot jobs whose estimated search exceeds NODES (they
//! stay in the report's table of estimates).

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io::Write as _;
use std::time::Instant;
use surftopo_census::search::{self, Job, estimate_nodes, run_job};
use surftopo_census::{CensusOptions, SurfaceKind, census};

const JSONL: &str = "results/census.jsonl";
const REPORT: &str = "results/census.md";

fn load() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .map(|s| s.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_default()
}

fn now() -> String {
    std::process::Command::new("date")
        .arg("-u")
        .arg("+%Y-%m-%d %H:%M")
        .output()
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .unwrap_or_default()
}

fn append(line: &str) {
    let mut file = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(JSONL)
        .expect("results/census.jsonl opens (run from the checkout's root)");
    writeln!(file, "{line}").expect("written");
}

/// One field of a flat JSON line (numbers and strings only).
fn field<'a>(line: &'a str, key: &str) -> Option<&'a str> {
    let start = line.find(&format!("\"{key}\":"))? + key.len() + 3;
    let rest = &line[start..];
    let end = if let Some(stripped) = rest.strip_prefix('"') {
        return stripped.split('"').next();
    } else {
        rest.find([',', '}']).unwrap_or(rest.len())
    };
    Some(&rest[..end])
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let value = |name: &str| {
        args.iter()
            .position(|a| a == name)
            .and_then(|i| args.get(i + 1))
            .cloned()
    };
    let runs: usize = value("--runs").map_or(5, |v| v.parse().expect("--runs N"));
    let command = format!(
        "cargo run --release -p surftopo-census --example census_bench -- {}",
        args[1..].join(" ")
    );
    std::fs::create_dir_all("results").expect("results/");
    if runs > 0 {
        for (name, published) in [
            ("sphere", 1),
            ("projective-plane", 2),
            ("torus", 21),
            ("klein-bottle", 29),
        ] {
            let surface = SurfaceKind::parse(name).expect("name");
            let mut times = Vec::new();
            let mut found = 0;
            for _ in 0..runs {
                let start = Instant::now();
                let c = census(surface, CensusOptions::default()).expect("census");
                times.push(start.elapsed().as_secs_f64());
                found = c.triangulations.len();
            }
            times.sort_by(f64::total_cmp);
            let median = times[times.len() / 2];
            println!(
                "{name}: {found} (published {published}), median {median:.4} s of {runs} runs"
            );
            append(&format!(
                "{{\"kind\":\"published\",\"surface\":\"{name}\",\"classes\":{found},\"published\":{published},\"median_seconds\":{median:.6},\"min_seconds\":{:.6},\"runs\":{runs},\"load\":\"{}\",\"date\":\"{}\",\"command\":\"{command}\"}}",
                times[0],
                load(),
                now()
            ));
        }
    }
    if args.iter().any(|a| a == "--past-bound") {
        // The search past the published largest vertex counts: none is expected.
        for (name, upto) in [("torus", 12), ("klein-bottle", 12)] {
            let surface = SurfaceKind::parse(name).expect("name");
            let bound = surface.vertex_range().max.map_or(0, |(m, _)| m);
            let start = Instant::now();
            let c = census(
                surface,
                CensusOptions {
                    max_vertices: Some(upto),
                    ..Default::default()
                },
            )
            .expect("census");
            let seconds = start.elapsed().as_secs_f64();
            let beyond = c
                .triangulations
                .iter()
                .filter(|t| t.vertex_count() > bound)
                .count();
            println!(
                "{name}: {beyond} classes with {} to {upto} vertices ({seconds:.1} s)",
                bound + 1
            );
            append(&format!(
                "{{\"kind\":\"past_bound\",\"surface\":\"{name}\",\"bound\":{bound},\"searched_up_to\":{upto},\"beyond\":{beyond},\"nodes\":{},\"seconds\":{seconds:.3},\"load\":\"{}\",\"date\":\"{}\",\"command\":\"{command}\"}}",
                c.nodes,
                load(),
                now()
            ));
        }
    }
    if let Some(name) = value("--moonshot") {
        let surface = SurfaceKind::parse(&name).expect("surface name");
        let max: usize = value("--max-vertices")
            .expect("--max-vertices N")
            .parse()
            .expect("a number");
        let done = finished_jobs(
            &std::fs::read_to_string(JSONL).unwrap_or_default(),
            &surface.name(),
        );
        let (jobs, _) = search::jobs(surface, Some(max)).expect("jobs");
        let skip_above: f64 =
            value("--skip-above").map_or(f64::INFINITY, |v| v.parse().expect("--skip-above NODES"));
        let never = || false;
        for job in jobs {
            if is_done(&done, job) {
                continue;
            }
            let estimate = estimate_nodes(surface, job, 2000, 7);
            if estimate > skip_above {
                println!(
                    "{name}: {} vertices, degree {}, part {}: skipped (estimated {estimate:.3e} nodes)",
                    job.vertices, job.max_degree, job.part
                );
                continue;
            }
            let r = run_job(surface, job, &never).expect("job");
            println!(
                "{name}: {} vertices, degree {}, part {}: {} classes, {} nodes (estimated {:.3e}), {:.2} s",
                job.vertices,
                job.max_degree,
                job.part,
                r.triangulations.len(),
                r.nodes,
                estimate,
                r.seconds
            );
            append(&format!(
                "{{\"kind\":\"job\",\"surface\":\"{}\",\"vertices\":{},\"max_degree\":{},\"part\":{},\"classes\":{},\"nodes\":{},\"estimated_nodes\":{estimate:.0},\"seconds\":{:.3},\"load\":\"{}\",\"date\":\"{}\",\"command\":\"{command}\"}}",
                surface.name(),
                job.vertices,
                job.max_degree,
                job.part,
                r.triangulations.len(),
                r.nodes,
                r.seconds,
                load(),
                now()
            ));
        }
    }
    write_report();
}

/// The (vertex count, maximum degree, part) of the finished jobs of `surface` in the JSONL text;
/// part `None` for a line that covers every part.
fn finished_jobs(text: &str, surface: &str) -> Vec<(usize, usize, Option<usize>)> {
    text.lines()
        .filter(|l| field(l, "kind") == Some("job") && field(l, "surface") == Some(surface))
        .filter_map(|l| {
            Some((
                field(l, "vertices")?.parse().ok()?,
                field(l, "max_degree")?.parse().ok()?,
                field(l, "part").and_then(|p| p.parse().ok()),
            ))
        })
        .collect()
}

fn is_done(done: &[(usize, usize, Option<usize>)], job: Job) -> bool {
    done.iter().any(|&(n, d, part)| {
        n == job.vertices && d == job.max_degree && part.is_none_or(|p| p == job.part)
    })
}

/// `results/census.md` from every line of `results/census.jsonl`, with Knuth's estimates for
/// the moonshot jobs not run.
fn write_report() {
    let text = std::fs::read_to_string(JSONL).unwrap_or_default();
    let mut md = String::new();
    let _ = writeln!(
        md,
        "# Census of irreducible triangulations: figures\n\nGenerated by `crates/census/examples/census_bench.rs` from `results/census.jsonl` (every run, with the machine's load average and the date). Release build, this project's 2-core shared machine.\n\n## The published censuses\n\n| surface | classes | published | median s | min s | runs | load | date |\n|---|---:|---:|---:|---:|---:|---|---|"
    );
    let mut latest: BTreeMap<String, String> = BTreeMap::new();
    for line in text
        .lines()
        .filter(|l| field(l, "kind") == Some("published"))
    {
        latest.insert(
            field(line, "surface").unwrap_or_default().to_string(),
            line.to_string(),
        );
    }
    for name in ["sphere", "projective-plane", "torus", "klein-bottle"] {
        if let Some(l) = latest.get(name) {
            let f = |k| field(l, k).unwrap_or_default();
            let _ = writeln!(
                md,
                "| {name} | {} | {} | {} | {} | {} | {} | {} |",
                f("classes"),
                f("published"),
                f("median_seconds"),
                f("min_seconds"),
                f("runs"),
                f("load"),
                f("date")
            );
        }
    }
    let past: Vec<&str> = text
        .lines()
        .filter(|l| field(l, "kind") == Some("past_bound"))
        .collect();
    if !past.is_empty() {
        let _ = writeln!(
            md,
            "\n## Past the published bounds\n\nThe search run beyond the largest vertex count of the published lists (a check, not a proof: Joret and Wood's bound is 22 for both).\n\n| surface | published largest | searched up to | classes beyond | search nodes | seconds | load | date |\n|---|---:|---:|---:|---:|---:|---|---|"
        );
        for l in past {
            let f = |k| field(l, k).unwrap_or_default();
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {} | {} | {} | {} |",
                f("surface"),
                f("bound"),
                f("searched_up_to"),
                f("beyond"),
                f("nodes"),
                f("seconds"),
                f("load"),
                f("date")
            );
        }
    }
    for name in ["n3", "genus-2"] {
        let surface = SurfaceKind::parse(name).expect("name");
        let jobs: Vec<&str> = text
            .lines()
            .filter(|l| field(l, "kind") == Some("job") && field(l, "surface") == Some(name))
            .collect();
        if jobs.is_empty() {
            continue;
        }
        let done = finished_jobs(&text, name);
        let mut per_n: BTreeMap<usize, (usize, u64, f64)> = BTreeMap::new();
        for l in &jobs {
            let n: usize = field(l, "vertices")
                .and_then(|v| v.parse().ok())
                .unwrap_or(0);
            let e = per_n.entry(n).or_default();
            e.0 += field(l, "classes")
                .and_then(|v| v.parse::<usize>().ok())
                .unwrap_or(0);
            e.1 += field(l, "nodes")
                .and_then(|v| v.parse::<u64>().ok())
                .unwrap_or(0);
            e.2 += field(l, "seconds")
                .and_then(|v| v.parse::<f64>().ok())
                .unwrap_or(0.0);
        }
        let total_nodes: u64 = per_n.values().map(|e| e.1).sum();
        let total_seconds: f64 = per_n.values().map(|e| e.2).sum();
        let per_node = total_seconds / total_nodes.max(1) as f64;
        let _ = writeln!(
            md,
            "\n## {name}: classes found against time, per vertex count\n\nJobs (vertex count n, maximum degree d, part: the subtree below one apex of the search's first branching) run one by one (resumable: a rerun skips the jobs in the JSONL; a line without a part covers every part of its (n, d)). Seconds are those of the search on a loaded machine (see the load column of the JSONL). A vertex count is complete when all its jobs ran.\n\n| vertices | classes | search nodes | seconds | jobs run / all |\n|---:|---:|---:|---:|---:|"
        );
        let upper = surface.vertex_range().max.map_or(16, |(m, _)| m).min(17);
        let (all, _) = search::jobs(surface, Some(upper)).expect("jobs");
        let mut cumulative = 0;
        for (n, (classes, nodes, seconds)) in &per_n {
            cumulative += classes;
            let of_n: Vec<&Job> = all.iter().filter(|j| j.vertices == *n).collect();
            let run = of_n.iter().filter(|&&&j| is_done(&done, j)).count();
            let _ = writeln!(
                md,
                "| {n} | {classes} (total {cumulative}) | {nodes} | {seconds:.1} | {run} / {} |",
                of_n.len()
            );
        }
        let missing: Vec<Job> = all.into_iter().filter(|&j| !is_done(&done, j)).collect();
        if !missing.is_empty() {
            let _ = writeln!(
                md,
                "\nNot run: Knuth's estimate of the search nodes (2,000 random probes per job), and the time at the measured {:.0} ns per node:\n\n| vertices | estimated nodes | estimated time |\n|---:|---:|---:|",
                per_node * 1e9
            );
            let mut by_n: BTreeMap<usize, f64> = BTreeMap::new();
            for job in missing {
                *by_n.entry(job.vertices).or_default() += estimate_nodes(surface, job, 2000, 7);
            }
            for (n, nodes) in by_n {
                let seconds = nodes * per_node;
                let time = if seconds < 7200.0 {
                    format!("{seconds:.0} s")
                } else if seconds < 3.0 * 86400.0 {
                    format!("{:.1} h", seconds / 3600.0)
                } else if seconds < 1000.0 * 86400.0 {
                    format!("{:.0} days", seconds / 86400.0)
                } else {
                    format!("{:.0} years", seconds / (365.25 * 86400.0))
                };
                let _ = writeln!(md, "| {n} | {nodes:.2e} | {time} |");
            }
        }
    }
    std::fs::write(REPORT, md).expect("results/census.md written");
}
