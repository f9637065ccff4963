//! Inertias: name (renaming a node renames every reference to it), moment of inertia and
//! damping to the frame; add (joined by a shaft) and remove (with its connections).

use crate::gui::views::editor::fields::{self, EditCtx};
use crate::gui::views::editor::widgets;
use crate::gui::views::schematic::Selection;
use egui::{Shape, Ui};
use torsim::model::{Connection, ConnectionKind, GROUND, Inertia, Model, Shaft};

/// Renames node `old` to `new` everywhere the model names it: the inertia, connection
/// ends, the engine's nodes, the load node and the harmonics' nodes.
pub fn rename_node(model: &mut Model, old: &str, new: &str) {
    let swap = |name: &mut String| {
        if name == old {
            *name = new.to_string();
        }
    };
    model.inertias.iter_mut().for_each(|n| swap(&mut n.name));
    for c in &mut model.connections {
        swap(&mut c.from);
        swap(&mut c.to);
    }
    if let Some(e) = &mut model.engine {
        e.at.iter_mut().for_each(swap);
    }
    if let Some(at) = model.load.as_mut().and_then(|l| l.at.as_mut()) {
        swap(at);
    }
    model.harmonics.iter_mut().for_each(|h| swap(&mut h.at));
}

/// Why `name` cannot be the new name of node `i`, if it cannot.
fn check_node_name(model: &Model, i: usize, name: &str) -> Result<(), String> {
    if name.trim().is_empty() {
        Err("a node needs a name".into())
    } else if name == GROUND {
        Err("`ground` is reserved for the frame".into())
    } else if model
        .inertias
        .iter()
        .enumerate()
        .any(|(k, n)| k != i && n.name == name)
    {
        Err(format!("`{name}` is already a node"))
    } else {
        Ok(())
    }
}

/// The Inertias section.
pub fn inertias_ui(ui: &mut Ui, cx: &mut EditCtx, model: &mut Model, stations: &mut [String]) {
    let mut remove = None;
    let mut rename = None;
    egui::Grid::new("inertias")
        .num_columns(4)
        .spacing([6.0, 3.0])
        .show(ui, |ui| {
            ui.label("name");
            ui.label("J");
            ui.label("damping to frame");
            ui.label("");
            ui.end_row();
            for i in 0..model.inertias.len() {
                let key = format!("inertia[{i}]");
                let background = ui.painter().add(Shape::Noop);
                cx.begin_element();
                let name = model.inertias[i].name.clone();
                let check = |new: &str| check_node_name(model, i, new);
                let (name_field, renamed) = widgets::name_field(
                    ui,
                    cx,
                    &format!("{key}.name"),
                    &format!("name {name}"),
                    &name,
                    96.0,
                    check,
                );
                let node = &mut model.inertias[i];
                let j = widgets::number(
                    ui,
                    cx,
                    &format!("{key}.inertia"),
                    &format!("J {name}"),
                    &mut node.inertia_kg_m2,
                    "kg·m²",
                    0.01,
                );
                let damping = widgets::number(
                    ui,
                    cx,
                    &format!("{key}.damping"),
                    &format!("damping {name}"),
                    &mut node.damping_nm_s_per_rad,
                    "N·m·s/rad",
                    1.0,
                );
                let attached = model
                    .connections
                    .iter()
                    .filter(|c| c.from == name || c.to == name)
                    .count();
                let x = ui
                    .small_button("×")
                    .on_hover_text(format!("remove {name} and its {attached} connection(s)"));
                ui.ctx().accesskit_node_builder(x.id, |node| {
                    node.set_label(format!("remove {name}"));
                });
                if x.clicked() {
                    remove = Some(i);
                }
                if let Some(new) = renamed {
                    rename = Some((name.clone(), new));
                }
                let element = Selection::Inertia(i);
                let whole = cx.error_at(&key);
                let row = name_field
                    .rect
                    .union(j.rect)
                    .union(damping.rect)
                    .union(x.rect);
                let fill = if whole.is_some() {
                    Some(fields::error_color(ui).gamma_multiply(0.25))
                } else if cx.is_selected(element) {
                    Some(ui.visuals().selection.bg_fill.gamma_multiply(0.45))
                } else {
                    None
                };
                if let Some(fill) = fill {
                    ui.painter()
                        .set(background, Shape::rect_filled(row.expand(2.0), 3.0, fill));
                }
                if let Some(m) = whole {
                    cx.row_message = Some(m);
                    cx.shown.push(key.clone());
                }
                if cx.is_selected(element) && cx.reveal {
                    j.scroll_to_me(Some(egui::Align::Center));
                    cx.revealed = true;
                }
                cx.end_element(element);
                fields::end_row(ui, cx);
            }
        });
    if let Some((old, new)) = rename {
        rename_node(model, &old, &new);
        stations
            .iter_mut()
            .filter(|s| **s == old)
            .for_each(|s| *s = new.clone());
    }
    if let Some(i) = remove {
        let name = model.inertias.remove(i).name;
        model.connections.retain(|c| c.from != name && c.to != name);
        cx.select = Some(None);
    }
    add_ui(ui, cx, model);
}

/// `+ inertia`: a new node, joined by a shaft to the selected node (or the last one).
fn add_ui(ui: &mut Ui, cx: &mut EditCtx, model: &mut Model) {
    let anchor = match cx.selected {
        Some(Selection::Inertia(i)) if i < model.inertias.len() => Some(i),
        _ => model.inertias.len().checked_sub(1),
    };
    let hint = match anchor {
        Some(i) => format!("a new node joined by a shaft to {}", model.inertias[i].name),
        None => "a first node".to_string(),
    };
    if !ui.button("+ inertia").on_hover_text(hint).clicked() {
        return;
    }
    let name = (model.inertias.len() + 1..)
        .map(|k| format!("node{k}"))
        .find(|n| model.node_index(n).is_none())
        .unwrap_or_default();
    model.inertias.push(Inertia {
        name: name.clone(),
        inertia_kg_m2: 0.1,
        damping_nm_s_per_rad: 0.0,
    });
    if let Some(i) = anchor {
        let from = model.inertias[i].name.clone();
        model.connections.push(Connection {
            name: crate::gui::views::editor::add_connection::unique_connection_name(
                model,
                &Connection::default_name(&from, &name),
            ),
            from,
            to: name,
            kind: ConnectionKind::Shaft(Shaft::massless(
                crate::gui::views::editor::add_connection::typical_shaft_stiffness(model),
                0.0,
            )),
        });
    }
    cx.select = Some(Some(Selection::Inertia(model.inertias.len() - 1)));
}
