//! What a diagnosis holds while it runs, and the two ways it evaluates a model: the time
//! domain ([`super::forward`], what gets scored) and the linear surrogate
//! ([`super::surrogate`], what the fits move on).

use super::candidates::Candidate;
use super::fit::{Bounds, levenberg_marquardt};
use super::observe::Observed;
use super::residual::{chi2_per_point, z_scores};
use super::sensor::{self, TapeJoint};
use super::surrogate::{Around, Plain, ratios, scaled};
use super::{DiagnoseError, DiagnoseOptions, forward, spread};
use crate::model::Model;

/// Plain parameters stay within ±30 % of the user's values.
pub const PLAIN_BOUNDS: Bounds = Bounds {
    lo: 0.7,
    hi: 1.3,
    log: true,
};
/// A priori spread of a plain parameter (its catalogue or drawing tolerance), as a
/// relative standard deviation: 10 %. It enters the fit as one residual
/// `w·ln f / 0.1` per factor ([`Context::prior_weight`] `w`) and only matters along
/// directions the recordings cannot tell apart (an inertia and a stiffness scaled
/// together keep every natural frequency).
pub(super) const PLAIN_PRIOR: f64 = 0.1;
/// Levenberg–Marquardt iterations on the surrogate, and the relative gain of the cost
/// under which a fit stops.
pub(super) const SURROGATE_ITERATIONS: usize = 30;
pub(super) const SURROGATE_TOLERANCE: f64 = 1e-4;

/// A model evaluated on every observation.
#[derive(Debug, Clone)]
pub struct Evaluated {
    /// The model.
    pub model: Model,
    /// Tape joint, for a sensor artifact.
    pub joint: Option<TapeJoint>,
    /// Simulated amplitudes as measured (time domain, or the surrogate for a
    /// [`Proposal`]'s screening).
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
    /// Weight of the plain parameters' prior against the data, `√max(1, F)` with `F` the
    /// fitted χ²/N the plain fit reaches with weight 1 (the campaign's model floor); 1
    /// before that fit. Where the model cannot fit the data to their noise, the misfit is
    /// model error, not noise: weighing it with the noise's σ lets a fit buy a little of
    /// it with large, implausible parameter changes (every inertia and stiffness at −30 %,
    /// benchtruth 1009; one mass at +30 %, control 1035). Scaling the data's σ by the
    /// Birge ratio `√F` is the standard correction (Birge 1932; Press et al., *Numerical
    /// Recipes*, §15.1); weighting the prior by `√F` instead gives the same minimum and
    /// keeps χ² in the noise's units.
    pub prior_weight: f64,
    /// Recordings the user's model cannot simulate, by label, left out of `observed`
    /// ([`super::unsimulable`]).
    pub set_aside: Vec<super::unsimulable::SetAside>,
    /// Why `held_out` is the other fold, when it is ([`super::holdout::swap_reason`]).
    pub swapped_because: Option<String>,
    /// Mesh dampings added to the user's model, which `user` then carries
    /// ([`super::mesh_damping`]).
    pub mesh_damping: Option<super::mesh_damping::Added>,
}

impl<'a> Context<'a> {
    /// The context of a diagnosis of `observed` against `user`: its held-out split
    /// ([`super::holdout::held_out`]), the model's plain parameters, and the prior's
    /// weight 1 (until the plain fit has measured the floor).
    pub fn new(user: &'a Model, options: &'a DiagnoseOptions, observed: Observed) -> Self {
        Self {
            held_out: super::holdout::held_out(&observed),
            user,
            plain: super::surrogate::plain_parameters(user),
            options,
            observed,
            prior_weight: 1.0,
            set_aside: Vec::new(),
            swapped_because: None,
            mesh_damping: None,
        }
    }
}

