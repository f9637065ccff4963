//! The diagnosis tab running a real diagnosis headless: the `none` case's regimes A and B
//! (about 10 s in the dev profile) diagnosed on the diagnosis thread with progress, and
//! Cancel stopping it.

use crate::gui::tests::diagnosis::{harness, step_until};
use crate::gui::views::diagnosis::load::Source;
use egui_kittest::kittest::{NodeT, Queryable};
use std::path::{Path, PathBuf};
use std::time::Duration;

/// The `none` case's folder.
fn case() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/diagnosis/none")
}

/// The `none` case's regimes A and B (about 10 s in the dev profile): progress arrives
/// with its stages, and the report comes back with its verdict.
#[test]
fn a_real_diagnosis_runs_off_the_gui_thread() {
    let case = case();
    let model = torsim::model::read_model_file(&case.join("model.toml")).expect("case model");
    let mut h = harness(model.clone());
    let paths = vec![case.join("regime-a.csv"), case.join("regime-b.csv")];
    let ctx = h.ctx.clone();
    let app = h.state_mut();
    app.diagnosis.options.threads = 2;
    app.diagnosis.add(Source::Paths(paths), &model, &ctx);
    step_until(&mut h, Duration::from_secs(30), |a| {
        a.diagnosis.recordings.len() == 2
    });
    assert!(h.state().diagnosis.load_errors.is_empty());
    h.get_by_label("Regime A");
    h.get_by_label("Diagnose").click();
    h.step();
    let mut stages: Vec<String> = Vec::new();
    let mut fractions: Vec<f64> = Vec::new();
    step_until(&mut h, Duration::from_secs(300), |a| {
        if let Some(job) = &a.diagnosis.job
            && stages.last() != Some(&job.stage)
        {
            stages.push(job.stage.clone());
            fractions.push(job.fraction);
        }
        a.diagnosis.finished.is_some() || a.diagnosis.error.is_some()
    });
    let d = &h.state().diagnosis;
    assert_eq!(d.error, None);
    let finished = d.finished.as_ref().expect("report");
    assert_eq!(finished.report.verdict.effect, "none");
    assert_eq!(finished.report.recordings.len(), 2);
    assert!(
        stages.iter().any(|s| s.starts_with("fitting ")),
        "{stages:?}"
    );
    assert!(fractions.windows(2).all(|w| w[0] <= w[1]), "{fractions:?}");
    assert!(d.job.is_none());
    assert_eq!(
        h.get_all_by_label("none").count(),
        2,
        "the verdict and its row"
    );
}

/// Cancel stops a running diagnosis at its next step: no report, "cancelled" shown, and
/// Diagnose can be pressed again.
#[test]
fn cancel_stops_the_diagnosis() {
    let case = case();
    let model = torsim::model::read_model_file(&case.join("model.toml")).expect("case model");
    let mut h = harness(model.clone());
    let ctx = h.ctx.clone();
    let app = h.state_mut();
    app.diagnosis.options.threads = 1;
    let paths = vec![case.join("regime-a.csv"), case.join("regime-b.csv")];
    app.diagnosis.add(Source::Paths(paths), &model, &ctx);
    step_until(&mut h, Duration::from_secs(30), |a| {
        a.diagnosis.recordings.len() == 2
    });
    h.get_by_label("Diagnose").click();
    h.step();
    step_until(&mut h, Duration::from_secs(60), |a| {
        a.diagnosis.job.as_ref().is_some_and(|j| j.fraction > 0.0)
    });
    h.get_by_label("Cancel").click();
    h.step();
    step_until(&mut h, Duration::from_secs(120), |a| {
        a.diagnosis.job.is_none()
    });
    let d = &h.state().diagnosis;
    assert_eq!(d.error.as_deref(), Some("cancelled"));
    assert!(d.finished.is_none());
    h.get_by_label("The diagnosis was cancelled.");
    assert!(!h.get_by_label("Diagnose").accesskit_node().is_disabled());
}
