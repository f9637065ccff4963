//! Operation (`[operation]`): sweep and operating speed ranges, the orders to draw and sum
//! (an editable list), and the named steady regimes (label, speed, engine load).

use crate::gui::views::editor::fields::{self, EditCtx, end_row};
use crate::gui::views::editor::widgets;
use egui::Ui;
use torsim::model::{Model, Regime, default_orders};

/// The Operation section.
pub fn operation_ui(ui: &mut Ui, cx: &mut EditCtx, model: &mut Model) {
    let strokes = model.strokes();
    let op = &mut model.operation;
    egui::Grid::new("operation ranges")
        .num_columns(2)
        .spacing([8.0, 3.0])
        .show(ui, |ui| {
            for (label, key, range, default) in [
                (
                    "speed sweep",
                    "operation.speed_range_rpm",
                    &mut op.speed_range_rpm,
                    [0.0, 3000.0],
                ),
                (
                    "operating range",
                    "operation.operating_range_rpm",
                    &mut op.operating_range_rpm,
                    [1000.0, 2000.0],
                ),
            ] {
                ui.label(label);
                ui.horizontal(|ui| {
                    let mut on = range.is_some();
                    let r = ui.checkbox(&mut on, "");
                    cx.track(&r);
                    if r.changed() {
                        *range = on.then_some(default);
                    }
                    match range {
                        Some([lo, hi]) => {
                            widgets::number(
                                ui,
                                cx,
                                key,
                                &format!("{label} from"),
                                lo,
                                "rpm",
                                100.0,
                            );
                            ui.label("to");
                            widgets::number(ui, cx, key, &format!("{label} to"), hi, "rpm", 100.0);
                        }
                        None => {
                            ui.weak("not set");
                        }
                    }
                });
                end_row(ui, cx);
            }
        });
    ui.separator();
    orders_ui(ui, cx, &mut op.orders, strokes);
    ui.separator();
    regimes_ui(ui, cx, &mut op.regimes);
}

fn orders_ui(ui: &mut Ui, cx: &mut EditCtx, orders: &mut Option<Vec<f64>>, strokes: u32) {
    let mut custom = orders.is_some();
    let r = ui
        .checkbox(&mut custom, "own list of orders")
        .on_hover_text("orders to draw and sum; otherwise every multiple of 0.5 (4-stroke) or 1 (2-stroke) up to 12");
    cx.track(&r);
    if r.changed() {
        *orders = custom.then(|| default_orders(strokes, 12.0));
    }
    let Some(list) = orders else {
        ui.weak(format!(
            "orders: every {} up to 12",
            if strokes == 2 { "1" } else { "0.5" }
        ));
        return;
    };
    ui.horizontal(|ui| {
        ui.label("orders");
        let width = ui.available_width() - 8.0;
        widgets::list_field(ui, cx, "operation.orders", "operation orders", list, width)
            .on_hover_text("numbers separated by commas, applied when you leave the field");
    });
    fields::note(ui, cx);
}

fn regimes_ui(ui: &mut Ui, cx: &mut EditCtx, regimes: &mut Vec<Regime>) {
    ui.label("Regimes (steady operating points for torsim compare)");
    let mut remove = None;
    if !regimes.is_empty() {
        egui::Grid::new("regimes")
            .num_columns(4)
            .spacing([6.0, 3.0])
            .show(ui, |ui| {
                for title in ["label", "speed", "engine load", ""] {
                    ui.label(title);
                }
                ui.end_row();
                for (i, r) in regimes.iter_mut().enumerate() {
                    let key = format!("operation.regimes[{i}]");
                    let t = ui.add(egui::TextEdit::singleline(&mut r.label).desired_width(48.0));
                    cx.track(&t);
                    let name = format!("regime {}", r.label);
                    widgets::number(
                        ui,
                        cx,
                        &format!("{key}.speed_rpm"),
                        &format!("{name} speed"),
                        &mut r.speed_rpm,
                        "rpm",
                        100.0,
                    );
                    widgets::number(
                        ui,
                        cx,
                        &format!("{key}.load"),
                        &format!("{name} load"),
                        &mut r.load,
                        "",
                        0.1,
                    )
                    .on_hover_text("engine load 0 … 1");
                    if ui
                        .small_button("×")
                        .on_hover_text("remove this regime")
                        .clicked()
                    {
                        remove = Some(i);
                    }
                    end_row(ui, cx);
                }
            });
    }
    if let Some(i) = remove {
        regimes.remove(i);
    }
    if ui.small_button("+ regime").clicked() {
        let speed_rpm = regimes.last().map_or(1500.0, |r| r.speed_rpm + 500.0);
        let label = char::from(b'A' + (regimes.len() % 26) as u8).to_string();
        regimes.push(Regime {
            label,
            speed_rpm,
            load: 1.0,
        });
    }
}
