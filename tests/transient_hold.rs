//! The hold before a recording (`RunOptions::hold_s`): the start speed held after settling
//! with every state free, so that a self-heating rubber stage warms before the record
//! starts (issue 14: the diagnosis holds its simulated regimes as a bench does, benchtruth
//! case 2050). A hold of `H` then `d` recorded must be the last `d` of a run recorded
//! `H + d` from the same settled start: the hold is nothing but unrecorded time.

use torsim::model::{ConnectionKind, Model, Thermal, parse_model, presets};
use torsim::recording::Run;
use torsim::transient::{RunOptions, Simulation, simulate};

/// test-rig-70sh with its rubber stages warming into 40 J/K (time constant 5 s).
fn warming_rig() -> Model {
    let p = presets::preset("test-rig-70sh").expect("preset");
    let mut model = parse_model(p.text, "test-rig-70sh").expect("model");
    for c in &mut model.connections {
        if let ConnectionKind::Rubber(r) = &mut c.kind {
            r.thermal = Some(Thermal {
                capacity_j_per_k: 40.0,
                conductance_w_per_k: 8.0,
                ambient_c: r.temperature_c,
            });
        }
    }
    model
}

fn run(model: &Model, duration_s: f64, hold_s: f64) -> Simulation {
    let options = RunOptions {
        rate_hz: 2048.0,
        rtol: 1e-8,
        hold_s,
        ..RunOptions::default()
    };
    simulate(model, Run::steady(1500.0, duration_s), options, &mut |_| {
        true
    })
    .expect("runs")
}

/// Held 0.5 s then recorded 0.25 s: the same temperatures and speeds as the last 0.25 s
/// of a 0.75 s record. The tolerance is the integrator's (rtol 1e-8 here; the step
/// sequences differ where the hold ends): 1e-6 K and 1e-5 of the vibration.
#[test]
fn a_hold_is_unrecorded_time() {
    let model = warming_rig();
    let (hold_s, rec_s) = (0.5, 0.25);
    let long = run(&model, hold_s + rec_s, 0.0);
    let held = run(&model, rec_s, hold_s);
    let skip = (hold_s * 2048.0) as usize;
    let (_, t_long) = &long.temperature_c[0];
    let (_, t_held) = &held.temperature_c[0];
    // The stage warmed in the hold: the record starts warm.
    assert!(
        t_held[0] > t_long[0] + 0.05,
        "{} vs {}",
        t_held[0],
        t_long[0]
    );
    for (i, t) in t_held.iter().enumerate() {
        assert!(
            (t - t_long[skip + i]).abs() < 1e-6,
            "sample {i}: {t} vs {}",
            t_long[skip + i]
        );
    }
    let node = long.reference_node;
    let mean = long.speed_rpm[node].iter().sum::<f64>() / long.speed_rpm[node].len() as f64;
    let vibration = long.speed_rpm[node]
        .iter()
        .fold(0.0_f64, |m, v| m.max((v - mean).abs()));
    for (i, v) in held.speed_rpm[node].iter().enumerate() {
        let w = long.speed_rpm[node][skip + i];
        assert!(
            (v - w).abs() < 1e-5 * vibration,
            "sample {i}: {v} vs {w} rpm"
        );
    }
}

/// Without a hold the record starts at the model's temperature (settling holds it), to
/// the dense output's interpolation error at the first sample (1.3e-5 K seen; a
/// thousandth of what the 0.5 s hold above warms).
#[test]
fn without_a_hold_the_record_starts_at_the_start_temperature() {
    let model = warming_rig();
    let sim = run(&model, 0.1, 0.0);
    let (c, temps) = &sim.temperature_c[0];
    let start = match &model.connections[*c].kind {
        ConnectionKind::Rubber(r) => r.temperature_c,
        _ => unreachable!("a rubber stage"),
    };
    assert!((temps[0] - start).abs() < 1e-4, "{} vs {start}", temps[0]);
}

/// A negative or infinite hold is refused, naming the key and the flag.
#[test]
fn a_bad_hold_is_refused_by_name() {
    let model = warming_rig();
    for hold_s in [-1.0, f64::INFINITY, f64::NAN] {
        let options = RunOptions {
            hold_s,
            ..RunOptions::default()
        };
        let message = simulate(&model, Run::steady(1500.0, 0.1), options, &mut |_| true)
            .expect_err("refused")
            .to_string();
        assert!(message.contains("hold_s (--hold-s)"), "{message}");
    }
}
