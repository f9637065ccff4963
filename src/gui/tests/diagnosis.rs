//! The diagnosis tab driven headless by egui_kittest: Diagnose is disabled without
//! recordings; a finished report shows its verdict, candidates and Accept, and Accept
//! puts the verdict into the model as one undo step; a real diagnosis of two recordings
//! runs on its own thread with progress and comes back with a report
//! ([`crate::gui::tests::diagnosis_run`]).

use crate::gui::app::{Tab, TorsimApp};
use crate::gui::session::diagnosis::finished::Finished;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use std::collections::BTreeMap;
use std::time::{Duration, Instant};
use torsim::diagnose::Report;
use torsim::diagnose::report::{
    Candidate, Fit, MapCell, Overlay, ParameterValue, REPORT_FORMAT, RecordingUse, Verdict,
};
use torsim::model::{ConnectionKind, Model, RubberStiffness, parse_model, presets};

pub(super) fn bench() -> Model {
    let p = presets::preset("diagnosis-bench").expect("preset");
    parse_model(p.text, "diagnosis-bench").expect("model")
}

pub(super) fn harness(model: Model) -> Harness<'static, TorsimApp> {
    Harness::builder()
        .with_size([1400.0, 1400.0])
        .build_eframe(move |cc| {
            let ctx = cc.egui_ctx.clone();
            let mut app = TorsimApp::new(model, None, move || ctx.request_repaint());
            app.tab = Tab::Diagnosis;
            app
        })
}

/// Steps the UI until `done` holds, at most `limit`.
pub(super) fn step_until(
    h: &mut Harness<'static, TorsimApp>,
    limit: Duration,
    mut done: impl FnMut(&TorsimApp) -> bool,
) {
    let start = Instant::now();
    while !done(h.state()) {
        assert!(start.elapsed() < limit, "timed out");
        std::thread::sleep(Duration::from_millis(20));
        h.step();
    }
    h.step();
}

fn coupling_n_per_m(model: &Model) -> f64 {
    model
        .connections
        .iter()
        .find_map(|c| match &c.kind {
            ConnectionKind::Rubber(r) => match &r.stiffness {
                RubberStiffness::Elements(e) => Some(e.radial_stiffness_n_per_m),
                RubberStiffness::Direct(_) => None,
            },
            _ => None,
        })
        .expect("the coupling from elements")
}

/// A report as `diagnose` makes it: the coupling's elements 10 % too stiff.
pub(super) fn report() -> Report {
    let name = "connection.coupling.elements.radial_stiffness";
    let row = |effect: &str, after: f64, score: f64, k: usize| Candidate {
        effect: effect.into(),
        parameters: BTreeMap::from([(format!("scale.{name}"), ParameterValue::Number(0.9))]),
        score,
        residual_before: 9.5,
        residual_after: after,
        residual_fitted: after,
        parameter_count: k,
        signature: String::new(),
        verified: true,
        rejected: None,
        rejected_steps: Vec::new(),
        set_aside: None,
    };
    let cell = |station: &str, order: f64, speed_rpm: f64, z: f64| MapCell {
        recording: "Regime A".into(),
        station: station.into(),
        order,
        speed_rpm,
        z,
    };
    Report {
        format: REPORT_FORMAT,
        verdict: Verdict {
            effect: "parameter_error".into(),
            confidence: 0.4,
            parameters: BTreeMap::from([
                ("parameter".into(), ParameterValue::Text(name.into())),
                ("factor".into(), ParameterValue::Number(0.9)),
            ]),
            explanation: "No physics is missing: the coupling is softer than the catalogue.".into(),
            equivalent_places: Vec::new(),
        },
        mismatches: vec![],
        candidates: vec![
            row("parameter_error", 1.1, 1.3, 7),
            row("gear_backlash", 1.05, 1.4, 8),
            row("none", 9.5, 9.5, 0),
        ],
        fit: Fit {
            metric: "chi2_per_amplitude (held out)".into(),
            before: 9.5,
            after: 1.1,
            validated_on: vec!["Regime B".into()],
            swapped_because: None,
        },
        mismatch_map: vec![
            cell("engine", 2.0, 3000.0, 7.5),
            cell("coupling_es", 2.0, 3000.0, -3.0),
        ],
        unexplained_resonances: vec![],
        overlays: vec![Overlay {
            recording: "steady regimes at 100 % load (held out)".into(),
            station: "engine".into(),
            order: "2".into(),
            x_label: "speed [rpm]".into(),
            x: vec![3480.0, 4440.0],
            measured: vec![4.0, 3.0],
            sigma: vec![0.02, 0.02],
            before: vec![3.5, 2.6],
            after: vec![4.0, 3.01],
        }],
        recordings: vec![RecordingUse {
            label: "Regime A".into(),
            kind: "steady".into(),
            speed_rpm: [3000.0, 3000.0],
            load: 1.0,
            role: "fit".into(),
            set_aside: None,
        }],
        noise_rpm: 0.02,
        not_fitted: Vec::new(),
        elapsed_s: 50.0,
    }
}

#[test]
fn the_tab_shows_and_diagnose_waits_for_recordings() {
    let mut h = harness(bench());
    h.state_mut().tab = Tab::Campbell;
    h.step();
    h.get_by_label("Diagnosis").click();
    h.step();
    h.step();
    assert_eq!(h.state().tab, Tab::Diagnosis);
    h.get_by_label("Add recordings…");
    h.get_by_label_contains("No recordings yet");
    let button = h.get_by_label("Diagnose");
    assert!(button.accesskit_node().is_disabled(), "no recordings");
    button.click();
    h.step();
    assert!(h.state().diagnosis.job.is_none(), "nothing started");
}

