//! The time domain against cases with known answers.

use num_complex::Complex64;
use std::f64::consts::TAU;
use torsim::model::{ConnectionKind, parse_model};
use torsim::physics::{Excitation, OperatingPoint, System};
use torsim::recording::Run;
use torsim::response::forced_response;
use torsim::transient::dopri::Dopri5;
use torsim::transient::plant::Plant;
use torsim::transient::{Method, RunOptions, SpeedProfile, simulate};

mod transient_support;
use transient_support::{assert_orders_match, order_amplitude};

const THREE_DOF: &str = r#"format = 1
name = "linear three-DOF"
[[inertia]]
name = "engine"
inertia = 0.5
[[inertia]]
name = "hub"
inertia = 0.02
[[inertia]]
name = "flange"
inertia = 0.01
[[connection]]
kind = "shaft"
from = "engine"
to = "hub"
stiffness = 2.0e5
damping = 2.0
[[connection]]
kind = "shaft"
from = "hub"
to = "flange"
stiffness = 1.0e4
damping = 1.5
[[connection]]
kind = "shaft"
from = "flange"
to = "ground"
stiffness = 1.0e4
damping = 1.5
[[harmonic]]
at = "engine"
order = 1.0
amplitude = 100.0
phase_deg = 0.0
[[harmonic]]
at = "engine"
order = 2.5
amplitude = 40.0
phase_deg = 60.0
"#;

/// The orders the steady-run comparisons check: THREE_DOF's two harmonics.
const ORDERS: [f64; 2] = [1.0, 2.5];

/// The frequency-domain response of `model` at `speed_rpm` to [`ORDERS`], full load.
fn response_at(model: &torsim::model::Model, speed_rpm: f64) -> torsim::response::Response {
    let system = System::new(model, OperatingPoint::default()).unwrap();
    let excitation = Excitation::new(model, &system, 1.0, &ORDERS);
    forced_response(&system, &excitation, &[speed_rpm]).unwrap()
}

/// A steady run's order amplitudes at every node (`speed_rpm_records`, sampled at
/// `rate_hz`) agree with `model`'s frequency-domain response within 1 %.
fn assert_matches_response(
    model: &torsim::model::Model,
    speed_rpm_records: &[Vec<f64>],
    rate_hz: f64,
    speed_rpm: f64,
) {
    let r = response_at(model, speed_rpm);
    assert_orders_match(
        speed_rpm_records,
        rate_hz,
        speed_rpm,
        &r.ias_amplitude_rpm,
        &ORDERS,
        0.01,
    );
}

/// A linear model's steady run agrees with the frequency-domain response, order by
/// order, within 1 % at every node — the issue's bar. Measured at the default rtol 1e-5:
/// 0.004 % for order 1 and 0.027 % for order 2.5.
#[test]
fn linear_run_matches_frequency_domain() {
    let model = parse_model(THREE_DOF, "three.toml").unwrap();
    let speed_rpm = 1500.0;
    let options = RunOptions {
        rate_hz: 4096.0,
        ..RunOptions::default()
    };
    let sim = simulate(&model, Run::steady(speed_rpm, 2.0), options, &mut |_| true).unwrap();
    assert!(sim.settling.converged, "{:?}", sim.settling);
    assert_matches_response(&model, &sim.speed_rpm, options.rate_hz, speed_rpm);
}

/// The implicit integrator (ROS2), forced on the linear model, agrees with the frequency
/// domain within 1 % too: both integrators solve the same equations.
#[test]
fn implicit_run_matches_frequency_domain() {
    // Ten times the damping of THREE_DOF so that the start transient dies in ~3 s.
    let text = THREE_DOF.replace("damping = 1.5", "damping = 15.0");
    let model = parse_model(&text, "three.toml").unwrap();
    let speed_rpm = 1500.0;
    // 4000 Hz: one two-revolution cycle at 1500 rpm is exactly 320 samples, so the DFT
    // below spans whole periods of every order.
    let options = RunOptions {
        rate_hz: 4000.0,
        method: Method::Implicit,
        max_settle_s: 6.0,
        ..RunOptions::default()
    };
    let sim = simulate(&model, Run::steady(speed_rpm, 0.5), options, &mut |_| true).unwrap();
    assert!(sim.settling.converged, "{:?}", sim.settling);
    assert_matches_response(&model, &sim.speed_rpm, options.rate_hz, speed_rpm);
}

