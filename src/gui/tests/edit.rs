//! Editing, driven through the real app with egui_kittest: a click in the schematic
//! selects the element under it (its position comes from the schematic's own layout
//! functions), renaming a node renames every reference, a drag is one undo step, an
//! invalid value marks the widget that edits it — for every key `validate` can produce.

use crate::gui::app::TorsimApp;
use crate::gui::views::schematic::geometry::{self, Geometry};
use crate::gui::views::schematic::{CANVAS_LABEL, Selection, layout};
use egui::{Key, Modifiers, Pos2, vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use torsim::model::{ConnectionKind, Model, parse_model, presets, validate};

pub(super) fn preset(name: &str) -> Model {
    let p = presets::preset(name).expect("preset");
    parse_model(p.text, name).expect("model")
}

/// The real app on `model`, tall enough that the driveline panel needs no scrolling.
pub(super) fn harness(model: Model) -> Harness<'static, TorsimApp> {
    Harness::builder()
        .with_size([1280.0, 2600.0])
        .build_eframe(move |cc| {
            let ctx = cc.egui_ctx.clone();
            TorsimApp::new(model, None, move || ctx.request_repaint())
        })
}

/// Where the schematic put everything, from its canvas on screen and the layout functions.
fn on_screen(h: &Harness<'static, TorsimApp>) -> Geometry {
    let rect = h.get_by_label(CANVAS_LABEL).rect();
    let model = &h.state().model;
    geometry::geometry(model, &layout::layout(model), rect)
}

fn click_at(h: &mut Harness<'static, TorsimApp>, pos: Pos2) {
    h.hover_at(pos);
    h.step();
    h.drag_at(pos);
    h.drop_at(pos);
    h.step();
    h.step();
}

/// The keys at which the editor showed the validation error in the last frame.
pub(super) fn shown(h: &Harness<'static, TorsimApp>) -> Vec<String> {
    h.ctx
        .data(|d| d.get_temp::<Vec<String>>(crate::gui::views::editor::shown_id()))
        .unwrap_or_default()
}

#[test]
fn clicking_the_schematic_selects_and_opens_the_element() {
    let mut h = harness(preset("cng-genset"));
    h.run_steps(2);
    let j = h
        .state()
        .model
        .connections
        .iter()
        .position(|c| c.name == "coupling")
        .expect("coupling");
    let at = on_screen(&h)
        .point_of(Selection::Connection(j))
        .expect("drawn");
    click_at(&mut h, at);
    assert_eq!(h.state().selected, Some(Selection::Connection(j)));
    // The editor opened the coupling: its fields are on screen.
    h.run_steps(4);
    h.get_by_label("psi coupling");
    let i = h.state().model.node_index("flywheel").expect("flywheel");
    let at = on_screen(&h)
        .point_of(Selection::Inertia(i))
        .expect("drawn");
    click_at(&mut h, at);
    assert_eq!(h.state().selected, Some(Selection::Inertia(i)));
    let at = on_screen(&h).point_of(Selection::Engine).expect("drawn");
    click_at(&mut h, at);
    assert_eq!(h.state().selected, Some(Selection::Engine));
    let at = on_screen(&h).point_of(Selection::Load).expect("drawn");
    click_at(&mut h, at);
    assert_eq!(h.state().selected, Some(Selection::Load));
    // Empty canvas clears the selection; touching a field in the editor selects again.
    let canvas = h.get_by_label(CANVAS_LABEL).rect();
    click_at(&mut h, canvas.left_bottom() + vec2(4.0, -4.0));
    assert_eq!(h.state().selected, None);
    // Selecting the engine scrolled the panel to its section, which took the inertias
    // out of view (under the schematic): a user scrolls back up first.
    for _ in 0..4 {
        h.get_by_label("J throw2").scroll_up();
        h.run_steps(2);
    }
    h.get_by_label("J throw2").click();
    h.run_steps(2);
    assert_eq!(h.state().selected, Some(Selection::Inertia(2)));
    h.key_press(Key::Escape);
    h.step();
}

/// Types `text` into the name field labelled `label`, replacing its content, and leaves it.
pub(super) fn rename(h: &mut Harness<'static, TorsimApp>, label: &str, text: &str) {
    h.get_by_label(label).click();
    h.step();
    h.key_press_modifiers(Modifiers::COMMAND, Key::A);
    h.step();
    h.get_by_label(label).type_text(text);
    h.step();
    h.key_press(Key::Enter);
    h.run_steps(2);
}

#[test]
fn renaming_a_node_renames_every_reference() {
    let mut h = harness(preset("cng-genset"));
    h.run_steps(2);
    rename(&mut h, "name throw3", "crank_throw_3");
    rename(&mut h, "name generator", "alternator");
    let m = &h.state().model;
    assert_eq!(validate(m), Ok(()), "the renamed model stays valid");
    assert!(h.state().invalid.is_none());
    assert_eq!(m.node_index("throw3"), None);
    let engine = m.engine.as_ref().expect("engine");
    assert_eq!(engine.at[2], "crank_throw_3", "engine.at follows");
    let by_name = |n: &str| {
        m.connections
            .iter()
            .find(|c| c.name == n)
            .expect("connection")
    };
    assert_eq!(by_name("crank_23").to, "crank_throw_3");
    assert_eq!(by_name("crank_34").from, "crank_throw_3");
    assert_eq!(by_name("generator_shaft").to, "alternator");
    assert_eq!(
        m.load.as_ref().and_then(|l| l.at.as_deref()),
        Some("alternator")
    );
    assert_eq!(h.state().undo.len(), 2, "one undo step per rename");
    // A name that is taken is refused, says why, and changes nothing.
    let before = h.state().model.clone();
    rename(&mut h, "name damper", "flywheel");
    assert_eq!(h.state().model, before);
    h.get_by_label_contains("`flywheel` is already a node");
    h.state_mut().undo();
    h.state_mut().undo();
    assert_eq!(h.state().model, preset("cng-genset"));
}

