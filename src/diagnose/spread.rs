//! The bench's slow wobble of the mean speed, carried to the simulated amplitudes.
//!
//! A steady regime on a bench is not quite steady: the mean speed drifts by a few tenths
//! of a percent within the record. Near a resonance an order's amplitude changes by
//! several percent per ten rpm, and the synchronous average of the record averages the
//! amplitude over the speeds it went through, not its value at the mean speed. The
//! simulation runs at the mean speed; this factor, from the linear frequency-domain
//! model ([`crate::response`]), scales it to the mean over the measured cycle speeds:
//! `mean_c A(n_c) / A(n̄)`.

use super::observe::{Observed, Run, RunShape};
use super::sweeps::CampaignSweeps;
use crate::model::Model;

/// Most cycle speeds evaluated per record (quantiles of the measured ones).
const MAX_SPEEDS: usize = 24;
/// The factor stays within `[1/LIMIT, LIMIT]`.
const LIMIT: f64 = 1.5;

/// `n` quantiles of `values` (sorted copy), or all of them when fewer.
fn quantiles(values: &[f64], n: usize) -> Vec<f64> {
    let mut v: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
    v.sort_by(f64::total_cmp);
    if v.len() <= n {
        return v;
    }
    (0..n)
        .map(|k| v[((k as f64 + 0.5) / n as f64 * v.len() as f64) as usize])
        .collect()
}

/// Per observation: the factor from the amplitude at the mean speed to its mean over the
/// measured cycle speeds (1 for run-ups, and where the linear model cannot be built).
pub fn spread_factors(model: &Model, observed: &Observed) -> Vec<f64> {
    let parts: Vec<_> = observed.runs.iter().map(part_speeds).collect();
    let sweeps = CampaignSweeps::new(model, observed, |r| parts[r].concat());
    let mut factors = vec![1.0; observed.observations.len()];
    factors_into(observed, &parts, &sweeps, &mut factors);
    factors
}

/// The speeds each part of a steady run is evaluated at, rpm: its mean, then
/// [`MAX_SPEEDS`] quantiles of its measured cycle speeds; empty for a part with no cycle
/// speeds and for a run-up.
pub(super) fn part_speeds(run: &Run) -> Vec<Vec<f64>> {
    let mean = match run.regime {
        RunShape::Steady { speed_rpm } | RunShape::LongRun { speed_rpm } => speed_rpm,
        RunShape::Ramp { .. } => return Vec::new(),
    };
    run.cycle_speeds_rpm
        .iter()
        .map(|cycles| {
            let mut speeds = vec![mean];
            speeds.extend(quantiles(cycles, MAX_SPEEDS));
            if speeds.len() < 2 {
                speeds.clear();
            }
            speeds
        })
        .collect()
}

/// The orders observed in run `r`, sorted, each once.
pub(super) fn run_orders(observed: &Observed, r: usize) -> Vec<f64> {
    let mut orders: Vec<f64> = observed
        .observations
        .iter()
        .filter(|o| o.run == r)
        .map(|o| o.order)
        .collect();
    orders.sort_by(f64::total_cmp);
    orders.dedup();
    orders
}

/// [`spread_factors`] into `factors`, from each run's [`part_speeds`] (`parts[run]`) and
/// the campaign's linear sweeps, which hold them all. A part one of whose speeds could
/// not be solved is left at 1.
pub(super) fn factors_into(
    observed: &Observed,
    parts: &[Vec<Vec<f64>>],
    sweeps: &CampaignSweeps,
    factors: &mut [f64],
) {
    for (r, run_parts) in parts.iter().enumerate() {
        for (part, speeds) in run_parts.iter().enumerate() {
            if speeds.is_empty() {
                continue;
            }
            for (i, o) in observed.observations.iter().enumerate() {
                if o.run != r || o.part != part {
                    continue;
                }
                let Some(found) = sweeps.find(r, &o.station, o.order) else {
                    continue;
                };
                let a: Option<Vec<f64>> = speeds.iter().map(|v| sweeps.at(found, *v)).collect();
                let Some(a) = a else {
                    continue;
                };
                let at_mean = a[0];
                let largest = a.iter().fold(0.0_f64, |m, x| m.max(*x));
                if at_mean > 1e-6 * largest.max(1e-12) && at_mean > 1e-9 {
                    let spread = a[1..].iter().sum::<f64>() / (a.len() - 1) as f64;
                    factors[i] = (spread / at_mean).clamp(1.0 / LIMIT, LIMIT);
                }
            }
        }
    }
}
