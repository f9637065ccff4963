//! Before and after on the held-out data (`report.overlays`): for each, the measured
//! order amplitude with its ±σ, the user's model (dashed) and the verdict's model
//! (solid), two plots a row.

use crate::gui::views::plots::{fmt, grid_125};
use egui::{Color32, RichText, Ui};
use egui_plot::{HoverPosition, Line, LineStyle, Plot, PlotPoints, Points};
use torsim::diagnose::Report;
use torsim::diagnose::report::Overlay;

/// Height of a plot, points.
const HEIGHT: f32 = 220.0;
const MEASURED: Color32 = Color32::from_rgb(230, 230, 230);
const BEFORE: Color32 = Color32::from_rgb(77, 139, 245);
const AFTER: Color32 = Color32::from_rgb(255, 200, 0);

/// The overlays.
pub fn overlays_ui(report: &Report, ui: &mut Ui) {
    ui.label(RichText::new("Before and after, on data the fit did not use").strong());
    if report.overlays.is_empty() {
        ui.label("no held-out data to show");
        return;
    }
    ui.horizontal(|ui| {
        ui.label(RichText::new("measured ± σ: points").color(MEASURED));
        ui.label(RichText::new("before, the model as it is: dashed").color(BEFORE));
        ui.label(RichText::new("after, the verdict's model: solid").color(AFTER));
    });
    let spacing = ui.spacing().item_spacing.x;
    let width = ((ui.available_width() - spacing) / 2.0).max(240.0);
    for (row, pair) in report.overlays.chunks(2).enumerate() {
        ui.horizontal(|ui| {
            for (k, o) in pair.iter().enumerate() {
                ui.vertical(|ui| {
                    ui.label(format!(
                        "{} · {} · order {}",
                        o.recording, o.station, o.order
                    ));
                    overlay_plot(ui, o, 2 * row + k, width);
                });
            }
        });
    }
}

/// The hover read-out of an overlay: the measured point with its σ, or the line's value.
fn readout(o: &Overlay, pos: &HoverPosition<'_>) -> String {
    let unit = o
        .x_label
        .split_once('[')
        .and_then(|(_, r)| r.split_once(']'))
        .map_or("", |(u, _)| u);
    match pos {
        HoverPosition::NearDataPoint {
            plot_name,
            position,
            index,
        } if *plot_name == "measured" => format!(
            "measured\n{} {unit}\n{} ± {} rpm",
            fmt(position.x),
            fmt(position.y),
            fmt(o.sigma.get(*index).copied().unwrap_or(f64::NAN))
        ),
        HoverPosition::NearDataPoint {
            plot_name,
            position,
            ..
        } => format!(
            "{plot_name}\n{} {unit}\n{} rpm",
            fmt(position.x),
            fmt(position.y)
        ),
        HoverPosition::Elsewhere { position } => {
            format!("{} {unit}\n{} rpm", fmt(position.x), fmt(position.y))
        }
    }
}

/// One overlay's plot.
fn overlay_plot(ui: &mut Ui, o: &Overlay, index: usize, width: f32) {
    let points =
        |y: &[f64]| -> Vec<[f64; 2]> { o.x.iter().zip(y).map(|(&x, &y)| [x, y]).collect() };
    Plot::new(("diagnosis overlay", index))
        .width(width)
        .height(HEIGHT)
        .x_axis_label(o.x_label.as_str())
        .y_axis_label("IAS amplitude [rpm]")
        .x_grid_spacer(grid_125)
        .x_axis_formatter(crate::gui::views::plots::tick_label)
        .include_y(0.0)
        .allow_scroll(false)
        .label_formatter(|pos| Some(readout(o, pos)))
        .show(ui, |plot| {
            for (i, ((&x, &y), &s)) in o.x.iter().zip(&o.measured).zip(&o.sigma).enumerate() {
                let bar: PlotPoints = vec![[x, y - s], [x, y + s]].into();
                plot.line(
                    Line::new("", bar)
                        .id(("sigma", i))
                        .color(MEASURED.gamma_multiply(0.6))
                        .width(1.0)
                        .allow_hover(false),
                );
            }
            plot.points(
                Points::new("measured", points(&o.measured))
                    .radius(3.0)
                    .color(MEASURED),
            );
            plot.line(
                Line::new(
                    "before (the model as it is)",
                    PlotPoints::from(points(&o.before)),
                )
                .color(BEFORE)
                .width(1.5)
                .style(LineStyle::dashed_loose()),
            );
            plot.line(
                Line::new(
                    "after (the verdict's model)",
                    PlotPoints::from(points(&o.after)),
                )
                .color(AFTER)
                .width(2.0),
            );
        });
}
