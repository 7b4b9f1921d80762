//! The census: every irreducible triangulation of a closed surface, up to isomorphism.
//!
//! Method (ours; the search strategy is Lutz's and Sulanke–Lutz's "complete the links in
//! order", specialised to irreducible triangulations). For each vertex count n from the Heawood
//! bound to the surface's largest vertex count of an irreducible triangulation, and each maximum
//! degree d, one *job* ([`enumerate`]) lists every labelled triangulation with n vertices, the
//! surface's Euler characteristic and orientability, maximum degree d, vertex 0 of degree d and
//! link 1..d, in which every edge fails the link condition; isomorph rejection keeps a leaf only
//! when its root flag has the least code among the preferred flags (one labelled copy per class,
//! [`enumerate::Enumerator::is_canonical_leaf`]), and the classes are stored by canonical form
//! ([`crate::canonical_form`]).
//!
//! Completeness: (1) every triangulation with maximum degree d has a preferred flag (a vertex of
//! degree d with the largest neighbour-degree sum among those, its neighbour of largest degree,
//! the apex of larger degree on that edge), from which it is labelled as job (n, d) labels: 0, then
//! the link 1..d, then in the search's order; (2) each job's search is exhaustive over such
//! labellings (see [`enumerate`]: it branches over every apex, and prunes only by necessary
//! conditions and by the preferred-flag inequalities); (3) of the labelled copies of a class,
//! exactly those from its least-code preferred flags pass the canonical-root test, and they are one
//! labelled triangulation; canonical forms are equal exactly for isomorphic triangulations; (4) no
//! irreducible triangulation has more vertices than the upper end of the range: a theorem for the
//! sphere (Steinitz–Rademacher) and the projective plane (Joret–Wood's 13h − 4 = 9), and for the
//! torus (10), the Klein bottle (11) and the double torus (17) the largest vertex count of the
//! published complete lists (Lawrencenko 1987; Lawrencenko–Negami 1997 and Sulanke 2006;
//! Sulanke 2006), which the census therefore does not re-prove; [`crate::SurfaceKind::vertex_range`]
//! holds them. A census cut at `max_vertices` below that end is complete only up to it and says so;
//! `max_vertices` above it searches further (a check of the published bound: none is found).
//!
//! Jobs are independent: a run can be resumed from the jobs it finished ([`CensusOptions::done`]).
//! A job is one part of an (n, d) search: the subtree below one apex of its first branching.

pub mod enumerate;

use crate::canonical::{CanonicalForm, canonical_form, is_chiral};
use crate::error::CensusError;
use crate::surface::{BoundSource, SurfaceKind};
use crate::triangulation::Triangulation;
use enumerate::{Enumerator, MAX_VERTICES};
use rand::SeedableRng;
use std::collections::{BTreeMap, HashSet};
use std::time::Instant;

/// One job: vertex count, maximum degree, and the part of that search (the subtree below one
/// apex of its first branching, [`Enumerator::root_choices`]), so that a long search is resumable
/// part by part.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Job {
    /// n.
    pub vertices: usize,
    /// d: the maximum degree, that of vertex 0.
    pub max_degree: usize,
    /// Which part of the (n, d) search: the index of the first branching's apex.
    pub part: usize,
}

/// The enumerator of a job, entered into its part; `None` when the job has no search.
fn enumerator(surface: SurfaceKind, job: Job) -> Option<Enumerator> {
    let chi = surface.euler_characteristic();
    let mut e = Enumerator::new(job.vertices, chi, surface.orientable, job.max_degree)?;
    let choices = e.root_choices();
    if choices.is_empty() {
        // No branching at all: part 0 is the start state itself.
        return (job.part == 0).then_some(e);
    }
    let q = *choices.get(job.part)?;
    e.enter_part(q).then_some(e)
}

/// The number of parts of the (n, d) search (at least 1).
fn part_count(surface: SurfaceKind, vertices: usize, max_degree: usize) -> usize {
    let chi = surface.euler_characteristic();
    Enumerator::new(vertices, chi, surface.orientable, max_degree)
        .map_or(1, |mut e| e.root_choices().len().max(1))
}

/// What one finished job found.
#[derive(Clone, Debug, PartialEq)]
pub struct JobResult {
    /// The job.
    pub job: Job,
    /// The distinct irreducible triangulations found (canonical forms, sorted).
    pub triangulations: Vec<CanonicalForm>,
    /// Search nodes.
    pub nodes: u64,
    /// Labelled triangulations reached (each class is reached once per choice of its vertex 0
    /// and of the start and direction of its link).
    pub candidates: u64,
    /// Seconds.
    pub seconds: f64,
}

