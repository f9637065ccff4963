//! Steady runs and run-ups: start from the static twist, integrate working cycle by
//! working cycle until the cycle-to-cycle change is below tolerance, then record at the
//! output rate (a steady speed for a duration, or a linear speed ramp).

use super::TransientError;
use super::budget::{StepBudget, bound_thermal_time_constants};
use super::dopri::Dopri5;
use super::exact::Exact;
use super::forces::Scratch;
use super::measured_speed::MeasuredSpeed;
use super::observe::{Event, take_chunk};
use super::periodic_start::add_periodic_state;
use super::plant::{Plant, PlantLaw, Temperature};
use super::record::{Recorder, empty_simulation};
use super::ros2::Ros2;
pub use super::run_options::RunOptions;
use super::settle::{Course, SettleRule, Settling, checked_step, hold, settle};
use super::speed::SpeedProfile;
use super::start::initial_state;
use super::stepper::{Method, Stepper, is_stiff};
use super::validate::check_run;
use crate::model::Model;
use crate::recording::Run;
use crate::rubber::MaxwellChain;
use std::f64::consts::TAU;
use std::sync::Arc;

/// A recorded simulation: what a bench would have measured, and more.
#[derive(Debug, Clone)]
pub struct Simulation {
    /// Node names, model order.
    pub node_names: Vec<String>,
    /// Reference node index.
    pub reference_node: usize,
    /// Mean speed of each node over the reference's (signed).
    pub speed_ratio: Vec<f64>,
    /// Sample times from the start of recording, s.
    pub time_s: Vec<f64>,
    /// IAS of every node in its own shaft, rpm: `[node][sample]`.
    pub speed_rpm: Vec<Vec<f64>>,
    /// Torque of every connection with an element, own shaft, N·m: `(connection, samples)`.
    pub torque_nm: Vec<(usize, Vec<f64>)>,
    /// Mean power dissipated in every connection with an element over the recording, W:
    /// `(connection, W)` — rubber in its Maxwell arms, shafts in their dampers.
    pub power_loss_w: Vec<(usize, f64)>,
    /// Temperature of every rubber stage with `thermal`, °C: `(connection, samples)`.
    pub temperature_c: Vec<(usize, Vec<f64>)>,
    /// Connection names, model order.
    pub connection_names: Vec<String>,
    /// Fitted Maxwell chain of each rubber stage: `(connection, chain)` (without the arms
    /// run as a dashpot, [`RunOptions::viscous_above_hz`]).
    pub chains: Vec<(usize, MaxwellChain)>,
    /// Settling before the recording.
    pub settling: Settling,
    /// Integrator steps (accepted, rejected).
    pub steps: (u64, u64),
    /// What the run changed to be able to run, for a person (a thermal time constant
    /// shorter than a step, [`super::budget::bound_thermal_time_constants`]).
    pub warnings: Vec<String>,
}

/// Runs `run` on `model` (a steady or long run at constant mean speed after settling, or
/// a linear ramp after settling at its start speed). `progress` is called with the fraction done (0–1) a few
/// hundred times per run; returning `false` cancels.
pub fn simulate(
    model: &Model,
    run: Run,
    options: RunOptions,
    progress: &mut dyn FnMut(f64) -> bool,
) -> Result<Simulation, TransientError> {
    run_quiet(model, run, options, progress, None)
}

/// Runs run-up `run` like [`simulate`], its mean speed after settling along the measured
/// trajectory `speed` from its time `from_s` on ([`SpeedProfile::along`]) instead of the
/// straight line between `run`'s end speeds: a recording's run-up simulated as the bench
/// ran it (the diagnosis' forward model, [`crate::diagnose`]). It settles at the
/// trajectory's speed at `from_s`; a steady `run` ignores `speed`.
pub fn simulate_along(
    model: &Model,
    run: Run,
    options: RunOptions,
    speed: Arc<MeasuredSpeed>,
    from_s: f64,
    progress: &mut dyn FnMut(f64) -> bool,
) -> Result<Simulation, TransientError> {
    run_quiet(model, run, options, progress, Some((speed, from_s)))
}

/// [`run_recorded`] reporting only the fraction done to `progress`: nobody reads the
/// chunks, so the run does not assemble them.
fn run_quiet(
    model: &Model,
    run: Run,
    options: RunOptions,
    progress: &mut dyn FnMut(f64) -> bool,
    along: Option<(Arc<MeasuredSpeed>, f64)>,
) -> Result<Simulation, TransientError> {
    run_recorded(
        model,
        run,
        options,
        &mut |event| match event {
            Event::Progress(f) => progress(f),
            Event::Chunk(_) => true,
        },
        false,
        along,
    )
}

