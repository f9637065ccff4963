//! Times a steady run and a run-up of two presets (release build):
//! `cargo run --release --example time_runs [rtol] [explicit|implicit]`.
use std::time::Instant;
use torsim::model::{parse_model, presets};
use torsim::recording::Run;
use torsim::transient::{Method, RunOptions, simulate};

fn main() {
    let rtol: f64 = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(1e-5);
    let method = match std::env::args().nth(2).as_deref() {
        Some("implicit") => Method::Implicit,
        Some("explicit") => Method::Explicit,
        _ => Method::Auto,
    };
    let run = |name: &str, kind: Run| {
        let preset = presets::preset(name).expect("preset");
        let model = parse_model(preset.text, name).expect("model");
        let start = Instant::now();
        let options = RunOptions {
            rtol,
            method,
            ..RunOptions::default()
        };
        let sim = simulate(&model, kind, options, &mut |_| true).expect("run");
        let secs = start.elapsed().as_secs_f64();
        let simulated = sim.settling.time_s + sim.time_s.len() as f64 / options.rate_hz;
        let ias = &sim.speed_rpm[sim.reference_node];
        let (lo, hi) = ias
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
        println!(
            "{name} {kind:?}: {secs:.3} s wall for {simulated:.2} s simulated ({:.0}× real time); settled in {} cycles; steps {:?}; crank IAS {lo:.2}…{hi:.2} rpm",
            simulated / secs,
            sim.settling.cycles,
            sim.steps
        );
    };
    run("test-rig-70sh", Run::steady(3000.0, 2.0));
    run("cng-genset", Run::steady(1500.0, 2.0));
    run("cng-genset", Run::ramp(400.0, 2000.0, 20.0));
}