/// Progress of a census run, given to [`CensusOptions::on_job`] after each job.
#[derive(Clone, Copy, Debug)]
pub struct Progress {
    /// The job just finished.
    pub job: Job,
    /// Jobs finished (including resumed ones) and jobs in all.
    pub done: usize,
    /// Jobs in all.
    pub total: usize,
    /// Distinct classes so far.
    pub classes: usize,
}

/// The callback [`CensusOptions::on_job`].
pub type OnJob<'a> = &'a mut dyn FnMut(&JobResult, Progress);

/// Options of [`census`].
#[derive(Default)]
pub struct CensusOptions<'a> {
    /// Search up to this many vertices (below the surface's bound the census is then complete
    /// only up to it; above it the search goes past the bound).
    pub max_vertices: Option<usize>,
    /// Jobs finished by an earlier run (their results are taken as they are).
    pub done: Vec<JobResult>,
    /// Called after each job finishes (for checkpoints and progress).
    pub on_job: Option<OnJob<'a>>,
    /// Asked every few thousand search nodes: true stops the run ([`CensusError::Cancelled`]).
    pub stop: Option<&'a (dyn Fn() -> bool + Sync)>,
}

/// Per vertex count: classes found, chiral classes among them, candidates, nodes, seconds.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct VertexCountFigures {
    /// n.
    pub vertices: usize,
    /// Irreducible triangulations with n vertices, up to isomorphism.
    pub classes: usize,
    /// How many of them are chiral (orientable surfaces only).
    pub chiral: usize,
    /// Labelled triangulations reached by the search.
    pub candidates: u64,
    /// Search nodes.
    pub nodes: u64,
    /// Seconds of search (including resumed jobs' recorded times).
    pub seconds: f64,
}

/// A census: the irreducible triangulations of a surface, up to isomorphism (mirror images
/// identified), in canonical labelling, sorted by vertex count then face list.
#[derive(Clone, Debug)]
pub struct Census {
    /// The surface.
    pub surface: SurfaceKind,
    /// The canonical forms.
    pub triangulations: Vec<CanonicalForm>,
    /// Figures per vertex count searched.
    pub per_vertex_count: Vec<VertexCountFigures>,
    /// Whether the search covered the surface's whole vertex range (false when cut by
    /// `max_vertices`).
    pub complete: bool,
    /// The largest vertex count searched.
    pub searched_up_to: usize,
    /// Where the upper end of the range comes from.
    pub bound: Option<BoundSource>,
    /// Labelled triangulations reached, in all.
    pub candidates: u64,
    /// Candidates that were isomorphic to one found before.
    pub duplicates: u64,
    /// Search nodes, in all.
    pub nodes: u64,
    /// Seconds in all.
    pub seconds: f64,
}

/// The jobs of a census of `surface` up to `max_vertices` vertices (default: the surface's
/// bound), with whether they cover the whole range.
pub fn jobs(
    surface: SurfaceKind,
    max_vertices: Option<usize>,
) -> Result<(Vec<Job>, bool), CensusError> {
    let range = surface.vertex_range();
    let (upper, complete) = match (range.max, max_vertices) {
        (Some((bound, _)), Some(m)) => (m, m >= bound),
        (Some((bound, _)), None) => (bound, true),
        (None, Some(m)) => (m, false),
        (None, None) => {
            return Err(CensusError::BeyondReach {
                reason: format!(
                    "no published complete list bounds the vertex count of the irreducible triangulations of {surface}, \
                     and Joret and Wood's bound ({} vertices) is beyond the search's reach; give --max-vertices N for the \
                     census up to N vertices",
                    range.joret_wood
                ),
            });
        }
    };
    if upper > MAX_VERTICES {
        return Err(CensusError::TooManyVertices {
            vertices: upper,
            limit: MAX_VERTICES,
        });
    }
    let chi = surface.euler_characteristic();
    let mut jobs = Vec::new();
    for n in range.min..=upper {
        // The average degree 6(n − χ)/n bounds the maximum degree from below.
        let average = (6 * (n as i64 - chi)).div_euclid(n as i64) as usize;
        let exact = (6 * (n as i64 - chi)) % n as i64 == 0;
        let least = if exact { average } else { average + 1 };
        let least = least.max(if n == 4 { 3 } else { 4 });
        for d in least..n {
            for part in 0..part_count(surface, n, d) {
                jobs.push(Job {
                    vertices: n,
                    max_degree: d,
                    part,
                });
            }
        }
    }
    Ok((jobs, complete))
}

