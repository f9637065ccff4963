//! An evenly firing engine makes only its own orders in the time domain: no half orders
//! from the integration, and no start transient left in the record, even where a lightly
//! damped mode makes a half order resonant. The diagnosis compares those orders with a
//! bench's noise (0.001 rpm on benchtruth's campaigns), so the time domain must put
//! nothing there that the engine does not.
//!
//! The model is benchtruth control 2047 with the plain parameters torsim fitted to it
//! (`tests/data/models/six-cylinder-half-order.toml`): six cylinders firing every 120°,
//! mode 1 at 15.7 Hz with 1.3 % damping (a quality factor of 39), so order 0.5 is resonant
//! near 1870 rpm. Before the pressure curve was integrated as its Fourier series through
//! order 48 (`src/transient/pressure.rs`), the crank's order 0.5 came out at 0.036–0.052
//! rpm at the diagnosis' settings below; before steady runs settled for the slowest mode's
//! decay (`diagnose::settling::min_settle_s`), 0.0044 rpm at 2250 rpm.

use torsim::model::parse_model;
use torsim::recording::Run;
use torsim::transient::{RunOptions, simulate};

mod transient_support;
use transient_support::order_amplitude;

/// The crank's orders 0.5, 1 and 3 at `speed_rpm`, eight cycles recorded after settling
/// at the diagnosis' settings (`src/diagnose/forward.rs`: rtol 1e-4, 90 steps a cycle,
/// settled to 2e-3 and for 5.3 decay times of mode 1, 1/(ζω) = 0.78 s).
fn crank_orders(speed_rpm: f64) -> [f64; 3] {
    let text = std::fs::read_to_string("tests/data/models/six-cylinder-half-order.toml")
        .expect("the model file");
    let model = parse_model(&text, "six-cylinder-half-order.toml").expect("model");
    let cycle_s = 120.0 / speed_rpm;
    // 256 samples a cycle: every half order is a whole number of periods in a cycle.
    let rate_hz = 256.0 / cycle_s;
    let options = RunOptions {
        load: 1.0,
        rate_hz,
        rtol: 1e-4,
        settle_tolerance: 2e-3,
        min_settle_s: 5.3 * 0.78,
        max_settle_s: 16.0,
        min_steps_per_cycle: 90.0,
        viscous_above_hz: Some(3.0 * 8.0 * speed_rpm / 60.0),
        ..RunOptions::default()
    };
    let sim = simulate(
        &model,
        Run::steady(speed_rpm, 8.0 * cycle_s),
        options,
        &mut |_| true,
    )
    .expect("run");
    let crank = sim
        .node_names
        .iter()
        .position(|n| n == "crank")
        .expect("crank");
    let ias = &sim.speed_rpm[crank];
    [0.5, 1.0, 3.0].map(|q| order_amplitude(ias, rate_hz, speed_rpm, q))
}

/// At the half order's resonance (1860 rpm) and above it (2250 rpm): orders 0.5 and 1
/// stay below 1e-3 rpm, the bench noise they are compared with, where the firing order
/// is 4–7.5 rpm. Measured: 0.00072 and 0.000015 rpm at 1860, 0.00020 and 0.00003 at 2250
/// (0.00054 and 0.00004 for order 0.5 while the speed governor still damped mode 1).
#[test]
fn an_even_firing_engine_makes_no_half_orders() {
    for speed_rpm in [1860.0, 2250.0] {
        let [half, first, third] = crank_orders(speed_rpm);
        eprintln!("{speed_rpm} rpm: order 0.5 {half:.6}, 1 {first:.6}, 3 {third:.4} rpm");
        assert!(third > 3.0, "{speed_rpm} rpm: the firing order is {third}");
        assert!(
            half < 1e-3 && first < 1e-3,
            "{speed_rpm} rpm: {half}, {first}"
        );
    }
}
