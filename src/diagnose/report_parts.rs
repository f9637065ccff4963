//! The report's parts beyond the verdict: mismatches of the user's model, the mismatch
//! map, resonances no mode explains, before/after overlays on held-out data, and the
//! recordings used.

use super::context::{Context, Evaluated};
use super::decide::{run_roles, validated_on};
use super::observe::{Run, RunShape};
use super::report::*;
use crate::physics::{OperatingPoint, System};

/// Mismatches listed in the report.
const MAX_MISMATCHES: usize = 50;
/// Overlays drawn.
const MAX_OVERLAYS: usize = 8;

/// Puts the report together.
#[allow(clippy::too_many_arguments)]
pub fn assemble(
    cx: &Context,
    baseline: &Evaluated,
    after_model: &Evaluated,
    verdict: Verdict,
    candidates: Vec<Candidate>,
    before: f64,
    after: f64,
    not_fitted: Vec<NotFitted>,
    elapsed_s: f64,
) -> Report {
    let obs = &cx.observed;
    let label = |r: usize| obs.runs[r].label.clone();
    let mut mismatch_map = Vec::with_capacity(obs.observations.len());
    let mut mismatches = Vec::new();
    for ((o, z), sim) in obs
        .observations
        .iter()
        .zip(&baseline.z)
        .zip(&baseline.simulated)
    {
        mismatch_map.push(MapCell {
            recording: label(o.run),
            station: o.station.clone(),
            order: o.order,
            speed_rpm: o.speed_rpm,
            z: *z,
        });
        mismatches.push(Mismatch {
            recording: label(o.run),
            station: o.station.clone(),
            order: format!("{}", o.order),
            speed_rpm: o.speed_rpm,
            frequency_hz: o.order * o.speed_rpm / 60.0,
            measured: o.measured_rpm,
            simulated: *sim,
            quantity: "ias_amplitude_rpm".into(),
            z: *z,
        });
    }
    mismatches.sort_by(|a, b| b.z.abs().total_cmp(&a.z.abs()));
    mismatches.truncate(MAX_MISMATCHES);
    let mut noise: Vec<f64> = obs.observations.iter().map(|o| o.sigma_rpm).collect();
    noise.sort_by(f64::total_cmp);
    let roles = run_roles(cx);
    let mut recordings: Vec<RecordingUse> = obs
        .runs
        .iter()
        .zip(roles)
        .map(|(r, role)| recording_use(r, role, None))
        .chain(
            cx.set_aside
                .iter()
                .map(|s| recording_use(&s.run, "set aside".into(), Some(s.reason.clone()))),
        )
        .collect();
    recordings.sort_by(|a, b| a.label.cmp(&b.label));
    Report {
        format: REPORT_FORMAT,
        verdict,
        mismatches,
        candidates,
        fit: Fit {
            metric: "chi2_per_amplitude (held out): mean of ((measured − simulated)/σ)² over \
                     the IAS order amplitudes the fit did not use"
                .into(),
            before,
            after,
            validated_on: validated_on(cx),
            swapped_because: cx.swapped_because.clone(),
        },
        mismatch_map,
        unexplained_resonances: resonances(cx, baseline),
        overlays: overlays(cx, baseline, after_model),
        recordings,
        noise_rpm: noise.get(noise.len() / 2).copied().unwrap_or(0.0),
        not_fitted,
        elapsed_s,
    }
}

/// A recording's entry in the report.
fn recording_use(r: &Run, role: String, set_aside: Option<String>) -> RecordingUse {
    RecordingUse {
        label: r.label.clone(),
        kind: r.regime.label().into(),
        speed_rpm: match r.regime {
            RunShape::Steady { speed_rpm } | RunShape::LongRun { speed_rpm } => {
                [speed_rpm, speed_rpm]
            }
            RunShape::Ramp { from_rpm, to_rpm } => [from_rpm, to_rpm],
        },
        load: r.load,
        role,
        set_aside,
    }
}

