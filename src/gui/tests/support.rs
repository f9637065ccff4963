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

/// A fresh empty directory under the system temp dir, removed with everything in it when
/// dropped, so a test leaves nothing behind, passed or failed. It derefs to its path:
/// `dir.join("x")` and `&dir` as a `&Path` work as on a `PathBuf`. Bind it to a named
/// variable (not `_`) that lives as long as the test uses the path.
#[must_use = "the directory is removed when this is dropped"]
pub(super) struct Scratch(tempfile::TempDir);

impl Scratch {
    /// A new directory whose name starts with `prefix` (a random suffix makes it unique).
    pub(super) fn new(prefix: &str) -> Self {
        Self(
            tempfile::Builder::new()
                .prefix(prefix)
                .tempdir()
                .expect("temp dir"),
        )
    }
}

impl std::ops::Deref for Scratch {
    type Target = std::path::Path;
    fn deref(&self) -> &std::path::Path {
        self.0.path()
    }
}

impl AsRef<std::path::Path> for Scratch {
    fn as_ref(&self) -> &std::path::Path {
        self.0.path()
    }
}
