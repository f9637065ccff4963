//! The driveline panel: every value of the model with its unit (drag or typed entry), add,
//! remove and rename, one section per file. A bad value is marked where it is edited (see
//! [`fields`]); the status bar keeps the message and the last good results stay on screen.
//! The element selected in the schematic opens here and is scrolled to; touching an
//! element here selects it there. A drag or a typed edit is one undo step
//! ([`Command::Edit`], applied by the app at the end of the frame).

mod add_connection;
mod connections;
mod engine;
mod engine_cycle;
mod expect;
pub mod fields;
mod inertias;
mod load;
mod modal_damping;
mod operation;
mod rating;
mod rubber;
mod rubber_polys;
mod shaft;
mod widgets;

use crate::gui::app::TorsimApp;
use crate::gui::command::Command;
use crate::gui::views::schematic::{self, Selection};
use egui::{CollapsingHeader, Ui};
use fields::EditCtx;

/// Temporary memory: the keys at which the editor showed the validation error last frame.
pub fn shown_id() -> egui::Id {
    egui::Id::unique("torsim.editor.shown")
}

fn last_error_id() -> egui::Id {
    egui::Id::unique("torsim.editor.last_error")
}

/// The whole panel. Edits are committed at the end: results are requested at once, the
/// undo step when the gesture ends.
pub fn driveline_ui(app: &mut TorsimApp, ui: &mut Ui) {
    undo_bar_ui(app, ui);
    // The panel edits a draft; the edit goes to the app as a command.
    let mut draft = app.model.clone();
    // Frames left to open and scroll to the element chosen in the schematic (a header
    // opening shows its body from the next frame).
    let reveal_frames = ui
        .data(|d| d.get_temp::<u8>(schematic::reveal_id()))
        .unwrap_or(0);
    let reveal = reveal_frames > 0;
    let key = app.invalid_error.as_ref().map(|e| e.key.clone());
    let error_new = ui.data(|d| d.get_temp::<Option<String>>(last_error_id())) != Some(key.clone());
    ui.data_mut(|d| d.insert_temp(last_error_id(), key));
    let mut cx = EditCtx {
        error: app.invalid_error.clone(),
        error_new,
        selected: app.selected,
        reveal,
        revealed: false,
        active: false,
        touched: false,
        select: None,
        shown: Vec::new(),
        row_message: None,
        nodes: app.model.inertias.iter().map(|n| n.name.clone()).collect(),
    };
    egui::ScrollArea::vertical()
        .auto_shrink([false, false])
        .show(ui, |ui| {
            ui.horizontal(|ui| {
                let l = ui.label("Model name");
                let r = ui
                    .add(egui::TextEdit::singleline(&mut draft.name).desired_width(f32::INFINITY))
                    .labelled_by(l.id);
                cx.track(&r);
            });
            let sections: [(&str, &[&str], Option<Selection>, bool); 7] = [
                (
                    "Inertias",
                    &["inertia"],
                    app.selected.filter(|s| matches!(s, Selection::Inertia(_))),
                    true,
                ),
                (
                    "Connections",
                    &["connection"],
                    app.selected
                        .filter(|s| matches!(s, Selection::Connection(_))),
                    true,
                ),
                (
                    "Engine and harmonics",
                    &["engine", "harmonic"],
                    app.selected.filter(|s| *s == Selection::Engine),
                    false,
                ),
                (
                    "Load",
                    &["load"],
                    app.selected.filter(|s| *s == Selection::Load),
                    false,
                ),
                ("Modal damping", &["modal_damping"], None, false),
                ("Operation", &["operation"], None, false),
                ("Checks (torsim check)", &["expect"], None, false),
            ];
            for (k, (title, prefixes, selected, default_open)) in sections.into_iter().enumerate() {
                let error = prefixes.iter().find_map(|p| cx.error_in(p));
                let open_now =
                    (cx.reveal && selected.is_some()) || (cx.error_new && error.is_some());
                let (text, message) = match error {
                    Some(m) => (
                        egui::RichText::new(format!("{title} (invalid)"))
                            .color(fields::error_color(ui)),
                        Some(m),
                    ),
                    None => (egui::RichText::new(title).strong(), None),
                };
                let r = CollapsingHeader::new(text)
                    .id_salt(("section", k))
                    .default_open(default_open)
                    .open(open_now.then_some(true))
                    .show(ui, |ui| match k {
                        0 => inertias::inertias_ui(ui, &mut cx, &mut draft, &mut app.stations),
                        1 => connections::connections_ui(ui, &mut cx, &mut draft),
                        2 => {
                            engine::engine_ui(ui, &mut cx, &mut draft);
                            let cycle = app.results.engine_cycle.clone();
                            if draft.engine.is_some() {
                                engine_cycle::cycle_ui(ui, cycle.as_deref());
                            }
                        }
                        3 => load::load_ui(ui, &mut cx, &mut draft),
                        4 => modal_damping::modal_damping_ui(ui, &mut cx, &mut draft),
                        5 => operation::operation_ui(ui, &mut cx, &mut draft),
                        _ => expect::expect_ui(ui, &mut cx, &mut draft),
                    });
                if let Some(m) = message {
                    if let Some(e) = &cx.error
                        && prefixes.contains(&e.key.as_str())
                    {
                        cx.shown.push(e.key.clone());
                    }
                    r.header_response.on_hover_text(m);
                }
            }
        });
    if let Some(sel) = cx.select {
        app.commands.push(Command::Select(sel));
    }
    ui.data_mut(|d| {
        if cx.revealed || reveal_frames <= 1 {
            d.remove::<u8>(schematic::reveal_id());
        } else {
            d.insert_temp(schematic::reveal_id(), reveal_frames - 1);
        }
    });
    ui.data_mut(|d| d.insert_temp(shown_id(), cx.shown.clone()));
    if draft != app.model {
        app.commands.push(Command::Edit {
            model: Box::new(draft),
            in_progress: cx.active,
        });
    } else if !cx.active && app.gesture_open() {
        app.commands.push(Command::EndGesture);
    }
}

