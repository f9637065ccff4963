//! Checks of the diagnosis' parts against exact answers.

use super::LabelledRecording;
use super::holdout::held_out;
use super::observe::{RunShape, cycle_speeds, observe};
use super::residual::expected;
use super::sensor::sinc;
use crate::effects::rng::Rng;
use crate::recording::{Channel, ChannelKind, Recording, RecordingMeta, RunKind};
use std::f64::consts::TAU;

/// A steady recording of the crank at `speed_rpm` with order 2 (`a2` rpm) and order 4
/// (`a4` rpm) and white noise of `noise_rpm` per sample.
pub(super) fn steady(
    label: &str,
    speed_rpm: f64,
    a2: f64,
    a4: f64,
    noise_rpm: f64,
    seed: u64,
) -> LabelledRecording {
    let rate = 2000.0;
    let n = 2000;
    let mut rng = Rng::new(seed);
    let time_s: Vec<f64> = (0..n).map(|k| k as f64 / rate).collect();
    let values = time_s
        .iter()
        .map(|t| {
            let theta = TAU * speed_rpm / 60.0 * t;
            speed_rpm
                + a2 * (2.0 * theta).cos()
                + a4 * (4.0 * theta + 0.3).cos()
                + noise_rpm * rng.normal()
        })
        .collect();
    let mut meta = RecordingMeta::new(RunKind::Steady, "engine");
    meta.speed_rpm = Some(speed_rpm);
    meta.label = Some(label.into());
    LabelledRecording {
        label: label.into(),
        recording: Recording {
            time_s,
            channels: vec![Channel {
                column: "engine_rpm".into(),
                kind: ChannelKind::SpeedRpm {
                    node: "engine".into(),
                },
                values,
            }],
            meta,
        },
    }
}

/// The amplitudes are the ones put in, and the noise estimate is the theory's
/// σ_n·√(2/N) per component within the scatter of an estimate from a few parts.
#[test]
fn a_steady_record_gives_its_orders_and_its_noise() {
    let noise = 0.3;
    let rec = steady("A", 3000.0, 5.0, 2.0, noise, 7);
    let observed = observe(&[rec], 8.0).unwrap();
    let at = |q: f64| observed.observations.iter().find(|o| o.order == q).unwrap();
    // Noise moves an amplitude by about σ (0.01 rpm here).
    assert!((at(2.0).measured_rpm - 5.0).abs() < 0.05, "{:?}", at(2.0));
    assert!((at(4.0).measured_rpm - 2.0).abs() < 0.05, "{:?}", at(4.0));
    let theory = noise * (2.0_f64 / 2000.0).sqrt();
    let sigma = at(2.0).sigma_rpm;
    assert!(
        sigma > 0.5 * theory && sigma < 2.0 * theory,
        "σ {sigma} vs {theory}"
    );
    assert!(matches!(observed.runs[0].regime, RunShape::Steady { .. }));
    // 2000 samples at 2 kHz span 1999 intervals, 0.9995 s at 3000 rpm: 24 whole working
    // cycles (the 25th is 0.05 % short), each at the mean speed within noise.
    let cycles = cycle_speeds(&observed_recording(), "engine", 2.0);
    assert_eq!(cycles.len(), 24);
    assert!(
        cycles.iter().all(|c| (c - 3000.0).abs() < 1.0),
        "{cycles:?}"
    );
}

fn observed_recording() -> Recording {
    steady("A", 3000.0, 5.0, 2.0, 0.3, 7).recording
}

/// The Rice mean of a noisy amplitude: exact for no signal, the signal for a large one.
#[test]
fn expected_amplitude_is_the_rayleigh_mean_without_signal() {
    let sigma = 0.2;
    assert!((expected(0.0, sigma) - sigma * (std::f64::consts::FRAC_PI_2).sqrt()).abs() < 1e-15);
    assert!((expected(100.0, sigma) - 100.0).abs() < 1e-3);
    // A zebra tape's pitch averaging: engine order 2 on 78 lines at 1/3 crank speed.
    assert!((sinc(6.0 / 78.0) - 0.99028).abs() < 1e-4);
}

