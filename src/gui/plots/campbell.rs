//! The Campbell diagram.

use super::mode_color;
use crate::gui::app::{Tab, TorsimApp};
use egui::{Color32, Ui};
use egui_plot::{Legend, Line, Plot, PlotPoint, PlotPoints, Points, Span, Text};

/// Every mode over speed, the order lines, crossings (click one to see its mode shape),
/// the operating range shaded.
pub fn campbell_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let Some(c) = app.results.campbell.clone() else {
        ui.label("computing modes…");
        return;
    };
    let (_, diagram, _) = &*c;
    let speeds = &diagram.speeds_rpm;
    let (n0, n1) = (speeds[0], speeds[speeds.len() - 1]);
    // The view opens on the band the orders excite (the highest order at the top speed);
    // modes above it are still drawn and reached by zooming out.
    let q_max = diagram.orders.iter().copied().fold(0.0, f64::max);
    let f_top = (q_max * n1 / 60.0 * 1.1).max(1.0);
    // Major orders: multiples of half the cylinder count (4-stroke) or of it (2-stroke).
    let major_step = app.model.engine.as_ref().map_or(1.0, |e| {
        f64::from(e.cylinders) * if e.strokes == 2 { 1.0 } else { 0.5 }
    });
    let is_major = |q: f64| ((q / major_step).round() * major_step - q).abs() < 1e-9;
    let operating = app.model.operation.operating_range_rpm;
    let crossings: Vec<[f64; 2]> = diagram
        .crossings
        .iter()
        .map(|x| [x.speed_rpm, x.frequency_hz])
        .collect();
    let response = Plot::new("campbell")
        .legend(Legend::default())
        .default_x_bounds(n0, n1)
        .default_y_bounds(0.0, f_top)
        .x_axis_label("engine speed [rpm]")
        .y_axis_label("frequency [Hz]")
        .show(ui, |plot| {
            if let Some([lo, hi]) = operating {
                plot.span(
                    Span::new("operating range", lo..=hi)
                        .fill(Color32::from_rgba_unmultiplied(60, 160, 60, 30)),
                );
            }
            for &q in &diagram.orders {
                let end = n1.min(f_top * 60.0 / q);
                let line: PlotPoints = vec![[n0, q * n0 / 60.0], [end, q * end / 60.0]].into();
                if is_major(q) {
                    plot.line(
                        Line::new("", line)
                            .color(Color32::from_gray(190))
                            .width(1.2),
                    );
                    let label = Text::new("", PlotPoint::new(end, q * end / 60.0), format!("{q}"));
                    plot.text(
                        label
                            .color(Color32::from_gray(220))
                            .anchor(egui::Align2::RIGHT_BOTTOM),
                    );
                } else {
                    plot.line(Line::new("", line).color(Color32::from_gray(70)).width(0.6));
                }
            }
            for (i, f) in diagram.frequency_hz.iter().enumerate() {
                let line: PlotPoints = speeds.iter().zip(f).map(|(&n, &f)| [n, f]).collect();
                plot.line(
                    Line::new(format!("mode {} ({:.2} Hz)", i + 1, f[0]), line)
                        .color(mode_color(i))
                        .width(2.0),
                );
            }
            plot.points(
                Points::new("crossings", crossings.clone())
                    .radius(4.0)
                    .color(Color32::from_rgb(214, 39, 40)),
            );
            plot.pointer_coordinate()
        });
    if response.response.clicked()
        && let Some(p) = response.inner
        && let Some(hit) = diagram.crossings.iter().min_by(|a, b| {
            let d = |x: &torsim::modal::Crossing| {
                ((x.speed_rpm - p.x) / (n1 - n0)).powi(2) + ((x.frequency_hz - p.y) / f_top).powi(2)
            };
            d(a).total_cmp(&d(b))
        })
    {
        app.selected_mode = hit.mode - 1;
        app.status = format!(
            "order {} crosses mode {} at {:.1} rpm ({:.2} Hz)",
            hit.order, hit.mode, hit.speed_rpm, hit.frequency_hz
        );
        app.tab = Tab::Modes;
    }
}
