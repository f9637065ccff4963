//! The interactive simulator (eframe/egui): the driveline panel ([`editor`]), the plots
//! ([`plots`]), files and menus ([`files`]), and the simulation thread ([`worker`]) that
//! does all the computing off the GUI thread. Plot data and the window are exported by
//! [`export`].

pub mod app;
pub mod decimate;
pub mod diagnosis;
pub mod editor;
pub mod export;
pub mod files;
pub mod overwrite;
pub mod plots;
pub mod recording_job;
pub mod recordings;
pub mod schematic;
pub mod spectrogram;
pub mod trace_data;
pub mod trace_job;
pub mod trace_series;
pub mod trace_state;
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
mod tests_modal_damping;
#[cfg(test)]
mod tests_overwrite;
#[cfg(test)]
mod tests_plots;
#[cfg(test)]
mod tests_shaft;
#[cfg(test)]
mod tests_traces;

use crate::cli::error::CliError;
use std::path::PathBuf;

/// The last session's model, its file and whether it had unsaved edits, if stored.
fn restore(
    storage: Option<&dyn eframe::Storage>,
) -> Option<(torsim::model::Model, Option<PathBuf>, bool)> {
    let storage = storage?;
    let text = storage.get_string(app::SESSION_MODEL)?;
    let model = torsim::model::parse_model(&text, "last session").ok()?;
    let path = storage
        .get_string(app::SESSION_PATH)
        .filter(|p| !p.is_empty())
        .map(PathBuf::from);
    let dirty = storage
        .get_string(app::SESSION_DIRTY)
        .is_some_and(|d| d == "true");
    Some((model, path, dirty))
}

/// Opens the window on `model_arg` (a file or `preset:NAME`); without one, on the last
/// session's model (unsaved edits included), else the default preset.
pub fn run(model_arg: Option<String>) -> Result<(), CliError> {
    let explicit = model_arg.is_some();
    let arg =
        model_arg.unwrap_or_else(|| format!("preset:{}", torsim::model::presets::DEFAULT_PRESET));
    let model = crate::cli::load_model(&arg)?;
    let path = (!arg.starts_with("preset:")).then(|| PathBuf::from(&arg));
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_inner_size([1280.0, 800.0])
            .with_title("torsim"),
        ..Default::default()
    };
    eframe::run_native(
        "torsim",
        options,
        Box::new(move |cc| {
            let ctx = cc.egui_ctx.clone();
            let wake = move || ctx.request_repaint();
            let restored = if explicit { None } else { restore(cc.storage) };
            Ok(Box::new(match restored {
                Some((model, path, dirty)) => {
                    let mut app = app::TorsimApp::new(model, path, wake);
                    app.dirty = dirty;
                    app.status = "restored the last session".into();
                    app
                }
                None => app::TorsimApp::new(model, path, wake),
            }))
        }),
    )
    .map_err(|e| CliError::failed(anyhow::anyhow!("cannot open the window: {e}")))
}
