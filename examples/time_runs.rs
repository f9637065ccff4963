//! Times a steady run and a run-up of two presets (release build):
//! `cargo run --release --example time_runs`.
use std::time::Instant;
use torsim::model::{parse_model, presets};
use torsim::transient::{RunKind, RunOptions, simulate};

fn main() {
    let run = |name: &str, kind: RunKind| {
        let preset = presets::preset(name).expect("preset");
        let model = parse_model(preset.text, name).expect("model");
        let start = Instant::now();
        let sim = simulate(&model, kind, RunOptions::default(), &mut |_| true).expect("run");
        let secs = start.elapsed().as_secs_f64();
        let simulated = sim.settling.time_s + sim.time_s.len() as f64 / 10240.0;
        println!(
            "{name} {kind:?}: {secs:.3} s wall for {simulated:.2} s simulated ({:.0}× real time); settled {:?}; steps {:?}",
            simulated / secs,
            sim.settling,
            sim.steps
        );
    };
    run(
        "test-rig-70sh",
        RunKind::Steady {
            speed_rpm: 3000.0,
            duration_s: 2.0,
        },
    );
    run(
        "cng-genset",
        RunKind::Steady {
            speed_rpm: 1500.0,
            duration_s: 2.0,
        },
    );
    run(
        "cng-genset",
        RunKind::Ramp {
            from_rpm: 400.0,
            to_rpm: 2000.0,
            duration_s: 20.0,
        },
    );
}
