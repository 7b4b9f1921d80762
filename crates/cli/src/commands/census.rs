//! `surftopo census`: every irreducible triangulation of a closed surface, up to isomorphism.

use crate::args::JsonArg;
use crate::failure::{invalid, shown};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::time::Instant;
use surftopo_census::search::{self, estimate_nodes};
use surftopo_census::{
    BoundSource, Census, CensusError, CensusOptions, Job, JobResult, SurfaceKind,
    VertexCountFigures, parse_lutz_line, to_lutz, to_lutz_line,
};

/// The arguments of `census`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The surface: sphere, torus, projective-plane, klein-bottle, genus-G, nK (double-torus =
    /// genus-2).
    pub surface: String,
    /// The census file: one triangulation per line in Lutz's format `[[1,2,3],[1,2,4],...]`
    /// (vertices 1..n, canonical labelling, sorted by vertex count then faces); written only when
    /// the run finishes.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Search up to N vertices: below the surface's bound the census is complete up to N vertices
    /// only (and says so); above it, the search goes on past the bound (a check: none is found).
    #[arg(long, value_name = "N")]
    pub max_vertices: Option<usize>,
    /// A checkpoint file (JSON) rewritten after each finished job; a run given an existing one
    /// resumes from it. It says `"complete": false` until the whole census is in it.
    #[arg(long, value_name = "FILE")]
    pub checkpoint: Option<PathBuf>,
    /// Refuse to start when the estimated search time (Knuth's estimator) exceeds this many
    /// seconds.
    #[arg(long, value_name = "SECONDS", default_value_t = 3600.0)]
    pub budget: f64,
    #[command(flatten)]
    pub json: JsonArg,
}

/// What `--json` prints.
#[derive(Serialize)]
pub struct Report {
    /// The surface's name.
    pub surface: String,
    /// Orientable.
    pub orientable: bool,
    /// Euler characteristic.
    pub euler_characteristic: i64,
    /// The number of classes (mirror images identified).
    pub total: usize,
    /// Chiral classes in all.
    pub chiral: usize,
    /// Whether the whole vertex range was searched.
    pub complete: bool,
    /// The largest vertex count searched.
    pub searched_up_to: usize,
    /// Where the largest vertex count comes from.
    pub bound: Option<String>,
    /// Always true: a triangulation and its mirror image are one class.
    pub mirror_images_identified: bool,
    /// Per vertex count.
    pub per_vertex_count: Vec<VertexCountFigures>,
    /// Labelled triangulations the search reached.
    pub candidates: u64,
    /// Candidates rejected as isomorphic to another.
    pub duplicates: u64,
    /// Search nodes.
    pub nodes: u64,
    /// Seconds of search (resumed jobs with their recorded times).
    pub seconds: f64,
    /// Jobs taken from the checkpoint.
    pub resumed_jobs: usize,
}

/// A finished job in a checkpoint.
#[derive(Serialize, Deserialize)]
struct CheckpointJob {
    vertices: usize,
    max_degree: usize,
    part: usize,
    nodes: u64,
    candidates: u64,
    seconds: f64,
    triangulations: Vec<String>,
}

/// The checkpoint file.
#[derive(Serialize, Deserialize)]
struct Checkpoint {
    surface: String,
    complete: bool,
    jobs: Vec<CheckpointJob>,
}

fn read_checkpoint(path: &Path, surface: SurfaceKind) -> anyhow::Result<Vec<JobResult>> {
    if !path.exists() {
        return Ok(Vec::new());
    }
    let text = std::fs::read_to_string(path)
        .map_err(|e| invalid(format!("{}: cannot be read: {e}", shown(path))))?;
    let checkpoint: Checkpoint = serde_json::from_str(&text)
        .map_err(|e| invalid(format!("{}: not a census checkpoint: {e}", shown(path))))?;
    if SurfaceKind::parse(&checkpoint.surface).ok() != Some(surface) {
        return Err(invalid(format!(
            "{}: a checkpoint of {}, not of {surface}",
            shown(path),
            checkpoint.surface
        )));
    }
    let mut results = Vec::new();
    for job in checkpoint.jobs {
        let mut triangulations = Vec::new();
        for (k, line) in job.triangulations.iter().enumerate() {
            let faces = parse_lutz_line(line, k + 1).map_err(|e| {
                invalid(format!(
                    "{}: job ({} vertices, degree {}): {e}",
                    shown(path),
                    job.vertices,
                    job.max_degree
                ))
            })?;
            let t = surftopo_census::Triangulation::new(faces).map_err(|e| {
                invalid(format!(
                    "{}: job ({} vertices, degree {}), triangulation {}: {e}",
                    shown(path),
                    job.vertices,
                    job.max_degree,
                    k + 1
                ))
            })?;
            triangulations.push(surftopo_census::canonical_form(&t));
        }
        results.push(JobResult {
            job: Job {
                vertices: job.vertices,
                max_degree: job.max_degree,
                part: job.part,
            },
            triangulations,
            nodes: job.nodes,
            candidates: job.candidates,
            seconds: job.seconds,
        });
    }
    Ok(results)
}