/// An undamped, unforced grounded chain conserves ½Σ Jω² + ½Σ kΔθ² over 200 periods of
/// its lowest mode (7000 of its highest) within 1e-6. Dormand–Prince is not symplectic:
/// its energy drift follows the tolerance (9e-6 at rtol 1e-9, so rtol 1e-11 here).
#[test]
fn undamped_free_vibration_conserves_energy() {
    let text = THREE_DOF
        .replace("damping = 2.0", "damping = 0.0")
        .replace("damping = 1.5", "damping = 0.0")
        .split("[[harmonic]]")
        .next()
        .unwrap()
        .to_string();
    let model = parse_model(&text, "undamped.toml").unwrap();
    let plant = Plant::new(&model, 1.0, None).unwrap();
    let profile = SpeedProfile::steady(1000.0);
    let mut scratch = torsim::transient::forces::Scratch::new(3);
    let mut rhs =
        |t: f64, y: &[f64], dy: &mut [f64]| plant.derivatives(t, y, dy, &profile, &mut scratch);
    let y0 = vec![0.001, -0.002, 0.003, 5.0, -3.0, 1.0];
    let energy = |y: &[f64]| {
        let (j, k) = ([0.5, 0.02, 0.01], [2.0e5, 1.0e4, 1.0e4]);
        let kinetic: f64 = (0..3).map(|i| 0.5 * j[i] * y[3 + i] * y[3 + i]).sum();
        let twists = [y[0] - y[1], y[1] - y[2], y[2]];
        kinetic
            + (0..3)
                .map(|i| 0.5 * k[i] * twists[i] * twists[i])
                .sum::<f64>()
    };
    let e0 = energy(&y0);
    let mut d = Dopri5::new(0.0, y0, 1e-5, 1e-3, 1e-11, vec![1e-14; 6], &mut rhs);
    let t_end = 200.0 / 15.0; // mode 1 is ~15 Hz
    while d.t < t_end {
        d.step(t_end, &mut rhs).unwrap();
    }
    let drift = (energy(&d.y) - e0).abs() / e0;
    assert!(drift < 1e-6, "energy drift {drift:e}");
}

const RUBBER_1DOF: &str = r#"format = 1
name = "rubber 1-DOF"
[[inertia]]
name = "a"
inertia = 0.1
[[connection]]
kind = "rubber"
name = "r"
from = "a"
to = "ground"
stiffness = 1.0e4
psi = 1.0
frequency_poly = [-0.000023, 0.01519, 1.0]
frequency_poly_range = [0.0, 300.0]
[[harmonic]]
at = "a"
order = 1.0
amplitude = 20.0
phase_deg = 0.0
"#;

/// The steady order-1 IAS amplitude of [`RUBBER_1DOF`] at 2400 rpm (40 Hz, near its
/// resonance, ~55 Hz with α_f), simulated with `viscous_above_hz`, and the closed form
/// `T/|c_Tstat·(K*(ω) + iω·c_v) − ω²J|` with K* the chain the run reports and `c_v` the
/// dashpot of the arms it took out, rpm. Also the number of arms before and after.
fn rubber_1dof(viscous_above_hz: Option<f64>) -> (f64, f64, [usize; 2]) {
    let model = parse_model(RUBBER_1DOF, "r.toml").unwrap();
    let speed_rpm = 2400.0;
    let options = RunOptions {
        rate_hz: 4096.0,
        viscous_above_hz,
        ..RunOptions::default()
    };
    let sim = simulate(&model, Run::steady(speed_rpm, 2.0), options, &mut |_| true).unwrap();
    assert!(matches!(
        model.connections[0].kind,
        ConnectionKind::Rubber(_)
    ));
    // The run's chain is the model's own (one law in every view), less any fast arms.
    let system = System::new(&model, OperatingPoint::default()).unwrap();
    let full = system.chains[0].clone().unwrap();
    let viscous_s = viscous_above_hz.map_or(0.0, |f| full.clone().take_fast_arms(f));
    let chain = &sim.chains[0].1;
    if viscous_above_hz.is_none() {
        assert_eq!(*chain, full);
    }
    let omega = speed_rpm * TAU / 60.0;
    let k = 1.0e4 * (chain.complex_stiffness(omega / TAU) + Complex64::new(0.0, omega * viscous_s));
    let theta = 20.0 / (k - Complex64::new(omega * omega * 0.1, 0.0)).norm();
    let expected_rpm = omega * theta * 60.0 / TAU;
    let got = order_amplitude(&sim.speed_rpm[0], options.rate_hz, speed_rpm, 1.0);
    (got, expected_rpm, [full.arms.len(), chain.arms.len()])
}

