//! Where free play can open: backlash acts only while the torque through a gear mesh
//! reverses, so a backlash candidate is screened on those recordings only, and not at all
//! when none has them ([`super::screen::screen_one`]). Judged on the linear model of the
//! plain fit, from its steady forced response per engine order, summed over the orders as
//! an upper bound of the vibratory torque.

use super::context::{Context, Evaluated};
use super::surrogate::{causal_system, run_speeds};
use crate::physics::Excitation;
use crate::response::forced_response_orders;

/// Backlash can only act where the torque through the gear reverses: its vibratory
/// torque (every engine order up to 24, summed) reaches this fraction of the mean torque
/// in the linear model (the fraction leaves room for the linear model's error).
pub(super) const REVERSAL_FRACTION: f64 = 0.8;

/// The runs in which the linear model of `e` lets the torque in connection `name`
/// reverse (at any speed of the run).
pub(super) fn torque_reversal_runs(cx: &Context, e: &Evaluated, name: &str) -> Vec<bool> {
    let Some(k) = e.model.connections.iter().position(|c| c.name == name) else {
        return vec![false; cx.observed.runs.len()];
    };
    let orders: Vec<f64> = (1..=48).map(|i| 0.5 * f64::from(i)).collect();
    (0..cx.observed.runs.len())
        .map(|r| {
            let run = &cx.observed.runs[r];
            let [lo, hi] = run_speeds(&cx.observed, r);
            let steps = ((hi - lo) / 50.0).ceil().max(0.0) as usize;
            let speeds: Vec<f64> = (0..=steps)
                .map(|i| lo + (hi - lo) * i as f64 / steps.max(1) as f64)
                .collect();
            let Some(system) = causal_system(&e.model, run.load) else {
                return false;
            };
            let mean = system.mean_torque_nm[k].unwrap_or(0.0).abs();
            let excitation = Excitation::new(&e.model, &system, run.load, &orders);
            let Ok(response) = forced_response_orders(&system, &excitation, &speeds) else {
                return false;
            };
            let Some(j) = response.connections.iter().position(|c| *c == k) else {
                return false;
            };
            (0..speeds.len()).any(|s| {
                let vibratory: f64 = response.torque_amplitude_nm[j].iter().map(|q| q[s]).sum();
                vibratory >= REVERSAL_FRACTION * mean
            })
        })
        .collect()
}
