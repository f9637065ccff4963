//! The engine (seed 001 eq. 3–5): nodes it acts on, cylinders, strokes, firing angles,
//! crank-slider dimensions and masses, a read-only summary of the pressure tables; and the
//! prescribed harmonics (node, order, amplitude, phase).

use super::element_frame;
use crate::gui::views::editor::fields::{self, EditCtx, end_row};
use crate::gui::views::editor::widgets;
use crate::gui::views::schematic::Selection;
use egui::Ui;
use torsim::model::{Engine, HarmonicAmplitude, Model, Pressure, PressureCurve};

/// The Engine and harmonics section.
pub fn engine_ui(ui: &mut Ui, cx: &mut EditCtx, model: &mut Model) {
    match &mut model.engine {
        Some(engine) => {
            let selected = cx.is_selected(Selection::Engine);
            cx.begin_element();
            let ((), revealed) =
                element_frame(ui, selected, cx.reveal, |ui| engine_grid_ui(ui, cx, engine));
            cx.revealed |= revealed;
            cx.end_element(Selection::Engine);
        }
        None => {
            ui.weak("no [engine]: excitation by harmonics only");
        }
    }
    harmonics_ui(ui, cx, model);
}

fn engine_grid_ui(ui: &mut Ui, cx: &mut EditCtx, e: &mut Engine) {
    egui::Grid::new("engine")
        .num_columns(2)
        .spacing([8.0, 3.0])
        .show(ui, |ui| {
            ui.label("acts on")
                .on_hover_text("one node for all cylinders, or one crank throw per cylinder");
            let mut per_cylinder = e.at.len() > 1;
            let r = ui.checkbox(&mut per_cylinder, "one node per cylinder");
            cx.track(&r);
            if r.changed() {
                let first = e.at.first().cloned().unwrap_or_default();
                let n = if per_cylinder {
                    e.cylinders.max(1) as usize
                } else {
                    1
                };
                e.at = vec![first; n];
            }
            end_row(ui, cx);
            if e.at.len() == 1 {
                ui.label("");
                widgets::node_combo(ui, cx, "engine.at", "engine at", &mut e.at[0], false);
                end_row(ui, cx);
            } else {
                for (i, at) in e.at.iter_mut().enumerate() {
                    ui.label(format!("   cylinder {}", i + 1));
                    let key = format!("engine.at[{i}]");
                    let access = format!("engine cylinder {} at", i + 1);
                    widgets::node_combo(ui, cx, &key, &access, at, false);
                    end_row(ui, cx);
                }
                ui.label("");
                fields::message_at(ui, cx, "engine.at");
                end_row(ui, cx);
            }
            ui.label("cylinders");
            widgets::count(
                ui,
                cx,
                "engine.cylinders",
                "engine cylinders",
                &mut e.cylinders,
            );
            end_row(ui, cx);
            ui.label("strokes");
            ui.horizontal(|ui| {
                for s in [4, 2] {
                    let r = ui.radio_value(&mut e.strokes, s, format!("{s}-stroke"));
                    cx.track(&r);
                }
                fields::message_at(ui, cx, "engine.strokes");
            });
            end_row(ui, cx);
            ui.label("firing angles")
                .on_hover_text("firing TDC of each cylinder after cylinder 1's, ° crank");
            let mut even = e.firing_angles_deg.is_none();
            let r = ui.checkbox(&mut even, "evenly spaced");
            cx.track(&r);
            if r.changed() {
                e.firing_angles_deg = (!even).then(|| e.firing_angles_or_even_deg());
            }
            end_row(ui, cx);
            ui.label("");
            firing_ui(ui, cx, e);
            end_row(ui, cx);
            let rows: [(&str, &str, &mut f64, &str, f64); 5] = [
                ("bore", "engine.bore", &mut e.bore_m, "m", 0.1),
                (
                    "crank radius",
                    "engine.crank_radius",
                    &mut e.crank_radius_m,
                    "m",
                    0.05,
                ),
                (
                    "conrod length",
                    "engine.conrod_length",
                    &mut e.conrod_length_m,
                    "m",
                    0.2,
                ),
                (
                    "reciprocating mass",
                    "engine.reciprocating_mass",
                    &mut e.reciprocating_mass_kg,
                    "kg",
                    1.0,
                ),
                (
                    "rod inertia J0/l²",
                    "engine.rod_inertia_correction",
                    &mut e.rod_inertia_correction_kg,
                    "kg",
                    0.1,
                ),
            ];
            for (label, key, value, unit, typical) in rows {
                ui.label(label);
                widgets::number(
                    ui,
                    cx,
                    key,
                    &format!("engine {label}"),
                    value,
                    unit,
                    typical,
                );
                end_row(ui, cx);
            }
            ui.label("");
            let swept = std::f64::consts::PI / 4.0
                * e.bore_m
                * e.bore_m
                * 2.0
                * e.crank_radius_m
                * f64::from(e.cylinders);
            ui.weak(format!(
                "stroke {} m, displacement {} l, λ = r/l = {}",
                fields::format_value(2.0 * e.crank_radius_m),
                fields::format_sig(swept * 1000.0, 3),
                fields::format_sig(e.crank_radius_m / e.conrod_length_m, 3)
            ));
            end_row(ui, cx);
            ui.label("pressure")
                .on_hover_text("cylinder gauge pressure tables: edit them in the model file");
            let prefix = match e.pressure {
                Pressure::Single(_) => "engine.pressure",
                Pressure::ByLoad(_) => "engine.pressure_by_load",
            };
            fields::summary(ui, cx, prefix, pressure_summary(&e.pressure));
            end_row(ui, cx);
        });
}

