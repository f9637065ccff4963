//! Issue 16, deliverable 6, on the real app: the "?" beside each tab explains it, and a
//! selected Campbell crossing runs the time domain at its speed ("Simulate at … rpm").
//! The teaching presets' modes against their closed forms are held by their `[expect]`
//! (`torsim check`, and `tests/presets.rs`).

use crate::gui::app::{Tab, TorsimApp};
use crate::gui::tests::support::{app_on, step_until};
use crate::gui::trace_state::TraceMode;
use crate::gui::views::plots::CrossingKey;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

fn harness() -> Harness<'static, TorsimApp> {
    app_on("two-inertia", [1280.0, 800.0])
}

#[test]
fn every_tab_has_its_explanation() {
    let mut h = harness();
    h.run_steps(2);
    let marks: Vec<_> = h.get_all_by_label("?").collect();
    assert_eq!(marks.len(), 5, "one ? per tab");
    for tab in [
        Tab::Campbell,
        Tab::Modes,
        Tab::Response,
        Tab::Traces,
        Tab::Diagnosis,
    ] {
        let text = crate::gui::views::help::tab_help(tab);
        let sentences = text.matches(". ").count() + 1;
        assert!(
            (3..=4).contains(&sentences),
            "{tab:?}: {sentences} sentences"
        );
    }
}

/// The two-inertia preset's order-2 crossing is at 1169.5 rpm (closed form); "Simulate
/// at 1170 rpm" opens the Time traces tab on a steady run there.
#[test]
fn a_crossing_runs_the_time_domain_at_its_speed() {
    let mut h = harness();
    step_until(&mut h, |a| a.results.campbell.is_some());
    h.state_mut().plots.crossing = Some(CrossingKey {
        order: 2.0,
        mode: 1,
    });
    h.run_steps(3);
    h.get_by_label("Simulate at 1170 rpm").click();
    h.run_steps(2);
    let app = h.state();
    assert_eq!(app.tab, Tab::Traces);
    assert_eq!(app.traces.mode, TraceMode::Steady);
    assert!(
        (app.trace_speed_rpm - 1169.545).abs() < 0.1,
        "{}",
        app.trace_speed_rpm
    );
}

/// The engine editor draws the working cycle the simulation thread computed: on
/// cng-genset, six cylinders' mean gas torque is 250 kW at 1800 rpm (seed 000).
#[test]
fn the_engine_cycle_comes_from_the_simulation_thread() {
    let mut h = app_on("cng-genset", [1280.0, 2600.0]);
    step_until(&mut h, |a| a.results.engine_cycle.is_some());
    let mean = h
        .state()
        .results
        .engine_cycle
        .as_ref()
        .expect("cycle")
        .mean_torque_nm;
    assert!(
        (mean - 250e3 / (1800.0 * std::f64::consts::TAU / 60.0)).abs() < 1.0,
        "{mean}"
    );
    h.get_by_label("Engine and harmonics").click();
    h.run_steps(4);
    h.get_by_label_contains("cycle at full load");
}
