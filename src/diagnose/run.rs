//! The diagnosis from end to end: observe, simulate the user's model, fit the plain
//! parameters, fit every candidate effect with them, score on held-out data, decide.

use super::candidates::{Candidate, candidates};
use super::fit::{Bounds, levenberg_marquardt};
use super::observe::{Observed, Regime, observe};
use super::residual::{chi2_per_point, z_scores};
use super::sensor::{self, TapeJoint};
use super::surrogate::{Plain, linear_predict, plain_parameters, ratios, scaled};
use super::{DiagnoseError, DiagnoseOptions, LabelledRecording, Report, forward, holdout};
use super::{decide, spread};
use crate::model::Model;
use crate::synth::Effect;

/// Plain parameters stay within ±30 % of the user's values.
const PLAIN_BOUNDS: Bounds = Bounds {
    lo: 0.7,
    hi: 1.3,
    log: true,
};
/// A priori spread of a plain parameter (its catalogue or drawing tolerance), as a
/// relative standard deviation: 10 %. It enters the fit as one residual `ln f / 0.1`
/// per factor and only matters along directions the recordings cannot tell apart (an
/// inertia and a stiffness scaled together keep every natural frequency).
const PLAIN_PRIOR: f64 = 0.1;
/// Rounds of linear fit and time-domain correction for the plain parameters.
const PLAIN_ROUNDS: usize = 6;
/// The same for a candidate, from the plain fit.
const CANDIDATE_ROUNDS: usize = 3;
/// Rounds stop when χ²/N on the fitted data improves by less than this fraction.
const ROUND_GAIN: f64 = 0.005;
/// Levenberg–Marquardt iterations on the surrogate, and on the time domain.
const SURROGATE_ITERATIONS: usize = 30;
const TIME_DOMAIN_ITERATIONS: usize = 3;

/// A model evaluated on every observation.
#[derive(Debug, Clone)]
pub struct Evaluated {
    /// The model.
    pub model: Model,
    /// Tape joint, for a sensor artifact.
    pub joint: Option<TapeJoint>,
    /// Simulated amplitudes as measured (time domain).
    pub simulated: Vec<f64>,
    /// z of every observation.
    pub z: Vec<f64>,
    /// Plain scale factors.
    pub factors: Vec<f64>,
    /// The effect's fitted value, if any.
    pub value: Option<f64>,
}

/// Everything a diagnosis needs while it runs.
pub struct Context<'a> {
    /// The recordings analysed.
    pub observed: Observed,
    /// Held-out observations.
    pub held_out: Vec<bool>,
    /// The user's model.
    pub user: &'a Model,
    /// Its plain parameters.
    pub plain: Vec<Plain>,
    /// Settings.
    pub options: &'a DiagnoseOptions,
}

