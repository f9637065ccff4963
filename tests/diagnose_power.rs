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
    // White noise only, as the power analysis assumes (see the check below).
    let measurement = Measurement {
        stations: torsim::synth::Station::defaults(model),
        jitter_ns: 0.0,
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

/// The named size of `effect` at `place` on the default plan.
fn named_size(model: &Model, effect: &str, place: &str) -> f64 {
    let plan = Plan::default_for(model, PlanDurations::default()).expect("plan");
    let mut bench = Bench::default_for(model);
    bench.jitter_ns = 0.0;
    let report = power(model, &plan, &bench, 2, &mut |_, _| true).expect("analysis");
    let row = report
        .effects
        .iter()
        .find(|e| e.effect == effect && e.place == place)
        .expect("row");
    row.named_size.expect("named within bounds")
}

/// The check against full diagnoses (issue 14, item 6; slow: three campaigns, ~2 min in
/// the test profile): at twice its *named* size ([`torsim::diagnose::power_named`]) an
/// effect is named; at 0.3 times the surrogate's effect is not (see below). The named
/// size, not the detectable one, is what a verdict needs: the diagnosis asks for a
/// held-out misfit above twice the noise and a margin over the plain fit, 5–10 times
/// the size of λ ≥ 7.85 on this campaign (cylinder 1: 3.6e-4 against 7.0e-5).
/// Two effects: one the surrogate evaluates (cylinder imbalance) and one only the time
/// domain does (thermal drift, on the long run). The bench has white noise only: pulse
/// timing jitter makes a speed's noise rise with frequency (it is the derivative of an
/// angle noise), which the analysis' one σ per station does not model; with the default
/// 20 ns the crank encoder's order amplitudes are 3–4 times noisier than it assumes
/// (σ 0.0087 rpm measured against 0.0031 rpm), and a right model reads χ²/N = 1.56
/// instead of 0.84.
/// An effect's name, place, kind, parameter key and size-to-parameter map.
type Case = (
    &'static str,
    &'static str,
    Effect,
    &'static str,
    fn(f64) -> f64,
);

#[test]
fn full_diagnoses_agree_with_the_named_size() {
    let model = bench_model();
    let cases: [Case; 2] = [
        (
            "cylinder_imbalance",
            "cylinder 1",
            Effect::CylinderImbalance,
            "pressure_scale",
            |s| 1.0 - s,
        ),
        (
            "coupling_thermal_drift",
            "coupling",
            Effect::CouplingThermalDrift,
            "capacity_j_per_k",
            |s| 1.0 / s,
        ),
    ];
    for (k, (name, place, effect, key, value)) in cases.into_iter().enumerate() {
        let s = named_size(&model, name, place);
        let big = diagnose_case(&model, key, value(2.0 * s), effect);
        eprintln!("{name}: named from {s}: 2× → {big}");
        assert_eq!(big, name);
        // The surrogate's effect is not named at 0.3×. Thermal drift's signature is
        // simulated on the long run only (`power_eval`), so its named size is an upper
        // bound: measured, it is still named at 0.3× (332 J/K against 99.5 J/K named),
        // and that side is not asserted.
        if k == 0 {
            let small = diagnose_case(&model, key, value(0.3 * s), effect);
            eprintln!("{name}: 0.3× → {small}");
            assert!(
                small == "none" || small == "parameter_error",
                "{name}: {small}"
            );
        }
    }
}
