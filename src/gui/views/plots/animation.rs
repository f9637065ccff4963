//! The animated mode: each inertia a disk whose radius line turns by its modal amplitude
//! × sin(2π·f_anim·t), in driveline order, the springs between them coloured by their
//! share of the strain energy. Drawn with the painter; repaints only while playing.

use super::PlotState;
use crate::gui::views::plots::modes::driveline_order;
use egui::{Align2, Color32, FontId, Pos2, Sense, Stroke, Ui, pos2, vec2};
use std::f64::consts::TAU;
use torsim::modal::Mode;
use torsim::physics::{ElementLaw, System};

/// Visual frequency of the animation, Hz (the mode's own is far too fast to see).
const VISUAL_HZ: f64 = 0.6;
/// Time between the animation's frames, ms: 33 (30 frames a second).
const ANIMATION_FRAME_MS: u64 = 33;

/// Colour of a spring by its strain energy relative to the largest: grey to hot orange.
fn heat(share: f64) -> Color32 {
    let t = share.clamp(0.0, 1.0) as f32;
    let lerp = |a: u8, b: u8| (f32::from(a) + t * (f32::from(b) - f32::from(a))) as u8;
    Color32::from_rgb(lerp(110, 255), lerp(110, 120), lerp(110, 30))
}

/// A zigzag from `a` to `b` (a rubber stage), or a straight line (a shaft or mesh).
fn spring(painter: &egui::Painter, a: Pos2, b: Pos2, zigzag: bool, stroke: Stroke) {
    if !zigzag {
        painter.line_segment([a, b], stroke);
        return;
    }
    let d = b - a;
    let normal = vec2(-d.y, d.x).normalized() * 7.0;
    let mut points = vec![a, a + 0.15 * d];
    for k in 0..8_u32 {
        let t = 0.15 + 0.7 * (k as f32 + 0.5) / 8.0;
        let side = if k.is_multiple_of(2) { 1.0 } else { -1.0 };
        points.push(a + t * d + side * normal);
    }
    points.extend([a + 0.85 * d, b]);
    painter.add(egui::Shape::line(points, stroke));
}

