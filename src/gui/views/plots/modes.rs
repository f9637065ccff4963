//! Mode shapes along the driveline, where each mode keeps its strain energy, and the
//! animated view of the selected mode.

use super::{PlotData, mode_color};
use crate::gui::app::TorsimApp;
use crate::gui::views::plots::series::fmt;
use egui::Ui;
use egui_plot::{GridMark, HLine, HoverPosition, Line, Plot, PlotPoint, PlotPoints, Points, Text};
use std::collections::VecDeque;
use torsim::modal::{Campbell, DampedMode, shares_by_connection};
use torsim::physics::System;

/// Nodes in driveline order: from one end of the longest path through the springs (the
/// end nearer the reference node, so the engine comes first) depth-first, branches in
/// element order; nodes on one DOF (rigid gears) together; unconnected ones last.
pub fn driveline_order(system: &System) -> Vec<usize> {
    let n = system.dof_count();
    let mut neighbours = vec![Vec::new(); n];
    for e in &system.elements {
        if let (Some(a), Some(b)) = (e.from_dof, e.to_dof) {
            neighbours[a].push(b);
            neighbours[b].push(a);
        }
    }
    let farthest = |start: usize| {
        let mut dist = vec![usize::MAX; n];
        let mut queue = VecDeque::from([start]);
        dist[start] = 0;
        let mut last = start;
        while let Some(d) = queue.pop_front() {
            last = d;
            for &m in &neighbours[d] {
                if dist[m] == usize::MAX {
                    dist[m] = dist[d] + 1;
                    queue.push_back(m);
                }
            }
        }
        last
    };
    let reference = system.dof_of_node.get(system.reference_node).copied();
    let mut dofs = Vec::with_capacity(n);
    let mut seen = vec![false; n];
    let starts = reference.into_iter().chain(0..n);
    for start in starts {
        if start >= n || seen[start] {
            continue;
        }
        // Double sweep: the far end from the far end is the near end of a diameter.
        let end = farthest(farthest(start));
        let mut stack = vec![end];
        while let Some(d) = stack.pop() {
            if std::mem::replace(&mut seen[d], true) {
                continue;
            }
            dofs.push(d);
            stack.extend(neighbours[d].iter().rev().filter(|&&m| !seen[m]));
        }
    }
    dofs.iter()
        .flat_map(|&d| (0..system.dof_of_node.len()).filter(move |&k| system.dof_of_node[k] == d))
        .collect()
}

/// Text for mode `i`: undamped and damped frequency, damping ratio.
pub fn mode_text(diagram: &Campbell, damped: &[DampedMode], i: usize) -> String {
    let f = diagram.modes.get(i).map_or(f64::NAN, |m| m.frequency_hz);
    match damped.get(i) {
        Some(d) => format!(
            "mode {}: {f:.2} Hz (damped {:.2} Hz), ζ = {:.2} %",
            i + 1,
            d.frequency_hz,
            100.0 * d.damping_ratio
        ),
        None => format!("mode {}: {f:.2} Hz", i + 1),
    }
}

/// The connection keeping most of mode `i`'s strain energy: its name and share.
pub fn main_element(system: &System, diagram: &Campbell, i: usize) -> Option<(String, f64)> {
    let shares = diagram.strain_energy_share.get(i)?;
    let (connection, share) = shares_by_connection(system, shares)
        .into_iter()
        .max_by(|a, b| a.1.total_cmp(&b.1))?;
    Some((system.connection_names.get(connection)?.clone(), share))
}

/// The shape of mode `selected` along the driveline (own-shaft rotation, largest 1), the
/// node names under it (staggered so that long names do not overlap). `id` tells plots
/// apart.
pub fn shape_plot(
    ui: &mut Ui,
    (system, diagram): (&System, &Campbell),
    selected: usize,
    id: &str,
    epoch: u64,
) {
    let Some(mode) = diagram.modes.get(selected) else {
        return;
    };
    let order = driveline_order(system);
    let names: Vec<String> = order
        .iter()
        .map(|&k| system.node_names[k].clone())
        .collect();
    let hover_names = names.clone();
    let shape = mode.shape_by_node(system);
    let points: Vec<[f64; 2]> = order
        .iter()
        .enumerate()
        .map(|(x, &k)| [x as f64, shape[k]])
        .collect();
    let name = format!("mode {} · {:.2} Hz", selected + 1, mode.frequency_hz);
    let color = mode_color(selected);
    let label_color = ui.visuals().text_color();
    super::fit_for_model(ui, Plot::new(id), id, epoch)
        .x_axis_label("node, along the driveline")
        .y_axis_label("relative rotation [-] (own shaft)")
        .include_y(-1.35)
        .include_y(1.1)
        .include_x(-0.5)
        .include_x(names.len() as f64 - 0.5)
        .x_grid_spacer(|input| {
            let (lo, hi) = input.bounds;
            (lo.ceil() as i64..=hi.floor() as i64)
                .map(|v| GridMark {
                    value: v as f64,
                    step_size: 1.0,
                })
                .collect()
        })
        .x_axis_formatter(|mark, _| {
            let k = mark.value.round();
            if k >= 0.0 && (mark.value - k).abs() < 1e-6 {
                format!("{}", k + 1.0)
            } else {
                String::new()
            }
        })
        .label_formatter(move |pos| match pos {
            HoverPosition::NearDataPoint {
                plot_name,
                position,
                ..
            } if !plot_name.is_empty() => {
                let node = hover_names.get(position.x.round().max(0.0) as usize)?;
                Some(format!(
                    "{plot_name}\n{node}\n{} (relative)",
                    fmt(position.y)
                ))
            }
            _ => None,
        })
        .show(ui, |plot| {
            plot.hline(
                HLine::new("", 0.0)
                    .color(label_color.gamma_multiply(0.4))
                    .width(1.0),
            );
            let line: PlotPoints = points.iter().copied().collect();
            plot.line(Line::new(name.clone(), line).color(color).width(3.0));
            plot.points(Points::new(name, points).color(color).radius(4.0));
            for (x, n) in names.iter().enumerate() {
                let y = if x.is_multiple_of(2) { -1.13 } else { -1.27 };
                let text = egui::RichText::new(n.as_str()).size(12.0);
                plot.text(
                    Text::new("", PlotPoint::new(x as f64, y), text)
                        .color(label_color)
                        .allow_hover(false),
                );
            }
        });
}

