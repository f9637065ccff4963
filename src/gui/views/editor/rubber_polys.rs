//! The correction polynomials of a rubber stage (seed 000 eq. 1, 9, 10, 11): switched on
//! with seed 000's coefficients, edited coefficient by coefficient, with an optional
//! validity range outside which the factor is held.

use crate::gui::views::editor::fields::{self, EditCtx, end_row};
use crate::gui::views::editor::widgets;
use egui::Ui;
use torsim::model::Poly;

/// One correction polynomial: file key, label, what x is, seed 000's coefficients (used
/// when the user switches it on) and a validity range to start from.
pub struct PolyInfo {
    key: &'static str,
    label: &'static str,
    hint: &'static str,
    seed: [f64; 3],
    range: [f64; 2],
    /// Unit of x.
    unit: &'static str,
}

pub const POLYS: [PolyInfo; 4] = [
    PolyInfo {
        key: "amplitude_poly",
        label: "α_x amplitude",
        hint: "α_x(x) = a2·x² + a1·x + a0, x the element's radial deformation in mm (seed 000 eq. 1; needs elements)",
        seed: [0.0152, 0.0033, 1.0],
        range: [0.0, 10.0],
        unit: "mm",
    },
    PolyInfo {
        key: "frequency_poly",
        label: "α_f frequency",
        hint: "α_f(f), f the vibration frequency in Hz (seed 000 eq. 9, measured 50-300 Hz)",
        seed: [-0.000023, 0.01519, 1.0],
        range: [0.0, 300.0],
        unit: "Hz",
    },
    PolyInfo {
        key: "temperature_stiffness_poly",
        label: "α_Tc temperature",
        hint: "α_Tc(T), stiffness factor, T in °C (seed 000 eq. 10, measured 25-55 °C)",
        seed: [0.000187, -0.02565, 1.530],
        range: [25.0, 55.0],
        unit: "°C",
    },
    PolyInfo {
        key: "temperature_damping_poly",
        label: "α_Tξ temperature",
        hint: "α_Tξ(T), damping factor, T in °C (seed 000 eq. 11, measured 25-55 °C)",
        seed: [0.000063, -0.01275, 1.281],
        range: [25.0, 55.0],
        unit: "°C",
    },
];

/// One polynomial's rows: on/off, its coefficients, its validity range.
pub fn poly_ui(
    ui: &mut Ui,
    cx: &mut EditCtx,
    key: &str,
    name: &str,
    info: &PolyInfo,
    poly: &mut Option<Poly>,
) {
    let pkey = format!("{key}.{}", info.key);
    let whole = cx.error_at(&pkey);
    let mut on = poly.is_some();
    let label = match &whole {
        Some(_) => egui::RichText::new(info.label).color(fields::error_color(ui)),
        None => egui::RichText::new(info.label),
    };
    let r = ui.checkbox(&mut on, label).on_hover_text(info.hint);
    cx.track(&r);
    if let Some(m) = whole {
        r.on_hover_text(m.clone());
        cx.row_message = Some(m);
        if !cx.shown.contains(&pkey) {
            cx.shown.push(pkey.clone());
        }
    }
    if on != poly.is_some() {
        *poly = on.then_some(Poly {
            coeffs: info.seed,
            range: None,
        });
    }
    ui.horizontal(|ui| match poly {
        Some(p) => {
            for (i, (c, a)) in p.coeffs.iter_mut().zip(["a2", "a1", "a0"]).enumerate() {
                widgets::number(
                    ui,
                    cx,
                    &format!("{pkey}[{i}]"),
                    &format!("{} {a} {name}", info.key),
                    c,
                    "",
                    0.01,
                );
            }
        }
        None => {
            ui.weak("off (factor 1)");
        }
    });
    end_row(ui, cx);
    let Some(p) = poly else { return };
    ui.label("   valid over");
    ui.horizontal(|ui| {
        let mut limited = p.range.is_some();
        let r = ui
            .checkbox(&mut limited, "")
            .on_hover_text("outside the range the factor is held at the end value");
        cx.track(&r);
        if limited != p.range.is_some() {
            p.range = limited.then_some(info.range);
        }
        match &mut p.range {
            Some([lo, hi]) => {
                let rkey = format!("{pkey}_range");
                widgets::number(
                    ui,
                    cx,
                    &rkey,
                    &format!("{} from {name}", info.key),
                    lo,
                    info.unit,
                    1.0,
                );
                ui.label("to");
                widgets::number(
                    ui,
                    cx,
                    &rkey,
                    &format!("{} to {name}", info.key),
                    hi,
                    info.unit,
                    1.0,
                );
            }
            None => {
                ui.weak("any x");
            }
        }
    });
    end_row(ui, cx);
}
