//! Resampling to the reference shaft's angle (order tracking).
//!
//! The reference angle is the integral of the reference speed, taken on the band-limited
//! interpolant of its samples (exact for band-limited signals, where the trapezoid rule
//! misses 30 % of an order that has 3.4 samples per period). For each target angle the
//! time is found by inverting the angle (monotonic: the reference speed is > 0) with a
//! cubic Hermite between samples, whose end slopes are the measured speeds. A station's
//! signal is then evaluated at those times with the windowed-sinc interpolant
//! ([`kernel`](super::kernel)).
//!
//! Angle zero is the reference angle at the first sample; the grid starts at the first
//! whole working cycle after the kernel's half-width, so cycle `c` covers
//! `[c0 + c, c0 + c + 1)` cycles from angle zero, and order phases refer to the first
//! sample.

use super::SignalError;
use super::kernel::{self, HALF_WIDTH};
use crate::recording::timing;

/// Resampling points per revolution of the reference shaft: order 24 gets 10.7 points
/// per period, a 4-stroke cycle 512 points (a power of two for the FFT).
pub const SAMPLES_PER_REV: usize = 256;

/// How to evaluate a station's signal between its samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Interpolation {
    /// Kaiser-windowed sinc, ±16 samples (the default).
    BandLimited,
    /// Linear: loses 6 % of an order with 7 samples per period. For comparison only.
    Linear,
}

/// A uniform grid of the reference shaft's angle and where each point falls in time.
#[derive(Debug, Clone, PartialEq)]
pub struct AngleGrid {
    /// Points per revolution of the reference shaft.
    pub samples_per_rev: usize,
    /// Points per working cycle.
    pub samples_per_cycle: usize,
    /// Whole working cycles on the grid.
    pub cycles: usize,
    /// Reference angle of the first point, rev from the first sample (a whole number of
    /// cycles).
    pub start_rev: f64,
    /// Fractional sample index of each point (`(t − t₀) / Δt`).
    pub positions: Vec<f64>,
    /// Sampling interval of the recording, s.
    pub dt_s: f64,
    /// Time of the first sample, s.
    pub t0_s: f64,
    /// Reference angle at each sample of the recording, rev from the first.
    pub sample_angle_rev: Vec<f64>,
}

impl AngleGrid {
    /// Position of each recording sample on the grid, in cycles from its start.
    pub fn sample_cycles(&self) -> Vec<f64> {
        let cycle_rev = self.samples_per_cycle as f64 / self.samples_per_rev as f64;
        self.sample_angle_rev
            .iter()
            .map(|a| (a - self.start_rev) / cycle_rev)
            .collect()
    }

    /// Time of each grid point, s.
    pub fn times_s(&self) -> Vec<f64> {
        self.positions
            .iter()
            .map(|p| self.t0_s + p * self.dt_s)
            .collect()
    }
}

/// The sampling interval, s, of time stamps held in memory, judged by
/// [`crate::recording::timing::judge`] like the reader's (one rule for the reader, the
/// analysis, the GUI and the diagnosis): within 0.1 % of a step of the fitted grid.
/// Jittered samples must be resampled first (the reader does it).
pub fn uniform_interval(time_s: &[f64]) -> Result<f64, SignalError> {
    let n = time_s.len();
    let timing = timing::judge(time_s, None).map_err(|fault| match fault.index() {
        Some(k) => SignalError::NonUniform(format!("sample {k} (0-based): {fault}")),
        None => SignalError::TooFewSamples {
            samples: n,
            needed: 2 * HALF_WIDTH + 2,
            margin: HALF_WIDTH,
        },
    })?;
    if !timing.is_uniform() {
        return Err(SignalError::NonUniform(format!(
            "time stamps scatter by up to {:.3e} s, {:.2} % of the {:.6e} s step (more than \
             {} %): resample them onto the fitted grid (recording::timing::regularize, as \
             the reader does)",
            timing.max_residual_s,
            100.0 * timing.max_residual_s / timing.dt_s,
            timing.dt_s,
            100.0 * timing::IN_MEMORY_TOLERANCE_STEPS
        )));
    }
    Ok(timing.dt_s)
}

