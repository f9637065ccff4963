//! The `torsim` binary: parses the command line, runs it, maps errors to exit codes
//! (1: failed check or analysis, 2: bad input or usage; 130 and 143 after SIGINT and
//! SIGTERM).

mod cli;
#[cfg(feature = "gui")]
mod gui;

/// A build without the `gui` feature (issue 13, deliverable 5): no window to open.
#[cfg(not(feature = "gui"))]
mod gui {
    /// Why there is no window: this build has none.
    #[derive(Debug, thiserror::Error)]
    #[error(
        "this torsim was built without the `gui` feature; name a command (see `torsim --help`)"
    )]
    pub struct OpenError;

    impl OpenError {
        /// A usage error (exit 2): the user asked this build for what it has not got.
        pub fn is_input(&self) -> bool {
            true
        }
    }

    /// No subcommand: there is no window in this build.
    pub fn run(_model: Option<String>) -> Result<(), OpenError> {
        Err(OpenError)
    }
}

use clap::Parser;
use std::process::ExitCode;

/// On SIGINT or SIGTERM: removes the temporary files in progress and exits 128 + the
/// signal's number (130, 143), so that no `.tmp` file is left and every target is either
/// as it was or complete (issue 13). The library installs no handler; it keeps the
/// registry ([`torsim::files::remove_temporaries`]).
fn install_signal_handler() {
    #[cfg(unix)]
    {
        use signal_hook::consts::{SIGINT, SIGTERM};
        // Without the handler a signal still ends the process, leaving a temporary file.
        let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM]) else {
            return;
        };
        let _ = std::thread::Builder::new()
            .name("torsim-signals".into())
            .spawn(move || {
                if let Some(signal) = signals.forever().next() {
                    torsim::files::remove_temporaries();
                    std::process::exit(128 + signal);
                }
            });
    }
}

fn main() -> ExitCode {
    let cli = cli::Cli::parse();
    install_signal_handler();
    match cli::run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("torsim: {:#}", e.error);
            ExitCode::from(e.code)
        }
    }
}
