//! Where the time goes: CPU seconds (this thread's on-CPU time from `/proc/thread-self/schedstat`,
//! robust to a shared machine; tick granularity, so averaged over repetitions) of each stage of
//! the pairing algorithms on one mesh, with the nodes reached by the augmenting searches, and how
//! far apart adjacent faces are in id order (locality of the input).
//!
//! ```text
//! cargo run --release -p surftopo-quad --example quad_profile -- MESH [REPEAT] [ks]
//! ```
//! MESH: a mesh file, `box:C:H:T` (a brick of groups A and B), `icosphere:N`, or `shuffled:MESH`
//! (its faces shuffled as by `quad_tables --derived`).
//!
//! The augmentation uses the Forest strategy, or the Local one with `BUDGET=<initial budget>`.
//! KS runs with its guided completion and with the Forest completion alone, alternately (with
//! `ks` as the third argument: KS alone, guided, for a profiler); `KS_BUDGET=<n>` sets its repair
//! budget, `KS_FILE_ORDER=0` turns off its file-order step, `KS_SUBDIVISION=0` its subdivision
//! step, `COLD=1` flushes the caches before each of its runs. Its line gives the mean CPU seconds
//! per call, then the medians of the wall-clock stage times.

use std::error::Error;
use std::time::Instant;

use surftopo_matching::{
    AugmentStrategy, DualGraph, KarpSipserOptions, augment_to_perfect, karp_sipser_perfect_with,
    pulli_segal, simple_greedy, verify_perfect_pairing,
};
use surftopo_mesh::Surface;

/// On-CPU nanoseconds of the current thread (`/proc/thread-self/schedstat`), or wall time when
/// unavailable.
fn cpu_ns(start: &Instant) -> u128 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse().ok())
        .unwrap_or_else(|| start.elapsed().as_nanos())
}

/// Average on-CPU seconds of `f` over `repeat` runs (the accounting has tick granularity, so the
/// runs are timed together), and the last result.
fn time<T>(repeat: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let wall = Instant::now();
    let t0 = cpu_ns(&wall);
    let mut out = None;
    for _ in 0..repeat {
        out = Some(f());
    }
    let spent = cpu_ns(&wall) - t0;
    (
        spent as f64 * 1e-9 / repeat as f64,
        out.expect("repeat >= 1"),
    )
}

/// A mesh file, `box:CAVITIES:HOLES:TRIANGLES` for the generated brick of groups A and B,
/// `icosphere:N`, or `shuffled:SPEC` for SPEC with its faces shuffled as `quad_tables
/// --derived` does (seed 1), so that its derived inputs can be profiled as benchmarked.
fn load(path: &str) -> Result<Surface, Box<dyn Error>> {
    if let Some(spec) = path.strip_prefix("shuffled:") {
        return Ok(surftopo_mesh::generators::shuffle_faces(&load(spec)?, 1));
    }
    if let Some(level) = path.strip_prefix("icosphere:") {
        return Ok(surftopo_mesh::generators::icosphere(level.parse()?));
    }
    if let Some(spec) = path.strip_prefix("box:") {
        let v: Vec<u64> = spec.split(':').map(str::parse).collect::<Result<_, _>>()?;
        let [c, h, t] = v[..] else {
            return Err("box:CAVITIES:HOLES:TRIANGLES".into());
        };
        return Ok(surftopo_mesh::generators::cavity_box(c as u32, h as u32, t));
    }
    let soup = surftopo_io::read_path(std::path::Path::new(path))?;
    let triangles = soup.triangles()?;
    Ok(Surface::from_triangles(soup.positions, &triangles)?)
}

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<String> = std::env::args().collect();
    let surface = load(&args[1])?;
    let repeat: usize = args.get(2).map_or(Ok(5), |s| s.parse())?;
    let mesh = &surface.mesh;
    println!(
        "{}: {} faces, genus {}",
        args[1],
        mesh.face_count(),
        mesh.genus()
    );
    let local = match std::env::var("BUDGET") {
        Ok(b) => AugmentStrategy::Local {
            initial_budget: b.parse()?,
        },
        Err(_) => AugmentStrategy::Forest,
    };
    // `ks` as a third argument: KS alone, with its guided completion (for a profiler).
    if args.get(3).is_some_and(|a| a == "ks") {
        return profile_ks(mesh, repeat, &[true]);
    }
    let (t, sg) = time(repeat, || simple_greedy(mesh, 1));
    println!(
        "sg pairing            {t:.5}  unpaired {}",
        sg.unmatched_count(mesh)
    );
    let (t, stats) = time(repeat, || {
        let mut p = sg.clone();
        augment_to_perfect(mesh, &mut p, local).unwrap()
    });
    println!(
        "sg augment (mesh)     {t:.5}  reached {} searches {}",
        stats.reached, stats.searches
    );
    let (t, ps) = time(repeat, || pulli_segal(mesh, 1));
    println!(
        "ps pairing            {t:.5}  unpaired {}",
        ps.unmatched_count(mesh)
    );
    let (t, stats) = time(repeat, || {
        let mut p = ps.clone();
        augment_to_perfect(mesh, &mut p, local).unwrap()
    });
    println!(
        "ps augment (mesh)     {t:.5}  reached {} searches {}",
        stats.reached, stats.searches
    );
    let (t, stats) = time(repeat, || {
        let mut p = ps.clone();
        augment_to_perfect(mesh, &mut p, AugmentStrategy::Global).unwrap()
    });
    println!(
        "ps augment global     {t:.5}  reached {} searches {}",
        stats.reached, stats.searches
    );
    profile_ks(mesh, repeat, &[true, false])?;
    let (t, _) = time(repeat, || mesh.clone());
    println!("mesh clone            {t:.5}");
    let (t, reduction) = time(repeat, || {
        surftopo_irreducible::ramaswami_siqueira(mesh.clone()).unwrap()
    });
    println!(
        "rs (incl. clone)      {t:.5}  contractions {}",
        reduction.history.len()
    );
    let (t, expansion) = time(repeat, || {
        surftopo_quad::expand(reduction.mesh.clone(), &reduction.history).unwrap()
    });
    println!(
        "lrs expansion         {t:.5}  flipped {}",
        expansion.flipped_edges
    );
    let (t, stats) = time(repeat, || {
        let mut p = expansion.pairing.clone();
        augment_to_perfect(&expansion.mesh, &mut p, local).unwrap()
    });
    println!(
        "lrs augment           {t:.5}  reached {} searches {}",
        stats.reached, stats.searches
    );
    let (t, n) = time(repeat, || {
        (0..mesh.face_slots() as u32)
            .map(|f| DualGraph::adjacent(mesh, f)[2].1 as u64)
            .sum::<u64>()
    });
    println!("one adjacency pass    {t:.5}  ({n})");
    let mut gaps: Vec<u64> = (0..mesh.face_slots() as u32)
        .flat_map(|f| {
            DualGraph::adjacent(mesh, f).map(|(_, g)| (g as i64 - f as i64).unsigned_abs())
        })
        .collect();
    gaps.sort_unstable();
    println!(
        "face id gap to neighbours: median {} p90 {} p99 {}",
        gaps[gaps.len() / 2],
        gaps[gaps.len() * 9 / 10],
        gaps[gaps.len() * 99 / 100]
    );
    Ok(())
}

