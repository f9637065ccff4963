//! Issue 16, deliverables 1 and 4, on the real app with egui_kittest: every path that
//! replaces the model (a preset, File → Open, File → New, a recent file) and closing the
//! window ask before unsaved edits go — Cancel keeps them with their undo history, Save
//! writes them first, Discard lets them go — and what belonged to the old model goes
//! with it. The autosave of [`crate::gui::recovery`] writes within 2 s of an edit and is
//! removed by a save.

use crate::gui::app::TorsimApp;
use crate::gui::files;
use crate::gui::recovery::{AUTOSAVE_AFTER, Recovery};
use crate::gui::tests::support::Scratch;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use std::path::PathBuf;
use std::time::{Duration, Instant};
use torsim::model::{Model, presets, read_model_file};

/// A fresh empty directory, removed when the returned guard is dropped.
pub(super) fn dir(name: &str) -> Scratch {
    Scratch::new(&format!("torsim-unsaved-{name}-"))
}

use crate::gui::tests::support::preset_model as preset;

fn harness(path: Option<PathBuf>) -> Harness<'static, TorsimApp> {
    let model = preset("cng-genset");
    let mut h = Harness::builder()
        .with_size([1280.0, 800.0])
        .build_eframe(move |cc| {
            let ctx = cc.egui_ctx.clone();
            TorsimApp::new(model, path, move || ctx.request_repaint())
        });
    h.run_steps(2);
    h
}

/// An edit through the app's own commit: the flywheel 10 % heavier. Returns its model.
fn edit(h: &mut Harness<'static, TorsimApp>) -> Model {
    let app = h.state_mut();
    let before = app.model.clone();
    let i = app.model.node_index("flywheel").expect("flywheel");
    app.model.inertias[i].inertia_kg_m2 *= 1.1;
    app.commit(before);
    h.step();
    h.state().model.clone()
}

fn choose_preset(h: &mut Harness<'static, TorsimApp>, name: &str) {
    h.get_by_label("Presets").click();
    h.run_steps(2);
    h.get_by_label(name).click();
    // A window's first frame only measures it: the question is on screen in the next.
    h.run_steps(3);
}

#[test]
fn a_preset_over_unsaved_edits_asks_and_cancel_keeps_them() {
    let mut h = harness(None);
    let edited = edit(&mut h);
    choose_preset(&mut h, "two-inertia");
    h.get_by_label_contains("has changes that are not saved");
    h.get_by_label("Cancel").click();
    h.run_steps(2);
    assert_eq!(h.state().model, edited, "Cancel keeps the edits");
    assert!(h.state().dirty);
    assert_eq!(h.state().undo.len(), 1, "and their undo history");
    assert!(
        h.query_by_label_contains("has changes that are not saved")
            .is_none()
    );
    // Discard lets them go; the preset is shown, clean, with a fresh history.
    choose_preset(&mut h, "two-inertia");
    h.get_by_label("Discard changes").click();
    h.run_steps(2);
    assert_eq!(h.state().model, preset("two-inertia"));
    assert!(!h.state().dirty);
    assert!(h.state().undo.is_empty());
}

#[test]
fn a_clean_model_is_replaced_without_asking() {
    let mut h = harness(None);
    choose_preset(&mut h, "three-inertia");
    assert_eq!(h.state().model, preset("three-inertia"));
    assert!(h.state().unsaved.is_none());
}

#[test]
fn save_writes_the_edits_before_the_other_model_opens() {
    let d = dir("save-first");
    let path = d.join("genset.toml");
    std::fs::write(&path, presets::preset("cng-genset").expect("p").text).expect("write");
    let other = d.join("other.toml");
    std::fs::write(&other, presets::preset("two-inertia").expect("p").text).expect("write");
    let mut h = harness(Some(path.clone()));
    let edited = edit(&mut h);
    // File → Open's answer, as the dialog thread would give it: a recent file takes the
    // same path.
    h.state_mut().recent = vec![other.clone()];
    h.get_by_label("File").click();
    h.run_steps(2);
    h.get_by_label("Open recent").hover();
    h.run_steps(2);
    h.get_by_label(&other.display().to_string()).click();
    h.run_steps(3);
    h.get_by_label("Save").click();
    h.run_steps(2);
    assert_eq!(
        read_model_file(&path).expect("saved"),
        edited,
        "saved first"
    );
    assert_eq!(h.state().model, preset("two-inertia"), "then opened");
    assert_eq!(h.state().path.as_deref(), Some(other.as_path()));
    assert!(!h.state().dirty);
    assert_eq!(h.state().recent.first(), Some(&other));
}

