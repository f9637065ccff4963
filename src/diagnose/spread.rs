//! The bench's slow wobble of the mean speed, carried to the simulated amplitudes.
//!
//! A steady regime on a bench is not quite steady: the mean speed drifts by a few tenths
//! of a percent within the record. Near a resonance an order's amplitude changes by
//! several percent per ten rpm, and the synchronous average of the record averages the
//! amplitude over the speeds it went through, not its value at the mean speed. The
//! simulation runs at the mean speed; this factor, from the linear frequency-domain
//! model ([`crate::response`]), scales it to the mean over the measured cycle speeds:
//! `mean_c A(n_c) / A(n̄)`.

use super::observe::{Observed, RunShape};
use super::surrogate::causal_system;
use crate::model::Model;
use crate::physics::{Excitation, System};
use crate::response::forced_response_orders;

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
    let mut factors = vec![1.0; observed.observations.len()];
    for (r, run) in observed.runs.iter().enumerate() {
        if matches!(run.regime, RunShape::Ramp { .. }) {
            continue;
        }
        let Some(system) = causal_system(model, run.load) else {
            continue;
        };
        let orders = run_orders(observed, r);
        let excitation = Excitation::new(model, &system, run.load, &orders);
        run_factors(observed, r, &system, &excitation, &orders, &mut factors);
    }
    factors
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

/// [`spread_factors`] of run `r` into `factors`, with the run's linear system and its
/// excitation at `orders` ([`run_orders`]) already built (the linear model's prediction
/// builds the same ones, [`super::surrogate::linear_predict`]). A run-up is left alone.
pub(super) fn run_factors(
    observed: &Observed,
    r: usize,
    system: &System,
    excitation: &Excitation,
    orders: &[f64],
    factors: &mut [f64],
) {
    let run = &observed.runs[r];
    let mean = match run.regime {
        RunShape::Steady { speed_rpm } | RunShape::LongRun { speed_rpm } => speed_rpm,
        RunShape::Ramp { .. } => return,
    };
    for (part, cycles) in run.cycle_speeds_rpm.iter().enumerate() {
        let mut speeds = vec![mean];
        speeds.extend(quantiles(cycles, MAX_SPEEDS));
        if speeds.len() < 2 {
            continue;
        }
        let Ok(response) = forced_response_orders(system, excitation, &speeds) else {
            continue;
        };
        for (i, o) in observed.observations.iter().enumerate() {
            if o.run != r || o.part != part {
                continue;
            }
            let node = system.node_names.iter().position(|n| *n == o.station);
            let q = orders.iter().position(|x| (x - o.order).abs() < 1e-9);
            let (Some(node), Some(q)) = (node, q) else {
                continue;
            };
            let a = &response.ias_amplitude_rpm[node][q];
            let at_mean = a[0];
            let largest = a.iter().fold(0.0_f64, |m, x| m.max(*x));
            if at_mean > 1e-6 * largest.max(1e-12) && at_mean > 1e-9 {
                let spread = a[1..].iter().sum::<f64>() / (a.len() - 1) as f64;
                factors[i] = (spread / at_mean).clamp(1.0 / LIMIT, LIMIT);
            }
        }
    }
}
