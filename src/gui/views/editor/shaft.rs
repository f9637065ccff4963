//! A shaft's values: stiffness, damping, and its own distributed inertia with the segments
//! the time domain divides it into (automatic, or a number the user sets).

use crate::gui::views::editor::fields::{EditCtx, end_row};
use crate::gui::views::editor::widgets;
use egui::Ui;
use torsim::model::Shaft;

/// Segments offered when the user turns automatic off: what a short shaft needs.
const FIRST_SEGMENTS: u32 = 8;

/// The rows of a shaft in the connection's grid; `key` is `connection[j]`.
pub fn shaft_ui(ui: &mut Ui, cx: &mut EditCtx, key: &str, name: &str, s: &mut Shaft) {
    let k = |sub: &str| format!("{key}.{sub}");
    ui.label("stiffness");
    widgets::number(
        ui,
        cx,
        &k("stiffness"),
        &format!("stiffness {name}"),
        &mut s.stiffness_nm_per_rad,
        "N·m/rad",
        1e4,
    );
    end_row(ui, cx);
    ui.label("damping");
    widgets::number(
        ui,
        cx,
        &k("damping"),
        &format!("damping {name}"),
        &mut s.damping_nm_s_per_rad,
        "N·m·s/rad",
        1.0,
    );
    end_row(ui, cx);
    ui.label("inertia").on_hover_text(
        "the shaft's own polar inertia ρ·I_p·L, distributed along it; 0: massless. \
         Modes and the forced response use the exact element",
    );
    widgets::number(
        ui,
        cx,
        &k("inertia"),
        &format!("inertia {name}"),
        &mut s.inertia_kg_m2,
        "kg·m²",
        0.01,
    );
    end_row(ui, cx);
    if s.inertia_kg_m2 <= 0.0 {
        return;
    }
    ui.label("segments").on_hover_text(
        "lumped segments of the time domain and the mode shapes; automatic: 0.1 % in \
         frequency over the model's band",
    );
    ui.horizontal(|ui| {
        let mut automatic = s.segments.is_none();
        let r = ui.checkbox(&mut automatic, "automatic");
        cx.track(&r);
        if r.changed() {
            s.segments = (!automatic).then_some(FIRST_SEGMENTS);
        }
        if let Some(n) = &mut s.segments {
            widgets::count(ui, cx, &k("segments"), &format!("segments {name}"), n);
        }
    });
    end_row(ui, cx);
}
