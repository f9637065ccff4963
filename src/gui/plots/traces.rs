//! The traces tab: what to run and its progress ([`super::run_controls`]), then one of
//! three views: time traces (this file: IAS per node, relative speed across each rubber
//! stage, torque, power loss, rubber temperature — one plot per quantity, x axes and
//! cursors linked, growing while the run streams in, a recording's stations overlaid),
//! the run-up spectrogram ([`super::stft`]) or the orders ([`super::recording`]).

use super::{mode_color, recording, run_controls, stft};
use crate::gui::app::TorsimApp;
use crate::gui::trace_data::{GroupKind, TraceLayout, decimate};
use crate::gui::trace_state::TraceView;
use egui::{Id, Ui};
use egui_plot::{HoverPosition, ItemId, Legend, Line, Plot, PlotUi};
use std::sync::Arc;
use torsim::recording::ChannelKind;

/// The traces tab.
pub fn traces_ui(app: &mut TorsimApp, ui: &mut Ui) {
    run_controls::controls_ui(app, ui);
    run_controls::status_ui(app, ui);
    run_controls::recording_ui(app, ui);
    run_controls::view_ui(app, ui);
    ui.separator();
    match app.traces.view {
        TraceView::Traces => time_traces_ui(app, ui),
        TraceView::Spectrogram => stft::spectrogram_ui(app, ui),
        TraceView::Orders => recording::orders_ui(app, ui),
    }
}

/// The x axes (time) of every time plot move together.
pub fn time_link() -> Id {
    Id::unique("torsim-time-axis")
}

/// The visible time range of a plot (all of it while it follows the data), with a
/// plot width of margin either side.
pub fn visible_range(plot: &PlotUi<'_>) -> [f64; 2] {
    let b = plot.plot_bounds();
    if plot.auto_bounds().x || !b.is_valid_x() {
        return [f64::NEG_INFINITY, f64::INFINITY];
    }
    let w = b.width();
    [b.min()[0] - w, b.max()[0] + w]
}

/// Points of `(time_s + offset_s, values − baseline(time_s + offset_s))` within `range`,
/// decimated to `buckets`.
pub fn points(
    time_s: &[f64],
    values: &[f64],
    offset_s: f64,
    baseline: &dyn Fn(f64) -> f64,
    range: [f64; 2],
    buckets: usize,
) -> Vec<[f64; 2]> {
    let shifted = |t: f64| baseline(t + offset_s);
    let mut p = decimate(
        time_s,
        values,
        &shifted,
        [range[0] - offset_s, range[1] - offset_s],
        buckets,
    );
    p.iter_mut().for_each(|x| x[0] += offset_s);
    p
}

/// Hover read-out: the series, time with the reference speed, and value with unit.
pub fn hover_label(
    layout: Arc<TraceLayout>,
    unit: &'static str,
) -> impl Fn(&HoverPosition<'_>) -> Option<String> {
    move |pos| {
        let (name, p) = match pos {
            HoverPosition::NearDataPoint {
                plot_name,
                position,
                ..
            } => (*plot_name, *position),
            HoverPosition::Elsewhere { position } => ("", *position),
        };
        let head = if name.is_empty() {
            String::new()
        } else {
            format!("{name}\n")
        };
        let speed = layout.speed_at(p.x);
        Some(format!(
            "{head}t = {:.4} s ({speed:.0} rpm)\n{:.3} {unit}",
            p.x, p.y
        ))
    }
}

/// The unit of a group's values.
fn unit(kind: GroupKind) -> &'static str {
    match kind {
        GroupKind::Speed | GroupKind::RelativeSpeed => "rpm",
        GroupKind::Torque => "N·m",
        GroupKind::PowerLoss => "W",
        GroupKind::Temperature => "°C",
    }
}

/// Width of the y axes of stacked plots, points (equal, so linked time axes line up).
pub const Y_AXIS_W: f32 = 64.0;

