//! A spinner on stderr for steps that can take more than a second; hidden when stderr is not a
//! terminal (indicatif draws nothing then).

use indicatif::{ProgressBar, ProgressStyle};
use std::sync::{Mutex, MutexGuard};
use std::time::Duration;

/// The steps in progress, innermost last (for `--time-limit`'s message).
static CURRENT: Mutex<Vec<String>> = Mutex::new(Vec::new());

/// The steps in progress, a poisoned lock taken as is (a step's name is only shown).
fn steps_in_progress() -> MutexGuard<'static, Vec<String>> {
    CURRENT
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// The step running now, if any: the innermost [`step`] (or [`steps`]' current one) in progress.
pub fn current() -> Option<String> {
    steps_in_progress()
        .iter()
        .rev()
        .find(|name| !name.is_empty())
        .cloned()
}

/// A spinner showing `message`, ticking.
fn spinner(message: &str) -> ProgressBar {
    let spinner = ProgressBar::new_spinner();
    spinner.set_style(
        ProgressStyle::with_template("{spinner} {msg} ({elapsed})")
            .unwrap_or_else(|_| ProgressStyle::default_spinner()),
    );
    spinner.set_message(message.to_string());
    spinner.enable_steady_tick(Duration::from_millis(120));
    spinner
}

/// Runs `work` while a spinner shows `message` ([`current`] names it meanwhile).
pub fn step<T>(message: &str, work: impl FnOnce() -> T) -> T {
    steps_in_progress().push(message.to_string());
    let spinner = spinner(message);
    let result = work();
    steps_in_progress().pop();
    spinner.finish_and_clear();
    result
}

/// Runs `work`, which names each of its steps as it starts through the callback it is given,
/// while a spinner shows the current one ([`current`] names it meanwhile).
pub fn steps<T>(work: impl FnOnce(&mut dyn FnMut(&'static str)) -> T) -> T {
    steps_in_progress().push(String::new());
    let spinner = spinner("");
    let result = work(&mut |message| {
        spinner.set_message(message);
        if let Some(name) = steps_in_progress().last_mut() {
            *name = message.to_string();
        }
    });
    steps_in_progress().pop();
    spinner.finish_and_clear();
    result
}
