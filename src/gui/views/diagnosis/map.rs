//! The mismatch map of the user's model: one plot per station, engine speed × engine
//! order, each cell coloured by `z = (measured − simulated)/σ` on a diverging scale
//! clamped at ±10 (red: the recording has more than the model, blue: less). Run-up bins
//! are cells [`BIN_RPM`] wide; steady regimes and long-run blocks are narrower cells
//! with an outline, drawn over them. Where cells overlap the worst is on top, and the
//! hover read-out lists every cell under the pointer.

use crate::gui::session::diagnosis::finished::sig4;
use crate::gui::views::plots::colour_scale::gradient_bar;
use egui::{Align2, Color32, Rect, Sense, Stroke, Ui, Vec2};
use egui_plot::{HoverPosition, Plot, PlotPoints, Polygon};
use torsim::diagnose::Report;
use torsim::diagnose::observe::BIN_RPM;
use torsim::diagnose::report::MapCell;

/// |z| at which the colour saturates.
pub const Z_CLAMP: f64 = 10.0;
/// Width of a steady regime's cell, rpm (regimes are some 500 rpm apart).
const STEADY_RPM: f64 = 160.0;
/// Height of the plots, points.
const HEIGHT: f32 = 280.0;
/// Width of the colour scale, points.
const SCALE_WIDTH: f32 = 80.0;
/// The narrowest a station's plot is drawn, px: its speed axis still reads.
const MIN_PLOT_WIDTH: f32 = 200.0;

const NEUTRAL: [f32; 3] = [70.0, 70.0, 70.0];
const ABOVE: [f32; 3] = [235.0, 65.0, 45.0];
const BELOW: [f32; 3] = [55.0, 120.0, 240.0];

/// The colour of `z`: grey at 0, red towards +10, blue towards −10, saturated beyond.
pub fn z_colour(z: f64) -> Color32 {
    let t = if z.is_finite() {
        (z / Z_CLAMP).clamp(-1.0, 1.0) as f32
    } else {
        0.0
    };
    let end = if t >= 0.0 { ABOVE } else { BELOW };
    let c = |i: usize| (NEUTRAL[i] + t.abs() * (end[i] - NEUTRAL[i])).round() as u8;
    Color32::from_rgb(c(0), c(1), c(2))
}

/// A cell as drawn: its rectangle `[x0, x1] × [y0, y1]` in rpm and order.
struct Drawn<'a> {
    cell: &'a MapCell,
    x: [f64; 2],
    y: [f64; 2],
    steady: bool,
}

/// The cells of `station`, in drawing order: run-up bins, then steady cells, each by |z|.
fn drawn<'a>(report: &'a Report, station: &str, order_step: f64) -> Vec<Drawn<'a>> {
    let run_up = |label: &str| {
        report
            .recordings
            .iter()
            .any(|r| r.label == label && r.kind == torsim::recording::RunKind::RunUp.as_str())
    };
    let mut out: Vec<Drawn> = report
        .mismatch_map
        .iter()
        .filter(|c| c.station == station)
        .map(|cell| {
            let steady = !run_up(&cell.recording);
            let w = if steady { STEADY_RPM } else { BIN_RPM };
            let h = 0.45 * order_step;
            Drawn {
                cell,
                x: [cell.speed_rpm - 0.5 * w, cell.speed_rpm + 0.5 * w],
                y: [cell.order - h, cell.order + h],
                steady,
            }
        })
        .collect();
    out.sort_by(|a, b| {
        a.steady
            .cmp(&b.steady)
            .then(a.cell.z.abs().total_cmp(&b.cell.z.abs()))
    });
    out
}

/// The read-out at `(speed, order)`: every cell there, worst first.
fn readout(cells: &[Drawn], x: f64, y: f64) -> String {
    let mut here: Vec<&Drawn> = cells
        .iter()
        .filter(|d| (d.x[0]..=d.x[1]).contains(&x) && (d.y[0]..=d.y[1]).contains(&y))
        .collect();
    if here.is_empty() {
        return format!("{x:.0} rpm, order {y:.2}");
    }
    here.sort_by(|a, b| b.cell.z.abs().total_cmp(&a.cell.z.abs()));
    let mut lines: Vec<String> = here
        .iter()
        .take(5)
        .map(|d| {
            let c = d.cell;
            format!(
                "{}: order {} at {:.0} rpm, z = {:+.1}",
                c.recording, c.order, c.speed_rpm, c.z
            )
        })
        .collect();
    if here.len() > 5 {
        lines.push(format!("and {} more", here.len() - 5));
    }
    lines.join("\n")
}

