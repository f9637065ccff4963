//! Time traces.

use super::mode_color;
use crate::gui::app::TorsimApp;
use egui::Ui;
use egui_plot::{Legend, Line, Plot, PlotPoints};

/// IAS of every node during a steady run at the chosen speed.
pub fn traces_ui(app: &mut TorsimApp, ui: &mut Ui) {
    ui.horizontal(|ui| {
        let l = ui.label("steady run at");
        let changed = ui
            .add(
                egui::DragValue::new(&mut app.trace_speed_rpm)
                    .speed(10.0)
                    .range(10.0..=100_000.0)
                    .suffix(" rpm"),
            )
            .labelled_by(l.id)
            .changed();
        if changed {
            app.request();
        }
        if app.results.trace_progress < 1.0 {
            ui.add(
                egui::ProgressBar::new(app.results.trace_progress)
                    .desired_width(160.0)
                    .show_percentage(),
            );
        }
    });
    let Some(t) = app.results.trace.clone() else {
        ui.label("computing the time run…");
        return;
    };
    Plot::new("traces")
        .legend(Legend::default())
        .x_axis_label("time [s]")
        .y_axis_label("IAS [rpm] (own shaft)")
        .show(ui, |plot| {
            for (k, (name, values)) in t.node_names.iter().zip(&t.speed_rpm).enumerate() {
                let points: PlotPoints =
                    t.time_s.iter().zip(values).map(|(&x, &v)| [x, v]).collect();
                plot.line(Line::new(name.clone(), points).color(mode_color(k)));
            }
        });
}
