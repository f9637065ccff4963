//! The colour scale beside a spectrogram: the colour map from bottom to top of its
//! 60 dB range, labelled every 10 dB (re 1 rpm).

use crate::gui::session::spectrogram::{RANGE_DB, colour};
use egui::{Align2, Rect, Sense, Stroke, Ui, Vec2};

/// Fills `bar` from bottom to top in `steps` bands, band `k` in `colour_at(u)` at its
/// middle `u` (0 at the bottom, 1 at the top).
pub fn gradient_bar(
    painter: &egui::Painter,
    bar: Rect,
    steps: usize,
    colour_at: &dyn Fn(f64) -> egui::Color32,
) {
    for i in 0..steps {
        let u0 = i as f32 / steps as f32;
        let u1 = (i + 1) as f32 / steps as f32;
        let r = Rect::from_x_y_ranges(
            bar.x_range(),
            bar.bottom() - u1 * bar.height()..=bar.bottom() - u0 * bar.height(),
        );
        painter.rect_filled(r, 0.0, colour_at(f64::from(u0 + 0.5 / steps as f32)));
    }
}

/// The colour scale: the map from bottom to top with labels every 10 dB.
pub fn colour_scale_ui(ui: &mut Ui, [bottom, top]: [f64; 2], height: f32, width: f32) {
    let (rect, _) = ui.allocate_exact_size(Vec2::new(width, height), Sense::hover());
    let painter = ui.painter_at(rect);
    let bar = Rect::from_min_max(
        rect.min + Vec2::new(6.0, 22.0),
        rect.min + Vec2::new(22.0, height - 30.0),
    );
    gradient_bar(&painter, bar, 64, &colour);
    let text = ui.visuals().text_color();
    let font = egui::TextStyle::Small.resolve(ui.style());
    painter.text(
        rect.min + Vec2::new(2.0, 2.0),
        Align2::LEFT_TOP,
        "dB re 1 rpm",
        font.clone(),
        text,
    );
    let mut db = top;
    while db >= bottom - 1e-9 {
        let y = bar.bottom() - ((db - bottom) / RANGE_DB) as f32 * bar.height();
        painter.line_segment(
            [egui::pos2(bar.right(), y), egui::pos2(bar.right() + 4.0, y)],
            Stroke::new(1.0, text),
        );
        painter.text(
            egui::pos2(bar.right() + 6.0, y),
            Align2::LEFT_CENTER,
            format!("{db:.0}"),
            font.clone(),
            text,
        );
        db -= 10.0;
    }
}
