//! The menu bar and files: new, open (also recent files) and save models (TOML per the
//! spec, written atomically), presets, undo and redo. File dialogs run on their own thread
//! so the window never freezes; their answer arrives over a channel. Whatever replaces
//! the model asks first when it has unsaved edits ([`crate::gui::unsaved`]).

use crate::gui::app::TorsimApp;
use crate::gui::background::{self, Pending};
use std::path::PathBuf;
use torsim::model::{parse_model, presets::PRESETS, read_model_file, save_model_file};

/// Dialogs waiting for the user.
#[derive(Default)]
pub struct FileDialogs {
    open: Option<Pending<Option<PathBuf>>>,
    save: Option<Pending<Option<PathBuf>>>,
}

/// Runs a blocking model-file dialog on a thread (a thread that cannot start answers as a
/// cancelled dialog).
fn dialog(
    pick: impl FnOnce(rfd::FileDialog) -> Option<PathBuf> + Send + 'static,
    ctx: &egui::Context,
) -> Pending<Option<PathBuf>> {
    background::spawn("torsim-file-dialog", ctx, move || {
        pick(rfd::FileDialog::new().add_filter("torsim model", &["toml"]))
    })
    .unwrap_or_else(|_| Pending::ready(None))
}

/// Saves the model to `path`, reporting in the status line.
pub fn save_to(app: &mut TorsimApp, path: PathBuf) {
    match save_model_file(&app.model, &path) {
        Ok(()) => {
            app.status = format!("saved {}", path.display());
            remember_recent(app, &path);
            app.path = Some(path);
            app.dirty = false;
            crate::gui::recovery::discard(app);
        }
        Err(e) => app.status = format!("could not save {}: {e}", path.display()),
    }
}

/// Opens the Save as… dialog; its answer is taken by [`poll`].
pub fn save_as(app: &mut TorsimApp, ctx: &egui::Context) {
    let name = app
        .path
        .as_ref()
        .and_then(|p| p.file_name())
        .map_or("model.toml".into(), |n| n.to_string_lossy().into_owned());
    app.files.save = Some(dialog(move |d| d.set_file_name(name).save_file(), ctx));
}

/// True while the Save as… dialog is open.
pub fn save_dialog_open(app: &TorsimApp) -> bool {
    app.files.save.is_some()
}

/// The most recent files kept in the File menu: 8.
pub const RECENT_FILES: usize = 8;

/// Puts `path` first in the recent files.
fn remember_recent(app: &mut TorsimApp, path: &std::path::Path) {
    app.recent.retain(|p| p != path);
    app.recent.insert(0, path.to_path_buf());
    app.recent.truncate(RECENT_FILES);
}

/// Replaces the model (a file opened, a preset or a new model); undo history starts
/// afresh, and what belonged to the old model goes with it (issue 16): its results, the
/// selections, the open recording, the diagnosis and its report, the plots' zoom. Call
/// it through [`crate::gui::unsaved::replace_or_ask`], which asks before unsaved edits go.
pub fn replace_model(app: &mut TorsimApp, model: torsim::model::Model, path: Option<PathBuf>) {
    if let Some(p) = &path {
        remember_recent(app, p);
    }
    app.model = model;
    app.path = path;
    app.dirty = false;
    app.undo.clear();
    app.redo.clear();
    app.results = Default::default();
    app.selected = None;
    app.selected_mode = 0;
    app.stations.clear();
    app.plots = crate::gui::views::plots::PlotState {
        model_epoch: app.plots.model_epoch + 1,
        amplitude_deg: app.plots.amplitude_deg,
        ..Default::default()
    };
    app.traces = Default::default();
    app.diagnosis.clear_for_new_model();
    app.trace_speed_rpm = crate::gui::app::default_trace_speed_rpm(&app.model);
    crate::gui::recovery::discard(app);
    app.request();
}

