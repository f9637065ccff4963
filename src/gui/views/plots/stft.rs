//! The run-up spectrogram: the STFT of the selected station's IAS (`torsim::signal`, built
//! into an image on the simulation thread) as a texture with time across (linked to the
//! time traces; the reference speed on a second axis) and frequency up, engine-order lines
//! and the model's natural frequencies over it, a colour scale in dB re 1 rpm; below it
//! the order tracks of that station, the recording's dashed when one is open.

use super::{colour_scale, order_tracks};
use crate::gui::app::TorsimApp;
use crate::gui::session::spectrogram::SpectrogramSet;
use crate::gui::session::trace_data::profile_rpm;
use crate::gui::views::plots::time_series::{self, time_link};
use egui::{Align2, Color32, Ui, Vec2};
use egui_plot::{
    AxisHints, HLine, HoverPosition, Line, LineStyle, Plot, PlotImage, PlotPoint, Text,
};
use std::sync::Arc;
use torsim::recording::Run;
use torsim::signal::{Analysis, StationAnalysis};

/// Width of the colour scale beside the spectrogram, points.
pub const SCALE_W: f32 = 78.0;

/// The spectrogram view.
pub fn spectrogram_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let simulated = app.results.trace_analysis.clone();
    let measured = app.results.recording.clone();
    let sim_set = simulated.as_ref().and_then(|a| a.spectrograms.clone());
    let meas_set = measured.as_ref().and_then(|r| r.spectrograms.clone());
    if meas_set.is_none() {
        app.traces.measured_stft = false;
    }
    let use_measured = app.traces.measured_stft;
    let (set, analysis, other) = match (use_measured, sim_set, meas_set.clone()) {
        (true, _, Some(m)) => (m, measured.as_ref().map(|r| &r.analysis), None),
        (_, Some(s), m) => (
            s,
            simulated.as_ref().map(|a| &a.analysis),
            m.zip(measured.as_ref().map(|r| &r.analysis)),
        ),
        _ => {
            let running = app
                .results
                .live
                .as_ref()
                .is_some_and(|l| l.layout.is_ramp());
            ui.label(if running {
                "The spectrogram is computed when the run-up has finished."
            } else {
                "Choose Run-up above: the spectrogram is of a run-up."
            });
            return;
        }
    };
    let Some(analysis) = analysis else { return };
    let names: Vec<String> = set.stations.iter().map(|s| s.station.clone()).collect();
    if !names.contains(&app.traces.station) {
        app.traces.station = if names.contains(&analysis.reference) {
            analysis.reference.clone()
        } else {
            names.first().cloned().unwrap_or_default()
        };
    }
    ui.horizontal_wrapped(|ui| {
        let l = ui.label("station");
        egui::ComboBox::from_id_salt("stft-station")
            .selected_text(app.traces.station.clone())
            .show_ui(ui, |ui| {
                for n in &names {
                    ui.selectable_value(&mut app.traces.station, n.clone(), n);
                }
            })
            .response
            .labelled_by(l.id);
        if meas_set.is_some() {
            ui.separator();
            ui.selectable_value(&mut app.traces.measured_stft, false, "simulated");
            ui.selectable_value(&mut app.traces.measured_stft, true, "measured");
        }
        ui.separator();
        // The tracks drawn below: the main orders unless chosen.
        let major = major_order_step(app);
        if app
            .traces
            .track_orders
            .as_ref()
            .is_none_or(|(m, _)| *m != major)
        {
            let main = set.orders.iter().copied();
            let main = main.filter(|q| (q / major - (q / major).round()).abs() < 1e-9);
            app.traces.track_orders = Some((major, main.collect()));
        }
        let Some((_, tracks)) = app.traces.track_orders.as_mut() else {
            return;
        };
        ui.menu_button(format!("order tracks ({})", tracks.len()), |ui| {
            for &q in &set.orders {
                let mut on = tracks.contains(&q);
                if ui.checkbox(&mut on, format!("order {q}")).changed() {
                    tracks.retain(|x| *x != q);
                    if on {
                        tracks.push(q);
                        tracks.sort_by(f64::total_cmp);
                    }
                }
            }
        });
        ui.weak("0.1 s Hann windows, amplitude 0-peak");
    });
    let Some(index) = names.iter().position(|n| *n == app.traces.station) else {
        return;
    };
    let image = &set.stations[index];
    let key = (app.results.generation, use_measured, image.station.clone());
    let texture = match &app.traces.texture {
        Some((k, t)) if *k == key => t.clone(),
        _ => {
            let t = ui.ctx().load_texture(
                "torsim-spectrogram",
                image.image.clone(),
                egui::TextureOptions::LINEAR,
            );
            app.traces.texture = Some((key, t.clone()));
            t
        }
    };
    let height = (ui.available_height() * 0.6).max(220.0);
    let [t0, t1] = set.time_range_s;
    let [f0, f1] = set.freq_range_hz;
    // The ramp on the time axis: round speeds get the grid lines.
    let ramp = if use_measured {
        measured.as_ref().map(|r| r.regime)
    } else {
        app.results.live.as_ref().map(|l| l.layout.kind)
    };
    let axis = SpeedAxis::new(ramp, set.clone());
    let speed_axis = axis.clone();
    let modes: Vec<f64> = app
        .results
        .campbell
        .as_ref()
        .map(|c| c.campbell.modes.iter().map(|m| m.frequency_hz).collect())
        .unwrap_or_default();
    let major = major_order_step(app);
    // The view opens on the modes and the main order twice over (zoom out for the rest).
    let top_rpm = set.speeds_rpm.iter().fold(0.0_f64, |m, v| m.max(*v));
    let highest_mode = modes
        .iter()
        .copied()
        .filter(|f| *f < f1)
        .fold(0.0, f64::max);
    let f_view = (1.5 * highest_mode)
        .max(2.0 * major * top_rpm / 60.0)
        .min(f1);
    let set_hover = set.clone();
    ui.horizontal(|ui| {
        Plot::new("spectrogram")
            .height(height)
            .width((ui.available_width() - SCALE_W).max(200.0))
            .y_axis_min_width(time_series::Y_AXIS_W)
            .link_axis(time_link(), [true, false])
            .link_cursor(time_link(), [true, false])
            .include_x(t0)
            .include_x(t1)
            .default_y_bounds(0.0, f_view)
            .y_axis_label("frequency [Hz]")
            .x_grid_spacer(axis.grid())
            .custom_x_axes(vec![
                AxisHints::new_x().label("time [s]"),
                AxisHints::new_x()
                    .label("reference speed [rpm]")
                    .formatter(move |mark, _| format!("{:.0}", speed_axis.rpm(mark.value))),
            ])
            .label_formatter(move |pos| {
                let p = match pos {
                    HoverPosition::NearDataPoint { position, .. }
                    | HoverPosition::Elsewhere { position } => *position,
                };
                let n = set_hover.speed_at(p.x);
                let level = set_hover.stations[index]
                    .db_at(&set_hover, p.x, p.y)
                    .map_or(String::new(), |db| format!("\n{db:.1} dB re 1 rpm"));
                Some(format!(
                    "t = {:.2} s ({n:.0} rpm)\nf = {:.1} Hz = order {:.2}{level}",
                    p.x,
                    p.y,
                    p.y * 60.0 / n.max(1e-9)
                ))
            })
            .show(ui, |plot| {
                plot.image(PlotImage::new(
                    "STFT",
                    texture.id(),
                    PlotPoint::new(0.5 * (t0 + t1), 0.5 * (f0 + f1)),
                    Vec2::new((t1 - t0) as f32, (f1 - f0) as f32),
                ));
                for (i, &f) in modes.iter().enumerate().filter(|(_, f)| **f < f1) {
                    plot.hline(
                        HLine::new(format!("mode {}", i + 1), f)
                            .color(Color32::from_white_alpha(110))
                            .style(LineStyle::dashed_loose()),
                    );
                    plot.text(
                        Text::new(
                            "",
                            PlotPoint::new(t0, f),
                            format!(" mode {} {f:.1} Hz", i + 1),
                        )
                        .color(Color32::WHITE)
                        .anchor(Align2::LEFT_BOTTOM),
                    );
                }
                for &q in set.orders.iter().filter(|q| q.fract() == 0.0) {
                    let line: Vec<[f64; 2]> = set
                        .times_s
                        .iter()
                        .zip(&set.speeds_rpm)
                        .map(|(&t, &n)| [t, q * n / 60.0])
                        .filter(|p| p[1] <= f1)
                        .collect();
                    // The label where the line leaves the opening view.
                    let Some(&[t_end, f_end]) = line.iter().rfind(|p| p[1] <= f_view) else {
                        continue;
                    };
                    let strong = (q / major - (q / major).round()).abs() < 1e-9;
                    let alpha = if strong { 110 } else { 40 };
                    plot.line(
                        Line::new("", line)
                            .color(Color32::from_white_alpha(alpha))
                            .width(1.0)
                            .style(LineStyle::dashed_loose())
                            .allow_hover(false),
                    );
                    // Lines leaving through the top are labelled below their end.
                    let anchor = if f_end > 0.95 * f_view {
                        Align2::RIGHT_TOP
                    } else {
                        Align2::RIGHT_BOTTOM
                    };
                    plot.text(
                        Text::new("", PlotPoint::new(t_end, f_end), format!("{q}"))
                            .color(Color32::WHITE)
                            .anchor(anchor),
                    );
                }
            });
        colour_scale::colour_scale_ui(ui, image.db_range, height, SCALE_W);
    });
    let station = find(analysis, &app.traces.station);
    let other = other.and_then(|(set, a)| Some((set, find(a, &app.traces.station)?)));
    let shown = app
        .traces
        .track_orders
        .as_ref()
        .map(|(_, t)| t.clone())
        .unwrap_or_default();
    order_tracks::order_tracks_ui(ui, &set, &axis, station, other, &shown);
}