/// Reference angle at each sample, rev (0 at the first), from the speed in rpm.
pub fn reference_angle_rev(speed_rpm: &[f64], dt_s: f64) -> Vec<f64> {
    let mut angle = Vec::with_capacity(speed_rpm.len());
    let mut theta = 0.0;
    angle.push(theta);
    for k in 0..speed_rpm.len().saturating_sub(1) {
        theta += kernel::integrate_interval(speed_rpm, k) * dt_s / 60.0;
        angle.push(theta);
    }
    angle
}

/// The angle grid of the reference shaft: `samples_per_rev` points per revolution over
/// the whole working cycles (`cycle_rev` revolutions each) that the recording covers
/// away from its ends.
pub fn angle_grid(
    time_s: &[f64],
    reference_rpm: &[f64],
    samples_per_rev: usize,
    cycle_rev: f64,
) -> Result<AngleGrid, SignalError> {
    angle_grid_within(
        time_s,
        reference_rpm,
        samples_per_rev,
        cycle_rev,
        HALF_WIDTH,
    )
}

/// [`angle_grid`] keeping `margin` samples (at least the kernel's [`HALF_WIDTH`]) clear
/// of either end: a signal low-passed first ([`super::antialias`]) is exact only where
/// the filter had samples on both sides.
pub fn angle_grid_within(
    time_s: &[f64],
    reference_rpm: &[f64],
    samples_per_rev: usize,
    cycle_rev: f64,
    margin: usize,
) -> Result<AngleGrid, SignalError> {
    let margin = margin.max(HALF_WIDTH);
    let n = time_s.len();
    if n < 2 * margin + 2 {
        return Err(SignalError::TooFewSamples {
            samples: n,
            needed: 2 * margin + 2,
            margin,
        });
    }
    let dt = uniform_interval(time_s)?;
    if let Some(k) = reference_rpm
        .iter()
        .position(|&n| !(n > 0.0 && n.is_finite()))
    {
        return Err(SignalError::NonPositiveSpeed { time_s: time_s[k] });
    }
    let theta = reference_angle_rev(reference_rpm, dt);
    let (lo, hi) = (theta[margin], theta[n - 1 - margin]);
    let samples_per_cycle = (samples_per_rev as f64 * cycle_rev).round() as usize;
    // Bounded before allocating (issue 13): one over-range speed sample must not ask for
    // terabytes. Checked on the angle itself, which is finite or not, before any cast.
    let limit = crate::limits::current().max_grid_points;
    let points = (hi - lo) * samples_per_rev as f64;
    if points.is_nan() || points > limit as f64 {
        return Err(SignalError::GridTooLarge {
            points,
            limit,
            revolutions: hi - lo,
            samples_per_rev,
        });
    }
    let first_cycle = (lo / cycle_rev).ceil();
    let start_rev = first_cycle * cycle_rev;
    let cycles_f = ((hi - start_rev) / cycle_rev).floor();
    if cycles_f < 1.0 {
        return Err(SignalError::TooShort {
            cycles: ((hi - lo) / cycle_rev).max(0.0),
            needed: (start_rev + cycle_rev - lo) / cycle_rev,
            margin,
        });
    }
    let cycles = cycles_f as usize;
    let total = cycles * samples_per_cycle;
    let mut positions = Vec::with_capacity(total);
    let mut k = margin;
    for i in 0..total {
        let target = start_rev + (i as f64) * cycle_rev / samples_per_cycle as f64;
        while k + 2 < n && theta[k + 1] <= target {
            k += 1;
        }
        let d0 = reference_rpm[k] * dt / 60.0;
        let d1 = reference_rpm[k + 1] * dt / 60.0;
        positions.push(k as f64 + hermite_inverse(theta[k], theta[k + 1], d0, d1, target));
    }
    Ok(AngleGrid {
        samples_per_rev,
        samples_per_cycle,
        cycles,
        start_rev,
        positions,
        dt_s: dt,
        t0_s: time_s[0],
        sample_angle_rev: theta,
    })
}

