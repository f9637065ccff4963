//! The traces tab driven headless by egui_kittest: a run-up streams in (the traces grow
//! before it finishes, and the chunks add up to the finished simulation exactly), a
//! newer edit cancels it, a recording opens and is overlaid by the simulation of its
//! regime, a bad recording shows an error naming its file.

use crate::gui::app::TorsimApp;
use crate::gui::recordings::open_recording;
use crate::gui::session::trace_data::GroupKind;
use crate::gui::tests::support::Scratch;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use std::path::PathBuf;
use std::time::{Duration, Instant};
use torsim::model::{Model, parse_model, presets};
use torsim::recording::{Recording, write_recording};
use torsim::recording::{Run, RunShape};
use torsim::signal::analyse;
use torsim::transient::{RunOptions, simulate, to_recording};

fn rig() -> Model {
    let p = presets::preset("test-rig-70sh").expect("preset");
    parse_model(p.text, "test-rig-70sh").expect("model")
}

fn harness() -> Harness<'static, TorsimApp> {
    Harness::builder()
        .with_size([1400.0, 1000.0])
        .build_eframe(|cc| {
            let ctx = cc.egui_ctx.clone();
            TorsimApp::new(rig(), None, move || ctx.request_repaint())
        })
}

/// Steps the UI until `done` holds, checking `invariant` at every step; at most 120 s.
fn step_until(
    h: &mut Harness<'static, TorsimApp>,
    done: impl Fn(&TorsimApp) -> bool,
    mut invariant: impl FnMut(&TorsimApp),
) {
    let start = Instant::now();
    while !done(h.state()) {
        invariant(h.state());
        assert!(
            start.elapsed() < Duration::from_secs(120),
            "timed out; errors: {:?}",
            h.state().results.errors
        );
        std::thread::sleep(Duration::from_millis(10));
        h.step();
    }
    h.step();
}

/// A fresh temporary folder for one test, removed when the returned guard is dropped.
fn temp_dir(name: &str) -> Scratch {
    Scratch::new(&format!("torsim-gui-{name}-"))
}

/// The traces tab, run-up selected (the model's range 1500 to 6000 rpm in 60 s).
fn start_run_up(h: &mut Harness<'static, TorsimApp>) {
    h.get_by_label("Time traces").click();
    h.step();
    h.get_by_label("Run-up").click();
    h.step();
    h.step();
}

#[test]
fn a_run_up_streams_in_and_adds_up_to_the_finished_run() {
    let mut h = harness();
    start_run_up(&mut h);
    let generation = h.state().results.generation;
    // Chunks arrive while the run is going: more than one, before it has finished.
    step_until(
        &mut h,
        |a| a.results.live.as_ref().is_some_and(|l| l.chunks > 1) && a.results.trace_progress < 1.0,
        |a| assert!(a.results.trace.is_none(), "finished before any chunk"),
    );
    let app = h.state();
    assert!(app.results.trace.is_none(), "still running");
    let live = app.results.live.as_ref().expect("live");
    assert_eq!(live.generation, generation);
    assert_eq!(
        live.layout.kind,
        Run::ramp(1500.0, 6000.0, 60.0),
        "defaults: the model's speed range in 60 s"
    );
    let early = live.group(GroupKind::Speed).expect("IAS").1.time_s.len();
    assert!(early > 0 && early < 60 * 4096, "{early} samples so far");
    h.get_by_label_contains("run-up 1500 to 6000 rpm in 60 s: ");
    h.get_by_label("Cancel");
    step_until(
        &mut h,
        |a| a.results.trace.is_some() && a.results.trace_analysis.is_some(),
        |_| {},
    );
    // The plotted samples are the finished simulation's, sample for sample.
    let app = h.state();
    let sim = app.results.trace.as_ref().expect("trace");
    let live = app.results.live.as_ref().expect("live");
    let (_, speed) = live.group(GroupKind::Speed).expect("IAS");
    assert_eq!(speed.time_s, sim.time_s);
    assert_eq!(speed.values, sim.speed_rpm);
    let (_, torque) = live.group(GroupKind::Torque).expect("torque");
    let sim_torque: Vec<Vec<f64>> = sim.torque_nm.iter().map(|(_, v)| v.clone()).collect();
    assert_eq!(torque.values, sim_torque);
    assert!(live.chunks >= 3, "{} chunks", live.chunks);
    // The CSV export holds every streamed series with its unit, and the reference speed.
    let data = crate::gui::views::plots::traces_data(app).expect("traces export");
    let names: Vec<&str> = data.columns.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names[0], "reference speed engine [rpm]", "{names:?}");
    assert!(names.contains(&"IAS engine [rpm]"), "{names:?}");
    assert!(
        names
            .iter()
            .any(|n| n.starts_with("torque ") && n.ends_with("[N·m]"))
    );
    assert!(
        names
            .iter()
            .any(|n| n.starts_with("power loss ") && n.ends_with("[W]"))
    );
    assert_eq!(data.columns[1].1.len(), sim.time_s.len());
    let last = data.columns[0].1.last().expect("samples")[1];
    assert!((last - 6000.0).abs() < 1.0, "ramp ends at {last} rpm");
    // The spectrogram of the run-up is there, one image per station.
    let analysis = app.results.trace_analysis.as_ref().expect("analysis");
    let set = analysis.spectrograms.as_ref().expect("run-up spectrograms");
    assert!(set.stations.iter().any(|s| s.station == "engine"));
    h.get_by_label("Spectrogram (run-up)").click();
    h.step();
    h.step();
    h.get_by_label_contains("0.1 s Hann windows");
}

