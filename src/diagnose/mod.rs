//! Diagnosis (`spec/diagnosis.md`): where a model and bench recordings disagree, which
//! physics the model left out, that physics modelled and fitted, and the fit shown to
//! improve on recordings the fit did not use — or `none` / `parameter_error` when that is
//! the truth.
//!
//! The steps, one file each:
//! - [`observe`]: the measured side. Every recording through the order analysis of
//!   [`crate::signal`]: order amplitudes per station of every steady regime, of the time
//!   blocks of a long run, and of the speed bins of a run-up, each with its noise.
//! - [`forward`]: the same quantities predicted by a model: the nonlinear time domain of
//!   [`crate::transient`] run at each recording's regime and analysed the same way, so
//!   measured and simulated meet on equal terms.
//!   A long run-up is simulated in segments on parallel threads ([`forward_runup`]).
//! - [`context`]: the two ways a model is evaluated: the time domain (what is scored) and
//!   the linear surrogate (what the fits move on).
//! - [`candidates`]: the effects of the spec's table as model extensions with few
//!   parameters (they are the effect models of [`crate::effects`]), each with its signature.
//! - [`fit`]: Levenberg–Marquardt on the effect's parameter together with the scale
//!   factors of the plain parameters it could be confused with (all of them).
//! - [`screen`]: every candidate fitted cheaply (surrogate, or the time domain of only the
//!   recordings that show it; an effect whose signature is absent is not fitted). Thermal
//!   drift needs a drifting long run ([`drift`]). Each parameter declares how its search
//!   and verification treat it ([`param`]).
//! - [`verify`]: the best three by the fitted data, and those their parameter declares,
//!   verified in the time domain of the whole campaign ([`rounds`]).
//! - [`multistart`]: the plain fit started from the user's values and a small
//!   deterministic design, so that it escapes a local minimum.
//! - [`restart`]: every candidate the linear model sees also fitted from the user's
//!   values, where the plain fit has not bent the plain parameters to stand in for it.
//! - [`trial`]: every model the diagnosis proposes is run there; one that cannot be
//!   simulated is a rejected step (the fit keeps its point) or a rejected candidate (listed
//!   with its reason, never the verdict). Only the user's own model failing is an error.
//! - [`decide`]: held-out scoring with a parameter penalty and the verdict; [`guard`]
//!   keeps every verdict at least as good as the user's model on held-out data (else
//!   `none`, saying so); [`places`] the places of an effect the recordings cannot tell
//!   apart.
//! - [`report`]: the JSON of the spec; [`html`] the page for a person.

pub mod accept;
mod aside;
mod backlash_damping;
pub mod branch;
pub mod branch_damping;
pub mod candidates;
pub mod candidates_amplitude;
pub mod candidates_backlash;
pub mod context;
pub mod decide;
pub mod drift;
pub mod fit;
pub mod forward;
pub mod forward_runup;
pub mod guard;
pub mod holdout;
pub mod html;
pub mod labels;
pub mod mesh_damping;
pub mod mesh_damping_search;
pub mod multistart;
pub mod observe;
pub mod observe_runup;
mod own_gain;
pub mod parallel;
pub mod param;
pub mod places;
pub mod power;
pub mod power_add;
pub mod power_eval;
pub mod power_fisher;
pub mod power_named;
pub mod power_pairs;
pub mod power_plan;
pub mod power_run;
pub mod power_size;
pub mod report;
pub mod report_parts;
pub mod residual;
pub mod restart;
pub mod reversal;
pub mod rounds;
pub mod run;
#[cfg(test)]
mod runup_tests;
pub mod screen;
pub mod searched;
pub mod sensor;
pub mod sensor_gain;
mod sensor_local;
pub mod sensor_refine;
pub mod settling;
pub mod spread;
pub mod surrogate;
mod svg;
mod sweeps;
#[cfg(test)]
mod test_fixtures;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_guard;
#[cfg(test)]
mod tests_prior;
#[cfg(test)]
mod tests_rejected;
#[cfg(test)]
mod tests_sensor_gain;
#[cfg(test)]
mod tests_verify;
pub mod thermal_start;
mod tie;
pub mod trial;
mod unsimulable;
pub mod verify;
pub mod words;

pub use html::report_html;
pub use report::Report;
pub use run::diagnose;

use crate::recording::Recording;

/// A recording to diagnose with its label (sidecar `label`, else the file stem).
#[derive(Debug, Clone)]
pub struct LabelledRecording {
    /// For a person and for the report: `"Regime A"`.
    pub label: String,
    /// The recording.
    pub recording: Recording,
}

/// Settings of [`diagnose`].
#[derive(Debug, Clone, PartialEq)]
pub struct DiagnoseOptions {
    /// Worker threads for the simulations (default: the machine's cores, at most 8).
    pub threads: usize,
    /// Highest engine order compared (default 8).
    pub max_order: f64,
}

impl Default for DiagnoseOptions {
    fn default() -> Self {
        Self {
            threads: std::thread::available_parallelism()
                .map_or(2, |n| n.get())
                .min(8),
            max_order: 8.0,
        }
    }
}

/// Why a diagnosis could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DiagnoseError {
    /// The inputs do not fit together (a station that is no node, no recordings, …).
    #[error("{0}")]
    Input(String),
    /// A recording could not be analysed.
    #[error("recording `{label}`: {message}")]
    Analysis {
        /// Its label.
        label: String,
        /// What went wrong.
        message: String,
    },
    /// A simulation of the user's model failed.
    #[error("simulating `{label}`: {message}")]
    Simulation {
        /// The recording simulated.
        label: String,
        /// What went wrong.
        message: String,
    },
    /// The caller cancelled.
    #[error("cancelled")]
    Cancelled,
}
