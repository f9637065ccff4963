//! The schematic's symbols: gear wheels with their speed ratio, springs, the frame, the
//! engine's cylinders and the load's brake.

use crate::gui::views::schematic::draw::Palette;
use egui::{Align2, Color32, FontId, Painter, Pos2, Rect, Stroke, StrokeKind, pos2, vec2};
use torsim::model::Model;

/// The gear's speeds `from`:`to` as a driveline engineer writes them: `2.5:1` for a
/// reduction (ratio 0.4), `1:1.5` for a step-up, `rev.` when the direction reverses.
pub fn speed_ratio_label(ratio: f64) -> String {
    let short = |x: f64| {
        let s = format!("{x:.3}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    };
    let r = ratio.abs();
    let reverse = if ratio < 0.0 { " rev." } else { "" };
    if r == 0.0 || !r.is_finite() {
        format!("ratio {ratio}")
    } else if r <= 1.0 {
        format!("{}:1{reverse}", short(1.0 / r))
    } else {
        format!("1:{}{reverse}", short(r))
    }
}

/// A gear wheel with teeth.
pub fn wheel(p: &Painter, pal: &Palette, c: Pos2, r: f32, color: Color32) {
    p.circle_filled(c, r, pal.background);
    p.circle_stroke(c, r - 1.5, Stroke::new(1.5, color));
    let teeth = ((r * 0.9) as usize).clamp(6, 24);
    for k in 0..teeth {
        let a = std::f32::consts::TAU * k as f32 / teeth as f32;
        let d = vec2(a.cos(), a.sin());
        p.line_segment(
            [c + d * (r - 1.5), c + d * (r + 1.0)],
            Stroke::new(1.5, color),
        );
    }
    p.circle_filled(c, 2.0, color);
}

/// A zigzag spring across `s`.
pub fn spring(p: &Painter, s: Rect, stroke: Stroke) {
    let turns = 6;
    let mut pts = vec![s.left_center()];
    for k in 0..=2 * turns {
        let x = s.left() + s.width() * (k as f32 + 0.5) / (2 * turns + 1) as f32;
        let y = if k % 2 == 0 { s.top() } else { s.bottom() };
        pts.push(pos2(x, y));
    }
    pts.push(s.right_center());
    p.line(pts, stroke);
}

/// The frame: a wall with hatching, the link ending at its face.
pub fn ground(p: &Painter, color: Color32, at: Pos2) {
    let stroke = Stroke::new(1.5, color);
    let x = at.x - 6.0;
    p.line_segment([pos2(x, at.y - 14.0), pos2(x, at.y + 14.0)], stroke);
    for k in 0..6 {
        let y = at.y - 14.0 + 5.6 * k as f32;
        p.line_segment(
            [pos2(x, y), pos2(x + 6.0, y + 5.0)],
            Stroke::new(1.0, color),
        );
    }
}

/// The engine: cylinders with pistons and rods down to the crank throws.
pub fn engine(
    p: &Painter,
    pal: &Palette,
    model: &Model,
    outline: Rect,
    cylinders: &[(Rect, Pos2)],
) {
    p.rect_filled(outline, 3.0, pal.engine.gamma_multiply(0.12));
    p.rect_stroke(
        outline,
        3.0,
        Stroke::new(1.0, pal.engine.gamma_multiply(0.6)),
        StrokeKind::Inside,
    );
    for (bore, crank) in cylinders {
        p.rect_stroke(*bore, 1.0, Stroke::new(1.2, pal.engine), StrokeKind::Inside);
        let piston = Rect::from_min_max(
            bore.min + vec2(1.5, 5.0),
            pos2(bore.right() - 1.5, bore.top() + 11.0),
        );
        p.rect_filled(piston, 1.0, pal.engine);
        p.line_segment(
            [piston.center_bottom(), *crank],
            Stroke::new(1.2, pal.engine),
        );
    }
    if let Some(e) = &model.engine {
        p.text(
            outline.center_top() - vec2(0.0, 1.0),
            Align2::CENTER_BOTTOM,
            format!("{} cyl · {}-stroke", e.cylinders, e.strokes),
            FontId::proportional(11.0),
            pal.engine,
        );
    }
}

/// A brake: pads either side of the disk's lower half and their caliper underneath.
pub fn brake(p: &Painter, color: Color32, r: Rect) {
    let pad = |x: f32| Rect::from_min_max(pos2(x, r.top() + 2.0), pos2(x + 5.0, r.bottom() - 6.0));
    p.rect_filled(pad(r.left() + 1.0), 1.0, color);
    p.rect_filled(pad(r.right() - 6.0), 1.0, color);
    p.line(
        vec![
            pos2(r.left() + 3.5, r.bottom() - 6.0),
            pos2(r.left() + 3.5, r.bottom()),
            pos2(r.right() - 3.5, r.bottom()),
            pos2(r.right() - 3.5, r.bottom() - 6.0),
        ],
        Stroke::new(2.0, color),
    );
}