/// The reference speed along a run-up's time axis: the imposed (or fitted) ramp when
/// known, else interpolated between the STFT windows.
#[derive(Clone)]
pub struct SpeedAxis {
    ramp: Option<Run>,
    set: Arc<SpectrogramSet>,
}

impl SpeedAxis {
    fn new(ramp: Option<Run>, set: Arc<SpectrogramSet>) -> Self {
        Self { ramp, set }
    }

    /// Reference speed at `t_s`, rpm.
    pub fn rpm(&self, t_s: f64) -> f64 {
        match self.ramp {
            Some(kind) => profile_rpm(kind, t_s),
            None => self.set.speed_at(t_s),
        }
    }

    /// Grid lines at round speeds.
    pub fn grid(&self) -> impl Fn(egui_plot::GridInput) -> Vec<egui_plot::GridMark> + use<> {
        let (from, rate) = match self.ramp {
            Some(run) if run.is_ramp() => (run.speeds_rpm()[0], run.rate_rpm_per_s()),
            _ => (0.0, 0.0),
        };
        time_series::speed_grid(from, rate)
    }
}

/// Orders at multiples of this step are the engine's main ones (half the cylinder count
/// for a 4-stroke, the count for a 2-stroke; 1 without an engine).
fn major_order_step(app: &TorsimApp) -> f64 {
    app.model.engine.as_ref().map_or(1.0, |e| {
        f64::from(e.cylinders) * if e.strokes == 2 { 1.0 } else { 0.5 }
    })
}

/// A station or relative speed of an analysis by name.
fn find<'a>(a: &'a Analysis, name: &str) -> Option<&'a StationAnalysis> {
    a.stations.iter().chain(&a.n_rel).find(|s| s.name == name)
}
