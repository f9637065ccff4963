//! What the window's tests share: the real app on a preset at a window size, and stepping
//! it until the simulation thread has delivered what a test waits for.

use crate::gui::app::TorsimApp;
use egui_kittest::Harness;
use std::time::{Duration, Instant};
use torsim::model::{Model, parse_model, presets};

/// The preset `name` as a model.
pub(super) fn preset_model(name: &str) -> Model {
    let p = presets::preset(name).expect("preset");
    parse_model(p.text, p.name).expect("model")
}

/// The real app on preset `name` in a window of `size` points.
pub(super) fn app_on(name: &'static str, size: [f32; 2]) -> Harness<'static, TorsimApp> {
    Harness::builder().with_size(size).build_eframe(move |cc| {
        let ctx = cc.egui_ctx.clone();
        TorsimApp::new(preset_model(name), None, move || ctx.request_repaint())
    })
}

/// Steps `h` (the simulation thread works meanwhile) until `done` holds, at most 60 s.
pub(super) fn step_until(h: &mut Harness<'static, TorsimApp>, done: impl Fn(&TorsimApp) -> bool) {
    let start = Instant::now();
    while !done(h.state()) {
        assert!(start.elapsed() < Duration::from_secs(60), "timed out");
        std::thread::sleep(Duration::from_millis(20));
        h.step();
    }
}

/// The integration tests' scratch directory (`tests/scratch`), one guard for both.
#[path = "../../../tests/scratch/mod.rs"]
mod scratch;
pub(super) use scratch::Scratch;
