//! The `torsim` binary: parses the command line, runs it, maps errors to exit codes
//! (1: failed check or analysis, 2: bad input or usage).

mod cli;
#[cfg(feature = "gui")]
mod gui;

/// A build without the `gui` feature (issue 13, deliverable 5): no window to open.
#[cfg(not(feature = "gui"))]
mod gui {
    use crate::cli::error::CliError;

    /// No subcommand: a usage error (exit 2), since there is no window in this build.
    pub fn run(_model: Option<String>) -> Result<(), CliError> {
        Err(CliError::input(anyhow::anyhow!(
            "this torsim was built without the `gui` feature; name a command (see `torsim --help`)"
        )))
    }
}

use clap::Parser;
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = cli::Cli::parse();
    match cli::run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("torsim: {:#}", e.error);
            ExitCode::from(e.code)
        }
    }
}
