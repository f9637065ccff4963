//! Issue 16, deliverable 3: image snapshots of every tab of the real app at 1280 × 800 and
//! 1920 × 1080, so a regression in layout or drawing fails the tests. Rendered with wgpu
//! on Mesa's lavapipe (Vulkan on the CPU; scripts/debian-cargo installs it for `test`),
//! which draws the same pixels on every machine with the same Mesa. The references are
//! `tests/snapshots/gui-<tab>-<width>x<height>.png`; after an intended change, rerun with
//! `UPDATE_SNAPSHOTS=1` and look at the new images before committing them.

use crate::gui::app::{Tab, TorsimApp};
use crate::gui::tests::support::{preset_model, step_until};
use egui_kittest::{Harness, SnapshotOptions};

/// The real app on `preset`, rendered by wgpu, with its results in.
fn rendered(preset: &'static str, size: [f32; 2]) -> Harness<'static, TorsimApp> {
    let mut h = Harness::builder()
        .with_size(size)
        .wgpu()
        .build_eframe(move |cc| {
            let ctx = cc.egui_ctx.clone();
            TorsimApp::new(preset_model(preset), None, move || ctx.request_repaint())
        });
    step_until(&mut h, |a| {
        a.results.ratings.is_some() && a.results.live.is_some()
    });
    h
}

#[test]
fn every_tab_looks_as_it_did() {
    let options = SnapshotOptions::new();
    let mut failures = Vec::new();
    for size in [[1280.0, 800.0], [1920.0, 1080.0]] {
        let mut h = rendered("cng-genset", size);
        for (tab, name) in [
            (Tab::Campbell, "campbell"),
            (Tab::Modes, "modes"),
            (Tab::Response, "response"),
            (Tab::Traces, "traces"),
            (Tab::Diagnosis, "diagnosis"),
        ] {
            h.state_mut().tab = tab;
            h.run_steps(4);
            let file = format!("gui-{name}-{}x{}", size[0], size[1]);
            if let Err(e) = h.try_snapshot_options(&file, &options) {
                failures.push(format!("{file}: {e}"));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
