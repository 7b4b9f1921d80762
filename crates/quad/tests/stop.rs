//! The quad pipeline stops when asked (`surftopo_mesh::stop`, what Ctrl-C sets from Python): LRS's
//! expansion (Algorithm 3.1) run alone under `run_stoppable` with the flag already set unwinds
//! within its first `CHECK_EVERY` steps, and so does `quadrangulate` by every algorithm, whatever
//! the machine's speed; with the flag unset the expansion leaves at most 44 triangles of the torus
//! unpaired (the bound `quadrangulate` checks, max(4, 56g − 12) for genus 1).

use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use surftopo_mesh::generators::torus;
use surftopo_mesh::stop::{CHECK_EVERY, run_stoppable};
use surftopo_quad::{QuadAlgorithm, expand, quadrangulate};

fn flag(set: bool) -> Arc<AtomicBool> {
    Arc::new(AtomicBool::new(set))
}

#[test]
fn lrs_expansion_and_every_quadrangulation_stop_when_asked() {
    let mesh = torus(150, 150).mesh;
    let reduction = surftopo_irreducible::ramaswami_siqueira(mesh.clone()).unwrap();
    assert!(reduction.history.len() > 10 * CHECK_EVERY as usize);
    let run = |set: bool| {
        run_stoppable(flag(set), || {
            expand(reduction.mesh.clone(), &reduction.history)
        })
    };
    assert!(run(true).is_none(), "the expansion ran on");
    let expanded = run(false).unwrap().unwrap();
    // The bound `quadrangulate` checks LRS against: max(4, 56 g - 12) for genus g = 1.
    assert!(expanded.pairing.unmatched_count(&expanded.mesh) <= 44);
    for algorithm in [
        QuadAlgorithm::SimpleGreedy { seed: 1 },
        QuadAlgorithm::PulliSegal { seed: 1 },
        QuadAlgorithm::Lrs,
        QuadAlgorithm::DiksStanczyk,
        QuadAlgorithm::KarpSipser,
    ] {
        let stopped = run_stoppable(flag(true), || quadrangulate(&mesh, algorithm));
        assert!(stopped.is_none(), "{algorithm:?} ran on");
    }
}
