//! The simulated side: a model run in the nonlinear time domain ([`crate::transient`]) at
//! each recording's regime — its measured mean speed, or its measured ramp, and its load —
//! and analysed exactly like the recording ([`super::observe`]), so that every
//! [`Observation`](super::observe::Observation) gets its simulated counterpart.
//!
//! The runs are independent and run on `threads` worker threads, longest first; a long
//! run-up is cut into [`forward_runup::SEGMENTS`] segments ([`super::forward_runup`]).
//! The numbers do not depend on the thread count or on which thread ends first.

use super::forward_runup::{self, BinSums};
use super::observe::{LONG_RUN_BLOCKS, Observed, Run, RunShape, analysis_options, slice};
use super::settling::{self, warms_up};
use crate::model::Model;
use crate::recording::{Channel, ChannelKind, Recording, RecordingMeta, RunKind as RecKind};
use crate::signal::{Analysis, analyse_with};
use crate::transient::{RunOptions, simulate};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Shortest simulated steady record, s, and fewest working cycles in it.
const STEADY_MIN_S: f64 = 0.25;
const STEADY_MIN_CYCLES: f64 = 8.0;
/// Cycle-to-cycle change of the vibration speeds, relative to their peak, at which a
/// simulated run counts as settled. Amplitudes are compared with a floor of 0.5 % of
/// their value ([`super::residual`]); an unsettled remainder of 2e-3 of the peak moves
/// an order amplitude by less than that, and the slow rigid-body remainder of the speed
/// governor, which dominates it, falls below every analysed order. The transient
/// module's default (1e-4) takes 5–6 times as many cycles here.
const SETTLE_TOLERANCE: f64 = 2e-3;
/// Longest settling of a simulated run, s, for a model whose modes decay fast: a driveline
/// settles to [`SETTLE_TOLERANCE`] in 20–40 working cycles (under 1 s above 1000 rpm);
/// one that has not by then is rattling (gear backlash), never settles, and is recorded
/// as it is — its orders then carry the rattle as the bench's do. A lightly damped mode
/// extends it to its own decay ([`super::settling::settle_s`]).
const MAX_SETTLE_S: f64 = 6.0;
/// The simulation's output rate over the recording's (orders above the recording's
/// Nyquist frequency must not fold back onto engine orders).
const OVERSAMPLING: f64 = 4.0;

/// The steady simulation of a steady regime or long run, `(speed_rpm, duration_s)`;
/// `None` for a run-up (simulated by segments, [`super::forward_runup`]).
fn steady_record(model: &Model, run: &Run) -> Option<(f64, f64)> {
    let cycle_s = |speed_rpm: f64| 120.0 / speed_rpm.max(1.0);
    let short = |speed_rpm: f64| STEADY_MIN_S.max(STEADY_MIN_CYCLES * cycle_s(speed_rpm));
    match run.regime {
        RunShape::Steady { speed_rpm } => Some((speed_rpm, run.duration_s.min(short(speed_rpm)))),
        RunShape::LongRun { speed_rpm } => Some((
            speed_rpm,
            if warms_up(model) {
                run.duration_s
            } else {
                short(speed_rpm)
            },
        )),
        RunShape::Ramp { .. } => None,
    }
}

/// Relative tolerance of the diagnosis' integration: order amplitudes then differ from
/// those at the default 1e-5 by 0.005 σ rms, 0.07 σ at most (measured on the reference
/// thermal campaign: every observation of the user's model), well inside the 0.5 %
/// amplitude floor of [`super::residual`].
const RTOL: f64 = 1e-4;
/// Integrator steps per working cycle at least: 8° of crank on a four-stroke engine, where
/// [`RTOL`] then sets the step.
const MIN_STEPS_PER_CYCLE: f64 = 90.0;
/// Maxwell arms of a rubber stage that relax faster than this multiple of the highest
/// frequency the diagnosis compares run as a dashpot
/// ([`crate::transient::maxwell::MaxwellChain::take_fast_arms`]): it changes the
/// stiffness there by at most 10 % of those arms (a few per cent of the stage). With
/// [`RTOL`] and [`MIN_STEPS_PER_CYCLE`], the order amplitudes of the user's model move by
/// 0.005–0.023 σ rms, 0.35 σ at most, over every observation of six campaigns (three
/// reference, three shipped), and a campaign runs 1.4–1.6 times faster (a 60 s run-up of
/// the diagnosis bench: 329 000 steps instead of 678 000).
const VISCOUS_ABOVE: f64 = 3.0;

