//! `Method::Auto` takes the integrator that takes fewer steps (`transient::stepper::is_stiff`):
//! Dormand–Prince until the fastest eigenvalue × the largest step is far beyond its
//! stability limit, ROS2 past that. Step counts, not seconds: they are deterministic, and a
//! ROS2 step costs about what a Dormand–Prince step does (3 right-hand sides and 2 solves
//! against 6 right-hand sides), so fewer steps is the faster run on any machine.

use torsim::model::{Model, parse_model, presets};
use torsim::recording::Run;
use torsim::transient::{Method, RunOptions, simulate};

fn steps(model: &Model, run: Run, method: Method) -> (u64, u64) {
    let options = RunOptions {
        method,
        rate_hz: 2048.0,
        // The explicit run of the stiff model below takes ~10× more steps than its
        // largest step would: allowed here, so that both integrators finish.
        step_budget_factor: Some(1e4),
        ..RunOptions::default()
    };
    let sim = simulate(model, run, options, &mut |_| true).expect("simulates");
    sim.steps
}

/// Steps, accepted and rejected, of `auto`, Dormand–Prince and ROS2 on `run` of `model`.
fn steps_of_each(model: &Model, run: Run) -> [(u64, u64); 3] {
    [Method::Auto, Method::Explicit, Method::Implicit].map(|m| steps(model, run, m))
}

fn total(s: (u64, u64)) -> u64 {
    s.0 + s.1
}

/// `genset-20dof` at 1500 rpm: its gear mesh puts a 9.1 kHz mode in it, so the fastest
/// eigenvalue × largest step is 25, past Dormand–Prince's stability limit (3.3) but far
/// below where ROS2, of order 2, would catch up. `auto` runs Dormand–Prince, which takes
/// under a fifth of ROS2's steps (measured: 49 336 + 11 106 rejected against
/// 297 696 + 25 471 for 0.5 s and its settling). Under the rule before 2026-12-04
/// (threshold 20) `auto` took ROS2.
#[test]
fn a_mesh_mode_past_the_explicit_stability_limit_runs_explicit() {
    let preset = presets::preset("genset-20dof").expect("shipped");
    let model = parse_model(preset.text, "genset-20dof.toml").expect("parses");
    let [auto, explicit, implicit] = steps_of_each(&model, Run::steady(1500.0, 0.5));
    assert_eq!(auto, explicit, "auto took another integrator");
    assert!(
        5 * total(explicit) < total(implicit),
        "explicit {explicit:?}, implicit {implicit:?}"
    );
}

/// A 0.2 g·m² hub on a 2·10⁸ N·m/rad spline (a 160 kHz mode) at the end of the
/// two-inertia teaching model, in a run-up (no exact discretization): eigenvalue
/// (10⁶ rad/s) × largest step (417 µs at 1600 rpm) ≈ 420, past the threshold of 194 at
/// rtol 10⁻⁵, so Dormand–Prince is held to a step ~200× below the largest one. `auto` runs
/// ROS2, which takes under a quarter of Dormand–Prince's steps (measured: 55 613 + 510
/// rejected against 218 448 + 36 867).
#[test]
fn a_mode_far_past_the_explicit_stability_limit_runs_implicit() {
    let preset = presets::preset("two-inertia").expect("shipped");
    // Before the first `[[harmonic]]`, once.
    let text = preset.text.replacen(
        "[[harmonic]]",
        "[[inertia]]\nname = \"hub\"\ninertia = 2.0e-4\n\n\
         [[connection]]\nkind = \"shaft\"\nname = \"spline\"\nfrom = \"load\"\nto = \"hub\"\n\
         stiffness = 2.0e8\ndamping = 20.0\n\n[[harmonic]]",
        1,
    );
    let model = parse_model(&text, "stiff.toml").expect("parses");
    let [auto, explicit, implicit] = steps_of_each(&model, Run::ramp(1500.0, 1600.0, 0.2));
    assert_eq!(auto, implicit, "auto took another integrator");
    assert!(
        4 * total(implicit) < total(explicit),
        "explicit {explicit:?}, implicit {implicit:?}"
    );
}
