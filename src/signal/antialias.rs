//! The low-pass a steady recording passes before it is sampled on the angle grid.
//!
//! Order tracking evaluates each signal at the grid's angles ([`super::resample`]):
//! `samples_per_rev` points a revolution, a sampling in angle. Content above the grid's
//! Nyquist order `samples_per_rev / 2` folds back: order `q` reads as order
//! `samples_per_rev − q`. The band-limited interpolation kernel ([`super::kernel`]) only
//! stops what lies above the *time* sampling's Nyquist, so a record sampled faster than
//! the grid needs passes its high orders straight into the low ones.
//!
//! Measured on benchtruth case 101289 (published run 13: a gear mesh mode at 1484 Hz,
//! the diagnosis' grid of 64 points a revolution, its forward model sampled at
//! 10 240 Hz): at 1270 rpm the mesh mode is order 70.1 and folded onto order 6.1, and
//! the simulated IAS of the geared node read 0.18 rpm at order 6.5 where the bench
//! measured 0.005 rpm (z = −69 on the user's model, and 0.0018 rpm at 256 points a
//! revolution). The bench's own recording at 2560 Hz folded too, less (order 5.5 at
//! 0.0020 rpm on 64 points, 0.0007 on 256).
//!
//! The filter: a sinc in the interpolation kernel's Kaiser window ([`super::kernel`],
//! β = 10, about 100 dB of stopband), linear
//! phase, half-amplitude at the grid's Nyquist frequency at the record's lowest speed
//! `f_c`. It is flat (within 1e-5) below 0.7 `f_c`, the orders the kernel itself keeps
//! flat, and stops above 1.3 `f_c`, whose content would fold below 0.7 `f_c`. Its
//! half-width, [`HALF_WIDTH_PER_CUTOFF`] / `(f_c Δt)` samples, is Kaiser's length for that
//! 0.6 `f_c` transition. Samples beyond a record's ends are left out and the weights of
//! those inside renormalised, as the kernel does, so a constant passes exactly.
//!
//! Written here rather than taken from a crate: it is one symmetric FIR of the same
//! Kaiser window as the interpolation kernel, and the DSP crates on crates.io design
//! IIR sections (not linear phase, so they would shift the order phases) or need a
//! filter designed elsewhere.

use super::kernel::kaiser;
use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use std::f64::consts::PI;

/// Half-width of the filter in samples times the cutoff in cycles per sample (Kaiser's
/// length `(A − 8) / (2.285 · 2π · Δ)` for A = 100 dB and a transition Δ = 0.6 `f_c Δt`,
/// halved: 5.3, rounded up).
const HALF_WIDTH_PER_CUTOFF: f64 = 6.0;
/// A cutoff at or above this fraction of the sampling rate needs no filter: what lies
/// between it and the time Nyquist folds onto orders above 0.8 of the grid's Nyquist,
/// beyond the orders any analysis reads.
const NO_FILTER_ABOVE: f64 = 0.4;

/// The angle grid's Nyquist frequency, Hz, at `speed_rpm` of the reference: half the
/// grid's points per revolution times the revolutions per second.
pub fn grid_nyquist_hz(samples_per_rev: usize, speed_rpm: f64) -> f64 {
    0.5 * samples_per_rev as f64 * speed_rpm / 60.0
}

/// A linear-phase low-pass of uniformly sampled signals.
#[derive(Debug, Clone, PartialEq)]
pub struct LowPass {
    /// Weights at lags `0 ..= M` (the filter is symmetric), summing to 1 over `−M ..= M`.
    taps: Vec<f64>,
}

impl LowPass {
    /// The low-pass with its half-amplitude point at `cutoff_hz` for a sampling interval
    /// of `dt_s`; `None` when the cutoff is at or above [`NO_FILTER_ABOVE`] of the rate
    /// (or not a positive finite number), where no filter is needed.
    pub fn new(cutoff_hz: f64, dt_s: f64) -> Option<Self> {
        let c = cutoff_hz * dt_s;
        if !(c.is_finite() && c > 0.0) || c >= NO_FILTER_ABOVE {
            return None;
        }
        let half = (HALF_WIDTH_PER_CUTOFF / c).ceil() as usize;
        let m = half as f64;
        let mut taps: Vec<f64> = (0..=half)
            .map(|j| {
                let x = j as f64;
                let sinc = if j == 0 {
                    1.0
                } else {
                    (2.0 * PI * c * x).sin() / (2.0 * PI * c * x)
                };
                sinc * kaiser(x / (m + 1.0))
            })
            .collect();
        let total = taps[0] + 2.0 * taps[1..].iter().sum::<f64>();
        taps.iter_mut().for_each(|t| *t /= total);
        Some(Self { taps })
    }

    /// Half-width, samples.
    pub fn half_width(&self) -> usize {
        self.taps.len() - 1
    }

