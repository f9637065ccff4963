//! A rubber stage's catalogue rating (issue 16, [`torsim::model::rating`]) in the editor:
//! on or off, T_KN, and each optional limit (T_Kmax, T_KW, P_KV) on or off with its
//! value, the ambient and the rubber's permissible temperature. A value that breaks a
//! rule (T_Kmax below T_KN, say) is marked at its field like every other.

use crate::gui::views::editor::fields::{EditCtx, end_row};
use crate::gui::views::editor::widgets;
use egui::Ui;
use torsim::model::CouplingRating;

/// The rating's rows in its connection's grid; `key` is the connection's key path.
pub fn rating_ui(
    ui: &mut Ui,
    cx: &mut EditCtx,
    key: &str,
    name: &str,
    rating: &mut Option<CouplingRating>,
) {
    let k = |sub: &str| format!("{key}.rating.{sub}");
    let mut on = rating.is_some();
    let r = ui
        .checkbox(&mut on, "catalogue rating")
        .on_hover_text("DIN 740-2: T_KN, T_Kmax, T_KW, P_KV, checked in the Forced response tab");
    cx.track(&r);
    if on != rating.is_some() {
        // A start: rated for twice the model's stiffness scale is unknown here, so round
        // catalogue-like numbers the user replaces.
        *rating = on.then_some(CouplingRating {
            rated_torque_nm: 1000.0,
            max_torque_nm: Some(2500.0),
            permissible_vibratory_torque_nm: Some(400.0),
            permissible_power_loss_w: Some(150.0),
            ambient_c: 30.0,
            permissible_temperature_c: 80.0,
        });
    }
    ui.label("");
    end_row(ui, cx);
    let Some(rt) = rating else { return };
    ui.label("   T_KN rated torque");
    widgets::number(
        ui,
        cx,
        &k("rated_torque_nm"),
        &format!("T_KN {name}"),
        &mut rt.rated_torque_nm,
        "N·m",
        100.0,
    );
    end_row(ui, cx);
    let fallback = rt.rated_torque_nm;
    for (label, sub, value, unit, start) in [
        (
            "   T_Kmax",
            "max_torque_nm",
            &mut rt.max_torque_nm,
            "N·m",
            2.5 * fallback,
        ),
        (
            "   T_KW at 10 Hz",
            "permissible_vibratory_torque_nm",
            &mut rt.permissible_vibratory_torque_nm,
            "N·m",
            0.4 * fallback,
        ),
        (
            "   P_KV at 30 °C",
            "permissible_power_loss_w",
            &mut rt.permissible_power_loss_w,
            "W",
            150.0,
        ),
    ] {
        let mut given = value.is_some();
        let r = ui.checkbox(&mut given, label);
        cx.track(&r);
        if given != value.is_some() {
            *value = given.then_some(start);
        }
        match value {
            Some(v) => {
                widgets::number(ui, cx, &k(sub), &format!("{sub} {name}"), v, unit, start);
            }
            None => {
                ui.weak("not rated");
            }
        }
        end_row(ui, cx);
    }
    ui.label("   ambient");
    widgets::number(
        ui,
        cx,
        &k("ambient_c"),
        &format!("rating ambient {name}"),
        &mut rt.ambient_c,
        "°C",
        10.0,
    );
    end_row(ui, cx);
    ui.label("   permissible temperature");
    widgets::number(
        ui,
        cx,
        &k("permissible_temperature_c"),
        &format!("rating permissible temperature {name}"),
        &mut rt.permissible_temperature_c,
        "°C",
        10.0,
    );
    end_row(ui, cx);
}
