//! Unsaved edits are never discarded without asking (issue 16): File → New, Open, a
//! recent file, a preset and closing the window all go through [`replace_or_ask`] or
//! [`close_or_ask`]. With unsaved edits a modal asks "Save / Discard / Cancel"; Save on a
//! model that has no file yet opens Save as…, and the waiting action runs once the save
//! has made the model clean (a cancelled or failed save brings the question back).

use crate::gui::app::TorsimApp;
use crate::gui::files;
use std::path::PathBuf;
use torsim::model::Model;

/// A model that replaces the one being edited, waiting for the user's answer.
#[derive(Debug, Clone)]
pub struct Replacement {
    /// The model to show.
    pub model: Model,
    /// Its file (`None`: a preset or a new model).
    pub path: Option<PathBuf>,
    /// The status line once it is shown (`"opened …"`).
    pub status: String,
    /// The recovery file it was read from, when it is an ended window's unsaved edits
    /// ([`crate::gui::recovery`]).
    pub recovered_from: Option<PathBuf>,
}

/// What waits for the unsaved edits to be saved or discarded.
#[derive(Debug, Clone)]
pub enum After {
    /// Show another model.
    Replace(Box<Replacement>),
    /// Close the window.
    Close,
}

/// The question on screen.
#[derive(Debug, Clone)]
pub struct Prompt {
    /// What runs once the edits are saved or discarded.
    pub after: After,
    /// Save as… was chosen and its dialog (or the overwrite question) is open.
    saving: bool,
}

/// Shows `model` at once when there is nothing unsaved, else asks first.
pub fn replace_or_ask(app: &mut TorsimApp, model: Model, path: Option<PathBuf>, status: String) {
    ask_unless_clean(
        app,
        Replacement {
            model,
            path,
            status,
            recovered_from: None,
        },
    );
}

/// As [`replace_or_ask`], for the unsaved edits of an ended window.
pub fn replace_or_ask_recovered(
    app: &mut TorsimApp,
    orphan: crate::gui::recovery::Orphan,
    status: String,
) {
    ask_unless_clean(
        app,
        Replacement {
            model: orphan.model,
            path: orphan.path,
            status,
            recovered_from: Some(orphan.file),
        },
    );
}

/// Shows `replacement` now when the model is clean, else asks first.
fn ask_unless_clean(app: &mut TorsimApp, replacement: Replacement) {
    if app.dirty {
        app.unsaved = Some(Prompt {
            after: After::Replace(Box::new(replacement)),
            saving: false,
        });
    } else {
        finish(app, After::Replace(Box::new(replacement)), None);
    }
}

/// The window was asked to close: with unsaved edits it stays open and asks.
pub fn close_or_ask(app: &mut TorsimApp, ctx: &egui::Context) {
    if ctx.input(|i| i.viewport().close_requested()) && app.dirty && !app.close_confirmed {
        ctx.send_viewport_cmd(egui::ViewportCommand::CancelClose);
        app.unsaved = Some(Prompt {
            after: After::Close,
            saving: false,
        });
    }
}

/// Runs `after`: the edits were saved or the user discarded them.
fn finish(app: &mut TorsimApp, after: After, ctx: Option<&egui::Context>) {
    app.unsaved = None;
    match after {
        After::Replace(r) => {
            let Replacement {
                model,
                path,
                status,
                recovered_from,
            } = *r;
            files::replace_model(app, model, path);
            app.status = status;
            if let Some(file) = recovered_from {
                crate::gui::recovery::adopt(app, file);
            }
        }
        After::Close => {
            app.close_confirmed = true;
            crate::gui::recovery::discard(app);
            if let Some(ctx) = ctx {
                ctx.send_viewport_cmd(egui::ViewportCommand::Close);
            }
        }
    }
}

/// What the question says will happen.
fn action_text(after: &After) -> String {
    match after {
        After::Replace(r) => format!("Open “{}” instead?", r.model.name),
        After::Close => "Close the window?".into(),
    }
}

/// The modal, and the wait for a Save as… to finish.
pub fn ui(app: &mut TorsimApp, ctx: &egui::Context) {
    let Some(prompt) = app.unsaved.clone() else {
        return;
    };
    if prompt.saving {
        if !app.dirty {
            finish(app, prompt.after, Some(ctx));
        } else if !files::save_dialog_open(app) && app.confirm.is_none() {
            // The dialog was cancelled or the save failed (the status says why): ask again.
            app.unsaved = Some(Prompt {
                saving: false,
                ..prompt
            });
        }
        return;
    }
    let mut answer = None;
    egui::Window::new("Unsaved changes")
        .collapsible(false)
        .resizable(false)
        .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
        .show(ctx, |ui| {
            ui.label(format!(
                "“{}” has changes that are not saved. {}",
                app.model.name,
                action_text(&prompt.after)
            ));
            ui.horizontal(|ui| {
                let save = if app.path.is_some() {
                    "Save"
                } else {
                    "Save as…"
                };
                if ui.button(save).clicked() {
                    answer = Some(Answer::Save);
                }
                if ui.button("Discard changes").clicked() {
                    answer = Some(Answer::Discard);
                }
                if ui.button("Cancel").clicked() {
                    answer = Some(Answer::Cancel);
                }
            });
        });
    match answer {
        Some(Answer::Save) => match app.path.clone() {
            Some(path) => {
                files::save_to(app, path);
                if !app.dirty {
                    finish(app, prompt.after, Some(ctx));
                }
            }
            None => {
                files::save_as(app, ctx);
                app.unsaved = Some(Prompt {
                    saving: true,
                    ..prompt
                });
            }
        },
        Some(Answer::Discard) => finish(app, prompt.after, Some(ctx)),
        Some(Answer::Cancel) => app.unsaved = None,
        None => {}
    }
}

/// The user's answer.
enum Answer {
    Save,
    Discard,
    Cancel,
}
