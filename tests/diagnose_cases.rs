//! The concealed diagnosis cases of `tests/data/diagnosis/` (spec/diagnosis.md, "Proof on
//! concealed data"): `diagnose` gets the user's model and the ten recordings of each case,
//! nothing else; the test then reads the truth the generator wrote beside them and checks
//! that the verdict names it and that the fit improves on the held-out recordings.

mod diagnosis_inputs;

use std::path::{Path, PathBuf};
use torsim::diagnose::{DiagnoseOptions, LabelledRecording, Report, diagnose};
use torsim::model::Model;

fn case_dir(case: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/diagnosis")
        .join(case)
}

/// The user's model and the recordings, as `torsim diagnose` would read them.
fn inputs(case: &str) -> (Model, Vec<LabelledRecording>) {
    diagnosis_inputs::inputs(&case_dir(case))
}

/// The truth's effect name, from `truth.toml` (only tests read it).
fn truth_effect(case: &str) -> String {
    let text = std::fs::read_to_string(case_dir(case).join("truth.toml")).expect("truth.toml");
    let doc: toml_edit::DocumentMut = text.parse().expect("truth.toml parses");
    doc["effect"]["name"]
        .as_str()
        .expect("effect.name")
        .to_string()
}

/// A parameter of the truth's effect (`[effect.parameters]`), as text.
fn truth_parameter(case: &str, key: &str) -> String {
    let text = std::fs::read_to_string(case_dir(case).join("truth.toml")).expect("truth.toml");
    let doc: toml_edit::DocumentMut = text.parse().expect("truth.toml parses");
    let item = &doc["effect"]["parameters"][key];
    item.as_str().map_or_else(
        || {
            item.as_float()
                .map(|x| x.to_string())
                .or_else(|| item.as_integer().map(|x| x.to_string()))
                .expect("a string or a number")
        },
        str::to_string,
    )
}

/// The verdict's parameter `key`, as JSON.
fn verdict_parameter(report: &Report, key: &str) -> serde_json::Value {
    let p = report
        .verdict
        .parameters
        .get(key)
        .unwrap_or_else(|| panic!("verdict has no `{key}`: {:?}", report.verdict));
    serde_json::to_value(p).expect("json")
}

/// The verdict puts the effect where the truth has it (or names that place among the
/// ones the recordings cannot tell apart).
fn check_place(case: &str, report: &Report, key: &str) {
    let truth = truth_parameter(case, key);
    let truth = truth.trim_end_matches(".0");
    let named = verdict_parameter(report, key);
    let named = named.as_str().expect("a place is text");
    assert!(
        named == truth || report.verdict.equivalent_places.iter().any(|p| p == truth),
        "case {case}: {key} {named} (equivalent: {:?}), truth {truth}",
        report.verdict.equivalent_places
    );
}

/// The verdict's fitted `key` is within `relative` of the truth's.
fn check_value(case: &str, report: &Report, key: &str, relative: f64) {
    let truth: f64 = truth_parameter(case, key).parse().expect("a number");
    let fitted = verdict_parameter(report, key).as_f64().expect("a number");
    assert!(
        (fitted / truth - 1.0).abs() < relative,
        "case {case}: {key} fitted {fitted}, truth {truth} (±{:.0} %)",
        100.0 * relative
    );
}

fn run(case: &str) -> Report {
    let (model, recordings) = inputs(case);
    assert_eq!(recordings.len(), 10, "ten recordings per case");
    diagnose(
        &model,
        &recordings,
        &DiagnoseOptions::default(),
        &mut |_, _| true,
    )
    .expect("diagnosis runs")
}

/// The verdict names the truth; an effect or a parameter error improves the held-out fit.
fn check(case: &str) -> Report {
    let report = run(case);
    let truth = truth_effect(case);
    assert_eq!(
        report.verdict.effect,
        truth,
        "case {case}: {}\ncandidates: {:#?}",
        report.verdict.explanation,
        report
            .candidates
            .iter()
            .map(|c| (c.effect.as_str(), c.score, c.residual_after))
            .collect::<Vec<_>>()
    );
    if truth != "none" {
        assert!(
            report.fit.after < 0.5 * report.fit.before,
            "case {case}: held-out χ²/N {} → {}",
            report.fit.before,
            report.fit.after
        );
    }
    assert!(!report.fit.validated_on.is_empty());
    check_set_aside(case, &report);
    report
}

