//! Scratch: per-job nodes and times (replaced by census_bench).
use surftopo_census::*;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let s = SurfaceKind::parse(&args[1]).unwrap();
    let max: usize = args[2].parse().unwrap();
    let run_upto: usize = args[3].parse().unwrap();
    let (jobs, _) = search::jobs(s, Some(max)).unwrap();
    for job in jobs {
        let est = search::estimate_nodes(s, job, 2000, 7);
        if job.vertices <= run_upto {
            let never = || false;
            let r = search::run_job(s, job, &never).unwrap();
            println!(
                "{:?} est {:.3e} nodes {} classes {} secs {:.3}",
                job,
                est,
                r.nodes,
                r.triangulations.len(),
                r.seconds
            );
        } else {
            println!("{:?} est {:.3e}", job, est);
        }
    }
}
