//! Modal damping through the real app (issue 15, item 4): added in its editor section,
//! typed, switched to a list per mode and extended, shown in the schematic's corner, one
//! undo step per edit, and a ζ ≥ 1 refused at its key.

use crate::gui::tests::edit::{harness, preset};
use crate::gui::views::schematic::modal_label;
use egui::Key;
use egui_kittest::kittest::Queryable;
use torsim::model::ModalDamping;

#[test]
fn modal_damping_is_added_typed_and_listed_per_mode() {
    let mut h = harness(preset("test-rig-45sh"));
    h.run_steps(2);
    assert_eq!(h.state().model.modal_damping, None);
    h.get_by_label("Modal damping").click();
    h.run_steps(3);
    h.get_by_label("+ modal damping").click();
    h.run_steps(2);
    assert_eq!(h.state().model.modal_damping, Some(ModalDamping::All(0.02)));
    h.get_by_label("modal ζ").click();
    h.step();
    h.get_by_label("modal ζ").type_text("0.05");
    h.step();
    h.key_press(Key::Enter);
    h.run_steps(2);
    assert_eq!(h.state().model.modal_damping, Some(ModalDamping::All(0.05)));
    h.get_by_label("ζ per mode").click();
    h.run_steps(2);
    h.get_by_label("+ mode").click();
    h.run_steps(2);
    let model = h.state().model.clone();
    assert_eq!(
        model.modal_damping,
        Some(ModalDamping::PerMode(vec![0.05, 0.05]))
    );
    assert_eq!(
        modal_label(&model).as_deref(),
        Some("modal ζ 5, 5 % (modes 1–2)")
    );
    assert_eq!(h.state().undo.len(), 4, "add, type, per mode, add a mode");
    // ζ = 1.5 of mode 2 is refused at its key.
    h.get_by_label("modal ζ of mode 2").click();
    h.step();
    h.get_by_label("modal ζ of mode 2").type_text("1.5");
    h.step();
    h.key_press(Key::Enter);
    h.run_steps(2);
    let key = h.state().invalid_error.as_ref().map(|e| e.key.clone());
    assert_eq!(key.as_deref(), Some("modal_damping.zeta[1]"));
    h.get_by_label("remove modal damping").click();
    h.run_steps(2);
    assert_eq!(h.state().model.modal_damping, None);
}
