//! Orders: per station, the order amplitudes of the synchronously averaged cycle
//! (`torsim::signal::analyse`, rpm 0-peak) of the simulation, beside the recording's when
//! one is open — bars per order for a steady run, the track of one order over speed for a
//! run-up — with a table of mean speed, RMS, irregularity and the dominant order (seed
//! 001 Tables 2, 3, 9).

use super::side_legend::{Entry, with_side_legend};
use crate::gui::app::TorsimApp;
use crate::gui::session::trace_data::GroupKind;
use egui::{Color32, Ui};
use egui_plot::{Bar, BarChart, Line, LineStyle, Plot};
use torsim::signal::{Analysis, OrderAmplitude, StationAnalysis};

const SIMULATED: Color32 = Color32::from_rgb(60, 130, 230);
const MEASURED: Color32 = Color32::from_rgb(235, 150, 40);

/// The largest order of a station's averaged cycle: (order, rpm).
pub fn dominant(orders: &[OrderAmplitude]) -> Option<(f64, f64)> {
    orders
        .iter()
        .max_by(|a, b| a.amplitude.total_cmp(&b.amplitude))
        .map(|o| (o.order, o.amplitude))
}

/// `v` with `decimals` decimals, without a minus sign on a value that rounds to zero.
fn fixed(v: f64, decimals: usize) -> String {
    let text = format!("{v:.decimals$}");
    match text.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => text,
    }
}

fn find<'a>(a: &'a Analysis, name: &str) -> Option<&'a StationAnalysis> {
    a.stations.iter().chain(&a.n_rel).find(|s| s.name == name)
}

/// The orders view.
pub fn orders_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let Some(sim) = app.results.trace_analysis.clone() else {
        ui.label("The orders are analysed when the time run has finished.");
        return;
    };
    let measured = app.results.recording.clone();
    let meas = measured.as_ref().map(|r| &r.analysis);
    // The stations: the recording's, else the nodes shown in the traces, and the
    // relative speeds.
    let shown: Vec<String> = match (&meas, &app.results.live) {
        (Some(m), _) => m
            .stations
            .iter()
            .chain(&m.n_rel)
            .map(|s| s.name.clone())
            .collect(),
        (None, Some(live)) => live
            .group(GroupKind::Speed)
            .map(|(g, _)| {
                g.names
                    .iter()
                    .zip(&g.visible)
                    .filter(|(_, v)| **v)
                    .map(|(n, _)| n.clone())
                    .collect::<Vec<_>>()
            })
            .unwrap_or_default()
            .into_iter()
            .chain(sim.analysis.n_rel.iter().map(|s| s.name.clone()))
            .collect(),
        (None, None) => sim
            .analysis
            .stations
            .iter()
            .map(|s| s.name.clone())
            .collect(),
    };
    let ramp = sim.analysis.stft.is_some();
    summary_ui(ui, &sim.analysis, meas, &shown, ramp);
    ui.separator();
    if ramp {
        let orders = sim
            .analysis
            .stft
            .as_ref()
            .map(|s| s.orders.clone())
            .unwrap_or_default();
        if !orders.contains(&app.traces.track_order) {
            let step = app.model.engine.as_ref().map_or(1.0, |e| {
                f64::from(e.cylinders) * if e.strokes == 2 { 1.0 } else { 0.5 }
            });
            app.traces.track_order = if orders.contains(&step) {
                step
            } else {
                orders.first().copied().unwrap_or(1.0)
            };
        }
        ui.horizontal_wrapped(|ui| {
            let l = ui.label("order");
            egui::ComboBox::from_id_salt("track-order")
                .selected_text(format!("{}", app.traces.track_order))
                .show_ui(ui, |ui| {
                    for q in &orders {
                        ui.selectable_value(&mut app.traces.track_order, *q, format!("{q}"));
                    }
                })
                .response
                .labelled_by(l.id);
            ui.weak("amplitude over the run-up, 0.1 s windows");
        });
    }
    let per =
        ((ui.available_height() - 8.0 * shown.len() as f32) / shown.len().max(1) as f32).max(150.0);
    // Orders up to the last one above 1 % of the largest (at least 6).
    let peak = sim
        .analysis
        .stations
        .iter()
        .chain(meas.iter().flat_map(|m| &m.stations))
        .flat_map(|s| &s.orders)
        .fold(0.0_f64, |m, o| m.max(o.amplitude));
    let last_order = sim
        .analysis
        .stations
        .iter()
        .chain(meas.iter().flat_map(|m| &m.stations))
        .flat_map(|s| &s.orders)
        .filter(|o| o.amplitude > 0.01 * peak)
        .fold(6.0_f64, |m, o| m.max(o.order + 1.0));
    egui::ScrollArea::vertical().show(ui, |ui| {
        for (i, name) in shown.iter().enumerate() {
            let s = find(&sim.analysis, name);
            let m = meas.and_then(|a| find(a, name));
            let mut plot = Plot::new(("orders", i))
                .height(per)
                .y_axis_min_width(crate::gui::views::plots::time_series::Y_AXIS_W)
                .y_grid_spacer(crate::gui::views::plots::time_series::nice_grid())
                .y_axis_formatter(super::tick_label)
                .x_axis_formatter(super::tick_label)
                .y_axis_label(format!("{name} [rpm] 0-pk"));
            // The legend beside the plot (issue 16: on it, it covered the bars).
            let mut entries = vec![Entry {
                name: "simulated".into(),
                color: SIMULATED,
                dashed: false,
            }];
            if m.is_some() {
                entries.push(Entry {
                    name: "measured".into(),
                    color: MEASURED,
                    dashed: true,
                });
            }
            let legend_id = format!("orders {name}");
            let last = i + 1 == shown.len();
            if ramp {
                let q = app.traces.track_order;
                let tracks = |a: &Analysis, s: Option<&StationAnalysis>| -> Vec<[f64; 2]> {
                    let (Some(axes), Some(st)) = (&a.stft, s.and_then(|s| s.stft.as_ref())) else {
                        return Vec::new();
                    };
                    let Some(k) = axes.orders.iter().position(|o| *o == q) else {
                        return Vec::new();
                    };
                    axes.speeds_rpm
                        .iter()
                        .zip(&st.order_tracks_rpm[k])
                        .map(|(&n, &v)| [n, v])
                        .collect()
                };
                let sim_track = tracks(&sim.analysis, s);
                let meas_track = meas.map(|a| tracks(a, m)).unwrap_or_default();
                if last {
                    plot = plot.x_axis_label("reference speed [rpm]");
                }
                with_side_legend(ui, &legend_id, &entries, per, |ui, hidden| {
                    plot.show(ui, |plot| {
                        if !hidden.contains("simulated") {
                            plot.line(
                                Line::new(format!("simulated, order {q}"), sim_track)
                                    .color(SIMULATED),
                            );
                        }
                        if !meas_track.is_empty() && !hidden.contains("measured") {
                            plot.line(
                                Line::new(format!("measured, order {q}"), meas_track)
                                    .color(MEASURED)
                                    .style(LineStyle::dashed_dense()),
                            );
                        }
                    });
                });
            } else {
                let width = if m.is_some() { 0.2 } else { 0.35 };
                let bars =
                    |s: Option<&StationAnalysis>, dx: f64, colour: Color32, what: &'static str| {
                        let bars = s
                            .map(|s| {
                                s.orders
                                    .iter()
                                    .map(|o| {
                                        Bar::new(o.order + dx, o.amplitude)
                                            .width(width)
                                            .name(format!("order {}", o.order))
                                    })
                                    .collect()
                            })
                            .unwrap_or_default();
                        BarChart::new(what, bars)
                            .color(colour)
                            .element_formatter(Box::new(move |bar, _| {
                                format!("{what}, {}\n{:.4} rpm (0-peak)", bar.name, bar.value)
                            }))
                    };
                let dx = if m.is_some() { 0.11 } else { 0.0 };
                let sim_bars = bars(s, -dx, SIMULATED, "simulated");
                let meas_bars = m.map(|m| bars(Some(m), dx, MEASURED, "measured"));
                if last {
                    plot = plot.x_axis_label("engine order");
                }
                let plot = plot.include_y(0.0).default_x_bounds(0.0, last_order);
                with_side_legend(ui, &legend_id, &entries, per, |ui, hidden| {
                    plot.show(ui, |plot| {
                        if !hidden.contains("simulated") {
                            plot.bar_chart(sim_bars);
                        }
                        if let Some(b) = meas_bars.filter(|_| !hidden.contains("measured")) {
                            plot.bar_chart(b);
                        }
                    });
                });
            }
        }
    });
}

