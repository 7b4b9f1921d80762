//! The Voronoi wave's computation against flipping's, side by side in one process: what
//! `surftopo delaunay --method voronoi` and `--method flip` compute (the intrinsic Delaunay
//! triangulation and its cotan Laplacian, through [`intrinsic_delaunay`]), in alternating rounds on
//! the same input, on every shared mesh of 1k–300k faces and on generated inputs made here with
//! seeds used nowhere else (flipped, high-genus, needle-rich, intrinsically flipped).
//!
//! ```text
//! SURFTOPO_MESHES=../shared/meshes cargo run --release -p surftopo-intrinsic \
//!     --example voronoi_speed -- [--rounds N] [--mesh-budget SECONDS] [--only NAME] \
//!     [--skip NAME]... [--min-faces F] [--max-faces F] [--out FILE]
//! ```
//!
//! Per input: up to `--rounds` rounds (default 5), each a flip run then a voronoi run on a clone
//! of the same edge lengths (the clone is not timed); after the first round, rounds stop once the
//! input has taken `--mesh-budget` seconds (default 30). Printed per input: the median wall times,
//! the ratio of the medians and the median of the per-round ratios voronoi / flip (the paired
//! ratio), the same in the thread's CPU time, the wave's events and the system load; `--out` also writes the table as markdown. `--only`
//! keeps the inputs whose name contains NAME, `--skip` drops them (e.g. a mesh the wave takes
//! minutes on: a run cannot be stopped in-process); the face range applies to the shared meshes.

use std::fmt::Write as _;
use std::time::Instant;

use surftopo_intrinsic::generators::random_flips as intrinsic_flips;
use surftopo_intrinsic::{
    DelaunayInput, DelaunayMethod, DelaunayOutputs, DelaunayRequest, IntrinsicTriangulation,
    intrinsic_delaunay,
};
use surftopo_mesh::Surface;
use surftopo_mesh::generators::{
    genus_surface, icosphere, random_flips, random_vertex_splits, sheared_torus, torus,
};
use surftopo_testkit::{load, shared_meshes};

struct Args {
    rounds: usize,
    mesh_budget: f64,
    only: Option<String>,
    skip: Vec<String>,
    min_faces: usize,
    max_faces: usize,
    out: Option<String>,
}

fn parse_args() -> Args {
    let mut args = Args {
        rounds: 5,
        mesh_budget: 30.0,
        only: None,
        skip: Vec::new(),
        min_faces: 1_000,
        max_faces: 300_000,
        out: None,
    };
    let mut it = std::env::args().skip(1);
    while let Some(a) = it.next() {
        let mut value = || it.next().unwrap_or_else(|| panic!("{a} needs a value"));
        match a.as_str() {
            "--rounds" => args.rounds = value().parse::<usize>().expect("--rounds N").max(1),
            "--mesh-budget" => args.mesh_budget = value().parse().expect("--mesh-budget SECONDS"),
            "--only" => args.only = Some(value()),
            "--skip" => args.skip.push(value()),
            "--min-faces" => args.min_faces = value().parse().expect("--min-faces F"),
            "--max-faces" => args.max_faces = value().parse().expect("--max-faces F"),
            "--out" => args.out = Some(value()),
            other => panic!("unknown argument {other}"),
        }
    }
    args
}

/// A generated input: its name and how to make it.
type Generated = (&'static str, fn() -> IntrinsicTriangulation);

/// The generated inputs. Seeds chosen for this benchmark only (the wave was not tuned on them).
const GENERATED: [Generated; 5] = [
    ("torus 150×100 + 25k flips (seed 8087)", || {
        by_positions(random_flips(&torus(150, 100), 25_000, 8087))
    }),
    ("genus 9 size 3 + 8k flips (seed 6151)", || {
        by_positions(random_flips(&genus_surface(9, 3), 8_000, 6151))
    }),
    ("icosphere 5 + 6k vertex splits (seed 7919)", || {
        by_positions(random_vertex_splits(&icosphere(5), 6_000, 7919))
    }),
    ("sheared torus 300×60 shear 7 (needles)", || {
        by_positions(sheared_torus(300, 60, 7))
    }),
    ("icosphere 6 + 50k intrinsic flips (seed 5003)", || {
        let mut t = by_positions(icosphere(6));
        intrinsic_flips(&mut t, 50_000, 5003);
        t
    }),
];

/// The triangulation of a surface by the lengths of its edges.
fn by_positions(s: Surface) -> IntrinsicTriangulation {
    IntrinsicTriangulation::from_positions(s.mesh, &s.positions).expect("a valid surface")
}

/// The one-minute load average (Linux), or NaN.
fn load_average() -> f64 {
    std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse().ok())
        .unwrap_or(f64::NAN)
}

