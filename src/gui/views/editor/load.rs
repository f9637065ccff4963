//! The load (`[load]`): the node that holds the mean speed and its extra damping.

use super::element_frame;
use crate::gui::views::editor::fields::{EditCtx, end_row};
use crate::gui::views::editor::widgets;
use crate::gui::views::schematic::Selection;
use egui::Ui;
use torsim::model::{Load, Model};

/// The Load section.
pub fn load_ui(ui: &mut Ui, cx: &mut EditCtx, model: &mut Model) {
    let last = model
        .inertias
        .last()
        .map(|n| n.name.clone())
        .unwrap_or_default();
    let Some(load) = &mut model.load else {
        ui.weak(if model.is_grounded() {
            "no [load]: the connection to ground holds the mean torque"
        } else {
            "no [load]: the last node holds the mean speed"
        });
        if ui.button("+ load").clicked() {
            model.load = Some(Load {
                at: None,
                damping_nm_s_per_rad: 0.0,
            });
            cx.select = Some(Some(Selection::Load));
        }
        return;
    };
    let selected = cx.is_selected(Selection::Load);
    cx.begin_element();
    let (remove, revealed) = element_frame(ui, selected, cx.reveal, |ui| {
        egui::Grid::new("load").num_columns(2).spacing([8.0, 3.0]).show(ui, |ui| {
            ui.label("at").on_hover_text("the node that takes the mean torque");
            ui.horizontal(|ui| {
                let mut last_node = load.at.is_none();
                let r = ui.checkbox(&mut last_node, format!("last node ({last})"));
                cx.track(&r);
                if r.changed() {
                    load.at = (!last_node).then(|| last.clone());
                }
                if let Some(at) = &mut load.at {
                    widgets::node_combo(ui, cx, "load.at", "load at", at, false);
                }
            });
            end_row(ui, cx);
            ui.label("damping").on_hover_text("extra damping on vibration of that node (e.g. a generator's electrical damping)");
            widgets::number(ui, cx, "load.damping", "load damping", &mut load.damping_nm_s_per_rad, "N·m·s/rad", 1.0);
            end_row(ui, cx);
        });
        ui.button("remove load").clicked()
    });
    cx.revealed |= revealed;
    cx.end_element(Selection::Load);
    if remove {
        model.load = None;
        cx.select = Some(None);
    }
}
