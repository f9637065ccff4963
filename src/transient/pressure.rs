//! The cylinder pressure as the time domain integrates it: the table's Fourier series
//! through order [`HIGHEST_ORDER`], on a fine uniform grid over the working cycle.
//!
//! The spec's curve (`spec/model-format.md`, `[engine] pressure`: periodic, linear
//! interpolation) has a kink at every point of the user's table: 2° apart around firing
//! TDC in a typical table, where the pressure rises by several bar per degree. An
//! adaptive explicit step that straddles a kink commits an error of order `h²` times the
//! jump in slope, which its embedded error estimate sees only in part; the steps fall
//! differently on each cylinder's kinks, so the errors differ from cylinder to cylinder
//! and from cycle to cycle. The integration then makes an imbalance of its own: a noise
//! at the half orders and the orders the firing order cancels, the orders where a bench
//! measures only its noise. Measured on benchtruth control 2047 (six cylinders, mode 1 at
//! 15.6 Hz with 1.3 % damping, so order 0.5 at 1860 rpm is resonant): with the curve as
//! tabled, the crank's order 0.5 came out anywhere from 1e-5 to 0.07 rpm depending on
//! the tolerance and the steps' luck (at `rtol` 1e-4, 90 steps a cycle: 0.036 rpm, and
//! the mean speed wandering by ±0.05 rpm), where the bench measured 0.001 ± 0.001 rpm.
//! With the series through order 48 it is 0.00026 rpm at the same settings and 1e-5 at
//! `rtol` 1e-5, and order 3 moves by 0.01 %.
//!
//! The series has the same coefficients as the curve through order 48 (the frequency
//! domain takes the curve's harmonics from the same table, [`crate::physics::excitation`]),
//! so every view sees one excitation through that order. Above it a gas torque's
//! harmonics have fallen by well over two decades from the firing order's, and every
//! order torsim analyses or compares lies below it.

use crate::model::Engine;
use crate::physics::engine;
use realfft::RealFftPlanner;

/// Samples of the cylinder pressure table per working cycle (0.1° for a 4-stroke).
pub const SAMPLES: usize = 7200;
/// Highest engine order of the integrated pressure (orders per revolution of the crank).
pub const HIGHEST_ORDER: f64 = 48.0;

/// Gauge pressure in Pa at `load` on [`SAMPLES`] points over the working cycle from firing
/// TDC: the curve's Fourier series through [`HIGHEST_ORDER`].
pub fn cycle_table_pa(e: &Engine, load: f64) -> Vec<f64> {
    let cycle_deg = e.cycle_deg();
    let mut table: Vec<f64> = (0..SAMPLES)
        .map(|k| engine::pressure_bar(e, load, cycle_deg * k as f64 / SAMPLES as f64) * 1.0e5)
        .collect();
    // Harmonic k of the cycle is order k / (revolutions per cycle).
    let highest = (HIGHEST_ORDER * cycle_deg / 360.0).round() as usize;
    let mut planner = RealFftPlanner::<f64>::new();
    let forward = planner.plan_fft_forward(SAMPLES);
    let inverse = planner.plan_fft_inverse(SAMPLES);
    let mut spectrum = forward.make_output_vec();
    let original = table.clone();
    if forward.process(&mut table, &mut spectrum).is_err() {
        return original;
    }
    for c in spectrum.iter_mut().skip(highest + 1) {
        *c = num_complex::Complex64::new(0.0, 0.0);
    }
    let mut smooth = inverse.make_output_vec();
    if inverse.process(&mut spectrum, &mut smooth).is_err() {
        return original;
    }
    smooth.iter().map(|v| v / SAMPLES as f64).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{parse_model, presets::preset};

    fn harmonic(table: &[f64], k: usize) -> num_complex::Complex64 {
        let n = table.len() as f64;
        table
            .iter()
            .enumerate()
            .map(|(i, p)| {
                p * num_complex::Complex64::from_polar(
                    1.0,
                    -std::f64::consts::TAU * (k * i) as f64 / n,
                )
            })
            .sum::<num_complex::Complex64>()
            * (2.0 / n)
    }

    /// cng-genset's full-load curve: the table keeps every harmonic through order 48 to
    /// rounding (relative 1e-9 of the firing pressure's) and none above.
    #[test]
    fn the_series_keeps_the_curve_through_order_48() {
        let model =
            parse_model(preset("cng-genset").expect("preset").text, "p.toml").expect("model");
        let e = model.engine.as_ref().expect("engine");
        let smooth = cycle_table_pa(e, 1.0);
        let raw: Vec<f64> = (0..SAMPLES)
            .map(|k| engine::pressure_bar(e, 1.0, e.cycle_deg() * k as f64 / SAMPLES as f64) * 1e5)
            .collect();
        let peak = raw.iter().fold(0.0_f64, |m, p| m.max(p.abs()));
        // Order q is cycle harmonic 2q on a four-stroke engine.
        for k in [0, 1, 6, 12, 48, 96] {
            let d = (harmonic(&smooth, k) - harmonic(&raw, k)).norm();
            assert!(d < 1e-9 * peak, "harmonic {k}: {d}");
        }
        for k in [97, 120, 400] {
            assert!(harmonic(&smooth, k).norm() < 1e-9 * peak, "harmonic {k}");
            assert!(
                harmonic(&raw, k).norm() > 1e-7 * peak,
                "the raw curve has harmonic {k}"
            );
        }
    }
}
