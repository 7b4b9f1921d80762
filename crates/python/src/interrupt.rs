//! Ctrl-C during a long call: the one way every long function of the package runs its library
//! work ([`interruptible`]).
//!
//! Python handles a signal only between bytecodes, so a Rust call holding the thread would take
//! Ctrl-C when it returns. Here the work runs on a thread of its own while the calling thread,
//! without the GIL, waits for it in slices of [`POLL`] and asks Python between slices whether a
//! signal is pending (`Python::check_signals`): a pending signal raises its exception
//! (`KeyboardInterrupt` for Ctrl-C) within one slice, and the call returns nothing. The work
//! touches no Python object, so nothing Python sees is left half-done. The work then stops too:
//! it runs under [`surftopo_mesh::stop::run_stoppable`] with the [`Stop`] flag the interrupt
//! sets, and the long loops of the libraries (flips, the wave, Dubois' reduction, Diks–Stanczyk
//! with its dual's bridge check and its dynamic connectivity's build, the mesh build's steps,
//! the irreducible reductions, the pairings: SG, Pulli–Segal, Karp–Sipser and its shortcuts, the augmenting
//! paths, LRS's expansion, the quality pairing's blossom and its fast mode) read it every [`surftopo_mesh::stop::CHECK_EVERY`] steps and
//! unwind; the census reads the same flag through its `stop` hook.

use pyo3::prelude::*;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::time::Duration;

/// How long the calling thread waits for the work between two checks for a signal.
const POLL: Duration = Duration::from_millis(20);

/// The stack of the work's thread: as large as a main thread's usual limit, since the work used
/// to run on the caller's thread (the pages are only reserved, not committed).
const STACK_BYTES: usize = 64 << 20;

/// Set once the call that started the work has been interrupted: library work with a stop hook
/// reads it and ends early (its result is dropped anyway).
#[derive(Clone, Default)]
pub struct Stop(Arc<AtomicBool>);

impl Stop {
    /// Whether the call was interrupted.
    pub fn is_set(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }
}

/// Runs `work` on a thread of its own, the GIL released, and returns its result; raises the
/// exception of a signal (`KeyboardInterrupt` for Ctrl-C) within [`POLL`] of its arrival, setting
/// the work's [`Stop`]. A panic of the work is resumed on the caller's thread (pyo3 turns it into
/// `PanicException`, as for a call on the caller's thread).
pub fn interruptible<T: Send + 'static>(
    py: Python<'_>,
    work: impl FnOnce(&Stop) -> T + Send + 'static,
) -> PyResult<T> {
    let stop = Stop::default();
    let (sender, receiver) = mpsc::sync_channel(1);
    let worker_stop = stop.clone();
    let spawned = std::thread::Builder::new()
        .name("surftopo-work".into())
        .stack_size(STACK_BYTES)
        .spawn(move || {
            let flag = worker_stop.0.clone();
            let done = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                surftopo_mesh::stop::run_stoppable(flag, || work(&worker_stop))
            }));
            // Stopped (`Ok(None)`) or not, the caller is gone after an interrupt: nobody to tell.
            if let Some(done) = done.transpose() {
                let _ = sender.send(done);
            }
        });
    if let Err(e) = spawned {
        return Err(pyo3::exceptions::PyRuntimeError::new_err(format!(
            "could not start a thread for the work: {e}"
        )));
    }
    let mut receiver = receiver;
    loop {
        // The receiver goes in and out of each slice (it is `Send`, not `Sync`).
        let (back, received) = py.detach(move || {
            let received = receiver.recv_timeout(POLL);
            (receiver, received)
        });
        receiver = back;
        match received {
            Ok(Ok(value)) => return Ok(value),
            Ok(Err(panic)) => std::panic::resume_unwind(panic),
            Err(mpsc::RecvTimeoutError::Timeout) => {
                if let Err(signal) = py.check_signals() {
                    stop.0.store(true, Ordering::Relaxed);
                    return Err(signal);
                }
            }
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                return Err(pyo3::exceptions::PyRuntimeError::new_err(
                    "the work's thread ended without a result",
                ));
            }
        }
    }
}
