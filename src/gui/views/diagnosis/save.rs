//! "Save report…": asks where (rfd, on its own thread); the window then checks the path
//! against its open files ([`crate::gui::overwrite`], issue 13) and renders the page for a
//! person (`torsim::diagnose::report_html`) and writes it atomically — a temporary file in
//! the same folder, renamed over the target once complete.

use crate::gui::background::{self, Pending};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use torsim::diagnose::{Report, report_html};

/// How the dialog ended: the path chosen, `None` when it was cancelled.
pub type Outcome = Option<Result<PathBuf, String>>;

/// A save in progress: the dialog's answer, and what to write.
pub struct Saving {
    answer: Pending<Outcome>,
    /// The report to write.
    pub report: Arc<Report>,
    /// The model it diagnosed.
    pub model_name: String,
}

impl Saving {
    /// Asks where to save `report` (of the model named `model_name`).
    pub fn start(report: Arc<Report>, model_name: String, ctx: &egui::Context) -> Self {
        let answer = background::spawn("torsim-diagnosis-save", ctx, || {
            rfd::FileDialog::new()
                .set_title("Save the diagnosis report")
                .add_filter("HTML page", &["html"])
                .set_file_name("diagnosis.html")
                .save_file()
                .map(Ok)
        })
        .unwrap_or_else(|e| Pending::ready(Some(Err(format!("cannot open the file dialog: {e}")))));
        Self {
            answer,
            report,
            model_name,
        }
    }

    /// The outcome once the thread is done (`Some(None)`: cancelled).
    pub fn poll(&mut self) -> Option<Outcome> {
        Some(
            self.answer
                .poll()?
                .unwrap_or_else(|_| Some(Err("the save thread ended without an answer".into()))),
        )
    }
}

/// Renders the page and writes it to `path`.
pub fn write_page(path: &Path, report: &Report, model_name: &str) -> Result<PathBuf, String> {
    write_atomic(path, &report_html(report, model_name)).map(|()| path.to_path_buf())
}

/// Writes `text` to `path` atomically, or not at all.
pub fn write_atomic(path: &Path, text: &str) -> Result<(), String> {
    torsim::files::write_atomic(path, text)
        .map_err(|e| format!("could not write {}: {e}", path.display()))
}
