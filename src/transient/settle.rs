//! Settling before a recording: whole working cycles from the start state until the
//! cycle-to-cycle change of the speeds is below tolerance, and for at least a set time
//! ([`SettleRule::min_settle_s`]: the change sees a slowly decaying start transient only
//! in part, a component with per-cycle multiplier μ changing by `|1 − μ|` of itself),
//! then, when asked, a hold at the start speed with every state free, the rubber's
//! temperature too ([`hold`]).

use super::TransientError;
use super::budget::{StepBudget, check_state, name_collapse};
use super::forces::Scratch;
use super::plant::Plant;
use super::speed::SpeedProfile;
use super::stepper::Stepper;

/// How the settling went.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settling {
    /// Working cycles integrated before recording.
    pub cycles: usize,
    /// Simulated time before recording, s.
    pub time_s: f64,
    /// Last cycle-to-cycle change (relative).
    pub change: f64,
    /// True when the change fell below the tolerance.
    pub converged: bool,
}

/// When a run counts as settled (from [`super::RunOptions`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct SettleRule {
    /// Cycle-to-cycle change of the speeds, relative to their vibration, below which a
    /// run may count as settled.
    pub tolerance: f64,
    /// Shortest settling, s.
    pub min_settle_s: f64,
    /// Longest settling, s.
    pub max_settle_s: f64,
}

/// What settling integrates: the plant, its speed profile and the run's step budget.
#[derive(Clone, Copy)]
pub(super) struct Course<'a> {
    pub plant: &'a Plant,
    pub profile: &'a SpeedProfile,
    pub budget: &'a StepBudget,
}

/// Integrates whole working cycles of `cycle_s` until settled by `rule` (at least three
/// cycles).
///
/// A self-heating rubber's temperature is held at its start value meanwhile: settling
/// removes the mechanical transient (cycles), the rubber warms over its thermal time
/// constant (minutes), and the recorded run starts at the model's `temperature_c`
/// whatever settling took. Letting it warm made the start depend on the settling time: a
/// steady regime at resonance of the diagnosis bench (3960 rpm, 30 % load, capacity 192
/// J/K) settled in 13 s and started 15 K warm, with twice the order-2 amplitude.
pub(super) fn settle(
    course: Course,
    scratch: &mut Scratch,
    solver: &mut Stepper,
    cycle_s: f64,
    rule: SettleRule,
    progress: &mut dyn FnMut(f64) -> bool,
) -> Result<Settling, TransientError> {
    let (plant, profile) = (course.plant, course.profile);
    let n = plant.n_dof;
    let held = plant.thermal_states();
    let mut rhs = |t: f64, y: &[f64], dy: &mut [f64]| {
        plant.derivatives(t, y, dy, profile, scratch);
        for &s in &held {
            dy[s] = 0.0;
        }
    };
    let mut previous: Vec<f64> = solver.y()[n..2 * n].to_vec();
    let mut settling = Settling {
        cycles: 0,
        time_s: 0.0,
        change: f64::INFINITY,
        converged: false,
    };
    let max_cycles = (rule.max_settle_s / cycle_s).ceil().max(3.0) as usize;
    while settling.cycles < max_cycles {
        let t_end = solver.t() + cycle_s;
        let mut peak: f64 = 0.0;
        while solver.t() < t_end - 1e-12 * t_end.max(1.0) {
            checked_step(course, solver, t_end, &mut rhs)?;
            peak = solver.y()[n..2 * n]
                .iter()
                .fold(peak, |m, v| m.max(v.abs()));
        }
        settling.cycles += 1;
        let scale = peak.max(1e-9 * profile.at(solver.t()).1);
        settling.change = max_difference(&solver.y()[n..2 * n], &previous) / scale;
        settling.time_s = solver.t();
        if !progress(0.1 * settling.cycles as f64 / max_cycles as f64) {
            return Err(TransientError::Cancelled { time_s: solver.t() });
        }
        previous.copy_from_slice(&solver.y()[n..2 * n]);
        if settling.cycles >= 3
            && settling.time_s >= rule.min_settle_s
            && settling.change < rule.tolerance
        {
            settling.converged = true;
            break;
        }
    }
    Ok(settling)
}

/// Holds the start speed for `hold_s` (s) after settling, every state free: a self-heating
/// rubber warms meanwhile by its loss, as on a bench that holds a regime a while before
/// it records ([`super::RunOptions::hold_s`]). Settling holds the temperature, so that
/// the start does not depend on how long settling took; the hold is a set time.
pub(super) fn hold(
    course: Course,
    scratch: &mut Scratch,
    solver: &mut Stepper,
    hold_s: f64,
) -> Result<(), TransientError> {
    let (plant, profile) = (course.plant, course.profile);
    let t_end = solver.t() + hold_s.max(0.0);
    let mut rhs = |t: f64, y: &[f64], dy: &mut [f64]| plant.derivatives(t, y, dy, profile, scratch);
    while solver.t() < t_end - 1e-12 * t_end.max(1.0) {
        checked_step(course, solver, t_end, &mut rhs)?;
    }
    Ok(())
}

/// One step of `solver` towards `t_end`, then its step budget and its state checked (the
/// settling, the hold and the recording step so).
pub(super) fn checked_step<F: FnMut(f64, &[f64], &mut [f64])>(
    course: Course,
    solver: &mut Stepper,
    t_end: f64,
    rhs: &mut F,
) -> Result<(), TransientError> {
    let Course {
        plant,
        profile,
        budget,
    } = course;
    solver
        .step(t_end, rhs)
        .map_err(|e| name_collapse(plant, solver, e))?;
    budget.check(plant, solver)?;
    check_state(plant, solver.t(), solver.y(), profile)
}

/// The largest `|a_i − b_i|`.
fn max_difference(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
}
