//! Which observations a fit may use, and which it is judged on.
//!
//! - Steady regimes at one load, in speed order, alternate: the first, third, … are
//!   fitted, the second, fourth, … held out (seed 001's A–F: A, C, E fitted; B, D, F
//!   held out).
//! - A long run: its first half fitted, its second half held out (a drift must be
//!   predicted forward in time, not interpolated).
//! - A run-up: its speed bins alternate, so a resonance is in both halves.

use super::DiagnoseError;
use super::observe::{LONG_RUN_BLOCKS, Observed, RunShape};

/// `true` for the held-out observations.
pub fn held_out(observed: &Observed) -> Vec<bool> {
    // Rank the steady runs of each load by speed.
    let mut steady: Vec<(usize, f64, f64)> = observed
        .runs
        .iter()
        .enumerate()
        .filter_map(|(r, run)| match run.regime {
            RunShape::Steady { speed_rpm } => Some((r, (run.load * 1000.0).round(), speed_rpm)),
            _ => None,
        })
        .collect();
    steady.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.2.total_cmp(&b.2)));
    let mut rank = vec![0usize; observed.runs.len()];
    let mut last_load = f64::NAN;
    let mut k = 0;
    for (r, load, _) in &steady {
        if *load != last_load {
            k = 0;
            last_load = *load;
        }
        rank[*r] = k;
        k += 1;
    }
    observed
        .observations
        .iter()
        .map(|o| match observed.runs[o.run].regime {
            RunShape::Steady { .. } => rank[o.run] % 2 == 1,
            RunShape::LongRun { .. } => o.part >= LONG_RUN_BLOCKS / 2,
            RunShape::Ramp { .. } => o.part % 2 == 1,
        })
        .collect()
}

/// Refuses a campaign that leaves nothing to fit or nothing held out: the held-out χ²/N
/// that judges every verdict (`spec/diagnosis.md`) would be 0/0 (issue 13: one recording
/// gave "held-out χ²/N from NaN to NaN" with exit 0).
pub fn check_split(observed: &Observed, mask: &[bool]) -> Result<(), DiagnoseError> {
    let held = mask.iter().filter(|m| **m).count();
    if held > 0 && held < mask.len() {
        return Ok(());
    }
    let runs: Vec<String> = observed
        .runs
        .iter()
        .map(|r| format!("`{}`", r.label))
        .collect();
    let missing = if held == 0 { "held out" } else { "fitted" };
    Err(DiagnoseError::Input(format!(
        "the recordings ({}) give {} compared amplitudes and none to be {missing}: a diagnosis \
         fits on some and judges on others, so give at least two steady runs at one load, \
         a long run or a run-up",
        runs.join(", "),
        mask.len()
    )))
}

/// The labels of what is held out: `"Regime B"`, `"Regime C, long run (second half)"`,
/// `"Run-up … (every other 100 rpm bin)"`.
pub fn held_out_labels(observed: &Observed, mask: &[bool]) -> Vec<String> {
    let mut labels = Vec::new();
    for (r, run) in observed.runs.iter().enumerate() {
        let any = observed
            .observations
            .iter()
            .zip(mask)
            .any(|(o, m)| *m && o.run == r);
        if !any {
            continue;
        }
        labels.push(match run.regime {
            RunShape::Steady { .. } => run.label.clone(),
            RunShape::LongRun { .. } => format!("{} (second half)", run.label),
            RunShape::Ramp { .. } => format!("{} (every other 100 rpm bin)", run.label),
        });
    }
    labels
}

/// The role of each run for the report.
pub fn roles(observed: &Observed, mask: &[bool]) -> Vec<String> {
    observed
        .runs
        .iter()
        .enumerate()
        .map(|(r, run)| match run.regime {
            RunShape::LongRun { .. } => "fit (first half), held out (second half)".to_string(),
            RunShape::Ramp { .. } => "fit and held out (alternate speed bins)".to_string(),
            RunShape::Steady { .. } => {
                let held = observed
                    .observations
                    .iter()
                    .zip(mask)
                    .any(|(o, m)| *m && o.run == r);
                if held { "held out" } else { "fit" }.to_string()
            }
        })
        .collect()
}
