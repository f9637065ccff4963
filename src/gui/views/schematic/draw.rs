//! Painting the schematic's symbols where [`crate::gui::views::schematic::geometry`] put them.

use super::Selection;
use crate::gui::views::schematic::geometry::{Geometry, LinkShape};
use crate::gui::views::schematic::symbols::{
    brake, engine, ground, speed_ratio_label, spring, wheel,
};
use egui::{Align2, Color32, FontId, Painter, Rect, Shape, Stroke, StrokeKind, pos2, vec2};
use torsim::model::{ConnectionKind, Model, RubberStiffness};

/// Colours of the symbols, for the light or the dark theme.
pub struct Palette {
    /// Disks and shafts.
    pub steel: Color32,
    /// Rubber stages.
    pub rubber: Color32,
    /// Gear pairs.
    pub gear: Color32,
    /// The engine.
    pub engine: Color32,
    /// The load's brake.
    pub load: Color32,
    /// Measurement stations.
    pub station: Color32,
    /// Node names.
    pub text: Color32,
    /// Behind gear wheels.
    pub background: Color32,
    /// Outline of the selected element.
    pub selected: Stroke,
    /// Outline of the hovered element.
    pub hovered: Stroke,
}

impl Palette {
    /// The palette for these visuals.
    pub fn of(v: &egui::Visuals) -> Self {
        let dark = v.dark_mode;
        let pick = |d: (u8, u8, u8), l: (u8, u8, u8)| {
            let (r, g, b) = if dark { d } else { l };
            Color32::from_rgb(r, g, b)
        };
        Self {
            steel: pick((150, 162, 180), (85, 97, 115)),
            rubber: pick((214, 128, 52), (190, 100, 30)),
            gear: pick((110, 170, 235), (35, 95, 175)),
            engine: pick((205, 205, 205), (70, 70, 70)),
            load: pick((225, 80, 80), (185, 35, 35)),
            station: pick((80, 200, 110), (30, 140, 60)),
            text: v.text_color(),
            background: v.extreme_bg_color,
            selected: Stroke::new(2.5, v.selection.stroke.color),
            hovered: Stroke::new(1.5, v.widgets.hovered.fg_stroke.color.gamma_multiply(0.7)),
        }
    }
}

/// Paints the whole schematic; `marks` is [selected, hovered].
pub fn paint(
    p: &Painter,
    pal: &Palette,
    model: &Model,
    g: &Geometry,
    stations: &[String],
    marks: [Option<Selection>; 2],
) {
    for link in &g.links {
        link_ui(p, pal, model, link);
    }
    for &(_, at) in &g.grounds {
        ground(p, pal.steel, at);
    }
    for d in g.disks.iter().flatten() {
        p.rect_filled(*d, 2.0, pal.steel);
        p.rect_stroke(
            *d,
            2.0,
            Stroke::new(1.0, pal.steel.gamma_multiply(0.6)),
            StrokeKind::Inside,
        );
    }
    if let Some((outline, cylinders)) = &g.engine {
        engine(p, pal, model, *outline, cylinders);
    }
    if let Some(r) = g.load {
        brake(p, pal.load, r);
    }
    if let Some(text) = super::modal_label(model) {
        let corner = p.clip_rect().right_top() + vec2(-6.0, 4.0);
        p.text(
            corner,
            Align2::RIGHT_TOP,
            text,
            FontId::proportional(11.0),
            pal.text,
        );
    }
    let font = FontId::proportional(11.0);
    let max_chars = ((g.column_pitch - 4.0) / 6.0).max(4.0) as usize;
    for (label, node) in g.labels.iter().zip(&model.inertias) {
        let Some(at) = label else { continue };
        let station = stations.contains(&node.name);
        let color = if station { pal.station } else { pal.text };
        let r = p.text(
            *at,
            Align2::CENTER_TOP,
            short(&node.name, max_chars),
            font.clone(),
            color,
        );
        if station {
            let tip = pos2(r.left() - 9.0, r.top() + 1.0);
            p.add(Shape::convex_polygon(
                vec![tip, tip + vec2(4.5, 9.0), tip + vec2(-4.5, 9.0)],
                pal.station,
                Stroke::NONE,
            ));
        }
    }
    for (mark, stroke) in marks.iter().zip([pal.selected, pal.hovered]) {
        if let Some(r) = mark.and_then(|m| outline_of(g, m)) {
            p.rect_stroke(r, 3.0, stroke, StrokeKind::Outside);
        }
    }
}

