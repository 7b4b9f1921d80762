//! Timing: wall-clock and on-CPU time of the running thread, repetitions of short runs.

use std::time::Instant;

/// CPU time of the calling thread in seconds (Linux `/proc/thread-self/schedstat`; 0 where it is
/// missing). On a shared machine it measures the work rather than the wait for a core; it
/// advances at scheduler ticks, so it is meaningful as a mean over calls adding up to many ticks.
pub fn thread_cpu_seconds() -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<u64>().ok())
        .map_or(0.0, |ns| ns as f64 * 1e-9)
}

/// The 1-minute load average (`/proc/loadavg`), as text.
pub fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|s| s.split_whitespace().next().map(String::from))
        .unwrap_or_else(|| "?".into())
}

/// A timed call: its first result, the least wall-clock seconds over the calls, the mean CPU
/// seconds per call and the number of calls.
pub struct Timed<T> {
    /// The result of the first call.
    pub first: T,
    /// Least wall-clock seconds over the calls.
    pub wall: f64,
    /// Mean CPU seconds per call.
    pub cpu: f64,
    /// Number of calls.
    pub calls: u32,
}

/// Calls `f` once, then again while less than `min_total` seconds have passed (at most 10,000
/// calls): one short call says little on the tick-based CPU clock. `f` returns its result and
/// the wall-clock seconds of the part that counts.
pub fn timed<T>(min_total: f64, mut f: impl FnMut() -> (T, f64)) -> Timed<T> {
    let start = Instant::now();
    let cpu_start = thread_cpu_seconds();
    let (first, mut wall) = f();
    let mut calls = 1u32;
    while start.elapsed().as_secs_f64() < min_total && calls < 10_000 {
        wall = wall.min(f().1);
        calls += 1;
    }
    Timed {
        first,
        wall,
        cpu: (thread_cpu_seconds() - cpu_start) / f64::from(calls),
        calls,
    }
}

/// Mean of `values` (0 for none).
pub fn mean(values: impl IntoIterator<Item = f64>) -> f64 {
    let (sum, n) = values
        .into_iter()
        .fold((0.0, 0usize), |(s, n), x| (s + x, n + 1));
    if n == 0 { 0.0 } else { sum / n as f64 }
}

/// Inputs with more triangles than this get [`LARGE_INPUT_SEEDS`] seeded runs of the randomised
/// algorithms (BF; SG and PS) instead of the papers' ten.
pub const LARGE_INPUT_FACES: usize = 1_000_000;

/// Seeded runs on an input above [`LARGE_INPUT_FACES`]. Decision (fewer than the papers' ten,
/// which average ten shuffles): at millions of triangles the spread over seeds of the counts is a
/// small fraction of their mean, while ten runs of PS's augmentation or of BF on the papers'
/// twenty-odd inputs of 4.2M triangles take most of an hour on a shared 2-core machine; the
/// reports name the inputs measured with fewer runs.
pub const LARGE_INPUT_SEEDS: u64 = 3;

/// The seeded runs of an algorithm that the paper runs `paper_seeds` times, on an input of
/// `faces` triangles: the paper's count, or [`LARGE_INPUT_SEEDS`] above [`LARGE_INPUT_FACES`].
pub fn seeds_for(paper_seeds: u64, faces: usize) -> u64 {
    if faces > LARGE_INPUT_FACES {
        paper_seeds.min(LARGE_INPUT_SEEDS)
    } else {
        paper_seeds
    }
}

/// The clause of a report's protocol sentence naming the inputs run with [`LARGE_INPUT_SEEDS`]
/// seeds (empty when there are none).
pub fn fewer_seeds(inputs: &[impl AsRef<str>]) -> String {
    if inputs.is_empty() {
        return String::new();
    }
    let names: Vec<&str> = inputs.iter().map(AsRef::as_ref).collect();
    format!(
        ", except on the inputs of more than {} triangles: {LARGE_INPUT_SEEDS} seeds (fewer than \
         the paper's ten, to bound the run's time on this shared 2-core machine) on {}",
        super::report::number(LARGE_INPUT_FACES as f64, 0),
        names.join(", ")
    )
}