impl Context<'_> {
    /// The time-domain amplitudes of `model` as the bench would measure them. With
    /// `only = Some((runs, fill))` just the runs flagged are simulated and every other
    /// observation is taken from `fill` (a cheaper evaluation for a fit that only moves
    /// those runs).
    pub fn simulate(
        &self,
        model: &Model,
        joint: Option<&TapeJoint>,
        only: Option<(&[bool], &[f64])>,
    ) -> Result<Vec<f64>, DiagnoseError> {
        let mut v = forward::predict(
            model,
            &self.observed,
            self.options.max_order,
            self.options.threads,
            only.map(|(runs, _)| runs),
        )
        .map_err(|(label, message)| DiagnoseError::Simulation { label, message })?;
        for (x, f) in v
            .iter_mut()
            .zip(spread::spread_factors(model, &self.observed))
        {
            *x *= f;
        }
        sensor::measure(&self.observed, &ratios(model), joint, &mut v);
        if let Some((runs, fill)) = only {
            for ((x, o), f) in v.iter_mut().zip(&self.observed.observations).zip(fill) {
                if !runs.get(o.run).copied().unwrap_or(false) {
                    *x = *f;
                }
            }
        }
        Ok(v)
    }

    /// `simulated` with its z-scores.
    pub fn scored(
        &self,
        model: Model,
        joint: Option<TapeJoint>,
        simulated: Vec<f64>,
        factors: Vec<f64>,
        value: Option<f64>,
    ) -> Evaluated {
        let z = z_scores(&self.observed, &simulated);
        Evaluated {
            model,
            joint,
            simulated,
            z,
            factors,
            value,
        }
    }

    /// Evaluates `model` in the time domain.
    pub fn evaluate(
        &self,
        model: Model,
        joint: Option<TapeJoint>,
        factors: Vec<f64>,
        value: Option<f64>,
    ) -> Result<Evaluated, DiagnoseError> {
        let simulated = self.simulate(&model, joint.as_ref(), None)?;
        Ok(self.scored(model, joint, simulated, factors, value))
    }

    /// χ²/N of `e` on the fitted (`held = false`) or held-out observations.
    pub fn chi2(&self, e: &Evaluated, held: bool) -> f64 {
        let mask: Vec<bool> = self.held_out.iter().map(|h| *h == held).collect();
        chi2_per_point(&e.z, &mask)
    }

    /// Fitted observations.
    pub fn n_fitted(&self) -> usize {
        self.held_out.iter().filter(|h| !**h).count().max(1)
    }

    /// The fitted observations' z for a prediction.
    pub fn fit_z(&self, predicted: &[f64]) -> Vec<f64> {
        z_scores(&self.observed, predicted)
            .into_iter()
            .zip(&self.held_out)
            .filter(|(_, h)| !**h)
            .map(|(z, _)| z)
            .collect()
    }

    /// The sum of squared z-scores of `predicted` over the fitted observations: what
    /// the fits minimise (without the plain parameters' prior).
    pub fn fit_cost(&self, predicted: &[f64]) -> f64 {
        self.fit_z(predicted).iter().map(|z| z * z).sum()
    }

    /// The surrogate around `at` ([`Around`]).
    pub(super) fn around(&self, at: &Evaluated) -> Around {
        Around::new(&at.model, &at.simulated, &self.observed, at.joint.as_ref())
    }

    /// Fits, on the surrogate around `at`, the plain factors `free` (the others stay at
    /// `at`'s) and, for a candidate the linear model represents ([`super::screen::
    /// linear_sees`]), its parameter; another candidate's stays at `at`'s value. Returns
    /// the fitted point with the surrogate's prediction in `simulated` (no time domain).
    pub fn propose(
        &self,
        at: &Evaluated,
        candidate: Option<&Candidate>,
        free: &[usize],
    ) -> Result<Evaluated, DiagnoseError> {
        self.propose_within(at, candidate, free, SURROGATE_ITERATIONS)
    }

    /// [`Self::propose`] in at most `iterations` Levenberg–Marquardt steps.
    pub fn propose_within(
        &self,
        at: &Evaluated,
        candidate: Option<&Candidate>,
        free: &[usize],
        iterations: usize,
    ) -> Result<Evaluated, DiagnoseError> {
        let full = |x: &[f64]| -> Vec<f64> {
            let mut f = at.factors.clone();
            for (k, i) in free.iter().enumerate() {
                f[*i] = x[k];
            }
            f
        };
        // An effect screened in the time domain keeps the value found there, out of the
        // fitted vector: the surrogate is blind to it (backlash) or sees only its tangent
        // at the static twist (an amplitude law set by the vibration).
        let pinned = candidate
            .filter(|c| !super::screen::linear_sees(c))
            .and(at.value);
        let value_of = |x: &[f64]| pinned.or_else(|| x.get(free.len()).copied());
        let build = |x: &[f64]| -> Option<(Model, Option<TapeJoint>)> {
            let m = scaled(self.user, &self.plain, &full(x)).ok()?;
            match candidate {
                Some(c) => c.apply(&m, value_of(x)?).ok(),
                None => Some((m, at.joint.clone())),
            }
        };
        let mut start: Vec<f64> = free.iter().map(|i| at.factors[*i]).collect();
        let mut bounds = vec![PLAIN_BOUNDS; free.len()];
        if let (Some(c), None) = (candidate, pinned) {
            start.push(at.value.unwrap_or(c.param.start));
            bounds.push(super::branch::fit_bounds(c, at.value));
        }
        let around = self.around(at);
        let predict = |x: &[f64]| -> Option<Vec<f64>> {
            let (m, j) = build(x)?;
            around.searched(&m, &self.observed, j.as_ref())
        };
        let residuals = |x: &[f64]| -> Option<Vec<f64>> {
            let mut r = self.fit_z(&predict(x)?);
            r.extend(
                full(x)
                    .iter()
                    .map(|f| self.prior_weight * f.ln() / PLAIN_PRIOR),
            );
            Some(r)
        };
        // A new effect starts from the best of a few values across its range (a local
        // mode, say, can sit on either side of a measured resonance).
        if let (Some(c), None) = (candidate, at.value) {
            let k = free.len();
            let mut best = (f64::INFINITY, start[k]);
            for v in start_grid(&c.param) {
                let mut x = start.clone();
                x[k] = v;
                if let Some(r) = residuals(&x) {
                    let cost: f64 = r.iter().map(|v| v * v).sum();
                    if cost < best.0 {
                        best = (cost, v);
                    }
                }
            }
            start[k] = best.1;
        }
        let x = levenberg_marquardt(
            &start,
            &bounds,
            iterations,
            SURROGATE_TOLERANCE,
            self.options.threads,
            &residuals,
        )
        .map_or(start, |f| f.x);
        let (m, j) = build(&x).ok_or_else(|| DiagnoseError::Input("bad fit".into()))?;
        let simulated = around
            .at(&m, &self.observed, j.as_ref())
            .ok_or_else(|| DiagnoseError::Input("bad fit".into()))?;
        let factors = full(&x);
        let value = candidate.and_then(|_| value_of(&x));
        Ok(self.scored(m, j, simulated, factors, value))
    }

    /// The one plain parameter that alone explains the most: each fitted by itself on the
    /// surrogate around `baseline`; returns its index, factor and χ²/N on the fitted
    /// data (surrogate).
    pub fn single_parameter(&self, baseline: &Evaluated) -> Option<(usize, f64, f64)> {
        // Each parameter's fit on its own thread, in order (the first of equal minima wins,
        // as in a loop).
        let fits: Vec<Option<(usize, f64, f64)>> =
            super::fit::parallel_map(self.plain.len(), self.options.threads, &|i| {
                let e = self.propose(baseline, None, &[i]).ok()?;
                // The prior's residual is not part of the data's χ².
                let z = self.fit_z(&e.simulated);
                let chi2 = z.iter().map(|v| v * v).sum::<f64>() / self.n_fitted() as f64;
                Some((i, e.factors[i], chi2))
            });
        fits.into_iter()
            .flatten()
            .min_by(|a, b| a.2.total_cmp(&b.2))
    }
}

