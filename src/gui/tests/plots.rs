//! The plots driven headless by egui_kittest on the real app: clicking a Campbell crossing
//! selects it (and the selection survives an edit), the Campbell CSV, the forced-response
//! quantity selector.

use crate::gui::app::{Tab, TorsimApp};
use crate::gui::export::csv_text;
use crate::gui::views::plots::{
    self, CAMPBELL_PLOT_ID, CrossingKey, crossing_at, crossing_response,
};
use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use egui_plot::{PlotMemory, PlotPoint};
use std::time::{Duration, Instant};
use torsim::model::{ConnectionKind, RubberStiffness, parse_model, presets};

fn harness() -> Harness<'static, TorsimApp> {
    Harness::builder()
        .with_size([1400.0, 1000.0])
        .build_eframe(|cc| {
            let ctx = cc.egui_ctx.clone();
            let p = presets::preset("cng-genset").expect("preset");
            let model = parse_model(p.text, "cng-genset").expect("model");
            TorsimApp::new(model, None, move || ctx.request_repaint())
        })
}

/// Steps until `done` holds (the worker computes meanwhile), at most 60 s.
fn step_until(h: &mut Harness<'static, TorsimApp>, done: impl Fn(&TorsimApp) -> bool) {
    let start = Instant::now();
    while !done(h.state()) {
        assert!(start.elapsed() < Duration::from_secs(60), "timed out");
        std::thread::sleep(Duration::from_millis(20));
        h.step();
    }
    h.step();
}

fn ready(a: &TorsimApp) -> bool {
    a.results.campbell.is_some() && a.results.response.is_some()
}

/// A real click on the 3rd-order × mode 1 crossing (found on screen through the plot's
/// transform) selects it; the mode shown is mode 1 and the response is the 3rd order at
/// the station where it is largest at the crossing speed. A stiffer coupling moves the
/// crossing, and the selection follows it.
#[test]
fn clicking_a_crossing_selects_its_mode_and_order() {
    let mut h = harness();
    step_until(&mut h, ready);
    let x = crossing_at(
        h.state(),
        CrossingKey {
            order: 3.0,
            mode: 1,
        },
    )
    .expect("3rd order crosses mode 1");
    let memory = PlotMemory::load(&h.ctx, egui::Id::unique(CAMPBELL_PLOT_ID)).expect("plot shown");
    let pos = memory
        .transform()
        .position_from_point(&PlotPoint::new(x.speed_rpm, x.frequency_hz));
    // A few points off the marker, as a hand would be.
    let pos = pos + egui::vec2(3.0, -2.0);
    h.hover_at(pos);
    h.step();
    h.drag_at(pos);
    h.step();
    h.drop_at(pos);
    h.step();
    h.step();
    let app = h.state();
    assert_eq!(
        app.plots.crossing,
        Some(CrossingKey {
            order: 3.0,
            mode: 1
        })
    );
    assert_eq!(app.selected_mode, 0);
    assert_eq!(app.tab, Tab::Campbell, "the diagram stays on screen");
    h.get_by_label_contains("selected: order 3 × mode 1");
    h.get_by_label_contains("mode 1: 26.");
    let r = app.results.response.clone().expect("response");
    let (q, node, series) = crossing_response(app, &r, &x).expect("order 3 response");
    assert_eq!(r.orders[q], 3.0);
    let s = r
        .speeds_rpm
        .iter()
        .position(|&n| (n - x.speed_rpm).abs() <= 4.0)
        .expect("grid speed near the crossing");
    let largest = (0..r.ias_amplitude_rpm.len())
        .max_by(|&a, &b| r.ias_amplitude_rpm[a][q][s].total_cmp(&r.ias_amplitude_rpm[b][q][s]))
        .expect("nodes");
    assert_eq!(node, largest);
    let expected: Vec<[f64; 2]> = r
        .speeds_rpm
        .iter()
        .zip(&r.ias_amplitude_rpm[node][q])
        .map(|(&n, &v)| [n, v])
        .collect();
    assert_eq!(series.points, expected);
    // A click far from any crossing changes nothing.
    let empty = memory.transform().position_from_point(&PlotPoint::new(
        x.speed_rpm,
        0.8 * memory.transform().bounds().max()[1],
    ));
    h.hover_at(empty);
    h.step();
    h.drag_at(empty);
    h.step();
    h.drop_at(empty);
    h.step();
    assert_eq!(h.state().plots.crossing.map(|k| k.order), Some(3.0));

    // Double the coupling's element stiffness: the crossing moves, the selection stays.
    let before = h.state().model.clone();
    let generation = h.state().results.generation;
    if let Some(ConnectionKind::Rubber(rubber)) = h
        .state_mut()
        .model
        .connections
        .iter_mut()
        .find(|c| c.name == "coupling")
        .map(|c| &mut c.kind)
        && let RubberStiffness::Elements(e) = &mut rubber.stiffness
    {
        e.radial_stiffness_n_per_m *= 2.0;
    }
    h.state_mut().commit(before);
    step_until(&mut h, |a| {
        a.results.generation > generation
            && a.results.campbell.as_ref().is_some_and(|c| {
                c.campbell.crossings.iter().any(|y| {
                    y.order == 3.0 && y.mode == 1 && (y.speed_rpm - x.speed_rpm).abs() > 20.0
                })
            })
    });
    let app = h.state();
    let moved = crossing_at(app, app.plots.crossing.expect("still selected")).expect("exists");
    assert!(
        moved.speed_rpm > x.speed_rpm + 20.0,
        "{} -> {}",
        x.speed_rpm,
        moved.speed_rpm
    );
    h.get_by_label_contains(&format!(
        "selected: order 3 × mode 1 at {:.0} rpm",
        moved.speed_rpm
    ));
}

