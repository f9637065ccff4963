//! The simulated side: a model run in the nonlinear time domain ([`crate::transient`]) at
//! each recording's regime — its measured mean speed, or its measured ramp, and its load —
//! and analysed exactly like the recording ([`super::observe`]), so that every
//! [`Observation`](super::observe::Observation) gets its simulated counterpart.
//!
//! The runs are independent and run on `threads` worker threads, longest first.

use super::observe::{LONG_RUN_BLOCKS, Observed, Regime, Run, analysis_options, slice};
use super::observe_runup::{bin_tracks, bins};
use crate::model::{ConnectionKind, Model};
use crate::recording::{Channel, ChannelKind, Recording, RecordingMeta, RunKind as RecKind};
use crate::signal::{Analysis, analyse_with};
use crate::transient::{RunKind, RunOptions, simulate};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Shortest simulated steady record, s, and fewest working cycles in it.
const STEADY_MIN_S: f64 = 0.25;
const STEADY_MIN_CYCLES: f64 = 8.0;
/// Run-ups start this long before the recording, at the same slope, so that the
/// simulated run enters the recorded speed range already sweeping, as on the bench, s.
const RUN_UP_LEAD_S: f64 = 0.1;
/// The simulation's output rate over the recording's (orders above the recording's
/// Nyquist frequency must not fold back onto engine orders).
const OVERSAMPLING: f64 = 4.0;

/// Does `model` warm up in the time domain (a rubber stage with `thermal`)?
fn warms_up(model: &Model) -> bool {
    model
        .connections
        .iter()
        .any(|c| matches!(&c.kind, ConnectionKind::Rubber(r) if r.thermal.is_some()))
}

/// What to simulate for `run`.
fn run_kind(model: &Model, run: &Run) -> RunKind {
    let cycle_s = |speed_rpm: f64| 120.0 / speed_rpm.max(1.0);
    match run.regime {
        Regime::Steady { speed_rpm } => RunKind::Steady {
            speed_rpm,
            duration_s: run
                .duration_s
                .min(STEADY_MIN_S.max(STEADY_MIN_CYCLES * cycle_s(speed_rpm))),
        },
        Regime::LongRun { speed_rpm } => RunKind::Steady {
            speed_rpm,
            duration_s: if warms_up(model) {
                run.duration_s
            } else {
                STEADY_MIN_S.max(STEADY_MIN_CYCLES * cycle_s(speed_rpm))
            },
        },
        Regime::RunUp { from_rpm, to_rpm } => {
            let lead = lead_s(run);
            let slope = (to_rpm - from_rpm) / run.duration_s.max(1e-9);
            RunKind::Ramp {
                from_rpm: from_rpm - slope * lead,
                to_rpm,
                duration_s: run.duration_s + lead,
            }
        }
    }
}

/// The lead-in of a run-up, s: [`RUN_UP_LEAD_S`], shortened so the ramp starts above a
/// quarter of its first recorded speed.
fn lead_s(run: &Run) -> f64 {
    match run.regime {
        Regime::RunUp { from_rpm, to_rpm } => {
            let slope = ((to_rpm - from_rpm) / run.duration_s.max(1e-9)).abs();
            RUN_UP_LEAD_S.min(0.75 * from_rpm.min(to_rpm) / slope.max(1e-9))
        }
        _ => 0.0,
    }
}

/// The simulated stations of `run` as a recording.
fn station_recording(
    sim: &crate::transient::Simulation,
    run: &Run,
    kind: RecKind,
) -> Result<Recording, String> {
    let mut meta = RecordingMeta::new(kind, run.reference.clone());
    meta.load = run.load;
    let mut channels = Vec::new();
    for station in &run.stations {
        let i = sim
            .node_names
            .iter()
            .position(|n| n == station)
            .ok_or_else(|| format!("station `{station}` is no node of the model"))?;
        channels.push(Channel {
            column: format!("{station}_rpm"),
            kind: ChannelKind::SpeedRpm {
                node: station.clone(),
            },
            values: sim.speed_rpm[i].clone(),
        });
    }
    Ok(Recording {
        time_s: sim.time_s.clone(),
        channels,
        meta,
    })
}

/// The order amplitude of `station` at `order` in `analysis` (0 when not analysed).
fn amplitude(analysis: &Analysis, station: &str, order: f64) -> f64 {
    analysis
        .stations
        .iter()
        .find(|s| s.name == station)
        .and_then(|s| s.orders.iter().find(|o| (o.order - order).abs() < 1e-9))
        .map_or(0.0, |o| o.amplitude)
}