/// Reads `path` off the GUI thread's way (a model file is small) and shows it, asking
/// first when there are unsaved edits.
fn open_path(app: &mut TorsimApp, path: PathBuf) {
    match read_model_file(&path) {
        Ok(model) => {
            let status = format!("opened {}", path.display());
            crate::gui::unsaved::replace_or_ask(app, model, Some(path), status);
        }
        Err(e) => {
            app.recent.retain(|p| *p != path);
            app.status = format!("could not open: {e}");
        }
    }
}

/// Takes the answers of finished dialogs.
pub fn poll(app: &mut TorsimApp, ctx: &egui::Context) {
    if let Some(Ok(Some(path))) = background::take(&mut app.files.open) {
        open_path(app, path);
    }
    if let Some(Ok(Some(path))) = background::take(&mut app.files.save) {
        // Issue 13: over an open recording only once the user agrees.
        crate::gui::overwrite::request(app, ctx, crate::gui::overwrite::PendingWrite::Model(path));
    }
}

/// The menu bar.
pub fn menu_ui(app: &mut TorsimApp, ui: &mut egui::Ui) {
    egui::MenuBar::new().ui(ui, |ui| {
        ui.menu_button("File", |ui| {
            if ui
                .button("New")
                .on_hover_text("a two-inertia driveline to build on")
                .clicked()
            {
                new_model(app);
            }
            if ui.button("Open…").clicked() {
                app.files.open = Some(dialog(|d| d.pick_file(), ui.ctx()));
            }
            ui.menu_button("Open recent", |ui| {
                if app.recent.is_empty() {
                    ui.label("no recent files");
                }
                for path in app.recent.clone() {
                    if ui.button(path.display().to_string()).clicked() {
                        open_path(app, path);
                    }
                }
            });
            if crate::gui::recovery::can_recover(app)
                && ui
                    .button("Recover unsaved edits…")
                    .on_hover_text("the edits of a torsim window that ended without saving")
                    .clicked()
            {
                crate::gui::recovery::recover(app);
            }
            if ui.button("Open recording…").clicked() {
                crate::gui::recordings::open_dialog(app, ui.ctx());
            }
            if ui.button("Save").clicked() {
                match app.path.clone() {
                    Some(path) => save_to(app, path),
                    None => save_as(app, ui.ctx()),
                }
            }
            if ui.button("Save as…").clicked() {
                save_as(app, ui.ctx());
            }
            ui.separator();
            if ui.button("Export plot as CSV…").clicked() {
                match crate::gui::views::plots::plot_data(app) {
                    Some(data) => crate::gui::export::export_csv(&mut app.exports, ui.ctx(), data),
                    None => app.status = "nothing to export yet".into(),
                }
            }
            if ui.button("Export window as PNG…").clicked() {
                crate::gui::export::export_png(&mut app.exports, ui.ctx());
            }
        });
        ui.menu_button("Presets", |ui| {
            for p in PRESETS {
                if ui.button(p.name).on_hover_text(p.summary).clicked()
                    && let Ok(model) = parse_model(p.text, p.name)
                {
                    let status = format!("preset {}", p.name);
                    crate::gui::unsaved::replace_or_ask(app, model, None, status);
                }
            }
        });
        ui.menu_button("Edit", |ui| {
            if ui
                .add_enabled(!app.undo.is_empty(), egui::Button::new("Undo (Ctrl+Z)"))
                .clicked()
            {
                app.undo();
            }
            if ui
                .add_enabled(
                    !app.redo.is_empty(),
                    egui::Button::new("Redo (Ctrl+Shift+Z)"),
                )
                .clicked()
            {
                app.redo();
            }
        });
    });
}

/// The preset File → New starts from: a two-inertia driveline.
pub const NEW_MODEL_PRESET: &str = "two-inertia";

/// File → New: the two-inertia preset, named "untitled", with no file.
pub fn new_model(app: &mut TorsimApp) {
    let Some(p) = torsim::model::presets::preset(NEW_MODEL_PRESET) else {
        return;
    };
    if let Ok(mut model) = parse_model(p.text, p.name) {
        model.name = "untitled".into();
        let status = "new model: two inertias and a shaft; add to it in the driveline panel";
        crate::gui::unsaved::replace_or_ask(app, model, None, status.into());
    }
}