/// The time domain's settings for simulating `run` (or a part of it whose highest speed
/// is `top_speed_rpm`) of `model` to compare orders up to `max_order`: its load, output at
/// [`OVERSAMPLING`] times the recording's rate, settling as long as the slowest mode's
/// decay time `decay_s` asks ([`super::settling`]): at most [`super::settling::settle_s`],
/// and, when `no_lead_in` (a run that starts on its periodic state, not on a lead-in of
/// the ramp), at least [`super::settling::min_settle_s`]; then held while a warming stage
/// warms ([`warm_hold_s`]).
pub(super) fn run_options(
    model: &Model,
    run: &Run,
    max_order: f64,
    top_speed_rpm: f64,
    decay_s: Option<f64>,
    no_lead_in: bool,
) -> RunOptions {
    let compared_hz = max_order * top_speed_rpm / 60.0;
    RunOptions {
        hold_s: if no_lead_in {
            warm_hold_s(model, run, decay_s)
        } else {
            0.0
        },
        load: run.load,
        rate_hz: OVERSAMPLING * run.rate_hz,
        settle_tolerance: SETTLE_TOLERANCE,
        max_settle_s: settling::settle_s(decay_s, MAX_SETTLE_S),
        min_settle_s: if no_lead_in {
            settling::min_settle_s(decay_s)
        } else {
            0.0
        },
        rtol: RTOL,
        min_steps_per_cycle: MIN_STEPS_PER_CYCLE,
        viscous_above_hz: Some(VISCOUS_ABOVE * compared_hz),
        ..RunOptions::default()
    }
}

/// How long `run` of `model` is held at its start speed before its simulated record, s,
/// the rubber warming ([`crate::transient::RunOptions::hold_s`]); 0 when nothing warms.
///
/// A bench holds a regime until its vibration has settled before it records, and a stage
/// warms meanwhile: the forward model holds for the slowest mode's settling
/// ([`super::settling::min_settle_s`]) before every run that starts on its periodic state.
/// A steady regime's record is a few cycles ([`steady_record`]), taken where the bench's
/// recording has its middle: held half its duration more. Recorded from a cold stage, a
/// regime at a resonance rose through it in the record (benchtruth case 2050 at 1020 rpm:
/// order 2.5 at 4.9 rpm where the bench measured 0.095, order 3 at 16.9 against 15.7);
/// held 1.1 s first, as the bench settles, order 2.5 is 0.029 and order 3 16.7.
fn warm_hold_s(model: &Model, run: &Run, decay_s: Option<f64>) -> f64 {
    if !warms_up(model) {
        return 0.0;
    }
    // As [`settling::bench_hold_s`], with the decay time already at hand.
    let settle_s = settling::min_settle_s(decay_s);
    match run.regime {
        RunShape::Steady { .. } => settle_s + 0.5 * run.duration_s,
        RunShape::LongRun { .. } | RunShape::Ramp { .. } => settle_s,
    }
}

