//! A progress bar on stderr for long work, shown only when stderr is a terminal
//! (`spec/cli.md`).

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;

/// A bar over 0–1 with a message (cut to the terminal's width, so the bar stays on one
/// line), or nothing when stderr is not a terminal.
pub struct Progress {
    bar: Option<ProgressBar>,
}

impl Progress {
    /// Starts a bar labelled `message`.
    pub fn new(message: &str) -> Self {
        let bar = std::io::stderr().is_terminal().then(|| {
            let bar = ProgressBar::new(1000);
            let style = ProgressStyle::with_template(
                "{spinner} [{bar:30}] {percent:>3}% {elapsed_precise} (ETA {eta}) {wide_msg}",
            )
            .map(|s| s.progress_chars("=> "))
            .unwrap_or_else(|_| ProgressStyle::default_bar());
            bar.set_style(style);
            bar.set_message(message.to_string());
            // Redrawn every 200 ms, so the elapsed time and the spinner move during a
            // long stage (a verification takes seconds with no new fraction).
            bar.enable_steady_tick(std::time::Duration::from_millis(200));
            bar
        });
        Self { bar }
    }

    /// Sets the fraction done (0–1); always returns true (the CLI never cancels).
    pub fn set(&self, fraction: f64) -> bool {
        if let Some(bar) = &self.bar {
            bar.set_position((fraction.clamp(0.0, 1.0) * 1000.0) as u64);
        }
        true
    }

    /// Replaces the bar's label (e.g. with the stage of the work).
    pub fn message(&self, message: &str) {
        if let Some(bar) = &self.bar {
            bar.set_message(message.to_string());
        }
    }

    /// Removes the bar.
    pub fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}
