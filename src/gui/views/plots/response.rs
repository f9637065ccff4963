//! Forced response over speed: IAS amplitude per station, torque amplitude per connection
//! or power loss per connection ([`crate::gui::views::plots::quantity`]), with the operating range and the
//! selected crossing marked.

use super::PlotData;
use crate::gui::app::TorsimApp;
use crate::gui::views::plots::quantity::{Quantity, response_series};
use crate::gui::views::plots::series::{Series, grid_125, hover_label, plot_data as series_data};
use crate::gui::views::plots::side_legend::{Entry, with_side_legend};
use egui::{Color32, Ui};
use egui_plot::{Plot, PlotBounds, Span, VLine};
use torsim::model::ConnectionKind;
use torsim::response::Response;

/// The node or response entry the tab shows, and its name.
fn target(app: &TorsimApp, r: &Response) -> (usize, String) {
    let model = &app.model;
    match app.plots.quantity {
        Quantity::Ias => {
            let wanted = app.plots.station.as_deref();
            let k = wanted
                .and_then(|w| model.inertias.iter().position(|n| n.name == w))
                .filter(|&k| k < r.ias_amplitude_rpm.len())
                .unwrap_or(0);
            (k, model.inertias.get(k).map_or("", |n| &n.name).to_string())
        }
        Quantity::Torque | Quantity::PowerLoss => {
            let name = |c: usize| model.connections.get(c).map_or("", |x| &x.name);
            let is_rubber = |c: usize| {
                model
                    .connections
                    .get(c)
                    .is_some_and(|x| matches!(x.kind, ConnectionKind::Rubber(_)))
            };
            let k = app
                .plots
                .connection
                .as_deref()
                .and_then(|w| r.connections.iter().position(|&c| name(c) == w))
                .or_else(|| r.connections.iter().position(|&c| is_rubber(c)))
                .unwrap_or(0);
            (k, r.connections.get(k).map_or("", |&c| name(c)).to_string())
        }
    }
}

/// The series on screen and their title.
fn current(app: &TorsimApp) -> Option<(String, Vec<Series>)> {
    let r = app.results.response.as_ref()?;
    let (index, name) = target(app, r);
    let quantity = app.plots.quantity;
    let mean = match quantity {
        Quantity::Torque => app.results.campbell.as_ref().and_then(|c| {
            let connection = *r.connections.get(index)?;
            c.system.mean_torque_nm.get(connection).copied().flatten()
        }),
        _ => None,
    };
    let title = format!(
        "{} at {name}",
        quantity
            .label()
            .replace(" per station", "")
            .replace(" per connection", "")
    );
    let mut series = response_series(r, quantity, index, mean);
    if let Some(&connection) = r.connections.get(index)
        && quantity != Quantity::Ias
    {
        series.extend(crate::gui::views::plots::limits::limit_series(
            app, quantity, connection,
        ));
    }
    Some((title, series))
}

/// The forced-response data on screen, for export.
pub fn plot_data(app: &TorsimApp) -> Option<PlotData> {
    let (title, series) = current(app)?;
    Some(series_data(
        format!("forced response {title}"),
        "engine speed [rpm]",
        &series,
    ))
}

/// Quantity and station/connection; true when "zoom to the operating range" was clicked.
fn selectors_ui(app: &mut TorsimApp, r: &Response, ui: &mut Ui) -> bool {
    ui.horizontal_wrapped(|ui| {
        let state = &mut app.plots;
        egui::ComboBox::from_label("quantity")
            .selected_text(state.quantity.label())
            .show_ui(ui, |ui| {
                for q in [Quantity::Ias, Quantity::Torque, Quantity::PowerLoss] {
                    ui.selectable_value(&mut state.quantity, q, q.label());
                }
            });
        let (_, current) = target(app, r);
        let model = &app.model;
        let (label, choices): (&str, Vec<String>) = match app.plots.quantity {
            Quantity::Ias => (
                "station",
                model.inertias.iter().map(|n| n.name.clone()).collect(),
            ),
            _ => (
                "connection",
                r.connections
                    .iter()
                    .filter_map(|&c| model.connections.get(c))
                    .map(|c| format!("{} ({})", c.name, c.kind.kind_str()))
                    .collect(),
            ),
        };
        egui::ComboBox::from_label(label)
            .selected_text(&current)
            .show_ui(ui, |ui| {
                for choice in choices {
                    let name = choice.split(" (").next().unwrap_or("").to_string();
                    if ui.selectable_label(name == current, &choice).clicked() {
                        match app.plots.quantity {
                            Quantity::Ias => app.plots.station = Some(name),
                            _ => app.plots.connection = Some(name),
                        }
                    }
                }
            });
        app.model.operation.operating_range_rpm.is_some()
            && ui
                .button("Zoom to the operating range")
                .on_hover_text("double-click the plot to see the whole sweep again")
                .clicked()
    })
    .inner
}

/// The forced-response tab.
pub fn response_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let Some(r) = app.results.response.clone() else {
        ui.label("computing the forced response…");
        return;
    };
    let zoom = selectors_ui(app, &r, ui);
    crate::gui::views::plots::limits::warnings_ui(app, ui);
    let Some((_, series)) = current(app) else {
        return;
    };
    let quantity = app.plots.quantity;
    let operating = app.model.operation.operating_range_rpm;
    let marker = app.plots.crossing.and_then(|k| super::crossing_at(app, k));
    let entries: Vec<Entry> = series
        .iter()
        .map(|s| Entry {
            name: s.name.clone(),
            color: s.color,
            dashed: s.dashed,
        })
        .collect();
    let epoch = app.plots.model_epoch;
    let height = ui.available_height();
    with_side_legend(ui, "response", &entries, height, |ui, hidden| {
        super::fit_for_model(ui, Plot::new("response"), "response", epoch)
            .x_axis_label("engine speed [rpm]")
            .y_axis_label(quantity.y_label())
            .x_grid_spacer(grid_125)
            .y_grid_spacer(grid_125)
            .x_axis_formatter(super::tick_label)
            .y_axis_formatter(super::tick_label)
            .label_formatter(hover_label("rpm", quantity.unit()))
            .include_y(0.0)
            .show(ui, |plot| {
                if let Some([lo, hi]) = operating {
                    plot.span(
                        Span::new("operating range", lo..=hi)
                            .fill(Color32::from_rgba_unmultiplied(60, 160, 60, 25)),
                    );
                }
                if let Some(x) = marker {
                    plot.vline(
                        VLine::new(
                            format!(
                                "order {} × mode {} at {:.0} rpm",
                                x.order, x.mode, x.speed_rpm
                            ),
                            x.speed_rpm,
                        )
                        .color(Color32::from_rgb(255, 200, 0))
                        .allow_hover(false),
                    );
                }
                for s in series.iter().filter(|s| !hidden.contains(&s.name)) {
                    plot.line(s.line());
                }
                if zoom && let Some([lo, hi]) = operating {
                    let top = series
                        .iter()
                        .flat_map(|s| &s.points)
                        .filter(|p| (lo..=hi).contains(&p[0]))
                        .map(|p| p[1])
                        .fold(0.0, f64::max);
                    plot.set_plot_bounds(PlotBounds::from_min_max(
                        [lo, 0.0],
                        [hi, 1.1 * top.max(1e-9)],
                    ));
                }
            });
    });
}
