//! Forced response over speed.

use crate::gui::app::TorsimApp;
use egui::{Color32, Ui};
use egui_plot::{Legend, Line, Plot, PlotPoints};

/// IAS amplitude over speed at a node: each order that matters, and their sum.
pub fn response_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let Some(r) = app.results.response.clone() else {
        ui.label("computing the forced response…");
        return;
    };
    let names: Vec<String> = app.model.inertias.iter().map(|n| n.name.clone()).collect();
    let id = ui.make_persistent_id("response_node");
    let mut node: usize = ui
        .data(|d| d.get_temp(id))
        .unwrap_or(0)
        .min(names.len().saturating_sub(1));
    egui::ComboBox::from_label("station")
        .selected_text(names.get(node).cloned().unwrap_or_default())
        .show_ui(ui, |ui| {
            for (k, n) in names.iter().enumerate() {
                ui.selectable_value(&mut node, k, n);
            }
        });
    ui.data_mut(|d| d.insert_temp(id, node));
    let per_order = &r.ias_amplitude_rpm[node];
    let top = per_order.iter().flatten().copied().fold(0.0, f64::max);
    Plot::new("response")
        .legend(Legend::default())
        .x_axis_label("engine speed [rpm]")
        .y_axis_label("IAS amplitude [rpm] (zero-to-peak)")
        .show(ui, |plot| {
            let mut sum = vec![0.0; r.speeds_rpm.len()];
            for (q, values) in r.orders.iter().zip(per_order) {
                for (s, v) in sum.iter_mut().zip(values) {
                    *s += v;
                }
                if values.iter().copied().fold(0.0, f64::max) < 0.02 * top {
                    continue;
                }
                let points: PlotPoints = r
                    .speeds_rpm
                    .iter()
                    .zip(values)
                    .map(|(&n, &v)| [n, v])
                    .collect();
                plot.line(Line::new(format!("order {q}"), points));
            }
            let points: PlotPoints = r
                .speeds_rpm
                .iter()
                .zip(&sum)
                .map(|(&n, &v)| [n, v])
                .collect();
            plot.line(
                Line::new("Σ orders (upper bound)", points)
                    .color(Color32::WHITE)
                    .width(2.0),
            );
        });
}
