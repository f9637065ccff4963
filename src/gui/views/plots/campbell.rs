//! The Campbell diagram: every mode over speed, the order lines (major ones labelled),
//! the crossings with a hover read-out, the operating range shaded. Clicking a crossing
//! selects it: its mode shape and the forced response of its order show below
//! ([`crate::gui::views::plots::crossing`]), and the selection stays while edits keep that crossing.

use super::{CrossingKey, PlotData, mode_color};
use crate::gui::app::TorsimApp;
use crate::gui::views::plots::series::{fmt, grid_125};
use crate::gui::views::plots::side_legend::{Entry, with_side_legend};
use egui::{Color32, RichText, Ui};
use egui_plot::{
    HoverPosition, Line, MarkerShape, Plot, PlotPoint, PlotPoints, Points, Span, Text,
};
use torsim::modal::Crossing;
use torsim::model::Model;

/// Id of the Campbell plot (its memory holds the transform, for tests that click).
pub const CAMPBELL_PLOT_ID: &str = "torsim.campbell";

/// A click selects the crossing within this many points of the pointer.
const PICK_RADIUS: f32 = 12.0;

/// Orders counted as major: multiples of half the cylinder count (4-stroke) or of the
/// cylinder count (2-stroke); every order without an engine.
fn major_step(model: &Model) -> f64 {
    model.engine.as_ref().map_or(0.5, |e| {
        f64::from(e.cylinders) * if e.strokes == 2 { 1.0 } else { 0.5 }
    })
}

fn is_major(step: f64, q: f64) -> bool {
    ((q / step).round() * step - q).abs() < 1e-9
}

/// The current crossing of `key`'s order and mode, if the latest diagram has one.
pub fn crossing_at(app: &TorsimApp, key: CrossingKey) -> Option<Crossing> {
    let c = app.results.campbell.as_ref()?;
    c.campbell
        .crossings
        .iter()
        .find(|x| x.mode == key.mode && (x.order - key.order).abs() < 1e-9)
        .copied()
}

/// Selects a crossing (what a click on it does): its mode becomes the selected mode.
pub fn select_crossing(app: &mut TorsimApp, key: CrossingKey) {
    app.plots.crossing = Some(key);
    app.selected_mode = key.mode.saturating_sub(1);
    if let Some(x) = crossing_at(app, key) {
        app.status = format!(
            "order {} crosses mode {} at {:.0} rpm ({:.2} Hz)",
            x.order, x.mode, x.speed_rpm, x.frequency_hz
        );
    }
}

/// The hover text of a crossing.
fn crossing_text(x: &Crossing) -> String {
    format!(
        "order {} × mode {}\n{:.0} rpm\n{:.2} Hz",
        x.order, x.mode, x.speed_rpm, x.frequency_hz
    )
}

/// The Campbell data, for export: each mode's frequency and each order line's over the
/// speed grid.
pub fn plot_data(app: &TorsimApp) -> Option<PlotData> {
    let c = app.results.campbell.as_ref()?;
    let diagram = &c.campbell;
    let speeds = &diagram.speeds_rpm;
    let mut columns: Vec<(String, Vec<[f64; 2]>)> = diagram
        .frequency_hz
        .iter()
        .enumerate()
        .map(|(i, f)| {
            let points = speeds.iter().zip(f).map(|(&n, &f)| [n, f]).collect();
            (format!("mode {} frequency [Hz]", i + 1), points)
        })
        .collect();
    columns.extend(diagram.orders.iter().map(|&q| {
        let points = speeds.iter().map(|&n| [n, q * n / 60.0]).collect();
        (format!("order {q} frequency [Hz]"), points)
    }));
    Some(PlotData {
        title: format!("Campbell {}", app.model.name),
        x_label: "engine speed [rpm]".into(),
        x_names: Vec::new(),
        columns,
    })
}

