//! The menu bar and files: open and save models (TOML per the spec, written atomically),
//! presets, undo and redo. File dialogs run on their own thread so the window never
//! freezes; their answer arrives over a channel.

use super::app::TorsimApp;
use crossbeam_channel::{Receiver, bounded};
use std::path::PathBuf;
use torsim::model::{parse_model, presets::PRESETS, read_model_file, save_model_file};

/// Dialogs waiting for the user.
#[derive(Default)]
pub struct FileDialogs {
    open: Option<Receiver<Option<PathBuf>>>,
    save: Option<Receiver<Option<PathBuf>>>,
}

/// Runs a blocking dialog on a thread; its answer comes back on the receiver.
fn dialog(
    pick: impl FnOnce(rfd::FileDialog) -> Option<PathBuf> + Send + 'static,
    ctx: egui::Context,
) -> Receiver<Option<PathBuf>> {
    let (tx, rx) = bounded(1);
    let spawned = std::thread::Builder::new()
        .name("torsim-file-dialog".into())
        .spawn(move || {
            let dialog = rfd::FileDialog::new().add_filter("torsim model", &["toml"]);
            let _ = tx.send(pick(dialog));
            ctx.request_repaint();
        });
    if spawned.is_err() {
        let (tx, rx) = bounded(1);
        let _ = tx.send(None);
        return rx;
    }
    rx
}

/// Saves the model to `path`, reporting in the status line.
pub fn save_to(app: &mut TorsimApp, path: PathBuf) {
    match save_model_file(&app.model, &path) {
        Ok(()) => {
            app.status = format!("saved {}", path.display());
            app.path = Some(path);
            app.dirty = false;
        }
        Err(e) => app.status = format!("could not save {}: {e}", path.display()),
    }
}

/// Replaces the model (a file opened or a preset chosen); undo history starts afresh.
pub fn replace_model(app: &mut TorsimApp, model: torsim::model::Model, path: Option<PathBuf>) {
    app.model = model;
    app.path = path;
    app.dirty = false;
    app.undo.clear();
    app.redo.clear();
    app.results = Default::default();
    app.request();
}

/// Takes the answers of finished dialogs.
pub fn poll(app: &mut TorsimApp, ctx: &egui::Context) {
    if let Some(rx) = &app.files.open
        && let Ok(answer) = rx.try_recv()
    {
        app.files.open = None;
        if let Some(path) = answer {
            match read_model_file(&path) {
                Ok(model) => {
                    replace_model(app, model, Some(path.clone()));
                    app.status = format!("opened {}", path.display());
                }
                Err(e) => app.status = format!("could not open: {e}"),
            }
        }
    }
    if let Some(rx) = &app.files.save
        && let Ok(answer) = rx.try_recv()
    {
        app.files.save = None;
        if let Some(path) = answer {
            // Issue 13: over an open recording only once the user agrees.
            super::overwrite::request(app, ctx, super::overwrite::PendingWrite::Model(path));
        }
    }
}

/// The menu bar.
pub fn menu_ui(app: &mut TorsimApp, ui: &mut egui::Ui) {
    egui::MenuBar::new().ui(ui, |ui| {
        ui.menu_button("File", |ui| {
            if ui.button("Open…").clicked() {
                app.files.open = Some(dialog(|d| d.pick_file(), ui.ctx().clone()));
            }
            if ui.button("Open recording…").clicked() {
                super::recordings::open_dialog(app, ui.ctx());
            }
            if ui.button("Save").clicked() {
                match app.path.clone() {
                    Some(path) => save_to(app, path),
                    None => {
                        app.files.save = Some(dialog(
                            |d| d.set_file_name("model.toml").save_file(),
                            ui.ctx().clone(),
                        ))
                    }
                }
            }
            if ui.button("Save as…").clicked() {
                app.files.save = Some(dialog(
                    |d| d.set_file_name("model.toml").save_file(),
                    ui.ctx().clone(),
                ));
            }
            ui.separator();
            if ui.button("Export plot as CSV…").clicked() {
                match super::plots::plot_data(app) {
                    Some(data) => super::export::export_csv(&mut app.exports, ui.ctx(), data),
                    None => app.status = "nothing to export yet".into(),
                }
            }
            if ui.button("Export window as PNG…").clicked() {
                super::export::export_png(&mut app.exports, ui.ctx());
            }
        });
        ui.menu_button("Presets", |ui| {
            for p in PRESETS {
                if ui.button(p.name).clicked()
                    && let Ok(model) = parse_model(p.text, p.name)
                {
                    replace_model(app, model, None);
                    app.status = format!("preset {}", p.name);
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