/// The median of `v` (sorted in place).
fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// The CPU time this thread has run, in seconds (Linux: the first field of
/// `/proc/thread-self/schedstat`, nanoseconds on the CPU), or NaN. Unlike wall time it does not
/// grow while the thread waits for a core, which on a loaded machine a long run does far more
/// than a short one.
fn thread_cpu_seconds() -> f64 {
    // The kernel brings the running thread's figure up to date when it yields (otherwise only
    // at a tick or a switch, which a sub-millisecond run may not see).
    std::thread::yield_now();
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<u64>().ok())
        .map_or(f64::NAN, |ns| ns as f64 * 1e-9)
}

/// One timed run of `method` on a clone of `tri` (the clone not timed): wall seconds, CPU
/// seconds ([`thread_cpu_seconds`]) and wave events.
fn run(tri: &IntrinsicTriangulation, method: DelaunayMethod) -> Result<(f64, f64, u64), String> {
    let input = DelaunayInput::Lengths(tri.clone());
    let request = DelaunayRequest {
        method,
        outputs: DelaunayOutputs {
            triangulation: true,
            laplacian: true,
            ..DelaunayOutputs::default()
        },
        ..DelaunayRequest::default()
    };
    let (start, cpu) = (Instant::now(), thread_cpu_seconds());
    let out = intrinsic_delaunay(input, &request).map_err(|e| e.to_string())?;
    let (seconds, cpu) = (start.elapsed().as_secs_f64(), thread_cpu_seconds() - cpu);
    std::hint::black_box(&out.laplacian);
    Ok((seconds, cpu, out.wave.map_or(0, |w| w.events)))
}

/// Alternating rounds on one input; its table row.
fn measure(name: &str, tri: &IntrinsicTriangulation, args: &Args) -> String {
    let faces = tri.mesh().face_count();
    let load = load_average();
    let started = Instant::now();
    let (mut flip, mut wave, mut ratios) = (Vec::new(), Vec::new(), Vec::new());
    let (mut flip_cpu, mut wave_cpu, mut cpu_ratios) = (Vec::new(), Vec::new(), Vec::new());
    let mut events = 0;
    for round in 0..args.rounds {
        if round > 0 && started.elapsed().as_secs_f64() > args.mesh_budget {
            break;
        }
        let (f, fc) = match run(tri, DelaunayMethod::Flip) {
            Ok((s, c, _)) => (s, c),
            Err(e) => return format!("| {name} | {faces} | flip failed: {e} |"),
        };
        let (w, wc) = match run(tri, DelaunayMethod::Voronoi) {
            Ok((s, c, e)) => {
                events = e;
                (s, c)
            }
            Err(e) => return format!("| {name} | {faces} | voronoi refused: {e} |"),
        };
        flip.push(f);
        wave.push(w);
        ratios.push(w / f);
        flip_cpu.push(fc);
        wave_cpu.push(wc);
        cpu_ratios.push(wc / fc);
    }
    let rounds = flip.len();
    let (f, w) = (median(&mut flip), median(&mut wave));
    let (fc, wc) = (median(&mut flip_cpu), median(&mut wave_cpu));
    format!(
        "| {name} | {faces} | {rounds} | {:.2} | {:.1} | {:.1} | {:.1} | {:.2} | {:.1} | {:.1} | \
         {events} | {:.2} | {load:.1} |",
        1e3 * f,
        1e3 * w,
        w / f,
        median(&mut ratios),
        1e3 * fc,
        1e3 * wc,
        median(&mut cpu_ratios),
        events as f64 / faces as f64,
    )
}

fn main() {
    let args = parse_args();
    let header = "| input | F | rounds | flip ms | voronoi ms | ratio of medians | paired ratio | \
                  flip CPU ms | voronoi CPU ms | paired CPU ratio | wave events | events / F | \
                  load |\n\
                  |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|";
    let mut md = String::new();
    writeln!(md, "{header}").unwrap();
    println!("{header}");
    let named = |name: &str| {
        args.only.as_ref().is_none_or(|o| name.contains(o.as_str()))
            && !args.skip.iter().any(|k| name.contains(k.as_str()))
    };
    let mut meshes = shared_meshes();
    meshes.sort_by_key(|m| m.faces);
    for mesh in meshes
        .iter()
        .filter(|m| named(&m.file) && (args.min_faces..=args.max_faces).contains(&m.faces))
    {
        let surface = load(mesh);
        let Ok(tri) = IntrinsicTriangulation::from_positions(surface.mesh, &surface.positions)
        else {
            continue;
        };
        let row = measure(&mesh.file, &tri, &args);
        println!("{row}");
        writeln!(md, "{row}").unwrap();
    }
    for (name, make) in GENERATED {
        if !named(name) {
            continue;
        }
        let tri = make();
        let row = measure(name, &tri, &args);
        println!("{row}");
        writeln!(md, "{row}").unwrap();
    }
    if let Some(out) = &args.out {
        std::fs::write(out, md).unwrap();
    }
}