#[test]
fn file_new_asks_and_gives_an_untitled_two_inertia_model() {
    let mut h = harness(None);
    edit(&mut h);
    h.get_by_label("File").click();
    h.run_steps(2);
    h.get_by_label("New").click();
    h.run_steps(3);
    h.get_by_label("Discard changes").click();
    h.run_steps(2);
    assert_eq!(h.state().model.name, "untitled");
    assert_eq!(h.state().model.inertias.len(), 2);
    assert_eq!(h.state().path, None);
}

#[test]
fn closing_with_unsaved_edits_asks_and_cancel_stays() {
    let mut h = harness(None);
    edit(&mut h);
    let close = |h: &mut Harness<'static, TorsimApp>| {
        h.input_mut()
            .viewports
            .entry(egui::ViewportId::ROOT)
            .or_default()
            .events
            .push(egui::ViewportEvent::Close);
        h.step();
        h.step();
    };
    close(&mut h);
    h.get_by_label_contains("Close the window?");
    h.get_by_label("Cancel").click();
    h.run_steps(2);
    assert!(!h.state().close_confirmed);
    close(&mut h);
    h.get_by_label("Discard changes").click();
    h.step();
    assert!(h.state().close_confirmed);
}

/// Issue 16, deliverable 4: what belonged to the old model goes with it.
#[test]
fn another_model_clears_the_old_models_state() {
    let mut h = harness(None);
    let app = h.state_mut();
    app.selected = Some(crate::gui::views::schematic::Selection::Engine);
    app.selected_mode = 1;
    app.stations = vec!["flywheel".into()];
    app.traces.recording = Some(PathBuf::from("/no/such/recording.csv"));
    app.diagnosis.message = "saved the report".into();
    let epoch = app.plots.model_epoch;
    files::replace_model(app, preset("two-inertia"), None);
    let app = h.state();
    assert_eq!(app.selected, None);
    assert_eq!(app.selected_mode, 0);
    assert!(app.stations.is_empty());
    assert!(app.traces.recording.is_none());
    assert!(app.diagnosis.message.is_empty());
    assert!(app.diagnosis.finished.is_none());
    assert_eq!(app.plots.model_epoch, epoch + 1);
    assert!(app.plots.crossing.is_none());
}

/// The autosave: an edit is on disk within 2 s (the bound; [`AUTOSAVE_AFTER`] is
/// 1 s), off the GUI thread, and a save removes it.
#[test]
fn the_autosave_writes_within_two_seconds_and_a_save_removes_it() {
    let d = dir("autosave");
    let saved = d.join("model.toml");
    let mut h = harness(Some(saved.clone()));
    h.state_mut().recovery = Recovery::in_dir(&d, Vec::new());
    let file = h.state().recovery.file.clone().expect("a recovery file");
    let edited = edit(&mut h);
    let start = Instant::now();
    while !file.exists() {
        assert!(
            start.elapsed() < Duration::from_secs(2),
            "not written in 2 s"
        );
        std::thread::sleep(Duration::from_millis(20));
        h.step();
    }
    assert!(start.elapsed() >= AUTOSAVE_AFTER - Duration::from_millis(50));
    let orphan = crate::gui::recovery::orphans_including_running(&d);
    assert_eq!(orphan.len(), 1);
    assert_eq!(orphan[0].model, edited);
    assert_eq!(orphan[0].path.as_deref(), Some(saved.as_path()));
    files::save_to(h.state_mut(), saved.clone());
    h.step();
    assert!(!file.exists(), "a clean model leaves no recovery file");
}
