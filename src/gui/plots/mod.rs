//! The central panel: Campbell diagram, mode shapes, forced response and time traces,
//! each with hover read-out (egui_plot's), legend, units and zoom. A panel whose analysis
//! failed says why in place and keeps its last good plot. One plot per file.

mod campbell;
mod colour_scale;
mod modes;
mod order_tracks;
mod recording;
mod response;
mod run_controls;
mod series;
mod stft;
mod traces;

use super::app::{Tab, TorsimApp};
use egui::{Color32, Ui};

const MODE_COLORS: [Color32; 6] = [
    Color32::from_rgb(31, 95, 191),
    Color32::from_rgb(214, 39, 40),
    Color32::from_rgb(44, 160, 44),
    Color32::from_rgb(148, 103, 189),
    Color32::from_rgb(255, 127, 14),
    Color32::from_rgb(23, 190, 207),
];

/// The colour of mode `i` (0-based), the same in every plot.
pub fn mode_color(i: usize) -> Color32 {
    MODE_COLORS[i % MODE_COLORS.len()]
}

/// Tabs and the selected plot.
pub fn central_ui(app: &mut TorsimApp, ui: &mut Ui) {
    ui.horizontal(|ui| {
        for (tab, label) in [
            (Tab::Campbell, "Campbell"),
            (Tab::Modes, "Mode shapes"),
            (Tab::Response, "Forced response"),
            (Tab::Traces, "Time traces"),
        ] {
            ui.selectable_value(&mut app.tab, tab, label);
        }
    });
    ui.separator();
    let panel = match app.tab {
        Tab::Campbell | Tab::Modes => "modes",
        Tab::Response => "response",
        Tab::Traces => "trace",
    };
    if let Some(e) = app.error_of(panel) {
        ui.colored_label(ui.visuals().error_fg_color, format!("Failed: {e}"));
    }
    match app.tab {
        Tab::Campbell => campbell::campbell_ui(app, ui),
        Tab::Modes => modes::modes_ui(app, ui),
        Tab::Response => response::response_ui(app, ui),
        Tab::Traces => traces::traces_ui(app, ui),
    }
}