/// The outline drawn around a selected or hovered element.
fn outline_of(g: &Geometry, m: Selection) -> Option<Rect> {
    match m {
        Selection::Inertia(i) => g.disks.get(i).copied().flatten().map(|d| d.expand(3.0)),
        Selection::Connection(j) => g
            .links
            .iter()
            .find(|l| l.connection == j)
            .map(|l| l.symbol.expand(2.0)),
        Selection::Engine => g.engine.as_ref().map(|(r, _)| *r),
        Selection::Load => g.load,
    }
}

/// `name`, cut to `max` characters with a trailing dot.
fn short(name: &str, max: usize) -> String {
    if name.chars().count() <= max {
        name.to_string()
    } else {
        name.chars()
            .take(max.saturating_sub(1))
            .chain(['.'])
            .collect()
    }
}

fn link_ui(p: &Painter, pal: &Palette, model: &Model, link: &LinkShape) {
    let Some(c) = model.connections.get(link.connection) else {
        return;
    };
    let color = match c.kind {
        ConnectionKind::Shaft(_) => pal.steel,
        ConnectionKind::Rubber(_) => pal.rubber,
        ConnectionKind::Gear(_) => pal.gear,
    };
    let s = link.symbol;
    let line = Stroke::new(1.5, pal.steel);
    if link.arc {
        let [a, apex, b] = [link.line[0], link.line[1], link.line[2]];
        let control = apex + (apex - pos2(0.5 * (a.x + b.x), 0.5 * (a.y + b.y)));
        p.add(egui::epaint::QuadraticBezierShape::from_points_stroke(
            [a, control, b],
            false,
            Color32::TRANSPARENT,
            Stroke::new(1.5, color),
        ));
        p.rect_filled(s, 3.0, pal.background);
        p.rect_stroke(s, 3.0, Stroke::new(1.0, color), StrokeKind::Inside);
        p.text(
            s.center(),
            Align2::CENTER_CENTER,
            c.kind.kind_str(),
            FontId::proportional(9.0),
            color,
        );
        return;
    }
    // The shaft line up to the symbol and on from it (gears sit on the line).
    let n = link.line.len();
    for w in link.line[..n - 1].windows(2) {
        p.line_segment([w[0], w[1]], line);
    }
    let (last, end) = (link.line[n - 2], link.line[n - 1]);
    if matches!(c.kind, ConnectionKind::Gear(_)) {
        p.line_segment([last, end], line);
    } else {
        p.line_segment([last, s.left_center()], line);
        p.line_segment([s.right_center(), end], line);
    }
    match &c.kind {
        // A shaft with its own inertia: a solid bar, the mass along it, over the spring.
        ConnectionKind::Shaft(shaft) if shaft.inertia_kg_m2 > 0.0 => {
            let bar = egui::Rect::from_center_size(s.center(), vec2(s.width(), 0.6 * s.height()));
            p.rect_filled(bar, 3.0, color.gamma_multiply(0.45));
            spring(p, s, Stroke::new(1.5, color));
        }
        ConnectionKind::Shaft(_) => spring(p, s, Stroke::new(1.5, color)),
        ConnectionKind::Rubber(r) => {
            p.rect_filled(s, 4.0, color.gamma_multiply(0.85));
            p.rect_stroke(s, 4.0, Stroke::new(1.0, color), StrokeKind::Inside);
            let stripes = match &r.stiffness {
                RubberStiffness::Elements(e) => e.count.clamp(2, 12) as usize,
                RubberStiffness::Direct(_) => 4,
            };
            for k in 1..stripes {
                let x = s.left() + s.width() * k as f32 / stripes as f32;
                p.line_segment(
                    [pos2(x, s.top() + 3.0), pos2(x, s.bottom() - 3.0)],
                    Stroke::new(1.0, pal.background.gamma_multiply(0.5)),
                );
            }
            // Cut to the width of the line between its two nodes (as the node names are
            // cut to their column): two stages side by side wrote over each other.
            let room = (link.line[n - 1].x - link.line[0].x).abs().max(s.width());
            let max_chars = ((room - 4.0) / 6.0).max(4.0) as usize;
            p.text(
                s.center_top() - vec2(0.0, 4.0),
                Align2::CENTER_BOTTOM,
                short(&c.name, max_chars),
                FontId::proportional(11.0),
                color,
            );
        }
        ConnectionKind::Gear(gear) => {
            let [r1, r2] = link.wheels.unwrap_or([0.25 * s.width(); 2]);
            let (c1, c2) = (
                pos2(s.left() + r1, s.center().y),
                pos2(s.right() - r2, s.center().y),
            );
            wheel(p, pal, c1, r1, color);
            wheel(p, pal, c2, r2, color);
            p.text(
                pos2(s.center().x, s.center().y + r1.max(r2) + 2.0),
                Align2::CENTER_TOP,
                speed_ratio_label(gear.ratio),
                FontId::proportional(11.0),
                color,
            );
        }
    }
}
