//! The editor's widgets: a number with its unit (drag, or click and type), a whole
//! number, a node picker, a name that is applied when its field is left. Each one knows
//! the key path of what it edits (as in the model file, e.g. `connection[2].stiffness`):
//! when the model's validation error is at that key the widget is framed in red and says
//! why on hover and under its row. Each reports whether an edit is still in progress (a
//! drag, or a field with keyboard focus), so that one gesture becomes one undo step.

use crate::gui::views::editor::fields::{EditCtx, error_color, format_value};
use egui::{DragValue, Response, Stroke, TextEdit, Ui};

/// Adds a widget, framed in red when the error is at `key`; marks it for the error.
fn marked(
    ui: &mut Ui,
    cx: &mut EditCtx,
    key: &str,
    add: impl FnOnce(&mut Ui) -> Response,
) -> Response {
    let message = cx.error_at(key);
    framed(ui, cx, message, add)
}

/// Adds a widget, framed in red with `message` on hover and under its row when the
/// error concerns it.
fn framed(
    ui: &mut Ui,
    cx: &mut EditCtx,
    message: Option<String>,
    add: impl FnOnce(&mut Ui) -> Response,
) -> Response {
    let response = ui
        .scope(|ui| {
            if message.is_some() {
                let red = error_color(ui);
                let tint = red.gamma_multiply(0.25);
                let w = &mut ui.visuals_mut().widgets;
                for s in [&mut w.inactive, &mut w.hovered, &mut w.active, &mut w.open] {
                    s.weak_bg_fill = tint;
                    s.bg_fill = tint;
                    s.bg_stroke = Stroke::new(1.5, red);
                }
                ui.visuals_mut().extreme_bg_color = tint;
                ui.visuals_mut().selection.stroke = Stroke::new(1.5, red);
            }
            add(ui)
        })
        .inner;
    cx.track(&response);
    match message {
        Some(m) => {
            if let Some(key) = cx.error.as_ref().map(|e| e.key.clone()) {
                cx.shown_at(&key);
            }
            cx.row_message = Some(m.clone());
            response.on_hover_text(m)
        }
        None => response,
    }
}

/// Gives a widget the accessible name `access` (what screen readers and tests use).
fn name_it(ui: &Ui, r: &Response, access: &str) {
    ui.ctx()
        .accesskit_node_builder(r.id, |node| node.set_label(access.to_string()));
}

/// A value with its unit: drag (the speed follows the value's size, at least
/// `typical`·0.4 % per point) or click and type. Not clamped: validation says what is
/// wrong instead.
pub fn number(
    ui: &mut Ui,
    cx: &mut EditCtx,
    key: &str,
    access: &str,
    value: &mut f64,
    unit: &str,
    typical: f64,
) -> Response {
    let mut refused_note = None;
    let r = marked(ui, cx, key, |ui| {
        let editing = ui.memory(|m| m.has_focus(ui.next_auto_id()));
        let shown = *value;
        let speed = value.abs().max(typical.abs()).max(1e-9) * 0.004;
        let mut drag = DragValue::new(value)
            .speed(speed)
            .custom_formatter(move |x, _| {
                // While typing, the exact value, so that leaving the field changes nothing.
                if editing {
                    format!("{x}")
                } else {
                    format_value(x)
                }
            });
        // Issue 16: text that is no number used to be dropped without a word. The parser
        // is egui's own rule (whitespace ignored, U+2212 is a minus); it remembers what it
        // refused, and a field left with such text says so under its row.
        let refused = std::rc::Rc::new(std::cell::RefCell::new(None::<String>));
        let seen = refused.clone();
        drag = drag.custom_parser(move |text| {
            let clean: String = text
                .chars()
                .filter(|c| !c.is_whitespace())
                .map(|c| if c == '−' { '-' } else { c })
                .collect();
            let parsed = clean.parse::<f64>().ok();
            *seen.borrow_mut() = parsed.is_none().then(|| text.to_string());
            parsed
        });
        match unit {
            "" => {}
            "°" => drag = drag.suffix("°"),
            _ => drag = drag.suffix(format!(" {unit}")),
        }
        let r = ui.add(drag);
        name_it(ui, &r, access);
        let note_id = r.id.with("not a number");
        if r.gained_focus() || r.changed() {
            ui.data_mut(|d| d.remove::<String>(note_id));
        }
        if r.lost_focus()
            && let Some(text) = refused.borrow_mut().take()
        {
            let note = format!(
                "“{}” is not a number: the value stays {}",
                text.trim(),
                format_value(shown)
            );
            ui.data_mut(|d| d.insert_temp(note_id, note));
        }
        refused_note = ui.data(|d| d.get_temp::<String>(note_id));
        r
    });
    // A validation message of the same row has the word first.
    if cx.row_message.is_none() {
        cx.row_message = refused_note;
    }
    r
}