/// The firing angles: editable when given, else the even spacing they default to.
fn firing_ui(ui: &mut Ui, cx: &mut EditCtx, e: &mut Engine) {
    match &mut e.firing_angles_deg {
        Some(angles) => {
            ui.horizontal_wrapped(|ui| {
                for (i, a) in angles.iter_mut().enumerate() {
                    let key = format!("engine.firing_angles_deg[{i}]");
                    let access = format!("firing angle cylinder {}", i + 1);
                    widgets::number(ui, cx, &key, &access, a, "°", 10.0);
                }
                fields::message_at(ui, cx, "engine.firing_angles_deg");
            });
        }
        None => {
            let angles = e.firing_angles_or_even_deg();
            let text: Vec<String> = angles.iter().map(|a| fields::format_value(*a)).collect();
            ui.weak(text.join(", ") + " °");
        }
    }
}

/// One line per curve: points, angle span, peak and where.
fn pressure_summary(p: &Pressure) -> String {
    let curve = |c: &PressureCurve| {
        let peak = c.pressure_bar.iter().zip(&c.crank_angle_deg).fold(
            (f64::NEG_INFINITY, 0.0),
            |best, (&p, &a)| {
                if p > best.0 { (p, a) } else { best }
            },
        );
        format!(
            "{} points, {} … {}°, peak {} bar at {}°",
            c.crank_angle_deg.len(),
            fields::format_value(c.crank_angle_deg.first().copied().unwrap_or(0.0)),
            fields::format_value(c.crank_angle_deg.last().copied().unwrap_or(0.0)),
            fields::format_sig(peak.0, 4),
            fields::format_value(peak.1)
        )
    };
    match p {
        Pressure::Single(c) => format!("one curve for every load: {}", curve(c)),
        Pressure::ByLoad(curves) => curves
            .iter()
            .map(|lp| {
                format!(
                    "load {}: {}",
                    fields::format_value(lp.load),
                    curve(&lp.curve)
                )
            })
            .collect::<Vec<_>>()
            .join("\n"),
    }
}

fn harmonics_ui(ui: &mut Ui, cx: &mut EditCtx, model: &mut Model) {
    if model.harmonics.is_empty() {
        return;
    }
    ui.separator();
    ui.label("Prescribed harmonics: T = amplitude · cos(order · θ + phase)");
    egui::Grid::new("harmonics")
        .num_columns(4)
        .spacing([6.0, 3.0])
        .show(ui, |ui| {
            for title in ["node", "order", "amplitude", "phase"] {
                ui.label(title);
            }
            ui.end_row();
            for (i, h) in model.harmonics.iter_mut().enumerate() {
                let key = |sub: &str| format!("harmonic[{i}].{sub}");
                let name = format!("harmonic {}", i + 1);
                widgets::node_combo(ui, cx, &key("at"), &format!("{name} at"), &mut h.at, false);
                widgets::number(
                    ui,
                    cx,
                    &key("order"),
                    &format!("{name} order"),
                    &mut h.order,
                    "",
                    0.5,
                );
                match &mut h.amplitude {
                    HarmonicAmplitude::Constant(a) => {
                        widgets::number(
                            ui,
                            cx,
                            &key("amplitude"),
                            &format!("{name} amplitude"),
                            a,
                            "N·m",
                            1.0,
                        );
                    }
                    HarmonicAmplitude::BySpeed {
                        speed_rpm,
                        amplitude_nm,
                    } => {
                        let text = format!(
                            "{} points over {} … {} rpm",
                            speed_rpm.len().min(amplitude_nm.len()),
                            fields::format_value(speed_rpm.first().copied().unwrap_or(0.0)),
                            fields::format_value(speed_rpm.last().copied().unwrap_or(0.0)),
                        );
                        fields::summary(ui, cx, &key("amplitude"), text);
                    }
                }
                widgets::number(
                    ui,
                    cx,
                    &key("phase_deg"),
                    &format!("{name} phase"),
                    &mut h.phase_deg,
                    "°",
                    10.0,
                );
                end_row(ui, cx);
            }
        });
}