/// Play/pause, amplitude, and the animated driveline for `mode`; `shares` per element,
/// `inertias_kg_m2` per node (own shaft) when known, for the disk sizes.
pub fn animation_ui(
    state: &mut PlotState,
    ui: &mut Ui,
    system: &System,
    mode: &Mode,
    shares: &[f64],
    inertias_kg_m2: Option<&[f64]>,
    color: Color32,
) {
    ui.horizontal_wrapped(|ui| {
        let label = if state.playing { "Pause" } else { "Play" };
        if ui.button(label).clicked() {
            state.playing = !state.playing;
        }
        let l = ui.label("amplitude");
        ui.add(egui::Slider::new(&mut state.amplitude_deg, 2.0..=60.0).suffix("° max"))
            .labelled_by(l.id);
    });
    let note = format!(
        "shown at {VISUAL_HZ} Hz, not {:.1} Hz; rotation not to scale (largest = slider)",
        mode.frequency_hz
    );
    ui.add(egui::Label::new(egui::RichText::new(note).weak()).wrap());
    if state.playing {
        let dt = ui.input(|i| f64::from(i.stable_dt).min(0.1));
        state.phase_cycles = (state.phase_cycles + dt * VISUAL_HZ).fract();
        // 30 frames a second draw a 0.6 Hz swing smoothly, at a fraction of the display
        // rate's cost.
        ui.ctx()
            .request_repaint_after(std::time::Duration::from_millis(ANIMATION_FRAME_MS));
    }
    let size = ui.available_size().max(vec2(200.0, 180.0));
    let (rect, _) = ui.allocate_exact_size(size, Sense::hover());
    let painter = ui.painter_at(rect);
    let order = driveline_order(system);
    let shape = mode.shape_by_node(system);
    let count = order.len().max(1) as f32;
    let pitch = rect.width() / count;
    let max_r = (0.4 * pitch).min(0.2 * rect.height()).max(6.0);
    let j_max = inertias_kg_m2.map_or(1.0, |j| j.iter().copied().fold(0.0, f64::max));
    let radius = |k: usize| {
        let j = inertias_kg_m2
            .and_then(|j| j.get(k))
            .copied()
            .unwrap_or(j_max);
        max_r * ((j / j_max).powf(0.25) as f32).clamp(0.45, 1.0)
    };
    let y = rect.center().y;
    let centre = |pos: usize| pos2(rect.left() + pitch * (pos as f32 + 0.5), y);
    let position_of_node: Vec<usize> = {
        let mut p = vec![0; order.len()];
        for (pos, &k) in order.iter().enumerate() {
            p[k] = pos;
        }
        p
    };
    // The first node of a DOF stands for it.
    let node_of_dof = |d: usize| {
        order
            .iter()
            .position(|&k| system.dof_of_node[k] == d)
            .map(|pos| (pos, order[pos]))
    };
    let text = ui.visuals().text_color();
    let weak = ui.visuals().weak_text_color();
    let drawn = springs(system, shares);
    let largest = drawn
        .iter()
        .map(|s| s.share)
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    for (n, spring_at) in drawn.into_iter().enumerate() {
        let Spring {
            from_dof,
            to_dof,
            connection,
            share,
            zigzag,
        } = spring_at;
        // Labels of neighbouring springs at two heights, so long names do not overlap.
        let stagger = if n.is_multiple_of(2) { 0.0 } else { -26.0 };
        let stroke = Stroke::new(1.5 + 4.0 * share as f32, heat(share / largest));
        let ends = (from_dof.and_then(node_of_dof), to_dof.and_then(node_of_dof));
        let (a, b, label_at) = match ends {
            (Some((pa, ka)), Some((pb, kb))) => {
                let (a, b) = (centre(pa), centre(pb));
                let dir = (b - a).normalized();
                let (a, b) = (a + dir * radius(ka), b - dir * radius(kb));
                let lift = if pa.abs_diff(pb) > 1 {
                    -max_r * 1.4
                } else {
                    0.0
                };
                let (a, b) = (a + vec2(0.0, lift), b + vec2(0.0, lift));
                let label_y = y - max_r - 6.0 + stagger + lift;
                (a, b, pos2(a.lerp(b, 0.5).x, label_y))
            }
            (Some((p, k)), None) | (None, Some((p, k))) => {
                let a = centre(p) - vec2(0.0, radius(k));
                let b = a - vec2(0.0, 0.2 * rect.height());
                painter.line_segment(
                    [b + vec2(-12.0, 0.0), b + vec2(12.0, 0.0)],
                    Stroke::new(2.0, weak),
                );
                (a, b, a.lerp(b, 0.5) + vec2(24.0, 0.0))
            }
            (None, None) => continue,
        };
        spring(&painter, a, b, zigzag, stroke);
        if share >= 0.005 {
            let name = system
                .connection_names
                .get(connection)
                .map_or("", String::as_str);
            painter.text(
                label_at,
                Align2::CENTER_BOTTOM,
                format!("{name}\n{:.0} %", 100.0 * share),
                FontId::proportional(11.0),
                if share >= 0.25 { text } else { weak },
            );
        }
    }
    let swing = f64::from(state.amplitude_deg).to_radians() * (TAU * state.phase_cycles).sin();
    for (k, name) in system.node_names.iter().enumerate() {
        let c = centre(position_of_node[k]);
        let r = radius(k);
        painter.circle(c, r, color.gamma_multiply(0.25), Stroke::new(1.5, color));
        // The swing's envelope, so that a still picture shows the shape too.
        let reach = (f64::from(state.amplitude_deg).to_radians() * shape[k].abs()) as f32;
        if reach > 0.05 {
            let arc = (0..=16).map(|i| {
                let t = -reach + 2.0 * reach * i as f32 / 16.0;
                c + r * vec2(t.sin(), -t.cos())
            });
            let wedge: Vec<Pos2> = std::iter::once(c).chain(arc).collect();
            painter.add(egui::Shape::convex_polygon(
                wedge,
                text.gamma_multiply(0.18),
                Stroke::NONE,
            ));
        }
        painter.line_segment([c, c - vec2(0.0, r)], Stroke::new(1.0, weak));
        let angle = (swing * shape[k]) as f32;
        let tip = c + r * vec2(angle.sin(), -angle.cos());
        painter.line_segment([c, tip], Stroke::new(3.0, text));
        painter.circle_filled(c, 2.5, text);
        let stagger = if position_of_node[k].is_multiple_of(2) {
            0.0
        } else {
            30.0
        };
        painter.text(
            c + vec2(0.0, max_r + 8.0 + stagger),
            Align2::CENTER_TOP,
            format!("{name}\n{:+.2}", shape[k]),
            FontId::proportional(12.0),
            text,
        );
    }
}

/// A spring as drawn: a distributed shaft once between its end nodes with the strain
/// energy of all its segments, every other element as it is.
struct Spring {
    from_dof: Option<usize>,
    to_dof: Option<usize>,
    connection: usize,
    share: f64,
    zigzag: bool,
}

fn springs(system: &System, shares: &[f64]) -> Vec<Spring> {
    let mut out: Vec<Spring> = Vec::new();
    for (i, (e, &share)) in system.elements.iter().zip(shares).enumerate() {
        match system.distributed.iter().find(|d| d.elements.contains(&i)) {
            Some(d) if d.elements.start != i => {
                if let Some(last) = out.last_mut() {
                    last.share += share;
                }
            }
            Some(d) => out.push(Spring {
                from_dof: d.from_dof,
                to_dof: d.to_dof,
                connection: d.connection,
                share,
                zigzag: false,
            }),
            None => out.push(Spring {
                from_dof: e.from_dof,
                to_dof: e.to_dof,
                connection: e.connection,
                share,
                zigzag: matches!(e.law, ElementLaw::Rubber { .. } | ElementLaw::Causal { .. }),
            }),
        }
    }
    out
}
