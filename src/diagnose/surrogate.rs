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
use super::spread::{factors_into, part_speeds};
use super::sweeps::CampaignSweeps;
use crate::effects::param_error::{parameter_names, scale_parameter};
use crate::model::Model;
use crate::physics::{OperatingPoint, System};

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
/// A steady run is compared at its regime's speed, a run-up bin at its own; the runs at
/// one load share one system and one sweep ([`super::sweeps`]).
pub fn linear_predict(
    model: &Model,
    observed: &Observed,
    joint: Option<&TapeJoint>,
) -> Option<Vec<f64>> {
    linear_predict_with(model, observed, joint, None)
}

/// [`linear_predict`], with the speed spread's factors `spread` (one per observation)
/// given instead of computed from `model` when `Some`.
fn linear_predict_with(
    model: &Model,
    observed: &Observed,
    joint: Option<&TapeJoint>,
    spread: Option<&[f64]>,
) -> Option<Vec<f64>> {
    let compared_at = |o: &super::observe::Observation| match observed.runs[o.run].regime {
        RunShape::Steady { speed_rpm } | RunShape::LongRun { speed_rpm } => speed_rpm,
        RunShape::Ramp { .. } => o.speed_rpm,
    };
    // The wobble's speeds, swept only when its factors are not given.
    let parts: Vec<Vec<Vec<f64>>> = match spread {
        Some(_) => Vec::new(),
        None => observed.runs.iter().map(part_speeds).collect(),
    };
    let sweeps = CampaignSweeps::new(model, observed, |r| {
        let mut speeds: Vec<f64> = observed
            .observations
            .iter()
            .filter(|o| o.run == r)
            .map(compared_at)
            .collect();
        if let Some(run_parts) = parts.get(r) {
            speeds.extend(run_parts.concat());
        }
        speeds
    });
    if (0..observed.runs.len()).any(|r| sweeps.system(r).is_none()) {
        return None;
    }
    let mut out = observed
        .observations
        .iter()
        .map(|o| sweeps.at(sweeps.find(o.run, &o.station, o.order)?, compared_at(o)))
        .collect::<Option<Vec<f64>>>()?;
    let computed;
    let factors = match spread {
        Some(f) => f,
        None => {
            let mut f = vec![1.0; out.len()];
            factors_into(observed, &parts, &sweeps, &mut f);
            computed = f;
            &computed
        }
    };
    for (v, f) in out.iter_mut().zip(factors) {
        *v *= f;
    }
    let ratios = sweeps
        .ratios_at_full_load()
        .unwrap_or_else(|| ratios(model));
    sensor::measure(observed, &ratios, joint, &mut out);
    Some(out)
}

/// The surrogate of a fit around its point `θ_k` (output space mapping, above):
/// `S(θ) = F(θ) + (T(θ_k) − F(θ_k))`, floored at zero.
///
/// During the search ([`Around::searched`]) the speed wobble's factors
/// ([`super::spread`]) are those of `θ_k`, held like the correction: they are a slow
/// correction of a few percent at most (within [`super::spread`]'s limit), and
/// recomputing them swept each steady part at 25 speeds, six sevenths of the points a
/// prediction solved (benchtruth campaigns: some 250 of 290). The point a search ends at
/// is scored with its own factors ([`Around::at`]), as before.
pub struct Around {
    /// `T(θ_k) − F(θ_k)` per observation, rpm (zero where the linear model cannot be
    /// built at `θ_k`).
    correction: Vec<f64>,
    /// The wobble's factors at `θ_k`, per observation.
    spread: Vec<f64>,
}

impl Around {
    /// The surrogate around `model` (`θ_k`), whose time-domain prediction is `simulated`.
    pub fn new(
        model: &Model,
        simulated: &[f64],
        observed: &Observed,
        joint: Option<&TapeJoint>,
    ) -> Self {
        let spread = super::spread::spread_factors(model, observed);
        // With θ_k's own factors this is `linear_predict` at θ_k, to the bit.
        let correction = match linear_predict_with(model, observed, joint, Some(&spread)) {
            Some(f0) => simulated.iter().zip(&f0).map(|(t, f)| t - f).collect(),
            None => vec![0.0; simulated.len()],
        };
        Self { correction, spread }
    }

    /// The surrogate at `model` during a search: θ_k's wobble factors.
    pub fn searched(
        &self,
        model: &Model,
        observed: &Observed,
        joint: Option<&TapeJoint>,
    ) -> Option<Vec<f64>> {
        let f = linear_predict_with(model, observed, joint, Some(&self.spread))?;
        Some(self.corrected(f))
    }

    /// The surrogate at `model`, the wobble factors its own: a search's result.
    pub fn at(
        &self,
        model: &Model,
        observed: &Observed,
        joint: Option<&TapeJoint>,
    ) -> Option<Vec<f64>> {
        let f = linear_predict(model, observed, joint)?;
        Some(self.corrected(f))
    }

    fn corrected(&self, f: Vec<f64>) -> Vec<f64> {
        f.iter()
            .zip(&self.correction)
            .map(|(a, d)| (a + d).max(0.0))
            .collect()
    }
}

#[cfg(test)]
#[path = "surrogate_tests.rs"]
mod tests;
