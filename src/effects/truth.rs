//! The truth: the user's model with plain parameter errors, then one effect added with
//! physically sensible values ([`build_truth`]). The effects on rubber stages are in
//! [`super::rubber`] and [`super::rubber_thermal`], those on the structure and the engine in
//! [`super::structure`]; a sensor artifact leaves the driveline alone and is
//! carried to the measurement.

use super::effect::{Effect, EffectSpec, ParamValue, Params};
use super::param_error::{ParameterError, apply_random_errors, scale_parameter};
use super::sensor::SensorArtifact;
use super::{EffectError, backlash, hysteretic, rubber, rubber_thermal, structure};
use crate::model::{ConnectionKind, Model, validate};
use crate::physics::{OperatingPoint, System};

/// The effect as applied: its resolved parameters (given or default) and a sentence.
#[derive(Debug, Clone, PartialEq)]
pub struct AppliedEffect {
    /// The effect.
    pub effect: Effect,
    /// Every parameter with the value used, in a stable order.
    pub parameters: Vec<(String, ParamValue)>,
    /// What the truth has that the user's model has not, for a person.
    pub summary: String,
}

/// The richer model the recordings are made from, and what makes it richer.
#[derive(Debug, Clone, PartialEq)]
pub struct Truth {
    /// The truth model.
    pub model: Model,
    /// The effect it adds.
    pub effect: AppliedEffect,
    /// Plain parameter errors (truth against user), including `parameter_error`'s own.
    pub parameter_errors: Vec<ParameterError>,
    /// The sensor artifact of effect `sensor_artifact`, if that is the effect.
    pub artifact: Option<SensorArtifact>,
    /// The seed of the parameter errors.
    pub seed: u64,
}

/// Builds the truth from the user's model: every inertia and stiffness off by a seeded
/// factor within ±`param_error_pct` %, then `spec`'s effect. The result is validated.
///
/// Effect `none` refuses parameter errors (model and recording must agree); use
/// `parameter_error` for a case where only values are off.
pub fn build_truth(
    user: &Model,
    spec: &EffectSpec,
    param_error_pct: f64,
    seed: u64,
) -> Result<Truth, EffectError> {
    validate(user).map_err(|e| EffectError::Input(format!("the user's model: {e}")))?;
    if spec.effect == Effect::None && param_error_pct != 0.0 {
        return Err(EffectError::Input(
            "effect `none` means the model and the recordings agree: --param-error-pct must \
             be 0 (use --effect parameter_error for values that are off)"
                .into(),
        ));
    }
    let mut model = user.clone();
    let mut errors = apply_random_errors(&mut model, param_error_pct, seed)?;
    let mut artifact = None;
    let (parameters, summary) = match spec.effect {
        Effect::None => {
            Params::new(spec, &[])?;
            (
                Vec::new(),
                "nothing: the truth is the user's model".to_string(),
            )
        }
        Effect::ParameterError => parameter_error(&mut model, user, spec, &mut errors)?,
        Effect::CouplingAmplitudeNonlinearity => rubber::amplitude(&mut model, spec)?,
        Effect::CouplingFrequencyDependence => rubber::frequency(&mut model, user, spec)?,
        Effect::CouplingThermalDrift => rubber_thermal::thermal(&mut model, spec)?,
        Effect::HystereticDamping => hysteretic::hysteretic(&mut model, user, spec)?,
        Effect::UnmodelledMode => structure::unmodelled_mode(&mut model, spec)?,
        Effect::CrankVariableInertia => structure::crank_inertia(&mut model, spec)?,
        Effect::GearBacklash => backlash::backlash(&mut model, spec)?,
        Effect::CylinderImbalance => structure::imbalance(&mut model, spec)?,
        Effect::SensorArtifact => {
            let (a, applied) = SensorArtifact::from_spec(spec, user)?;
            artifact = Some(a);
            applied
        }
    };
    validate(&model).map_err(|e| {
        EffectError::Input(format!(
            "effect `{}` with these values makes an invalid model: {e}",
            spec.effect
        ))
    })?;
    Ok(Truth {
        model,
        effect: AppliedEffect {
            effect: spec.effect,
            parameters,
            summary,
        },
        parameter_errors: errors,
        artifact,
        seed,
    })
}

/// Resolved parameters and a summary, as every effect returns them.
pub(crate) type Applied = (Vec<(String, ParamValue)>, String);

/// `parameter_error`: one named inertia or stiffness off by `factor` (on top of any plain
/// errors), by default the first rubber stage's stiffness, −12 %.
fn parameter_error(
    model: &mut Model,
    user: &Model,
    spec: &EffectSpec,
    errors: &mut Vec<ParameterError>,
) -> Result<Applied, EffectError> {
    let mut p = Params::new(spec, &["target", "factor"])?;
    let default = user
        .connections
        .iter()
        .find(|c| matches!(c.kind, ConnectionKind::Rubber(_)))
        .or_else(|| user.connections.first())
        .map(|c| c.name.clone());
    let target = p.text("target", default)?;
    let factor = p.number("factor", 0.88, 0.5, 1.5)?;
    if factor == 1.0 {
        return Err(p.bad("factor", "1 changes nothing (use --effect none)"));
    }
    let e = scale_parameter(model, &target, factor)?;
    let user_value = user_value_of(user, &target).unwrap_or(e.user_value);
    let summary = format!(
        "`{}` is off: the user has {user_value}, the truth {} (×{factor} on top of any \
         plain errors)",
        e.parameter, e.truth_value
    );
    match errors.iter_mut().find(|x| x.parameter == e.parameter) {
        Some(x) => x.truth_value = e.truth_value,
        None => errors.push(ParameterError {
            parameter: e.parameter,
            user_value,
            truth_value: e.truth_value,
        }),
    }
    Ok((p.resolved, summary))
}

/// The user's value of the parameter `target` names.
fn user_value_of(user: &Model, target: &str) -> Option<f64> {
    let mut copy = user.clone();
    scale_parameter(&mut copy, target, 1.0)
        .ok()
        .map(|e| e.user_value)
}

/// Undamped natural frequencies of `model` at full load, Hz (rigid-body modes left out).
pub(crate) fn mode_frequencies_hz(model: &Model) -> Result<Vec<f64>, EffectError> {
    let system = System::new(model, OperatingPoint::default())
        .map_err(|e| EffectError::Input(format!("the user's model: {e}")))?;
    let modes = crate::modal::modes(&system)
        .map_err(|e| EffectError::Input(format!("the user's model: {e}")))?;
    Ok(modes.iter().map(|m| m.frequency_hz).collect())
}