fn write_checkpoint(
    path: &Path,
    surface: SurfaceKind,
    results: &[JobResult],
    complete: bool,
) -> anyhow::Result<()> {
    let checkpoint = Checkpoint {
        surface: surface.name(),
        complete,
        jobs: results
            .iter()
            .map(|r| CheckpointJob {
                vertices: r.job.vertices,
                max_degree: r.job.max_degree,
                part: r.job.part,
                nodes: r.nodes,
                candidates: r.candidates,
                seconds: r.seconds,
                triangulations: r
                    .triangulations
                    .iter()
                    .map(|t| to_lutz_line(t.faces()))
                    .collect(),
            })
            .collect(),
    };
    let text = serde_json::to_string(&checkpoint)?;
    crate::output::write_file(path, |w| {
        use std::io::Write;
        w.write_all(text.as_bytes())?;
        Ok(())
    })
}

/// The estimated seconds of the jobs not yet done: Knuth's estimate of each job's nodes, times
/// the time per node the probes themselves took.
/// The estimated search nodes of each job (Knuth's estimator, in job order) and the estimated
/// seconds of them all, the time per node calibrated on the probing itself (a probe visits one
/// node per level, a job's search one level per face beyond vertex 0's d). Stops as soon as the
/// estimate passes 10,000 times `budget` (the jobs after are then not estimated: the figures
/// are a lower bound, and the third value is false).
fn estimate_seconds(surface: SurfaceKind, jobs: &[Job], budget: f64) -> (Vec<f64>, f64, bool) {
    let start = Instant::now();
    let probes = 200;
    let chi = surface.euler_characteristic();
    let (mut nodes, mut probe_nodes) = (Vec::with_capacity(jobs.len()), 0.0);
    let mut seconds = 0.0;
    for &job in jobs {
        nodes.push(estimate_nodes(surface, job, probes, 1));
        probe_nodes +=
            probes as f64 * (2 * (job.vertices as i64 - chi) - job.max_degree as i64).max(1) as f64;
        let per_node = (start.elapsed().as_secs_f64() / probe_nodes).max(5e-8);
        seconds = nodes.iter().sum::<f64>() * per_node;
        if seconds > 1e4 * budget {
            return (nodes, seconds, false);
        }
    }
    (nodes, seconds, true)
}

/// A duration in the largest fitting unit (seconds to years).
fn long_time(seconds: f64) -> String {
    const DAY: f64 = 86_400.0;
    if seconds < 3.0 * 3600.0 {
        crate::output::format_seconds(seconds)
    } else if seconds < 3.0 * DAY {
        format!("{:.1} hours", seconds / 3600.0)
    } else if seconds < 1000.0 * DAY {
        format!("{:.0} days", seconds / DAY)
    } else {
        format!("{:.1e} years", seconds / (365.25 * DAY))
    }
}

