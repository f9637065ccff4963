//! Issue 13, "Crashes and hangs" and deliverable 2: every size a run or a sweep allocates
//! is checked against `torsim::limits` before allocating, with an error that names the key
//! or flag and the limit; a run that would not end stops on its step budget naming the
//! element responsible; a thermal rubber stage with a tiny heat capacity runs.
//! Each case here aborted on an allocation of terabytes, or hung, before the fix.

use std::process::Command;
use torsim::model::{ConnectionKind, Model, Thermal, parse_model, presets};
use torsim::physics::{Excitation, OperatingPoint, PhysicsError, System};
use torsim::recording::Run;
use torsim::response::forced_response;
use torsim::transient::budget::state_name;
use torsim::transient::plant::Plant;
use torsim::transient::{Method, RunOptions, TransientError, simulate};

fn rig() -> Model {
    let p = presets::preset("test-rig-70sh").expect("preset");
    parse_model(p.text, "test-rig-70sh").expect("model")
}

fn steady(speed_rpm: f64, duration_s: f64) -> Run {
    Run::steady(speed_rpm, duration_s)
}

fn run(
    model: &Model,
    kind: Run,
    options: RunOptions,
) -> Result<torsim::transient::Simulation, TransientError> {
    simulate(model, kind, options, &mut |_| true)
}