/// One inertia on a rubber stage to ground under a harmonic torque: the steady amplitude
/// equals T/|c_Tstat·K*(ω) − ω²J| with K* the fitted Maxwell chain's complex stiffness
/// (within 0.5 %), so the chain is what the integrator solves.
#[test]
fn rubber_chain_response_matches_its_complex_stiffness() {
    let (got, expected_rpm, [full, run]) = rubber_1dof(None);
    assert_eq!(full, run);
    assert!(
        (got - expected_rpm).abs() / expected_rpm < 0.005,
        "{got} vs {expected_rpm}"
    );
}

/// The same with the arms faster than 120 Hz (three times the 40 Hz excitation) run as
/// their dashpot: the run solves the shorter chain plus the dashpot (within the same
/// 0.5 %), and its amplitude moves from the whole chain's by what the two closed forms
/// say (measured: 3 of 6 arms taken out, +2.0 % at 40 Hz, where the ~55 Hz resonance
/// doubles a stiffness change), to 0.1 % of the amplitude.
#[test]
fn fast_arms_run_as_their_dashpot() {
    let (got, expected_rpm, [full, run]) = rubber_1dof(Some(120.0));
    assert!(run < full, "{run} arms of {full}");
    assert!(
        (got - expected_rpm).abs() / expected_rpm < 0.005,
        "{got} vs {expected_rpm}"
    );
    let (whole, whole_expected_rpm, _) = rubber_1dof(None);
    let (moved, predicted) = (got - whole, expected_rpm - whole_expected_rpm);
    assert!(predicted.abs() < 0.05 * whole, "{predicted} of {whole}");
    assert!(
        (moved - predicted).abs() < 1e-3 * whole,
        "{moved} vs {predicted}"
    );
}

/// One inertia on a shaft to the frame: 0.1 kg·m², 2567 N·m/rad (25.5 Hz), 0.16
/// N·m·s/rad (0.5 % of critical, issue 14's lightest benches), forced at order 1 by
/// 10 N·m. At 1500 rpm order 1 is 25 Hz and a working cycle (two revolutions) lasts
/// 80 ms, 2.04 periods of the mode: a ringing changes by only 0.25 of itself per cycle,
/// and decays as e^{−0.8 t}.
const LIGHT: &str = r#"format = 1
name = "one lightly damped mode beside order 1"
[[inertia]]
name = "mass"
inertia = 0.1
[[connection]]
kind = "shaft"
from = "mass"
to = "ground"
stiffness = 2567.0
damping = 0.16
[[harmonic]]
at = "mass"
order = 1.0
amplitude = 10.0
phase_deg = 30.0
"#;

/// Settled in at most 4 cycles to the default 1e-4. Started at rest, the same run had
/// not settled after the 2 s allowed (25 cycles, change 6.4 % of the vibration: measured
/// with the periodic start taken out). Order 1, 0.98 of the mode's frequency, within 1 %
/// of the frequency domain over 1 s (the bar of `linear_run_matches_frequency_domain`; measured
/// 0.44 %: this close to resonance the 12-cycle window and rtol 1e-5 weigh more).
#[test]
fn a_lightly_damped_mode_is_not_rung_by_the_start() {
    let model = parse_model(LIGHT, "light.toml").unwrap();
    let speed_rpm = 1500.0;
    // 4000 Hz: a cycle at 1500 rpm is exactly 320 samples.
    let options = RunOptions {
        rate_hz: 4000.0,
        max_settle_s: 2.0,
        ..RunOptions::default()
    };
    let sim = simulate(&model, Run::steady(speed_rpm, 1.0), options, &mut |_| true).unwrap();
    assert!(sim.settling.converged, "{:?}", sim.settling);
    assert!(sim.settling.cycles <= 4, "{:?}", sim.settling);
    let system = System::new(&model, OperatingPoint::default()).unwrap();
    let excitation = Excitation::new(&model, &system, 1.0, &[1.0]);
    let r = forced_response(&system, &excitation, &[speed_rpm]).unwrap();
    let time = order_amplitude(&sim.speed_rpm[0], options.rate_hz, speed_rpm, 1.0);
    let freq = r.ias_amplitude_rpm[0][0][0];
    let err = (time - freq).abs() / freq;
    assert!(
        err < 1e-2,
        "time {time} vs frequency {freq} ({:.3} %)",
        100.0 * err
    );
}

