//! What the editor's widgets share while the panel is drawn ([`EditCtx`]): the model's
//! validation error and where it was shown, the selection, whether an edit is still in
//! progress; plus number formatting and the error messages under rows, on summaries and
//! on section headers.

use crate::gui::views::schematic::Selection;
use egui::{Color32, Response, RichText, Ui};
use torsim::model::ModelError;

/// What the editor knows while drawing, and what it learns.
pub struct EditCtx {
    /// The model's validation error, if any.
    pub error: Option<ModelError>,
    /// The error's key differs from the last frame's: sections holding it open once.
    pub error_new: bool,
    /// The selected element.
    pub selected: Option<Selection>,
    /// The selection was just made in the schematic: open it and scroll to it.
    pub reveal: bool,
    /// The selected element was scrolled to.
    pub revealed: bool,
    /// A widget is being dragged or typed into.
    pub active: bool,
    /// A widget of the element being drawn was clicked, dragged or focused.
    pub touched: bool,
    /// A new selection made in the editor (`Some(None)` clears it, e.g. after a removal).
    pub select: Option<Option<Selection>>,
    /// Keys of the widgets and headers that showed the error this frame.
    pub shown: Vec<String>,
    /// The error message of a widget in the current grid row (written under the row).
    pub row_message: Option<String>,
    /// Node names, for pickers.
    pub nodes: Vec<String>,
}

impl EditCtx {
    /// The error's message when its key is exactly `key`.
    pub fn error_at(&self, key: &str) -> Option<String> {
        self.error
            .as_ref()
            .filter(|e| e.key == key)
            .map(|e| e.message.clone())
    }

    /// The error's message when its key is `prefix` or lies inside it (`prefix.…`,
    /// `prefix[…`).
    pub fn error_in(&self, prefix: &str) -> Option<String> {
        self.error
            .as_ref()
            .filter(|e| inside(&e.key, prefix))
            .map(|e| e.message.clone())
    }

    /// Records that a widget or header showed the error at `key`.
    pub fn shown_at(&mut self, key: &str) {
        if !self.shown.iter().any(|k| k == key) {
            self.shown.push(key.to_string());
        }
    }

    /// Notes what a widget's response says about the gesture and the selection.
    pub fn track(&mut self, r: &Response) {
        if r.dragged() || r.has_focus() {
            self.active = true;
        }
        if r.clicked() || r.drag_started() || r.gained_focus() {
            self.touched = true;
        }
    }

    /// Starts an element: nothing of it touched yet.
    pub fn begin_element(&mut self) {
        self.touched = false;
    }

    /// Ends an element: if the user touched it, it becomes the selection.
    pub fn end_element(&mut self, element: Selection) {
        if self.touched {
            self.select = Some(Some(element));
        }
        self.touched = false;
    }

    /// True when `element` is selected.
    pub fn is_selected(&self, element: Selection) -> bool {
        self.selected == Some(element)
    }
}

/// `key` is `prefix` or a path inside it.
pub fn inside(key: &str, prefix: &str) -> bool {
    key.strip_prefix(prefix)
        .is_some_and(|rest| rest.is_empty() || rest.starts_with('.') || rest.starts_with('['))
}

/// A number for people: at most 6 significant digits, with an exponent outside
/// 0.001 … 10⁶ (`2.5e6`, `18055.4`, `0.333333`).
pub fn format_value(x: f64) -> String {
    format_sig(x, 6)
}

/// `x` with at most `digits` significant digits (derived values: `0.159`, `1.9 l`), with an
/// exponent outside 0.001 … 10⁶.
pub fn format_sig(x: f64, digits: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let a = x.abs();
    let digits = digits.max(1) as i32;
    if (1e-3..1e6).contains(&a) {
        let decimals = (digits - 1 - a.log10().floor() as i32).clamp(0, 9) as usize;
        trim(format!("{x:.decimals$}"))
    } else {
        let s = format!("{x:.prec$e}", prec = (digits - 1) as usize);
        match s.split_once('e') {
            Some((mantissa, exp)) => format!("{}e{exp}", trim(mantissa.to_string())),
            None => s,
        }
    }
}

