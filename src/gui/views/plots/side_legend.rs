//! A legend beside a plot rather than on it (issue 16: egui_plot's legend sits on the
//! data): one row per series with a swatch of its colour and style and a checkbox that
//! hides it. The plot gets the rest of the width. Which series a plot hides is kept in
//! egui's memory under the plot's name, so it survives edits and tab switches.

use egui::{Color32, Id, Sense, Stroke, Ui, vec2};
use std::collections::BTreeSet;

/// One legend row.
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    /// The series' name, as the plot draws it.
    pub name: String,
    /// Its colour.
    pub color: Color32,
    /// Drawn dashed.
    pub dashed: bool,
}

/// Width of the legend column, points: 190 at most, a third of a narrow plot area.
fn legend_width(available: f32) -> f32 {
    (available / 3.0).clamp(110.0, 190.0)
}

fn hidden_id(plot: &str) -> Id {
    Id::unique(("torsim side legend", plot))
}

/// The names `plot` hides.
pub fn hidden(ui: &Ui, plot: &str) -> BTreeSet<String> {
    ui.data(|d| d.get_temp::<BTreeSet<String>>(hidden_id(plot)))
        .unwrap_or_default()
}

fn swatch(ui: &mut Ui, e: &Entry) {
    let (rect, _) = ui.allocate_exact_size(vec2(22.0, 10.0), Sense::hover());
    let y = rect.center().y;
    let stroke = Stroke::new(2.5, e.color);
    if e.dashed {
        for k in 0..3 {
            let x = rect.left() + 8.0 * k as f32;
            ui.painter()
                .line_segment([egui::pos2(x, y), egui::pos2(x + 5.0, y)], stroke);
        }
    } else {
        ui.painter().line_segment(
            [egui::pos2(rect.left(), y), egui::pos2(rect.right(), y)],
            stroke,
        );
    }
}

/// `plot_ui` on the left with the remaining width and `height`, the legend of `entries`
/// on the right; returns what `plot_ui` returned.
pub fn with_side_legend<R>(
    ui: &mut Ui,
    plot: &str,
    entries: &[Entry],
    height: f32,
    plot_ui: impl FnOnce(&mut Ui, &BTreeSet<String>) -> R,
) -> R {
    let mut hidden = hidden(ui, plot);
    let width = ui.available_width();
    let legend_w = legend_width(width);
    let out = ui
        .horizontal_top(|ui| {
            let out = ui
                .allocate_ui(vec2(width - legend_w - 8.0, height), |ui| {
                    plot_ui(ui, &hidden)
                })
                .inner;
            let column = egui::Layout::top_down(egui::Align::Min);
            ui.allocate_ui_with_layout(vec2(legend_w, height), column, |ui| {
                egui::ScrollArea::vertical()
                    .id_salt(("legend", plot))
                    .max_height(height)
                    .show(ui, |ui| {
                        ui.set_width(legend_w);
                        for e in entries {
                            ui.horizontal(|ui| {
                                let mut shown = !hidden.contains(&e.name);
                                let r = ui.add(egui::Checkbox::without_text(&mut shown));
                                let name = format!("show {}", e.name);
                                r.widget_info(|| {
                                    egui::WidgetInfo::selected(
                                        egui::Role::CheckBox,
                                        true,
                                        shown,
                                        &name,
                                    )
                                });
                                let toggled = r.changed();
                                swatch(ui, e);
                                let label = egui::RichText::new(&e.name).small();
                                ui.add(egui::Label::new(label).truncate())
                                    .on_hover_text(&e.name);
                                if toggled {
                                    if shown {
                                        hidden.remove(&e.name);
                                    } else {
                                        hidden.insert(e.name.clone());
                                    }
                                }
                            });
                        }
                    });
            });
            out
        })
        .inner;
    ui.data_mut(|d| d.insert_temp(hidden_id(plot), hidden));
    out
}
