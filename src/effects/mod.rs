//! The effect models: the physics a user's model can leave out (`spec/diagnosis.md`,
//! table of effects), each as a change to a model, and plain parameter errors. They are
//! the library's, used both by the diagnosis (its candidates, [`crate::diagnose`]) and by
//! the synthetic bench that makes concealed cases (`synth`); they import neither (issue 14,
//! item 3: "Effects are the library's").
//!
//! | file | concept |
//! |---|---|
//! | [`effect`] | the effects by their spec identifiers, and the `key=value` parameters sizing one |
//! | [`truth`] | [`build_truth`]: the user's model with parameter errors and one effect added |
//! | [`rubber`] | rubber-stage effects: amplitude nonlinearity, frequency dependence, thermal drift |
//! | [`rubber_power`] | frequency dependence as a causal power law (`form = power_law`) |
//! | [`rubber_zener`] | frequency dependence as a fractional Zener law (`form = zener`) |
//! | [`branch`] | unmodelled mode, branch form: a local mode hanging on any node |
//! | [`hysteretic`] | rate-independent (hysteretic) damping in place of a viscous equivalent |
//! | [`structure`] | structure and engine: unmodelled mode, variable crank inertia, imbalance |
//! | [`backlash`] | free play in a gear mesh, its contact softening and the mesh's damping |
//! | [`sensor`] | sensor artifacts: a zebra tape's butt joint, a once-per-revolution pitch error |
//! | [`param_error`] | plain parameter errors, named by their place in the model file |
//! | [`rng`] | the seeded random numbers every draw comes from (same data on every machine) |
//!
//! ```
//! use torsim::model::{parse_model, presets};
//! use torsim::effects::{Effect, EffectSpec, build_truth};
//!
//! let text = presets::preset("diagnosis-bench").expect("shipped").text;
//! let user = parse_model(text, "diagnosis-bench.toml")?;
//! let spec = EffectSpec::new(Effect::GearBacklash).with("backlash_deg", 0.3);
//! let truth = build_truth(&user, &spec, 5.0, 7)?;
//! assert!(truth.effect.summary.contains("0.3°"));
//! assert_eq!(truth.parameter_errors.len(), 7); // 4 inertias, 3 stiffnesses
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod backlash;
pub mod branch;
pub mod effect;
pub mod hysteretic;
pub mod param_error;
pub mod rng;
pub mod rubber;
pub mod rubber_power;
pub mod rubber_thermal;
pub mod rubber_zener;
pub mod sensor;
pub mod structure;
pub mod truth;

pub use effect::{Effect, EffectSpec, ParamValue};
pub use param_error::ParameterError;
pub use sensor::SensorArtifact;
pub use truth::{AppliedEffect, Truth, build_truth};

/// Why an effect could not be applied: bad input (an effect, a parameter, a station, the
/// user's model); the message names it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EffectError {
    /// Bad input; the message names it.
    #[error("{0}")]
    Input(String),
}