fn trim(s: String) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// The colour of errors.
pub fn error_color(ui: &Ui) -> Color32 {
    ui.visuals().error_fg_color
}

/// Ends a grid row; a message of a widget in it goes on a row of its own underneath,
/// written across the panel without widening the grid's columns.
pub fn end_row(ui: &mut Ui, cx: &mut EditCtx) {
    ui.end_row();
    if let Some(m) = cx.row_message.take() {
        let red = error_color(ui);
        let width = (ui.clip_rect().right() - ui.cursor().left() - 4.0).max(80.0);
        let galley = ui
            .painter()
            .layout(m, egui::FontId::proportional(11.0), red, width);
        let size = egui::vec2(1.0, galley.size().y);
        let (rect, r) = ui.allocate_exact_size(size, egui::Sense::hover());
        r.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Label, true, galley.text()));
        ui.painter().galley(rect.left_top(), galley, red);
        ui.end_row();
    }
}

/// Outside a grid: the message of the widget just drawn, underneath it.
pub fn note(ui: &mut Ui, cx: &mut EditCtx) {
    if let Some(m) = cx.row_message.take() {
        ui.label(RichText::new(m).small().color(error_color(ui)));
    }
}

/// The error's message, in red, when its key is exactly `key` (a list's own key, e.g. its
/// length).
pub fn message_at(ui: &mut Ui, cx: &mut EditCtx, key: &str) {
    if let Some(m) = cx.error_at(key) {
        cx.shown_at(key);
        ui.label(RichText::new(m).small().color(error_color(ui)));
    }
}

/// A text that shows the error when its key lies inside `prefix` (for read-only
/// summaries of tables): red, with the message on hover and under its grid row.
pub fn summary(ui: &mut Ui, cx: &mut EditCtx, prefix: &str, text: impl Into<String>) -> Response {
    match cx.error_in(prefix) {
        Some(m) => {
            if let Some(e) = &cx.error {
                let key = e.key.clone();
                cx.shown_at(&key);
            }
            cx.row_message = Some(m.clone());
            let red = RichText::new(text.into()).color(error_color(ui));
            ui.add(egui::Label::new(red).wrap()).on_hover_text(m)
        }
        None => ui.add(egui::Label::new(text.into()).wrap()),
    }
}

/// A section or element header's text: red and marked when the error lies inside
/// `prefix`.
pub fn header_text(
    ui: &Ui,
    cx: &mut EditCtx,
    prefix: &str,
    text: String,
) -> (RichText, Option<String>) {
    match cx.error_in(prefix) {
        Some(m) => {
            if cx.error.as_ref().is_some_and(|e| e.key == prefix) {
                cx.shown_at(prefix);
            }
            (
                RichText::new(format!("{text} (invalid)")).color(error_color(ui)),
                Some(m),
            )
        }
        None => (RichText::new(text), None),
    }
}

#[cfg(test)]
mod tests {
    use super::{format_sig, format_value, inside};

    #[test]
    fn numbers_read_well_and_keys_nest() {
        assert_eq!(format_value(2.5e6), "2.5e6");
        assert_eq!(format_value(1.085e6), "1.085e6");
        assert_eq!(format_value(18055.4), "18055.4");
        assert_eq!(format_value(1.0 / 3.0), "0.333333");
        assert_eq!(format_value(-2.3e-5), "-2.3e-5");
        assert_eq!(format_value(0.0), "0");
        assert_eq!(format_sig(1.0 / std::f64::consts::TAU, 3), "0.159");
        assert!(inside("connection[2].elements.count", "connection[2]"));
        assert!(inside("engine.pressure", "engine.pressure"));
        assert!(!inside(
            "engine.pressure_by_load[0].load",
            "engine.pressure"
        ));
        assert!(!inside("connection[12].psi", "connection[1]"));
    }
}
