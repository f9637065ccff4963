//! Synthetic IAS recordings with known order content, generated in the angle domain.
//!
//! n(θ, t) = n_mean(t) + Σ a_q cos(q θ + φ_q), with θ the crank angle (rad) from t = 0
//! and dθ/dt = n · 2π/60, integrated by RK4 with 32 sub-steps per sample (the step error
//! is below 1e-12 rev), then sampled at the recording's rate.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use torsim::recording::{Channel, ChannelKind, Recording, RecordingMeta, RunKind};

#[path = "../scratch/mod.rs"]
mod scratch;
pub use scratch::Scratch;

/// One order line: (order, amplitude rpm, phase rad).
pub type Line = (f64, f64, f64);

/// Speed and angle at time `t` for a mean-speed law and order lines.
pub fn speed(mean: &dyn Fn(f64) -> f64, lines: &[Line], theta: f64, t: f64) -> f64 {
    mean(t)
        + lines
            .iter()
            .map(|(q, a, phi)| a * (q * theta + phi).cos())
            .sum::<f64>()
}

/// Samples the speed at `rate_hz` for `duration_s`: (times, speeds rpm).
pub fn generate(
    mean: &dyn Fn(f64) -> f64,
    lines: &[Line],
    rate_hz: f64,
    duration_s: f64,
) -> (Vec<f64>, Vec<f64>) {
    let (t, n, _) = generate_with_angle(mean, lines, rate_hz, duration_s);
    (t, n)
}

/// As [`generate`], also returning the angle θ (rad) at each sample.
pub fn generate_with_angle(
    mean: &dyn Fn(f64) -> f64,
    lines: &[Line],
    rate_hz: f64,
    duration_s: f64,
) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let n = (duration_s * rate_hz).round() as usize;
    let sub = 32;
    let h = 1.0 / (rate_hz * sub as f64);
    let w = std::f64::consts::PI / 30.0; // rpm → rad/s
    let f = |t: f64, th: f64| w * speed(mean, lines, th, t);
    let (mut times, mut speeds) = (Vec::with_capacity(n), Vec::with_capacity(n));
    let mut angles = Vec::with_capacity(n);
    let mut theta = 0.0;
    for k in 0..n {
        let t0 = k as f64 / rate_hz;
        times.push(t0);
        angles.push(theta);
        speeds.push(speed(mean, lines, theta, t0));
        for s in 0..sub {
            let t = t0 + s as f64 * h;
            let k1 = f(t, theta);
            let k2 = f(t + h / 2.0, theta + h / 2.0 * k1);
            let k3 = f(t + h / 2.0, theta + h / 2.0 * k2);
            let k4 = f(t + h, theta + h * k3);
            theta += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        }
    }
    (times, speeds, angles)
}

/// A recording of speed stations (node, speeds) sampled at `time_s`.
pub fn recording(kind: RunKind, time_s: Vec<f64>, stations: Vec<(&str, Vec<f64>)>) -> Recording {
    let reference = stations[0].0.to_string();
    Recording {
        time_s,
        channels: stations
            .into_iter()
            .map(|(node, v)| Channel::new(ChannelKind::SpeedRpm { node: node.into() }, v))
            .collect(),
        meta: RecordingMeta::new(kind, reference),
    }
}

/// A fresh empty directory under the system temp dir for one test, removed when the
/// returned guard is dropped.
pub fn temp_dir(test: &str) -> Scratch {
    Scratch::new(&format!("torsim-{test}-"))
}

/// Writes `text` to `dir/name` and returns the path.
pub fn put(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write test file");
    path
}