/// Runs `run` on `model` like [`simulate`], reporting to `observer` the fraction done
/// and, every 0.5 % of the recording and at its end, the samples recorded since the last
/// [`Event::Chunk`]. Returning `false` from `observer` cancels.
pub fn simulate_observed(
    model: &Model,
    run: Run,
    options: RunOptions,
    observer: &mut dyn FnMut(Event) -> bool,
) -> Result<Simulation, TransientError> {
    run_recorded(model, run, options, observer, true, None)
}

/// [`simulate_observed`] along a measured trajectory, as [`simulate_along`]: the GUI's
/// run matching a run-up recording streams as the diagnosis simulates it.
pub fn simulate_observed_along(
    model: &Model,
    run: Run,
    options: RunOptions,
    speed: Arc<MeasuredSpeed>,
    from_s: f64,
    observer: &mut dyn FnMut(Event) -> bool,
) -> Result<Simulation, TransientError> {
    run_recorded(model, run, options, observer, true, Some((speed, from_s)))
}

/// A ramp `run` with the end speeds of `speed` from its time `from_s` over the run's
/// duration; a steady one as it is.
fn along_run(run: Run, speed: &MeasuredSpeed, from_s: f64) -> Run {
    if run.is_ramp() {
        let at = |t: f64| speed.speed_rpm(t);
        Run::ramp(at(from_s), at(from_s + run.duration_s), run.duration_s)
    } else {
        run
    }
}

