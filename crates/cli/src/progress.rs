//! A spinner on stderr for steps that can take more than a second; hidden when stderr is not a
//! terminal (indicatif draws nothing then).

use indicatif::{ProgressBar, ProgressStyle};
use std::time::Duration;

/// The step running now (for `--time-limit`'s message): the innermost [`step`] in progress.
static CURRENT: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());

/// The step running now, if any.
pub fn current() -> Option<String> {
    CURRENT
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
        .last()
        .cloned()
}

/// Runs `work` while a spinner shows `message` ([`current`] names it meanwhile).
pub fn step<T>(message: &str, work: impl FnOnce() -> T) -> T {
    let steps = || {
        CURRENT
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
    };
    steps().push(message.to_string());
    let spinner = ProgressBar::new_spinner();
    spinner.set_style(
        ProgressStyle::with_template("{spinner} {msg} ({elapsed})")
            .unwrap_or_else(|_| ProgressStyle::default_spinner()),
    );
    spinner.set_message(message.to_string());
    spinner.enable_steady_tick(Duration::from_millis(120));
    let result = work();
    steps().pop();
    spinner.finish_and_clear();
    result
}