/// The simulated stations of `run` as a recording.
pub(super) fn station_recording(
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
    decay_s: Option<f64>,
) -> Result<Vec<(usize, f64)>, String> {
    let run = &observed.runs[r];
    let (speed_rpm, duration_s) =
        steady_record(model, run).ok_or("a run-up is simulated by segments")?;
    let run_spec = crate::recording::Run::steady(speed_rpm, duration_s);
    let options = run_options(model, run, max_order, speed_rpm, decay_s, true);
    let sim = simulate(model, run_spec, options, &mut |_| true).map_err(|e| e.to_string())?;
    let rec = station_recording(&sim, run, RecKind::Steady)?;
    let analysis_opts = analysis_options(max_order);
    let analyse = |rec: &Recording| analyse_with(rec, &analysis_opts).map_err(|e| e.to_string());
    let mine = observed
        .observations
        .iter()
        .enumerate()
        .filter(|(_, o)| o.run == r);
    match run.regime {
        RunShape::Steady { .. } => {
            let a = analyse(&rec)?;
            Ok(mine
                .map(|(i, o)| (i, amplitude(&a, &o.station, o.order)))
                .collect())
        }
        RunShape::LongRun { .. } => {
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
        RunShape::Ramp { .. } => Err("a run-up is simulated by segments".into()),
    }
}

/// The simulated amplitude of every observation of `observed` for `model`, before the
/// measurement ([`super::sensor`]); only the runs `wanted` (all when `None`) are simulated,
/// the others' observations are left 0. Errors name the recording whose simulation failed.
pub fn predict(
    model: &Model,
    observed: &Observed,
    max_order: f64,
    threads: usize,
    wanted: Option<&[bool]>,
) -> Result<Vec<f64>, (String, String)> {
    let threads = threads.max(1);
    // The slowest mode's decay time per run (its load): how long runs settle.
    let decays: Vec<Option<f64>> = observed
        .runs
        .iter()
        .map(|run| settling::slowest_decay_s(model, run.load))
        .collect();
    let mut jobs: Vec<Job> = Vec::new();
    for (r, run) in observed.runs.iter().enumerate() {
        if !wanted.is_none_or(|w| w.get(r).copied().unwrap_or(false)) {
            continue;
        }
        match run.regime {
            // A rubber stage that warms up carries its temperature through the whole
            // run-up: a segment would start it cold again.
            RunShape::Ramp { .. } => jobs.extend(
                forward_runup::segments(
                    observed,
                    r,
                    if warms_up(model) {
                        1
                    } else {
                        forward_runup::SEGMENTS
                    },
                    decays[r],
                )
                .into_iter()
                .map(Job::Segment),
            ),
            _ => jobs.push(Job::Run(r)),
        }
    }
    let cost = |j: &Job| match j {
        Job::Segment(s) => s.cost_s(),
        Job::Run(r) => steady_record(model, &observed.runs[*r]).map_or(0.0, |(_, d)| d),
    };
    jobs.sort_by(|a, b| cost(b).total_cmp(&cost(a)));
    let next = AtomicUsize::new(0);
    let out = Mutex::new(vec![0.0; observed.observations.len()]);
    // Each segment's bins by job, added up in job order once all have ended: added as
    // they ended, the sums' rounding depended on which thread finished first.
    let parts: Mutex<Vec<Option<BinSums>>> = Mutex::new(vec![None; jobs.len()]);
    let failure = Mutex::new(None);
    std::thread::scope(|scope| {
        for _ in 0..threads.min(jobs.len().max(1)) {
            scope.spawn(|| {
                loop {
                    let k = next.fetch_add(1, Ordering::Relaxed);
                    let Some(job) = jobs.get(k) else { break };
                    let (r, result) = match job {
                        Job::Run(r) => (
                            *r,
                            predict_run(model, observed, *r, max_order, decays[*r])
                                .map(Done::Values),
                        ),
                        Job::Segment(seg) => (
                            seg.run,
                            forward_runup::predict_segment(model, observed, *seg, max_order)
                                .map(Done::Sums),
                        ),
                    };
                    match result {
                        Ok(Done::Values(values)) => {
                            if let Ok(mut out) = out.lock() {
                                for (i, v) in values {
                                    out[i] = v;
                                }
                            }
                        }
                        Ok(Done::Sums(part)) => {
                            if let Ok(mut parts) = parts.lock() {
                                parts[k] = Some(part);
                            }
                        }
                        Err(e) => {
                            if let Ok(mut f) = failure.lock() {
                                f.get_or_insert((observed.runs[r].label.clone(), e));
                            }
                            next.store(jobs.len(), Ordering::Relaxed);
                        }
                    }
                }
            });
        }
    });
    if let Some(f) = failure.into_inner().ok().flatten() {
        return Err(f);
    }
    let panicked = || ("all".to_string(), "a worker thread panicked".to_string());
    let mut out = out.into_inner().map_err(|_| panicked())?;
    let mut sums = vec![BinSums::new(); observed.runs.len()];
    let parts = parts.into_inner().map_err(|_| panicked())?;
    for (job, part) in jobs.iter().zip(parts) {
        if let (Job::Segment(seg), Some(part)) = (job, part) {
            forward_runup::accumulate(&mut sums[seg.run], part);
        }
    }
    for (i, o) in observed.observations.iter().enumerate() {
        if matches!(observed.runs[o.run].regime, RunShape::Ramp { .. }) {
            out[i] = forward_runup::observation_rpm(&sums[o.run], o);
        }
    }
    Ok(out)
}

/// A piece of a campaign's simulation.
enum Job {
    /// A steady regime or long run.
    Run(usize),
    /// A stretch of a run-up.
    Segment(forward_runup::Segment),
}

/// What a job gives.
enum Done {
    /// `(observation, amplitude)` of a steady regime or long run.
    Values(Vec<(usize, f64)>),
    /// A run-up segment's bins.
    Sums(BinSums),
}
