//! Errors of the time domain.

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
    /// The step size collapsed (a discontinuity, or a model too stiff for the method).
    #[error(
        "the step size collapsed to {step_s:e} s at t = {time_s:.6} s (the model is too stiff or discontinuous there)"
    )]
    StepCollapse {
        /// Time, s.
        time_s: f64,
        /// Step size, s.
        step_s: f64,
    },
    /// A caller asked to stop.
    #[error("cancelled at t = {time_s:.3} s")]
    Cancelled {
        /// Time, s.
        time_s: f64,
    },
}
