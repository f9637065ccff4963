//! Modal damping (`[modal_damping]`): one ζ for every flexible mode, or ζ per mode (an
//! editable list; modes above it get none), on top of the dampers and rubber of the
//! driveline (`torsim::physics::modal_damping`).

use crate::gui::views::editor::fields::{EditCtx, end_row};
use crate::gui::views::editor::widgets;
use egui::Ui;
use torsim::model::{ModalDamping, Model};

/// ζ a new modal damping starts at: 2 %, a common value for steel drivelines.
const DEFAULT_ZETA: f64 = 0.02;

/// The Modal damping section.
pub fn modal_damping_ui(ui: &mut Ui, cx: &mut EditCtx, model: &mut Model) {
    let Some(damping) = &mut model.modal_damping else {
        ui.weak("none: only the dampers and rubber stages damp the modes");
        let r = ui
            .button("+ modal damping")
            .on_hover_text("a damping ratio ζ per mode, as OpenTorsion and DyRoBeS take it");
        cx.track(&r);
        if r.clicked() {
            model.modal_damping = Some(ModalDamping::All(DEFAULT_ZETA));
        }
        return;
    };
    let mut per_mode = matches!(damping, ModalDamping::PerMode(_));
    let r = ui
        .checkbox(&mut per_mode, "ζ per mode")
        .on_hover_text("off: one ζ for every flexible mode");
    cx.track(&r);
    if r.changed() {
        *damping = match damping {
            ModalDamping::All(z) => ModalDamping::PerMode(vec![*z]),
            ModalDamping::PerMode(list) => {
                ModalDamping::All(list.first().copied().unwrap_or(DEFAULT_ZETA))
            }
        };
    }
    let mut remove_last = false;
    let mut add = false;
    egui::Grid::new("modal damping")
        .num_columns(2)
        .spacing([8.0, 3.0])
        .show(ui, |ui| match damping {
            ModalDamping::All(z) => {
                ui.label("ζ, every mode")
                    .on_hover_text("ratio of critical damping: 0.02 is 2 %");
                widgets::number(ui, cx, "modal_damping.zeta", "modal ζ", z, "", DEFAULT_ZETA);
                end_row(ui, cx);
            }
            ModalDamping::PerMode(list) => {
                let count = list.len();
                for (i, z) in list.iter_mut().enumerate() {
                    ui.label(format!("ζ, mode {}", i + 1));
                    ui.horizontal(|ui| {
                        let key = format!("modal_damping.zeta[{i}]");
                        let access = format!("modal ζ of mode {}", i + 1);
                        widgets::number(ui, cx, &key, &access, z, "", DEFAULT_ZETA);
                        if i + 1 == count && count > 1 {
                            let r = ui.small_button("−").on_hover_text("remove this mode's ζ");
                            cx.track(&r);
                            remove_last = r.clicked();
                        }
                    });
                    end_row(ui, cx);
                }
                ui.label("");
                let r = ui
                    .small_button("+ mode")
                    .on_hover_text("modes above the list get no modal damping");
                cx.track(&r);
                add = r.clicked();
                end_row(ui, cx);
            }
        });
    if let ModalDamping::PerMode(list) = damping {
        if remove_last {
            list.pop();
        }
        if add {
            let last = list.last().copied().unwrap_or(DEFAULT_ZETA);
            list.push(last);
        }
    }
    let r = ui.button("remove modal damping");
    cx.track(&r);
    if r.clicked() {
        model.modal_damping = None;
    }
}
