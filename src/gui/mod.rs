//! The interactive simulator (eframe/egui): the driveline panel ([`editor`]), the plots
//! ([`plots`]), files and menus ([`files`]), and the simulation thread ([`worker`]) that
//! does all the computing off the GUI thread. Plot data and the window are exported by
//! [`export`].

pub mod app;
pub mod background;
pub mod decimate;
pub mod diagnosis;
pub mod editor;
pub mod export;
pub mod files;
pub mod help;
pub mod latency;
pub mod overwrite;
pub mod plots;
pub mod recording_job;
pub mod recordings;
pub mod recovery;
pub mod schematic;
pub mod spectrogram;
pub mod startup;
pub mod trace_data;
pub mod trace_job;
pub mod trace_series;
pub mod trace_state;
pub mod unsaved;
pub mod worker;

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_diagnosis;
#[cfg(test)]
mod tests_diagnosis_run;
#[cfg(test)]
mod tests_edit;
#[cfg(test)]
mod tests_edit_cases;
#[cfg(test)]
mod tests_edit_structure;
#[cfg(test)]
mod tests_idle;
#[cfg(test)]
mod tests_layout;
#[cfg(test)]
mod tests_modal_damping;
#[cfg(test)]
mod tests_overwrite;
#[cfg(test)]
mod tests_plots;
#[cfg(test)]
mod tests_ratings;
#[cfg(test)]
mod tests_recovery;
#[cfg(test)]
mod tests_shaft;
#[cfg(test)]
mod tests_snapshots;
#[cfg(test)]
mod tests_support;
#[cfg(test)]
mod tests_teaching;
#[cfg(test)]
mod tests_traces;
#[cfg(test)]
mod tests_unsaved;

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
