//! Issue 13, deliverable 6: a save or an export onto the open model or an open recording
//! (CSV or sidecar) asks first; "Cancel" leaves the file, "Replace" writes it; a path that
//! is no open file is written at once.

use crate::gui::app::TorsimApp;
use crate::gui::export::PlotData;
use crate::gui::overwrite::{PendingWrite, request};
use crate::gui::tests::support::Scratch;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use std::path::PathBuf;
use torsim::model::{parse_model, presets};

/// A fresh empty directory, removed when the returned guard is dropped.
fn dir(name: &str) -> Scratch {
    Scratch::new(&format!("torsim-gui-{name}-"))
}

/// A window on the cng-genset preset "opened" from `model`, with the recording `csv` open
/// in the traces tab.
fn harness(model: PathBuf, csv: PathBuf) -> Harness<'static, TorsimApp> {
    let p = presets::preset("cng-genset").expect("preset");
    let m = parse_model(p.text, "cng-genset").expect("model");
    let mut h = Harness::builder()
        .with_size([1280.0, 900.0])
        .build_eframe(move |cc| {
            let ctx = cc.egui_ctx.clone();
            TorsimApp::new(m, Some(model), move || ctx.request_repaint())
        });
    h.state_mut().traces.recording = Some(csv);
    h.step();
    h
}

fn data() -> PlotData {
    PlotData {
        title: "t".into(),
        x_label: "x".into(),
        x_names: Vec::new(),
        columns: vec![("y".into(), vec![[1.0, 2.0]])],
    }
}

#[test]
fn exports_onto_open_files_ask_and_others_are_written_at_once() {
    let d = dir("overwrite");
    let (model, csv, sidecar) = (d.join("m.toml"), d.join("r.csv"), d.join("r.toml"));
    for (path, text) in [(&model, "model"), (&csv, "csv"), (&sidecar, "sidecar")] {
        std::fs::write(path, text).unwrap();
    }
    let mut h = harness(model.clone(), csv.clone());
    let ctx = h.ctx.clone();
    // Onto the open recording's sidecar: asks, and Cancel leaves it.
    request(
        h.state_mut(),
        &ctx,
        PendingWrite::PlotCsv(sidecar.clone(), data()),
    );
    h.step();
    h.step();
    assert!(h.state().confirm.is_some());
    h.get_by_label_contains("r.toml is the sidecar of the recording open in this window");
    h.get_by_label("Cancel").click();
    h.step();
    h.step();
    assert!(h.state().confirm.is_none());
    assert_eq!(std::fs::read_to_string(&sidecar).unwrap(), "sidecar");
    // Onto the open model: asks, and Replace writes.
    request(
        h.state_mut(),
        &ctx,
        PendingWrite::PlotCsv(model.clone(), data()),
    );
    h.step();
    h.step();
    h.get_by_label_contains("m.toml is the model open in this window");
    assert_eq!(std::fs::read_to_string(&model).unwrap(), "model");
    h.get_by_label("Replace").click();
    h.step();
    h.step();
    assert!(h.state().confirm.is_none());
    assert!(
        std::fs::read_to_string(&model)
            .unwrap()
            .starts_with("x,y\n")
    );
    // Saving the model as the open recording's CSV asks too; saving onto its own file
    // (Save) does not.
    request(h.state_mut(), &ctx, PendingWrite::Model(csv.clone()));
    assert!(h.state_mut().confirm.take().is_some());
    assert_eq!(std::fs::read_to_string(&csv).unwrap(), "csv");
    request(h.state_mut(), &ctx, PendingWrite::Model(model.clone()));
    assert!(h.state().confirm.is_none());
    assert!(torsim::model::read_model_file(&model).is_ok(), "saved");
    // A new file: written at once.
    let fresh = d.join("plot.csv");
    request(
        h.state_mut(),
        &ctx,
        PendingWrite::PlotCsv(fresh.clone(), data()),
    );
    assert!(h.state().confirm.is_none());
    assert!(
        std::fs::read_to_string(&fresh)
            .unwrap()
            .starts_with("x,y\n")
    );
}
