//! The verdict in words (effect, confidence, parameters, explanation), the fit on the
//! held-out recordings, "Accept verdict" — the model with the verdict applied, through
//! [`TorsimApp::commit`] so that it is one undo step — and "Save report…".

use crate::gui::app::TorsimApp;
use crate::gui::command::Command;
use crate::gui::session::diagnosis::finished::{Finished, value_text};
use crate::gui::views::diagnosis::save::Saving;
use egui::{Color32, RichText, Ui};

/// The verdict's colour (also its row in the candidates table).
pub const VERDICT_COLOR: Color32 = Color32::from_rgb(255, 200, 0);

/// The verdict, the held-out fit, Accept and Save.
pub fn verdict_ui(app: &mut TorsimApp, finished: &Finished, ui: &mut Ui) {
    let r = &finished.report;
    let v = &r.verdict;
    ui.horizontal_wrapped(|ui| {
        ui.label(RichText::new("Verdict:").heading());
        ui.label(RichText::new(&v.effect).heading().color(VERDICT_COLOR));
    });
    // Issue 16: the physics in a sentence with its place and size, and the confidence
    // said as what it measures.
    let sentence = torsim::diagnose::words::effect_sentence(&v.effect, &v.parameters);
    ui.add(egui::Label::new(RichText::new(&sentence).strong()).wrap());
    ui.label(format!(
        "Confidence {:.0} %: on the recordings the fit did not use, the verdict's misfit \
         (χ²/N) is {:.0} % below that of the next best explanation.",
        100.0 * v.confidence,
        100.0 * v.confidence
    ))
    .on_hover_text("1 − (the verdict's held-out χ²/N) / (the runner-up's), 0 to 100 %");
    if !v.parameters.is_empty() {
        let parameters: Vec<String> = v
            .parameters
            .iter()
            .map(|(k, x)| format!("{k} = {}", value_text(x)))
            .collect();
        ui.label(format!("Fitted: {}", parameters.join(", ")));
    }
    // The explanation opens with the same sentence: said once.
    ui.label(
        v.explanation
            .strip_prefix(sentence.as_str())
            .unwrap_or(&v.explanation)
            .trim_start(),
    );
    let f = &r.fit;
    let on = if f.validated_on.is_empty() {
        "no held-out data".to_string()
    } else {
        f.validated_on.join("; ")
    };
    ui.label(format!(
        "Held-out fit, χ²/N (mean squared (measured − simulated)/σ): {:.3} before, {:.3} after, on {on}.",
        f.before, f.after
    ))
    .on_hover_text(&f.metric);
    if let Some(why) = &f.swapped_because {
        ui.label(format!("Held out the other fold: {why}."));
    }
    // A recording the model cannot simulate is in no number above: said here, not only
    // in the recordings table's role column.
    for sentence in r.recordings.iter().filter_map(|u| u.set_aside_sentence()) {
        ui.label(RichText::new(sentence).color(ui.visuals().warn_fg_color));
    }
    ui.label(
        RichText::new(format!(
            "{} recordings, noise {} rpm (median σ of the order amplitudes), {:.0} s.",
            r.recordings.len(),
            crate::gui::session::diagnosis::finished::sig4(r.noise_rpm),
            r.elapsed_s
        ))
        .weak(),
    );
    ui.horizontal_wrapped(|ui| accept_ui(app, finished, ui));
    // Said while the model is the accepted one, so an undo takes the line away with it.
    if finished.change() == Some(&app.model) {
        ui.label(format!("Accepted: {}.", finished.changes.join("; ")));
    }
    let message = &app.diagnosis.message;
    if !message.is_empty() {
        ui.label(message);
    }
}

/// Why Accept is disabled, or `None` when it can be pressed.
fn blocked(app: &TorsimApp, finished: &Finished) -> Option<String> {
    let effect = finished.report.verdict.effect.as_str();
    match (&finished.accepted, finished.change()) {
        (Err(e), _) => Some(format!("cannot apply the verdict: {e}")),
        _ if effect == "none" => Some("nothing is missing: the model stays as it is".into()),
        (_, None) if effect == "sensor_artifact" => Some(
            "the artifact is in the measurement, not the driveline: the model stays as it is"
                .into(),
        ),
        (_, None) => Some("the verdict changes nothing in the model".into()),
        (_, Some(m)) if app.model == *m => {
            Some("accepted: Edit, Undo (Ctrl+Z) takes it back".into())
        }
        _ if app.model != finished.model => {
            Some("the model was edited since this diagnosis: diagnose again first".into())
        }
        _ => None,
    }
}

/// "Accept verdict" with what it changes, and "Save report…".
fn accept_ui(app: &mut TorsimApp, finished: &Finished, ui: &mut Ui) {
    let why = blocked(app, finished);
    let changes = if finished.changes.is_empty() {
        "changes nothing".to_string()
    } else {
        finished.changes.join("\n")
    };
    let button = ui
        .add_enabled(why.is_none(), egui::Button::new("Accept verdict"))
        .on_hover_text(format!(
            "puts the verdict into the model (one undo step):\n{changes}"
        ))
        .on_disabled_hover_text(why.clone().unwrap_or_default());
    if button.clicked()
        && let Some(after) = finished.change()
    {
        app.commands.push(Command::Edit {
            model: Box::new(after.clone()),
            in_progress: false,
        });
        app.status = format!("accepted the diagnosis: {}", finished.report.verdict.effect);
    }
    if let Some(why) = why {
        ui.label(RichText::new(why).weak());
    }
    let saving = app.diagnosis.saving.is_some();
    if ui
        .add_enabled(!saving, egui::Button::new("Save report…"))
        .on_hover_text("the report as one self-contained HTML page, with its plots")
        .clicked()
    {
        app.diagnosis.saving = Some(Saving::start(
            finished.report.clone(),
            finished.model.name.clone(),
            ui.ctx(),
        ));
    }
}
