//! A spinner on stderr for steps that can take more than a second; hidden when stderr is not a
//! terminal (indicatif draws nothing then).

use indicatif::{ProgressBar, ProgressStyle};
use std::time::Duration;

/// Runs `work` while a spinner shows `message`.
pub fn step<T>(message: &str, work: impl FnOnce() -> T) -> T {
    let spinner = ProgressBar::new_spinner();
    spinner.set_style(
        ProgressStyle::with_template("{spinner} {msg} ({elapsed})")
            .unwrap_or_else(|_| ProgressStyle::default_spinner()),
    );
    spinner.set_message(message.to_string());
    spinner.enable_steady_tick(Duration::from_millis(120));
    let result = work();
    spinner.finish_and_clear();
    result
}