/// The Campbell tab: the diagram, and below it the selected crossing's mode and response.
pub fn campbell_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let Some(c) = app.results.campbell.clone() else {
        ui.label("computing modes…");
        return;
    };
    let selected = app.plots.crossing.map(|k| (k, crossing_at(app, k)));
    ui.horizontal_wrapped(|ui| match selected {
        Some((_, Some(x))) => {
            ui.label(
                RichText::new(format!(
                    "selected: order {} × mode {} at {:.0} rpm, {:.2} Hz",
                    x.order, x.mode, x.speed_rpm, x.frequency_hz
                ))
                .strong(),
            );
            if ui.button("Clear selection").clicked() {
                app.plots.crossing = None;
            }
        }
        Some((k, None)) => {
            ui.label(format!(
                "order {} no longer crosses mode {} in the speed range",
                k.order, k.mode
            ));
            if ui.button("Clear selection").clicked() {
                app.plots.crossing = None;
            }
        }
        None => {
            ui.weak(
                "click a crossing for its mode shape and forced response; order lines are \
                 labelled with their order at the edge, major orders bright",
            );
        }
    });
    let detail = selected.and_then(|(_, x)| x);
    let height = ui.available_height();
    let diagram_height = if detail.is_some() {
        0.56 * height
    } else {
        height
    };
    ui.allocate_ui(egui::vec2(ui.available_width(), diagram_height), |ui| {
        diagram_ui(app, ui, &c.campbell, detail)
    });
    if let Some(x) = detail {
        crate::gui::views::plots::crossing::detail_ui(app, ui, &c, x);
    }
}

/// The legend names of the crossings.
const MINOR: &str = "crossings, other orders";
const MAJOR: &str = "crossings, major orders";

/// A mode's legend name.
fn mode_name(i: usize, f_hz: f64) -> String {
    format!("mode {} · {:.2} Hz", i + 1, f_hz)
}

