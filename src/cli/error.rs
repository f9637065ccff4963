//! Errors of the command line and their exit codes (`spec/cli.md`): 1 for a failed check
//! or an analysis that could not run, 2 for bad input or usage.

use torsim::model::ModelError;
use torsim::physics::PhysicsError;

/// An error with the exit code it maps to.
#[derive(Debug)]
pub struct CliError {
    /// Process exit code.
    pub code: u8,
    /// What went wrong, for stderr.
    pub error: anyhow::Error,
}

impl CliError {
    /// Bad input or usage (exit 2).
    pub fn input(error: impl Into<anyhow::Error>) -> Self {
        Self {
            code: 2,
            error: error.into(),
        }
    }

    /// A failed check or an analysis that could not run (exit 1).
    pub fn failed(error: impl Into<anyhow::Error>) -> Self {
        Self {
            code: 1,
            error: error.into(),
        }
    }
}

impl From<ModelError> for CliError {
    fn from(e: ModelError) -> Self {
        Self::input(e)
    }
}

impl From<PhysicsError> for CliError {
    fn from(e: PhysicsError) -> Self {
        match e {
            PhysicsError::NoConvergence(_) => Self::failed(e),
            _ => Self::input(e),
        }
    }
}

impl From<std::io::Error> for CliError {
    fn from(e: std::io::Error) -> Self {
        Self::input(e)
    }
}
