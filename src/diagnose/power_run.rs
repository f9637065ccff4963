//! The detectability analysis from end to end (issue 14, item 6; see [`super::power`]).

use super::DiagnoseError;
use super::power::{PowerReport, analyse_all};
use super::power_add::{RunSummary, recommend};
use super::power_fisher::LAMBDA_DETECT;
use super::power_pairs::{pairs, representatives};
use super::power_plan::Bench;
use crate::campaign::Plan;
use crate::model::Model;

/// Analyses what `plan`, measured by `bench`, can detect and tell apart on `model`;
/// `progress(fraction, stage)` returns `false` to cancel.
pub fn power(
    model: &Model,
    plan: &Plan,
    bench: &Bench,
    threads: usize,
    progress: &mut dyn FnMut(f64, &str) -> bool,
) -> Result<PowerReport, DiagnoseError> {
    let started = std::time::Instant::now();
    if plan.runs.is_empty() {
        return Err(DiagnoseError::Input("the plan has no runs".into()));
    }
    let (ev, all) = analyse_all(model, plan, bench, threads, progress)?;
    if !progress(0.8, "separating the effects") {
        return Err(DiagnoseError::Cancelled);
    }
    let pair_rows = pairs(&ev, &all);
    let reps = representatives(&all);
    if !progress(0.85, "trying additions to the plan") {
        return Err(DiagnoseError::Cancelled);
    }
    let additions = recommend(model, plan, bench, &ev, &reps, &pair_rows, threads);
    let runs = ev
        .observed
        .runs
        .iter()
        .enumerate()
        .map(|(r, run)| {
            let sigmas: Vec<f64> = ev
                .observed
                .observations
                .iter()
                .filter(|o| o.run == r)
                .map(|o| o.sigma_rpm)
                .collect();
            RunSummary {
                label: run.label.clone(),
                kind: run.regime.label().into(),
                observables: sigmas.len(),
                sigma_rpm: [
                    sigmas
                        .iter()
                        .copied()
                        .fold(f64::INFINITY, f64::min)
                        .min(1e300),
                    sigmas.iter().copied().fold(0.0, f64::max),
                ],
            }
        })
        .collect();
    progress(1.0, "done");
    Ok(PowerReport {
        format: "torsim-power/1",
        lambda_detect: LAMBDA_DETECT,
        runs,
        observables: ev.observed.observations.len(),
        noise_rpm: bench.noise_rpm,
        jitter_ns: bench.jitter_ns,
        rate_hz: bench.rate_hz,
        stations: bench.stations.iter().map(|s| s.node.clone()).collect(),
        effects: all.into_iter().map(|a| a.row).collect(),
        pairs: pair_rows,
        additions,
        elapsed_s: started.elapsed().as_secs_f64(),
    })
}
