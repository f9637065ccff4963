//! The speed governor that holds a free driveline's mean speed does not touch its
//! vibration: the time domain of an engine-driven driveline with a load agrees with
//! `response` through its resonance.
//!
//! The governor's PI loop used to act at the load node on its raw speed. Its proportional
//! part, 2ω_g·ΣJ = 27 N·m·s/rad here, was then a damper at every frequency that the
//! frequency domain does not have: the crank's order 3 at the 75 Hz resonance came out
//! 7.5 % below `response`, and 10–16 % above it near the crank's antiresonance on
//! benchtruth control 2014 (whose recordings agreed with `response`, README issue 15).
//! It now acts on the rigid-body coordinate, spread by inertia, with its proportional
//! part on that speed low-passed (`transient::plant::Governor`); on control 2014
//! `simulate` went from 2.710 to 2.460 rpm against `response`'s 2.447.

use torsim::model::parse_model;
use torsim::physics::{Excitation, OperatingPoint, System};
use torsim::recording::Run;
use torsim::response::forced_response;
use torsim::transient::{RunOptions, simulate};

mod transient_support;
use transient_support::order_amplitude;

/// Crank (1.3 kg·m²) and brake (3 kg·m²) on a shaft of 2e5 N·m/rad: one mode at
/// √(k(1/J1 + 1/J2))/2π = 74.7 Hz with 3.5 % damping, which order 3 of the six cylinders
/// meets at 1494 rpm. The brake is the load (15 N·m·s/rad) and nothing is grounded, so
/// the governor holds the speed. A weak pressure curve (5 bar peak) keeps the engine's
/// dependence on the vibrating crank angle at ~1e-4 of the response.
const FREE_TWO_DOF: &str = r#"format = 1
name = "free two-DOF with a load"
[[inertia]]
name = "crank"
inertia = 1.3
[[inertia]]
name = "brake"
inertia = 3.0
[[connection]]
kind = "shaft"
from = "crank"
to = "brake"
stiffness = 2.0e5
damping = 30.0
[engine]
at = "crank"
cylinders = 6
firing_angles_deg = [0, 480, 240, 600, 120, 360]
bore = 0.12
crank_radius = 0.062
conrod_length = 0.2
reciprocating_mass = 0.0
pressure = { crank_angle_deg = [-360, -60, -20, 0, 10, 30, 60, 120, 360], bar = [0.0, 0.6, 2.5, 4.0, 5.0, 3.0, 1.2, 0.3, 0.0] }
[load]
at = "brake"
damping = 15.0
"#;

/// The crank's and the brake's order `q` from `simulate` and from `response` at
/// `speed_rpm`: `(node, time, frequency)`.
fn both_views(speed_rpm: f64, q: f64) -> Vec<(usize, f64, f64)> {
    let model = parse_model(FREE_TWO_DOF, "free.toml").unwrap();
    let rate_hz = 8192.0;
    let options = RunOptions {
        rate_hz,
        ..RunOptions::default()
    };
    let sim = simulate(&model, Run::steady(speed_rpm, 2.0), options, &mut |_| true).unwrap();
    assert!(sim.settling.converged, "{:?}", sim.settling);
    let system = System::new(&model, OperatingPoint::default()).unwrap();
    let excitation = Excitation::new(&model, &system, 1.0, &[q]);
    let r = forced_response(&system, &excitation, &[speed_rpm]).unwrap();
    (0..2)
        .map(|node| {
            let time = order_amplitude(&sim.speed_rpm[node], rate_hz, speed_rpm, q);
            (node, time, r.ias_amplitude_rpm[node][0][0])
        })
        .collect()
}

/// Order 3 at the resonance (1494 rpm) and below it (1020 rpm), and order 6 at 1020 rpm,
/// within 0.3 % at both nodes; measured 0.002–0.17 %, where the governor on the load's
/// raw speed gave −7.3 % (11.098 against 11.967 rpm at the crank) and +1.2 %. Order 6 at
/// the resonance is left out: the crank's 12 rpm of order 3 turn the crank angle by
/// 2.7 mrad, and the engine's kinematics at the vibrating angle double it into order 6
/// (0.073 against 0.099 rpm), physics the linear view does not have.
#[test]
fn the_governor_leaves_the_resonance_to_the_load_damping() {
    for (speed_rpm, q) in [(1494.0, 3.0), (1020.0, 3.0), (1020.0, 6.0)] {
        for (node, time, freq) in both_views(speed_rpm, q) {
            let gap = (time - freq) / freq;
            assert!(
                gap.abs() < 3e-3,
                "{speed_rpm} rpm, node {node}, order {q}: time {time} against {freq} ({:+.3} %)",
                100.0 * gap
            );
        }
    }
}
