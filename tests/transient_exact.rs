//! The exact discretization of linear steady runs (issue 15, item 2,
//! `src/transient/exact.rs`): conserves an undamped chain's energy to rounding, gives what
//! Dormand–Prince at a tight tolerance gives, is what `Method::Auto` takes for such runs,
//! and is refused where the equations are not affine.

use std::f64::consts::TAU;
use torsim::model::{parse_model, presets};
use torsim::recording::Run;
use torsim::transient::exact::Exact;
use torsim::transient::plant::Plant;
use torsim::transient::{Method, RunOptions, simulate};

/// Three inertias on viscous shafts, the last grounded, driven by orders 1 and 2 at the
/// engine (the time-domain benchmark's model).
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
order = 2.0
amplitude = 40.0
phase_deg = 30.0
"#;

/// Free vibration of the undamped chain over 200 periods of mode 1 (13 s, 133 000 steps of
/// 0.1 ms): the energy stays within 1e-9, what rounding in `e^{hA}` accumulates (~1e-15
/// per step; measured 5.4e-11). Dormand–Prince at rtol 1e-11 is held to 1e-6 by
/// `transient_reference`.
#[test]
fn an_undamped_chain_keeps_its_energy_to_rounding() {
    let text = THREE_DOF
        .replace("damping = 2.0", "damping = 0.0")
        .replace("damping = 1.5", "damping = 0.0")
        .split("[[harmonic]]")
        .next()
        .unwrap()
        .to_string();
    let model = parse_model(&text, "undamped.toml").unwrap();
    let plant = Plant::new(&model, 1.0, None).unwrap();
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
    let mut exact = Exact::new(&plant, 1000.0, y0, 1e-4).expect("a linear plant");
    let t_end = 200.0 / 15.0;
    while exact.t < t_end {
        exact.step(t_end).unwrap();
    }
    let drift = (energy(exact.y()) - e0).abs() / e0;
    eprintln!("energy drift {drift:e} after {} steps", exact.steps.0);
    assert!(drift < 1e-9, "energy drift {drift:e}");
}

/// A steady run of the driven chain: every sample of every node's speed within 2e-6 of the
/// peak vibration of Dormand–Prince at rtol 1e-10 (measured 5.6e-7: the second-order
/// remainder, ~(ωh)² of the 1e-4 the crank angle adds), and `Method::Auto` takes the exact
/// integrator: one step per sample (and one shortened step at the end of each settling
/// cycle), none rejected.
#[test]
fn a_driven_chain_matches_dormand_prince_at_a_tight_tolerance() {
    let model = parse_model(THREE_DOF, "three.toml").unwrap();
    let run = Run::steady(3000.0, 0.5);
    // Both settled until a cycle changes the speeds by < 1e-9 of the vibration, so that
    // what is compared is the steady state, not what is left of the start.
    // (Settling asks for no less than 20·rtol: the exact integrator has no error to
    // tolerate, so rtol here only sets that floor.)
    let settled = RunOptions {
        settle_tolerance: 1e-9,
        rtol: 1e-10,
        ..RunOptions::default()
    };
    let exact = simulate(&model, run, settled, &mut |_| true).unwrap();
    let tight = RunOptions {
        method: Method::Explicit,
        ..settled
    };
    let reference = simulate(&model, run, tight, &mut |_| true).unwrap();
    let samples = exact.time_s.len();
    let settle_steps = (exact.settling.time_s * RunOptions::default().rate_hz).round() as u64;
    let (accepted, rejected) = exact.steps;
    let whole = samples as u64 + settle_steps;
    assert_eq!(rejected, 0);
    assert!(
        (whole..=whole + exact.settling.cycles as u64).contains(&accepted),
        "{accepted} steps for {whole} sample intervals"
    );
    let mut worst: f64 = 0.0;
    let mut peak: f64 = 0.0;
    for (a, b) in exact.speed_rpm.iter().zip(&reference.speed_rpm) {
        for (x, y) in a.iter().zip(b) {
            worst = worst.max((x - y).abs());
            peak = peak.max((y - 3000.0).abs());
        }
    }
    eprintln!("worst {worst:e} rpm of a peak vibration {peak} rpm");
    assert!(worst < 2e-6 * peak, "{worst} rpm against {peak} rpm");
}

/// An engine, or equations that are not affine (a gear with free play), are not for the
/// exact integrator: `Auto` goes to Dormand–Prince, and `Exact` is refused saying why.
#[test]
fn engines_and_free_play_are_refused() {
    let genset = parse_model(presets::preset("cng-genset").unwrap().text, "g.toml").unwrap();
    let exact = RunOptions {
        method: Method::Exact,
        ..RunOptions::default()
    };
    let e = simulate(&genset, Run::steady(1500.0, 0.1), exact, &mut |_| true)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("exact integrator") && e.contains("engine"),
        "{e}"
    );
    let geared = THREE_DOF.replace(
        "kind = \"shaft\"\nfrom = \"hub\"\nto = \"flange\"\nstiffness = 1.0e4\ndamping = 1.5",
        "kind = \"gear\"\nfrom = \"hub\"\nto = \"flange\"\nratio = 1.0\nmesh_stiffness = 1.0e4\nbacklash_deg = 0.5",
    );
    let model = parse_model(&geared, "geared.toml").unwrap();
    let plant = Plant::new(&model, 1.0, None).unwrap();
    let y0 = vec![0.0; plant.state_len];
    assert!(Exact::new(&plant, 3000.0, y0, 1e-4).is_none());
    let omega = 3000.0 * TAU / 60.0;
    assert!(omega > 0.0);
}