/// Start values to try for a parameter: its start and, spread over its range, values a
/// factor √3 apart up to 9 times either way (log), or at eighths of the range (linear).
/// The surrogate makes them cheap, and a local mode's valley is narrow: on the reference
/// `unmodelled_mode` campaign a factor 3 between starts stepped over it.
/// A [`super::param::Param::resonance`] instead tries every value
/// [`super::param::RESONANCE_START_STEP`] apart from its lower to its upper bound.
fn start_grid(p: &super::param::Param) -> Vec<f64> {
    let mut out = vec![p.start];
    if p.resonance && p.lo > 0.0 && p.hi > p.lo {
        let step = super::param::RESONANCE_START_STEP;
        let n = ((p.hi / p.lo).ln() / step.ln()).floor().min(200.0) as i32;
        out.extend((0..=n).map(|k| p.lo * step.powi(k)));
        return out;
    }
    if p.log {
        for k in [-4, -3, -2, -1, 1, 2, 3, 4] {
            let v = p.start * 3f64.powf(0.5 * f64::from(k));
            if (p.lo..=p.hi).contains(&v) {
                out.push(v);
            }
        }
    } else {
        out.extend((0..=8).map(|k| p.lo + (p.hi - p.lo) * f64::from(k) / 8.0));
    }
    out
}
