//! Cooperative stop of long library work, shared by every crate of the workspace.
//!
//! A caller that may abandon a computation (the Python package on Ctrl-C) runs it with
//! [`run_stoppable`], which installs a flag on the current thread. The long loops of the
//! libraries (flips, the wave, Dubois' reduction, pairings, contractions) call [`Ticker::tick`]
//! once per step; every [`CHECK_EVERY`] steps it reads the flag, and once the flag is set it
//! unwinds out of the work (with [`std::panic::resume_unwind`]: no panic message), so the loop
//! ends within a few thousand steps and its partial state is dropped. [`run_stoppable`] catches
//! that unwinding and returns `None`. Without an installed flag (the CLI, which stops by ending
//! the process, and every plain library call) a tick costs one counter increment and, every
//! [`CHECK_EVERY`] steps, one thread-local read: results are unchanged.

use std::cell::RefCell;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// Steps between two reads of the flag.
pub const CHECK_EVERY: u32 = 1024;

thread_local! {
    static FLAG: RefCell<Option<Arc<AtomicBool>>> = const { RefCell::new(None) };
}

/// The unwinding payload of a stopped computation.
struct Stopped;

/// Runs `work` on the current thread with `flag` as its stop flag; `None` when the flag was set
/// and a loop of the work stopped (a panic of the work is resumed as it was).
pub fn run_stoppable<T>(flag: Arc<AtomicBool>, work: impl FnOnce() -> T) -> Option<T> {
    let previous = FLAG.with(|f| f.replace(Some(flag)));
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(work));
    FLAG.with(|f| *f.borrow_mut() = previous);
    match result {
        Ok(value) => Some(value),
        Err(payload) if payload.is::<Stopped>() => None,
        Err(payload) => std::panic::resume_unwind(payload),
    }
}

/// Whether the flag of the current thread is set (false without one).
pub fn stop_requested() -> bool {
    FLAG.with(|f| {
        f.borrow()
            .as_ref()
            .is_some_and(|s| s.load(Ordering::Relaxed))
    })
}

/// Unwinds out of the work when its flag is set (see the module doc).
pub fn check() {
    if stop_requested() {
        std::panic::resume_unwind(Box::new(Stopped));
    }
}

/// A step counter for a long loop: [`Ticker::tick`] calls [`check`] every [`CHECK_EVERY`] steps.
#[derive(Clone, Copy, Debug, Default)]
pub struct Ticker(u32);

impl Ticker {
    /// Counts one step; every [`CHECK_EVERY`] steps, stops the work if asked.
    #[inline]
    pub fn tick(&mut self) {
        self.0 = self.0.wrapping_add(1);
        if self.0.is_multiple_of(CHECK_EVERY) {
            check();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_set_flag_stops_a_loop_and_an_unset_one_does_not() {
        let flag = Arc::new(AtomicBool::new(false));
        let mut ticker = Ticker::default();
        let done = run_stoppable(flag.clone(), || {
            (0..10 * CHECK_EVERY).for_each(|_| ticker.tick());
            7
        });
        assert_eq!(done, Some(7));
        let mut steps = 0u64;
        let stopped = run_stoppable(flag.clone(), || {
            let mut ticker = Ticker::default();
            loop {
                steps += 1;
                if steps == 5000 {
                    flag.store(true, Ordering::Relaxed);
                }
                ticker.tick();
            }
        });
        assert_eq!(stopped, None::<()>);
        assert!(
            (5000..5000 + u64::from(CHECK_EVERY)).contains(&steps),
            "{steps}"
        );
        // The flag is gone once the work is over.
        assert!(!stop_requested());
        check();
    }

    #[test]
    fn other_panics_pass_through() {
        let flag = Arc::new(AtomicBool::new(false));
        let caught = std::panic::catch_unwind(|| run_stoppable(flag, || panic!("boom")));
        assert!(caught.is_err());
    }
}
