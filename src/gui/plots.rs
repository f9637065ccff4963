//! The central panel: Campbell diagram, mode shapes, forced response and time traces,
//! each with hover read-out (egui_plot's), legend, units and zoom. A panel whose analysis
//! failed says why in place and keeps its last good plot.

use super::app::{Tab, TorsimApp};
use egui::{Color32, Ui};
use egui_plot::{Legend, Line, Plot, PlotPoint, PlotPoints, Points, Span, Text};

const MODE_COLORS: [Color32; 6] = [
    Color32::from_rgb(31, 95, 191),
    Color32::from_rgb(214, 39, 40),
    Color32::from_rgb(44, 160, 44),
    Color32::from_rgb(148, 103, 189),
    Color32::from_rgb(255, 127, 14),
    Color32::from_rgb(23, 190, 207),
];

fn mode_color(i: usize) -> Color32 {
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
        Tab::Campbell => campbell_ui(app, ui),
        Tab::Modes => modes_ui(app, ui),
        Tab::Response => response_ui(app, ui),
        Tab::Traces => traces_ui(app, ui),
    }
}

/// Every mode over speed, the order lines, crossings (click one to see its mode shape),
/// the operating range shaded.
fn campbell_ui(app: &mut TorsimApp, ui: &mut Ui) {
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

/// The selected mode's shape along the driveline, the others faint.
fn modes_ui(app: &mut TorsimApp, ui: &mut Ui) {
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

/// IAS amplitude over speed at a node: each order that matters, and their sum.
fn response_ui(app: &mut TorsimApp, ui: &mut Ui) {
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

/// IAS of every node during a steady run at the chosen speed.
fn traces_ui(app: &mut TorsimApp, ui: &mut Ui) {
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
