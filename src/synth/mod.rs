//! Synthetic bench data for the diagnosis (`spec/diagnosis.md`, "Proof on concealed
//! data"): recordings made from a richer model than the one the user has.
//!
//! 1. [`build_truth`]: the user's model with plain parameter errors (every inertia and
//!    stiffness off by a seeded factor within ±P %, [`crate::effects::param_error`]) and
//!    one effect of the spec's table added with physically sensible values — the effect
//!    models are the library's, [`crate::effects`] (rubber, hysteretic, structure, or a
//!    [`SensorArtifact`]); the model format got one extension
//!    for it, `[engine] pressure_scale` (cylinder imbalance).
//! 2. [`Plan`]: the recordings of a campaign — by default regimes A–F at full load, two at
//!    part load, one long steady run and a slow full-load run-up.
//! 3. [`generate`]: each run simulated by the nonlinear time domain
//!    ([`crate::transient::simulate`]) and measured as a bench does ([`ias`]): pulse times
//!    where each shaft passes the lines of its zebra tape or encoder, moved by a slow wobble
//!    of the mean speed ([`wobble`]) and by timing jitter; the speed of every line
//!    interval; the anti-aliasing filter ([`fir`]) down to the output rate; white noise
//!    and the resolution of the samples. Only what a bench knows goes into the
//!    recordings' sidecars (label, kind, speed, load, sensors).
//! 4. [`truth_toml`]: what the recordings really contain, for tests; the diagnosis must
//!    not read it.
//!
//! Everything is deterministic for a seed: the random draws come from [`rng`]
//! ([`crate::effects::rng`]), streams
//! per purpose, so one setting does not shift another's draws.
//!
//! ```
//! use torsim::model::{parse_model, presets};
//! use torsim::synth::{Effect, EffectSpec, build_truth};
//!
//! let text = presets::preset("diagnosis-bench").expect("shipped").text;
//! let user = parse_model(text, "diagnosis-bench.toml")?;
//! let spec = EffectSpec::new(Effect::GearBacklash).with("backlash_deg", 0.3);
//! let truth = build_truth(&user, &spec, 5.0, 7)?;
//! assert!(truth.effect.summary.contains("0.3°"));
//! assert_eq!(truth.parameter_errors.len(), 7); // 4 inertias, 3 stiffnesses
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod fir;
pub mod generate;
pub mod ias;
pub mod measurement;
pub mod shaft_angle;
pub mod truth_file;
pub mod wobble;

pub use crate::campaign::{Plan, PlanDurations, PlannedRun, Station, plan, plan_file, station};
pub use crate::effects::rng;
pub use crate::effects::{
    AppliedEffect, Effect, EffectSpec, ParamValue, ParameterError, SensorArtifact, Truth,
    build_truth,
};
pub use generate::{SynthRecording, generate};
pub use measurement::{Measurement, time_stamps};
pub use truth_file::{TRUTH_FILE, TRUTH_MODEL_FILE, truth_toml};

use crate::effects::EffectError;
use crate::transient::TransientError;

/// Why synthetic data could not be made.
#[derive(Debug, thiserror::Error)]
pub enum SynthError {
    /// Bad input: an effect, a parameter, a plan, a station; the message names it.
    #[error("{0}")]
    Input(String),
    /// The time domain failed on one planned run.
    #[error("recording `{label}`: {source}")]
    Simulation {
        /// The run's label.
        label: String,
        /// What the simulator said.
        source: TransientError,
    },
    /// The measurement of one planned run failed.
    #[error("recording `{label}`: {message}")]
    Run {
        /// The run's label.
        label: String,
        /// Why.
        message: String,
    },
}

/// A plan's or a station's bad input is the synthesis's bad input, with the same message.
impl From<crate::campaign::CampaignError> for SynthError {
    fn from(e: crate::campaign::CampaignError) -> Self {
        match e {
            crate::campaign::CampaignError::Input(message) => SynthError::Input(message),
        }
    }
}

/// An effect's bad input is the synthesis's bad input, with the same message.
impl From<EffectError> for SynthError {
    fn from(e: EffectError) -> Self {
        match e {
            EffectError::Input(message) => SynthError::Input(message),
        }
    }
}
