//! The selected crossing, below the Campbell diagram: the shape of its mode, and the
//! forced response of its order (IAS amplitude at the station where that order is largest
//! at the crossing speed, or a chosen one) with a marker at the crossing speed.

use crate::gui::app::TorsimApp;
use crate::gui::command::Command;
use crate::gui::session::messages::Modal;
use crate::gui::views::plots::modes::{main_element, mode_text, shape_plot};
use crate::gui::views::plots::series::{Series, grid_125, hover_label};
use egui::{Color32, Ui};
use egui_plot::{Plot, VLine};
use torsim::modal::Crossing;
use torsim::response::Response;

/// The index of the speed grid nearest `speed_rpm`.
fn nearest_speed(speeds: &[f64], speed_rpm: f64) -> usize {
    speeds
        .iter()
        .enumerate()
        .min_by(|a, b| (a.1 - speed_rpm).abs().total_cmp(&(b.1 - speed_rpm).abs()))
        .map_or(0, |(s, _)| s)
}

/// What the crossing's response plot shows: the order index in `r`, the node, whether the
/// node was picked automatically, and the line.
pub fn crossing_response(
    app: &TorsimApp,
    r: &Response,
    x: &Crossing,
) -> Option<(usize, usize, Series)> {
    let q = r.orders.iter().position(|&o| (o - x.order).abs() < 1e-9)?;
    let s = nearest_speed(&r.speeds_rpm, x.speed_rpm);
    let chosen = app
        .plots
        .crossing_station
        .as_deref()
        .and_then(|w| app.model.inertias.iter().position(|n| n.name == w))
        .filter(|&k| k < r.ias_amplitude_rpm.len());
    let node = chosen.or_else(|| {
        (0..r.ias_amplitude_rpm.len())
            .max_by(|&a, &b| r.ias_amplitude_rpm[a][q][s].total_cmp(&r.ias_amplitude_rpm[b][q][s]))
    })?;
    let name = app.model.inertias.get(node).map_or("", |n| n.name.as_str());
    let points = r
        .speeds_rpm
        .iter()
        .zip(&r.ias_amplitude_rpm[node][q])
        .map(|(&n, &v)| [n, v])
        .collect();
    let series = Series::new(
        format!("order {} at {name}", x.order),
        format!("order {} IAS amplitude at {name} [rpm]", x.order),
        points,
    )
    .color(Color32::from_rgb(255, 200, 0))
    .width(2.0);
    Some((q, node, series))
}

/// A steady time run at `speed_rpm`, shown in the Time traces tab (issue 16: "run at this
/// crossing speed").
pub fn simulate_at(app: &mut TorsimApp, speed_rpm: f64) {
    app.trace_speed_rpm = speed_rpm;
    app.traces.mode = crate::gui::trace_state::TraceMode::Steady;
    app.commands
        .push(Command::ShowTab(crate::gui::app::Tab::Traces));
    app.commands.push(Command::Rerun);
}

/// The shape and response of crossing `x` side by side.
pub fn detail_ui(app: &mut TorsimApp, ui: &mut Ui, c: &Modal, x: Crossing) {
    let Modal {
        system,
        campbell: diagram,
        damped,
    } = c;
    let i = x.mode - 1;
    ui.separator();
    let energy = main_element(system, diagram, i).map_or(String::new(), |(name, share)| {
        format!("; strain energy mostly in {name} ({:.0} %)", 100.0 * share)
    });
    ui.horizontal_wrapped(|ui| {
        ui.strong(format!("{}{energy}", mode_text(diagram, damped, i)));
        if ui
            .button(format!("Simulate at {:.0} rpm", x.speed_rpm))
            .on_hover_text(
                "a steady time run at the crossing speed, in the Time traces tab: the \
                 nonlinear model's answer at this resonance",
            )
            .clicked()
        {
            simulate_at(app, x.speed_rpm);
        }
    });
    ui.columns(2, |cols| {
        shape_plot(
            &mut cols[0],
            (system, diagram),
            i,
            "crossing_shape",
            app.plots.model_epoch,
        );
        let ui = &mut cols[1];
        let Some(r) = app.results.response.clone() else {
            ui.label("computing the forced response…");
            return;
        };
        let Some((_, node, series)) = crossing_response(app, &r, &x) else {
            ui.label(format!("order {} is not in the forced response", x.order));
            return;
        };
        let auto = app.plots.crossing_station.is_none();
        let current = app.model.inertias.get(node).map_or("", |n| n.name.as_str());
        let shown = if auto {
            format!("largest: {current}")
        } else {
            current.to_string()
        };
        let names: Vec<String> = app.model.inertias.iter().map(|n| n.name.clone()).collect();
        egui::ComboBox::from_label("response station")
            .selected_text(shown)
            .show_ui(ui, |ui| {
                ui.selectable_value(&mut app.plots.crossing_station, None, "where largest");
                for name in names {
                    let value = Some(name.clone());
                    ui.selectable_value(&mut app.plots.crossing_station, value, name);
                }
            });
        // Named above the plot, not in a legend on it (issue 16: legends covered data).
        ui.label(egui::RichText::new(&series.name).color(series.color));
        super::fit_for_model(
            ui,
            Plot::new("crossing_response"),
            "crossing_response",
            app.plots.model_epoch,
        )
        .x_axis_label("engine speed [rpm]")
        .y_axis_label("IAS amplitude [rpm] (zero-to-peak)")
        .x_grid_spacer(grid_125)
        .y_grid_spacer(grid_125)
        .x_axis_formatter(super::tick_label)
        .y_axis_formatter(super::tick_label)
        .include_y(0.0)
        .label_formatter(hover_label("rpm", "rpm"))
        .show(ui, |plot| {
            plot.vline(
                VLine::new(format!("crossing {:.0} rpm", x.speed_rpm), x.speed_rpm)
                    .color(Color32::from_gray(200))
                    .allow_hover(false),
            );
            plot.line(series.line());
        });
    });
}