/// One plot per quantity, stacked; IAS twice as tall.
fn time_traces_ui(app: &mut TorsimApp, ui: &mut Ui) {
    if app.results.live.is_none() {
        ui.label("Waiting for the first samples of the time run…");
        return;
    }
    ui.horizontal(|ui| {
        ui.checkbox(
            &mut app.traces.ias_about_mean,
            "IAS about each station's mean speed",
        )
        .on_hover_text("the vibration without the mean speed (or the run-up ramp), in rpm");
        ui.weak("drag to pan, scroll or box-zoom (right drag), double-click to reset");
    });
    let Some(live) = &app.results.live else {
        return;
    };
    let about_mean = app.traces.ias_about_mean;
    let layout = live.layout.clone();
    let fresh = app.traces.drawn != Some(live.generation);
    let measured = app.results.recording.clone();
    let shift_s = app
        .results
        .trace_analysis
        .as_ref()
        .map_or(0.0, |a| a.overlay_shift_s);
    let n = layout.groups.len();
    let gap = ui.spacing().item_spacing.y;
    let unit_h = ((ui.available_height() - gap * n as f32) / (n + 1) as f32).max(90.0);
    let buckets = ui.available_width().max(100.0) as usize;
    let duration = layout.duration_s();
    egui::ScrollArea::vertical().show(ui, |ui| {
        for (i, ((kind, group), samples)) in layout.groups.iter().zip(&live.groups).enumerate() {
            let kind = *kind;
            let hidden: Vec<ItemId> = group
                .names
                .iter()
                .zip(&group.visible)
                .filter(|(_, v)| !**v)
                .map(|(name, _)| ItemId::new(name))
                .collect();
            let mut legend = Legend::default().follow_insertion_order(true);
            if fresh {
                legend = legend.hidden_items(hidden);
            }
            let axis = if kind == GroupKind::Speed && about_mean {
                "IAS - mean speed [rpm] (own shaft)".to_string()
            } else {
                group.axis.clone()
            };
            let mut plot = Plot::new(("trace", i))
                .height(if i == 0 { 2.0 * unit_h } else { unit_h })
                .y_axis_min_width(Y_AXIS_W)
                .legend(legend)
                .link_axis(time_link(), [true, false])
                .link_cursor(time_link(), [true, false])
                .include_x(0.0)
                .include_x(duration)
                .y_axis_label(axis)
                .label_formatter(hover_label(layout.clone(), unit(kind)));
            if i + 1 == n {
                plot = plot.x_axis_label("time from the start of recording [s]");
            }
            if fresh {
                plot = plot.reset();
            }
            let measured = measured.clone();
            let layout = layout.clone();
            // The mean speed of node `k` at time `t` in the simulated run, rpm.
            let sim_mean = |k: usize| {
                let (layout, on) = (layout.clone(), kind == GroupKind::Speed && about_mean);
                move |t: f64| {
                    if on {
                        layout.speed_ratio.get(k).copied().unwrap_or(1.0) * layout.speed_at(t)
                    } else {
                        0.0
                    }
                }
            };
            plot.show(ui, |plot| {
                let range = visible_range(plot);
                // Measured first: a pale wide band under the simulated line.
                if let Some(m) = &measured {
                    let offset = shift_s - m.t0_s;
                    for c in &m.recording.channels {
                        let name = match (&c.kind, kind) {
                            (ChannelKind::SpeedRpm { node }, GroupKind::Speed)
                            | (ChannelKind::TorqueNm { connection: node }, GroupKind::Torque) => {
                                node
                            }
                            _ => continue,
                        };
                        let Some(k) = group.names.iter().position(|n| n == name) else {
                            continue;
                        };
                        let mean = m.mean_speed_at(name, layout.speed_ratio.get(k).copied());
                        let baseline = |t: f64| {
                            if kind == GroupKind::Speed && about_mean {
                                mean(t - shift_s)
                            } else {
                                0.0
                            }
                        };
                        let p = points(
                            &m.recording.time_s,
                            &c.values,
                            offset,
                            &baseline,
                            range,
                            buckets,
                        );
                        plot.line(
                            Line::new(format!("{name} (measured)"), p)
                                .color(mode_color(k).gamma_multiply(0.45))
                                .width(3.0),
                        );
                    }
                }
                for (k, (name, values)) in group.names.iter().zip(&samples.values).enumerate() {
                    let p = points(&samples.time_s, values, 0.0, &sim_mean(k), range, buckets);
                    plot.line(Line::new(name.clone(), p).color(mode_color(k)).width(1.2));
                }
            });
        }
    });
    app.traces.drawn = Some(live.generation);
}