/// The spec's three-DOF example (`tests/data/spec-examples/three-dof.toml`: two rubber
/// stages, ψ = 0.9, no amplitude law: a linear model) swept through its first mode: the
/// time domain's steady order-1 IAS at the engine agrees with `response` within 1 % at
/// every speed, the resonance included (issue 15: one rubber law in every view; it was
/// +93 % at mode 1 when the time domain fitted its own chain per run). The harmonic is cut
/// from 100 to 5 N·m: at 100 N·m the resonant swing (0.17 rad) modulates the crank angle
/// the time domain drives at and moves 1.6 % of order 1 into order 2, a real nonlinearity
/// of the time domain that the linear response leaves out. Measured worst: printed.
#[test]
fn rubber_model_matches_the_frequency_domain_through_its_resonance() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/spec-examples/three-dof.toml"
    ))
    .unwrap()
    .replace("amplitude = 100.0", "amplitude = 5.0");
    let model = parse_model(&text, "three-dof.toml").unwrap();
    assert!(
        model.harmonics.iter().all(|h| matches!(
            h.amplitude,
            torsim::model::HarmonicAmplitude::Constant(a) if a <= 5.0
        )),
        "the harmonic was cut"
    );
    let system = System::new(&model, OperatingPoint::default()).unwrap();
    let mode_1_hz = torsim::modal::modes(&system).unwrap()[0].frequency_hz;
    let resonance_rpm = 60.0 * mode_1_hz;
    let speeds: Vec<f64> = [0.6, 0.85, 0.95, 1.0, 1.05, 1.15, 1.5]
        .iter()
        .map(|x| (x * resonance_rpm / 10.0).round() * 10.0)
        .collect();
    let excitation = Excitation::new(&model, &system, 1.0, &[1.0]);
    let r = forced_response(&system, &excitation, &speeds).unwrap();
    let mut worst: f64 = 0.0;
    for (i, &speed_rpm) in speeds.iter().enumerate() {
        // A rate that makes one two-revolution cycle a whole number of samples.
        let cycle_s = 120.0 / speed_rpm;
        let rate_hz = (4096.0 * cycle_s).round() / cycle_s;
        let options = RunOptions {
            rate_hz,
            max_settle_s: 20.0,
            ..RunOptions::default()
        };
        let sim = simulate(&model, Run::steady(speed_rpm, 1.0), options, &mut |_| true).unwrap();
        assert!(
            sim.settling.converged,
            "{speed_rpm} rpm: {:?}",
            sim.settling
        );
        let time = order_amplitude(&sim.speed_rpm[0], rate_hz, speed_rpm, 1.0);
        let freq = r.ias_amplitude_rpm[0][0][i];
        let err = (time - freq).abs() / freq;
        worst = worst.max(err);
        assert!(
            err < 0.01,
            "{speed_rpm} rpm: time {time} vs frequency {freq} rpm ({:.3} %)",
            100.0 * err
        );
    }
    eprintln!("worst {:.4} %", 100.0 * worst);
}

/// A damped gear mesh is one law in both domains: THREE_DOF with its hub–flange shaft
/// made a 1:2 gear (mesh 2.5e3 N·m/rad and 10 N·m·s/rad at the flange side: 1e4 and 40
/// referred to the hub), no play. The steady run (Dormand–Prince, where the mesh is the
/// free-play law at zero play) agrees with the frequency domain within 1 % at every node
/// and order, as the linear chain does above; and the mesh damping matters there: without
/// it the frequency domain moves by more than 5 % somewhere, so the check can fail.
#[test]
fn a_damped_gear_mesh_matches_the_frequency_domain() {
    let gear = "kind = \"gear\"\nfrom = \"hub\"\nto = \"flange\"\nratio = 2.0\n\
                mesh_stiffness = 2.5e3\nmesh_damping = 10.0";
    let text = THREE_DOF.replacen(
        "kind = \"shaft\"\nfrom = \"hub\"\nto = \"flange\"\nstiffness = 1.0e4\ndamping = 1.5",
        gear,
        1,
    );
    assert!(text.contains("mesh_damping"));
    let model = parse_model(&text, "geared.toml").unwrap();
    let speed_rpm = 1500.0;
    let options = RunOptions {
        rate_hz: 4096.0,
        method: Method::Explicit,
        ..RunOptions::default()
    };
    let sim = simulate(&model, Run::steady(speed_rpm, 2.0), options, &mut |_| true).unwrap();
    assert!(sim.settling.converged, "{:?}", sim.settling);
    assert_matches_response(&model, &sim.speed_rpm, options.rate_hz, speed_rpm);
    let r = response_at(&model, speed_rpm);
    let undamped_model = parse_model(&text.replace("mesh_damping = 10.0", ""), "u.toml").unwrap();
    let undamped = response_at(&undamped_model, speed_rpm);
    let largest_effect = (r.ias_amplitude_rpm.iter().flatten().flatten())
        .zip(undamped.ias_amplitude_rpm.iter().flatten().flatten())
        .map(|(with, without)| (without - with).abs() / with)
        .fold(0.0, f64::max);
    assert!(
        largest_effect > 0.05,
        "mesh damping moves the response by {largest_effect}"
    );
}
