//! Connections of every kind: name, ends, and the kind's values (shaft: see
//! [`crate::gui::views::editor::shaft`]; rubber: see [`crate::gui::views::editor::rubber`]; gear: ratio, mesh stiffness, backlash and its contact softening); add a
//! connection of a chosen kind between two chosen nodes; remove.

use super::{element_frame, rubber, shaft};
use crate::gui::views::editor::fields::{self, EditCtx, end_row};
use crate::gui::views::editor::widgets;
use crate::gui::views::schematic::Selection;
use egui::{CollapsingHeader, Ui};
use torsim::model::{ConnectionKind, Gear, Model};

/// The Connections section.
pub fn connections_ui(ui: &mut Ui, cx: &mut EditCtx, model: &mut Model) {
    let mut remove = None;
    for j in 0..model.connections.len() {
        let key = format!("connection[{j}]");
        let element = Selection::Connection(j);
        let c = &model.connections[j];
        let title = format!("{} · {}: {} - {}", c.name, c.kind.kind_str(), c.from, c.to);
        let (text, message) = fields::header_text(ui, cx, &key, title);
        let selected = cx.is_selected(element);
        let open_now = (cx.reveal && selected) || (cx.error_new && message.is_some());
        cx.begin_element();
        let (header, revealed) = element_frame(ui, selected, cx.reveal, |ui| {
            // Rubber stages, what this tool is about, start open.
            CollapsingHeader::new(text)
                .id_salt(("connection", j))
                .default_open(matches!(
                    model.connections[j].kind,
                    ConnectionKind::Rubber(_)
                ))
                .open(open_now.then_some(true))
                .show(ui, |ui| {
                    if body_ui(ui, cx, model, j) {
                        remove = Some(j);
                    }
                })
                .header_response
        });
        cx.revealed |= revealed;
        if header.clicked() {
            cx.touched = true;
        }
        if let Some(m) = message {
            header.on_hover_text(m);
        }
        cx.end_element(element);
    }
    if let Some(j) = remove {
        model.connections.remove(j);
        cx.select = Some(None);
    }
    ui.separator();
    crate::gui::views::editor::add_connection::add_ui(ui, cx, model);
}

/// One connection's values; true when the user asked to remove it.
fn body_ui(ui: &mut Ui, cx: &mut EditCtx, model: &mut Model, j: usize) -> bool {
    let key = format!("connection[{j}]");
    let k = |sub: &str| format!("{key}.{sub}");
    let name = model.connections[j].name.clone();
    let mut rename = None;
    egui::Grid::new(("connection grid", j))
        .num_columns(2)
        .spacing([8.0, 3.0])
        .show(ui, |ui| {
            ui.label("name");
            let check = |new: &str| {
                if new.trim().is_empty() {
                    Err("a connection needs a name".to_string())
                } else if model
                    .connections
                    .iter()
                    .enumerate()
                    .any(|(i, c)| i != j && c.name == new)
                {
                    Err(format!("`{new}` is already a connection"))
                } else {
                    Ok(())
                }
            };
            rename = widgets::name_field(
                ui,
                cx,
                &k("name"),
                &format!("name {name}"),
                &name,
                120.0,
                check,
            )
            .1;
            end_row(ui, cx);
            let c = &mut model.connections[j];
            ui.label("from");
            widgets::node_combo(
                ui,
                cx,
                &k("from"),
                &format!("from {name}"),
                &mut c.from,
                true,
            );
            end_row(ui, cx);
            ui.label("to");
            widgets::node_combo(ui, cx, &k("to"), &format!("to {name}"), &mut c.to, true);
            end_row(ui, cx);
            match &mut c.kind {
                ConnectionKind::Shaft(s) => shaft::shaft_ui(ui, cx, &key, &name, s),
                ConnectionKind::Rubber(r) => rubber::rubber_ui(ui, cx, &key, &name, r),
                ConnectionKind::Gear(g) => gear_ui(ui, cx, &key, &name, g),
            }
        });
    if !matches!(model.connections[j].kind, ConnectionKind::Gear(_)) {
        // A loop of connections that gives a node two speeds (see the gears on the loop).
        fields::message_at(ui, cx, &k("ratio"));
    }
    if let Some(new) = rename {
        model.connections[j].name = new;
    }
    ui.button("remove connection")
        .on_hover_text(format!("remove {name}"))
        .clicked()
}