    /// `values` low-passed, same length. Near the ends the weights of the samples that
    /// exist are renormalised to sum 1.
    ///
    /// The convolution runs by FFT (realfft), `O(n log n)`: the direct sum costs `2M + 1`
    /// products a sample, and `M` grows with the sampling rate (450 at 40 kHz for a grid
    /// of 64 points a revolution at 1000 rpm), so the direct form took 42 % of the
    /// diagnosis of benchtruth case 2210 (10 kHz, forward model at 40 kHz). The record's
    /// mean is taken out first and put back (the weights sum to 1 everywhere), so the
    /// transform's rounding scales with the vibration, not with the mean speed; it agrees
    /// with the direct sum within 1e-11 rpm (`tests`).
    pub fn apply(&self, values: &[f64]) -> Vec<f64> {
        self.apply_all(&[values]).pop().unwrap_or_default()
    }

    /// Each of `signals` low-passed as by [`Self::apply`]; the transform plan, the
    /// kernel's spectrum and the end weights are made once for all signals of a length
    /// (a recording's channels share theirs).
    pub fn apply_all(&self, signals: &[&[f64]]) -> Vec<Vec<f64>> {
        let mut convolver: Option<Convolver> = None;
        signals
            .iter()
            .map(|values| {
                let n = values.len();
                if convolver.as_ref().is_none_or(|c| c.n != n) {
                    convolver = Some(Convolver::new(&self.taps, n));
                }
                convolver
                    .as_ref()
                    .and_then(|c| c.apply(values))
                    .unwrap_or_else(|| self.apply_direct(values))
            })
            .collect()
    }

    /// The direct sum of [`Self::apply`], `O(n·M)`: the reference its transform is checked
    /// against, and its fallback.
    fn apply_direct(&self, values: &[f64]) -> Vec<f64> {
        let n = values.len();
        let m = self.half_width();
        (0..n)
            .map(|i| {
                let lo = i.saturating_sub(m);
                let hi = (i + m).min(n.saturating_sub(1));
                let (mut sum, mut weight) = (0.0, 0.0);
                for (k, v) in values.iter().enumerate().take(hi + 1).skip(lo) {
                    let w = self.taps[k.abs_diff(i)];
                    sum += w * v;
                    weight += w;
                }
                if weight == 0.0 {
                    values[i]
                } else {
                    sum / weight
                }
            })
            .collect()
    }
}

/// The FFT convolution of [`LowPass::apply`] for signals of `n` samples.
struct Convolver {
    n: usize,
    half_width: usize,
    forward: std::sync::Arc<dyn RealToComplex<f64>>,
    inverse: std::sync::Arc<dyn ComplexToReal<f64>>,
    /// The kernel at lags −M..=M, zero padded, transformed.
    kernel_spectrum: Vec<Complex<f64>>,
    /// Running sums of the kernel over its lags, for the weights within M of the ends.
    prefix: Vec<f64>,
}

impl Convolver {
    fn new(taps: &[f64], n: usize) -> Self {
        let m = taps.len() - 1;
        // Linear convolution with the symmetric kernel: zero padded to a length that holds
        // it whole.
        let len = (n + 2 * m).next_power_of_two();
        let mut planner = RealFftPlanner::<f64>::new();
        let forward = planner.plan_fft_forward(len);
        let inverse = planner.plan_fft_inverse(len);
        let mut kernel = forward.make_input_vec();
        for (j, k) in kernel.iter_mut().enumerate().take(2 * m + 1) {
            *k = taps[j.abs_diff(m)];
        }
        let mut kernel_spectrum = forward.make_output_vec();
        // The lengths are the plan's own, so the transform cannot fail; if it did, the
        // spectrum would be empty and every signal would take the direct sum.
        if forward.process(&mut kernel, &mut kernel_spectrum).is_err() {
            kernel_spectrum.clear();
        }
        let mut prefix = Vec::with_capacity(2 * m + 2);
        prefix.push(0.0);
        for j in 0..=2 * m {
            let last = prefix[j];
            prefix.push(last + taps[j.abs_diff(m)]);
        }
        Self {
            n,
            half_width: m,
            forward,
            inverse,
            kernel_spectrum,
            prefix,
        }
    }

