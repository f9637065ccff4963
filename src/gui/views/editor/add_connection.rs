//! Adding a connection of a chosen kind between two chosen nodes (or a node and the frame),
//! with a unique name and starting values.

use crate::gui::views::editor::fields::EditCtx;
use crate::gui::views::editor::widgets;
use crate::gui::views::schematic::Selection;
use egui::Ui;
use torsim::model::{Connection, ConnectionKind, Gear, Model, RubberStage, RubberStiffness, Shaft};

/// `base`, or `base_2`, `base_3`, … : a name no connection has yet.
pub fn unique_connection_name(model: &Model, base: &str) -> String {
    let taken = |n: &str| model.connections.iter().any(|c| c.name == n);
    if !taken(base) {
        return base.to_string();
    }
    (2..)
        .map(|k| format!("{base}_{k}"))
        .find(|n| !taken(n))
        .unwrap_or_default()
}

/// Stiffness of a new shaft: the geometric mean of the model's shafts, else 1e5 N·m/rad.
pub fn typical_shaft_stiffness(model: &Model) -> f64 {
    let logs: Vec<f64> = model
        .connections
        .iter()
        .filter_map(|c| match &c.kind {
            ConnectionKind::Shaft(s) if s.stiffness_nm_per_rad > 0.0 => {
                Some(s.stiffness_nm_per_rad.ln())
            }
            _ => None,
        })
        .collect();
    if logs.is_empty() {
        1e5
    } else {
        (logs.iter().sum::<f64>() / logs.len() as f64).exp()
    }
}

/// What the add form remembers between frames.
#[derive(Clone, Default)]
struct AddForm {
    kind: usize,
    from: String,
    to: String,
}

const KINDS: [&str; 3] = ["shaft", "rubber", "gear"];

/// Add a connection of a chosen kind between two chosen nodes.
pub fn add_ui(ui: &mut Ui, cx: &mut EditCtx, model: &mut Model) {
    let id = egui::Id::unique("torsim.editor.add_connection");
    let mut form: AddForm = ui.data(|d| d.get_temp(id)).unwrap_or_default();
    let n = model.inertias.len();
    if model.node_index(&form.from).is_none() && n >= 2 {
        form.from = model.inertias[n - 2].name.clone();
    }
    if model.node_index(&form.to).is_none() && form.to != torsim::model::GROUND && n >= 1 {
        form.to = model.inertias[n - 1].name.clone();
    }
    ui.horizontal(|ui| {
        ui.label("Add a");
        let r = egui::ComboBox::from_id_salt("add kind")
            .selected_text(KINDS[form.kind])
            .show_ui(ui, |ui| {
                for (k, kind) in KINDS.iter().enumerate() {
                    ui.selectable_value(&mut form.kind, k, *kind);
                }
            })
            .response;
        ui.ctx().accesskit_node_builder(r.id, |node| {
            node.set_label("new connection kind");
        });
    });
    ui.horizontal(|ui| {
        ui.label("from");
        widgets::node_combo(
            ui,
            cx,
            "add.from",
            "new connection from",
            &mut form.from,
            true,
        );
        ui.label("to");
        widgets::node_combo(ui, cx, "add.to", "new connection to", &mut form.to, true);
        let ok = form.from != form.to;
        let add = ui
            .add_enabled(ok, egui::Button::new("Add"))
            .on_disabled_hover_text("choose two different ends");
        if add.clicked() {
            let kind = match form.kind {
                0 => ConnectionKind::Shaft(Shaft::massless(typical_shaft_stiffness(model), 0.0)),
                1 => ConnectionKind::Rubber(RubberStage {
                    stiffness: RubberStiffness::Direct(1e4),
                    psi: 1.0,
                    temperature_c: 25.0,
                    amplitude_poly: None,
                    amplitude_saturation: None,
                    amplitude_form: Default::default(),
                    frequency_poly: None,
                    frequency_power_law: None,
                    frequency_zener: None,
                    temperature_stiffness_poly: None,
                    temperature_damping_poly: None,
                    thermal: None,
                    rating: None,
                }),
                _ => ConnectionKind::Gear(Gear {
                    ratio: 1.0,
                    mesh_stiffness_nm_per_rad: None,
                    mesh_damping_nm_s_per_rad: 0.0,
                    backlash_deg: 0.0,
                    backlash_softening_deg: 0.0,
                    contact_exponent: 1.0,
                    contact_reference_deg: 0.0,
                }),
            };
            model.connections.push(Connection {
                name: unique_connection_name(
                    model,
                    &Connection::default_name(&form.from, &form.to),
                ),
                from: form.from.clone(),
                to: form.to.clone(),
                kind,
            });
            cx.select = Some(Some(Selection::Connection(model.connections.len() - 1)));
        }
    });
    ui.data_mut(|d| d.insert_temp(id, form));
}
