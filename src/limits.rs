//! Bounds on every size that allocates or loops, derived from physics and memory, so that
//! no input can make torsim allocate terabytes or run for hours (issue 13).
//!
//! The limits are documented defaults ([`Limits::DEFAULT`]). A front end may raise them for
//! one process with [`set`] (the CLI's `--max-*` flags); the library reads them with
//! [`current`]. An error that hits a limit names the key or flag and the limit, and how to
//! raise it.
//!
//! Why each default:
//! - `max_samples` 2²⁷ (134 M) samples per channel: one channel is then 1 GiB of `f64`;
//!   a 10 240 Hz recording of 3.6 h.
//! - `max_order` 100: engine orders above ~24 carry no measurable torque (seed 001 reads
//!   up to order 12); 100 is a generous ceiling for gear-mesh and blade-pass orders.
//! - `max_cylinders` 64: the largest reciprocating engines have 20; 64 covers any
//!   multi-bank arrangement.
//! - `min_rtol` 1e-12: an `f64` state carries ~16 digits; a tolerance below 1e-12 makes
//!   the step collapse on round-off rather than be more accurate.
//! - `max_speed_rpm` 100 000: beyond any reciprocating engine or test-bench motor
//!   (turbochargers spin faster, but are not drivelines of this kind).
//! - `max_grid_points` 2²⁶: points of an angle grid (0.5 GiB of `f64`).
//! - `max_sweep_points` 10⁶: speeds of a Campbell or response sweep, and speeds × orders of
//!   a response sweep (each point is a complex solve and a few `f64` per node and
//!   connection: 10⁶ points take seconds and tens of MB).
//! - `step_budget_factor` 200: a time-domain run may take at most 200 times the steps a
//!   well-posed run needs, `t / h_max + 1000` by time `t` (`h_max` the step the
//!   excitation allows, [`crate::transient::RunOptions::min_steps_per_cycle`]). Measured:
//!   well-posed runs take 1–3 times that; a 10¹⁰ N·m/rad shaft on 5 g·m² (a stiff mode at
//!   38 kHz the integrator must resolve) 60–70 times and still ends in 3 s; an explicit
//!   run held back by stability, or a step near collapse, thousands.
//!
//! Checks: [`check_count`] and [`check_value`] give a [`LimitError`] that names the key or
//! flag, the value and the limit.

use std::sync::RwLock;

/// Bounds on sizes (see the module docs for why each default).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// Samples per channel of a recording or a simulated run (default 2²⁷).
    pub max_samples: usize,
    /// Highest engine order analysed or swept (default 100).
    pub max_order: f64,
    /// Most cylinders of an engine (default 64).
    pub max_cylinders: usize,
    /// Smallest relative tolerance of the time-domain integrator (default 1e-12).
    pub min_rtol: f64,
    /// Highest speed of any shaft, rpm (default 100 000).
    pub max_speed_rpm: f64,
    /// Most points of an angle grid (default 2²⁶).
    pub max_grid_points: usize,
    /// Most speeds of a Campbell or response sweep, and most speeds × orders of a
    /// response sweep (default 10⁶).
    pub max_sweep_points: usize,
    /// Integrator steps a time-domain run may take, as a multiple of what a well-posed
    /// run needs (default 200; see the module docs).
    pub step_budget_factor: f64,
}

impl Limits {
    /// The documented defaults.
    pub const DEFAULT: Limits = Limits {
        max_samples: 1 << 27,
        max_order: 100.0,
        max_cylinders: 64,
        min_rtol: 1e-12,
        max_speed_rpm: 100_000.0,
        max_grid_points: 1 << 26,
        max_sweep_points: 1_000_000,
        step_budget_factor: 200.0,
    };
}

impl Default for Limits {
    fn default() -> Self {
        Self::DEFAULT
    }
}

static CURRENT: RwLock<Limits> = RwLock::new(Limits::DEFAULT);

/// The limits in force in this process ([`Limits::DEFAULT`] unless a front end [`set`]
/// others).
pub fn current() -> Limits {
    match CURRENT.read() {
        Ok(guard) => *guard,
        Err(poisoned) => *poisoned.into_inner(),
    }
}

/// Sets the limits for this process (the CLI's `--max-*` flags).
pub fn set(limits: Limits) {
    match CURRENT.write() {
        Ok(mut guard) => *guard = limits,
        Err(poisoned) => *poisoned.into_inner() = limits,
    }
}

/// A size or value beyond a limit of [`Limits`] (issue 13: the error names the key or
/// flag and the limit).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{what} = {} exceeds the limit of {}{}", readable(*.value), readable(*.limit), raise_hint(.flag))]
pub struct LimitError {
    /// What was bounded, with the key or flag it came from, e.g. "`--duration-s` × `--rate-hz` (samples)".
    pub what: String,
    /// The value asked for.
    pub value: f64,
    /// The limit in force.
    pub limit: f64,
    /// The CLI flag that raises the limit for one run (`None`: a fixed bound).
    pub flag: Option<&'static str>,
}

/// A number as a person reads it: whole numbers below 10⁹ in full (`100`, `134217728`),
/// others in scientific notation (`1e9`, `1.024e13`).
fn readable(x: f64) -> String {
    if x.fract() == 0.0 && x.abs() < 1e9 {
        format!("{x:.0}")
    } else {
        format!("{x:e}")
    }
}

fn raise_hint(flag: &Option<&'static str>) -> String {
    flag.map_or(String::new(), |f| format!(" (raise it with `{f}`)"))
}

/// `Ok` when `count` ≤ `limit`, else a [`LimitError`] for `what`, raised by `flag`.
pub fn check_count(
    what: &str,
    count: f64,
    limit: usize,
    flag: Option<&'static str>,
) -> Result<(), LimitError> {
    check_value(what, count, limit as f64, flag)
}

/// `Ok` when `value` is finite and ≤ `limit`, else a [`LimitError`].
pub fn check_value(
    what: &str,
    value: f64,
    limit: f64,
    flag: Option<&'static str>,
) -> Result<(), LimitError> {
    if value <= limit {
        Ok(())
    } else {
        Err(LimitError {
            what: what.to_string(),
            value,
            limit,
            flag,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_the_documented_ones() {
        let d = Limits::default();
        assert_eq!(d.max_samples, 134_217_728);
        assert_eq!(d.max_order, 100.0);
        assert_eq!(d.max_cylinders, 64);
        assert_eq!(d.min_rtol, 1e-12);
        assert_eq!(d.max_sweep_points, 1_000_000);
    }

    #[test]
    fn limit_errors_name_the_flag_and_the_limit() {
        let e = check_count("samples", 1e13, 1 << 27, Some("--max-samples")).unwrap_err();
        assert_eq!(
            e.to_string(),
            "samples = 1e13 exceeds the limit of 134217728 (raise it with `--max-samples`)"
        );
        assert!(check_count("samples", 1e3, 1 << 27, None).is_ok());
        assert!(check_value("x", f64::NAN, 1.0, None).is_err());
    }
}