/// The mode shapes on screen, for export: one column per mode over the driveline.
pub fn plot_data(app: &TorsimApp) -> Option<PlotData> {
    let c = app.results.campbell.as_ref()?;
    let crate::gui::session::messages::Modal {
        system,
        campbell: diagram,
        ..
    } = &**c;
    let order = driveline_order(system);
    Some(PlotData {
        title: format!("mode shapes {}", app.model.name),
        x_label: "node index along the driveline".into(),
        x_names: order
            .iter()
            .map(|&k| system.node_names[k].clone())
            .collect(),
        columns: diagram
            .modes
            .iter()
            .enumerate()
            .map(|(i, m)| {
                let shape = m.shape_by_node(system);
                (
                    format!(
                        "mode {} ({:.3} Hz) relative rotation [-]",
                        i + 1,
                        m.frequency_hz
                    ),
                    order
                        .iter()
                        .enumerate()
                        .map(|(x, &k)| [x as f64, shape[k]])
                        .collect(),
                )
            })
            .collect(),
    })
}

/// Share of the mode's strain energy per connection, largest highlighted.
fn energy_table_ui(ui: &mut Ui, system: &System, shares: &[f64]) {
    let shares = shares_by_connection(system, shares);
    let largest = shares.iter().map(|s| s.1).fold(0.0, f64::max);
    // The bars share the column with the names: at most 180 points, less in a narrow
    // window (issue 16: at 800 px they ran past its edge).
    let bar_width = (0.4 * ui.available_width()).clamp(40.0, 180.0);
    egui::Grid::new("strain_energy")
        .num_columns(2)
        .striped(true)
        .show(ui, |ui| {
            ui.strong("connection");
            ui.strong("share");
            ui.end_row();
            for (connection, share) in shares {
                let name = system
                    .connection_names
                    .get(connection)
                    .map_or("", String::as_str);
                if share == largest {
                    ui.strong(name);
                } else {
                    ui.label(name);
                }
                ui.add(
                    egui::ProgressBar::new(share as f32)
                        .desired_width(bar_width)
                        .text(format!("{:.1} %", 100.0 * share)),
                );
                ui.end_row();
            }
        });
}

/// The mode-shape tab: mode selector, frequency, damping and strain energy, the shapes
/// along the driveline and the animated view.
pub fn modes_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let Some(c) = app.results.campbell.clone() else {
        ui.label("computing modes…");
        return;
    };
    let crate::gui::session::messages::Modal {
        system,
        campbell: diagram,
        damped,
    } = &*c;
    if diagram.modes.is_empty() {
        ui.label("no flexible modes");
        return;
    }
    app.selected_mode = app.selected_mode.min(diagram.modes.len() - 1);
    ui.horizontal_wrapped(|ui| {
        for (i, m) in diagram.modes.iter().enumerate() {
            let text = egui::RichText::new(format!("mode {} · {:.1} Hz", i + 1, m.frequency_hz))
                .color(mode_color(i));
            ui.selectable_value(&mut app.selected_mode, i, text);
        }
    });
    let i = app.selected_mode;
    let energy = main_element(system, diagram, i).map_or(String::new(), |(name, share)| {
        format!("; strain energy mostly in {name} ({:.0} %)", 100.0 * share)
    });
    ui.strong(format!("{}{energy}", mode_text(diagram, damped, i)));
    let shares = diagram
        .strain_energy_share
        .get(i)
        .cloned()
        .unwrap_or_default();
    let inertias: Option<Vec<f64>> = (app.model.inertias.len() == system.node_names.len()
        && app
            .model
            .inertias
            .iter()
            .zip(&system.node_names)
            .all(|(n, s)| &n.name == s))
    .then(|| app.model.inertias.iter().map(|n| n.inertia_kg_m2).collect());
    let height = ui.available_height();
    ui.allocate_ui(egui::vec2(ui.available_width(), 0.5 * height), |ui| {
        ui.columns(2, |cols| {
            shape_plot(
                &mut cols[0],
                (system, diagram),
                i,
                "modes",
                app.plots.model_epoch,
            );
            egui::ScrollArea::vertical()
                .id_salt("energy_scroll")
                .show(&mut cols[1], |ui| energy_table_ui(ui, system, &shares));
        });
    });
    ui.separator();
    crate::gui::views::plots::animation::animation_ui(
        &mut app.plots,
        ui,
        system,
        &diagram.modes[i],
        &shares,
        inertias.as_deref(),
        mode_color(i),
    );
}