/// The message of a run that must fail.
fn error_of(kind: Run, options: RunOptions) -> String {
    match run(&rig(), kind, options) {
        Ok(_) => panic!("{kind:?} ran"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn huge_durations_and_rates_are_refused_before_allocating() {
    // 1e9 s × 10240 Hz: 82 TB before the fix.
    let e = error_of(steady(1500.0, 1e9), RunOptions::default());
    assert!(
        e.contains("--duration-s") && e.contains("--max-samples") && e.contains("134217728"),
        "{e}"
    );
    // 2 s × 1e12 Hz: 8 TB.
    let options = RunOptions {
        rate_hz: 1e12,
        ..RunOptions::default()
    };
    let e = error_of(steady(1500.0, 2.0), options);
    assert!(
        e.contains("--rate-hz") && e.contains("--max-samples"),
        "{e}"
    );
}

#[test]
fn speeds_beyond_the_limit_are_refused() {
    // A ramp to 1e9 rpm hung (a step of 1e-10 s); 1e6 rpm gave no order at all.
    let ramp = Run::ramp(1000.0, 1e9, 1.0);
    let e = error_of(ramp, RunOptions::default());
    assert!(
        e.contains("to_rpm (--run-up TO) = 1e9") && e.contains("--max-speed-rpm"),
        "{e}"
    );
    let e = error_of(steady(1e6, 1.0), RunOptions::default());
    assert!(e.contains("--speed-rpm") && e.contains("100000"), "{e}");
    for bad in [0.0, -5.0, f64::NAN] {
        let e = error_of(steady(bad, 1.0), RunOptions::default());
        assert!(e.contains("must be a finite number > 0"), "{e}");
    }
}

#[test]
fn a_tolerance_below_min_rtol_is_refused() {
    let options = RunOptions {
        rtol: 1e-20,
        ..RunOptions::default()
    };
    let e = error_of(steady(1500.0, 1.0), options);
    assert!(
        e.contains("--rtol") && e.contains("min_rtol = 1e-12"),
        "{e}"
    );
}

/// At 3000 rpm the lowest order, 0.5, is 25 Hz: the analysis reports orders up to 0.8 ×
/// Nyquist, so 40 Hz (16 Hz) carries none and 63 Hz (25.2 Hz) carries it.
#[test]
fn an_output_rate_that_carries_no_order_is_refused() {
    let options = RunOptions {
        rate_hz: 40.0,
        ..RunOptions::default()
    };
    let e = error_of(steady(3000.0, 1.0), options);
    assert!(
        e.contains("cannot carry any order") && e.contains("--rate-hz ≥ 63"),
        "{e}"
    );
}

/// A shaft of 10¹² N·m/rad on the 5 g·m² gearbox output: a 380 kHz mode that holds
/// Dormand–Prince at a step of ~4e-7 s, 1000 times below the 4e-4 s the excitation needs.
/// Before the budget the run took minutes; now it stops in about a second, naming the
/// shaft and the implicit method.
#[test]
fn an_explicit_run_held_by_stability_stops_on_its_budget() {
    let mut model = rig();
    for c in &mut model.connections {
        if let ConnectionKind::Shaft(s) = &mut c.kind {
            s.stiffness_nm_per_rad = 1e12;
        }
    }
    let options = RunOptions {
        method: Method::Explicit,
        ..RunOptions::default()
    };
    match run(&model, steady(3000.0, 0.2), options) {
        Err(TransientError::StepBudget { time_s, cause, .. }) => {
            assert!(time_s < 1.0, "{time_s}");
            assert!(
                cause.contains("connection `a`") && cause.contains("--method implicit"),
                "{cause}"
            );
        }
        other => panic!("{:?}", other.map(|s| s.steps)),
    }
}

/// A heat capacity of 1e-9 J/K (C/G = 1e-9 s) hung even a 0.05 s run: its temperature
/// equation held the step at ~1e-9 s. With the time constant bounded below by one step the
/// run ends, and the mean temperature over the recording is still `ambient + P/G` (a
/// linear first-order lag keeps the mean of a periodic input): within 2 % of the rise.
#[test]
fn a_tiny_heat_capacity_runs_quasi_statically() {
    let mut model = rig();
    let conductance_w_per_k = 0.01;
    for c in &mut model.connections {
        if let ConnectionKind::Rubber(r) = &mut c.kind {
            r.thermal = Some(Thermal {
                capacity_j_per_k: 1e-9,
                conductance_w_per_k,
                ambient_c: 25.0,
            });
        }
    }
    let options = RunOptions {
        max_settle_s: 0.5,
        ..RunOptions::default()
    };
    let sim = run(&model, steady(3000.0, 0.2), options).expect("runs");
    assert!(sim.steps.0 + sim.steps.1 < 100_000, "{:?}", sim.steps);
    assert!(
        sim.warnings.iter().any(|w| w.contains("quasi-statically")),
        "{:?}",
        sim.warnings
    );
    for (c, temps) in &sim.temperature_c {
        let power = sim
            .power_loss_w
            .iter()
            .find(|(k, _)| k == c)
            .expect("power")
            .1;
        let rise = power / conductance_w_per_k;
        let mean = temps.iter().sum::<f64>() / temps.len() as f64;
        assert!(
            (mean - 25.0 - rise).abs() < 0.02 * rise,
            "{mean} vs 25 + {rise}"
        );
    }
}

#[test]
fn states_are_named_by_node_and_rubber_stage() {
    let mut model = rig();
    if let ConnectionKind::Rubber(r) = &mut model.connections[2].kind {
        r.thermal = Some(Thermal {
            capacity_j_per_k: 40.0,
            conductance_w_per_k: 8.0,
            ambient_c: 25.0,
        });
    }
    let plant = Plant::new(&model, 1.0, None).expect("plant");
    let n = plant.n_dof;
    assert!(state_name(&plant, n).starts_with("the vibration speed of node `engine"));
    assert!(state_name(&plant, 2 * n).starts_with("Maxwell arm 1 of rubber stage `b`"));
    let names: Vec<String> = (0..plant.state_len)
        .map(|i| state_name(&plant, i))
        .collect();
    assert!(
        names
            .iter()
            .any(|s| s == "the temperature of rubber stage `b` (°C)"),
        "{names:?}"
    );
}

/// Order 1e9 asked the peak synthesis for 137 GB; 1e5 hung.
#[test]
fn response_orders_beyond_the_limit_are_refused() {
    let model = rig();
    let system = System::new(
        &model,
        OperatingPoint {
            load: 1.0,
            temperature_c: None,
        },
    )
    .expect("system");
    for order in [1e9, 1e5] {
        let excitation = Excitation::new(&model, &system, 1.0, &[order]);
        match forced_response(&system, &excitation, &[1000.0, 2000.0]) {
            Err(e @ PhysicsError::Limit(_)) => {
                let e = e.to_string();
                assert!(e.contains("--orders") && e.contains("--max-order"), "{e}");
            }
            other => panic!("{:?}", other.map(|r| r.orders)),
        }
    }
}

/// `--max-order` raises the limit for one run; without it the same order exits 2.
#[test]
fn the_max_order_flag_raises_the_limit() {
    let torsim = |extra: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_torsim"))
            .args([
                "response",
                "preset:test-rig-70sh",
                "--orders",
                "150",
                "--from-rpm",
                "1000",
                "--to-rpm",
                "1100",
            ])
            .args(extra)
            .output()
            .expect("runs")
    };
    let refused = torsim(&[]);
    assert_eq!(refused.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert!(
        stderr.contains(
            "order (--orders) = 150 exceeds the limit of 100 (raise it with `--max-order`)"
        ),
        "{stderr}"
    );
    let raised = torsim(&["--max-order", "200"]);
    assert_eq!(
        raised.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&raised.stderr)
    );
}