/// Simulates and analyses run `r`; returns `(observation index, simulated amplitude)`.
fn predict_run(
    model: &Model,
    observed: &Observed,
    r: usize,
    max_order: f64,
) -> Result<Vec<(usize, f64)>, String> {
    let run = &observed.runs[r];
    let kind = run_kind(model, run);
    let options = RunOptions {
        load: run.load,
        rate_hz: OVERSAMPLING * run.rate_hz,
        ..RunOptions::default()
    };
    let sim = simulate(model, kind, options, &mut |_| true).map_err(|e| e.to_string())?;
    let rec_kind = match run.regime {
        Regime::RunUp { .. } => RecKind::RunUp,
        _ => RecKind::Steady,
    };
    let mut rec = station_recording(&sim, run, rec_kind)?;
    if let Regime::RunUp { .. } = run.regime {
        let lead = lead_s(run);
        rec = slice(&rec, lead, lead + run.duration_s);
        let t0 = rec.time_s.first().copied().unwrap_or(0.0);
        rec.time_s.iter_mut().for_each(|t| *t -= t0);
    }
    let analysis_opts = analysis_options(max_order);
    let analyse = |rec: &Recording| analyse_with(rec, &analysis_opts).map_err(|e| e.to_string());
    let mine = observed
        .observations
        .iter()
        .enumerate()
        .filter(|(_, o)| o.run == r);
    match run.regime {
        Regime::Steady { .. } => {
            let a = analyse(&rec)?;
            Ok(mine
                .map(|(i, o)| (i, amplitude(&a, &o.station, o.order)))
                .collect())
        }
        Regime::LongRun { .. } => {
            let blocks: Vec<Analysis> = if warms_up(model) {
                let block = run.duration_s / LONG_RUN_BLOCKS as f64;
                (0..LONG_RUN_BLOCKS)
                    .map(|b| analyse(&slice(&rec, b as f64 * block, (b + 1) as f64 * block)))
                    .collect::<Result<_, _>>()?
            } else {
                vec![analyse(&rec)?]
            };
            Ok(mine
                .map(|(i, o)| {
                    let a = &blocks[o.part.min(blocks.len() - 1)];
                    (i, amplitude(a, &o.station, o.order))
                })
                .collect())
        }
        Regime::RunUp { .. } => {
            let a = analyse(&rec)?;
            let stft = a.stft.as_ref().ok_or("no STFT of the simulated run-up")?;
            // Each simulated window takes the bin of the measured window nearest in time.
            let (measured_bins, speeds) = bins(&run.window_speeds_rpm);
            let window_bins: Vec<Option<usize>> = stft
                .times_s
                .iter()
                .map(|t| {
                    let k = run.window_times_s.partition_point(|x| x < t);
                    let near = [k.saturating_sub(1), k.min(run.window_times_s.len() - 1)]
                        .into_iter()
                        .min_by(|a, b| {
                            (run.window_times_s[*a] - t)
                                .abs()
                                .total_cmp(&(run.window_times_s[*b] - t).abs())
                        })?;
                    measured_bins.get(near).copied().flatten()
                })
                .collect();
            let (tracks, _) = bin_tracks(&a, &window_bins, speeds.len());
            Ok(mine
                .map(|(i, o)| {
                    let s = a.stations.iter().position(|s| s.name == o.station);
                    let q = stft.orders.iter().position(|q| (q - o.order).abs() < 1e-9);
                    let v = match (s, q) {
                        (Some(s), Some(q)) => tracks[s][q].get(o.part).copied(),
                        _ => None,
                    };
                    (i, v.filter(|v| v.is_finite()).unwrap_or(0.0))
                })
                .collect())
        }
    }
}

/// The simulated amplitude of every observation of `observed` for `model`, before the
/// measurement ([`super::sensor`]). Errors name the recording whose simulation failed.
pub fn predict(
    model: &Model,
    observed: &Observed,
    max_order: f64,
    threads: usize,
) -> Result<Vec<f64>, (String, String)> {
    let mut order: Vec<usize> = (0..observed.runs.len()).collect();
    let cost = |r: usize| match run_kind(model, &observed.runs[r]) {
        RunKind::Steady { duration_s, .. } | RunKind::Ramp { duration_s, .. } => duration_s,
    };
    order.sort_by(|a, b| cost(*b).total_cmp(&cost(*a)));
    let next = AtomicUsize::new(0);
    let out = Mutex::new(vec![0.0; observed.observations.len()]);
    let failure = Mutex::new(None);
    std::thread::scope(|scope| {
        for _ in 0..threads.clamp(1, observed.runs.len().max(1)) {
            scope.spawn(|| {
                loop {
                    let k = next.fetch_add(1, Ordering::Relaxed);
                    let Some(&r) = order.get(k) else { break };
                    match predict_run(model, observed, r, max_order) {
                        Ok(values) => {
                            if let Ok(mut out) = out.lock() {
                                for (i, v) in values {
                                    out[i] = v;
                                }
                            }
                        }
                        Err(e) => {
                            if let Ok(mut f) = failure.lock() {
                                f.get_or_insert((observed.runs[r].label.clone(), e));
                            }
                            next.store(order.len(), Ordering::Relaxed);
                        }
                    }
                }
            });
        }
    });
    if let Some(f) = failure.into_inner().ok().flatten() {
        return Err(f);
    }
    out.into_inner()
        .map_err(|_| ("all".to_string(), "a worker thread panicked".to_string()))
}