impl Context<'_> {
    /// The time-domain amplitudes of `model` as the bench would measure them.
    pub fn simulate(
        &self,
        model: &Model,
        joint: Option<&TapeJoint>,
    ) -> Result<Vec<f64>, DiagnoseError> {
        let mut v = forward::predict(
            model,
            &self.observed,
            self.options.max_order,
            self.options.threads,
        )
        .map_err(|(label, message)| DiagnoseError::Simulation { label, message })?;
        for (x, f) in v
            .iter_mut()
            .zip(spread::spread_factors(model, &self.observed))
        {
            *x *= f;
        }
        sensor::measure(&self.observed, &ratios(model), joint, &mut v);
        Ok(v)
    }

    /// Evaluates `model` in the time domain.
    pub fn evaluate(
        &self,
        model: Model,
        joint: Option<TapeJoint>,
        factors: Vec<f64>,
        value: Option<f64>,
    ) -> Result<Evaluated, DiagnoseError> {
        let simulated = self.simulate(&model, joint.as_ref())?;
        let z = z_scores(&self.observed, &simulated);
        Ok(Evaluated {
            model,
            joint,
            simulated,
            z,
            factors,
            value,
        })
    }

    /// χ²/N of `e` on the fitted (`held = false`) or held-out observations.
    pub fn chi2(&self, e: &Evaluated, held: bool) -> f64 {
        let mask: Vec<bool> = self.held_out.iter().map(|h| *h == held).collect();
        chi2_per_point(&e.z, &mask)
    }

    /// The fitted observations' z for a surrogate prediction.
    fn fit_z(&self, predicted: &[f64]) -> Vec<f64> {
        z_scores(&self.observed, predicted)
            .into_iter()
            .zip(&self.held_out)
            .filter(|(_, h)| !**h)
            .map(|(z, _)| z)
            .collect()
    }

    /// Fits the plain factors (and, for a candidate the linear model represents, its
    /// parameter) on the surrogate around `at`, then runs the time domain there.
    pub fn fit_surrogate(
        &self,
        at: &Evaluated,
        candidate: Option<&Candidate>,
    ) -> Result<Evaluated, DiagnoseError> {
        let build = |x: &[f64]| -> Option<(Model, Option<TapeJoint>)> {
            let n = self.plain.len();
            let m = scaled(self.user, &self.plain, &x[..n]).ok()?;
            match candidate {
                Some(c) => c.apply(&m, x[n]).ok(),
                None => Some((m, None)),
            }
        };
        let mut start = at.factors.clone();
        let mut bounds = vec![PLAIN_BOUNDS; self.plain.len()];
        if let Some(c) = candidate {
            start.push(at.value.unwrap_or(c.param.start));
            bounds.push(Bounds {
                lo: c.param.lo,
                hi: c.param.hi,
                log: c.param.log,
            });
        }
        // The correction is taken where the time domain was run: at `at` itself.
        let f0 = linear_predict(&at.model, &self.observed, at.joint.as_ref());
        let correction: Vec<f64> = match &f0 {
            Some(f0) => at.simulated.iter().zip(f0).map(|(t, f)| t - f).collect(),
            None => vec![0.0; at.simulated.len()],
        };
        let mut residuals = |x: &[f64]| -> Option<Vec<f64>> {
            let (m, j) = build(x)?;
            let f = linear_predict(&m, &self.observed, j.as_ref())?;
            let s: Vec<f64> = f
                .iter()
                .zip(&correction)
                .map(|(a, d)| (a + d).max(0.0))
                .collect();
            let mut r = self.fit_z(&s);
            r.extend(x[..self.plain.len()].iter().map(|f| f.ln() / PLAIN_PRIOR));
            Some(r)
        };
        // A new effect starts from the best of a few values across its range (a local
        // mode, say, can sit on either side of a measured resonance).
        if let (Some(c), None) = (candidate, at.value) {
            let n = self.plain.len();
            let mut best = (f64::INFINITY, start[n]);
            for v in start_grid(&c.param) {
                let mut x = start.clone();
                x[n] = v;
                if let Some(r) = residuals(&x) {
                    let cost: f64 = r.iter().map(|v| v * v).sum();
                    if cost < best.0 {
                        best = (cost, v);
                    }
                }
            }
            start[n] = best.1;
        }
        let fit = levenberg_marquardt(&start, &bounds, SURROGATE_ITERATIONS, &mut residuals);
        let x = fit.map_or(start, |f| f.x);
        let (m, j) = build(&x).ok_or_else(|| DiagnoseError::Input("bad fit".into()))?;
        let n = self.plain.len();
        self.evaluate(m, j, x[..n].to_vec(), x.get(n).copied())
    }

    /// The one plain parameter that alone explains the most: each fitted by itself on the
    /// surrogate around `baseline`; returns its index, factor and χ²/N on the fitted
    /// data (surrogate).
    pub fn single_parameter(&self, baseline: &Evaluated) -> Option<(usize, f64, f64)> {
        let f0 = linear_predict(&baseline.model, &self.observed, None)?;
        let correction: Vec<f64> = baseline
            .simulated
            .iter()
            .zip(&f0)
            .map(|(t, f)| t - f)
            .collect();
        let mut best: Option<(usize, f64, f64)> = None;
        for i in 0..self.plain.len() {
            let fit =
                levenberg_marquardt(&[1.0], &[PLAIN_BOUNDS], SURROGATE_ITERATIONS, &mut |x| {
                    let mut factors = vec![1.0; self.plain.len()];
                    factors[i] = x[0];
                    let m = scaled(self.user, &self.plain, &factors).ok()?;
                    let f = linear_predict(&m, &self.observed, None)?;
                    let s: Vec<f64> = f
                        .iter()
                        .zip(&correction)
                        .map(|(a, d)| (a + d).max(0.0))
                        .collect();
                    Some(self.fit_z(&s))
                })?;
            let n = self.held_out.iter().filter(|h| !**h).count().max(1) as f64;
            let chi2 = fit.cost / n;
            if best.is_none_or(|b| chi2 < b.2) {
                best = Some((i, fit.x[0], chi2));
            }
        }
        best
    }

    /// Surrogate fits and time-domain runs, alternating from `start` until χ²/N on the
    /// fitted data gains less than [`ROUND_GAIN`] or `max` rounds are done.
    pub fn rounds(
        &self,
        start: Evaluated,
        candidate: Option<&Candidate>,
        max: usize,
    ) -> Result<Evaluated, DiagnoseError> {
        // A candidate's first round always counts when it adds the effect.
        let mut first = candidate.is_some() && start.value.is_none();
        let mut best = start;
        for _ in 0..max {
            let next = self.fit_surrogate(&best, candidate)?;
            let (old, new) = (self.chi2(&best, false), self.chi2(&next, false));
            if new < old || first {
                best = next;
            }
            first = false;
            if new >= old * (1.0 - ROUND_GAIN) {
                break;
            }
        }
        Ok(best)
    }

    /// Fits a candidate's parameter in the time domain with the plain factors of `at`.
    pub fn fit_time_domain(
        &self,
        at: &Evaluated,
        c: &Candidate,
    ) -> Result<Evaluated, DiagnoseError> {
        let base = scaled(self.user, &self.plain, &at.factors).map_err(DiagnoseError::Input)?;
        let bounds = [Bounds {
            lo: c.param.lo,
            hi: c.param.hi,
            log: c.param.log,
        }];
        let cheap = c.effect == Effect::SensorArtifact;
        let fit = levenberg_marquardt(
            &[c.param.start],
            &bounds,
            if cheap { 20 } else { TIME_DOMAIN_ITERATIONS },
            &mut |x| {
                let (m, j) = c.apply(&base, x[0]).ok()?;
                let simulated = if cheap {
                    let mut v = at.simulated.clone();
                    // Undo nothing: the artifact adds in power to the measured amplitudes.
                    sensor::add_joint(&self.observed, &ratios(&m), j.as_ref(), &mut v);
                    v
                } else {
                    self.simulate(&m, j.as_ref()).ok()?
                };
                Some(self.fit_z(&simulated))
            },
        );
        let value = fit.map_or(c.param.start, |f| f.x[0]);
        let (m, j) = c.apply(&base, value).map_err(DiagnoseError::Input)?;
        if cheap {
            let mut simulated = at.simulated.clone();
            sensor::add_joint(&self.observed, &ratios(&m), j.as_ref(), &mut simulated);
            let z = z_scores(&self.observed, &simulated);
            return Ok(Evaluated {
                model: m,
                joint: j,
                simulated,
                z,
                factors: at.factors.clone(),
                value: Some(value),
            });
        }
        self.evaluate(m, j, at.factors.clone(), Some(value))
    }
}

