//! The central panel: Campbell diagram, mode shapes, forced response and time traces,
//! each with hover read-out, legend, units and zoom. A panel whose analysis failed says
//! why in place and keeps its last good plot. One plot per file; what every plot shows
//! can be exported as CSV ([`plot_data`], the "Export CSV…" button of the tab bar).

mod animation;
mod campbell;
pub mod colour_scale;
mod crossing;
mod limits;
mod modes;
mod order_tracks;
mod quantity;
mod recording;
mod response;
mod run_controls;
mod series;
pub mod side_legend;
mod stft;
mod time_series;
pub use time_series::{nice_grid, nice_x_grid};
mod traces;

pub use crate::gui::export::PlotData;
#[cfg(test)]
pub use campbell::CAMPBELL_PLOT_ID;
pub use campbell::crossing_at;
#[cfg(test)]
pub use crossing::crossing_response;
pub use quantity::Quantity;
#[cfg(test)]
pub use quantity::matters;
pub use series::{fmt, grid_125, tick_label};

use crate::gui::app::{Tab, TorsimApp};
use egui::{Color32, Ui};

const MODE_COLORS: [Color32; 10] = [
    Color32::from_rgb(77, 139, 245),
    Color32::from_rgb(235, 80, 70),
    Color32::from_rgb(80, 185, 80),
    Color32::from_rgb(175, 125, 230),
    Color32::from_rgb(255, 150, 40),
    Color32::from_rgb(40, 200, 215),
    Color32::from_rgb(200, 130, 95),
    Color32::from_rgb(240, 130, 200),
    Color32::from_rgb(200, 200, 70),
    Color32::from_rgb(160, 160, 160),
];

/// The colour of mode `i` (0-based), the same in every plot; also used for the `i`-th
/// series of a plot.
pub fn mode_color(i: usize) -> Color32 {
    MODE_COLORS[i % MODE_COLORS.len()]
}

/// A crossing of the Campbell diagram, named by what survives an edit: its order and mode.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CrossingKey {
    /// Engine order.
    pub order: f64,
    /// Mode number, from 1.
    pub mode: usize,
}

/// `plot` fitted to its data (as a double-click does) in the first frame it is drawn
/// for a model opened after the one it last showed (issue 16: the Campbell diagram kept
/// the previous model's speed range); `key` names the plot.
pub fn fit_for_model<'a>(
    ui: &Ui,
    plot: egui_plot::Plot<'a>,
    key: &str,
    epoch: u64,
) -> egui_plot::Plot<'a> {
    let id = egui::Id::unique(("torsim-plot-epoch", key));
    let drawn = ui.data(|d| d.get_temp::<u64>(id));
    ui.data_mut(|d| d.insert_temp(id, epoch));
    match drawn {
        Some(e) if e != epoch => plot.reset(),
        _ => plot,
    }
}

/// What the plots show, kept in the app across edits.
#[derive(Debug, Clone, PartialEq)]
pub struct PlotState {
    /// The crossing selected on the Campbell diagram (kept while the edited model still
    /// has a crossing of that order and mode).
    pub crossing: Option<CrossingKey>,
    /// Station of the selected crossing's forced response; `None`: where that order's
    /// IAS amplitude at the crossing speed is largest.
    pub crossing_station: Option<String>,
    /// Quantity of the forced-response tab.
    pub quantity: Quantity,
    /// Station (node name) of the IAS response.
    pub station: Option<String>,
    /// Connection (name) of the torque and power-loss responses.
    pub connection: Option<String>,
    /// The mode-shape animation runs (default: paused, so an idle window is idle; issue 16).
    pub playing: bool,
    /// Peak rotation drawn for the largest modal amplitude, degrees.
    pub amplitude_deg: f32,
    /// Phase of the animation, cycles (default 0.25: the shape at its largest swing).
    pub phase_cycles: f64,
    /// Counts the models shown in this window: a plot drawn for the first time after
    /// another model was opened fits its data again ([`fit_for_model`]).
    pub model_epoch: u64,
}

impl Default for PlotState {
    fn default() -> Self {
        Self {
            crossing: None,
            crossing_station: None,
            quantity: Quantity::Ias,
            station: None,
            connection: None,
            playing: false,
            amplitude_deg: 40.0,
            phase_cycles: 0.25,
            model_epoch: 0,
        }
    }
}

