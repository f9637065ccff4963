//! The top of the traces tab: what to run (steady run or run-up, or the open recording's
//! regime), the progress of the running job with Cancel, the recording line, errors, and
//! the view selector.

use crate::gui::app::TorsimApp;
use crate::gui::command::Command;
use crate::gui::recordings;
use crate::gui::trace_state::{TraceMode, TraceView};
use egui::{DragValue, Ui};

/// Mode and parameters; any change asks for a new run.
pub fn controls_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let mut changed = false;
    ui.horizontal_wrapped(|ui| {
        let t = &mut app.traces;
        let before = t.mode;
        ui.selectable_value(&mut t.mode, TraceMode::Steady, "Steady run");
        ui.selectable_value(&mut t.mode, TraceMode::RunUp, "Run-up");
        if t.recording.is_some() {
            ui.selectable_value(&mut t.mode, TraceMode::Recording, "Recording's regime");
        }
        changed |= t.mode != before;
        ui.separator();
        match t.mode {
            TraceMode::Steady => {
                let l = ui.label("speed");
                changed |= ui
                    .add(
                        DragValue::new(&mut app.trace_speed_rpm)
                            .speed(10.0)
                            .range(10.0..=100_000.0)
                            .suffix(" rpm"),
                    )
                    .labelled_by(l.id)
                    .changed();
                let l = ui.label("for");
                changed |= ui
                    .add(
                        DragValue::new(&mut t.steady_duration_s)
                            .speed(0.1)
                            .range(0.2..=60.0)
                            .suffix(" s"),
                    )
                    .labelled_by(l.id)
                    .changed();
            }
            TraceMode::RunUp => {
                for (label, value, suffix) in [
                    ("from", &mut t.from_rpm, " rpm"),
                    ("to", &mut t.to_rpm, " rpm"),
                ] {
                    let l = ui.label(label);
                    changed |= ui
                        .add(
                            DragValue::new(value)
                                .speed(10.0)
                                .range(10.0..=100_000.0)
                                .suffix(suffix),
                        )
                        .labelled_by(l.id)
                        .changed();
                }
                let l = ui.label("at");
                changed |= ui
                    .add(
                        DragValue::new(&mut t.rate_rpm_per_s)
                            .speed(1.0)
                            .range(1.0..=10_000.0)
                            .max_decimals(1)
                            .suffix(" rpm/s"),
                    )
                    .labelled_by(l.id)
                    .changed();
                let seconds = (t.to_rpm - t.from_rpm).abs() / t.rate_rpm_per_s.max(1e-9);
                ui.weak(format!("= {seconds:.0} s"));
            }
            TraceMode::Recording => {
                ui.weak("the recording's speed, duration and load");
            }
        }
    });
    if changed {
        app.commands.push(Command::Rerun);
    }
}

/// Progress bar with what runs and Cancel; or how the finished run went.
pub fn status_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let r = &app.results;
    let cancelled = r.trace_cancelled == Some(r.generation);
    let failed = app.error_of("trace").is_some();
    let running = r.trace_progress < 1.0 && !cancelled && !failed && app.invalid.is_none();
    let label = if r.trace_label.is_empty() {
        "time run".to_string()
    } else {
        r.trace_label.clone()
    };
    let progress = r.trace_progress;
    let pct = 100.0 * progress;
    let finished = r.trace.as_ref().map(|sim| {
        let s = &sim.settling;
        let settled = if s.converged {
            "settled"
        } else {
            "NOT settled"
        };
        let analysing = if r.trace_analysis.is_none() && !failed {
            " · analysing orders…"
        } else {
            ""
        };
        format!(
            "{label} · {settled} after {} cycles ({:.2} s) · {} steps{analysing}",
            s.cycles, s.time_s, sim.steps.0
        )
    });
    ui.horizontal_wrapped(|ui| {
        if running {
            let stage = if progress < 0.1 { " (settling)" } else { "" };
            // Room for Cancel beside it in a narrow window (issue 16).
            let width = (ui.available_width() - 90.0).clamp(120.0, 360.0);
            ui.add(
                egui::ProgressBar::new(progress)
                    .desired_width(width)
                    .text(format!("{label}: {pct:.0} %{stage}")),
            );
            if ui.button("Cancel").clicked() {
                app.commands.push(Command::CancelTrace);
            }
        } else if cancelled {
            ui.label(format!("{label}: cancelled at {pct:.0} %"));
            if ui.button("Run again").clicked() {
                app.commands.push(Command::Rerun);
            }
        } else if let Some(text) = finished {
            ui.label(text);
        }
    });
}

/// The open recording, its error, and Close.
pub fn recording_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let Some(path) = app.traces.recording.clone() else {
        return;
    };
    let mut close = false;
    ui.horizontal_wrapped(|ui| {
        let file = path.file_name().map_or_else(
            || path.display().to_string(),
            |f| f.to_string_lossy().into(),
        );
        match (&app.results.recording, app.error_of("recording")) {
            (_, Some(e)) => {
                ui.colored_label(
                    ui.visuals().error_fg_color,
                    format!("Recording {file} could not be used: {e}"),
                );
            }
            (Some(view), None) => {
                ui.label(format!("Recording {}: {}", view.file, view.summary));
            }
            (None, None) => {
                ui.label(format!("Reading recording {file}…"));
            }
        }
        close = ui.button("Close recording").clicked();
    });
    if close {
        recordings::close_recording(app);
    }
}

/// Time traces, spectrogram or orders.
pub fn view_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let ramp = app
        .results
        .live
        .as_ref()
        .is_some_and(|l| l.layout.is_ramp());
    let measured_ramp = app
        .results
        .recording
        .as_ref()
        .is_some_and(|r| r.spectrograms.is_some());
    ui.horizontal_wrapped(|ui| {
        let t = &mut app.traces;
        ui.selectable_value(&mut t.view, TraceView::Traces, "Traces");
        ui.add_enabled_ui(ramp || measured_ramp, |ui| {
            ui.selectable_value(&mut t.view, TraceView::Spectrogram, "Spectrogram (run-up)")
                .on_disabled_hover_text("for run-ups: choose Run-up above");
        });
        let orders = if app.results.recording.is_some() {
            "Orders: measured vs simulated"
        } else {
            "Orders"
        };
        ui.selectable_value(&mut t.view, TraceView::Orders, orders);
    });
}
