//! What a run may ask for, checked before anything is allocated (issue 13, "Huge durations
//! or rates", `--run-up 1000:1e9`, `--speed-rpm 1e6`, `--rtol 1e-20`): finite positive
//! speeds up to [`Limits::max_speed_rpm`], samples `duration × rate` up to
//! [`Limits::max_samples`], an output rate that carries at least the model's lowest
//! order, and a tolerance within [`Limits::min_rtol`] … 0.1. Errors name the key
//! (`Run`/`RunOptions` field) and the CLI flag.

use super::TransientError;
use super::run::RunOptions;
use crate::limits::{self, Limits};
use crate::model::Model;
use crate::recording::Run;

/// The analysis reports orders up to this fraction of the Nyquist frequency
/// ([`crate::signal::AnalysisOptions::max_order`]).
const ANALYSED_FRACTION_OF_NYQUIST: f64 = 0.8;

/// Largest relative tolerance: above it the integrator's error control means nothing.
const MAX_RTOL: f64 = 0.1;

/// Checks `run` and `options` for `model` against the [`limits::current`] limits.
pub fn check_run(model: &Model, run: Run, options: &RunOptions) -> Result<(), TransientError> {
    let limits = limits::current();
    let [from_rpm, to_rpm] = run.speeds_rpm();
    let duration_s = run.duration_s;
    let speeds: &[(&str, f64)] = if run.is_ramp() {
        &[
            ("from_rpm (--run-up FROM)", from_rpm),
            ("to_rpm (--run-up TO)", to_rpm),
        ]
    } else {
        &[("speed_rpm (--speed-rpm)", from_rpm)]
    };
    for &(what, v) in speeds {
        positive(what, v, "rpm")?;
        limits::check_value(what, v, limits.max_speed_rpm, Some("--max-speed-rpm"))?;
    }
    positive("duration_s (--duration-s)", duration_s, "s")?;
    positive("rate_hz (--rate-hz)", options.rate_hz, "Hz")?;
    positive("min_steps_per_cycle", options.min_steps_per_cycle, "")?;
    if let Some(f) = options.viscous_above_hz {
        positive("viscous_above_hz", f, "Hz")?;
    }
    if let Some(f) = options.step_budget_factor {
        positive("step_budget_factor", f, "")?;
    }
    let samples = duration_s * options.rate_hz;
    limits::check_count(
        "samples: duration_s (--duration-s) × rate_hz (--rate-hz)",
        samples,
        limits.max_samples,
        Some("--max-samples"),
    )?;
    if samples.round() < 2.0 {
        return Err(TransientError::Model(format!(
            "duration_s (--duration-s) {duration_s} s × rate_hz (--rate-hz) {} Hz records {samples:.2} samples: need at least 2",
            options.rate_hz
        )));
    }
    let hold_s = options.hold_s;
    if !(hold_s.is_finite() && hold_s >= 0.0) {
        return Err(TransientError::Model(format!(
            "hold_s (--hold-s) = {hold_s} s: must be a finite number ≥ 0"
        )));
    }
    // A hold costs what a recording of its length costs.
    limits::check_count(
        "hold: hold_s (--hold-s) × rate_hz (--rate-hz)",
        hold_s * options.rate_hz,
        limits.max_samples,
        Some("--max-samples"),
    )?;
    check_rtol(options.rtol, &limits)?;
    let top_rpm = speeds.iter().map(|s| s.1).fold(0.0, f64::max);
    check_rate(model, options.rate_hz, top_rpm)
}

/// `Err` unless `v` is finite and > 0.
fn positive(what: &str, v: f64, unit: &str) -> Result<(), TransientError> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(TransientError::Model(format!(
            "{what} = {v} {unit}: must be a finite number > 0"
        )))
    }
}

/// `rtol` within `min_rtol … 0.1`: an `f64` carries ~16 digits, so a smaller tolerance
/// only makes the step collapse on round-off.
fn check_rtol(rtol: f64, limits: &Limits) -> Result<(), TransientError> {
    if rtol >= limits.min_rtol && rtol <= MAX_RTOL {
        Ok(())
    } else {
        Err(TransientError::Model(format!(
            "rtol (--rtol) = {rtol:e}: must be within min_rtol = {:e} … {MAX_RTOL} (an f64 state carries ~16 digits)",
            limits.min_rtol
        )))
    }
}

/// The output rate must carry the model's lowest order at the top speed within the
/// analysed band (0.8 × Nyquist): else the run's analysis would report no order at all
/// (issue 13: `--speed-rpm 1e6` gave `"orders": {}`).
fn check_rate(model: &Model, rate_hz: f64, top_rpm: f64) -> Result<(), TransientError> {
    let Some(lowest) = model.orders().into_iter().reduce(f64::min) else {
        return Ok(());
    };
    let frequency_hz = lowest * top_rpm / 60.0;
    let needed_hz = frequency_hz / (0.5 * ANALYSED_FRACTION_OF_NYQUIST);
    if rate_hz >= needed_hz {
        return Ok(());
    }
    Err(TransientError::Model(format!(
        "rate_hz (--rate-hz) = {rate_hz} Hz cannot carry any order: the lowest, order {lowest} at {top_rpm} rpm, is {frequency_hz:.1} Hz, above {ANALYSED_FRACTION_OF_NYQUIST} × Nyquist ({:.1} Hz); give --rate-hz ≥ {:.0}",
        0.5 * ANALYSED_FRACTION_OF_NYQUIST * rate_hz,
        needed_hz.ceil()
    )))
}