#[test]
fn a_newer_edit_cancels_the_running_run_up() {
    let mut h = harness();
    start_run_up(&mut h);
    let old = h.state().results.generation;
    step_until(
        &mut h,
        |a| a.results.live.as_ref().is_some_and(|l| l.chunks >= 2),
        |_| {},
    );
    let chunks_at_edit = h.state().results.live.as_ref().map_or(0, |l| l.chunks);
    assert!(h.state().results.trace_progress < 0.9);
    let before = h.state().model.clone();
    h.state_mut().model.inertias[3].inertia_kg_m2 = 0.12;
    h.state_mut().commit(before);
    let new = h.state().results.generation;
    assert!(new > old);
    // Until the new run's first samples arrive, the old trace stays as it was: none of
    // the old run's later chunks is shown.
    step_until(
        &mut h,
        |a| {
            a.results.trace_cancelled == Some(old)
                && a.results.live.as_ref().is_some_and(|l| l.generation == new)
        },
        |a| {
            let live = a.results.live.as_ref().expect("live");
            assert!(
                live.generation == new || (live.generation == old && live.chunks == chunks_at_edit),
                "generation {} with {} chunks after the edit",
                live.generation,
                live.chunks
            );
            assert!(a.results.trace.is_none(), "the old run never finishes");
        },
    );
    assert_eq!(h.state().results.trace_cancelled, Some(old));
}

/// Simulates `kind` on the test rig as `torsim simulate --csv` does and writes a
/// recording of two stations (engine and middle flange), as a bench would have them.
fn write_rig_recording(dir: &std::path::Path, name: &str, kind: Run) -> (PathBuf, Recording) {
    let model = rig();
    let options = RunOptions {
        rate_hz: 4096.0,
        max_settle_s: 30.0,
        ..RunOptions::default()
    };
    let sim = simulate(&model, kind, options, &mut |_| true).expect("run");
    let mut recording = to_recording(&sim, kind, 1.0, model.strokes(), &model.name);
    recording
        .channels
        .retain(|c| c.column == "engine_rpm" || c.column == "middle_flange_rpm");
    let path = dir.join(name);
    write_recording(&recording, &path).expect("written");
    (path, recording)
}

