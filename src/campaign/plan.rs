//! What a bench campaign records: steady regimes and run-ups, each with its speed, load,
//! duration and (optionally) its own sample rate. [`Plan::default_for`] makes the usual
//! campaign from a model; [`Plan::parse`] ([`super::plan_file`]) reads a plan file.

use super::CampaignError;
use crate::model::{Model, Pressure};
use crate::recording::RunShape;

/// One recording of the plan.
#[derive(Debug, Clone, PartialEq)]
pub struct PlannedRun {
    /// Stem of the CSV and sidecar files.
    pub file: String,
    /// The sidecar's label.
    pub label: String,
    /// Steady, long run (a steady run of at least [`crate::recording::LONG_RUN_S`]) or
    /// ramp, in the one vocabulary of runs ([`RunShape`], issue 14 item 1).
    pub shape: RunShape,
    /// Recorded duration, s.
    pub duration_s: f64,
    /// Engine load 0..1.
    pub load: f64,
    /// Sample rate of this recording, Hz (`None`: the measurement's).
    pub rate_hz: Option<f64>,
}

/// The recordings of one campaign.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    /// In recording order.
    pub runs: Vec<PlannedRun>,
}

/// Durations of the default plan.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanDurations {
    /// Each steady regime, s (default 4).
    pub regime_s: f64,
    /// The long steady run, s (default 30).
    pub long_run_s: f64,
    /// The full-load run-up, s (default 60).
    pub run_up_s: f64,
}

impl Default for PlanDurations {
    fn default() -> Self {
        Self {
            regime_s: 4.0,
            long_run_s: 30.0,
            run_up_s: 60.0,
        }
    }
}

/// A file stem from a label: lower case, runs of other characters as one `-`.
pub(crate) fn stem(label: &str) -> String {
    let mut out = String::new();
    for c in label.chars() {
        if c.is_ascii_alphanumeric() {
            out.push(c.to_ascii_lowercase());
        } else if !out.ends_with('-') && !out.is_empty() {
            out.push('-');
        }
    }
    out.trim_end_matches('-').to_string()
}

impl Plan {
    /// The usual campaign on `model` (a bench engineer's, seed 001 §2.3): every
    /// `[operation] regimes` entry (A–F at full load, say) for `regime_s`; two part-load
    /// regimes, at the speeds of the regimes half and three quarters along (C and E), at the
    /// lowest load of `pressure_by_load` (0.3 without one), unless the model lists two; one
    /// long full-load run at the middle regime; one full-load run-up over `speed_range_rpm`.
    /// A model without regimes gets six speeds A–F spread over its operating (or speed)
    /// range.
    pub fn default_for(model: &Model, d: PlanDurations) -> Result<Self, CampaignError> {
        let op = &model.operation;
        let mut regimes: Vec<(String, f64, f64)> = op
            .regimes
            .iter()
            .map(|r| (r.label.clone(), r.speed_rpm, r.load))
            .collect();
        if regimes.is_empty() {
            let [lo, hi] = op
                .operating_range_rpm
                .or(op.speed_range_rpm)
                .ok_or_else(|| {
                    CampaignError::Input(
                        "the model has no [operation] regimes, operating_range_rpm or \
                         speed_range_rpm: give a plan (--plan)"
                            .into(),
                    )
                })?;
            regimes = ["A", "B", "C", "D", "E", "F"]
                .iter()
                .enumerate()
                .map(|(i, l)| (l.to_string(), lo + (hi - lo) * i as f64 / 5.0, 1.0))
                .collect();
        }
        let label = |l: &str| {
            if l.to_ascii_lowercase().starts_with("regime") {
                l.to_string()
            } else {
                format!("Regime {l}")
            }
        };
        let steady = |label: String, speed_rpm: f64, load: f64, duration_s: f64| PlannedRun {
            file: stem(&label),
            label,
            shape: RunShape::steady(speed_rpm, duration_s),
            duration_s,
            load,
            rate_hz: None,
        };
        let mut runs: Vec<PlannedRun> = regimes
            .iter()
            .map(|(l, s, load)| steady(label(l), *s, *load, d.regime_s))
            .collect();
        let full: Vec<&(String, f64, f64)> = regimes.iter().filter(|r| r.2 >= 1.0).collect();
        let part_count = regimes.iter().filter(|r| r.2 < 1.0).count();
        let part_load = match model.engine.as_ref().map(|e| &e.pressure) {
            Some(Pressure::ByLoad(c)) => c.first().map_or(0.3, |c| c.load).min(0.3),
            _ => 0.3,
        };
        if part_count < 2 && full.len() >= 2 {
            let n = full.len() - 1;
            let picks = [n / 2, (n as f64 * 0.75).round() as usize];
            for i in picks.into_iter().take(2 - part_count) {
                let (l, s, _) = full[i];
                let pct = (100.0 * part_load).round();
                runs.push(steady(
                    format!("{}, {pct} % load", label(l)),
                    *s,
                    part_load,
                    d.regime_s,
                ));
                if let Some(r) = runs.last_mut() {
                    r.file = format!("{}-part", stem(&label(l)));
                }
            }
        }
        if let Some((l, s, _)) = full.get(full.len().saturating_sub(1) / 2) {
            let mut run = steady(format!("{}, long run", label(l)), *s, 1.0, d.long_run_s);
            run.file = "long-run".into();
            runs.push(run);
        }
        let (lo, hi) = match op.speed_range_rpm {
            Some([lo, hi]) => (lo, hi),
            None => {
                let speeds = regimes.iter().map(|r| r.1);
                let lo = speeds.clone().fold(f64::INFINITY, f64::min);
                let hi = speeds.fold(0.0, f64::max);
                (0.5 * lo, 1.05 * hi)
            }
        };
        runs.push(PlannedRun {
            file: "run-up".into(),
            label: format!("Run-up {lo:.0} to {hi:.0} rpm, full load"),
            shape: RunShape::Ramp {
                from_rpm: lo.max(1.0),
                to_rpm: hi,
            },
            duration_s: d.run_up_s,
            load: 1.0,
            rate_hz: None,
        });
        Ok(Self { runs })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stems_from_labels() {
        assert_eq!(stem("Regime C, 30 % load"), "regime-c-30-load");
        assert_eq!(stem("A"), "a");
    }
}
