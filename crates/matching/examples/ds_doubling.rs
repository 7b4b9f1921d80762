//! Doubling series for the Diks–Stanczyk perfect matching: prints, per size, the seconds, the
//! seconds divided by n log² n and by n², so that the growth rate is visible.
//!
//! ```text
//! cargo run --release -p surftopo-matching --example ds_doubling -- [MAX_NODES] [FAMILY]
//! ```
//! `MAX_NODES` defaults to 1048576 (sizes 1000·2^k up to it); `FAMILY` is `random` (handle
//! insertions, shuffled ids), `torus` (dual of a grid torus, mesh order) or `both` (default).
//!
//! Besides wall-clock seconds it prints the CPU seconds of the matching (on-CPU time of this
//! thread, from `/proc/thread-self/schedstat`, so that a shared machine does not inflate the
//! ratios); the ratio columns use CPU seconds when available.

use std::time::Instant;

use surftopo_matching::generators::{random_bridgeless_cubic, torus_dual};
use surftopo_matching::{CubicGraph, diks_stanczyk_with_stats, verify_perfect_matching};

/// On-CPU nanoseconds of this thread (Linux), if available.
fn thread_cpu_ns() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    text.split_whitespace().next()?.parse().ok()
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let max: u64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1 << 20);
    let family = args.get(2).map_or("both", String::as_str);
    println!(
        "{:<7} {:>9} {:>8} {:>8} {:>9} {:>9} {:>9} {:>13} {:>13} {:>6} {:>6}",
        "family",
        "n",
        "gen_s",
        "build_s",
        "reduce_s",
        "wall_s",
        "cpu_s",
        "cpu/(nlg²n)",
        "cpu/n²",
        "maxlvl",
        "digon"
    );
    for fam in ["random", "torus"] {
        if family != "both" && family != fam {
            continue;
        }
        let mut n: u64 = 1000;
        while n <= max {
            let t = Instant::now();
            let g: CubicGraph = if fam == "random" {
                random_bridgeless_cubic(n as u32, 42)
            } else {
                // w x h torus with 2wh ~ n faces, w ~ h
                let w = ((n / 2) as f64).sqrt().round() as u32;
                let h = (n as u32 / 2).div_ceil(w);
                torus_dual(w, h)
            };
            let gen_s = t.elapsed().as_secs_f64();
            let nn = f64::from(g.node_count());
            let cpu0 = thread_cpu_ns();
            let (m, stats) = diks_stanczyk_with_stats(&g);
            let cpu_s = match (cpu0, thread_cpu_ns()) {
                (Some(a), Some(b)) => (b - a) as f64 * 1e-9,
                _ => stats.seconds,
            };
            verify_perfect_matching(&g, &m.edge_flags(g.edge_count() as usize)).expect("perfect");
            let lg = nn.log2();
            println!(
                "{:<7} {:>9} {:>8.3} {:>8.3} {:>9.3} {:>9.3} {:>9.3} {:>13.4e} {:>13.4e} {:>6} {:>6}",
                fam,
                g.node_count(),
                gen_s,
                stats.build_seconds,
                stats.reduce_seconds,
                stats.seconds,
                cpu_s,
                cpu_s / (nn * lg * lg),
                cpu_s / (nn * nn),
                stats.dynamic.max_level,
                stats.digon_reductions
            );
            let r = stats.reductions.max(1) as f64;
            let d = stats.dynamic;
            eprintln!(
                "        per reduction: tree deletions {:.2} (from {:.2} forests), replacements {:.2}, tree promotions {:.2}, non-tree promotions {:.2}",
                d.tree_deletions as f64 / r,
                d.tree_deletion_forests as f64 / r,
                d.replacements as f64 / r,
                d.tree_promotions as f64 / r,
                d.nontree_promotions as f64 / r
            );
            n *= 2;
        }
    }
}
