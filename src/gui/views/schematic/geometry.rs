//! The schematic on screen: the grid layout mapped into a rectangle, with the size of each
//! disk, where each connection's symbol goes, the engine and load symbols, and what lies
//! under a point. Pure functions of the model, the layout and the rectangle.

use super::Selection;
use crate::gui::views::schematic::layout::{Cell, Layout};
use egui::{Pos2, Rect, Vec2, pos2, vec2};
use torsim::model::{ConnectionKind, Model};

/// Smallest and largest column pitch, points.
const COLUMN_PITCH: [f32; 2] = [64.0, 150.0];
/// Lane pitch, points.
pub const LANE_PITCH: f32 = 84.0;
/// Tallest disk, points (100 kg·m² and more).
pub const DISK_MAX: f32 = 52.0;
/// Room above the top lane for the engine's cylinders and its label, points.
const TOP: f32 = 50.0;
/// Room below the bottom lane's disks for names, points.
const BOTTOM: f32 = 26.0;
/// Left and right margin, points.
const SIDE: f32 = 8.0;

/// Disk height for an inertia, points: log scale, 10 pt at 0.001 kg·m², 8.5 pt more per
/// decade, at most [`DISK_MAX`] (so 0.01 and 10 kg·m² are 18.5 and 44 pt).
pub fn disk_height(inertia_kg_m2: f64) -> f32 {
    let decades = (inertia_kg_m2.max(1e-12) / 1e-3).log10() as f32;
    (10.0 + 8.5 * decades).clamp(10.0, DISK_MAX)
}

/// A connection on screen.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkShape {
    /// Index in `model.connections`.
    pub connection: usize,
    /// The shaft line from one end to the other (with the elbow, if any).
    pub line: Vec<Pos2>,
    /// Where the symbol (spring, rubber block, gear pair) is drawn.
    pub symbol: Rect,
    /// A loop connection, drawn as an arc through `symbol`'s centre.
    pub arc: bool,
    /// Radii of a gear pair's wheels (`from`, `to`), points.
    pub wheels: Option<[f32; 2]>,
}

/// Everything's place on screen.
#[derive(Debug, Clone, PartialEq)]
pub struct Geometry {
    /// Centre of each inertia's disk (model order).
    pub centers: Vec<Option<Pos2>>,
    /// Each inertia's disk.
    pub disks: Vec<Option<Rect>>,
    /// Where each inertia's name is written (centre top).
    pub labels: Vec<Option<Pos2>>,
    /// Connections.
    pub links: Vec<LinkShape>,
    /// Frame symbols: (connection, attachment point).
    pub grounds: Vec<(usize, Pos2)>,
    /// Engine: its outline and its cylinders (bore rectangle, crank point).
    pub engine: Option<(Rect, Vec<(Rect, Pos2)>)>,
    /// Load: the brake's outline around the disk of the load node.
    pub load: Option<Rect>,
    /// Horizontal pitch, points.
    pub column_pitch: f32,
}

/// The size the schematic needs at the smallest column pitch.
pub fn desired_size(layout: &Layout) -> Vec2 {
    let lanes = (layout.lanes[1] - layout.lanes[0]) as f32;
    vec2(
        layout.columns.max(1) as f32 * COLUMN_PITCH[0] + 2.0 * SIDE,
        TOP + DISK_MAX + lanes * LANE_PITCH + BOTTOM,
    )
}

/// Maps `layout` into `rect` (centred horizontally).
pub fn geometry(model: &Model, layout: &Layout, rect: Rect) -> Geometry {
    let columns = layout.columns.max(1) as f32;
    let dx = ((rect.width() - 2.0 * SIDE) / columns).clamp(COLUMN_PITCH[0], COLUMN_PITCH[1]);
    let left = rect.center().x - 0.5 * columns * dx;
    let at = |c: Cell| {
        pos2(
            left + (c[0] as f32 + 0.5) * dx,
            rect.top() + TOP + 0.5 * DISK_MAX + (c[1] - layout.lanes[0]) as f32 * LANE_PITCH,
        )
    };
    let mut g = Geometry {
        centers: layout.nodes.iter().map(|c| c.map(at)).collect(),
        disks: Vec::new(),
        labels: Vec::new(),
        links: Vec::new(),
        grounds: layout.grounds.iter().map(|&(j, c)| (j, at(c))).collect(),
        engine: None,
        load: None,
        column_pitch: dx,
    };
    g.disks = g
        .centers
        .iter()
        .zip(&model.inertias)
        .map(|(c, node)| {
            c.map(|c| {
                let h = disk_height(node.inertia_kg_m2);
                Rect::from_center_size(c, vec2((0.28 * h).clamp(6.0, 14.0), h))
            })
        })
        .collect();
    g.labels = g
        .centers
        .iter()
        .map(|c| c.map(|c| c + vec2(0.0, 0.5 * DISK_MAX + 3.0)))
        .collect();
    let half_width = |cell: Cell| {
        layout
            .nodes
            .iter()
            .position(|&n| n == Some(cell))
            .and_then(|i| g.disks[i])
            .map_or(8.0, |d| 0.5 * d.width())
    };
    for link in &layout.links {
        let (a, b) = (at(link.from), at(link.to));
        let shape = if !link.tree {
            let apex = pos2(0.5 * (a.x + b.x), a.y.min(b.y) - 0.5 * LANE_PITCH + 6.0);
            LinkShape {
                connection: link.connection,
                line: vec![a, apex, b],
                symbol: Rect::from_center_size(apex, vec2(28.0, 16.0)),
                arc: true,
                wheels: None,
            }
        } else {
            // Straight, or down/up at the parent's column and then to the right.
            let corner = pos2(a.x, b.y);
            let start_x = if link.from[1] == link.to[1] {
                a.x + half_width(link.from) + 2.0
            } else {
                a.x
            };
            let end_x = b.x - half_width(link.to) - 2.0;
            let span = (end_x - start_x).max(8.0);
            let mid = pos2(start_x + 0.5 * span, b.y);
            let mut wheels = None;
            let size = match &model.connections[link.connection].kind {
                ConnectionKind::Gear(gear) => {
                    let (r1, r2) = gear_radii(gear.ratio, span);
                    wheels = Some([r1, r2]);
                    vec2(2.0 * (r1 + r2), 2.0 * r1.max(r2))
                }
                ConnectionKind::Rubber(_) => vec2(0.5 * span, 22.0),
                ConnectionKind::Shaft(_) => vec2(0.6 * span, 16.0),
            };
            let line = if corner == a {
                vec![a, b]
            } else {
                vec![a, corner, b]
            };
            LinkShape {
                connection: link.connection,
                line,
                symbol: Rect::from_center_size(mid, size),
                arc: false,
                wheels,
            }
        };
        g.links.push(shape);
    }
    g.engine = engine_shape(model, &g);
    g.load = model
        .load_node()
        .and_then(|name| model.node_index(name))
        .filter(|_| model.load.is_some() || (model.engine.is_some() && !model.is_grounded()))
        .and_then(|i| g.disks[i])
        .map(|d| {
            Rect::from_min_max(
                pos2(d.left() - 9.0, d.center().y),
                pos2(d.right() + 9.0, d.bottom() + 4.0),
            )
        });
    g
}

