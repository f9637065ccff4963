//! The measured side of a diagnosis: every recording through the order analysis of
//! [`crate::signal`], as a list of order amplitudes ([`Observation`]), each with its noise.
//!
//! - A steady regime gives the synchronously averaged order amplitudes of each station.
//! - A long steady run (at least [`LONG_RUN_S`]) is cut into [`LONG_RUN_BLOCKS`] time
//!   blocks, each analysed like a regime: the drift of the amplitudes over the run.
//! - A run-up gives its STFT order tracks, averaged in speed bins of [`BIN_RPM`].
//!
//! Noise: a steady amplitude's σ is the scatter of the same amplitude over [`PARTS`]
//! quarters of the record, divided by √PARTS, pooled over the orders of the station (white
//! noise is the same at every order). A run-up bin's σ comes from that pooled sample noise
//! through the STFT window's length and the windows averaged.

use super::DiagnoseError;
use super::LabelledRecording;
use crate::recording::{Recording, classify};
use crate::signal::{Analysis, AnalysisOptions, analyse_with};

/// Time blocks of a long run.
pub const LONG_RUN_BLOCKS: usize = 4;
/// Speed bin of a run-up, rpm.
pub const BIN_RPM: f64 = 100.0;
/// Parts of a record whose scatter gives the noise.
const PARTS: usize = 4;

/// How a recording is compared: its shape, by the one classifier
/// ([`crate::recording::classify`]), with the speeds this analysis measures.
pub use crate::recording::RunShape;
/// A steady recording at least this long is a long run (the classifier's rule).
pub use crate::recording::shape::{LONG_RUN_S, duration_s};

/// A recording as the diagnosis sees it.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// Label.
    pub label: String,
    /// How it is compared.
    pub regime: RunShape,
    /// Engine load 0..1.
    pub load: f64,
    /// Recorded duration, s.
    pub duration_s: f64,
    /// Sample rate, Hz.
    pub rate_hz: f64,
    /// Reference node.
    pub reference: String,
    /// Speed stations (nodes), in column order.
    pub stations: Vec<String>,
    /// Run-ups: the measured STFT window speeds, rpm (the bins follow them).
    pub window_speeds_rpm: Vec<f64>,
    /// Run-ups: the measured STFT window centres, s from the first sample.
    pub window_times_s: Vec<f64>,
    /// Lines per revolution of each station's tape or encoder (sidecar `sensors`), if
    /// known.
    pub lines_per_rev: Vec<Option<u32>>,
    /// Steady runs: the mean reference speed of each working cycle, per part (one part,
    /// or the blocks of a long run), rpm — the bench's slow wobble of the mean speed.
    pub cycle_speeds_rpm: Vec<Vec<f64>>,
}

/// One compared amplitude.
#[derive(Debug, Clone, PartialEq)]
pub struct Observation {
    /// Index of its [`Run`].
    pub run: usize,
    /// Long runs: the time block; run-ups: the speed bin; steady: 0.
    pub part: usize,
    /// Station (node).
    pub station: String,
    /// Engine order.
    pub order: f64,
    /// Mean reference speed, rpm.
    pub speed_rpm: f64,
    /// Middle of the time block, s (long runs), else the record's middle.
    pub time_s: f64,
    /// Measured amplitude, rpm zero-to-peak.
    pub measured_rpm: f64,
    /// Its noise, rpm (one σ).
    pub sigma_rpm: f64,
    /// The noise of each estimate whose magnitudes were averaged into `measured_rpm`, rpm
    /// (one σ): `sigma_rpm` for a steady amplitude (one estimate), one STFT window's for
    /// a run-up bin. It sets the Rayleigh/Rice bias, which averaging magnitudes keeps.
    pub bias_sigma_rpm: f64,
}

/// Every recording analysed.
#[derive(Debug, Clone, PartialEq)]
pub struct Observed {
    /// The runs, in the order given.
    pub runs: Vec<Run>,
    /// The amplitudes.
    pub observations: Vec<Observation>,
    /// Sample noise per station and run, rpm (`[run][station]`), for the report.
    pub sample_noise_rpm: Vec<Vec<f64>>,
}

