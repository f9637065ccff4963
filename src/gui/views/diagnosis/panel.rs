//! The diagnosis tab: recordings (add, list, remove), Diagnose with progress and Cancel,
//! then the finished report — verdict and Accept ([`crate::gui::views::diagnosis::verdict`]), the mismatch map
//! ([`crate::gui::views::diagnosis::map`]), the candidates ([`crate::gui::views::diagnosis::candidates`]) and the before/after
//! overlays ([`crate::gui::views::diagnosis::overlays`]).

use crate::gui::app::TorsimApp;
use crate::gui::views::diagnosis::load::Source;
use egui::{RichText, Ui};

/// The tab.
pub fn diagnosis_ui(app: &mut TorsimApp, ui: &mut Ui) {
    // CSV files dropped on the window are added as the dialog's are.
    let dropped: Vec<std::path::PathBuf> = ui.ctx().input(|i| {
        i.raw
            .dropped_files
            .iter()
            .map(|f| f.path().to_path_buf())
            .filter(|p| p.extension().is_some_and(|x| x.eq_ignore_ascii_case("csv")))
            .collect()
    });
    if !dropped.is_empty() && !app.diagnosis.loading() && app.diagnosis.job.is_none() {
        app.diagnosis
            .add(Source::Paths(dropped), &app.model, ui.ctx());
    }
    controls_ui(app, ui);
    egui::ScrollArea::vertical()
        .id_salt("diagnosis scroll")
        .auto_shrink([false, false])
        .show(ui, |ui| {
            recordings_ui(app, ui);
            let Some(finished) = app.diagnosis.finished.take() else {
                if app.diagnosis.job.is_none() && !app.diagnosis.recordings.is_empty() {
                    ui.label("Press Diagnose: torsim simulates every recording's regime, fits the plain parameters and every candidate effect, and judges them on held-out recordings.");
                }
                return;
            };
            ui.separator();
            if app.model != finished.model && finished.change() != Some(&app.model) {
                // Issue 16: a report of the model as it was is marked, not passed off as
                // this model's.
                ui.colored_label(
                    ui.visuals().warn_fg_color,
                    "This report diagnosed the model as it was before later edits: its \
                     numbers are not this model's. Press Diagnose to run it on the model as \
                     it is now.",
                );
            }
            crate::gui::views::diagnosis::verdict::verdict_ui(app, &finished, ui);
            ui.separator();
            crate::gui::views::diagnosis::map::map_ui(&finished.report, ui);
            ui.separator();
            crate::gui::views::diagnosis::candidates::candidates_ui(&finished.report, ui);
            ui.separator();
            crate::gui::views::diagnosis::overlays::overlays_ui(&finished.report, ui);
            if app.diagnosis.finished.is_none() {
                app.diagnosis.finished = Some(finished);
            }
        });
}

/// Add recordings…, Diagnose, the progress bar with the stage and Cancel.
fn controls_ui(app: &mut TorsimApp, ui: &mut Ui) {
    ui.horizontal_wrapped(|ui| {
        let d = &mut app.diagnosis;
        let busy = d.job.is_some();
        let add = ui
            .add_enabled(!d.loading() && !busy, egui::Button::new("Add recordings…"))
            .on_hover_text("bench recordings: CSV files, each with its .toml sidecar beside it");
        if add.clicked() {
            d.add(Source::Dialog, &app.model, ui.ctx());
        }
        let ready = !d.recordings.is_empty() && !busy && app.invalid.is_none();
        let why = if d.recordings.is_empty() {
            "add recordings first"
        } else if app.invalid.is_some() {
            "the model is invalid"
        } else {
            "running"
        };
        let diagnose = ui
            .add_enabled(ready, egui::Button::new("Diagnose"))
            .on_hover_text(
                "where the model and the recordings disagree, and which physics it left out",
            )
            .on_disabled_hover_text(why);
        if diagnose.clicked() {
            d.start(&app.model, ui.ctx());
        }
        if d.loading() {
            ui.spinner();
            ui.label("reading the recordings…");
        }
        if let Some(job) = &d.job {
            let text = if job.cancelling() {
                "cancelling (at the end of this step)…".to_string()
            } else {
                format!("{} · {:.0} %", job.stage, 100.0 * job.fraction)
            };
            ui.add(
                egui::ProgressBar::new(job.fraction as f32)
                    .desired_width(360.0)
                    .text(text),
            );
            if ui
                .add_enabled(!job.cancelling(), egui::Button::new("Cancel"))
                .clicked()
            {
                job.cancel();
            }
        }
    });
    let d = &app.diagnosis;
    if let Some(e) = &d.error {
        let text = if e == "cancelled" {
            "The diagnosis was cancelled.".to_string()
        } else {
            format!("The diagnosis failed: {e}")
        };
        ui.colored_label(ui.visuals().error_fg_color, text);
    }
    for e in &d.load_errors {
        ui.colored_label(ui.visuals().error_fg_color, format!("Not added: {e}"));
    }
}

/// The recordings: label, kind, speed, load, duration, role in the last report, file;
/// each with Remove.
fn recordings_ui(app: &mut TorsimApp, ui: &mut Ui) {
    let d = &mut app.diagnosis;
    if d.recordings.is_empty() {
        ui.label("No recordings yet. Add the bench recordings of the driveline (CSV files with their .toml sidecars), or drop them on the window.");
        return;
    }
    let roles = d.finished.as_ref().map(|f| f.report.recordings.clone());
    let mut remove = None;
    let busy = d.job.is_some();
    // Open until a report arrives, then closed (each has its own open state).
    egui::CollapsingHeader::new(format!("Recordings ({})", d.recordings.len()))
        .id_salt(("diagnosis recordings", roles.is_some()))
        .default_open(roles.is_none())
        .show(ui, |ui| {
            egui::Grid::new("diagnosis recordings")
                .striped(true)
                .num_columns(8)
                .show(ui, |ui| {
                    for h in [
                        "recording",
                        "kind",
                        "speed",
                        "load",
                        "duration",
                        "role",
                        "file",
                        "",
                    ] {
                        ui.label(RichText::new(h).strong());
                    }
                    ui.end_row();
                    for (i, r) in d.recordings.iter().enumerate() {
                        let label = &r.labelled.label;
                        ui.label(label);
                        ui.label(r.shape.label());
                        ui.label(r.speed_text());
                        ui.label(format!("{:.0} %", 100.0 * r.load));
                        ui.label(format!("{:.1} s", r.duration_s));
                        let used = roles
                            .as_ref()
                            .and_then(|u| u.iter().find(|x| x.label == *label));
                        let role = ui.label(used.map_or("", |x| x.role.as_str()));
                        if let Some(sentence) = used.and_then(|x| x.set_aside_sentence()) {
                            role.on_hover_text(sentence);
                        }
                        let file = r
                            .path
                            .file_name()
                            .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
                        ui.label(file).on_hover_text(r.path.display().to_string());
                        if ui.add_enabled(!busy, egui::Button::new("Remove")).clicked() {
                            remove = Some(i);
                        }
                        ui.end_row();
                    }
                });
        });
    if let Some(i) = remove {
        d.remove(i);
    }
}
