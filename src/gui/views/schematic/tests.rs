//! The schematic's layout of a branched geared driveline: every node in a cell of its
//! own, the main line to the load, branches on lanes of their own, no symbol overlapping
//! another, wheels in proportion to the ratio, and each element found under its point.

use super::Selection;
use crate::gui::views::schematic::geometry;
use crate::gui::views::schematic::layout;
use crate::gui::views::schematic::symbols::speed_ratio_label;
use egui::{Pos2, Rect, pos2};
use torsim::model::{Model, parse_model};

/// A driveline with a gearbox splitting to a propeller (the load) and a PTO generator.
const BRANCHED: &str = r#"
format = 1
name = "branched"
[[inertia]]
name = "damper"
inertia = 0.02
[[inertia]]
name = "crank"
inertia = 0.15
[[inertia]]
name = "flywheel"
inertia = 0.9
[[inertia]]
name = "gear_in"
inertia = 0.05
[[inertia]]
name = "prop_pinion"
inertia = 0.3
[[inertia]]
name = "propeller"
inertia = 12.0
[[inertia]]
name = "pto_pinion"
inertia = 0.01
[[inertia]]
name = "pto_hub"
inertia = 0.02
[[inertia]]
name = "generator"
inertia = 0.6
[[inertia]]
name = "pump"
inertia = 0.004
[[connection]]
kind = "shaft"
name = "nose"
from = "damper"
to = "crank"
stiffness = 2e5
[[connection]]
kind = "shaft"
name = "crank_rear"
from = "crank"
to = "flywheel"
stiffness = 4e5
[[connection]]
kind = "rubber"
name = "main_coupling"
from = "flywheel"
to = "gear_in"
stiffness = 9000
psi = 1.0
[[connection]]
kind = "gear"
name = "prop_stage"
from = "gear_in"
to = "prop_pinion"
ratio = 0.4
[[connection]]
kind = "shaft"
name = "prop_shaft"
from = "prop_pinion"
to = "propeller"
stiffness = 3e5
[[connection]]
kind = "gear"
name = "pto_stage"
from = "gear_in"
to = "pto_pinion"
ratio = 1.5
mesh_stiffness = 1e6
[[connection]]
kind = "rubber"
name = "pto_coupling"
from = "pto_pinion"
to = "pto_hub"
stiffness = 3000
psi = 0.8
[[connection]]
kind = "shaft"
name = "gen_shaft"
from = "pto_hub"
to = "generator"
stiffness = 1e5
[[connection]]
kind = "gear"
name = "pump_drive"
from = "crank"
to = "pump"
ratio = 2.0
[[harmonic]]
at = "crank"
order = 2.0
amplitude = 50.0
phase_deg = 0.0
[load]
at = "propeller"
damping = 20
"#;

fn branched() -> Model {
    parse_model(BRANCHED, "branched").expect("branched model")
}

#[test]
fn branched_geared_layout_has_no_overlaps() {
    let model = branched();
    let l = layout::layout(&model);
    // Every node placed, each in a cell of its own; every connection drawn.
    let cells: Vec<[i32; 2]> = l.nodes.iter().map(|c| c.expect("placed")).collect();
    for (a, ca) in cells.iter().enumerate() {
        for cb in &cells[a + 1..] {
            assert_ne!(ca, cb);
        }
    }
    assert_eq!(l.links.len(), model.connections.len());
    // The main line runs from the damper to the load (propeller), left to right.
    let lane = cells[5][1];
    let main: Vec<&str> = (0..l.columns)
        .filter_map(|x| cells.iter().position(|c| *c == [x, lane]))
        .map(|i| model.inertias[i].name.as_str())
        .collect();
    assert_eq!(
        main,
        [
            "damper",
            "crank",
            "flywheel",
            "gear_in",
            "prop_pinion",
            "propeller"
        ]
    );
    // The PTO branch goes below, the pump above, each on a lane of its own.
    assert_eq!(cells[6], [4, lane + 1], "pto_pinion");
    assert_eq!(cells[9], [2, lane - 1], "pump");
    // Tree connections go one column to the right.
    assert!(l.links.iter().all(|k| k.tree && k.to[0] == k.from[0] + 1));
    let g = geometry::geometry(
        &model,
        &l,
        Rect::from_min_size(Pos2::ZERO, geometry::desired_size(&l)),
    );
    let mut boxes: Vec<(String, Rect)> = Vec::new();
    for (i, d) in g.disks.iter().enumerate() {
        boxes.push((model.inertias[i].name.clone(), d.expect("drawn")));
    }
    for link in &g.links {
        boxes.push((model.connections[link.connection].name.clone(), link.symbol));
    }
    for (a, (na, ra)) in boxes.iter().enumerate() {
        for (nb, rb) in &boxes[a + 1..] {
            assert!(!ra.intersects(*rb), "{na} {ra:?} overlaps {nb} {rb:?}");
        }
    }
    // Gear wheels in proportion: the `to` wheel of ratio 0.4 is 2.5 times the `from` wheel.
    let wheels = g.links[3].wheels.expect("gear");
    assert!((wheels[1] / wheels[0] - 2.5).abs() < 1e-5, "{wheels:?}");
    // Each element under its own point.
    for sel in (0..model.inertias.len())
        .map(Selection::Inertia)
        .chain((0..model.connections.len()).map(Selection::Connection))
        .chain([Selection::Load])
    {
        let p = g.point_of(sel).expect("drawn");
        assert_eq!(g.hit(p), Some(sel));
    }
    assert_eq!(g.hit(pos2(-100.0, -100.0)), None);
}

#[test]
fn gear_labels_read_as_speed_ratios() {
    assert_eq!(speed_ratio_label(0.4), "2.5:1");
    assert_eq!(speed_ratio_label(1.0 / 3.0), "3:1");
    assert_eq!(speed_ratio_label(1.5), "1:1.5");
    assert_eq!(speed_ratio_label(-2.0), "1:2 rev.");
}
