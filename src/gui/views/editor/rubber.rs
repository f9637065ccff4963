//! A rubber coupling stage (seed 000): static stiffness given directly or assembled from
//! its elements (eq. 12), relative damping ψ, temperature, the correction polynomials
//! ([`crate::gui::views::editor::rubber_polys`]), the optional saturating amplitude law
//! ([`torsim::model::amplitude_saturation`]) and the optional self-heating model.

use crate::gui::views::editor::fields::{self, EditCtx, end_row};
use crate::gui::views::editor::rubber_polys::{self, POLYS};
use crate::gui::views::editor::widgets;
use egui::Ui;
use torsim::model::{AmplitudeSaturation, RubberElements, RubberStage, RubberStiffness, Thermal};

/// The rubber stage's rows in its connection's grid.
pub fn rubber_ui(ui: &mut Ui, cx: &mut EditCtx, key: &str, name: &str, r: &mut RubberStage) {
    let k = |sub: &str| format!("{key}.{sub}");
    ui.label("stiffness from");
    ui.horizontal(|ui| {
        let mut by_elements = matches!(r.stiffness, RubberStiffness::Elements(_));
        let a = ui.radio_value(&mut by_elements, false, "value");
        let b = ui.radio_value(&mut by_elements, true, "elements");
        cx.track(&a);
        cx.track(&b);
        if a.changed() || b.changed() {
            r.stiffness = converted(&r.stiffness, by_elements);
        }
    });
    end_row(ui, cx);
    match &mut r.stiffness {
        RubberStiffness::Direct(s) => {
            ui.label("static stiffness").on_hover_text("at 25 °C");
            widgets::number(
                ui,
                cx,
                &k("stiffness"),
                &format!("stiffness {name}"),
                s,
                "N·m/rad",
                1e3,
            );
            end_row(ui, cx);
        }
        RubberStiffness::Elements(e) => {
            ui.label("elements");
            widgets::count(
                ui,
                cx,
                &k("elements.count"),
                &format!("elements {name}"),
                &mut e.count,
            );
            end_row(ui, cx);
            ui.label("per side");
            widgets::count(
                ui,
                cx,
                &k("elements.per_side"),
                &format!("elements per side {name}"),
                &mut e.per_side,
            );
            end_row(ui, cx);
            ui.label("pitch diameter");
            widgets::number(
                ui,
                cx,
                &k("elements.pitch_diameter"),
                &format!("pitch diameter {name}"),
                &mut e.pitch_diameter_m,
                "m",
                0.1,
            );
            end_row(ui, cx);
            ui.label("radial stiffness")
                .on_hover_text("c_R0 of one unloaded element");
            widgets::number(
                ui,
                cx,
                &k("elements.radial_stiffness"),
                &format!("element radial stiffness {name}"),
                &mut e.radial_stiffness_n_per_m,
                "N/m",
                1e5,
            );
            end_row(ui, cx);
            ui.label("");
            ui.weak(format!(
                "= {} N·m/rad static at 25 °C (eq. 12)",
                fields::format_sig(e.torsional_stiffness_nm_per_rad(), 4)
            ));
            end_row(ui, cx);
        }
    }
    ui.label("ψ relative damping")
        .on_hover_text("DIN 740; loss factor ξ = ψ/2π");
    ui.horizontal(|ui| {
        widgets::number(
            ui,
            cx,
            &k("psi"),
            &format!("psi {name}"),
            &mut r.psi,
            "",
            0.1,
        );
        ui.weak(format!(
            "ξ = {}",
            fields::format_sig(r.psi / std::f64::consts::TAU, 3)
        ));
    });
    end_row(ui, cx);
    ui.label("temperature")
        .on_hover_text("of the rubber; with self-heating, at the start");
    widgets::number(
        ui,
        cx,
        &k("temperature_c"),
        &format!("temperature {name}"),
        &mut r.temperature_c,
        "°C",
        10.0,
    );
    end_row(ui, cx);
    let polys = [
        &mut r.amplitude_poly,
        &mut r.frequency_poly,
        &mut r.temperature_stiffness_poly,
        &mut r.temperature_damping_poly,
    ];
    for (i, (info, poly)) in POLYS.iter().zip(polys).enumerate() {
        rubber_polys::poly_ui(ui, cx, key, name, info, poly);
        // The other amplitude law, beside the first.
        if i == 0 {
            saturation_ui(ui, cx, key, name, &mut r.amplitude_saturation);
        }
    }
    thermal_ui(ui, cx, key, name, &mut r.thermal);
    crate::gui::views::editor::rating::rating_ui(ui, cx, key, name, &mut r.rating);
}

