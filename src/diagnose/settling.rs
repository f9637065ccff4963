//! How long a simulated run must settle, and how long a run-up segment's lead-in must be,
//! so that no start transient reaches a compared amplitude (issue 14, item 5: "a run-up's
//! forward model starts settled at its start speed … and passes lightly damped modes
//! transiently").
//!
//! A start transient decays with the slowest mode's rate `σ = ζ ω_n` (the real part of
//! its eigenvalue `λ = −ζω_n ± iω_d`, [`crate::modal::damped`]; seed 000 eq. 14 for the
//! rubber's equivalent viscous damping). After `t` it is `e^{−σt}` of what it was. The
//! time domain's settling stops when the cycle-to-cycle change falls below its tolerance
//! ([`crate::transient::RunOptions::settle_tolerance`]), which a lightly damped mode
//! (0.5–1 % of critical) reaches only after `ln(1/tol)/σ`: 10 s and more for a 0.5 % mode
//! at 15 Hz. The rule here:
//!
//! - settling may last `DECAYS / σ` (at least the fixed bound of [`super::forward`], at
//!   most [`MAX_SETTLE_S`]);
//! - a run-up segment after the first starts, settled at the speed of its lead-in's start,
//!   `lead ≥ DECAYS / σ` before its stretch (at least [`MIN_LEAD_S`], at most
//!   [`MAX_LEAD_S`]) on the same ramp, and the lead-in's windows are discarded. The
//!   mismatch between the steady state there and the ramp's own state (up to a resonance
//!   peak, when a boundary falls just after a crossing) has then decayed to `e^{−DECAYS}`.
//!
//! [`DECAYS`] = ln(1/[`super::residual::FLOOR`]) = ln 200 = 5.3: the remainder of a start
//! transient is below the amplitude floor the comparison allows anyway.

use crate::modal::{damped_modes, modes};
use crate::model::{ConnectionKind, Model};
use crate::physics::{OperatingPoint, System};
use std::f64::consts::TAU;

/// e-folds of the slowest mode a start transient must have behind it: ln(1/0.005).
pub const DECAYS: f64 = 5.3;
/// Longest settling, s: bounds the cost of a model with a nearly undamped mode; beyond
/// it a run is recorded as it is, as before ([`crate::transient::Settling::converged`]).
pub const MAX_SETTLE_S: f64 = 16.0;
/// Shortest lead-in of a segment after the first, s: the switch from the settled start
/// to the ramp excites the modes through the ramp's inertia torque; 0.5 s let the shipped
/// cases' modes (ζ ≥ 3 %, ≥ 20 Hz: e⁻¹ in ≤ 0.27 s) decay.
pub const MIN_LEAD_S: f64 = 0.5;
/// Longest lead-in, s: at most 8 s more per segment (a 0.5 % mode at 21 Hz needs 8 s).
pub const MAX_LEAD_S: f64 = 8.0;

/// The slowest decay time `1/min(ζ ω_n)` of `model`'s flexible modes at `load`, s
/// (`None` when the modes cannot be computed, or none has a positive decay rate).
pub fn slowest_decay_s(model: &Model, load: f64) -> Option<f64> {
    let point = OperatingPoint {
        load,
        temperature_c: None,
    };
    let system = System::new(model, point).ok()?;
    let undamped = modes(&system).ok()?;
    damped_modes(&system, &undamped)
        .iter()
        .filter(|m| m.frequency_hz.is_finite() && m.damping_ratio.is_finite())
        .filter(|m| m.frequency_hz > 0.0 && m.damping_ratio > 0.0 && m.damping_ratio < 1.0)
        .map(|m| {
            let omega_n = TAU * m.frequency_hz / (1.0 - m.damping_ratio.powi(2)).sqrt();
            m.damping_ratio * omega_n
        })
        .min_by(f64::total_cmp)
        .map(|rate| 1.0 / rate)
}

/// Settling allowed for a model whose slowest decay time is `decay_s`: `DECAYS · decay_s`
/// within `[floor_s, MAX_SETTLE_S]` (`floor_s` when unknown).
pub fn settle_s(decay_s: Option<f64>, floor_s: f64) -> f64 {
    decay_s.map_or(floor_s, |tau| {
        (DECAYS * tau).clamp(floor_s, MAX_SETTLE_S.max(floor_s))
    })
}

