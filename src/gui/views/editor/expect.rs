//! Checks (`[expect]`, run by `torsim check`): mode frequency windows, critical speed
//! windows, and the orders that must cross no mode in the operating range.

use crate::gui::views::editor::fields::{self, EditCtx, end_row};
use crate::gui::views::editor::widgets;
use egui::Ui;
use torsim::model::{CriticalExpectation, ModeExpectation, Model};

/// The Checks section.
pub fn expect_ui(ui: &mut Ui, cx: &mut EditCtx, model: &mut Model) {
    let ex = &mut model.expect;
    let mut remove_mode = None;
    let mut remove_critical = None;
    egui::Grid::new("expect")
        .num_columns(4)
        .spacing([6.0, 3.0])
        .show(ui, |ui| {
            if !ex.mode_hz.is_empty() || !ex.critical_rpm.is_empty() {
                for title in ["", "from", "to", ""] {
                    ui.label(title);
                }
                ui.end_row();
            }
            for (i, m) in ex.mode_hz.iter_mut().enumerate() {
                let key = format!("expect.mode_hz[{i}]");
                ui.horizontal(|ui| {
                    ui.label("mode");
                    widgets::count(
                        ui,
                        cx,
                        &format!("{key}.mode"),
                        &format!("expected mode {}", i + 1),
                        &mut m.mode,
                    );
                });
                widgets::number(
                    ui,
                    cx,
                    &format!("{key}.min"),
                    &format!("mode {} min", m.mode),
                    &mut m.min_hz,
                    "Hz",
                    1.0,
                );
                widgets::number(
                    ui,
                    cx,
                    &format!("{key}.max"),
                    &format!("mode {} max", m.mode),
                    &mut m.max_hz,
                    "Hz",
                    1.0,
                );
                if ui.small_button("×").clicked() {
                    remove_mode = Some(i);
                }
                end_row(ui, cx);
            }
            for (i, c) in ex.critical_rpm.iter_mut().enumerate() {
                let key = format!("expect.critical_rpm[{i}]");
                ui.horizontal(|ui| {
                    ui.label("order");
                    widgets::number(
                        ui,
                        cx,
                        &format!("{key}.order"),
                        &format!("critical order {}", i + 1),
                        &mut c.order,
                        "",
                        0.5,
                    );
                });
                widgets::number(
                    ui,
                    cx,
                    &format!("{key}.min"),
                    &format!("critical {} min", i + 1),
                    &mut c.min_rpm,
                    "rpm",
                    10.0,
                );
                widgets::number(
                    ui,
                    cx,
                    &format!("{key}.max"),
                    &format!("critical {} max", i + 1),
                    &mut c.max_rpm,
                    "rpm",
                    10.0,
                );
                if ui.small_button("×").clicked() {
                    remove_critical = Some(i);
                }
                end_row(ui, cx);
            }
        });
    if let Some(i) = remove_mode {
        ex.mode_hz.remove(i);
    }
    if let Some(i) = remove_critical {
        ex.critical_rpm.remove(i);
    }
    ui.horizontal(|ui| {
        if ui
            .small_button("+ mode window")
            .on_hover_text("mode k must lie in [min, max] Hz")
            .clicked()
        {
            let mode = ex.mode_hz.last().map_or(1, |m| m.mode + 1);
            ex.mode_hz.push(ModeExpectation {
                mode,
                min_hz: 0.0,
                max_hz: 100.0,
            });
        }
        if ui
            .small_button("+ critical speed")
            .on_hover_text("the order line crosses some mode in [min, max] rpm")
            .clicked()
        {
            ex.critical_rpm.push(CriticalExpectation {
                order: 1.0,
                min_rpm: 0.0,
                max_rpm: 1000.0,
            });
        }
    });
    ui.label("No resonance in the operating range for orders");
    let key = "expect.no_resonance_in_operating_range";
    let width = ui.available_width() - 8.0;
    let list = &mut ex.no_resonance_in_operating_range;
    widgets::list_field(ui, cx, key, "no resonance orders", list, width)
        .on_hover_text("orders separated by commas, applied when you leave the field");
    fields::note(ui, cx);
}