/// The other way of giving the same static stiffness: elements (8, 4 per side, 0.2 m
/// pitch, radial stiffness solved from eq. 12) or the value they give.
fn converted(s: &RubberStiffness, by_elements: bool) -> RubberStiffness {
    match (s, by_elements) {
        (RubberStiffness::Direct(k), true) => {
            let (count, per_side, d) = (8u32, 4u32, 0.2);
            let geometry =
                (d / 2.0) * (d / 2.0) * f64::from(per_side * (count - per_side)) / f64::from(count);
            RubberStiffness::Elements(RubberElements {
                count,
                per_side,
                pitch_diameter_m: d,
                radial_stiffness_n_per_m: k / geometry,
            })
        }
        (RubberStiffness::Elements(e), false) => {
            RubberStiffness::Direct(e.torsional_stiffness_nm_per_rad())
        }
        _ => s.clone(),
    }
}

/// A number row of an optional table: label, field key, value, unit, typical step.
type Row<'a> = (&'static str, &'static str, &'a mut f64, &'static str, f64);

/// One optional table of a stage (`thermal`, `amplitude_saturation`) under `key`: a
/// checkbox `label` that adds it at `start` or removes it, and a number row per field of
/// `rows` while it is there.
#[allow(clippy::too_many_arguments)]
fn optional_ui<T>(
    ui: &mut Ui,
    cx: &mut EditCtx,
    key: &str,
    name: &str,
    (label, hover): (&str, &str),
    value: &mut Option<T>,
    start: impl FnOnce() -> T,
    rows: impl FnOnce(&mut T) -> Vec<Row<'_>>,
) {
    let mut on = value.is_some();
    let r = ui.checkbox(&mut on, label).on_hover_text(hover);
    cx.track(&r);
    if on != value.is_some() {
        *value = on.then(start);
    }
    // An error of the whole table (`amplitude_saturation` beside `amplitude_poly`).
    if cx.error_at(key).is_some() {
        fields::message_at(ui, cx, key);
    } else {
        ui.label("");
    }
    end_row(ui, cx);
    let Some(v) = value else { return };
    for (label, sub, value, unit, typical) in rows(v) {
        ui.label(label);
        let k = format!("{key}.{sub}");
        widgets::number(ui, cx, &k, &format!("{sub} {name}"), value, unit, typical);
        end_row(ui, cx);
    }
}

fn thermal_ui(ui: &mut Ui, cx: &mut EditCtx, key: &str, name: &str, thermal: &mut Option<Thermal>) {
    let label = (
        "self-heating",
        "time domain: the rubber warms by its own power loss and cools to ambient",
    );
    // A start: about 2 kg of rubber (1.7 kJ/(kg·K)) losing 10 W per kelvin, in 25 °C air.
    let start = || Thermal {
        capacity_j_per_k: 3400.0,
        conductance_w_per_k: 10.0,
        ambient_c: 25.0,
    };
    let key = format!("{key}.thermal");
    optional_ui(ui, cx, &key, name, label, thermal, start, |t| {
        vec![
            (
                "   heat capacity",
                "capacity_j_per_k",
                &mut t.capacity_j_per_k,
                "J/K",
                1000.0,
            ),
            (
                "   conductance",
                "conductance_w_per_k",
                &mut t.conductance_w_per_k,
                "W/K",
                1.0,
            ),
            ("   ambient", "ambient_c", &mut t.ambient_c, "°C", 10.0),
        ]
    });
}

/// `amplitude_saturation`: α_x = 1 + s·tanh((x/x_s)²), in place of `amplitude_poly`
/// (the model check says so when both are given, or the stage has no elements).
fn saturation_ui(
    ui: &mut Ui,
    cx: &mut EditCtx,
    key: &str,
    name: &str,
    law: &mut Option<AmplitudeSaturation>,
) {
    let label = (
        "saturating stiffening",
        "α_x = 1 + s·tanh((x/x_s)²), x the element deformation in mm: a progressive \
         coupling whose stiffening levels off once its elements bear on their housing",
    );
    // A start: 30 % stiffer once saturated, over 1 mm of element deformation.
    let start = || AmplitudeSaturation {
        stiffening: 0.3,
        deformation_mm: 1.0,
    };
    let key = format!("{key}.amplitude_saturation");
    optional_ui(ui, cx, &key, name, label, law, start, |s| {
        vec![
            ("   stiffening s", "stiffening", &mut s.stiffening, "", 0.1),
            (
                "   over deformation x_s",
                "deformation_mm",
                &mut s.deformation_mm,
                "mm",
                0.1,
            ),
        ]
    });
}