/// Runs `census`.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let surface = SurfaceKind::parse(&args.surface).map_err(|e| invalid(e.to_string()))?;
    if crate::input::is_stdio(&args.output) {
        return Err(invalid(
            "-o: the census is written to a file, not to standard output",
        ));
    }
    if let Some(checkpoint) = &args.checkpoint
        && crate::output::name(checkpoint) == crate::output::name(&args.output)
    {
        return Err(invalid(format!(
            "{}: named by both -o and --checkpoint: give each output its own file",
            shown(checkpoint)
        )));
    }
    let folder = args
        .output
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    if !folder.is_dir() {
        return Err(invalid(format!(
            "{}: not written: no folder {}",
            shown(&args.output),
            shown(folder)
        )));
    }
    if args.budget.is_nan() || args.budget <= 0.0 {
        return Err(invalid("--budget: a positive number of seconds is needed"));
    }
    let (jobs, _) = search::jobs(surface, args.max_vertices).map_err(|e| invalid(e.to_string()))?;
    let done = match &args.checkpoint {
        Some(path) => read_checkpoint(path, surface)?,
        None => Vec::new(),
    };
    let resumed_jobs = done.iter().filter(|r| jobs.contains(&r.job)).count();
    let todo: Vec<Job> = jobs
        .iter()
        .copied()
        .filter(|j| !done.iter().any(|r| r.job == *j))
        .collect();
    let (job_nodes, estimated_seconds, whole) = estimate_seconds(surface, &todo, args.budget);
    let estimated_nodes: f64 = job_nodes.iter().sum();
    let qualifier = if whole { "about" } else { "at least" };
    if estimated_seconds > args.budget {
        return Err(invalid(format!(
            "the census of {surface} up to {} vertices is beyond reach: estimated {qualifier} \
             {:.1e} search nodes, {qualifier} {} on this machine (Knuth's estimator), over the \
             budget of {}; lower --max-vertices, or raise --budget and use --checkpoint to make \
             the run resumable",
            jobs.last().map_or(0, |j| j.vertices),
            estimated_nodes,
            long_time(estimated_seconds),
            crate::output::format_seconds(args.budget)
        )));
    }
    // The bar advances by each job's estimated search nodes (Knuth), so its ETA weighs the jobs.
    let weight = |job: &Job| {
        todo.iter()
            .position(|j| j == job)
            .map_or(0, |k| job_nodes[k].max(1.0) as u64)
    };
    let bar = indicatif::ProgressBar::new(todo.iter().map(weight).sum::<u64>().max(1));
    bar.set_style(
        indicatif::ProgressStyle::with_template("{bar:30} {msg} ({elapsed}, about {eta} left)")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    bar.set_message(format!("{resumed_jobs}/{} jobs", jobs.len()));
    bar.enable_steady_tick(std::time::Duration::from_millis(500));
    let mut finished: Vec<JobResult> = done.clone();
    let checkpoint = args.checkpoint.clone();
    let mut checkpoint_error: Option<anyhow::Error> = None;
    let mut on_job = |result: &JobResult, progress: search::Progress| {
        bar.inc(weight(&progress.job));
        bar.set_message(format!(
            "{}/{} jobs, {} classes; last: {} vertices, degree {}, part {}",
            progress.done,
            progress.total,
            progress.classes,
            progress.job.vertices,
            progress.job.max_degree,
            progress.job.part
        ));
        finished.push(result.clone());
        if let Some(path) = &checkpoint
            && checkpoint_error.is_none()
            && let Err(e) = write_checkpoint(path, surface, &finished, false)
        {
            checkpoint_error = Some(e);
        }
    };
    let census = surftopo_census::census(
        surface,
        CensusOptions {
            max_vertices: args.max_vertices,
            done,
            on_job: Some(&mut on_job),
            stop: None,
        },
    );
    bar.finish_and_clear();
    if let Some(e) = checkpoint_error {
        return Err(e);
    }
    let census = census.map_err(|e| match e {
        CensusError::Cancelled => invalid("stopped before the census was complete"),
        other => invalid(other.to_string()),
    })?;
    if let Some(path) = &checkpoint {
        write_checkpoint(path, surface, &finished, census.complete)?;
    }
    let text = to_lutz(&census.triangulations);
    crate::output::write_file(&args.output, |w| {
        use std::io::Write;
        w.write_all(text.as_bytes())?;
        Ok(())
    })?;
    report(args, &census, resumed_jobs)
}

fn report(args: &Args, census: &Census, resumed_jobs: usize) -> anyhow::Result<()> {
    let chiral: usize = census.per_vertex_count.iter().map(|f| f.chiral).sum();
    let bound = census.bound.map(|b| match b {
        BoundSource::Theorem(s) | BoundSource::Published(s) => s.to_string(),
    });
    if !census.complete {
        stderr_println!(
            "note: the census of {} searched up to {} vertices only: it is complete up to there, not for the surface",
            census.surface,
            census.searched_up_to
        );
    }
    if args.json.json {
        let report = Report {
            surface: census.surface.name(),
            orientable: census.surface.orientable,
            euler_characteristic: census.surface.euler_characteristic(),
            total: census.triangulations.len(),
            chiral,
            complete: census.complete,
            searched_up_to: census.searched_up_to,
            bound,
            mirror_images_identified: true,
            per_vertex_count: census.per_vertex_count.clone(),
            candidates: census.candidates,
            duplicates: census.duplicates,
            nodes: census.nodes,
            seconds: census.seconds,
            resumed_jobs,
        };
        return crate::output::print_json(&report);
    }
    let mut text = String::new();
    for f in &census.per_vertex_count {
        text.push_str(&format!(
            "{} vertices: {}{}\n",
            f.vertices,
            f.classes,
            if census.surface.orientable {
                format!(" ({} chiral)", f.chiral)
            } else {
                String::new()
            }
        ));
    }
    text.push_str(&format!(
        "{}: {} irreducible triangulations of {} (mirror images identified{}), {}, {} candidates, {} ({})\n",
        crate::output::name(&args.output),
        census.triangulations.len(),
        census.surface,
        if census.surface.orientable {
            format!("; {chiral} chiral")
        } else {
            String::new()
        },
        if census.complete {
            "complete".to_string()
        } else {
            format!("complete up to {} vertices only", census.searched_up_to)
        },
        census.candidates,
        crate::output::format_seconds(census.seconds),
        bound.unwrap_or_else(|| "no published bound".into())
    ));
    crate::output::emit(&text)
}