    /// `values` (of `n` samples) convolved; `None` if a transform failed.
    fn apply(&self, values: &[f64]) -> Option<Vec<f64>> {
        let (n, m) = (self.n, self.half_width);
        if n == 0 {
            return Some(Vec::new());
        }
        if self.kernel_spectrum.is_empty() {
            return None;
        }
        let mean = values.iter().sum::<f64>() / n as f64;
        let mut signal = self.forward.make_input_vec();
        for (x, v) in signal.iter_mut().zip(values) {
            *x = v - mean;
        }
        let mut spectrum = self.forward.make_output_vec();
        self.forward.process(&mut signal, &mut spectrum).ok()?;
        for (a, b) in spectrum.iter_mut().zip(&self.kernel_spectrum) {
            *a *= b;
        }
        let mut convolved = self.inverse.make_output_vec();
        self.inverse.process(&mut spectrum, &mut convolved).ok()?;
        let scale = 1.0 / convolved.len() as f64;
        // The weights of the samples inside the record: 1 but within M of its ends.
        Some(
            (0..n)
                .map(|i| {
                    // Lags l with 0 ≤ i − l < n, within −M..=M, as indices l + M.
                    let lo = (i + m + 1).saturating_sub(n);
                    let hi = (i + m).min(2 * m);
                    let weight = self.prefix[hi + 1] - self.prefix[lo];
                    mean + convolved[i + m] * scale / weight
                })
                .collect(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The gain of the filter at `f` cycles per sample, measured on a long cosine away
    /// from its ends (amplitude by least squares on the cosine and sine).
    fn gain(filter: &LowPass, f: f64) -> f64 {
        let n = 8000;
        let x: Vec<f64> = (0..n).map(|k| (2.0 * PI * f * k as f64).cos()).collect();
        let y = filter.apply(&x);
        let (mut cc, mut ss, mut cs, mut yc, mut ys) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for (k, v) in y.iter().enumerate().take(6000).skip(2000) {
            let (c, s) = (
                (2.0 * PI * f * k as f64).cos(),
                (2.0 * PI * f * k as f64).sin(),
            );
            (cc, ss, cs, yc, ys) = (cc + c * c, ss + s * s, cs + c * s, yc + v * c, ys + v * s);
        }
        let det = cc * ss - cs * cs;
        let (a, b) = ((yc * ss - ys * cs) / det, (ys * cc - yc * cs) / det);
        a.hypot(b)
    }

    /// Flat within 1e-5 below 0.7 of the cutoff, half amplitude at it, below 1e-4 from
    /// 1.3 of it: the band the module's doc promises, at the cutoff of the diagnosis'
    /// forward model (64 points a revolution at 1270 rpm, sampled at 10 240 Hz).
    #[test]
    fn the_low_pass_keeps_the_grids_band_and_stops_what_would_fold() {
        let dt = 1.0 / 10240.0;
        let fc = grid_nyquist_hz(64, 1270.0);
        let filter = LowPass::new(fc, dt).expect("a filter is needed");
        let c = fc * dt;
        for r in [0.05, 0.3, 0.5, 0.7] {
            let g = gain(&filter, r * c);
            assert!((g - 1.0).abs() < 1e-5, "gain {g} at {r} of the cutoff");
        }
        let g = gain(&filter, c);
        assert!((g - 0.5).abs() < 0.02, "gain {g} at the cutoff");
        for r in [1.3, 1.6, 2.1, 3.7] {
            let g = gain(&filter, r * c);
            assert!(g < 1e-4, "gain {g} at {r} of the cutoff");
        }
    }

    /// A constant passes exactly, to the ends; no filter when the cutoff is near the
    /// time Nyquist already.
    #[test]
    fn a_constant_passes_and_a_slow_grid_needs_no_filter() {
        let filter = LowPass::new(500.0, 1.0 / 10240.0).expect("filter");
        let y = filter.apply(&[1956.3; 300]);
        assert!(y.iter().all(|v| (v - 1956.3).abs() < 1e-9));
        assert!(LowPass::new(0.45 * 2560.0, 1.0 / 2560.0).is_none());
        assert!(LowPass::new(f64::NAN, 1.0 / 2560.0).is_none());
    }

    /// The transform gives the direct sum: within 1e-11 rpm (3e-12 of the vibration) at
    /// every sample, the ends (renormalised weights) included (the direct sum itself
    /// rounds each of its ~900 products at 1500 rpm's 2.3e-13), on a 1500 rpm record with
    /// orders below and above the cutoff, for record lengths shorter and longer than the
    /// filter; [`LowPass::apply_all`] on signals of two lengths gives each its own.
    #[test]
    fn the_transform_is_the_direct_sum() {
        let dt = 1.0 / 40960.0;
        let filter = LowPass::new(grid_nyquist_hz(64, 1000.0), dt).expect("filter");
        for n in [7usize, 300, 1001, 20000] {
            let x: Vec<f64> = (0..n)
                .map(|k| {
                    let t = k as f64 * dt;
                    1500.0 + 3.0 * (2.0 * PI * 50.0 * t).sin() + 0.4 * (2.0 * PI * 1900.0 * t).cos()
                })
                .collect();
            let fast = filter.apply(&x);
            let direct = filter.apply_direct(&x);
            let half = &x[..n / 2 + 1];
            let all = filter.apply_all(&[&x, &x, half]);
            assert_eq!(all[0], fast);
            assert_eq!(all[1], fast);
            assert_eq!(all[2], filter.apply(half));
            for (i, (a, b)) in fast.iter().zip(&direct).enumerate() {
                assert!(
                    (a - b).abs() < 1e-11,
                    "n = {n}, sample {i}: {a} against {b}"
                );
            }
        }
    }
}