/// Radii of the gear pair on a link `span` points long: the `to` wheel is `1/|ratio|`
/// times the `from` wheel (it turns `ratio` times as fast), the larger at most 20 pt.
pub fn gear_radii(ratio: f64, span: f32) -> (f32, f32) {
    let ratio = if ratio.is_finite() && ratio != 0.0 {
        (ratio.abs() as f32).clamp(0.1, 10.0)
    } else {
        1.0
    };
    let (r1, r2): (f32, f32) = (1.0, 1.0 / ratio);
    let scale = (20.0 / r1.max(r2)).min(0.4 * span / (r1 + r2));
    ((r1 * scale).max(3.0), (r2 * scale).max(3.0))
}

/// Cylinders above the nodes the engine acts on.
fn engine_shape(model: &Model, g: &Geometry) -> Option<(Rect, Vec<(Rect, Pos2)>)> {
    let engine = model.engine.as_ref()?;
    let mut per_node: Vec<(usize, usize)> = Vec::new();
    for cylinder in 0..engine.cylinders.min(64) as usize {
        let name = if engine.at.len() == 1 {
            engine.at.first()
        } else {
            engine.at.get(cylinder)
        };
        let Some(i) = name.and_then(|n| model.node_index(n)) else {
            continue;
        };
        match per_node.iter_mut().find(|(node, _)| *node == i) {
            Some((_, k)) => *k += 1,
            None => per_node.push((i, 1)),
        }
    }
    let mut cylinders = Vec::new();
    for (i, k) in per_node {
        let Some(c) = g.centers[i] else { continue };
        let width = (0.8 * g.column_pitch / k as f32).min(20.0);
        let bottom = c.y - 0.5 * DISK_MAX - 6.0;
        for m in 0..k {
            let x = c.x + (m as f32 - 0.5 * (k as f32 - 1.0)) * width;
            let bore = Rect::from_min_max(
                pos2(x - 0.42 * width, bottom - 22.0),
                pos2(x + 0.42 * width, bottom),
            );
            cylinders.push((bore, pos2(c.x, c.y - 0.5 * DISK_MAX + 4.0)));
        }
    }
    let outline = cylinders
        .iter()
        .fold(Rect::NOTHING, |r, (bore, _)| r.union(*bore))
        .expand(3.0);
    (!cylinders.is_empty()).then_some((outline, cylinders))
}

impl Geometry {
    /// The element under `pos`: disks and names first, then the load, the engine and the
    /// connection symbols.
    pub fn hit(&self, pos: Pos2) -> Option<Selection> {
        for (i, disk) in self.disks.iter().enumerate() {
            let Some(disk) = disk else { continue };
            let grab = Rect::from_center_size(
                disk.center(),
                vec2(disk.width().max(16.0), disk.height() + 6.0),
            );
            let name = self.labels[i].map(|l| {
                Rect::from_min_size(
                    l - vec2(0.4 * self.column_pitch, 0.0),
                    vec2(0.8 * self.column_pitch, 14.0),
                )
            });
            if grab.contains(pos) || name.is_some_and(|r| r.contains(pos)) {
                return Some(Selection::Inertia(i));
            }
        }
        if self.load.is_some_and(|r| r.contains(pos)) {
            return Some(Selection::Load);
        }
        if self.engine.as_ref().is_some_and(|(r, _)| r.contains(pos)) {
            return Some(Selection::Engine);
        }
        self.links
            .iter()
            .find(|l| l.symbol.expand(3.0).contains(pos))
            .map(|l| Selection::Connection(l.connection))
    }

    /// A point on the element that [`Geometry::hit`] maps back to it, if drawn.
    #[cfg(test)]
    pub fn point_of(&self, selection: Selection) -> Option<Pos2> {
        match selection {
            Selection::Inertia(i) => self.disks.get(i).copied().flatten().map(|d| d.center()),
            Selection::Connection(j) => self
                .links
                .iter()
                .find(|l| l.connection == j)
                .map(|l| l.symbol.center()),
            Selection::Engine => self
                .engine
                .as_ref()
                .map(|(r, _)| r.center_top() + vec2(0.0, 6.0)),
            Selection::Load => self.load.map(|r| pos2(r.left() + 4.0, r.center().y)),
        }
    }
}
