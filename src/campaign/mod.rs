//! A bench campaign as planned: which runs are recorded (steady regimes, long runs,
//! run-ups, with speed, load, duration and rate: [`Plan`], read from a plan file by
//! [`plan_file`]) and where (the speed [`Station`]s).
//!
//! Two users: `synth` records such a campaign on a truth model, and the diagnosis's
//! detectability analysis (`diagnose --power`) predicts what it can tell apart before it
//! is run (issue 14, item 6). It lives outside `synth` so that `synth` stays a leaf.

pub mod plan;
pub mod plan_file;
pub mod station;

pub use plan::{Plan, PlanDurations, PlannedRun};
pub use station::Station;

/// Why a campaign plan or a station is not valid; the message names the file, run or key.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CampaignError {
    /// Bad input: a plan file, a planned run or a `--station`.
    #[error("{0}")]
    Input(String),
}