/// The map: one plot per station and the colour scale.
pub fn map_ui(report: &Report, ui: &mut Ui) {
    ui.label(egui::RichText::new("Mismatch map of the model as it is").strong());
    ui.label(
        egui::RichText::new(format!(
            "z = (measured − simulated)/σ of each IAS order amplitude; noise σ ≈ {} rpm. \
             Cells without outline: run-up bins; outlined: steady regimes and long-run \
             blocks, drawn over them. Saturated beyond ±10; hover for the values.",
            sig4(report.noise_rpm)
        ))
        .weak(),
    );
    let mut stations: Vec<&str> = Vec::new();
    for c in &report.mismatch_map {
        if !stations.contains(&c.station.as_str()) {
            stations.push(&c.station);
        }
    }
    if stations.is_empty() {
        ui.label("no cells");
        return;
    }
    let mut orders: Vec<f64> = report.mismatch_map.iter().map(|c| c.order).collect();
    orders.sort_by(f64::total_cmp);
    orders.dedup();
    let step = orders
        .windows(2)
        .map(|w| w[1] - w[0])
        .fold(f64::INFINITY, f64::min);
    let step = if step.is_finite() { step } else { 0.5 };
    // As many plots to a row as fit at [`MIN_PLOT_WIDTH`] beside the scale, the rest on
    // rows below: a row wider than the panel would widen everything under it, and the
    // notes below would then wrap past the window's edge.
    let spacing = ui.spacing().item_spacing.x;
    let room = ui.available_width() - SCALE_WIDTH - spacing;
    let per_row = ((room / (MIN_PLOT_WIDTH + spacing)).floor() as usize).clamp(1, stations.len());
    let width = (room / per_row as f32 - spacing).max(MIN_PLOT_WIDTH);
    for (row, chunk) in stations.chunks(per_row).enumerate() {
        ui.horizontal(|ui| {
            for station in chunk {
                let cells = drawn(report, station, step);
                ui.vertical(|ui| {
                    ui.label(format!("station {station}"));
                    station_plot(ui, station, &cells, width);
                });
            }
            if row == 0 {
                scale_ui(ui);
            }
        });
    }
}

/// One station's plot.
fn station_plot(ui: &mut Ui, station: &str, cells: &[Drawn], width: f32) {
    Plot::new(("diagnosis map", station))
        .width(width)
        .height(HEIGHT)
        .x_axis_label("engine speed [rpm]")
        .y_axis_label("engine order")
        .x_grid_spacer(crate::gui::views::plots::grid_125)
        .x_axis_formatter(crate::gui::views::plots::tick_label)
        .allow_scroll(false)
        .label_formatter(|pos| {
            let p = match pos {
                HoverPosition::NearDataPoint { position, .. }
                | HoverPosition::Elsewhere { position } => position,
            };
            Some(readout(cells, p.x, p.y))
        })
        .show(ui, |plot| {
            for (i, d) in cells.iter().enumerate() {
                let [x0, x1] = d.x;
                let [y0, y1] = d.y;
                let corners: PlotPoints = vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]].into();
                let stroke = if d.steady {
                    Stroke::new(1.0, Color32::from_gray(210))
                } else {
                    Stroke::new(0.0, Color32::TRANSPARENT)
                };
                plot.polygon(
                    Polygon::new("", corners)
                        .id(("cell", i))
                        .fill_color(z_colour(d.cell.z))
                        .stroke(stroke)
                        .allow_hover(false),
                );
            }
        });
}

/// The colour scale from −10 to +10, labelled every 5, with what each end means.
fn scale_ui(ui: &mut Ui) {
    let height = HEIGHT + 20.0;
    let (rect, _) = ui.allocate_exact_size(Vec2::new(SCALE_WIDTH, height), Sense::hover());
    let painter = ui.painter_at(rect);
    let bar = Rect::from_min_max(
        rect.min + Vec2::new(6.0, 56.0),
        rect.min + Vec2::new(20.0, height - 40.0),
    );
    gradient_bar(&painter, bar, 80, &|u| z_colour((u * 2.0 - 1.0) * Z_CLAMP));
    let text = ui.visuals().text_color();
    let weak = ui.visuals().weak_text_color();
    let font = egui::TextStyle::Small.resolve(ui.style());
    let at = |dy: f32| rect.min + Vec2::new(2.0, dy);
    painter.text(at(20.0), Align2::LEFT_TOP, "z", font.clone(), text);
    painter.text(at(34.0), Align2::LEFT_TOP, "model low", font.clone(), weak);
    for k in -2..=2 {
        let z = 5.0 * f64::from(k);
        let y = bar.bottom() - ((z / Z_CLAMP + 1.0) / 2.0) as f32 * bar.height();
        painter.line_segment(
            [egui::pos2(bar.right(), y), egui::pos2(bar.right() + 4.0, y)],
            Stroke::new(1.0, text),
        );
        let label = if k == 0 {
            "0".to_string()
        } else {
            format!("{z:+.0}")
        };
        painter.text(
            egui::pos2(bar.right() + 6.0, y),
            Align2::LEFT_CENTER,
            label,
            font.clone(),
            text,
        );
    }
    painter.text(
        egui::pos2(rect.left() + 2.0, bar.bottom() + 10.0),
        Align2::LEFT_TOP,
        "model high",
        font,
        weak,
    );
}