fn gear_ui(ui: &mut Ui, cx: &mut EditCtx, key: &str, name: &str, g: &mut Gear) {
    let k = |sub: &str| format!("{key}.{sub}");
    ui.label("ratio")
        .on_hover_text("speed of `to` / speed of `from`; negative reverses the direction");
    widgets::number(
        ui,
        cx,
        &k("ratio"),
        &format!("ratio {name}"),
        &mut g.ratio,
        "",
        1.0,
    );
    end_row(ui, cx);
    ui.label("mesh stiffness")
        .on_hover_text("at the `to` side; rigid: a kinematic constraint");
    ui.horizontal(|ui| {
        let mut rigid = g.mesh_stiffness_nm_per_rad.is_none();
        let r = ui.checkbox(&mut rigid, "rigid");
        cx.track(&r);
        if r.changed() {
            g.mesh_stiffness_nm_per_rad = (!rigid).then_some(1e6);
            // A rigid gear has no mesh twist to damp (the model refuses the pair).
            g.mesh_damping_nm_s_per_rad = 0.0;
        }
        if let Some(m) = &mut g.mesh_stiffness_nm_per_rad {
            widgets::number(
                ui,
                cx,
                &k("mesh_stiffness"),
                &format!("mesh stiffness {name}"),
                m,
                "N·m/rad",
                1e5,
            );
        }
    });
    end_row(ui, cx);
    // Shown on a rigid gear too when a file gave it one, so the refusal has its widget.
    if g.mesh_stiffness_nm_per_rad.is_some() || g.mesh_damping_nm_s_per_rad != 0.0 {
        ui.label("mesh damping")
            .on_hover_text("viscous, on the mesh twist rate at the `to` side");
        widgets::number(
            ui,
            cx,
            &k("mesh_damping"),
            &format!("mesh damping {name}"),
            &mut g.mesh_damping_nm_s_per_rad,
            "N·m·s/rad",
            10.0,
        );
        end_row(ui, cx);
    }
    ui.label("backlash")
        .on_hover_text("total free play at the `to` side");
    widgets::number(
        ui,
        cx,
        &k("backlash_deg"),
        &format!("backlash {name}"),
        &mut g.backlash_deg,
        "°",
        0.1,
    );
    end_row(ui, cx);
    ui.label("contact softening").on_hover_text(
        "width ε over which the tooth contact stiffens after the play closes \
         (0: a hard contact)",
    );
    widgets::number(
        ui,
        cx,
        &k("backlash_softening_deg"),
        &format!("contact softening {name}"),
        &mut g.backlash_softening_deg,
        "°",
        0.01,
    );
    end_row(ui, cx);
    ui.label("contact exponent").on_hover_text(
        "exponent n of the tooth contact's law once the flanks touch: 1 linear, 1.5 Hertzian",
    );
    widgets::number(
        ui,
        cx,
        &k("contact_exponent"),
        &format!("contact exponent {name}"),
        &mut g.contact_exponent,
        "",
        0.05,
    );
    end_row(ui, cx);
    ui.label("contact reference").on_hover_text(
        "deflection at which a power-law contact is as stiff as the mesh stiffness \
         (needed when the exponent is not 1)",
    );
    widgets::number(
        ui,
        cx,
        &k("contact_reference_deg"),
        &format!("contact reference {name}"),
        &mut g.contact_reference_deg,
        "°",
        0.01,
    );
    end_row(ui, cx);
}