#[test]
fn a_drag_is_one_undo_step_with_live_results() {
    let mut h = harness(preset("cng-genset"));
    h.run_steps(2);
    h.get_by_label_contains("crank_12 · shaft").click();
    h.run_steps(4);
    let field = h.get_by_label("stiffness crank_12").rect().center();
    let generation = h.state().results.generation;
    h.hover_at(field);
    h.step();
    h.drag_at(field);
    h.step();
    let mut values = Vec::new();
    for k in 1..=12 {
        h.hover_at(field + vec2(6.0 * k as f32, 0.0));
        h.step();
        if let ConnectionKind::Shaft(s) = &h.state().model.connections[1].kind {
            values.push(s.stiffness_nm_per_rad);
        }
        assert!(
            h.state().undo.is_empty(),
            "no undo step while the drag goes on"
        );
    }
    h.drop_at(field + vec2(72.0, 0.0));
    h.run_steps(2);
    values.dedup();
    assert!(values.len() >= 5, "the value follows the drag: {values:?}");
    assert!(values.windows(2).all(|w| w[1] > w[0]), "{values:?}");
    assert!(
        h.state().results.generation >= generation + 5,
        "results are requested live during the drag"
    );
    assert_eq!(h.state().undo.len(), 1, "the whole drag is one undo step");
    h.state_mut().undo();
    assert_eq!(
        h.state().model,
        preset("cng-genset"),
        "undo restores the value"
    );
    assert_eq!(h.state().redo.len(), 1);
}

#[test]
fn a_typed_value_is_one_undo_step_and_an_invalid_one_is_marked_at_its_key() {
    let mut h = harness(preset("cng-genset"));
    h.run_steps(2);
    h.get_by_label("J generator").click();
    h.step();
    // One key per frame: the value follows each key (-4, then -40, valid results are
    // requested for none of them) ...
    let mut seen = Vec::new();
    for key in ["-", "4", "0"] {
        h.get_by_label("J generator").type_text(key);
        h.step();
        seen.push(h.state().model.inertias[9].inertia_kg_m2);
        assert!(
            h.state().undo.is_empty(),
            "no undo step while the field has focus"
        );
    }
    seen.dedup();
    assert_eq!(seen, [4.0, -4.0, -40.0], "the model follows the typing");
    h.key_press(Key::Enter);
    h.run_steps(3);
    let app = h.state();
    let error = app
        .invalid_error
        .clone()
        .expect("a negative inertia is rejected");
    assert_eq!(error.key, "inertia[9].inertia");
    assert_eq!(
        shown(&h),
        vec![error.key.clone()],
        "the J field of generator shows it"
    );
    assert!(
        app.invalid
            .as_deref()
            .is_some_and(|s| s.contains("positive")),
        "status bar"
    );
    // The message is under the field and in the status bar.
    let messages = h
        .query_all_by_label_contains("must be a positive finite number")
        .count();
    assert!(messages >= 2, "{messages}");
    assert_eq!(
        h.state().undo.len(),
        1,
        "... and typing -40 is one undo step"
    );
    h.state_mut().undo();
    h.run_steps(2);
    assert!(h.state().invalid_error.is_none() && shown(&h).is_empty());
}

/// Every key path `validate` can produce lands on a widget (or, for whole sections and
/// tables, on their header or summary).
#[test]
fn every_validation_key_is_shown_where_it_is_edited() {
    let mut h = harness(preset("cng-genset"));
    h.run_steps(2);
    for (base, break_it) in crate::gui::tests::edit_cases::cases() {
        let mut model = base.clone();
        break_it(&mut model);
        let key = validate(&model).expect_err("the case breaks the model").key;
        h.state_mut().model = model;
        h.state_mut().request();
        h.run_steps(6);
        assert!(
            shown(&h).contains(&key),
            "`{key}` is not shown; shown: {:?}",
            shown(&h)
        );
    }
}

/// Issue 16: letters typed into a number field are refused with a word under the field,
/// and the value stays.
#[test]
fn letters_in_a_number_field_are_refused_with_a_message() {
    let mut h = harness(preset("cng-genset"));
    h.run_steps(2);
    let before = h.state().model.inertias[9].inertia_kg_m2;
    h.get_by_label("J generator").click();
    h.step();
    h.get_by_label("J generator").type_text("abc");
    h.step();
    h.key_press(Key::Enter);
    h.run_steps(3);
    assert_eq!(h.state().model.inertias[9].inertia_kg_m2, before);
    h.get_by_label_contains("is not a number: the value stays 4");
}
