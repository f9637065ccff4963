//! The engine's working cycle in the engine editor (issue 16, the teacher's question):
//! cylinder 1's pressure and the gas torque of one cylinder and of the engine over the
//! cycle, and the engine torque's amplitude per order, at full load. Computed on the
//! simulation thread ([`torsim::physics::engine_cycle`]).

use crate::gui::views::plots::{fmt, nice_grid, nice_x_grid, tick_label};
use egui::{Color32, Ui};
use egui_plot::{Bar, BarChart, Line, Plot, PlotPoints};
use torsim::physics::engine_cycle::EngineCycle;

/// Height of each small plot, points.
const HEIGHT: f32 = 150.0;

fn line(name: &str, x: &[f64], y: &[f64], color: Color32) -> Line<'static> {
    let points: PlotPoints = x.iter().zip(y).map(|(&a, &b)| [a, b]).collect();
    Line::new(name.to_string(), points).color(color).width(1.5)
}

/// Crank-angle marks every 30°, 90° and 180° (labelled), as engine diagrams are drawn.
fn crank_grid() -> impl Fn(egui_plot::GridInput) -> Vec<egui_plot::GridMark> {
    egui_plot::uniform_grid_spacer(|_| [30.0, 90.0, 180.0])
}

/// The three plots, collapsed under "cycle at full load" (open by default).
pub fn cycle_ui(ui: &mut Ui, cycle: Option<&EngineCycle>) {
    egui::CollapsingHeader::new("cycle at full load: pressure, torque, orders")
        .id_salt("engine cycle")
        .default_open(true)
        .show(ui, |ui| {
            let Some(c) = cycle else {
                ui.weak("computing…");
                return;
            };
            ui.weak(format!(
                "gas torque only (the oscillating masses add a part growing with speed²); \
                 mean {} N·m",
                fmt(c.mean_torque_nm)
            ));
            Plot::new("engine pressure")
                .height(HEIGHT)
                .x_axis_label("crank angle from cylinder 1's firing TDC [°]")
                .y_axis_label("pressure [bar]")
                .x_grid_spacer(crank_grid())
                .y_grid_spacer(nice_grid())
                .x_axis_formatter(tick_label)
                .y_axis_formatter(tick_label)
                .allow_scroll(false)
                .show(ui, |plot| {
                    plot.line(line(
                        "cylinder 1",
                        &c.angle_deg,
                        &c.pressure_bar,
                        Color32::from_rgb(77, 139, 245),
                    ));
                });
            // The key above the plot: the editor's panel is too narrow for a legend beside
            // it, and one on it covers the curves (issue 16).
            ui.horizontal(|ui| {
                let key = |text: &str, colour| egui::RichText::new(text).small().color(colour);
                ui.label(key("— engine", Color32::from_rgb(255, 150, 40)));
                ui.label(key("— one cylinder", Color32::from_gray(150)));
            });
            Plot::new("engine torque")
                .height(HEIGHT)
                .x_axis_label("crank angle [°]")
                .y_axis_label("gas torque [N·m]")
                .x_grid_spacer(crank_grid())
                .y_grid_spacer(nice_grid())
                .x_axis_formatter(tick_label)
                .y_axis_formatter(tick_label)
                .allow_scroll(false)
                .show(ui, |plot| {
                    plot.line(line(
                        "one cylinder",
                        &c.angle_deg,
                        &c.cylinder_torque_nm,
                        Color32::from_gray(150),
                    ));
                    plot.line(line(
                        "engine",
                        &c.angle_deg,
                        &c.engine_torque_nm,
                        Color32::from_rgb(255, 150, 40),
                    ));
                });
            let bars: Vec<Bar> = c
                .orders
                .iter()
                .zip(&c.order_amplitude_nm)
                .map(|(&q, &a)| Bar::new(q, a).width(0.35).name(format!("order {q}")))
                .collect();
            Plot::new("engine orders")
                .height(HEIGHT)
                .x_axis_label("engine order")
                .y_axis_label("amplitude [N·m]")
                .x_grid_spacer(nice_x_grid())
                .y_grid_spacer(nice_grid())
                .x_axis_formatter(tick_label)
                .y_axis_formatter(tick_label)
                .include_y(0.0)
                .allow_scroll(false)
                .show(ui, |plot| {
                    plot.bar_chart(
                        BarChart::new("engine torque by order", bars)
                            .color(Color32::from_rgb(255, 200, 0)),
                    );
                });
        });
}
