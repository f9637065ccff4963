//! The interactive simulator (eframe/egui), in three parts a newcomer can tell by folder:
//! - this folder: the GUI thread's app ([`app`]) and what it does besides drawing: files
//!   and menus ([`files`]), asking before edits go ([`unsaved`]), autosave and restore
//!   ([`recovery`], [`startup`]), exports ([`export`], [`overwrite`]), the recording a
//!   user opens ([`recordings`]), the time run's settings ([`trace_state`]), the one
//!   helper that starts background threads ([`background`]) and latency logging;
//! - [`session`]: what runs off the GUI thread without egui: the simulation thread and
//!   its jobs, the diagnosis thread, and their result types;
//! - [`views`]: what is drawn: the driveline panel, the schematic, the plots of each tab
//!   and the diagnosis tab.

pub mod app;
pub mod background;
pub mod command;
pub mod export;
pub mod files;
pub mod history;
pub mod latency;
pub mod overwrite;
pub mod recordings;
pub mod recovery;
pub mod results;
pub mod session;
pub mod startup;
pub mod trace_state;
pub mod unsaved;
pub mod views;

#[cfg(test)]
mod tests;

use torsim::model::{ModelError, PRESET_PREFIX};

/// Why the window did not open: its model could not be read, or the window itself failed.
#[derive(Debug, thiserror::Error)]
pub enum OpenError {
    /// The model named on the command line (file, line and key in the error).
    #[error(transparent)]
    Model(#[from] ModelError),
    /// The window system refused the window.
    #[error("cannot open the window: {0}")]
    Window(String),
}

impl OpenError {
    /// True for the user's input (exit 2: the model), false for a failure (exit 1).
    pub fn is_input(&self) -> bool {
        matches!(self, Self::Model(_))
    }
}

/// The smallest window, points: below it the panels would overlap (issue 16).
pub const MIN_WINDOW_SIZE: [f32; 2] = [800.0, 500.0];

/// Opens the window on `model_arg` (a file or `preset:NAME`); without one, on an ended
/// window's unsaved edits, the last session's model, else the default preset
/// ([`startup`]).
pub fn run(model_arg: Option<String>) -> Result<(), OpenError> {
    let explicit = model_arg.is_some();
    let arg = model_arg
        .unwrap_or_else(|| format!("{PRESET_PREFIX}{}", torsim::model::presets::DEFAULT_PRESET));
    let torsim::model::Sourced { model, path } = torsim::model::load_model(&arg)?;
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_inner_size([1280.0, 800.0])
            .with_min_inner_size(MIN_WINDOW_SIZE)
            .with_title("torsim"),
        ..Default::default()
    };
    eframe::run_native(
        "torsim",
        options,
        Box::new(move |cc| {
            let ctx = cc.egui_ctx.clone();
            let wake = move || ctx.request_repaint();
            let named = explicit.then(|| (model.clone(), path.clone()));
            let session = startup::last_session(cc.storage);
            let dir = recovery::recovery_dir();
            let mut app = startup::open_app(named, (model, path), session, dir.as_deref(), wake);
            app.recent = startup::recent_files(cc.storage);
            Ok(Box::new(app))
        }),
    )
    .map_err(|e| OpenError::Window(e.to_string()))
}