/// The data the current tab shows, for export (`None` while it has nothing to show).
pub fn plot_data(app: &TorsimApp) -> Option<PlotData> {
    match app.tab {
        Tab::Campbell => campbell::plot_data(app),
        Tab::Modes => modes::plot_data(app),
        Tab::Response => response::plot_data(app),
        Tab::Traces => traces_data(app),
        Tab::Diagnosis => None,
    }
}

/// The time traces as streamed so far: every series of every group (IAS, relative speed,
/// torque, power loss, temperature), each column named with its group, series and unit;
/// a run-up adds the imposed reference speed.
pub fn traces_data(app: &TorsimApp) -> Option<PlotData> {
    let live = app.results.live.as_ref()?;
    let layout = &live.layout;
    let mut columns = Vec::new();
    for ((_, group), samples) in layout.groups.iter().zip(&live.groups) {
        let unit = group
            .axis
            .split_once('[')
            .and_then(|(_, rest)| rest.split_once(']'))
            .map_or("", |(unit, _)| unit);
        for (name, values) in group.names.iter().zip(&samples.values) {
            let points = samples.time_s.iter().zip(values).map(|(&t, &v)| [t, v]);
            columns.push((format!("{} {name} [{unit}]", group.title), points.collect()));
        }
    }
    if columns
        .iter()
        .all(|(_, p): &(String, Vec<[f64; 2]>)| p.is_empty())
    {
        return None;
    }
    if let Some(first) = live.groups.first()
        && layout.kind.is_ramp()
    {
        let points = first.time_s.iter().map(|&t| [t, layout.speed_at(t)]);
        columns.insert(
            0,
            (
                format!("reference speed {} [rpm]", layout.reference),
                points.collect(),
            ),
        );
    }
    Some(PlotData {
        title: layout.label.clone(),
        x_label: "time [s]".into(),
        x_names: Vec::new(),
        columns,
    })
}

/// Tabs, the export button and the selected plot.
pub fn central_ui(app: &mut TorsimApp, ui: &mut Ui) {
    // Wrapped, so that a narrow window puts the tabs on two lines rather than past its
    // edge (issue 16).
    ui.horizontal_wrapped(|ui| {
        for (tab, label) in [
            (Tab::Campbell, "Campbell"),
            (Tab::Modes, "Mode shapes"),
            (Tab::Response, "Forced response"),
            (Tab::Traces, "Time traces"),
            (Tab::Diagnosis, "Diagnosis"),
        ] {
            ui.selectable_value(&mut app.tab, tab, label);
            ui.add(egui::Label::new(egui::RichText::new("?").weak()).sense(egui::Sense::hover()))
                .on_hover_text(crate::gui::views::help::tab_help(tab));
        }
        if app.tab == Tab::Diagnosis {
            return;
        }
        ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
            let available = match app.tab {
                Tab::Campbell | Tab::Modes => app.results.campbell.is_some(),
                Tab::Response => app.results.response.is_some(),
                Tab::Traces => app.results.live.is_some(),
                Tab::Diagnosis => false,
            };
            let button = ui
                .add_enabled(available, egui::Button::new("Export CSV…"))
                .on_hover_text("the data of this plot, one column per series, with units");
            if button.clicked()
                && let Some(data) = plot_data(app)
            {
                crate::gui::export::export_csv(&mut app.exports, ui.ctx(), data);
            }
        });
    });
    ui.separator();
    let panel = match app.tab {
        Tab::Campbell | Tab::Modes => "modes",
        Tab::Response => "response",
        Tab::Traces => "trace",
        Tab::Diagnosis => "diagnosis",
    };
    if let Some(e) = app.error_of(panel) {
        ui.colored_label(ui.visuals().error_fg_color, format!("Failed: {e}"));
    }
    match app.tab {
        Tab::Campbell => campbell::campbell_ui(app, ui),
        Tab::Modes => modes::modes_ui(app, ui),
        Tab::Response => response::response_ui(app, ui),
        Tab::Traces => traces::traces_ui(app, ui),
        Tab::Diagnosis => crate::gui::views::diagnosis::diagnosis_ui(app, ui),
    }
}
