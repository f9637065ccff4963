//! Issue 16, deliverable 5, in the window: a rated coupling's limits are drawn on its
//! torque and power-loss plots (and exported with them), and the limits it exceeds are
//! said above the plot — in the operating range, outside it, and where the linear model
//! leaves its range.

use crate::gui::app::{Tab, TorsimApp};
use crate::gui::tests::support::{app_on, step_until};
use crate::gui::views::plots::{Quantity, plot_data};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

fn harness(preset: &'static str) -> Harness<'static, TorsimApp> {
    let mut h = app_on(preset, [1280.0, 800.0]);
    step_until(&mut h, |a| a.results.ratings.is_some());
    h.state_mut().tab = Tab::Response;
    h.run_steps(3);
    h
}

fn columns(h: &Harness<'static, TorsimApp>) -> Vec<String> {
    plot_data(h.state())
        .expect("plot data")
        .columns
        .into_iter()
        .map(|(name, _)| name)
        .collect()
}

#[test]
fn a_rated_coupling_shows_its_limits() {
    let mut h = harness("cng-genset");
    h.state_mut().plots.quantity = Quantity::Torque;
    h.state_mut().plots.connection = Some("coupling".into());
    h.run_steps(2);
    let names = columns(&h);
    for wanted in [
        "T_KN / S_t [N·m]",
        "T_Kmax / S_t [N·m]",
        "T_KW / (S_t S_f) for order 3 [N·m]",
    ] {
        assert!(names.iter().any(|n| n == wanted), "{wanted} in {names:?}");
    }
    h.state_mut().plots.quantity = Quantity::PowerLoss;
    h.run_steps(2);
    assert!(columns(&h).iter().any(|n| n == "P_KV at the ambient [W]"));
    // cng-genset holds its ratings in 1000–2000 rpm; the 520 rpm resonance does not.
    assert!(
        h.query_by_label_contains("Ratings exceeded in the operating range")
            .is_none()
    );
    h.get_by_label_contains("rating(s) exceeded outside the operating range");
    h.get_by_label_contains("Beyond the linear model");
    // A shaft has no rating: no limit lines.
    h.state_mut().plots.connection = Some("crank_12".into());
    h.run_steps(2);
    assert!(!columns(&h).iter().any(|n| n.contains("P_KV")));
}

#[test]
fn an_undersized_coupling_is_flagged_in_the_operating_range() {
    let h = harness("genset-20dof");
    h.get_by_label_contains(
        "Ratings exceeded in the operating range (DIN 740-2): coupling_stage1 T_KW",
    );
}
