//! The signatures the detectability analysis works on (issue 14, item 6): for a planned
//! campaign ([`super::power_plan`]), the change of every observable that one candidate
//! effect at one size makes, and the sensitivities of the plain parameters.
//!
//! Evaluated like the diagnosis' fits evaluate them: on the linear surrogate
//! ([`super::surrogate::linear_predict`], milliseconds) for every effect the linear model
//! represents and for sensor artifacts (a measurement effect, applied to any prediction);
//! in the time domain ([`super::forward`]) for the two it does not (thermal drift: the
//! long runs only, where it shows; gear backlash: the steady regimes and long runs — the
//! run-up is left out of its signature to keep the analysis under a minute, which can
//! only understate what the campaign sees of it).

use super::candidates::Candidate;
use super::context::PLAIN_BOUNDS;
use super::observe::{Observed, RunShape};
use super::power_fisher::Column;
use super::power_size::EffectSize;
use super::residual::{FLOOR, FLOOR_RUN_UP, expected};
use super::surrogate::{Plain, linear_predict, plain_parameters, ratios, scaled};
use super::{forward, sensor, spread};
use crate::effects::Effect;
use crate::model::Model;

/// Relative step of a plain parameter's factor for its sensitivity (central
/// differences in `ln f`; the linear model is smooth there, round-off is ~1e-12).
const PLAIN_STEP: f64 = 1e-3;
/// Prior precision of a plain parameter's `ln f`: the diagnosis' 10 % prior
/// ([`super::context`]), 1/0.1².
const PLAIN_PRIOR_PRECISION: f64 = 100.0;

/// A planned campaign with what every signature is measured against.
pub struct Evaluator<'a> {
    /// The user's model.
    pub model: &'a Model,
    /// The planned observables (`measured_rpm`: the user's model, surrogate).
    pub observed: Observed,
    /// `1/σ²` of every observable, with the diagnosis' model floor
    /// ([`super::residual`]).
    pub weights: Vec<f64>,
    /// The plain parameters and their sensitivities (per unit `ln f`, with the prior).
    pub plain: Vec<(Plain, Column)>,
    /// Highest order, for the time domain.
    pub max_order: f64,
    /// Threads of the time domain.
    pub threads: usize,
}

/// The expected *measured* amplitudes of simulated ones `v`: an order amplitude is a
/// magnitude, biased up by the noise ([`super::residual::expected`]), so an effect whose
/// change stays under the noise moves it only to second order. Signatures are taken in
/// this space, as the diagnosis compares.
pub fn expected_all(observed: &Observed, v: Vec<f64>) -> Vec<f64> {
    v.into_iter()
        .zip(&observed.observations)
        .map(|(a, o)| expected(a, o.bias_sigma_rpm))
        .collect()
}

/// Does the analysis evaluate `effect` in the time domain? Thermal drift and backlash,
/// which the linear model cannot represent. An amplitude law, which the diagnosis screens
/// in the time domain in its elastic form, is sized here on the linear model's tangent at
/// the static twist: the analysis must stay under a minute, and that is the size a test
/// plan can change (the static twist a load puts on the coupling).
pub fn in_time_domain(effect: Effect) -> bool {
    matches!(effect, Effect::CouplingThermalDrift | Effect::GearBacklash)
}