/// The analysis options of a diagnosis: no relative speeds, orders up to `max_order`, a
/// run-up's order tracks without its spectrogram.
pub fn analysis_options(max_order: f64) -> AnalysisOptions {
    AnalysisOptions {
        samples_per_rev: samples_per_rev(max_order),
        max_order,
        track_max_order: max_order,
        pairs: Some(Vec::new()),
        spectrogram: false,
        ..AnalysisOptions::default()
    }
}

/// Angle-domain points per revolution for orders up to `max_order`: at least
/// [`POINTS_PER_PERIOD`] per period of the highest order, a power of two, no more than
/// the analysis' default (the cost of every analysis, measured or simulated, is
/// proportional to it).
pub fn samples_per_rev(max_order: f64) -> usize {
    let wanted = (POINTS_PER_PERIOD * max_order).ceil().max(16.0) as usize;
    wanted
        .next_power_of_two()
        .min(crate::signal::resample::SAMPLES_PER_REV)
}

/// Angle-domain points per period of the highest analysed order.
const POINTS_PER_PERIOD: f64 = 8.0;

/// The samples of `recording` from `from_s` to `to_s` (relative to its first sample).
///
/// The cut is made on the sample index, `i·Δt` with Δt the recording's mean step, not on
/// the printed clock: a DAQ's time column rounded to the microsecond, or a clock that starts
/// at 187.6 s, must not move a sample across a boundary (issue 14, item 1).
pub fn slice(recording: &Recording, from_s: f64, to_s: f64) -> Recording {
    let n = recording.time_s.len();
    let step_s = if n > 1 {
        duration_s(recording) / n as f64
    } else {
        0.0
    };
    let index = |at_s: f64| {
        if step_s > 0.0 {
            // The first index whose nominal time i·Δt is not before `at_s` (a boundary
            // on a sample, within 1e-9 of a step of round-off, keeps that sample).
            let i = (at_s / step_s - 1e-9).ceil().max(0.0);
            (if i.is_finite() { i as usize } else { n }).min(n)
        } else {
            usize::from(at_s > 0.0).min(n)
        }
    };
    let (lo, hi) = (index(from_s), index(to_s));
    let hi = hi.max(lo);
    let mut out = recording.clone();
    out.time_s = recording.time_s[lo..hi].to_vec();
    for c in &mut out.channels {
        c.values = c.values[lo..hi].to_vec();
    }
    out
}

