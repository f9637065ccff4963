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
//! - `max_grid_points` 2²⁶: points of an angle grid, speed sweep or Campbell grid.

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
    /// Most points of an angle grid, speed sweep or Campbell grid (default 2²⁶).
    pub max_grid_points: usize,
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
    }
}
