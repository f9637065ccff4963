//! Order tracks of a run-up: for one station, the amplitude of each engine order in
//! every STFT window at the order's exact frequency (`torsim::signal`, rpm 0-peak) over
//! time, linked to the spectrogram above; the recording's dashed when one is open. The
//! legend sits in the column under the spectrogram's colour scale, beside the data
//! (issue 16: on the plot it covered the tracks); which orders are drawn is chosen in the
//! "order tracks" menu above.

use super::mode_color;
use crate::gui::session::spectrogram::SpectrogramSet;
use crate::gui::views::plots::stft::{SCALE_W, SpeedAxis};
use crate::gui::views::plots::time_series::{self, Look, draw, time_link, visible_range};
use egui::{RichText, Ui};
use egui_plot::{AxisHints, HoverPosition, Plot};
use std::sync::Arc;
use torsim::signal::StationAnalysis;

/// The tracks of the orders `shown` of a station over the run-up (rpm 0-peak), the
/// recording's dashed.
pub fn order_tracks_ui(
    ui: &mut Ui,
    set: &Arc<SpectrogramSet>,
    axis: &SpeedAxis,
    station: Option<&StationAnalysis>,
    other: Option<(Arc<SpectrogramSet>, &StationAnalysis)>,
    shown: &[f64],
) {
    let Some(tracks) = station.and_then(|s| s.stft.as_ref()) else {
        return;
    };
    let label = if other.is_some() {
        "order amplitude [rpm] (0-peak; dashed: measured)"
    } else {
        "order amplitude [rpm] (0-peak)"
    };
    let drawn: Vec<(usize, f64)> = set
        .orders
        .iter()
        .copied()
        .filter(|q| shown.contains(q))
        .enumerate()
        .collect();
    ui.horizontal_top(|ui| {
        plot_ui(ui, set, axis, tracks, other, shown, label);
        ui.vertical(|ui| {
            ui.set_width(SCALE_W - ui.spacing().item_spacing.x);
            for (rank, q) in &drawn {
                ui.label(
                    RichText::new(format!("— order {q}"))
                        .small()
                        .color(mode_color(*rank)),
                );
            }
        });
    });
}

/// The plot of [`order_tracks_ui`], leaving [`SCALE_W`] for the legend.
fn plot_ui(
    ui: &mut Ui,
    set: &Arc<SpectrogramSet>,
    axis: &SpeedAxis,
    tracks: &torsim::signal::StationStft,
    other: Option<(Arc<SpectrogramSet>, &StationAnalysis)>,
    shown: &[f64],
    label: &str,
) {
    let speed_axis = axis.clone();
    let hover_axis = axis.clone();
    Plot::new("order-tracks")
        .width((ui.available_width() - SCALE_W).max(200.0))
        .y_axis_min_width(time_series::Y_AXIS_W)
        .y_grid_spacer(time_series::nice_grid())
        .y_axis_formatter(super::tick_label)
        .x_grid_spacer(axis.grid())
        .link_axis(time_link(), [true, false])
        .link_cursor(time_link(), [true, false])
        .custom_x_axes(vec![
            AxisHints::new_x().label("time [s]"),
            AxisHints::new_x()
                .label("reference speed [rpm]")
                .formatter(move |mark, _| format!("{:.0}", speed_axis.rpm(mark.value))),
        ])
        .y_axis_label(label)
        .label_formatter(move |pos| {
            let (name, p) = match pos {
                HoverPosition::NearDataPoint {
                    plot_name,
                    position,
                    ..
                } => (*plot_name, *position),
                HoverPosition::Elsewhere { position } => ("", *position),
            };
            Some(format!(
                "{name}\nt = {:.2} s ({:.0} rpm)\n{:.3} rpm",
                p.x,
                hover_axis.rpm(p.x),
                p.y
            ))
        })
        .show(ui, |plot| {
            let range = visible_range(plot);
            let tracked = set.orders.iter().zip(&tracks.order_tracks_rpm).enumerate();
            let shown_tracks = tracked.filter(|(_, (q, _))| shown.contains(q));
            for (rank, (k, (q, track))) in shown_tracks.enumerate() {
                let name = format!("order {q}");
                let d = time_series::series(&set.times_s, track, 0.0, &|_| 0.0, range, 2000);
                draw(plot, &name, d, mode_color(rank), Look::Simulated);
                let Some((o_set, o)) = &other else {
                    continue;
                };
                if let Some(track) = o.stft.as_ref().and_then(|s| s.order_tracks_rpm.get(k)) {
                    let d = time_series::series(&o_set.times_s, track, 0.0, &|_| 0.0, range, 2000);
                    draw(plot, &name, d, mode_color(rank), Look::Dashed);
                }
            }
        });
}