/// Analyses every recording.
pub fn observe(
    recordings: &[LabelledRecording],
    max_order: f64,
) -> Result<Observed, DiagnoseError> {
    let options = analysis_options(max_order);
    let mut observed = Observed {
        runs: Vec::new(),
        observations: Vec::new(),
        sample_noise_rpm: Vec::new(),
    };
    // Run-ups wait for the sample noise of the steady runs: `(run, analysis)`.
    let mut run_ups: Vec<(usize, Analysis)> = Vec::new();
    for (i, lr) in recordings.iter().enumerate() {
        let fail = |message: String| DiagnoseError::Analysis {
            label: lr.label.clone(),
            message,
        };
        let rec = &lr.recording;
        let analysis = analyse_with(rec, &options).map_err(|e| fail(e.to_string()))?;
        let duration = duration_s(rec);
        let rate_hz = match (rec.time_s.first(), rec.time_s.last()) {
            (Some(a), Some(b)) if b > a => (rec.time_s.len() - 1) as f64 / (b - a),
            _ => return Err(fail("fewer than two samples".into())),
        };
        let stations: Vec<String> = analysis.stations.iter().map(|s| s.name.clone()).collect();
        let reference_speed = analysis
            .stations
            .iter()
            .find(|s| s.name == analysis.reference)
            .map_or(0.0, |s| s.mean_speed_rpm);
        let mut run = Run {
            label: lr.label.clone(),
            regime: RunShape::Steady {
                speed_rpm: reference_speed,
            },
            load: rec.meta.load,
            duration_s: duration,
            rate_hz,
            reference: analysis.reference.clone(),
            stations: stations.clone(),
            window_speeds_rpm: Vec::new(),
            window_times_s: Vec::new(),
            lines_per_rev: stations
                .iter()
                .map(|s| rec.meta.sensors.get(s).and_then(|x| x.lines_per_rev))
                .collect(),
            cycle_speeds_rpm: Vec::new(),
        };
        let noise = match classify(rec) {
            RunShape::LongRun { .. } => {
                run.regime = RunShape::LongRun {
                    speed_rpm: reference_speed,
                };
                let (noise, cycles) =
                    long_run(&mut observed, i, rec, duration, &options).map_err(fail)?;
                run.cycle_speeds_rpm = cycles;
                noise
            }
            RunShape::Steady { .. } => {
                run.cycle_speeds_rpm =
                    vec![cycle_speeds(rec, &analysis.reference, analysis.cycle_rev)];
                let noise = steady_noise(rec, duration, &options, &analysis).map_err(fail)?;
                push_steady(
                    &mut observed,
                    i,
                    0,
                    (rec, &analysis),
                    &noise,
                    duration / 2.0,
                );
                noise
                    .iter()
                    .map(|s| sample_noise(*s, rec.time_s.len()))
                    .collect()
            }
            RunShape::Ramp { .. } => {
                let t0 = rec.time_s.first().copied().unwrap_or(0.0);
                let (from, to, speeds) = ramp_of(&analysis, t0, duration).map_err(fail)?;
                // Relative to the first sample, as the simulated run-up's windows are: a
                // bench clock that starts at 131.4 s must not move every window out of
                // the simulation's bins (issue 14: `none` controls simulated as 0 rpm).
                run.window_times_s = analysis
                    .stft
                    .as_ref()
                    .map_or(Vec::new(), |s| s.times_s.iter().map(|t| t - t0).collect());
                run.regime = RunShape::Ramp {
                    from_rpm: from,
                    to_rpm: to,
                };
                run.window_speeds_rpm = speeds;
                run_ups.push((i, analysis));
                Vec::new()
            }
        };
        observed.runs.push(run);
        observed.sample_noise_rpm.push(noise);
    }
    // Run-ups take the sample noise of the steady runs (median per station), never below
    // their own column's quantisation noise q/√12 ([`amplitude_floor`]).
    for (i, analysis) in run_ups {
        let rec = &recordings[i].recording;
        let noise: Vec<f64> = observed.runs[i]
            .stations
            .iter()
            .map(|s| {
                let q = resolution_rpm(rec.speed_rpm(s).unwrap_or(&[]));
                median_noise(&observed, s).max(q / 12f64.sqrt())
            })
            .collect();
        super::observe_runup::push_run_up(&mut observed, i, &analysis, &noise);
        observed.sample_noise_rpm[i] = noise;
    }
    Ok(observed)
}

/// The mean reference speed of each whole working cycle of `rec` (`cycle_rev`
/// revolutions), rpm.
pub fn cycle_speeds(rec: &Recording, reference: &str, cycle_rev: f64) -> Vec<f64> {
    let Some(speed) = rec.speed_rpm(reference) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    let (mut angle_rev, mut sum, mut count) = (0.0, 0.0, 0usize);
    for (k, v) in speed.iter().enumerate() {
        let dt = match (rec.time_s.get(k), rec.time_s.get(k + 1)) {
            (Some(a), Some(b)) => b - a,
            _ => break,
        };
        angle_rev += v / 60.0 * dt;
        sum += v;
        count += 1;
        if angle_rev >= cycle_rev {
            out.push(sum / count as f64);
            angle_rev -= cycle_rev;
            sum = 0.0;
            count = 0;
        }
    }
    out
}

/// The median sample noise of `station` over the steady runs (0.1 rpm when none has it).
fn median_noise(observed: &Observed, station: &str) -> f64 {
    let mut values: Vec<f64> = observed
        .runs
        .iter()
        .zip(&observed.sample_noise_rpm)
        .filter_map(|(r, n)| {
            n.get(r.stations.iter().position(|s| s == station)?)
                .copied()
        })
        .filter(|x| x.is_finite() && *x > 0.0)
        .collect();
    values.sort_by(f64::total_cmp);
    values.get(values.len() / 2).copied().unwrap_or(0.1)
}

