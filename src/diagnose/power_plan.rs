//! The observables of a campaign that has not been run yet (issue 14, item 6): the order
//! amplitudes a diagnosis would compare — per station, per steady regime, per long-run
//! block, per run-up speed bin — each with the σ the order analysis of the planned
//! duration and rate would give under white noise.
//!
//! Noise model, per sample of a station turning at `n` rpm (rate `f_s`):
//! `σ_n² = noise_rpm² + (√2 · jitter · f_s · n)²` — the electronics' white noise and the
//! pulse-edge jitter (`jitter` s) of the two edges that bound a sample's interval
//! (consecutive line intervals' jitter telescopes). Through the order analysis:
//! - a steady record (or a long-run block) of `N` samples: `σ = σ_n · √(2/N)` per order,
//!   the inverse of [`super::observe`]'s `sample_noise`;
//! - a run-up bin of `m` STFT windows of `N_w` samples (0.1 s, half-overlapping, Hann):
//!   `σ_w = σ_n · √(2/N_w) · √1.5`, and `σ = σ_w / √(m/1.5)`, as
//!   [`super::observe_runup::push_run_up`] takes it from a recording.

use super::observe::{BIN_RPM, LONG_RUN_BLOCKS, Observation, Observed, Run, RunShape};
use super::observe_runup::bins;
use crate::campaign::{Plan, Station};
use crate::model::{Model, graph};

/// STFT window of the analysis, s, and its overlap ([`crate::signal::AnalysisOptions`]).
const STFT_WINDOW_S: f64 = 0.1;
const STFT_OVERLAP: f64 = 0.5;
/// Hann window's equivalent noise bandwidth, bins.
const HANN_ENBW: f64 = 1.5;
/// Smallest σ of an amplitude, rpm (as [`super::observe`]).
const MIN_SIGMA_RPM: f64 = 1e-4;

/// How the planned campaign is measured.
#[derive(Debug, Clone, PartialEq)]
pub struct Bench {
    /// Stations (node and sensor).
    pub stations: Vec<Station>,
    /// Sample rate, Hz, unless a run gives its own (default 2048, `torsim synth`'s).
    pub rate_hz: f64,
    /// White noise of every sample, rpm (default 0.1, `torsim synth`'s).
    pub noise_rpm: f64,
    /// Pulse-edge jitter, ns (default 20, `torsim synth`'s).
    pub jitter_ns: f64,
    /// Highest engine order compared (default 8).
    pub max_order: f64,
}

impl Bench {
    /// `torsim synth`'s bench on `model`: its default stations, 2048 Hz, 0.1 rpm, 20 ns.
    pub fn default_for(model: &Model) -> Self {
        Self {
            stations: Station::defaults(model),
            rate_hz: 2048.0,
            noise_rpm: 0.1,
            jitter_ns: 20.0,
            max_order: 8.0,
        }
    }

    /// Per-sample noise of a station at `speed_rpm`, rpm (module docs).
    pub fn sample_noise_rpm(&self, rate_hz: f64, speed_rpm: f64) -> f64 {
        let jitter = std::f64::consts::SQRT_2 * self.jitter_ns * 1e-9 * rate_hz * speed_rpm.abs();
        self.noise_rpm.hypot(jitter)
    }
}

/// The engine orders compared: multiples of the cycle order up to `max_order`.
pub fn orders(model: &Model, max_order: f64) -> Vec<f64> {
    let step = if model.strokes() == 2 { 1.0 } else { 0.5 };
    (1..)
        .map(|k| f64::from(k) * step)
        .take_while(|q| *q <= max_order + 1e-9)
        .collect()
}

