//! Structural edits through the real app: a node added with its shaft, a rubber stage to
//! the frame added through the add form's combo boxes, the node removed with its
//! connections; an order list typed as text, refused when it does not parse, marked at the
//! bad entry when it does.

use crate::gui::tests::edit::{harness, preset, rename, shown};
use crate::gui::views::schematic::Selection;
use egui::Key;
use egui_kittest::kittest::Queryable;
use torsim::model::validate;

#[test]
fn a_node_added_connected_and_removed_leaves_the_model_as_it_was() {
    let original = preset("cng-genset");
    let mut h = harness(original.clone());
    h.run_steps(2);
    h.get_by_label("J generator").click();
    h.key_press(Key::Escape);
    h.run_steps(2);
    h.get_by_label("+ inertia").click();
    h.run_steps(2);
    let m = &h.state().model;
    assert_eq!(m.inertias.len(), 11);
    let added = m.connections.last().expect("a shaft to the new node");
    assert_eq!(
        (added.from.as_str(), added.to.as_str()),
        ("generator", "node11")
    );
    assert_eq!(validate(m), Ok(()), "the new node is connected");
    assert_eq!(h.state().selected, Some(Selection::Inertia(10)));
    // A rubber stage from the new node to the frame, through the add form's combo boxes.
    h.get_by_label("new connection kind").click();
    h.run_steps(3);
    h.get_by_label("rubber").click();
    h.run_steps(3);
    h.get_by_label("new connection from").click();
    h.run_steps(3);
    // The list is longer than the popup: choose by accessibility action, not position.
    h.get_by_label("node11").click_accesskit();
    h.run_steps(3);
    h.get_by_label("new connection to").click();
    h.run_steps(3);
    h.get_by_label("ground").click_accesskit();
    h.run_steps(3);
    h.get_by_label("Add").click();
    h.run_steps(2);
    let last = h.state().model.connections.last().expect("added").clone();
    assert_eq!(
        (last.from.as_str(), last.to.as_str(), last.kind.kind_str()),
        ("node11", "ground", "rubber")
    );
    assert_eq!(last.name, "node11-ground");
    // Removing the node removes both its connections.
    h.get_by_label("remove node11").click();
    h.run_steps(2);
    assert_eq!(h.state().model, original);
    assert_eq!(h.state().undo.len(), 3, "add, add connection, remove");
}

#[test]
fn an_order_list_is_typed_as_text_and_its_bad_entry_is_marked() {
    let mut h = harness(preset("test-rig-45sh"));
    h.run_steps(2);
    h.get_by_label("Operation").click();
    h.run_steps(3);
    rename(&mut h, "operation orders", "0.5, 1, x");
    h.get_by_label_contains("not applied: `x` is not a number");
    assert!(h.state().undo.is_empty());
    rename(&mut h, "operation orders", "0.5 1 -2");
    assert_eq!(h.state().model.operation.orders, Some(vec![0.5, 1.0, -2.0]));
    let key = h.state().invalid_error.as_ref().map(|e| e.key.clone());
    assert_eq!(key.as_deref(), Some("operation.orders[2]"));
    assert_eq!(shown(&h), ["operation.orders[2]"]);
}
