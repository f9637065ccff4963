//! The model values a calibration may change, named by their place in the model file
//! (the names [`crate::effects::param_error`] uses for plain parameters, and a few more),
//! read and written in one place.

use super::CalibrateError;
use crate::model::{ConnectionKind, HarmonicAmplitude, Model, RubberStiffness};

/// A value of the model the calibration may change, with its bounds (SI unit of the key).
///
/// Names: `inertia.<node>` (kg·m²), `connection.<name>.stiffness` (a shaft's or a rubber
/// stage's given directly, N·m/rad), `connection.<name>.psi` (a rubber stage's relative
/// damping ψ), `engine.reciprocating_mass` (kg), `engine.pressure_factor` (every
/// cylinder's `pressure_scale`), `harmonic.<k>.amplitude` (the k-th `[[harmonic]]`, from
/// 1, N·m) and `operation.regime_speed_factor` (every regime's speed times this factor,
/// of the base model's; a paper that gives speeds as a share of an undisclosed maximum).
/// Several names joined by `,` are one knob: one value set into each (two stages of the
/// same rubber share one ψ).
#[derive(Debug, Clone, PartialEq)]
pub struct Knob {
    /// Its place in the model file.
    pub parameter: String,
    /// Lower bound (> 0: knobs are fitted in the logarithm).
    pub lo: f64,
    /// Upper bound.
    pub hi: f64,
}

/// The plain value a knob names (`None` for the two that are not one number of the
/// file, `engine.pressure_factor` and `operation.regime_speed_factor`, or an unknown name).
fn value_mut<'a>(model: &'a mut Model, parameter: &str) -> Option<&'a mut f64> {
    let parts: Vec<&str> = parameter.split('.').collect();
    match parts.as_slice() {
        ["inertia", node] => model
            .inertias
            .iter_mut()
            .find(|n| n.name == *node)
            .map(|n| &mut n.inertia_kg_m2),
        ["connection", name, key] => {
            let c = model.connections.iter_mut().find(|c| c.name == *name)?;
            match (&mut c.kind, *key) {
                (ConnectionKind::Shaft(s), "stiffness") => Some(&mut s.stiffness_nm_per_rad),
                (ConnectionKind::Rubber(r), "stiffness") => match &mut r.stiffness {
                    RubberStiffness::Direct(k) => Some(k),
                    RubberStiffness::Elements(_) => None,
                },
                (ConnectionKind::Rubber(r), "psi") => Some(&mut r.psi),
                _ => None,
            }
        }
        ["engine", "reciprocating_mass"] => {
            model.engine.as_mut().map(|e| &mut e.reciprocating_mass_kg)
        }
        ["harmonic", k, "amplitude"] => {
            let k: usize = k.parse().ok()?;
            match &mut model.harmonics.get_mut(k.checked_sub(1)?)?.amplitude {
                HarmonicAmplitude::Constant(a) => Some(a),
                HarmonicAmplitude::BySpeed { .. } => None,
            }
        }
        _ => None,
    }
}

/// Sets `parameter` of `model` to `value` (`base`: the model the regime speed factor
/// refers to).
pub fn set_parameter(
    model: &mut Model,
    base: &Model,
    parameter: &str,
    value: f64,
) -> Result<(), CalibrateError> {
    if parameter.contains(',') {
        for one in parameter.split(',') {
            set_parameter(model, base, one.trim(), value)?;
        }
        return Ok(());
    }
    let unknown = || {
        CalibrateError::Input(format!(
            "knob `{parameter}`: no such value in the model (see calibrate::Knob)"
        ))
    };
    match parameter {
        "engine.pressure_factor" => {
            let e = model.engine.as_mut().ok_or_else(unknown)?;
            e.pressure_scale = Some(vec![value; e.cylinders as usize]);
        }
        "operation.regime_speed_factor" => {
            for (r, b) in model
                .operation
                .regimes
                .iter_mut()
                .zip(&base.operation.regimes)
            {
                r.speed_rpm = b.speed_rpm * value;
            }
        }
        _ => *value_mut(model, parameter).ok_or_else(unknown)? = value,
    }
    Ok(())
}

/// The value `parameter` has in `model` (1 for `operation.regime_speed_factor`, which
/// is relative to the base); for a knob of several names, the first's.
pub fn parameter_value(model: &Model, parameter: &str) -> Result<f64, CalibrateError> {
    let first = parameter.split(',').next().unwrap_or(parameter).trim();
    match first {
        "engine.pressure_factor" if model.engine.is_some() => Ok(model
            .engine
            .as_ref()
            .map_or(1.0, |e| e.pressure_scale_of(0))),
        "operation.regime_speed_factor" => Ok(1.0),
        _ => value_mut(&mut model.clone(), first)
            .map(|v| *v)
            .ok_or_else(|| {
                CalibrateError::Input(format!(
                    "knob `{first}`: no such value in the model (see calibrate::Knob)"
                ))
            }),
    }
}
