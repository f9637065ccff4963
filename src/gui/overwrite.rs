//! Issue 13, deliverable 6: an export or a save never replaces the open model file or an
//! open recording (its CSV or its sidecar) without asking. Every chosen path goes through
//! the library's output guard ([`torsim::files::OutputGuard`]) over the window's open
//! files; a path that resolves to one of them waits in a modal ("Replace an open file?")
//! until the user replaces it or cancels.

use crate::gui::app::TorsimApp;
use crate::gui::export::PlotData;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use torsim::diagnose::Report;
use torsim::files::{OutputError, OutputGuard};

/// A write that can wait for an answer.
#[derive(Debug, Clone)]
pub enum PendingWrite {
    /// Save the model (Save as…).
    Model(PathBuf),
    /// Export a plot's data as CSV.
    PlotCsv(PathBuf, PlotData),
    /// Export the window as PNG.
    Png(PathBuf),
    /// Save the diagnosis report (HTML) of the model named `model_name`.
    Report {
        /// Where.
        path: PathBuf,
        /// The report.
        report: Arc<Report>,
        /// The model it diagnosed.
        model_name: String,
    },
}

impl PendingWrite {
    fn path(&self) -> &Path {
        match self {
            Self::Model(p) | Self::PlotCsv(p, _) | Self::Png(p) => p,
            Self::Report { path, .. } => path,
        }
    }
}

/// A write waiting in the modal, with the question.
#[derive(Debug, Clone)]
pub struct Confirm {
    /// The write to do on "Replace".
    pub write: PendingWrite,
    /// What it would replace, for a person.
    pub message: String,
}

/// The window's open files. The model file counts for exports, not for a save of the
/// model (saving over its own file is what Save does).
pub fn open_files(app: &TorsimApp, with_model: bool) -> OutputGuard {
    let mut guard = OutputGuard::new();
    if with_model && let Some(path) = &app.path {
        guard.input("the model", path);
    }
    if let Some(csv) = &app.traces.recording {
        guard.recording_input(csv);
    }
    for r in &app.diagnosis.recordings {
        guard.recording_input(&r.path);
    }
    guard
}

/// The question to ask before writing `path`, or `None` when it replaces no open file.
pub fn conflict(mut guard: OutputGuard, path: &Path) -> Option<String> {
    match guard.output("save", path) {
        Ok(()) => None,
        Err(OutputError::ReplacesInput { what, .. }) => Some(format!(
            "{} is {what} open in this window. Replace it?",
            path.display()
        )),
        Err(e) => Some(e.to_string()),
    }
}

/// Does `write` now, or asks first when it would replace an open file.
pub fn request(app: &mut TorsimApp, ctx: &egui::Context, write: PendingWrite) {
    let with_model = !matches!(write, PendingWrite::Model(_));
    match conflict(open_files(app, with_model), write.path()) {
        Some(message) => app.confirm = Some(Confirm { write, message }),
        None => perform(app, ctx, write),
    }
}

/// Does `write` (the user agreed, or nothing open is replaced).
pub fn perform(app: &mut TorsimApp, ctx: &egui::Context, write: PendingWrite) {
    match write {
        PendingWrite::Model(path) => crate::gui::files::save_to(app, path),
        PendingWrite::PlotCsv(path, data) => {
            app.status =
                match torsim::files::write_atomic(&path, crate::gui::export::csv_text(&data)) {
                    Ok(()) => format!("exported the plot data to {}", path.display()),
                    Err(e) => format!("could not write {}: {e}", path.display()),
                }
        }
        PendingWrite::Png(path) => crate::gui::export::screenshot_to(&mut app.exports, ctx, path),
        PendingWrite::Report {
            path,
            report,
            model_name,
        } => {
            app.diagnosis.message =
                match crate::gui::views::diagnosis::save::write_page(&path, &report, &model_name) {
                    Ok(path) => format!("saved the report to {}", path.display()),
                    Err(e) => e,
                }
        }
    }
}

/// The modal: "Replace" does the write, "Cancel" drops it (in the style of the
/// unsaved-changes prompt).
pub fn ui(app: &mut TorsimApp, ctx: &egui::Context) {
    if let Some((path, report, model_name)) = app.diagnosis.pending_save.take() {
        let write = PendingWrite::Report {
            path,
            report,
            model_name,
        };
        request(app, ctx, write);
    }
    let Some(confirm) = app.confirm.clone() else {
        return;
    };
    egui::Window::new("Replace an open file?")
        .collapsible(false)
        .resizable(false)
        .show(ctx, |ui| {
            ui.label(&confirm.message);
            ui.horizontal(|ui| {
                if ui.button("Replace").clicked() {
                    app.confirm = None;
                    perform(app, ctx, confirm.write.clone());
                }
                if ui.button("Cancel").clicked() {
                    app.confirm = None;
                    app.status = format!("not written: {}", confirm.write.path().display());
                }
            });
        });
}