/// Shortest settling of a run that starts on its periodic state (a steady regime, a long
/// run, a run-up's first segment), s: the lead-in's `DECAYS · decay_s` within
/// `[0, MAX_LEAD_S]` (0 when unknown).
///
/// The time domain's cycle-to-cycle test ([`crate::transient::RunOptions::settle_tolerance`],
/// 2e-3 of the largest vibration here) passes a start transient of the slowest mode at
/// about 0.1 % of the main order, and that transient leaks into the orders the engine
/// hardly excites, where the bench measures only its noise. Benchtruth control 2047 (a
/// six-cylinder engine, mode 1 at 15.7 Hz with 1.3 % damping) settled at 2250 rpm in 10
/// cycles and kept 0.0044 rpm of order 0.5 at the crank, where the bench measured
/// 0.001 ± 0.001 rpm; settled for the mode's 5.3 decay times (4.2 s) it keeps 0.00004 rpm
/// (`tests/transient_engine_orders.rs`).
pub fn min_settle_s(decay_s: Option<f64>) -> f64 {
    decay_s.map_or(0.0, |tau| (DECAYS * tau).clamp(0.0, MAX_LEAD_S))
}

/// Does `model` warm up in the time domain (a rubber stage with `thermal`)?
pub fn warms_up(model: &Model) -> bool {
    model
        .connections
        .iter()
        .any(|c| matches!(&c.kind, ConnectionKind::Rubber(r) if r.thermal.is_some()))
}

/// How long a bench holds a run of `model` at `load` at its start speed before it
/// records, its rubber warming, s ([`crate::transient::RunOptions::hold_s`]): the slowest
/// mode's settling, [`min_settle_s`]; 0 when nothing warms (the hold then changes nothing
/// a settled run records). One rule for the bench `torsim synth` plays and for the
/// diagnosis' forward model, so that the two agree on a warming stage's start.
pub fn bench_hold_s(model: &Model, load: f64) -> f64 {
    if warms_up(model) {
        min_settle_s(slowest_decay_s(model, load))
    } else {
        0.0
    }
}

/// Lead-in of a run-up segment after the first: `DECAYS · decay_s` within
/// `[MIN_LEAD_S, MAX_LEAD_S]` ([`MIN_LEAD_S`] when unknown).
pub fn lead_s(decay_s: Option<f64>) -> f64 {
    decay_s.map_or(MIN_LEAD_S, |tau| {
        (DECAYS * tau).clamp(MIN_LEAD_S, MAX_LEAD_S)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rule and its bounds: a 0.7 % mode at 36 Hz (σ = 1.58 /s) needs 3.35 s; a
    /// 6 % one is held at the floor; a nearly undamped one at the caps.
    #[test]
    fn leads_follow_the_slowest_decay() {
        let tau = 1.0 / (0.007 * TAU * 36.0);
        assert!((lead_s(Some(tau)) - DECAYS * tau).abs() < 1e-12);
        assert!((lead_s(Some(tau)) - 3.35).abs() < 0.01);
        assert_eq!(lead_s(Some(1.0 / (0.06 * TAU * 36.0))), MIN_LEAD_S);
        assert_eq!(lead_s(Some(100.0)), MAX_LEAD_S);
        assert_eq!(lead_s(None), MIN_LEAD_S);
        assert_eq!(settle_s(Some(100.0), 6.0), MAX_SETTLE_S);
        assert_eq!(settle_s(Some(0.1), 6.0), 6.0);
        assert_eq!(settle_s(None, 6.0), 6.0);
    }

    /// A bench holds a run only when a stage warms, for the slowest mode's settling.
    #[test]
    fn a_bench_holds_only_a_warming_model() {
        use crate::effects::{Effect, EffectSpec, build_truth};
        use crate::model::{parse_model, presets};
        let text = presets::preset("diagnosis-bench").expect("shipped").text;
        let cold = parse_model(text, "bench.toml").unwrap();
        assert_eq!(bench_hold_s(&cold, 1.0), 0.0);
        let spec = EffectSpec::new(Effect::CouplingThermalDrift);
        let warm = build_truth(&cold, &spec, 0.0, 0).unwrap().model;
        let hold_s = bench_hold_s(&warm, 1.0);
        assert!(hold_s > 0.0);
        assert_eq!(hold_s, min_settle_s(slowest_decay_s(&warm, 1.0)));
    }
}