/// The Campbell CSV: a header with units (speed, every mode, every order) and one row per
/// speed of the grid, each order column `q·n/60`.
#[test]
fn campbell_csv_has_the_header_and_one_row_per_speed() {
    let mut h = harness();
    step_until(&mut h, ready);
    let app = h.state();
    let c = app.results.campbell.clone().expect("campbell");
    let csv = csv_text(&plots::plot_data(app).expect("data"));
    let lines: Vec<&str> = csv.lines().collect();
    let header: Vec<&str> = lines[0].split(',').collect();
    assert_eq!(header[0], "engine speed [rpm]");
    assert_eq!(header[1], "mode 1 frequency [Hz]");
    assert_eq!(
        header.len(),
        1 + c.campbell.modes.len() + c.campbell.orders.len()
    );
    assert!(header.contains(&"order 4.5 frequency [Hz]"), "{header:?}");
    assert_eq!(lines.len() - 1, c.campbell.speeds_rpm.len());
    let col = header
        .iter()
        .position(|h| *h == "order 3 frequency [Hz]")
        .expect("order 3");
    for (line, &n) in lines[1..].iter().zip(&c.campbell.speeds_rpm) {
        let cells: Vec<f64> = line
            .split(',')
            .map(|v| v.parse().expect("number"))
            .collect();
        assert_eq!(cells[0], n);
        assert_eq!(cells[1], c.campbell.modes[0].frequency_hz);
        assert_eq!(cells[col], 3.0 * n / 60.0);
    }
}

/// The quantity selector switches the forced response to torque; what is plotted (and
/// exported) is the library's torque amplitude per order in the coupling, its synthesized
/// peak and mean torque.
#[test]
fn response_quantity_switches_to_the_library_torque() {
    let mut h = harness();
    step_until(&mut h, ready);
    h.get_by_label("Forced response").click();
    h.step();
    h.get_by_role_and_label(Role::ComboBox, "quantity").click();
    h.run_steps(3);
    h.get_by_role(Role::ListBox)
        .get_by_label("torque amplitude per connection")
        .click();
    h.step();
    h.step();
    let app = h.state();
    assert_eq!(app.plots.quantity, plots::Quantity::Torque);
    h.get_by_role_and_label(Role::ComboBox, "connection");
    let r = app.results.response.clone().expect("response");
    let coupling = app
        .model
        .connections
        .iter()
        .position(|c| c.name == "coupling")
        .expect("coupling");
    let k = r
        .connections
        .iter()
        .position(|&c| c == coupling)
        .expect("entry");
    let data = plots::plot_data(app).expect("data");
    assert!(data.title.contains("coupling"), "{}", data.title);
    let mut orders_seen = 0;
    for (name, points) in &data.columns {
        let values: Vec<f64> = points.iter().map(|p| p[1]).collect();
        if let Some(q) = name
            .strip_prefix("order ")
            .and_then(|rest| rest.split(' ').next())
            .and_then(|q| q.parse::<f64>().ok())
        {
            let qi = r.orders.iter().position(|&o| o == q).expect("order");
            assert_eq!(values, r.torque_amplitude_nm[k][qi], "{name}");
            assert!(name.ends_with("[N·m]"), "{name}");
            orders_seen += 1;
        } else if name.starts_with("peak torque") {
            assert_eq!(values, r.torque_peak_nm[k]);
        }
    }
    // Every order that matters (5 % of the sum at some speed) is plotted, the largest
    // among them.
    let sum_of: Vec<f64> = (0..r.speeds_rpm.len())
        .map(|s| r.torque_amplitude_nm[k].iter().map(|o| o[s]).sum())
        .collect();
    let top = sum_of.iter().copied().fold(0.0, f64::max);
    let shown = r.torque_amplitude_nm[k]
        .iter()
        .filter(|o| plots::matters(o, &sum_of, top))
        .count();
    assert_eq!(orders_seen, shown);
    assert!(shown >= 2);
    let sum = data
        .columns
        .iter()
        .find(|(n, _)| n.starts_with("sum of order amplitudes"))
        .expect("sum");
    for (s, p) in sum.1.iter().enumerate() {
        let total: f64 = r.torque_amplitude_nm[k].iter().map(|o| o[s]).sum();
        assert!((p[1] - total).abs() <= 1e-12 * total);
    }
}

/// The mode-shape tab names the element holding most of mode 1's strain energy — the
/// coupling (seed 000: the 26 Hz mode is the coupling mode) — with the library's share,
/// and the animation, paused on open (an idle window is idle), plays and pauses.
#[test]
fn mode_tab_shows_the_strain_energy_and_pauses() {
    let mut h = harness();
    step_until(&mut h, ready);
    h.get_by_label("Mode shapes").click();
    h.run_steps(2);
    let c = h.state().results.campbell.clone().expect("campbell");
    let (system, diagram) = (&c.system, &c.campbell);
    let shares = &diagram.strain_energy_share[0];
    let (e, share) = shares
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))
        .expect("elements");
    let name = &system.connection_names[system.elements[e].connection];
    assert_eq!(name, "coupling");
    assert!(*share > 0.9, "{share}");
    h.get_by_label_contains(&format!(
        "strain energy mostly in coupling ({:.0} %)",
        100.0 * share
    ));
    assert!(!h.state().plots.playing);
    h.get_by_label("Play").click();
    h.run_steps(2);
    assert!(h.state().plots.playing);
    h.get_by_label("Pause").click();
    h.run_steps(2);
    assert!(!h.state().plots.playing);
    h.get_by_label("Play");
}
