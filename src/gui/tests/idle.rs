//! Issue 16, deliverable 2: idle is idle. Once every result of the worker has arrived, a
//! frame of each tab asks for no further frame and sends the window no command (the
//! title was sent on every frame, and a viewport command repaints: 183 % of two cores
//! measured idle under Xvfb before). The mode-shape animation repaints only while it
//! plays, at 30 frames a second. `scripts/gui-idle-cpu.sh` measures the real window.

use crate::gui::app::TorsimApp;
use crate::gui::tests::support::{app_on, step_until};
use egui::ViewportId;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use std::time::Duration;

fn harness() -> Harness<'static, TorsimApp> {
    app_on("two-inertia", [1280.0, 800.0])
}

/// Every result of the worker is in: modes, response, the finished time run and its
/// order analysis, and the thread is done with the request, so that no wake-up of it is
/// still on its way (CI saw one land after six frames on a busy machine).
fn all_in(a: &TorsimApp) -> bool {
    let r = &a.results;
    a.worker.finished() == r.generation
        && r.campbell.is_some()
        && r.response.is_some()
        && r.trace.is_some()
        && r.trace_analysis.is_some()
        && r.live.is_some()
}

/// Steps until the app is quiet, then asserts that three more frames ask for nothing.
fn assert_idle(h: &mut Harness<'static, TorsimApp>, what: &str) {
    step_until(h, all_in);
    h.remove_cursor();
    h.run_steps(6);
    for _ in 0..3 {
        h.step();
        let out = &h.output().viewport_output[&ViewportId::ROOT];
        assert_eq!(
            out.repaint_delay,
            Duration::MAX,
            "{what}: an idle frame asked for another"
        );
        assert!(out.commands.is_empty(), "{what}: {:?}", out.commands);
    }
}

#[test]
fn every_tab_is_idle_once_its_results_are_in() {
    let mut h = harness();
    h.run_steps(2);
    for tab in [
        "Campbell",
        "Mode shapes",
        "Forced response",
        "Time traces",
        "Diagnosis",
    ] {
        h.get_by_label(tab).click();
        assert_idle(&mut h, tab);
    }
}

#[test]
fn the_title_is_sent_when_it_changes() {
    let mut h = harness();
    assert_idle(&mut h, "start");
    let app = h.state_mut();
    let before = app.model.clone();
    app.model.name = "renamed".into();
    app.commit(before);
    h.step();
    let out = &h.output().viewport_output[&ViewportId::ROOT];
    assert!(
        out.commands
            .iter()
            .any(|c| matches!(c, egui::ViewportCommand::Title(t) if t.contains("renamed"))),
        "{:?}",
        out.commands
    );
}

#[test]
fn the_animation_repaints_only_while_it_plays() {
    let mut h = harness();
    h.get_by_label("Mode shapes").click();
    assert_idle(&mut h, "paused");
    h.get_by_label("Play").click();
    h.run_steps(2);
    let delay = h.output().viewport_output[&ViewportId::ROOT].repaint_delay;
    assert!(delay <= Duration::from_millis(34), "{delay:?}");
    h.get_by_label("Pause").click();
    assert_idle(&mut h, "paused again");
}