/// One line per station: mean speed, RMS, IR and the dominant order, simulated and
/// measured.
fn summary_ui(ui: &mut Ui, sim: &Analysis, meas: Option<&Analysis>, shown: &[String], ramp: bool) {
    let cell = |s: Option<&StationAnalysis>, f: &dyn Fn(&StationAnalysis) -> String| {
        s.map_or("—".to_string(), f)
    };
    let dominant_text = |s: &StationAnalysis| {
        dominant(&s.orders).map_or("—".into(), |(q, a)| format!("{q} ({a:.3} rpm)"))
    };
    egui::Grid::new("orders-summary")
        .striped(true)
        .show(ui, |ui| {
            ui.strong("station");
            ui.strong("mean [rpm]");
            ui.strong("RMS [rpm]");
            ui.strong("IR [%]");
            if !ramp {
                ui.strong("dominant order");
            }
            ui.end_row();
            for name in shown {
                let s = find(sim, name);
                let m = meas.and_then(|a| find(a, name));
                let pair = |f: &dyn Fn(&StationAnalysis) -> String| match meas {
                    Some(_) => format!("sim {} · meas {}", cell(s, f), cell(m, f)),
                    None => cell(s, f),
                };
                ui.label(name);
                ui.label(pair(&|s| fixed(s.mean_speed_rpm, 1)));
                ui.label(pair(&|s| fixed(s.rms_rpm, 3)));
                ui.label(pair(&|s| fixed(s.irregularity_pct, 3)));
                if !ramp {
                    let text = match meas {
                        Some(_) => format!(
                            "dominant order: measured {} · simulated {}",
                            cell(m, &dominant_text),
                            cell(s, &dominant_text)
                        ),
                        None => format!("dominant order: {}", cell(s, &dominant_text)),
                    };
                    ui.label(text);
                }
                ui.end_row();
            }
        });
}
