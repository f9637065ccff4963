//! Issue 16, deliverable 3: nothing runs off the right edge of the window. Every tab of
//! the real app, at 1280 × 800 and 1920 × 1080 (and the smallest supported size), is
//! laid out with its results (and the Diagnosis tab with a report), and every widget
//! AccessKit reports must end inside the window's width (panels wrap or scroll vertically
//! instead; only the schematic scrolls sideways, by design).

use crate::gui::app::{Tab, TorsimApp};
use crate::gui::tests::support::{app_on, step_until};
use egui_kittest::Harness;
use egui_kittest::kittest::NodeT;

fn harness(preset: &'static str, size: [f32; 2]) -> Harness<'static, TorsimApp> {
    let mut h = app_on(preset, size);
    step_until(&mut h, |a| {
        a.results.ratings.is_some() && a.results.live.is_some()
    });
    h
}

/// The smallest window the app allows (`gui::run`'s minimum inner size).
const MIN_SIZE: [f32; 2] = crate::gui::MIN_WINDOW_SIZE;

/// The labels of widgets that end right of the window, with how far.
fn off_the_right_edge(h: &Harness<'static, TorsimApp>, width: f32) -> Vec<String> {
    let ppp = h.ctx.pixels_per_point();
    h.root()
        .children_recursive()
        .filter_map(|n| {
            let node = n.accesskit_node();
            let label = node.label().unwrap_or_default();
            let b = node.bounding_box()?;
            let (x0, x1) = (b.x0 as f32 / ppp, b.x1 as f32 / ppp);
            // The schematic scrolls sideways when the driveline is longer than the window.
            let scrolls = label == crate::gui::views::schematic::CANVAS_LABEL;
            (x1 > width + 1.0 && x1 > x0 && !scrolls).then(|| {
                format!(
                    "{label:?} {:?} {:?} ends at {x1:.0} (from {x0:.0})",
                    node.role(),
                    node.value()
                )
            })
        })
        .collect()
}

#[test]
fn no_tab_runs_off_the_window() {
    for size in [[1280.0, 800.0], [1920.0, 1080.0], MIN_SIZE] {
        for preset in ["cng-genset", "genset-20dof"] {
            let mut h = harness(preset, size);
            for tab in [
                Tab::Campbell,
                Tab::Modes,
                Tab::Response,
                Tab::Traces,
                Tab::Diagnosis,
            ] {
                h.state_mut().tab = tab;
                h.run_steps(4);
                let off = off_the_right_edge(&h, size[0]);
                assert!(off.is_empty(), "{preset} at {size:?}, {tab:?}: {off:#?}");
            }
        }
    }
}

/// The Diagnosis tab with a report (verdict, map, candidates table, overlays) fits the
/// window's width at both sizes.
#[test]
fn a_diagnosis_report_fits_the_window() {
    use crate::gui::session::diagnosis::finished::Finished;
    use crate::gui::tests::diagnosis::{bench, report};
    // At the smallest window the candidates table scrolls sideways (eight columns).
    for size in [[1280.0, 800.0], [1920.0, 1080.0]] {
        let mut h = Harness::builder().with_size(size).build_eframe(|cc| {
            let ctx = cc.egui_ctx.clone();
            TorsimApp::new(bench(), None, move || ctx.request_repaint())
        });
        h.state_mut().tab = Tab::Diagnosis;
        h.state_mut()
            .diagnosis
            .show(Finished::new(bench(), report()));
        h.run_steps(4);
        let off = off_the_right_edge(&h, size[0]);
        assert!(off.is_empty(), "{size:?}: {off:#?}");
    }
}