/// Every effect that scores better than the verdict, or that the verdict `parameter_error`
/// passed over, says why it is not the verdict; the verdict's row never does.
fn check_set_aside(case: &str, report: &Report) {
    let verdict = report.verdict.effect.as_str();
    let score_of = |effect: &str| {
        report
            .candidates
            .iter()
            .find(|c| c.effect == effect)
            .map(|c| c.score)
    };
    let verdict_score = score_of(verdict).expect("the verdict has a row");
    for c in &report.candidates {
        if c.effect == verdict {
            assert!(c.set_aside.is_none(), "case {case}: the verdict set aside");
            continue;
        }
        let effect = !matches!(c.effect.as_str(), "none" | "parameter_error");
        let passed_over = c.score < verdict_score || verdict == "parameter_error";
        if effect && c.rejected.is_none() && passed_over {
            assert!(
                c.set_aside.is_some(),
                "case {case}: {} (score {}) under the verdict {verdict} (score \
                 {verdict_score}) without a reason",
                c.effect,
                c.score
            );
        }
    }
}

#[test]
fn none() {
    let r = check("none");
    assert!(r.fit.before <= 2.0, "{}", r.fit.before);
}

#[test]
fn parameter_error() {
    let r = check("parameter_error");
    let p = &r.verdict.parameters;
    let name = serde_json::to_value(&p["parameter"]).expect("json");
    assert_eq!(name, "connection.coupling.elements.radial_stiffness");
    let factor = serde_json::to_value(&p["factor"]).expect("json");
    let factor = factor.as_f64().expect("number");
    // The truth is ×0.9; other parameters are exact in this case.
    assert!((factor - 0.9).abs() < 0.03, "factor {factor}");
}

#[test]
fn coupling_amplitude_nonlinearity() {
    let r = check("coupling_amplitude_nonlinearity");
    check_place("coupling_amplitude_nonlinearity", &r, "connection");
    // The truth also has a linear term a1 = 0.0033 per mm, which the candidate does not
    // fit: a2 stands in for it (0.0122 against 0.0152).
    check_value("coupling_amplitude_nonlinearity", &r, "a2", 0.3);
}

#[test]
fn coupling_frequency_dependence() {
    let r = check("coupling_frequency_dependence");
    check_place("coupling_frequency_dependence", &r, "connection");
    let form = r.verdict.parameters.get("form").map(|f| format!("{f:?}"));
    if form.is_some_and(|f| f.contains("power_law")) {
        // Since issue 14 a causal power law competes with seed 000 eq. 9 (the truth's
        // form). Its own loss, tan(nπ/2) = 0.066 at the fitted n = 0.042, stays below this
        // stage's ψ/2π = 0.159, so it is the same physics — storage rising, loss at ψ — in
        // another shape, and it predicts the held-out data better (χ²/N 1.06). Checked:
        // its storage rise from the truth's reference to 100 Hz is the truth's within a
        // factor 2 (measured 4.4 % against the truth's 7.7 %: a power law rises less
        // steeply over the band than the quadratic, in a log-spaced fit).
        let n = verdict_parameter(&r, "exponent")
            .as_f64()
            .expect("a number");
        let reference_hz: f64 = truth_parameter("coupling_frequency_dependence", "reference_hz")
            .parse()
            .expect("a number");
        let rise = (100.0 / reference_hz).powf(n) - 1.0;
        let truth_rise = 0.0772; // the truth's summary: α_f = 1.0772 at 100 Hz
        assert!(
            rise > 0.5 * truth_rise && rise < 2.0 * truth_rise,
            "power-law rise {rise} against {truth_rise}"
        );
    } else {
        // Fitted 0.110 against 0.1, together with seven plain parameters off by up to 9 %.
        check_value("coupling_frequency_dependence", &r, "scale", 0.2);
    }
}

#[test]
fn coupling_thermal_drift() {
    let r = check("coupling_thermal_drift");
    check_place("coupling_thermal_drift", &r, "connection");
}

#[test]
fn hysteretic_damping() {
    let r = check("hysteretic_damping");
    check_place("hysteretic_damping", &r, "connection");
    check_value("hysteretic_damping", &r, "reference_hz", 0.1);
}

#[test]
fn unmodelled_mode() {
    let r = check("unmodelled_mode");
    check_place("unmodelled_mode", &r, "connection");
    check_value("unmodelled_mode", &r, "inertia_kg_m2", 0.1);
}

#[test]
fn crank_variable_inertia() {
    let r = check("crank_variable_inertia");
    check_value("crank_variable_inertia", &r, "mass_kg", 0.05);
}

#[test]
fn gear_backlash() {
    let r = check("gear_backlash");
    check_place("gear_backlash", &r, "connection");
}

#[test]
fn cylinder_imbalance() {
    let r = check("cylinder_imbalance");
    // An in-line four with even firing: every cylinder predicts the same amplitudes.
    assert_eq!(r.verdict.equivalent_places.len(), 3, "{:?}", r.verdict);
    check_place("cylinder_imbalance", &r, "cylinder");
    check_value("cylinder_imbalance", &r, "pressure_scale", 0.01);
}

#[test]
fn sensor_artifact() {
    let r = check("sensor_artifact");
    check_place("sensor_artifact", &r, "station");
    check_value("sensor_artifact", &r, "joint_fraction", 0.1);
}
