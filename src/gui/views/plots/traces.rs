//! The traces tab: what to run and its progress ([`crate::gui::views::plots::run_controls`]), then one of
//! three views: time traces (this file: IAS per node, relative speed across each rubber
//! stage, torque, power loss, rubber temperature — one plot per quantity, x axes and
//! cursors linked, growing while the run streams in, a recording's stations overlaid),
//! the run-up spectrogram ([`crate::gui::views::plots::stft`]) or the orders ([`crate::gui::views::plots::recording`]).

use super::{mode_color, recording, run_controls, stft};
use crate::gui::app::TorsimApp;
use crate::gui::session::trace_data::GroupKind;
use crate::gui::trace_state::TraceView;
use crate::gui::views::plots::side_legend::{Entry, with_side_legend};
use crate::gui::views::plots::time_series::{
    self, Look, Y_AXIS_W, draw, hover_label, nice_grid, nice_x_grid, time_link,
};
use egui::Ui;
use egui_plot::Plot;
use torsim::recording::ChannelKind;

/// The traces tab.
pub fn traces_ui(app: &mut TorsimApp, ui: &mut Ui) {
    run_controls::controls_ui(app, ui);
    run_controls::status_ui(app, ui);
    run_controls::recording_ui(app, ui);
    run_controls::view_ui(app, ui);
    ui.separator();
    if app.traces.shown_view != Some(app.traces.view) {
        // Plots shown for the first time size their axes in the frame after.
        app.traces.shown_view = Some(app.traces.view);
        ui.ctx().request_repaint();
    }
    match app.traces.view {
        TraceView::Traces => time_traces_ui(app, ui),
        TraceView::Spectrogram => stft::spectrogram_ui(app, ui),
        TraceView::Orders => recording::orders_ui(app, ui),
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

/// The series shown per group: the layout's defaults for a run of a new kind (or a new
/// layout), else the user's choice.
fn shown(app: &mut TorsimApp, fresh: bool) -> Vec<Vec<bool>> {
    let Some(live) = &app.results.live else {
        return Vec::new();
    };
    let defaults: Vec<Vec<bool>> = live
        .layout
        .groups
        .iter()
        .map(|(_, g)| g.visible.clone())
        .collect();
    let same_shape = app.traces.shown.len() == defaults.len()
        && app
            .traces
            .shown
            .iter()
            .zip(&defaults)
            .all(|(a, b)| a.len() == b.len());
    if fresh || !same_shape {
        app.traces.shown = defaults;
    }
    app.traces.shown.clone()
}

/// A menu per group with more than one series: which are drawn.
fn series_menus_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let Some(live) = &app.results.live else {
        return;
    };
    let layout = live.layout.clone();
    for ((_, group), shown) in layout.groups.iter().zip(app.traces.shown.iter_mut()) {
        if group.names.len() < 2 {
            continue;
        }
        let count = shown.iter().filter(|s| **s).count();
        ui.menu_button(
            format!("{} ({count}/{})", group.title, group.names.len()),
            |ui| {
                for (name, on) in group.names.iter().zip(shown.iter_mut()) {
                    ui.checkbox(on, name);
                }
            },
        );
    }
}

/// One plot per quantity, stacked; IAS twice as tall.
fn time_traces_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let Some(kind) = app.results.live.as_ref().map(|l| l.layout.kind) else {
        // Issue 16: an error state says so and shows the way out, never "waiting".
        let text = if app.error_of("recording").is_some() {
            "No time run: it follows the open recording, which could not be used (above). \
             Close the recording, or choose a steady run or a run-up."
        } else if app.error_of("trace").is_some() {
            "No time run: the error above stops it. Edit the model or the run settings."
        } else if app.invalid.is_some() {
            "No time run: the model is invalid (see the status line and the driveline panel)."
        } else if app.results.trace_cancelled == Some(app.results.generation) {
            "The time run was cancelled: Run again above."
        } else {
            "Waiting for the first samples of the time run…"
        };
        ui.label(text);
        return;
    };
    // A run of another kind opens with its own zoom and series; a re-run of the same
    // (after an edit) keeps the user's.
    let fresh = app.traces.drawn != Some(kind);
    let shown = shown(app, fresh);
    ui.horizontal_wrapped(|ui| {
        ui.checkbox(
            &mut app.traces.ias_about_mean,
            "IAS about each station's mean speed",
        )
        .on_hover_text("the vibration without the mean speed (or the run-up ramp), in rpm");
        ui.separator();
        ui.label("show");
        series_menus_ui(app, ui);
        ui.separator();
        ui.weak("drag: pan · ctrl+scroll or right-drag: zoom · double-click: reset");
    });
    let Some(live) = &app.results.live else {
        return;
    };
    let about_mean = app.traces.ias_about_mean;
    let layout = live.layout.clone();
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
    let opening = layout.opening_range_s();
    egui::ScrollArea::vertical().show(ui, |ui| {
        for (i, ((kind, group), samples)) in layout.groups.iter().zip(&live.groups).enumerate() {
            let kind = *kind;
            let visible = &shown[i];
            // Colours by rank among the series shown, so that they differ.
            let colour = |k: usize| mode_color(visible[..k].iter().filter(|v| **v).count());
            let axis = if kind == GroupKind::Speed && about_mean {
                // Short enough for the height of the plot (issue 16: it was cut off).
                "IAS − mean [rpm]".to_string()
            } else {
                group.axis.clone()
            };
            let height = if i == 0 { 2.0 * unit_h } else { unit_h };
            let mut plot = Plot::new(("trace", i))
                .height(height)
                .y_axis_min_width(Y_AXIS_W)
                .y_grid_spacer(nice_grid())
                .y_axis_formatter(super::tick_label)
                .x_grid_spacer(nice_x_grid())
                .x_axis_formatter(super::tick_label)
                .link_axis(time_link(), [true, false])
                .link_cursor(time_link(), [true, false])
                .default_x_bounds(opening[0], opening[1])
                .y_axis_label(axis)
                .label_formatter(hover_label(layout.clone(), unit(kind)));
            // The recording's series of this plot: (series index, name, samples).
            let measured_series: Vec<(usize, String, Vec<f64>)> = measured
                .as_ref()
                .map(|m| {
                    let channels = m.recording.channels.iter().filter_map(|c| {
                        match (&c.kind, kind) {
                            (ChannelKind::SpeedRpm { node }, GroupKind::Speed)
                            | (ChannelKind::TorqueNm { connection: node }, GroupKind::Torque) => {
                                Some((node, &c.values))
                            }
                            _ => None,
                        }
                    });
                    let relative = m
                        .relative
                        .iter()
                        .filter(|_| kind == GroupKind::RelativeSpeed)
                        .map(|(n, v)| (n, v));
                    channels
                        .chain(relative)
                        .filter_map(|(name, values)| {
                            let k = group.names.iter().position(|n| n == name)?;
                            visible[k].then(|| (k, name.clone(), values.clone()))
                        })
                        .collect()
                })
                .unwrap_or_default();
            // The legend beside the plot (issue 16: on the plot it covered the traces).
            let mut entries: Vec<Entry> = group
                .names
                .iter()
                .enumerate()
                .filter(|(k, _)| visible[*k])
                .map(|(k, name)| Entry {
                    name: name.clone(),
                    color: colour(k),
                    dashed: false,
                })
                .collect();
            entries.extend(measured_series.iter().map(|(k, name, _)| Entry {
                name: format!("{name} (measured)"),
                color: colour(*k),
                dashed: true,
            }));
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
            with_side_legend(ui, &format!("trace {i}"), &entries, height, |ui, hidden| {
                plot.show(ui, |plot| {
                    let range = time_series::visible_range(plot);
                    // Measured first, under the simulated.
                    if let Some(m) = &measured {
                        let offset = shift_s - m.t0_s;
                        for (k, name, values) in &measured_series {
                            let label = format!("{name} (measured)");
                            if hidden.contains(&label) {
                                continue;
                            }
                            let mean = m.mean_speed_at(name, layout.speed_ratio.get(*k).copied());
                            let baseline = |t: f64| {
                                if kind == GroupKind::Speed && about_mean {
                                    mean(t - shift_s)
                                } else {
                                    0.0
                                }
                            };
                            let d = time_series::series(
                                &m.recording.time_s,
                                values,
                                offset,
                                &baseline,
                                range,
                                buckets,
                            );
                            draw(plot, &label, d, colour(*k), Look::Measured);
                        }
                    }
                    let series = group.names.iter().zip(&samples.values).enumerate();
                    for (k, (name, values)) in series.filter(|(k, _)| visible[*k]) {
                        if hidden.contains(name) {
                            continue;
                        }
                        let baseline = sim_mean(k);
                        let d = time_series::series(
                            &samples.time_s,
                            values,
                            0.0,
                            &baseline,
                            range,
                            buckets,
                        );
                        draw(plot, name, d, colour(k), Look::Simulated);
                    }
                });
            });
        }
    });
    if fresh {
        // The reset plots lay out their axes and legends again in the next frame.
        ui.ctx().request_repaint();
    }
    app.traces.drawn = Some(live.layout.kind);
}