/// Start values to try for a parameter: its start and, spread over its range, values a
/// factor 3 apart (log) or at fifths of the range (linear).
fn start_grid(p: &super::candidates::Param) -> Vec<f64> {
    let mut out = vec![p.start];
    if p.log {
        for k in [-2, -1, 1, 2] {
            let v = p.start * 3f64.powi(k);
            if (p.lo..=p.hi).contains(&v) {
                out.push(v);
            }
        }
    } else {
        out.extend((0..=4).map(|k| p.lo + (p.hi - p.lo) * f64::from(k) / 4.0));
    }
    out
}

/// Does the linear model represent this effect (so the surrogate can fit it)?
fn linear_sees(effect: Effect) -> bool {
    !matches!(
        effect,
        Effect::CouplingThermalDrift | Effect::GearBacklash | Effect::SensorArtifact
    )
}

/// Diagnoses `recordings` against `model` (see the module docs of [`super`]).
pub fn diagnose(
    model: &Model,
    recordings: &[LabelledRecording],
    options: &DiagnoseOptions,
    progress: &mut dyn FnMut(f64, &str) -> bool,
) -> Result<Report, DiagnoseError> {
    let started = std::time::Instant::now();
    if recordings.is_empty() {
        return Err(DiagnoseError::Input("no recordings to diagnose".into()));
    }
    for r in recordings {
        for (node, _) in r.recording.speed_stations() {
            if model.node_index(node).is_none() {
                return Err(DiagnoseError::Input(format!(
                    "recording `{}`: station `{node}` is no node of the model",
                    r.label
                )));
            }
        }
    }
    let mut step = |f: f64, stage: &str| {
        if progress(f, stage) {
            Ok(())
        } else {
            Err(DiagnoseError::Cancelled)
        }
    };
    step(0.0, "analysing the recordings")?;
    let observed = observe(recordings, options.max_order)?;
    let held_out = holdout::held_out(&observed);
    let cx = Context {
        held_out,
        user: model,
        plain: plain_parameters(model),
        options,
        observed,
    };
    step(0.1, "simulating the model")?;
    let ones = vec![1.0; cx.plain.len()];
    let baseline = cx.evaluate(model.clone(), None, ones, None)?;
    step(0.2, "fitting the plain parameters")?;
    let plain_fit = cx.rounds(baseline.clone(), None, PLAIN_ROUNDS)?;
    let stations: Vec<String> = {
        let mut s: Vec<String> = cx
            .observed
            .runs
            .iter()
            .flat_map(|r| r.stations.clone())
            .collect();
        s.sort();
        s.dedup();
        s
    };
    let long_run = cx
        .observed
        .runs
        .iter()
        .any(|r| matches!(r.regime, Regime::LongRun { .. }));
    let list = candidates(model, &stations, long_run);
    let mut fitted: Vec<(Candidate, Evaluated)> = Vec::new();
    for (k, c) in list.iter().enumerate() {
        step(
            0.25 + 0.7 * k as f64 / list.len() as f64,
            &format!("fitting {}", c.name()),
        )?;
        let result = if linear_sees(c.effect) {
            cx.rounds(plain_fit.clone(), Some(c), CANDIDATE_ROUNDS)
        } else if c.effect == Effect::SensorArtifact {
            cx.fit_time_domain(&plain_fit, c)
        } else {
            // The effect's value in the time domain, then the plain parameters refitted
            // with the effect in place (the linear model cannot see it, the time domain's
            // correction carries it).
            cx.fit_time_domain(&plain_fit, c)
                .and_then(|e| cx.rounds(e, Some(c), CANDIDATE_ROUNDS - 1))
        };
        // A candidate whose model cannot be built or run is left out, not fatal.
        if let Ok(e) = result {
            fitted.push((c.clone(), e));
        }
    }
    // The plain fit gets the same further rounds a candidate had, so that no candidate
    // wins by a better-converged plain fit alone.
    step(0.95, "refining the plain parameters")?;
    let plain_fit = cx.rounds(plain_fit, None, CANDIDATE_ROUNDS)?;
    step(0.97, "deciding")?;
    let single = cx.single_parameter(&baseline);
    let report = decide::report(
        &cx,
        &baseline,
        &plain_fit,
        &fitted,
        single,
        started.elapsed().as_secs_f64(),
    );
    step(1.0, "done")?;
    Ok(report)
}