/// Undo and redo, with how many steps each has.
fn undo_bar_ui(app: &mut TorsimApp, ui: &mut Ui) {
    ui.horizontal(|ui| {
        ui.strong("Driveline");
        ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
            let redo = ui
                .add_enabled(!app.redo.is_empty(), egui::Button::new("Redo"))
                .on_hover_text(format!("Ctrl+Shift+Z — {} step(s) to redo", app.redo.len()))
                .on_disabled_hover_text("nothing to redo");
            let undo = ui
                .add_enabled(!app.undo.is_empty(), egui::Button::new("Undo"))
                .on_hover_text(format!("Ctrl+Z — {} step(s) to undo", app.undo.len()))
                .on_disabled_hover_text("nothing to undo");
            if undo.clicked() {
                app.commands.push(Command::Undo);
            }
            if redo.clicked() {
                app.commands.push(Command::Redo);
            }
        });
    });
    ui.separator();
}

/// An element's frame, outlined when `selected`; scrolled to when `reveal` too (then it
/// returns true).
pub(crate) fn element_frame<R>(
    ui: &mut Ui,
    selected: bool,
    reveal: bool,
    add: impl FnOnce(&mut Ui) -> R,
) -> (R, bool) {
    let stroke = if selected {
        ui.visuals().selection.stroke
    } else {
        egui::Stroke::NONE
    };
    let r = egui::Frame::new()
        .stroke(stroke)
        .corner_radius(3.0)
        .inner_margin(2.0)
        .show(ui, add);
    if selected && reveal {
        r.response.scroll_to_me(Some(egui::Align::Center));
    }
    (r.inner, selected && reveal)
}