/// Sample noise (rpm per sample) from an amplitude σ of a record of `samples` samples:
/// σ_amp = σ_n √(2/N).
fn sample_noise(sigma_amplitude: f64, samples: usize) -> f64 {
    sigma_amplitude * (samples as f64 / 2.0).sqrt()
}

/// The quantisation step of a speed column, rpm: the smallest positive difference
/// between two of its distinct values (0 for fewer than two distinct values).
fn resolution_rpm(values: &[f64]) -> f64 {
    let mut v: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
    v.sort_by(f64::total_cmp);
    v.windows(2)
        .map(|w| w[1] - w[0])
        .filter(|d| *d > 0.0)
        .min_by(f64::total_cmp)
        .unwrap_or(0.0)
}

/// Per station of `analysis`, the smallest σ an order amplitude of `rec` can have, rpm:
/// the quantisation noise of its speed column (step `q`, uniform error: `q/√12` per
/// sample) carried to an amplitude of `N` samples, `q/√12 · √(2/N)`; never below the
/// column's floating-point resolution (`ε` times its mean), so that a noise-free record
/// still has a finite z. Replaces a fixed 1e-4 rpm (issue 14, item 5: noise from each
/// campaign): an encoder whose pulse clock prints microseconds resolves far coarser.
pub fn amplitude_floor(rec: &Recording, analysis: &Analysis) -> Vec<f64> {
    let n = rec.time_s.len().max(1) as f64;
    analysis
        .stations
        .iter()
        .map(|s| {
            let values = rec.speed_rpm(&s.name).unwrap_or(&[]);
            let quantised = resolution_rpm(values) / 12f64.sqrt() * (2.0 / n).sqrt();
            quantised.max(f64::EPSILON * s.mean_speed_rpm.abs().max(1.0))
        })
        .collect()
}

/// Pushes the order amplitudes of every station of a steady `analysis` of `rec`.
fn push_steady(
    observed: &mut Observed,
    run: usize,
    part: usize,
    (rec, analysis): (&Recording, &Analysis),
    noise: &[f64],
    time_s: f64,
) {
    let floor = amplitude_floor(rec, analysis);
    let speed = analysis
        .stations
        .iter()
        .find(|s| s.name == analysis.reference)
        .map_or(0.0, |s| s.mean_speed_rpm);
    for ((station, sigma), floor) in analysis.stations.iter().zip(noise).zip(floor) {
        let sigma = sigma.max(floor);
        for o in station.orders.iter().filter(|o| o.order > 0.0) {
            observed.observations.push(Observation {
                run,
                part,
                station: station.name.clone(),
                order: o.order,
                speed_rpm: speed,
                time_s,
                measured_rpm: o.amplitude,
                sigma_rpm: sigma,
                bias_sigma_rpm: sigma,
            });
        }
    }
}