/// [`simulate_observed`], sending [`Event::Chunk`]s only when `chunks` (the progress
/// events are the same either way), a ramp `along` a measured trajectory from its time
/// `.1` on when given (its end speeds then the trajectory's, [`along_run`]).
fn run_recorded(
    model: &Model,
    run: Run,
    options: RunOptions,
    observer: &mut dyn FnMut(Event) -> bool,
    chunks: bool,
    along: Option<(Arc<MeasuredSpeed>, f64)>,
) -> Result<Simulation, TransientError> {
    let run = along
        .as_ref()
        .map_or(run, |(speed, from_s)| along_run(run, speed, *from_s));
    let [from_rpm, to_rpm] = run.speeds_rpm();
    let duration_s = run.duration_s;
    // The fastest the run goes: a measured trajectory may pass its end speeds between them.
    let top_rpm =
        along
            .as_ref()
            .filter(|_| run.is_ramp())
            .map_or(from_rpm.max(to_rpm), |(m, from_s)| {
                m.max_speed_rpm(*from_s, from_s + duration_s)
                    .max(from_rpm.max(to_rpm))
            });
    check_run(model, run, &options)?;
    let mut plant = Plant::new(model, options.load, options.viscous_above_hz)?;
    let cycle_rad = plant.engine.as_ref().map_or(2.0 * TAU, |e| e.cycle_rad);
    let mut profile = SpeedProfile::steady(from_rpm);
    let mut scratch = Scratch::new(plant.n_dof);
    let mut y0 = initial_state(&plant)?;
    // A model linear about its static state starts on its linear periodic state: settling
    // then only removes what the time domain adds to it ([`super::periodic_start`]).
    let power_w = add_periodic_state(model, &plant, from_rpm, options.load, &mut y0);
    if let Some(g) = plant.governor.as_mut() {
        if let Some(p) = power_w {
            g.dissipation_torque_nm = p / (from_rpm * TAU / 60.0);
        }
        g.rigid_angle_ref_rad = g.inertia_share.iter().zip(&y0).map(|(w, a)| w * a).sum();
        // The low-passed rigid-body speed starts at its steady mean, 0 (the orders in
        // the start state's rigid-body speed reach it only attenuated by ω_f/ω); started
        // at the instantaneous speed, the loop's transient left 1.1e-3 rpm of order 0.5
        // in `tests/transient_engine_orders.rs` (7.2e-4 so).
        y0[g.filter_state] = 0.0;
    }
    let atol = tolerances(&plant);
    let cycle_s = |rpm: f64| cycle_rad / (rpm * TAU / 60.0);
    let h_max = cycle_s(top_rpm) / options.min_steps_per_cycle.max(1.0);
    let warnings = bound_thermal_time_constants(&mut plant, h_max);
    let plant = plant;
    let budget = StepBudget {
        factor: options
            .step_budget_factor
            .unwrap_or(crate::limits::current().step_budget_factor),
        h_max_s: h_max,
    };
    // The exact discretization steps a whole fraction of the sample interval, at most h_max.
    let sample_s = 1.0 / options.rate_hz;
    let exact = match (options.method, run.is_ramp()) {
        (Method::Auto | Method::Exact, false) => {
            let h = sample_s / (sample_s / h_max).ceil().max(1.0);
            Exact::new(&plant, from_rpm, y0.clone(), h)
        }
        _ => None,
    };
    if options.method == Method::Exact && exact.is_none() {
        return Err(TransientError::Model(
            "the exact integrator takes steady runs of models without an engine whose \
             equations are linear (no backlash, amplitude law or self-heating); use \
             `--method auto`"
                .into(),
        ));
    }
    let mut solver = {
        let mut rhs =
            |t: f64, y: &[f64], dy: &mut [f64]| plant.derivatives(t, y, dy, &profile, &mut scratch);
        let implicit = match options.method {
            Method::Implicit => true,
            Method::Explicit | Method::Exact => false,
            Method::Auto => is_stiff(plant.fastest_rate_rad_s(), h_max, options.rtol),
        };
        if let Some(exact) = exact {
            Stepper::Exact(Box::new(exact))
        } else if implicit {
            Stepper::Implicit(Ros2::new(
                0.0,
                y0,
                h_max / 10.0,
                h_max,
                options.rtol,
                atol,
                &mut rhs,
            ))
        } else {
            Stepper::Explicit(Dopri5::new(
                0.0,
                y0,
                h_max / 10.0,
                h_max,
                options.rtol,
                atol,
                &mut rhs,
            ))
        }
    };
    let course = Course {
        plant: &plant,
        profile: &profile,
        budget: &budget,
    };
    // A ramp is itself a transient: settling its start to 1e-3 of the vibration is enough.
    // Integration error makes the change noisy at ~rtol: never ask for less than 20×.
    let tolerance = if run.is_ramp() {
        options.settle_tolerance.max(1e-3)
    } else {
        options.settle_tolerance
    };
    let rule = SettleRule {
        tolerance: tolerance.max(20.0 * options.rtol),
        min_settle_s: options.min_settle_s,
        max_settle_s: options.max_settle_s,
    };
    let settling = settle(
        course,
        &mut scratch,
        &mut solver,
        cycle_s(from_rpm),
        rule,
        &mut |f| observer(Event::Progress(f)),
    )?;
    if options.hold_s > 0.0 {
        hold(course, &mut scratch, &mut solver, options.hold_s)?;
    }
    let t0 = solver.t();
    if run.is_ramp() {
        profile = match along {
            Some((speed, from_s)) => SpeedProfile::along(speed, from_s, t0, duration_s),
            None => SpeedProfile::ramp(from_rpm, to_rpm, t0, duration_s),
        };
    }
    let samples = (duration_s * options.rate_hz).round() as usize;
    let mut sim = empty_simulation(&plant, samples, settling);
    let recorder = Recorder::new(&plant, samples);
    sim.warnings = warnings;
    let mut state = vec![0.0; plant.state_len];
    let mut next = 0;
    let t_end = t0 + duration_s;
    let mut last_report = 0.0;
    // Instantaneous power per element of the samples not yet reported, W.
    let mut power = vec![Vec::new(); sim.torque_nm.len()];
    let mut reported = 0;
    while next < samples {
        {
            let course = Course {
                plant: &plant,
                profile: &profile,
                budget: &budget,
            };
            let mut rhs = |t: f64, y: &[f64], dy: &mut [f64]| {
                plant.derivatives(t, y, dy, &profile, &mut scratch)
            };
            checked_step(course, &mut solver, t_end + 1.0 / options.rate_hz, &mut rhs)?;
        }
        while next < samples {
            let since_start = next as f64 / options.rate_hz;
            let t = t0 + since_start;
            if t > solver.t() {
                break;
            }
            let y = solver.state_at(t, &mut state);
            let power = chunks.then_some(power.as_mut_slice());
            recorder.record(&profile, t, y, next, &mut sim, power);
            sim.time_s[next] = since_start;
            next += 1;
        }
        let done = next as f64 / samples as f64;
        if done - last_report >= 0.005 || (next == samples && reported < samples) {
            last_report = done;
            let sent =
                !chunks || observer(Event::Chunk(take_chunk(&sim, reported, next, &mut power)));
            reported = next;
            if !sent || !observer(Event::Progress(0.1 + 0.9 * done)) {
                return Err(TransientError::Cancelled { time_s: solver.t() });
            }
        }
    }
    sim.steps = solver.steps();
    Ok(sim)
}

/// Absolute tolerances: angles 1e-8 rad, speeds 1e-6 rad/s, arms 1e-8 rad, 1e-4 °C.
fn tolerances(plant: &Plant) -> Vec<f64> {
    let n = plant.n_dof;
    let mut atol = vec![1e-8; plant.state_len];
    atol[n..2 * n].fill(1e-6);
    if let Some(g) = &plant.governor {
        atol[g.filter_state] = 1e-6;
    }
    for e in &plant.elements {
        if let PlantLaw::Rubber(r) = &e.law
            && let Temperature::Thermal { state, .. } = r.temperature
        {
            atol[state] = 1e-4;
        }
    }
    atol
}
