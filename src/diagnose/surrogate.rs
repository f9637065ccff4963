//! The fast stand-in for the time domain during a fit, and the plain parameters.
//!
//! Output space mapping: the linear frequency-domain model ([`crate::response`]) at each
//! observation's speed and load, plus the difference the time domain had from it at the
//! last point where both were run: `S(θ) = F(θ) + (T(θ_k) − F(θ_k))`. It is exact at
//! `θ_k` and carries the linear model's sensitivities around it; every fit ends with a
//! time-domain run at its result, which is what gets scored.
//!
//! The plain parameters are every inertia and every stiffness of the model
//! ([`crate::effects::param_error::parameter_names`]), fitted as scale factors.

use super::observe::{Observed, RunShape};
use super::sensor::{self, TapeJoint};
use super::spread::{run_factors, run_orders};
use crate::effects::param_error::{parameter_names, scale_parameter};
use crate::model::Model;
use crate::physics::{Excitation, OperatingPoint, System};
use crate::response::forced_response_orders;

/// A plain parameter: its full name (`connection.shaft.stiffness`) and the node or
/// connection it belongs to.
#[derive(Debug, Clone, PartialEq)]
pub struct Plain {
    /// Full name.
    pub name: String,
    /// Node or connection name.
    pub target: String,
}

/// The plain parameters of `model`.
pub fn plain_parameters(model: &Model) -> Vec<Plain> {
    parameter_names(model)
        .into_iter()
        .map(|name| {
            let target = name
                .strip_prefix("inertia.")
                .or_else(|| name.strip_prefix("connection."))
                .map(|rest| rest.split('.').next().unwrap_or(rest).to_string())
                .unwrap_or_default();
            Plain { name, target }
        })
        .collect()
}

/// `model` with every plain parameter times its factor.
pub fn scaled(model: &Model, plain: &[Plain], factors: &[f64]) -> Result<Model, String> {
    let mut m = model.clone();
    for (p, f) in plain.iter().zip(factors) {
        if *f != 1.0 {
            scale_parameter(&mut m, &p.target, *f).map_err(|e| e.to_string())?;
        }
    }
    Ok(m)
}

/// The speeds a run covers, rpm: `[lo, hi]`.
pub fn run_speeds(observed: &Observed, run: usize) -> [f64; 2] {
    match observed.runs[run].regime {
        RunShape::Steady { speed_rpm } | RunShape::LongRun { speed_rpm } => [speed_rpm, speed_rpm],
        RunShape::Ramp { from_rpm, to_rpm } => [from_rpm.min(to_rpm), from_rpm.max(to_rpm)],
    }
}

/// The linear system of `model` at `load`: every rubber stage as the time domain
/// represents it, its one causal chain ([`System::new`], [`crate::rubber`]).
pub fn causal_system(model: &Model, load: f64) -> Option<System> {
    let point = OperatingPoint {
        load,
        temperature_c: None,
    };
    System::new(model, point).ok()
}

/// The user's value of the plain parameter `name` (full name), if it exists.
pub fn value_of(model: &Model, name: &str) -> Option<f64> {
    let target = plain_parameters(model)
        .into_iter()
        .find(|p| p.name == name)?
        .target;
    let mut copy = model.clone();
    scale_parameter(&mut copy, &target, 1.0)
        .ok()
        .map(|e| e.user_value)
}

/// Each node's mean speed over the reference's.
pub fn ratios(model: &Model) -> Vec<(String, f64)> {
    System::new(model, OperatingPoint::default())
        .map(|s| s.node_names.into_iter().zip(s.speed_ratio).collect())
        .unwrap_or_default()
}

/// The linear model's amplitude of every observation, with the speed spread and the
/// sensors applied like the time domain's (`None` when the model cannot be built).
pub fn linear_predict(
    model: &Model,
    observed: &Observed,
    joint: Option<&TapeJoint>,
) -> Option<Vec<f64>> {
    let mut out = vec![0.0; observed.observations.len()];
    // The speed spread's factors ([`super::spread`]) come from the same system and
    // excitation of each run, built once here for both.
    let mut factors = vec![1.0; observed.observations.len()];
    for (r, run) in observed.runs.iter().enumerate() {
        let system = causal_system(model, run.load)?;
        let mine: Vec<usize> = (0..out.len())
            .filter(|i| observed.observations[*i].run == r)
            .collect();
        let orders = run_orders(observed, r);
        let mut speeds: Vec<f64> = match run.regime {
            RunShape::Steady { speed_rpm } | RunShape::LongRun { speed_rpm } => vec![speed_rpm],
            RunShape::Ramp { .. } => mine
                .iter()
                .map(|i| observed.observations[*i].speed_rpm)
                .collect(),
        };
        speeds.sort_by(f64::total_cmp);
        speeds.dedup();
        let excitation = Excitation::new(model, &system, run.load, &orders);
        let response = forced_response_orders(&system, &excitation, &speeds).ok()?;
        for i in mine {
            let o = &observed.observations[i];
            let node = system.node_names.iter().position(|n| *n == o.station)?;
            let q = orders.iter().position(|x| (x - o.order).abs() < 1e-9)?;
            let s = speeds
                .iter()
                .position(|v| (v - o.speed_rpm).abs() < 1e-9)
                .unwrap_or(0);
            out[i] = response.ias_amplitude_rpm[node][q][s];
        }
        run_factors(observed, r, &system, &excitation, &orders, &mut factors);
    }
    for (v, f) in out.iter_mut().zip(factors) {
        *v *= f;
    }
    sensor::measure(observed, &ratios(model), joint, &mut out);
    Some(out)
}
