//! The driveline schematic: disks sized by inertia, shafts as springs, rubber stages as
//! rubber blocks with their names, gear stages as meshing wheels with their ratio, the
//! engine's cylinders over the nodes they act on, the load's brake, measurement stations
//! and the frame. Hover shows an element's values; a click selects it for the editor.
//!
//! Where things go is a pure function of the model ([`layout::layout`], then
//! [`geometry::geometry`] for a rectangle), so tests can find an element on screen.

mod draw;
pub mod geometry;
pub mod layout;
mod symbols;
#[cfg(test)]
mod tests;
mod tree;

use crate::gui::app::TorsimApp;
use crate::gui::command::Command;
use crate::gui::views::editor::fields::format_value as num;
use egui::{Sense, Ui};
use torsim::model::{ConnectionKind, ModalDamping, Model, RubberStiffness};

/// An element of the model chosen in the schematic or the editor.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Selection {
    /// `model.inertias[i]`.
    Inertia(usize),
    /// `model.connections[j]`.
    Connection(usize),
    /// `model.engine`.
    Engine,
    /// `model.load`.
    Load,
}

/// The accessible name of the schematic's canvas (tests find its rectangle by it).
pub const CANVAS_LABEL: &str = "driveline schematic";

/// Height of the schematic strip, points: all of the schematic (plus the panel's
/// margins), but at most `max` (then it scrolls).
pub fn strip_height(model: &Model, max: f32) -> f32 {
    (geometry::desired_size(&layout::layout(model)).y + 6.0).min(max.max(60.0))
}

/// Frames during which the editor tries to open and scroll to a selection just made.
const REVEAL_FRAMES: u8 = 10;

/// Temporary memory: frames left for the editor to open the element just selected in the
/// schematic and scroll to it (it stops once it has).
pub fn reveal_id() -> egui::Id {
    egui::Id::unique("torsim.schematic.reveal")
}

/// The schematic, filling the available width (scrolling when the driveline is long).
pub fn schematic_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let layout = layout::layout(&app.model);
    // Held to the panel's width: a long driveline scrolls inside it rather than widening
    // the window's layout (issue 16: at 800 px the plots below were laid out 1158 wide).
    egui::ScrollArea::both()
        .auto_shrink([false, false])
        .max_width(ui.available_width())
        .show(ui, |ui| {
            let size = geometry::desired_size(&layout).max(ui.available_size());
            let (rect, response) = ui.allocate_exact_size(size, Sense::click());
            response
                .widget_info(|| egui::WidgetInfo::labeled(egui::Role::Canvas, true, CANVAS_LABEL));
            let geometry = geometry::geometry(&app.model, &layout, rect);
            let hovered = response.hover_pos().and_then(|p| geometry.hit(p));
            let painter = ui.painter_at(rect);
            draw::paint(
                &painter,
                &draw::Palette::of(ui.visuals()),
                &app.model,
                &geometry,
                &app.stations,
                [app.selected, hovered],
            );
            if response.clicked()
                && let Some(pos) = response.interact_pointer_pos()
            {
                app.commands.push(Command::Select(geometry.hit(pos)));
                ui.data_mut(|d| d.insert_temp(reveal_id(), REVEAL_FRAMES));
            }
            if let Some(sel) = hovered {
                let text = describe(&app.model, sel, &app.stations);
                response.on_hover_text_at_pointer(text);
            }
        });
}

/// The schematic's note of the model's modal damping (`[modal_damping]`), which belongs
/// to no element: `modal ζ 2 %` for every mode, `modal ζ 2, 1.5 % (modes 1–2)` per mode.
pub fn modal_label(model: &Model) -> Option<String> {
    let percent = |z: f64| num(100.0 * z);
    model.modal_damping.as_ref().map(|d| match d {
        ModalDamping::All(z) => format!("modal ζ {} %", percent(*z)),
        ModalDamping::PerMode(list) => format!(
            "modal ζ {} % (mode{} 1{})",
            list.iter()
                .map(|z| percent(*z))
                .collect::<Vec<_>>()
                .join(", "),
            if list.len() > 1 { "s" } else { "" },
            if list.len() > 1 {
                format!("–{}", list.len())
            } else {
                String::new()
            }
        ),
    })
}

