//! Measured against simulated, in units of the noise.
//!
//! A measured order amplitude is the magnitude of the signal's component plus complex
//! noise of σ per component, so it is biased up where the signal is small (Rayleigh, Rice):
//! its mean is close to `√(A² + (π/2)σ²)`, exact for `A = 0` and within `σ²/(4A)` for
//! `A ≫ σ`. The residual compares with that mean, and divides by the noise with a model
//! floor: `z = (a − √(A² + (π/2)σ_b²)) / √(σ² + (FLOOR·A)²)`, where `σ_b` is the noise
//! of one averaged estimate (a run-up bin averages window magnitudes: its spread falls
//! with their number, its bias does not) and `σ` that of `a` itself.

use super::observe::{Observed, RunShape};
use std::f64::consts::FRAC_PI_2;

/// Relative accuracy asked of the simulation itself (integration tolerance, the
/// linear-model corrections for speed spread and sensors): 0.5 %.
pub const FLOOR: f64 = 0.005;
/// The same for a run-up's binned STFT tracks, 3 %: a resonance swept at a few hundred
/// rpm/s and windows of 0.1 s make the binned amplitudes sensitive to timing (and the
/// tracks of weak orders next to strong ones are window leakage).
pub const FLOOR_RUN_UP: f64 = 0.03;

/// The expected measured amplitude of a simulated amplitude `a` under noise `sigma`.
pub fn expected(a: f64, sigma: f64) -> f64 {
    (a * a + FRAC_PI_2 * sigma * sigma).sqrt()
}

/// `z` of every observation for the simulated amplitudes `simulated`.
pub fn z_scores(observed: &Observed, simulated: &[f64]) -> Vec<f64> {
    observed
        .observations
        .iter()
        .zip(simulated)
        .map(|(o, &a)| {
            let floor = match observed.runs[o.run].regime {
                RunShape::Ramp { .. } => FLOOR_RUN_UP,
                _ => FLOOR,
            };
            let sigma = (o.sigma_rpm.powi(2) + (floor * a).powi(2)).sqrt();
            (o.measured_rpm - expected(a, o.bias_sigma_rpm)) / sigma
        })
        .collect()
}

/// χ² per observation over the observations `mask` selects (NaN when none).
pub fn chi2_per_point(z: &[f64], mask: &[bool]) -> f64 {
    let (sum, n) = z
        .iter()
        .zip(mask)
        .filter(|(_, m)| **m)
        .fold((0.0, 0usize), |(s, n), (z, _)| (s + z * z, n + 1));
    if n == 0 { f64::NAN } else { sum / n as f64 }
}