/// The `u` in [0, 1] where the cubic Hermite through (0, `y0`, slope `d0`) and
/// (1, `y1`, slope `d1`) equals `target`: Newton from the linear guess, kept in range.
fn hermite_inverse(y0: f64, y1: f64, d0: f64, d1: f64, target: f64) -> f64 {
    let dy = y1 - y0;
    let mut u = ((target - y0) / dy).clamp(0.0, 1.0);
    for _ in 0..8 {
        let (u2, u3) = (u * u, u * u * u);
        let value = y0 + d0 * (u3 - 2.0 * u2 + u) + dy * (3.0 * u2 - 2.0 * u3) + d1 * (u3 - u2);
        let slope =
            d0 * (3.0 * u2 - 4.0 * u + 1.0) + dy * (6.0 * u - 6.0 * u2) + d1 * (3.0 * u2 - 2.0 * u);
        if slope <= 0.0 {
            break;
        }
        let step = (value - target) / slope;
        u = (u - step).clamp(0.0, 1.0);
        if step.abs() < 1e-14 {
            break;
        }
    }
    u
}

/// Several signals of one recording on the angle grid. The band-limited kernel's taps at
/// each position are worked out once for all signals of the same length (they depend on
/// the position only): with the stations and the relative speeds of a recording, the
/// interpolation was half of `torsim simulate`'s wall time. Each result is the one
/// [`resample`] gives, to the bit.
pub fn resample_many(grid: &AngleGrid, signals: &[&[f64]], how: Interpolation) -> Vec<Vec<f64>> {
    let len = signals.first().map_or(0, |s| s.len());
    if how == Interpolation::Linear || signals.iter().any(|s| s.len() != len) {
        return signals.iter().map(|s| resample(grid, s, how)).collect();
    }
    let mut out: Vec<Vec<f64>> = signals
        .iter()
        .map(|_| Vec::with_capacity(grid.positions.len()))
        .collect();
    for &p in &grid.positions {
        let taps = kernel::Taps::new(len, p);
        for (o, s) in out.iter_mut().zip(signals) {
            o.push(taps.apply(s));
        }
    }
    out
}

/// A station's signal on the angle grid.
pub fn resample(grid: &AngleGrid, values: &[f64], how: Interpolation) -> Vec<f64> {
    match how {
        Interpolation::BandLimited => grid
            .positions
            .iter()
            .map(|&p| kernel::interpolate(values, p))
            .collect(),
        Interpolation::Linear => grid
            .positions
            .iter()
            .map(|&p| kernel::interpolate_linear(values, p))
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A grid of `positions` only (the other fields play no part in resampling).
    fn grid(positions: Vec<f64>) -> AngleGrid {
        AngleGrid {
            samples_per_rev: 1,
            samples_per_cycle: 1,
            cycles: 1,
            start_rev: 0.0,
            positions,
            dt_s: 1.0,
            t0_s: 0.0,
            sample_angle_rev: Vec::new(),
        }
    }

    /// Shared taps give every signal exactly what its own resampling gives, at the ends
    /// (where taps fall outside the data) as well as inside, and past the data.
    #[test]
    fn resampling_many_signals_at_once_is_resampling_each() {
        let n = 300;
        let a: Vec<f64> = (0..n).map(|k| (0.37 * k as f64).sin() + 2.0).collect();
        let b: Vec<f64> = (0..n).map(|k| (k as f64 * 0.011).exp()).collect();
        let positions: Vec<f64> = (0..700)
            .map(|i| -3.0 + i as f64 * 0.437)
            .chain([0.0, 299.0, 310.5, -40.0])
            .collect();
        let g = grid(positions);
        let many = resample_many(&g, &[&a, &b], Interpolation::BandLimited);
        for (one, signal) in many.iter().zip([&a, &b]) {
            let alone = resample(&g, signal, Interpolation::BandLimited);
            assert_eq!(one.len(), alone.len());
            for (x, y) in one.iter().zip(&alone) {
                assert_eq!(x.to_bits(), y.to_bits());
            }
        }
        // Signals of other lengths are resampled one by one.
        let short = &a[..100];
        let mixed = resample_many(&g, &[&a, short], Interpolation::BandLimited);
        assert_eq!(mixed[1], resample(&g, short, Interpolation::BandLimited));
    }
}
