//! Errors of the time domain.

use crate::limits::LimitError;
use crate::physics::PhysicsError;

/// Why a simulation stopped.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TransientError {
    /// The model cannot be simulated as it is.
    #[error("{0}")]
    Model(String),
    /// Building the linear system failed.
    #[error(transparent)]
    Physics(#[from] PhysicsError),
    /// The solution blew up.
    #[error("the simulation diverged at t = {time_s:.6} s: {state} = {value:e}")]
    Diverged {
        /// Time, s.
        time_s: f64,
        /// Which state, for a person.
        state: String,
        /// Its value.
        value: f64,
    },
    /// A size or value beyond [`crate::limits::Limits`].
    #[error(transparent)]
    Limit(#[from] LimitError),
    /// The step size collapsed (a discontinuity, or a model too stiff for the method).
    #[error(
        "the step size collapsed to {step_s:.3e} s at t = {time_s:.6} s (the model is too stiff or discontinuous there); the error estimate is dominated by {state}"
    )]
    StepCollapse {
        /// Time, s.
        time_s: f64,
        /// Step size, s.
        step_s: f64,
        /// The state whose error dominated the last rejected step, for a person (the
        /// integrators give `state #i`; the run names it).
        state: String,
    },
    /// The run used up its step budget ([`super::RunOptions::step_budget_factor`]): it
    /// would not end in reasonable time (issue 13).
    #[error(
        "the run used up its step budget at t = {time_s:.6} s after {steps} steps (a well-posed run needs about {needed:.0}); the step size is {step_s:.3e} s. {cause}"
    )]
    StepBudget {
        /// Time reached, s.
        time_s: f64,
        /// Current step size, s.
        step_s: f64,
        /// Steps taken (accepted and rejected).
        steps: u64,
        /// Steps a well-posed run needs by `time_s`.
        needed: f64,
        /// The element responsible and what to do, for a person.
        cause: String,
    },
    /// A caller asked to stop.
    #[error("cancelled at t = {time_s:.3} s")]
    Cancelled {
        /// Time, s.
        time_s: f64,
    },
}
