//! The interactive simulator (eframe/egui): the driveline panel ([`editor`]), the plots
//! ([`plots`]), files and menus ([`files`]), and the simulation thread ([`worker`]) that
//! does all the computing off the GUI thread.

pub mod app;
pub mod editor;
pub mod files;
pub mod plots;
pub mod worker;

#[cfg(test)]
mod tests;

use crate::cli::error::CliError;
use std::path::PathBuf;

/// Opens the window on `model_arg` (a file or `preset:NAME`), or the default preset.
pub fn run(model_arg: Option<String>) -> Result<(), CliError> {
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
            Ok(Box::new(app::TorsimApp::new(model, path, move || {
                ctx.request_repaint()
            })))
        }),
    )
    .map_err(|e| CliError::failed(anyhow::anyhow!("cannot open the window: {e}")))
}