/// Run-up peaks of a measured order track that the model misses by more than half and
/// by more than 5 σ, with the nearest natural frequency of the model.
fn resonances(cx: &Context, baseline: &Evaluated) -> Vec<Resonance> {
    let obs = &cx.observed;
    let modes: Vec<f64> = System::new(cx.user, OperatingPoint::default())
        .ok()
        .and_then(|s| crate::modal::modes(&s).ok())
        .map(|m| m.iter().map(|m| m.frequency_hz).collect())
        .unwrap_or_default();
    let mut out: Vec<Resonance> = Vec::new();
    for (i, o) in obs.observations.iter().enumerate() {
        if !matches!(obs.runs[o.run].regime, RunShape::Ramp { .. }) {
            continue;
        }
        // A local peak of the measured track.
        let neighbour = |d: isize| {
            obs.observations.iter().find(|x| {
                x.run == o.run
                    && x.station == o.station
                    && x.order == o.order
                    && x.part as isize == o.part as isize + d
            })
        };
        let peak = [-1, 1]
            .iter()
            .all(|d| neighbour(*d).is_none_or(|x| x.measured_rpm <= o.measured_rpm));
        let sim = baseline.simulated[i];
        if peak && baseline.z[i] > 5.0 && o.measured_rpm > 2.0 * sim {
            let f = o.order * o.speed_rpm / 60.0;
            let nearest = modes
                .iter()
                .copied()
                .min_by(|a, b| (a - f).abs().total_cmp(&(b - f).abs()));
            out.push(Resonance {
                station: o.station.clone(),
                order: format!("{}", o.order),
                speed_rpm: o.speed_rpm,
                frequency_hz: f,
                measured: o.measured_rpm,
                simulated: sim,
                nearest_mode_hz: nearest,
            });
        }
    }
    out.sort_by(|a, b| (b.measured - b.simulated).total_cmp(&(a.measured - a.simulated)));
    out.truncate(10);
    out
}

/// An overlay's group: run kind (0 steady, 1 long run, 2 run-up), load in %, station,
/// order.
type GroupKey = (usize, i64, String, String);

/// Measured, before and after along the held-out data: per run kind and station, the
/// orders whose held-out χ² fell the most.
fn overlays(cx: &Context, before: &Evaluated, after: &Evaluated) -> Vec<Overlay> {
    let obs = &cx.observed;
    // Group: (kind, load key, station, order) over held-out observations.
    let mut groups: Vec<(GroupKey, Vec<usize>)> = Vec::new();
    for (i, o) in obs.observations.iter().enumerate() {
        if !cx.held_out[i] {
            continue;
        }
        let run = &obs.runs[o.run];
        let kind = match run.regime {
            RunShape::Steady { .. } => 0,
            RunShape::LongRun { .. } => 1,
            RunShape::Ramp { .. } => 2,
        };
        let key = (
            kind,
            (run.load * 100.0).round() as i64,
            o.station.clone(),
            format!("{}", o.order),
        );
        match groups.iter_mut().find(|(k, _)| *k == key) {
            Some((_, v)) => v.push(i),
            None => groups.push((key, vec![i])),
        }
    }
    let gain = |idx: &[usize]| -> f64 {
        idx.iter()
            .map(|&i| before.z[i].powi(2) - after.z[i].powi(2))
            .sum()
    };
    groups.sort_by(|a, b| gain(&b.1).total_cmp(&gain(&a.1)));
    groups
        .into_iter()
        .filter(|(_, idx)| idx.len() >= 2)
        .take(MAX_OVERLAYS)
        .map(|((kind, load, station, order), mut idx)| {
            let x_of = |i: usize| {
                let o = &obs.observations[i];
                if kind == 1 { o.time_s } else { o.speed_rpm }
            };
            idx.sort_by(|a, b| x_of(*a).total_cmp(&x_of(*b)));
            let recording = match kind {
                0 => format!("steady regimes at {load} % load (held out)"),
                1 => format!(
                    "{} (second half)",
                    obs.runs[obs.observations[idx[0]].run].label
                ),
                _ => format!(
                    "{} (held-out bins)",
                    obs.runs[obs.observations[idx[0]].run].label
                ),
            };
            Overlay {
                recording,
                station,
                order,
                x_label: if kind == 1 { "time [s]" } else { "speed [rpm]" }.into(),
                x: idx.iter().map(|&i| x_of(i)).collect(),
                measured: idx
                    .iter()
                    .map(|&i| obs.observations[i].measured_rpm)
                    .collect(),
                sigma: idx.iter().map(|&i| obs.observations[i].sigma_rpm).collect(),
                before: idx.iter().map(|&i| before.simulated[i]).collect(),
                after: idx.iter().map(|&i| after.simulated[i]).collect(),
            }
        })
        .collect()
}