fn diagram_ui(
    app: &mut TorsimApp,
    ui: &mut Ui,
    diagram: &torsim::modal::Campbell,
    selected: Option<Crossing>,
) {
    let speeds = &diagram.speeds_rpm;
    let (n0, n1) = (speeds[0], speeds[speeds.len() - 1]);
    // The view opens on the band the orders excite (the highest order at the top speed);
    // modes above it are still drawn and reached by zooming out.
    let q_max = diagram.orders.iter().copied().fold(0.0, f64::max);
    let f_top = (q_max * n1 / 60.0 * 1.1).max(1.0);
    let step = major_step(&app.model);
    let operating = app.model.operation.operating_range_rpm;
    let (major, minor): (Vec<Crossing>, Vec<Crossing>) = diagram
        .crossings
        .iter()
        .partition(|x| is_major(step, x.order));
    let above = diagram
        .frequency_hz
        .iter()
        .filter(|f| f.iter().all(|v| *v > f_top))
        .count();
    if above > 0 {
        let text = format!(
            "{above} mode(s) above {f_top:.0} Hz, the highest order at top speed: drawn beyond \
             the view (zoom out), not listed"
        );
        ui.add(egui::Label::new(RichText::new(text).weak()).wrap());
    }
    let strong = ui.visuals().strong_text_color();
    let faint = ui.visuals().weak_text_color().gamma_multiply(0.5);
    let (hover_major, hover_minor) = (major.clone(), minor.clone());
    // The legend beside the plot (issue 16): the modes of the opening view, and the two
    // kinds of crossing.
    let mut entries: Vec<Entry> = diagram
        .frequency_hz
        .iter()
        .enumerate()
        .filter(|(_, f)| !f.iter().all(|v| *v > f_top))
        .map(|(i, f)| Entry {
            name: mode_name(i, f[0]),
            color: mode_color(i),
            dashed: false,
        })
        .collect();
    entries.push(Entry {
        name: MINOR.into(),
        color: Color32::from_gray(170),
        dashed: false,
    });
    entries.push(Entry {
        name: MAJOR.into(),
        color: Color32::from_rgb(255, 200, 0),
        dashed: false,
    });
    let epoch = app.plots.model_epoch;
    let height = ui.available_height();
    let response = with_side_legend(ui, "campbell", &entries, height, |ui, hidden| {
        super::fit_for_model(ui, Plot::new("campbell"), "campbell", epoch)
            .id(egui::Id::unique(CAMPBELL_PLOT_ID))
            .default_x_bounds(n0, n1)
            .default_y_bounds(0.0, f_top)
            .x_axis_label("engine speed [rpm]")
            .y_axis_label("frequency [Hz]")
            .x_grid_spacer(grid_125)
            .y_grid_spacer(grid_125)
            .x_axis_formatter(super::tick_label)
            .y_axis_formatter(super::tick_label)
            .label_formatter(move |pos| match pos {
                HoverPosition::NearDataPoint {
                    plot_name, index, ..
                } if plot_name.starts_with("crossings") => {
                    let list = if plot_name.contains("major") {
                        &hover_major
                    } else {
                        &hover_minor
                    };
                    list.get(*index).map(crossing_text)
                }
                HoverPosition::NearDataPoint {
                    plot_name,
                    position,
                    ..
                } => Some(format!("{plot_name}\n{:.0} rpm", position.x)),
                HoverPosition::Elsewhere { position } => Some(format!(
                    "{:.0} rpm\n{} Hz\n= order {:.2}",
                    position.x,
                    fmt(position.y),
                    60.0 * position.y / position.x
                )),
            })
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
                    if is_major(step, q) {
                        plot.line(
                            Line::new("", line)
                                .color(strong.gamma_multiply(0.7))
                                .width(1.2)
                                .allow_hover(false),
                        );
                        let at = PlotPoint::new(end, q * end / 60.0);
                        let anchor = if end < n1 {
                            egui::Align2::CENTER_TOP
                        } else {
                            egui::Align2::RIGHT_BOTTOM
                        };
                        let label = RichText::new(format!("{q}")).size(14.0).strong();
                        plot.text(Text::new("", at, label).color(strong).anchor(anchor));
                    } else {
                        plot.line(
                            Line::new("", line)
                                .color(faint)
                                .width(0.6)
                                .allow_hover(false),
                        );
                    }
                }
                for (i, f) in diagram.frequency_hz.iter().enumerate() {
                    let line: PlotPoints = speeds.iter().zip(f).map(|(&n, &f)| [n, f]).collect();
                    // The legend names the modes in the opening view; those above it (a
                    // distributed shaft has many) are still drawn, unnamed.
                    let name = if f.iter().all(|v| *v > f_top) {
                        String::new()
                    } else {
                        mode_name(i, f[0])
                    };
                    if !hidden.contains(&name) {
                        plot.line(Line::new(name, line).color(mode_color(i)).width(2.0));
                    }
                }
                let at = |v: &[Crossing]| -> Vec<[f64; 2]> {
                    v.iter().map(|x| [x.speed_rpm, x.frequency_hz]).collect()
                };
                if !hidden.contains(MINOR) {
                    plot.points(
                        Points::new(MINOR, at(&minor))
                            .radius(3.0)
                            .filled(false)
                            .color(Color32::from_gray(170)),
                    );
                }
                if !hidden.contains(MAJOR) {
                    plot.points(
                        Points::new(MAJOR, at(&major))
                            .radius(4.5)
                            .color(Color32::from_rgb(255, 200, 0)),
                    );
                }
                if let Some(x) = selected {
                    plot.points(
                        Points::new("", vec![[x.speed_rpm, x.frequency_hz]])
                            .shape(MarkerShape::Circle)
                            .filled(false)
                            .radius(10.0)
                            .color(Color32::WHITE)
                            .allow_hover(false),
                    );
                }
            })
    });
    if response.response.clicked()
        && let Some(pointer) = response.response.interact_pointer_pos()
    {
        let transform = response.transform;
        let hit = diagram
            .crossings
            .iter()
            .map(|x| {
                let p = transform.position_from_point(&PlotPoint::new(x.speed_rpm, x.frequency_hz));
                (x, p.distance(pointer))
            })
            .filter(|(_, d)| *d <= PICK_RADIUS)
            .min_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((x, _)) = hit {
            select_crossing(
                app,
                CrossingKey {
                    order: x.order,
                    mode: x.mode,
                },
            );
        }
    }
}