/// σ of each station's order amplitudes from the scatter over [`PARTS`] parts (`whole`:
/// the analysis of all of `rec`).
fn steady_noise(
    rec: &Recording,
    duration: f64,
    options: &AnalysisOptions,
    whole: &Analysis,
) -> Result<Vec<f64>, String> {
    let parts: Vec<Analysis> = (0..PARTS)
        .map(|k| {
            let (a, b) = (
                duration * k as f64 / PARTS as f64,
                duration * (k + 1) as f64 / PARTS as f64,
            );
            analyse_with(&slice(rec, a, b), options).map_err(|e| e.to_string())
        })
        .collect::<Result<_, _>>()?;
    Ok((0..whole.stations.len())
        .map(|s| {
            let Some(first) = parts[0].stations.get(s) else {
                return f64::NAN;
            };
            // E[a_k²] = A² + 2s² for each part; the whole record's A_w² = A² + 2s²/P. So
            // 2s²(1 − 1/P) = mean(a_k²) − A_w² for every order; the median over the orders
            // resists the large orders, whose parts differ by more than noise (the wobble).
            // s is the per-component noise of one part, s/√P that of the whole record.
            let mut excess: Vec<f64> = Vec::new();
            let mut spread: Vec<f64> = Vec::new();
            for (k, o) in first
                .orders
                .iter()
                .enumerate()
                .filter(|(_, o)| o.order > 0.0)
            {
                let xs: Vec<f64> = parts
                    .iter()
                    .filter_map(|p| p.stations.get(s)?.orders.get(k))
                    .filter(|x| x.order == o.order)
                    .map(|x| x.amplitude)
                    .collect();
                let whole = whole
                    .stations
                    .get(s)
                    .and_then(|w| w.orders.iter().find(|x| x.order == o.order));
                if let (true, Some(w)) = (xs.len() == PARTS, whole) {
                    let mean_sq = xs.iter().map(|x| x * x).sum::<f64>() / PARTS as f64;
                    excess.push(mean_sq - w.amplitude * w.amplitude);
                    let mean = xs.iter().sum::<f64>() / PARTS as f64;
                    let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>();
                    spread.push(var / (PARTS as f64 - 1.0));
                }
            }
            excess.sort_by(f64::total_cmp);
            spread.sort_by(f64::total_cmp);
            let median = excess.get(excess.len() / 2).copied().unwrap_or(0.0);
            // Where every order of a station carries a line (a tape joint's, at each
            // shaft order), the whole record's amplitudes can exceed the parts' by more
            // than the noise, and the excess goes to zero or below: benchtruth case 101320
            // (a 6.3 % joint at 78 lines, 5000 Hz) got σ = 2.6e-6 rpm, the column's
            // quantisation, where its parts scatter by 0.02 rpm. The parts' own scatter
            // bounds σ from below: for a line it is the noise along it, s²; for an order
            // with noise only, (2 − π/2) s².
            let scatter = spread.get(spread.len() / 2).copied().unwrap_or(0.0);
            let s_part_sq = (median.max(0.0) / (2.0 * (1.0 - 1.0 / PARTS as f64))).max(scatter);
            (s_part_sq / PARTS as f64).sqrt()
        })
        .collect())
}

/// The blocks of a long run; returns the sample noise per station and the cycle speeds
/// of each block.
fn long_run(
    observed: &mut Observed,
    run: usize,
    rec: &Recording,
    duration: f64,
    options: &AnalysisOptions,
) -> Result<(Vec<f64>, Vec<Vec<f64>>), String> {
    let block = duration / LONG_RUN_BLOCKS as f64;
    let mut noise_sum: Vec<f64> = Vec::new();
    let mut cycles = Vec::with_capacity(LONG_RUN_BLOCKS);
    for b in 0..LONG_RUN_BLOCKS {
        let part = slice(rec, b as f64 * block, (b + 1) as f64 * block);
        let analysis = analyse_with(&part, options).map_err(|e| e.to_string())?;
        cycles.push(cycle_speeds(&part, &analysis.reference, analysis.cycle_rev));
        let noise = steady_noise(&part, block, options, &analysis)?;
        push_steady(
            observed,
            run,
            b,
            (&part, &analysis),
            &noise,
            (b as f64 + 0.5) * block,
        );
        noise_sum.resize(noise.len(), 0.0);
        for (acc, s) in noise_sum.iter_mut().zip(&noise) {
            *acc += sample_noise(*s, part.time_s.len()) / LONG_RUN_BLOCKS as f64;
        }
    }
    Ok((noise_sum, cycles))
}

/// The measured ramp of a run-up: speed at the first and last sample (a straight line
/// fitted to the STFT window speeds) and the window speeds.
fn ramp_of(analysis: &Analysis, t0_s: f64, duration: f64) -> Result<(f64, f64, Vec<f64>), String> {
    let stft = analysis
        .stft
        .as_ref()
        .ok_or_else(|| "a run-up without its STFT".to_string())?;
    let (t, v) = (&stft.times_s, &stft.speeds_rpm);
    let n = t.len() as f64;
    if t.len() < 2 {
        return Err("a run-up shorter than two STFT windows".into());
    }
    let (mt, mv) = (t.iter().sum::<f64>() / n, v.iter().sum::<f64>() / n);
    let sxy: f64 = t.iter().zip(v).map(|(a, b)| (a - mt) * (b - mv)).sum();
    let sxx: f64 = t.iter().map(|a| (a - mt).powi(2)).sum();
    let slope = sxy / sxx;
    let at = |x: f64| mv + slope * (x - mt);
    Ok((at(t0_s), at(t0_s + duration), v.clone()))
}
