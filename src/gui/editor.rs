//! The driveline panel: every value of the model with its unit, drag or typed entry, add,
//! remove and rename. Values are checked by the model's validation after each edit; the
//! status bar names a bad value and the last good results stay on screen.

use egui::{DragValue, Ui};
use torsim::model::{Connection, ConnectionKind, Inertia, Model, RubberStiffness, Shaft};

/// A labelled number with its unit; the drag speed follows the value's size.
fn number(ui: &mut Ui, label: &str, value: &mut f64, unit: &str) -> egui::Response {
    ui.horizontal(|ui| {
        let l = ui.label(label);
        let speed = (value.abs() * 0.005).max(1e-6);
        ui.add(
            DragValue::new(value)
                .speed(speed)
                .suffix(format!(" {unit}"))
                .max_decimals(6),
        )
        .labelled_by(l.id)
    })
    .inner
}

/// The whole panel.
pub fn driveline_ui(model: &mut Model, ui: &mut Ui) {
    egui::ScrollArea::vertical().show(ui, |ui| {
        ui.horizontal(|ui| {
            ui.label("Name");
            ui.text_edit_singleline(&mut model.name);
        });
        egui::CollapsingHeader::new("Inertias")
            .default_open(true)
            .show(ui, |ui| inertias_ui(model, ui));
        egui::CollapsingHeader::new("Connections")
            .default_open(true)
            .show(ui, |ui| connections_ui(model, ui));
        if let Some(engine) = &mut model.engine {
            egui::CollapsingHeader::new("Engine")
                .default_open(false)
                .show(ui, |ui| {
                    ui.label(format!(
                        "{} cylinders, {}-stroke, acting on {}",
                        engine.cylinders,
                        engine.strokes,
                        engine.at.join(", ")
                    ));
                    number(ui, "bore", &mut engine.bore_m, "m");
                    number(ui, "crank radius", &mut engine.crank_radius_m, "m");
                    number(ui, "conrod length", &mut engine.conrod_length_m, "m");
                    number(
                        ui,
                        "reciprocating mass",
                        &mut engine.reciprocating_mass_kg,
                        "kg",
                    );
                });
        }
        if let Some(load) = &mut model.load {
            egui::CollapsingHeader::new("Load")
                .default_open(false)
                .show(ui, |ui| {
                    ui.label(format!(
                        "at {}",
                        load.at.as_deref().unwrap_or("the last node")
                    ));
                    number(
                        ui,
                        "load damping",
                        &mut load.damping_nm_s_per_rad,
                        "N·m·s/rad",
                    );
                });
        }
        egui::CollapsingHeader::new("Operation")
            .default_open(false)
            .show(ui, |ui| {
                if let Some(r) = &mut model.operation.speed_range_rpm {
                    number(ui, "sweep from", &mut r[0], "rpm");
                    number(ui, "sweep to", &mut r[1], "rpm");
                }
                if let Some(r) = &mut model.operation.operating_range_rpm {
                    number(ui, "operating from", &mut r[0], "rpm");
                    number(ui, "operating to", &mut r[1], "rpm");
                }
            });
    });
}

fn inertias_ui(model: &mut Model, ui: &mut Ui) {
    let mut remove = None;
    for (i, node) in model.inertias.iter_mut().enumerate() {
        ui.push_id(("inertia", i), |ui| {
            ui.horizontal(|ui| {
                ui.add(egui::TextEdit::singleline(&mut node.name).desired_width(110.0));
                if ui
                    .small_button("×")
                    .on_hover_text("remove this inertia")
                    .clicked()
                {
                    remove = Some(i);
                }
            });
            number(
                ui,
                &format!("J {}", node.name),
                &mut node.inertia_kg_m2,
                "kg·m²",
            );
        });
    }
    if let Some(i) = remove {
        model.inertias.remove(i);
    }
    if ui.button("+ inertia").clicked() {
        let name = format!("node{}", model.inertias.len() + 1);
        model.inertias.push(Inertia {
            name,
            inertia_kg_m2: 0.1,
            damping_nm_s_per_rad: 0.0,
        });
    }
}

fn connections_ui(model: &mut Model, ui: &mut Ui) {
    let mut remove = None;
    for (j, c) in model.connections.iter_mut().enumerate() {
        ui.push_id(("connection", j), |ui| {
            ui.separator();
            ui.horizontal(|ui| {
                ui.add(egui::TextEdit::singleline(&mut c.name).desired_width(90.0));
                ui.label(format!("{}: {} -> {}", c.kind.kind_str(), c.from, c.to));
                if ui.small_button("×").on_hover_text("remove this connection").clicked() {
                    remove = Some(j);
                }
            });
            let name = c.name.clone();
            match &mut c.kind {
                ConnectionKind::Shaft(s) => {
                    number(ui, &format!("stiffness {name}"), &mut s.stiffness_nm_per_rad, "N·m/rad");
                    number(ui, &format!("damping {name}"), &mut s.damping_nm_s_per_rad, "N·m·s/rad");
                }
                ConnectionKind::Rubber(r) => {
                    match &mut r.stiffness {
                        RubberStiffness::Direct(k) => {
                            number(ui, &format!("stiffness {name}"), k, "N·m/rad");
                        }
                        RubberStiffness::Elements(e) => {
                            number(ui, &format!("element radial stiffness {name}"), &mut e.radial_stiffness_n_per_m, "N/m");
                            number(ui, &format!("pitch diameter {name}"), &mut e.pitch_diameter_m, "m");
                            ui.label(format!(
                                "{} elements, {} per side -> {:.0} N·m/rad static (seed 000 eq. 12)",
                                e.count,
                                e.per_side,
                                e.torsional_stiffness_nm_per_rad()
                            ));
                        }
                    }
                    number(ui, &format!("psi {name}"), &mut r.psi, "");
                    number(ui, &format!("temperature {name}"), &mut r.temperature_c, "°C");
                }
                ConnectionKind::Gear(g) => {
                    number(ui, &format!("ratio {name}"), &mut g.ratio, "");
                    if let Some(k) = &mut g.mesh_stiffness_nm_per_rad {
                        number(ui, &format!("mesh stiffness {name}"), k, "N·m/rad");
                    }
                    number(ui, &format!("backlash {name}"), &mut g.backlash_deg, "°");
                }
            }
        });
    }
    if let Some(j) = remove {
        model.connections.remove(j);
    }
    if model.inertias.len() >= 2
        && ui
            .button("+ shaft")
            .on_hover_text("a shaft between the last two inertias")
            .clicked()
    {
        let n = model.inertias.len();
        let (from, to) = (
            model.inertias[n - 2].name.clone(),
            model.inertias[n - 1].name.clone(),
        );
        model.connections.push(Connection {
            name: Connection::default_name(&from, &to),
            from,
            to,
            kind: ConnectionKind::Shaft(Shaft {
                stiffness_nm_per_rad: 1.0e4,
                damping_nm_s_per_rad: 0.0,
            }),
        });
    }
}
