//! The `torsim` binary: parses the command line, runs it, maps errors to exit codes
//! (1: failed check or analysis, 2: bad input or usage).

mod cli;
mod gui;

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