#[test]
fn a_report_shows_and_accept_is_one_undo_step() {
    let mut h = harness(bench());
    let user = bench();
    h.state_mut()
        .diagnosis
        .show(Finished::new(user.clone(), report()));
    h.step();
    h.step();
    assert_eq!(
        h.get_all_by_label("parameter_error").count(),
        2,
        "the verdict and its row"
    );
    h.get_by_label_contains("the coupling is softer than the catalogue");
    h.get_by_label_contains("9.500 before, 1.100 after, on Regime B");
    h.get_by_label("gear_backlash");
    assert_eq!(h.get_all_by_label("verdict").count(), 1, "one verdict row");
    h.get_by_label("station engine");
    h.get_by_label("station coupling_es");
    h.get_by_label_contains("steady regimes at 100 % load (held out) · engine · order 2");
    let undo_before = h.state().undo.len();
    let accept = h.get_by_label("Accept verdict");
    assert!(!accept.accesskit_node().is_disabled());
    accept.click();
    h.step();
    h.step();
    let k = coupling_n_per_m(&user);
    assert_eq!(coupling_n_per_m(&h.state().model), k * 0.9);
    assert_eq!(h.state().undo.len(), undo_before + 1, "one undo step");
    assert!(h.state().dirty);
    h.get_by_label_contains(
        "Accepted: connection.coupling.elements.radial_stiffness: 2.200e6 to 1.980e6 (× 0.900).",
    );
    assert!(
        h.get_by_label("Accept verdict")
            .accesskit_node()
            .is_disabled(),
        "done once"
    );
    h.state_mut().undo();
    h.step();
    assert_eq!(h.state().model, user);
    assert!(
        h.query_by_label_contains("Accepted:").is_none(),
        "the accepted line goes with the undo"
    );
    assert!(
        !h.get_by_label("Accept verdict")
            .accesskit_node()
            .is_disabled()
    );
}

#[test]
fn none_and_an_edited_model_cannot_be_accepted() {
    let mut h = harness(bench());
    let mut none = report();
    none.verdict.effect = "none".into();
    none.verdict.parameters.clear();
    h.state_mut().diagnosis.show(Finished::new(bench(), none));
    h.step();
    h.step();
    assert!(
        h.get_by_label("Accept verdict")
            .accesskit_node()
            .is_disabled()
    );
    h.get_by_label_contains("nothing is missing");
    // The model edited after the diagnosis: accepting would undo the edit.
    h.state_mut()
        .diagnosis
        .show(Finished::new(bench(), report()));
    let before = h.state().model.clone();
    h.state_mut().model.inertias[0].inertia_kg_m2 = 0.25;
    h.state_mut().commit(before);
    h.step();
    assert!(
        h.get_by_label("Accept verdict")
            .accesskit_node()
            .is_disabled()
    );
    h.get_by_label_contains("edited since this diagnosis");
}

/// A recording the model could not simulate is named under the verdict with its reason,
/// not only in the recordings table.
#[test]
fn a_recording_set_aside_is_said_under_the_verdict() {
    let mut h = harness(bench());
    let mut r = report();
    r.recordings.push(RecordingUse {
        label: "Regime A2".into(),
        kind: "steady".into(),
        speed_rpm: [1150.0, 1150.0],
        load: 1.0,
        role: "set aside".into(),
        set_aside: Some("the reference speed is not > 0 at 0.021484 s".into()),
    });
    h.state_mut().diagnosis.show(Finished::new(bench(), r));
    h.step();
    h.step();
    h.get_by_label(
        "Regime A2 is set aside: the model cannot be simulated there (the reference speed \
         is not > 0 at 0.021484 s).",
    );
    h.get_by_label_contains("2 recordings");
}

/// When the folds were swapped (the user's model fits the usual held-out half and misses
/// the other, `diagnose/holdout.rs`), the window says so under the held-out fit, with the
/// library's own reason and both χ²/N; without a swap it says nothing of folds.
#[test]
fn a_swapped_fold_is_said_under_the_held_out_fit() {
    let mut h = harness(bench());
    h.state_mut()
        .diagnosis
        .show(Finished::new(bench(), report()));
    h.step();
    h.step();
    assert!(
        h.query_by_label_contains("Held out the other fold")
            .is_none()
    );

    let mut r = report();
    r.fit.swapped_because = torsim::diagnose::holdout::swap_reason(1.405, 25.8);
    assert!(r.fit.swapped_because.is_some(), "1.405 / 25.8 swaps");
    h.state_mut().diagnosis.show(Finished::new(bench(), r));
    h.step();
    h.step();
    h.get_by_label_contains(
        "Held out the other fold: the user's model fits the usual held-out half",
    );
    h.get_by_label_contains("(χ²/N = 1.405)");
    h.get_by_label_contains("(χ²/N = 25.800)");
}

/// "Save report…" writes the page for a person atomically: the verdict is in it and no
/// temporary file is left; a folder that does not exist is an error naming the file.
#[test]
fn the_report_page_is_written_atomically() {
    let dir = crate::gui::tests::support::Scratch::new("torsim-gui-report-");
    let page = dir.join("diagnosis.html");
    let written =
        crate::gui::views::diagnosis::save::write_page(&page, &report(), "bench").expect("page");
    assert_eq!(written, page);
    let html = std::fs::read_to_string(&page).expect("read");
    assert!(html.contains("parameter_error") && html.contains("Regime B"));
    assert_eq!(
        std::fs::read_dir(&dir).expect("dir").count(),
        1,
        "no temporary"
    );
    let missing = dir.join("no/such/folder/r.html");
    let e =
        crate::gui::views::diagnosis::save::write_page(&missing, &report(), "bench").unwrap_err();
    assert!(e.contains("no/such/folder/r.html"), "{e}");
}