/// Runs one job: its distinct classes, sorted.
pub fn run_job(
    surface: SurfaceKind,
    job: Job,
    stop: &(dyn Fn() -> bool + Sync),
) -> Result<JobResult, CensusError> {
    let start = Instant::now();
    let mut found: HashSet<CanonicalForm> = HashSet::new();
    let (mut nodes, mut candidates) = (0, 0);
    if let Some(mut e) = enumerator(surface, job) {
        let mut leaf = |e: &Enumerator| {
            if e.is_canonical_leaf() {
                let t = Triangulation::from_search(job.vertices, e.faces().collect());
                found.insert(canonical_form(&t));
            }
        };
        if !e.run(&mut leaf, stop) {
            return Err(CensusError::Cancelled);
        }
        nodes = e.nodes;
        candidates = e.leaves;
    }
    let mut triangulations: Vec<CanonicalForm> = found.into_iter().collect();
    triangulations.sort();
    Ok(JobResult {
        job,
        triangulations,
        nodes,
        candidates,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// Knuth's estimate of a job's search nodes: the mean of `probes` random probes.
pub fn estimate_nodes(surface: SurfaceKind, job: Job, probes: usize, seed: u64) -> f64 {
    let Some(mut e) = enumerator(surface, job) else {
        return 0.0;
    };
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let total: f64 = (0..probes).map(|_| e.probe(&mut rng)).sum();
    total / probes.max(1) as f64
}

/// The census of `surface`: every irreducible triangulation up to isomorphism (see the module
/// documentation for the method and its completeness argument).
pub fn census(surface: SurfaceKind, mut options: CensusOptions<'_>) -> Result<Census, CensusError> {
    let (jobs, complete) = jobs(surface, options.max_vertices)?;
    let never = || false;
    let stop: &(dyn Fn() -> bool + Sync) = options.stop.unwrap_or(&never);
    let mut results: BTreeMap<Job, JobResult> = options
        .done
        .drain(..)
        .filter(|r| jobs.contains(&r.job))
        .map(|r| (r.job, r))
        .collect();
    let mut classes: HashSet<CanonicalForm> = results
        .values()
        .flat_map(|r| r.triangulations.iter().cloned())
        .collect();
    for &job in &jobs {
        if results.contains_key(&job) {
            continue;
        }
        let result = run_job(surface, job, stop)?;
        classes.extend(result.triangulations.iter().cloned());
        if let Some(on_job) = options.on_job.as_mut() {
            on_job(
                &result,
                Progress {
                    job,
                    done: results.len() + 1,
                    total: jobs.len(),
                    classes: classes.len(),
                },
            );
        }
        results.insert(job, result);
    }
    let mut per_n: BTreeMap<usize, VertexCountFigures> = BTreeMap::new();
    for r in results.values() {
        let f = per_n.entry(r.job.vertices).or_insert(VertexCountFigures {
            vertices: r.job.vertices,
            ..Default::default()
        });
        f.candidates += r.candidates;
        f.nodes += r.nodes;
        f.seconds += r.seconds;
    }
    let mut triangulations: Vec<CanonicalForm> = classes.into_iter().collect();
    triangulations.sort_by(|a, b| (a.vertex_count(), a).cmp(&(b.vertex_count(), b)));
    for t in &triangulations {
        let f = per_n.entry(t.vertex_count()).or_default();
        f.classes += 1;
        if is_chiral(&t.to_triangulation()) == Some(true) {
            f.chiral += 1;
        }
    }
    let per_vertex_count: Vec<VertexCountFigures> = per_n.into_values().collect();
    let candidates = per_vertex_count.iter().map(|f| f.candidates).sum();
    Ok(Census {
        surface,
        searched_up_to: jobs.last().map_or(0, |j| j.vertices),
        bound: surface.vertex_range().max.map(|(_, s)| s),
        complete,
        duplicates: candidates - triangulations.len() as u64,
        candidates,
        nodes: per_vertex_count.iter().map(|f| f.nodes).sum(),
        seconds: per_vertex_count.iter().map(|f| f.seconds).sum(),
        triangulations,
        per_vertex_count,
    })
}