/// Writes `buffer` (larger than the last-level cache) and sums it, so that the next run starts
/// with cold caches.
fn evict_caches(buffer: &mut [u8]) {
    for (i, b) in buffer.iter_mut().enumerate().step_by(64) {
        *b = b.wrapping_add(i as u8);
    }
    std::hint::black_box(
        buffer
            .iter()
            .step_by(64)
            .map(|&b| u64::from(b))
            .sum::<u64>(),
    );
}

/// KS with its guided completion (`true`) and with the Forest completion alone (`false`), as
/// `guided` says, alternately. `KS_BUDGET` sets the repair budget; `KS_FILE_ORDER=0` turns off
/// the file-order step, `KS_SUBDIVISION=0` the subdivision step.
fn profile_ks(
    mesh: &surftopo_mesh::SurfaceMesh,
    repeat: usize,
    guided: &[bool],
) -> Result<(), Box<dyn Error>> {
    let repair_budget = match std::env::var("KS_BUDGET") {
        Ok(b) => b.parse()?,
        Err(_) => KarpSipserOptions::default().repair_budget,
    };
    let file_order = std::env::var("KS_FILE_ORDER").map_or(true, |v| v != "0");
    let subdivision = std::env::var("KS_SUBDIVISION").map_or(true, |v| v != "0");
    // `COLD=1`: the caches are flushed before each run (as a single call after other work).
    let mut evict = std::env::var_os("COLD").map(|_| vec![0u8; 64 << 20]);
    // Per variant: the CPU seconds and the stats of each run.
    let mut ks_runs: [(Vec<f64>, Vec<_>); 2] = Default::default();
    let mut last_pairing = None;
    for _ in 0..repeat {
        for (&guided, (times, stats)) in guided.iter().zip(&mut ks_runs) {
            let options = KarpSipserOptions {
                guided_completion: guided,
                repair_budget,
                file_order,
                subdivision,
            };
            if let Some(buffer) = &mut evict {
                evict_caches(buffer);
            }
            let (t, (pairing, ks)) = time(1, || karp_sipser_perfect_with(mesh, &options).unwrap());
            last_pairing = Some(pairing);
            times.push(t);
            stats.push(ks);
        }
    }
    for ((times, stats), name) in ks_runs
        .into_iter()
        .zip(["ks (perfect)", "ks (Forest only)"])
    {
        let Some(&ks) = stats.last() else { continue };
        // Medians of the wall-clock stage times, which do not have the CPU clock's ticks.
        let median = |f: &dyn Fn(&surftopo_matching::KarpSipserStats) -> f64| {
            let mut v: Vec<f64> = stats.iter().map(f).collect();
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        };
        let cpu = times.iter().sum::<f64>() / times.len() as f64;
        println!(
            "{name:21} {cpu:.5}  median wall {:.5} greedy {:.5} repairs+completion {:.5} \
             file order {} isolated {} repaired {} deferred {} (skipped {}) guided {} (by Edmonds \
             {}) completed {} reached {} (completion {}) id order {} reversals {} subdivision \
             levels {}",
            median(&|k| k.greedy_seconds + k.augmentation_seconds),
            median(&|k| k.greedy_seconds),
            median(&|k| k.augmentation_seconds),
            ks.file_order,
            ks.isolated,
            ks.repaired,
            ks.deferred,
            ks.skipped,
            ks.guided,
            ks.guided_by_edmonds,
            ks.completed,
            ks.augment.reached,
            ks.completion_reached,
            ks.id_order,
            ks.reversals,
            ks.subdivision_levels,
        );
    }
    // The independent check every pipeline result goes through (copies made beforehand).
    if let Some(pairing) = last_pairing {
        let mut copies = vec![pairing; repeat].into_iter();
        let (t, perfect) = time(repeat, || {
            verify_perfect_pairing(mesh, copies.next().expect("one per run")).is_ok()
        });
        println!("{:21} {t:.5}  perfect {perfect}", "verify (ks pairing)");
    }
    Ok(())
}
