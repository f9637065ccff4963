//! Calibration of a model's undisclosed values to published targets (issue 15, item 3):
//! natural frequencies and irregularity ratios per station and regime, fitted with the
//! diagnosis' bounded Levenberg–Marquardt ([`crate::diagnose::fit`]).
//!
//! A paper gives results, not every input. Seed 001 gives the 70 Sh rig's LP modes as a
//! share of an undisclosed f_max (Table 8(c)) and its simulated IR at three stations and
//! six regimes (Table 9), but neither the inertias, nor the speeds, nor the engine. The
//! values a user may free are named by their place in the model file ([`Knob`]); the
//! targets are [`Target`]s. Each evaluation builds the model's one causal system
//! ([`System::new`]): the modes come from [`modes`], the IR from the forced response's
//! synthesized waveform, `IR = 2·(half peak-to-peak IAS) / mean speed · 100 %` in the
//! station's own shaft — the frequency-domain twin of what `compare` measures in the time
//! domain (seed 001's IR, §3.5). The fit is fast (milliseconds per evaluation), and the
//! time domain is checked afterwards by the caller.

use crate::diagnose::fit::Bounds;
use crate::diagnose::multistart::{design, multistart};
use crate::modal::modes;
use crate::model::{ConnectionKind, HarmonicAmplitude, Model, RubberStiffness};
use crate::physics::{Excitation, OperatingPoint, System};
use crate::response::forced_response;

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

/// What the calibrated model must reproduce.
#[derive(Debug, Clone, PartialEq)]
pub enum Target {
    /// Natural frequency of flexible mode `mode` (from 1), Hz, within `tolerance_pct`
    /// (one standard deviation of the residual, %).
    ModeHz {
        /// Mode number, from 1 (rigid-body modes not counted).
        mode: usize,
        /// Target, Hz.
        hz: f64,
        /// Relative tolerance, %.
        tolerance_pct: f64,
    },
    /// Irregularity ratio of `station` at regime `regime` (a label of `[operation]
    /// regimes`), %, within `tolerance_pct` of itself.
    Irregularity {
        /// Node name.
        station: String,
        /// Regime label.
        regime: String,
        /// Target IR, %.
        pct: f64,
        /// Relative tolerance, %.
        tolerance_pct: f64,
    },
}

impl Target {
    fn tolerance_pct(&self) -> f64 {
        match self {
            Self::ModeHz { tolerance_pct, .. } | Self::Irregularity { tolerance_pct, .. } => {
                *tolerance_pct
            }
        }
    }

    fn value(&self) -> f64 {
        match self {
            Self::ModeHz { hz, .. } => *hz,
            Self::Irregularity { pct, .. } => *pct,
        }
    }
}

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
    match parameter {
        "engine.pressure_factor" if model.engine.is_some() => {
            if let Some(e) = model.engine.as_mut() {
                e.pressure_scale = Some(vec![value; e.cylinders as usize]);
            }
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
        _ => {
            *value_mut(model, parameter).ok_or_else(|| {
                CalibrateError::Input(format!(
                    "knob `{parameter}`: no such value in the model (see calibrate::Knob)"
                ))
            })? = value;
        }
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

/// The value of every target for `model`, in target order (Hz or %); `None` where the
/// model cannot be evaluated (a mode or a regime it does not have, a failed build).
pub fn evaluate(model: &Model, targets: &[Target]) -> Option<Vec<f64>> {
    let system = System::new(model, OperatingPoint::default()).ok()?;
    let needs_modes = targets.iter().any(|t| matches!(t, Target::ModeHz { .. }));
    let found = if needs_modes {
        modes(&system).ok()?
    } else {
        Vec::new()
    };
    let regimes = &model.operation.regimes;
    let speeds: Vec<f64> = regimes.iter().map(|r| r.speed_rpm).collect();
    let needs_ir = targets
        .iter()
        .any(|t| matches!(t, Target::Irregularity { .. }));
    let response = if needs_ir {
        let excitation = Excitation::new(model, &system, 1.0, &model.orders());
        Some(forced_response(&system, &excitation, &speeds).ok()?)
    } else {
        None
    };
    targets
        .iter()
        .map(|t| match t {
            Target::ModeHz { mode, .. } => found.get(mode.checked_sub(1)?).map(|m| m.frequency_hz),
            Target::Irregularity {
                station, regime, ..
            } => {
                let node = system.node_names.iter().position(|n| n == station)?;
                let s = regimes.iter().position(|r| &r.label == regime)?;
                let mean_rpm = (speeds[s] * system.speed_ratio[node]).abs();
                let half = response.as_ref()?.ias_half_peak_to_peak_rpm[node][s];
                Some(200.0 * half / mean_rpm)
            }
        })
        .collect()
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
