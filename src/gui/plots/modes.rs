//! Mode shapes along the driveline.

use super::mode_color;
use crate::gui::app::TorsimApp;
use egui::Ui;
use egui_plot::{Legend, Line, Plot, PlotPoints};

/// The selected mode's shape along the driveline, the others faint.
pub fn modes_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let Some(c) = app.results.campbell.clone() else {
        ui.label("computing modes…");
        return;
    };
    let (system, diagram, damped) = &*c;
    if diagram.modes.is_empty() {
        ui.label("no flexible modes");
        return;
    }
    app.selected_mode = app.selected_mode.min(diagram.modes.len() - 1);
    ui.horizontal(|ui| {
        for (i, m) in diagram.modes.iter().enumerate() {
            let d = damped.get(i);
            let text = format!(
                "mode {}: {:.2} Hz, ζ {:.1} %",
                i + 1,
                m.frequency_hz,
                d.map_or(0.0, |d| 100.0 * d.damping_ratio)
            );
            ui.selectable_value(&mut app.selected_mode, i, text);
        }
    });
    let names = system.node_names.clone();
    Plot::new("modes")
        .legend(Legend::default())
        .x_axis_label("node")
        .y_axis_label("relative amplitude (own shaft)")
        .x_axis_formatter(move |mark, _| {
            names
                .get(mark.value.round() as usize)
                .filter(|_| (mark.value - mark.value.round()).abs() < 1e-6)
                .cloned()
                .unwrap_or_default()
        })
        .show(ui, |plot| {
            for (i, m) in diagram.modes.iter().enumerate() {
                let shape = m.shape_by_node(system);
                let points: PlotPoints = shape
                    .iter()
                    .enumerate()
                    .map(|(k, &v)| [k as f64, v])
                    .collect();
                let selected = i == app.selected_mode;
                let color = if selected {
                    mode_color(i)
                } else {
                    mode_color(i).gamma_multiply(0.25)
                };
                plot.line(
                    Line::new(format!("mode {}", i + 1), points)
                        .color(color)
                        .width(if selected { 3.0 } else { 1.0 }),
                );
            }
        });
}
