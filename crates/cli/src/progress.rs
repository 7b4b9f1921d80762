//! A spinner on stderr for steps that can take more than a second; hidden when stderr is not a
//! terminal (indicatif draws nothing then).

use indicatif::{ProgressBar, ProgressStyle};
use std::time::Duration;

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

/// Runs `work` while a spinner shows `message`.
pub fn step<T>(message: &str, work: impl FnOnce() -> T) -> T {
    let spinner = spinner(message);
    let result = work();
    spinner.finish_and_clear();
    result
}

/// Runs `work`, which names each of its steps as it starts through the callback it is given,
/// while a spinner shows the current one.
pub fn steps<T>(work: impl FnOnce(&mut dyn FnMut(&'static str)) -> T) -> T {
    let spinner = spinner("");
    let result = work(&mut |message| spinner.set_message(message));
    spinner.finish_and_clear();
    result
}