/// A whole number (counts, mode numbers).
pub fn count(ui: &mut Ui, cx: &mut EditCtx, key: &str, access: &str, value: &mut u32) -> Response {
    marked(ui, cx, key, |ui| {
        let r = ui.add(DragValue::new(value).speed(0.05));
        name_it(ui, &r, access);
        r
    })
}

/// A node picker (with `ground` when `ground` is true).
pub fn node_combo(
    ui: &mut Ui,
    cx: &mut EditCtx,
    key: &str,
    access: &str,
    value: &mut String,
    ground: bool,
) -> Response {
    let nodes = cx.nodes.clone();
    let before = value.clone();
    let mut r = marked(ui, cx, key, |ui| {
        let r = egui::ComboBox::from_id_salt(("node", key))
            .selected_text(value.as_str())
            .show_ui(ui, |ui| {
                let ground_name = torsim::model::GROUND.to_string();
                for name in nodes.iter().chain(ground.then_some(&ground_name)) {
                    ui.selectable_value(value, name.clone(), name);
                }
            })
            .response;
        name_it(ui, &r, access);
        r
    });
    if *value != before {
        r.mark_changed();
    }
    r
}

/// A name applied when the field is left (Enter or a click elsewhere; Escape cancels):
/// gives the new name when it differs and `check` accepts it, else shows `check`'s
/// reason under the row.
pub fn name_field(
    ui: &mut Ui,
    cx: &mut EditCtx,
    key: &str,
    access: &str,
    current: &str,
    width: f32,
    check: impl Fn(&str) -> Result<(), String>,
) -> (Response, Option<String>) {
    let message = cx.error_at(key);
    let field = Committed {
        id_key: key,
        access,
        width,
        refused: "not renamed",
    };
    field.show(ui, cx, message, current, check)
}

/// A list of numbers typed as `0.5, 1, 1.5` and applied when the field is left; the error
/// of any of its entries (`prefix[i]`) or of the list itself (`prefix`) marks it.
pub fn list_field(
    ui: &mut Ui,
    cx: &mut EditCtx,
    prefix: &str,
    access: &str,
    values: &mut Vec<f64>,
    width: f32,
) -> Response {
    let message = cx.error_in(prefix);
    let current: Vec<String> = values.iter().map(|v| format!("{v}")).collect();
    let field = Committed {
        id_key: prefix,
        access,
        width,
        refused: "not applied",
    };
    let (r, text) = field.show(ui, cx, message, &current.join(", "), |t| {
        parse_list(t).map(|_| ())
    });
    if let Some(list) = text.and_then(|t| parse_list(&t).ok()) {
        *values = list;
    }
    r
}

/// Numbers separated by commas or spaces.
fn parse_list(text: &str) -> Result<Vec<f64>, String> {
    text.split(|c: char| c == ',' || c == ';' || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .map(|t| {
            t.parse::<f64>()
                .map_err(|_| format!("`{t}` is not a number"))
        })
        .collect()
}

/// A text field whose content is applied when it is left.
struct Committed<'a> {
    /// Key path that makes its egui id.
    id_key: &'a str,
    /// Accessible name.
    access: &'a str,
    /// Width, points.
    width: f32,
    /// What the message says when `check` refuses the text.
    refused: &'a str,
}

impl Committed<'_> {
    fn show(
        &self,
        ui: &mut Ui,
        cx: &mut EditCtx,
        message: Option<String>,
        current: &str,
        check: impl Fn(&str) -> Result<(), String>,
    ) -> (Response, Option<String>) {
        let id = egui::Id::unique(("torsim.text", self.id_key));
        let rejected = id.with("rejected");
        let focused = ui.memory(|m| m.has_focus(id));
        let mut text = match focused {
            true => ui
                .data(|d| d.get_temp::<String>(id))
                .unwrap_or_else(|| current.to_string()),
            false => current.to_string(),
        };
        let width = self.width;
        let r = framed(ui, cx, message, |ui| {
            let edit = TextEdit::singleline(&mut text).id(id).desired_width(width);
            let r = ui.add_sized([width, ui.spacing().interact_size.y], edit);
            name_it(ui, &r, self.access);
            r
        });
        if r.has_focus() {
            ui.data_mut(|d| d.insert_temp(id, text.clone()));
        }
        if r.changed() {
            ui.data_mut(|d| d.remove::<String>(rejected));
        }
        let mut applied = None;
        if r.lost_focus() {
            ui.data_mut(|d| d.remove::<String>(id));
            let escape = ui.input(|i| i.key_pressed(egui::Key::Escape));
            if !escape && text != current {
                match check(&text) {
                    Ok(()) => applied = Some(text),
                    Err(why) => {
                        ui.data_mut(|d| d.insert_temp(rejected, why));
                    }
                }
            }
        }
        if let Some(why) = ui.data(|d| d.get_temp::<String>(rejected)) {
            cx.row_message = Some(format!("{}: {why}", self.refused));
        }
        (r, applied)
    }
}