/// The observables of `plan` measured by `bench` on `model`, with the amplitudes left 0
/// (the caller fills `measured_rpm` with a prediction). `None` when the model has no
/// reference node.
pub fn planned(model: &Model, plan: &Plan, bench: &Bench) -> Option<Observed> {
    let reference = model.inertias[graph::reference_node(model)?].name.clone();
    let ratios: Vec<(String, f64)> = super::surrogate::ratios(model);
    let ratio = |node: &str| {
        ratios
            .iter()
            .find(|(n, _)| n == node)
            .map_or(1.0, |(_, r)| r.abs())
    };
    let qs = orders(model, bench.max_order);
    let mut observed = Observed {
        runs: Vec::new(),
        observations: Vec::new(),
        sample_noise_rpm: Vec::new(),
    };
    for (r, p) in plan.runs.iter().enumerate() {
        let rate_hz = p.rate_hz.unwrap_or(bench.rate_hz);
        let mut run = Run {
            label: p.label.clone(),
            regime: RunShape::Steady { speed_rpm: 0.0 },
            load: p.load,
            duration_s: p.duration_s,
            rate_hz,
            reference: reference.clone(),
            stations: bench.stations.iter().map(|s| s.node.clone()).collect(),
            window_speeds_rpm: Vec::new(),
            window_times_s: Vec::new(),
            lines_per_rev: bench
                .stations
                .iter()
                .map(|s| Some(s.lines_per_rev))
                .collect(),
            cycle_speeds_rpm: Vec::new(),
        };
        let mut push = |part: usize, speed_rpm: f64, time_s: f64, samples: f64, windows: f64| {
            for s in &bench.stations {
                let sigma_n = bench.sample_noise_rpm(rate_hz, speed_rpm * ratio(&s.node));
                let (sigma, bias) = if windows > 0.0 {
                    let w = sigma_n * (2.0 / samples).sqrt() * HANN_ENBW.sqrt();
                    (w / (windows / 1.5).max(1.0).sqrt(), w)
                } else {
                    let a = sigma_n * (2.0 / samples).sqrt();
                    (a, a)
                };
                for q in &qs {
                    observed.observations.push(Observation {
                        run: r,
                        part,
                        station: s.node.clone(),
                        order: *q,
                        speed_rpm,
                        time_s,
                        measured_rpm: 0.0,
                        sigma_rpm: sigma.max(MIN_SIGMA_RPM),
                        bias_sigma_rpm: bias.max(MIN_SIGMA_RPM),
                    });
                }
            }
        };
        run.regime = p.shape;
        match p.shape {
            RunShape::LongRun { speed_rpm } => {
                let block = p.duration_s / LONG_RUN_BLOCKS as f64;
                for b in 0..LONG_RUN_BLOCKS {
                    push(b, speed_rpm, (b as f64 + 0.5) * block, block * rate_hz, 0.0);
                }
            }
            RunShape::Steady { speed_rpm } => {
                push(
                    0,
                    speed_rpm,
                    p.duration_s / 2.0,
                    p.duration_s * rate_hz,
                    0.0,
                );
            }
            RunShape::Ramp { from_rpm, to_rpm } => {
                let (times, speeds) = windows(from_rpm, to_rpm, p.duration_s, rate_hz);
                let (window_bins, bin_speeds) = bins(&speeds);
                for (b, v) in bin_speeds.iter().enumerate() {
                    let m = window_bins.iter().filter(|x| **x == Some(b)).count();
                    if v.is_finite() && m >= 2 {
                        push(b, *v, p.duration_s / 2.0, STFT_WINDOW_S * rate_hz, m as f64);
                    }
                }
                run.window_times_s = times;
                run.window_speeds_rpm = speeds;
            }
        }
        observed.runs.push(run);
        observed
            .sample_noise_rpm
            .push(vec![bench.noise_rpm; bench.stations.len()]);
    }
    Some(observed)
}

/// The STFT window centres (s) of a planned ramp and the reference speed at each, rpm.
fn windows(from_rpm: f64, to_rpm: f64, duration_s: f64, rate_hz: f64) -> (Vec<f64>, Vec<f64>) {
    let len = (STFT_WINDOW_S * rate_hz).round().max(1.0);
    let hop = (len * (1.0 - STFT_OVERLAP)).round().max(1.0);
    let samples = (duration_s * rate_hz).floor();
    if samples < len || duration_s <= 0.0 {
        return (Vec::new(), Vec::new());
    }
    let count = ((samples - len) / hop).floor() as usize + 1;
    let slope = (to_rpm - from_rpm) / duration_s;
    (0..count)
        .map(|i| {
            let t = (i as f64 * hop + len / 2.0) / rate_hz;
            (t, from_rpm + slope * t)
        })
        .unzip()
}

/// Run-up bins are [`BIN_RPM`] wide: the planned number of bins of a ramp.
pub fn bin_count(from_rpm: f64, to_rpm: f64) -> usize {
    ((to_rpm - from_rpm).abs() / BIN_RPM).ceil() as usize
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::campaign::PlanDurations;
    use crate::model::{parse_model, presets};

    fn bench_model() -> Model {
        let p = presets::preset("diagnosis-bench").expect("shipped");
        parse_model(p.text, "diagnosis-bench.toml").expect("parses")
    }

    /// A steady 4 s regime at 2048 Hz with 0.1 rpm and no jitter: σ = 0.1·√(2/8192)
    /// = 1.5625e-3 rpm for every order, exactly the formula.
    #[test]
    fn steady_sigma_follows_the_formula() {
        let model = bench_model();
        let mut bench = Bench::default_for(&model);
        bench.jitter_ns = 0.0;
        let plan = Plan::default_for(&model, PlanDurations::default()).expect("plan");
        let o = planned(&model, &plan, &bench).expect("observables");
        let first = &o.observations[0];
        assert!(matches!(o.runs[0].regime, RunShape::Steady { .. }));
        assert!((first.sigma_rpm - 0.1 * (2.0_f64 / 8192.0).sqrt()).abs() < 1e-12);
        // Orders 0.5 … 8 of a four-stroke engine at every station.
        assert_eq!(orders(&model, 8.0).len(), 16);
        assert!(
            o.runs
                .iter()
                .any(|r| matches!(r.regime, RunShape::LongRun { .. }))
        );
        let run_up = o
            .runs
            .iter()
            .position(|r| matches!(r.regime, RunShape::Ramp { .. }))
            .expect("a run-up");
        assert!(
            o.observations
                .iter()
                .any(|x| x.run == run_up && x.part > 10)
        );
    }
}