impl<'a> Evaluator<'a> {
    /// The evaluator of `observed` on `model`; `None` when the linear model cannot be
    /// built.
    pub fn new(
        model: &'a Model,
        mut observed: Observed,
        max_order: f64,
        threads: usize,
    ) -> Option<Self> {
        let base = linear_predict(model, &observed, None)?;
        for (o, a) in observed.observations.iter_mut().zip(&base) {
            o.measured_rpm = *a;
        }
        let weights = observed
            .observations
            .iter()
            .map(|o| {
                let floor = match observed.runs[o.run].regime {
                    RunShape::Ramp { .. } => FLOOR_RUN_UP,
                    _ => FLOOR,
                };
                1.0 / (o.sigma_rpm.powi(2) + (floor * o.measured_rpm).powi(2))
            })
            .collect();
        let names = plain_parameters(model);
        let mut plain = Vec::with_capacity(names.len());
        for k in 0..names.len() {
            let at = |f: f64| {
                let mut factors = vec![1.0; names.len()];
                factors[k] = f.clamp(PLAIN_BOUNDS.lo, PLAIN_BOUNDS.hi);
                let m = scaled(model, &names, &factors).ok()?;
                linear_predict(&m, &observed, None).map(|v| expected_all(&observed, v))
            };
            let (Some(up), Some(down)) = (at(PLAIN_STEP.exp()), at((-PLAIN_STEP).exp())) else {
                continue;
            };
            let values = up
                .iter()
                .zip(&down)
                .map(|(u, d)| (u - d) / (2.0 * PLAIN_STEP))
                .collect();
            let column = Column {
                values,
                prior: PLAIN_PRIOR_PRECISION,
            };
            plain.push((names[k].clone(), column));
        }
        Some(Self {
            model,
            observed,
            weights,
            plain,
            max_order,
            threads,
        })
    }

    /// The plain parameters' columns.
    pub fn plain_columns(&self) -> Vec<&Column> {
        self.plain.iter().map(|(_, c)| c).collect()
    }

    /// The runs a time-domain effect's signature is simulated on.
    fn wanted(&self, effect: Effect) -> Vec<bool> {
        self.observed
            .runs
            .iter()
            .map(|r| match (effect, &r.regime) {
                (Effect::CouplingThermalDrift, RunShape::LongRun { .. }) => true,
                (Effect::CouplingThermalDrift, _) => false,
                (_, RunShape::Ramp { .. }) => false,
                _ => true,
            })
            .collect()
    }

    /// The observables of `model` (with a tape `joint`), on the surrogate or, with
    /// `wanted`, in the time domain of those runs (the others 0).
    fn predict(
        &self,
        model: &Model,
        joint: Option<&super::sensor::TapeJoint>,
        wanted: Option<&[bool]>,
    ) -> Option<Vec<f64>> {
        let Some(wanted) = wanted else {
            return linear_predict(model, &self.observed, joint)
                .map(|v| expected_all(&self.observed, v));
        };
        let mut v = forward::predict(
            model,
            &self.observed,
            self.max_order,
            self.threads,
            Some(wanted),
        )
        .ok()?;
        for (x, f) in v
            .iter_mut()
            .zip(spread::spread_factors(model, &self.observed))
        {
            *x *= if f.is_finite() { f } else { 1.0 };
        }
        sensor::measure(&self.observed, &ratios(model), joint, &mut v);
        Some(expected_all(&self.observed, v))
    }

    /// What candidate `c` is measured against: the effect at its null value where it
    /// builds, else the user's model.
    pub fn reference(&self, c: &Candidate, size: &EffectSize) -> Option<Vec<f64>> {
        let wanted = in_time_domain(c.effect).then(|| self.wanted(c.effect));
        let built = size.null_value().and_then(|v| c.apply(self.model, v).ok());
        match built {
            Some((m, j)) => self.predict(&m, j.as_ref(), wanted.as_deref()),
            None => self.predict(self.model, None, wanted.as_deref()),
        }
    }

    /// The change of every observable that `c` at size `s` makes against `reference`.
    pub fn signature(
        &self,
        c: &Candidate,
        size: &EffectSize,
        s: f64,
        reference: &[f64],
    ) -> Option<Vec<f64>> {
        let (m, joint) = c.apply(self.model, size.value(s)).ok()?;
        let wanted = in_time_domain(c.effect).then(|| self.wanted(c.effect));
        let v = self.predict(&m, joint.as_ref(), wanted.as_deref())?;
        let d: Vec<f64> = v.iter().zip(reference).map(|(a, b)| a - b).collect();
        d.iter().all(|x| x.is_finite()).then_some(d)
    }
}
