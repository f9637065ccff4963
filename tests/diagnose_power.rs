//! `diagnose --power` (issue 14, item 6): the linearised detectability analysis, and its
//! check against full diagnoses of synthetic campaigns.

use torsim::diagnose::power_plan::Bench;
use torsim::diagnose::power_run::power;
use torsim::diagnose::{DiagnoseOptions, LabelledRecording, diagnose};
use torsim::model::{Model, parse_model, presets};
use torsim::recording::RunShape;
use torsim::synth::{
    Effect, EffectSpec, Measurement, Plan, PlanDurations, PlannedRun, build_truth, generate,
};

fn bench_model() -> Model {
    let p = presets::preset("diagnosis-bench").expect("shipped");
    parse_model(p.text, "diagnosis-bench.toml").expect("parses")
}

/// A small plan: three steady regimes at full load, one at part load.
fn small_plan() -> Plan {
    let steady = |label: &str, speed_rpm: f64, load: f64| PlannedRun {
        file: label.to_lowercase(),
        label: label.into(),
        shape: RunShape::steady(speed_rpm, 4.0),
        duration_s: 4.0,
        load,
        rate_hz: None,
    };
    Plan {
        runs: vec![
            steady("A", 1200.0, 1.0),
            steady("B", 1800.0, 1.0),
            steady("C", 2400.0, 1.0),
            steady("D", 1800.0, 0.3),
        ],
    }
}

/// Quick: every row is finite, cylinder imbalance is detectable, and four times the
/// noise makes its detectable size grow by more than 3 and less than 16: λ ∝ 1/σ² gives
/// size ∝ σ (×4) where the signal is above the noise; an order under the noise is a
/// biased magnitude that moves only as A²/σ, so size grows up to ∝ σ² there (×16). Its
/// signature, the half orders, has small amplitudes, so the 0.5 % model floor (which
/// would hold the ratio near 1) plays no part.
#[test]
fn detectable_sizes_scale_with_the_noise() {
    let model = bench_model();
    let plan = small_plan();
    let mut bench = Bench::default_for(&model);
    bench.jitter_ns = 0.0;
    let quiet = power(&model, &plan, &bench, 2, &mut |_, _| true).expect("analysis");
    bench.noise_rpm *= 4.0;
    let loud = power(&model, &plan, &bench, 2, &mut |_, _| true).expect("analysis");
    let imbalance = |r: &torsim::diagnose::power::PowerReport| {
        r.effects
            .iter()
            .find(|e| e.effect == "cylinder_imbalance")
            .and_then(|e| e.detectable_size)
            .expect("imbalance detectable")
    };
    for e in &quiet.effects {
        assert!(
            e.lambda_typical.is_finite() && e.lambda_typical >= 0.0,
            "{e:?}"
        );
    }
    let ratio = imbalance(&loud) / imbalance(&quiet);
    // Measured 5.70 (2025 build): between the linear (4) and the biased (16) regimes.
    assert!(ratio > 3.0 && ratio < 16.0, "ratio {ratio}");
    serde_json::to_string(&quiet).expect("serialises");
}

/// Diagnoses a synthetic campaign of `effect` with parameter `key` at `value`.
fn diagnose_case(model: &Model, key: &str, value: f64, effect: Effect) -> String {
    let spec = EffectSpec::new(effect).with(key, value);
    let truth = build_truth(model, &spec, 0.0, 3).expect("truth");
    let plan = Plan::default_for(model, PlanDurations::default()).expect("plan");
    let measurement = Measurement {
        stations: torsim::synth::Station::defaults(model),
        ..Measurement::default()
    };
    let recs = generate(&truth, &plan, &measurement, &mut |_| true).expect("generated");
    let labelled: Vec<LabelledRecording> = recs
        .into_iter()
        .map(|r| LabelledRecording {
            label: r.recording.meta.label.clone().unwrap_or(r.file),
            recording: r.recording,
        })
        .collect();
    let report = diagnose(
        model,
        &labelled,
        &DiagnoseOptions::default(),
        &mut |_, _| true,
    )
    .expect("diagnosis");
    report.verdict.effect
}

/// The check against full diagnoses (slow: four campaigns): cylinder imbalance at twice
/// its detectable size is named; at 0.3 times it is not.
#[test]
#[ignore]
fn full_diagnoses_agree_with_the_detectable_size() {
    let model = bench_model();
    let plan = Plan::default_for(&model, PlanDurations::default()).expect("plan");
    let bench = Bench::default_for(&model);
    let report = power(&model, &plan, &bench, 2, &mut |_, _| true).expect("analysis");
    let row = report
        .effects
        .iter()
        .find(|e| e.effect == "cylinder_imbalance" && e.place == "cylinder 1")
        .expect("cylinder 1");
    let s = row.detectable_size.expect("detectable");
    let big = diagnose_case(
        &model,
        "pressure_scale",
        1.0 - 2.0 * s,
        Effect::CylinderImbalance,
    );
    let small = diagnose_case(
        &model,
        "pressure_scale",
        1.0 - 0.3 * s,
        Effect::CylinderImbalance,
    );
    eprintln!("detectable {s}: 2× → {big}, 0.3× → {small}");
    assert_eq!(big, "cylinder_imbalance");
    assert!(small == "none" || small == "parameter_error", "{small}");
}