/// Regimes of one load alternate between fit and held out, in speed order.
#[test]
fn regimes_alternate_between_fit_and_held_out() {
    let recs: Vec<LabelledRecording> = [3000.0, 4000.0, 3500.0]
        .iter()
        .enumerate()
        .map(|(i, s)| steady(&format!("R{i}"), *s, 5.0, 2.0, 0.3, i as u64))
        .collect();
    let observed = observe(&recs, 8.0).unwrap();
    let mask = held_out(&observed);
    let held_runs: Vec<usize> = observed
        .observations
        .iter()
        .zip(&mask)
        .filter(|(_, h)| **h)
        .map(|(o, _)| o.run)
        .collect();
    // 3000 fit, 3500 held out, 4000 fit.
    assert!(
        !held_runs.is_empty() && held_runs.iter().all(|r| *r == 2),
        "{held_runs:?}"
    );
}

/// A run-up bin's window noise from the scatter of consecutive windows: twelve orders of
/// pure noise (Rayleigh magnitudes of σ = 0.3 per component) and four strong orders that
/// rise steeply across the bin give back σ within the scatter of 12 × 39 differences;
/// a bin of one window gives 0.
#[test]
fn run_up_window_noise_comes_from_the_bin_scatter() {
    let sigma = 0.3;
    let mut rng = Rng::new(11);
    let windows = 40;
    let mut tracks: Vec<Vec<f64>> = (0..12)
        .map(|_| {
            (0..windows)
                .map(|_| (sigma * rng.normal()).hypot(sigma * rng.normal()))
                .collect()
        })
        .collect();
    tracks.extend((0..4).map(|k| {
        (0..windows)
            .map(|w| 5.0 + k as f64 + 0.5 * w as f64)
            .collect::<Vec<f64>>()
    }));
    let mut bins: Vec<Option<usize>> = vec![Some(0); windows];
    bins.push(Some(1));
    tracks.iter_mut().for_each(|t| t.push(1.0));
    let scatter = super::observe_runup::window_scatter(&tracks, &bins, 2);
    // Consecutive differences of independent magnitudes: the estimate's relative spread
    // is about 1/√(2·39) per order, the lower quartile of twelve a little below σ.
    assert!(
        scatter[0] > 0.7 * sigma && scatter[0] < 1.2 * sigma,
        "σ {} vs {sigma}",
        scatter[0]
    );
    assert_eq!(scatter[1], 0.0);
}

/// One steady recording leaves nothing held out: refused with the recording named, never
/// "held-out χ²/N from NaN to NaN" (issue 13).
#[test]
fn one_steady_recording_is_refused_not_nan() {
    let recs = vec![steady("Regime A", 3000.0, 5.0, 2.0, 0.3, 1)];
    let observed = observe(&recs, 8.0).unwrap();
    let mask = held_out(&observed);
    let e = super::holdout::check_split(&observed, &mask).unwrap_err();
    let text = e.to_string();
    assert!(
        text.contains("`Regime A`") && text.contains("none to be held out"),
        "{text}"
    );
    let two = vec![
        steady("A", 3000.0, 5.0, 2.0, 0.3, 1),
        steady("B", 3500.0, 5.0, 2.0, 0.3, 2),
    ];
    let observed = observe(&two, 8.0).unwrap();
    assert!(super::holdout::check_split(&observed, &held_out(&observed)).is_ok());
}

/// The noise floor is the recording's own resolution (issue 14, item 5): a noise-free
/// record printed to 0.5 rpm cannot claim amplitudes finer than its quantisation noise
/// `q/√12 · √(2/N)` = 4.6e-3 rpm (N = 2000), where a fixed 1e-4 rpm floor claimed 46
/// times less; unrounded, the floor falls to the column's floating-point resolution.
#[test]
fn the_noise_floor_is_the_recordings_resolution() {
    let mut rec = steady("Q", 3000.0, 5.0, 2.0, 0.0, 1);
    for v in &mut rec.recording.channels[0].values {
        *v = (*v * 2.0).round() / 2.0;
    }
    let observed = observe(&[rec], 8.0).unwrap();
    let floor = 0.5 / 12f64.sqrt() * (2.0 / 2000.0_f64).sqrt();
    for o in &observed.observations {
        assert!(o.sigma_rpm >= floor * (1.0 - 1e-9), "{o:?}");
    }
    let exact = steady("E", 3000.0, 5.0, 2.0, 0.0, 1);
    let observed = observe(&[exact], 8.0).unwrap();
    for o in &observed.observations {
        assert!(o.sigma_rpm > 0.0 && o.sigma_rpm < 1e-3, "{o:?}");
    }
}
