//! Steady runs and run-ups: start from the static twist, integrate working cycle by
//! working cycle until the cycle-to-cycle change is below tolerance, then record at the
//! output rate (a steady speed for a duration, or a linear speed ramp).

use super::TransientError;
use super::budget::{StepBudget, bound_thermal_time_constants};
use super::dopri::Dopri5;
use super::exact::Exact;
use super::forces::Scratch;
use super::observe::{Event, take_chunk};
use super::periodic_start::add_periodic_state;
use super::plant::{Plant, PlantLaw, Temperature};
use super::record::{Recorder, empty_simulation};
use super::ros2::Ros2;
use super::settle::{Course, SettleRule, Settling, checked_step, hold, settle};
use super::speed::SpeedProfile;
use super::start::initial_state;
use super::stepper::{Method, Stepper, is_stiff};
use super::validate::check_run;
use crate::model::Model;
use crate::recording::Run;
use crate::rubber::MaxwellChain;
use std::f64::consts::TAU;

/// How to run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunOptions {
    /// Engine load 0..1 (default 1).
    pub load: f64,
    /// Output rate, Hz (default 10240, seed 001's IAS rate).
    pub rate_hz: f64,
    /// Relative tolerance of the integrator (default 1e-5: a linear run then agrees with
    /// the frequency domain within 0.03 %).
    pub rtol: f64,
    /// Cycle-to-cycle change of the speeds, relative to their vibration amplitude, below
    /// which a run counts as settled (default 1e-4; never below 20 × `rtol`, the noise
    /// floor of the integration).
    pub settle_tolerance: f64,
    /// Longest settling time before recording anyway, s (default 60).
    pub max_settle_s: f64,
    /// Shortest settling time, s, whatever the cycle-to-cycle change says (default 0).
    /// The change compares whole states a cycle apart against the largest vibration, so
    /// a start transient of a lightly damped mode at a few 0.1 % of it passes the
    /// tolerance, yet leaks into the orders that an engine hardly excites, where a bench
    /// measures noise (see [`crate::diagnose`]'s forward model, which settles for the
    /// slowest mode's decay).
    pub min_settle_s: f64,
    /// Time the start speed is held after settling and before recording, s, with every
    /// state free, a self-heating rubber's temperature too (default 0). Settling holds
    /// the temperature; a bench holds a regime a while before it records, and a stage at
    /// a resonance warms and detunes meanwhile (benchtruth case 2050: a stage losing
    /// 1 kW at 1020 rpm). The recorded time starts after the hold.
    pub hold_s: f64,
    /// Integrator (default: explicit unless the model is stiff).
    pub method: Method,
    /// Steps per working cycle at the run's highest speed that the integrator must take
    /// at least (default 180: 4° of crank on a four-stroke engine).
    pub min_steps_per_cycle: f64,
    /// Rubber Maxwell arms that relax faster than this, Hz, run as their low-frequency
    /// limit, a dashpot ([`MaxwellChain::take_fast_arms`]; default `None`:
    /// every arm is integrated). For runs of which only frequencies below a third of it
    /// matter: the fastest arms bound the explicit integrator's step.
    pub viscous_above_hz: Option<f64>,
    /// Step budget: by simulated time `t` the run may take at most this × `(t / h_max +
    /// 1000)` steps, `h_max` the largest step [`RunOptions::min_steps_per_cycle`] allows;
    /// a run beyond it stops with [`TransientError::StepBudget`], which names the element
    /// holding it back (default `None`: [`crate::limits::Limits::step_budget_factor`], 200;
    /// well-posed runs take 1–3×).
    pub step_budget_factor: Option<f64>,
}

impl Default for RunOptions {
    fn default() -> Self {
        Self {
            load: 1.0,
            rate_hz: 10240.0,
            rtol: 1e-5,
            settle_tolerance: 1e-4,
            max_settle_s: 60.0,
            min_settle_s: 0.0,
            hold_s: 0.0,
            method: Method::Auto,
            min_steps_per_cycle: 180.0,
            viscous_above_hz: None,
            step_budget_factor: None,
        }
    }
}

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
    // Nobody reads the chunks: the run does not assemble them.
    run_recorded(
        model,
        run,
        options,
        &mut |event| match event {
            Event::Progress(f) => progress(f),
            Event::Chunk(_) => true,
        },
        false,
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
    run_recorded(model, run, options, observer, true)
}

/// [`simulate_observed`], sending [`Event::Chunk`]s only when `chunks` (the progress
/// events are the same either way).
fn run_recorded(
    model: &Model,
    run: Run,
    options: RunOptions,
    observer: &mut dyn FnMut(Event) -> bool,
    chunks: bool,
) -> Result<Simulation, TransientError> {
    let [from_rpm, to_rpm] = run.speeds_rpm();
    let duration_s = run.duration_s;
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
    let h_max = cycle_s(from_rpm.max(to_rpm)) / options.min_steps_per_cycle.max(1.0);
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
        profile = SpeedProfile::ramp(from_rpm, to_rpm, t0, duration_s);
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
