//! A shaft's own inertia through the real app (issue 15, item 4): typed in the shaft's
//! section, its segments automatic until the user sets a number, each one undo step, the
//! results recomputed with the exact element, and a negative inertia refused at its key.

use crate::gui::app::TorsimApp;
use crate::gui::tests::edit::{harness, preset};
use egui::Key;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use torsim::model::ConnectionKind;

fn shaft_of(h: &Harness<'static, TorsimApp>, j: usize) -> torsim::model::Shaft {
    match &h.state().model.connections[j].kind {
        ConnectionKind::Shaft(s) => s.clone(),
        other => panic!("connection {j} is {other:?}"),
    }
}

fn type_into(h: &mut Harness<'static, TorsimApp>, label: &str, text: &str) {
    h.get_by_label(label).click();
    h.step();
    h.get_by_label(label).type_text(text);
    h.step();
    h.key_press(Key::Enter);
    h.run_steps(2);
}

#[test]
fn a_shaft_gets_inertia_and_segments() {
    let mut h = harness(preset("cng-genset"));
    h.run_steps(2);
    h.get_by_label_contains("crank_12 · shaft").click();
    h.run_steps(4);
    assert!(
        h.query_by_label("automatic").is_none(),
        "a massless shaft has no segments"
    );
    type_into(&mut h, "inertia crank_12", "0.05");
    let s = shaft_of(&h, 1);
    assert_eq!((s.inertia_kg_m2, s.segments), (0.05, None));
    h.get_by_label("automatic").click();
    h.run_steps(2);
    assert_eq!(shaft_of(&h, 1).segments, Some(8));
    type_into(&mut h, "segments crank_12", "12");
    assert_eq!(shaft_of(&h, 1).segments, Some(12));
    assert_eq!(h.state().undo.len(), 3, "inertia, automatic off, segments");
    // A negative inertia is refused at its key.
    type_into(&mut h, "inertia crank_12", "-1");
    let key = h.state().invalid_error.as_ref().map(|e| e.key.clone());
    assert_eq!(key.as_deref(), Some("connection[1].inertia"));
}
