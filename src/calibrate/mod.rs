//! Calibration of a model's undisclosed values to published targets (issue 15, item 3):
//! natural frequencies and irregularity ratios per station and regime, fitted with the
//! diagnosis' bounded Levenberg–Marquardt ([`crate::diagnose::fit`]).
//!
//! A paper gives results, not every input. Seed 001 gives the 70 Sh rig's LP modes as a
//! share of an undisclosed f_max (Table 8(c)) and its simulated IR at three stations and
//! six regimes (Table 9), but neither the inertias, nor the speeds, nor the engine. The
//! values a user may free are named by their place in the model file ([`Knob`]); the
//! targets are [`Target`]s ([`evaluate`]: modes from the model's one causal system, IR
//! from its forced response, the frequency-domain twin of what `compare` measures in the
//! time domain). The fit is fast (milliseconds per evaluation); the caller checks the
//! time domain afterwards (`examples/seed001_tables.rs` does).

mod knobs;
mod targets;

pub use knobs::{Knob, parameter_value, set_parameter};
pub use targets::{Target, evaluate};

use crate::diagnose::fit::Bounds;
use crate::diagnose::multistart::{design, multistart};
use crate::model::Model;

/// Why a calibration could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CalibrateError {
    /// A knob or target names something the model does not have, or its bounds are bad.
    #[error("{0}")]
    Input(String),
    /// The model could not be evaluated at the start.
    #[error("the model cannot be evaluated at its start values: {0}")]
    Start(String),
}

/// The outcome: the calibrated model and how close it comes to each target.
#[derive(Debug, Clone, PartialEq)]
pub struct Calibration {
    /// The base model with the fitted knob values set.
    pub model: Model,
    /// Fitted value of each knob, in knob order.
    pub values: Vec<f64>,
    /// Achieved value of each target, in target order (Hz or %).
    pub achieved: Vec<f64>,
    /// Σ of squared normalized residuals at the fit.
    pub cost: f64,
    /// Model evaluations used.
    pub evaluations: usize,
}

/// Fits `knobs` of `base` so that the model meets `targets`: each residual is the
/// target's relative error over its tolerance, in the logarithm
/// (`ln(achieved/target)/(tolerance/100)`), so a factor too high and too low weigh alike.
/// Levenberg–Marquardt (at most `max_iterations` steps) runs from the base model's values
/// and from `design_starts` more points spread over the knobs' bounds (a Halton design in
/// `ln x`, deterministic), on `threads` threads; the lowest cost wins. A calibration to
/// published tables has many valleys (a mode matched from either neighbour, a resonance
/// placed on either side of a regime), so a single local fit is not enough.
pub fn calibrate(
    base: &Model,
    knobs: &[Knob],
    targets: &[Target],
    max_iterations: usize,
    design_starts: usize,
    threads: usize,
) -> Result<Calibration, CalibrateError> {
    let mut start = Vec::with_capacity(knobs.len());
    let mut bounds = Vec::with_capacity(knobs.len());
    for knob in knobs {
        if !(knob.lo > 0.0 && knob.hi > knob.lo && knob.hi.is_finite()) {
            return Err(CalibrateError::Input(format!(
                "knob `{}`: bounds {} … {} must satisfy 0 < lo < hi",
                knob.parameter, knob.lo, knob.hi
            )));
        }
        // Refuses an unknown name before any evaluation.
        set_parameter(&mut base.clone(), base, &knob.parameter, knob.lo)?;
        start.push(parameter_value(base, &knob.parameter)?.clamp(knob.lo, knob.hi));
        bounds.push(Bounds {
            lo: knob.lo,
            hi: knob.hi,
            log: true,
        });
    }
    if let Some(t) = targets
        .iter()
        .find(|t| !(t.value() > 0.0 && t.tolerance_pct() > 0.0))
    {
        return Err(CalibrateError::Input(format!(
            "target {t:?}: value and tolerance must be > 0"
        )));
    }
    let with = |x: &[f64]| -> Option<Model> {
        let mut m = base.clone();
        for (knob, v) in knobs.iter().zip(x) {
            set_parameter(&mut m, base, &knob.parameter, *v).ok()?;
        }
        Some(m)
    };
    let residuals = |x: &[f64]| -> Option<Vec<f64>> {
        let achieved = evaluate(&with(x)?, targets)?;
        Some(
            targets
                .iter()
                .zip(&achieved)
                .map(|(t, a)| (a / t.value()).ln() / (t.tolerance_pct() / 100.0))
                .collect(),
        )
    };
    let unit = Bounds {
        lo: 0.0,
        hi: 1.0,
        log: false,
    };
    let others: Vec<Vec<f64>> = design(knobs.len(), design_starts, &unit)
        .into_iter()
        .map(|u| {
            u.iter()
                .zip(&bounds)
                .map(|(u, b)| (b.lo.ln() + u * (b.hi / b.lo).ln()).exp())
                .collect()
        })
        .collect();
    let fits = multistart(
        &start,
        &others,
        &bounds,
        max_iterations,
        1e-9,
        threads,
        &residuals,
    );
    let (fit, _) = fits
        .into_iter()
        .next()
        .ok_or_else(|| CalibrateError::Start("a target could not be computed".into()))?;
    let model = with(&fit.x).ok_or_else(|| CalibrateError::Start("knobs".into()))?;
    let achieved = evaluate(&model, targets)
        .ok_or_else(|| CalibrateError::Start("the fitted model cannot be evaluated".into()))?;
    Ok(Calibration {
        model,
        values: fit.x,
        achieved,
        cost: fit.cost,
        evaluations: fit.evaluations,
    })
}