/// What the tooltip says about an element: its name and key values with units.
pub fn describe(model: &Model, sel: Selection, stations: &[String]) -> String {
    match sel {
        Selection::Inertia(i) => {
            let Some(n) = model.inertias.get(i) else {
                return String::new();
            };
            let mut s = format!("{}\nJ = {} kg·m²", n.name, num(n.inertia_kg_m2));
            if n.damping_nm_s_per_rad != 0.0 {
                s += &format!("\ndamping to frame {} N·m·s/rad", num(n.damping_nm_s_per_rad));
            }
            if stations.contains(&n.name) {
                s += "\nmeasurement station";
            }
            s
        }
        Selection::Connection(j) => {
            let Some(c) = model.connections.get(j) else {
                return String::new();
            };
            let head = format!("{} ({}): {} - {}", c.name, c.kind.kind_str(), c.from, c.to);
            let body = match &c.kind {
                ConnectionKind::Shaft(s) => {
                    let distributed = if s.inertia_kg_m2 > 0.0 {
                        let segments =
                            s.segments.map_or("automatic".to_string(), |n| n.to_string());
                        format!(
                            "\nJ = {} kg·m² distributed (exact element; {segments} segments)",
                            num(s.inertia_kg_m2)
                        )
                    } else {
                        String::new()
                    };
                    format!(
                        "k = {} N·m/rad\nc = {} N·m·s/rad{distributed}",
                        num(s.stiffness_nm_per_rad),
                        num(s.damping_nm_s_per_rad)
                    )
                }
                ConnectionKind::Rubber(r) => {
                    let k = match &r.stiffness {
                        RubberStiffness::Direct(k) => *k,
                        RubberStiffness::Elements(e) => e.torsional_stiffness_nm_per_rad(),
                    };
                    let elements = match &r.stiffness {
                        RubberStiffness::Elements(e) => {
                            format!("\n{} elements, {} per side", e.count, e.per_side)
                        }
                        RubberStiffness::Direct(_) => String::new(),
                    };
                    format!(
                        "static k at 25 °C = {} N·m/rad{elements}\npsi = {} (loss factor {})\nrubber at {} °C",
                        num(k),
                        num(r.psi),
                        crate::gui::views::editor::fields::format_sig(r.psi / std::f64::consts::TAU, 3),
                        num(r.temperature_c)
                    )
                }
                ConnectionKind::Gear(g) => format!(
                    "ratio {} (speed of {} / speed of {})\nmesh {}\nbacklash {}°{}{}",
                    num(g.ratio),
                    c.to,
                    c.from,
                    g.mesh_stiffness_nm_per_rad
                        .map_or("rigid".to_string(), |k| format!("{} N·m/rad", num(k))),
                    num(g.backlash_deg),
                    if g.backlash_softening_deg > 0.0 {
                        format!(", contact softened over {}°", num(g.backlash_softening_deg))
                    } else {
                        String::new()
                    },
                    if g.contact_exponent != 1.0 {
                        format!(
                            "\ncontact law: power {} of the deflection, as stiff as the mesh at {}°",
                            num(g.contact_exponent),
                            num(g.contact_reference_deg)
                        )
                    } else {
                        String::new()
                    }
                ),
            };
            format!("{head}\n{body}")
        }
        Selection::Engine => model.engine.as_ref().map_or_else(String::new, |e| {
            format!(
                "engine: {} cylinders, {}-stroke, on {}\nbore {} m, stroke {} m, conrod {} m\nreciprocating mass {} kg per cylinder",
                e.cylinders,
                e.strokes,
                e.at.join(", "),
                num(e.bore_m),
                num(2.0 * e.crank_radius_m),
                num(e.conrod_length_m),
                num(e.reciprocating_mass_kg)
            )
        }),
        Selection::Load => {
            let at = model.load_node().unwrap_or("-");
            let damping = model.load.as_ref().map_or(0.0, |l| l.damping_nm_s_per_rad);
            format!(
                "load at {at}: holds the mean speed\ndamping {} N·m·s/rad",
                num(damping)
            )
        }
    }
}
