//! Errors of the linear analyses.

use crate::limits::LimitError;
use crate::model::ModelError;

/// Why an analysis could not be done.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PhysicsError {
    /// The model is invalid.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// A size beyond [`crate::limits::Limits`] (orders, sweep points).
    #[error(transparent)]
    Limit(#[from] LimitError),
    /// The model has no nodes.
    #[error("the model has no `[[inertia]]` nodes")]
    Empty,
    /// A rubber stage cannot carry the mean torque within 10 rad of twist.
    #[error(
        "rubber stage `{connection}` cannot carry the mean torque of {torque_nm:.1} N·m within 10 rad of twist"
    )]
    Twist {
        /// Connection name.
        connection: String,
        /// Mean torque through it, N·m.
        torque_nm: f64,
    },
    /// A correction factor is at or below zero where it is evaluated.
    #[error("rubber stage `{connection}`: `{key}` gives the factor {value:.4} (must be > 0)")]
    Factor {
        /// Connection name.
        connection: String,
        /// The polynomial's key.
        key: &'static str,
        /// The factor.
        value: f64,
    },
    /// α_f is at or below zero at a frequency the analysis needs.
    #[error(
        "rubber stage `{connection}`: `frequency_poly` gives α_f = {value:.4} at {frequency_hz:.1} Hz (must be > 0; give `frequency_poly_range` to hold it beyond the measured range)"
    )]
    FrequencyFactor {
        /// Connection name.
        connection: String,
        /// Frequency, Hz.
        frequency_hz: f64,
        /// The factor.
        value: f64,
    },
    /// A matrix that must be invertible is not (a free part of the driveline, or a
    /// forced response exactly at an undamped resonance).
    #[error("singular system: {0}")]
    Singular(String),
    /// An iteration did not converge.
    #[error("no convergence: {0}")]
    NoConvergence(String),
}