#[test]
fn a_steady_recording_is_overlaid_with_its_dominant_order() {
    let dir = temp_dir("steady");
    let kind = Run::steady(3000.0, 1.0);
    let (path, recording) = write_rig_recording(&dir, "regime-a.csv", kind);
    let measured = analyse(&recording).expect("analysis");
    let engine = &measured.stations[0];
    let dominant = engine
        .orders
        .iter()
        .max_by(|a, b| a.amplitude.total_cmp(&b.amplitude))
        .expect("orders");
    // The calibrated rig at 3000 rpm (seed 001 Table 9): the order-0.5 stand-in for the
    // cylinders' spread dominates the crank, not the firing order 2 (§3.1).
    assert_eq!(dominant.order, 0.5, "the rig's half order");
    let mut h = harness();
    open_recording(h.state_mut(), path);
    step_until(
        &mut h,
        |a| a.results.recording.is_some() && a.results.trace_analysis.is_some(),
        |_| {},
    );
    let app = h.state();
    assert_eq!(app.stations, ["engine", "middle_flange"]);
    let live = app.results.live.as_ref().expect("live");
    assert_eq!(
        live.layout.kind, kind,
        "the recording's regime is simulated"
    );
    // Same model, same regime: the simulated orders are the recording's.
    let sim = &app
        .results
        .trace_analysis
        .as_ref()
        .expect("analysis")
        .analysis;
    let sim_engine = sim
        .stations
        .iter()
        .find(|s| s.name == "engine")
        .expect("engine");
    for (s, m) in sim_engine.orders.iter().zip(&engine.orders) {
        assert!(
            (s.amplitude - m.amplitude).abs() <= 1e-9 * m.amplitude.max(1.0),
            "order {}: {} vs {}",
            s.order,
            s.amplitude,
            m.amplitude
        );
    }
    h.get_by_label_contains("Recording regime-a.csv: steady 3000 rpm");
    h.get_by_label("Orders: measured vs simulated").click();
    h.step();
    h.step();
    let row = format!(
        "dominant order: measured {} ({:.3} rpm)",
        dominant.order, dominant.amplitude
    );
    assert_eq!(
        h.get_all_by_label_contains(&row).count(),
        1,
        "the engine's row"
    );
}

#[test]
fn a_run_up_recording_is_simulated_with_its_speed_profile() {
    let dir = temp_dir("run-up");
    let kind = Run::ramp(2000.0, 3000.0, 2.0);
    let (path, _) = write_rig_recording(&dir, "run-up.csv", kind);
    let mut h = harness();
    open_recording(h.state_mut(), path);
    step_until(
        &mut h,
        |a| a.results.recording.is_some() && a.results.live.is_some(),
        |_| {},
    );
    let live = h.state().results.live.as_ref().expect("live");
    let Run {
        shape: RunShape::Ramp { from_rpm, to_rpm },
        duration_s,
    } = live.layout.kind
    else {
        panic!(
            "a run-up recording is simulated as a run-up: {:?}",
            live.layout.kind
        );
    };
    // The least-squares line through the IAS of the engine (its vibration included).
    assert!((from_rpm - 2000.0).abs() < 5.0, "{from_rpm}");
    assert!((to_rpm - 3000.0).abs() < 5.0, "{to_rpm}");
    assert!((duration_s - 2.0).abs() < 1e-9, "{duration_s}");
}

#[test]
fn a_bad_recording_shows_an_error_naming_the_file() {
    let dir = temp_dir("bad");
    let csv = dir.join("bad-run.csv");
    std::fs::write(&csv, "time_s,engine_rpm\n0.0,3000\n0.001,abc\n").expect("csv");
    std::fs::write(
        dir.join("bad-run.toml"),
        "format = 1\nkind = \"steady\"\nreference = \"engine\"\nspeed_rpm = 3000\n",
    )
    .expect("sidecar");
    let mut h = harness();
    open_recording(h.state_mut(), csv);
    step_until(&mut h, |a| a.error_of("recording").is_some(), |_| {});
    let error = h.state().error_of("recording").expect("error").to_string();
    assert!(
        error.contains("bad-run.csv") && error.contains('3') && error.contains("abc"),
        "{error}"
    );
    h.get_by_label_contains("Recording bad-run.csv could not be used");
    assert!(h.state().results.recording.is_none());
    assert!(h.state().stations.is_empty());
}
