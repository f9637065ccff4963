//! The candidates table: every effect tried, verdict first then best first, with its
//! fitted parameter count, χ²/N on the data the fit used and on the held-out data before
//! and after, and the score that ranked it; the verdict's row highlighted, and a
//! candidate the decision passed over marked "set aside" with the rule's reason on hover.

use crate::gui::session::diagnosis::finished::{sig4, value_text};
use crate::gui::views::diagnosis::verdict::VERDICT_COLOR;
use egui::{RichText, Ui};
use torsim::diagnose::Report;
use torsim::diagnose::decide::{EFFECT_MARGIN, NOISE_CHI2};

/// The table.
pub fn candidates_ui(report: &Report, ui: &mut Ui) {
    ui.label(RichText::new("Candidates").strong());
    ui.label(
        RichText::new(format!(
            "score = held-out χ²/N (from {NOISE_CHI2} up: below it every model fits to the \
             noise) + k·ln(n)/n (k fitted parameters on n fitted amplitudes); lower is better. \
             An effect must beat the plain parameters' score by {:.0} %, and its own fit with \
             the effect closed by as much, to be named.",
            100.0 * EFFECT_MARGIN
        ))
        .weak(),
    );
    let verdict = report.verdict.effect.as_str();
    // Eight columns: in a narrow window the table scrolls sideways rather than running
    // past the window's edge (issue 16).
    egui::ScrollArea::horizontal()
        .id_salt("candidates table")
        .show(ui, |ui| table_ui(report, verdict, ui));
}

/// The grid itself.
fn table_ui(report: &Report, verdict: &str, ui: &mut Ui) {
    egui::Grid::new("diagnosis candidates")
        .striped(true)
        .num_columns(8)
        .show(ui, |ui| {
            for (h, tip) in [
                ("", ""),
                ("effect", "identifier of spec/diagnosis.md"),
                (
                    "k",
                    "parameters fitted: the effect's and the plain scale factors",
                ),
                ("χ²/N fitted", "on the recordings the fit used"),
                (
                    "held out, before",
                    "χ²/N of the user's model on the held-out data",
                ),
                ("held out, after", "χ²/N after the fit on the held-out data"),
                (
                    "score",
                    "held-out χ²/N plus the parameter penalty; lower is better",
                ),
                ("fitted", "the effect's place and value"),
            ] {
                let l = ui.label(RichText::new(h).strong());
                if !tip.is_empty() {
                    l.on_hover_text(tip);
                }
            }
            ui.end_row();
            for c in &report.candidates {
                let is_verdict = c.effect == verdict;
                let cell = |text: String| {
                    let t = RichText::new(text);
                    if is_verdict {
                        t.strong().color(VERDICT_COLOR)
                    } else {
                        t
                    }
                };
                match (&c.set_aside, is_verdict) {
                    (_, true) => {
                        ui.label(cell("verdict".into()));
                    }
                    (Some(why), false) => {
                        ui.label(RichText::new("set aside").weak())
                            .on_hover_text(why.as_str());
                    }
                    (None, false) => {
                        ui.label("");
                    }
                }
                if c.verified {
                    ui.label(cell(c.effect.clone()));
                } else {
                    ui.label(cell(format!("{} (screened)", c.effect)))
                        .on_hover_text(
                            "only screened: its numbers are the screening's estimate, not a \
                         time-domain fit, and it cannot be the verdict",
                        );
                }
                ui.label(cell(c.parameter_count.to_string()));
                ui.label(cell(format!("{:.3}", c.residual_fitted)));
                ui.label(cell(format!("{:.3}", c.residual_before)));
                ui.label(cell(format!("{:.3}", c.residual_after)));
                ui.label(cell(format!("{:.3}", c.score)));
                let own: Vec<String> = c
                    .parameters
                    .iter()
                    .filter(|(k, _)| !k.starts_with("scale."))
                    .map(|(k, v)| format!("{k} = {}", value_text(v)))
                    .collect();
                let scales: Vec<String> = c
                    .parameters
                    .iter()
                    .filter_map(|(k, v)| Some((k.strip_prefix("scale.")?, v)))
                    .map(|(k, v)| format!("{k} × {}", value_text(v)))
                    .collect();
                let l = ui.label(cell(own.join(", ")));
                if !scales.is_empty() {
                    l.on_hover_text(format!("plain parameters:\n{}", scales.join("\n")));
                }
                ui.end_row();
            }
        });
    if !report.unexplained_resonances.is_empty() {
        ui.add_space(6.0);
        ui.label(RichText::new("Resonances no mode of the model explains").strong());
        for r in &report.unexplained_resonances {
            let nearest = r
                .nearest_mode_hz
                .map_or("the model has no modes".into(), |f| {
                    format!("nearest mode {f:.1} Hz")
                });
            ui.label(format!(
                "{} order {} at {:.0} rpm ({:.1} Hz): {} rpm measured, {} rpm simulated; {nearest}",
                r.station,
                r.order,
                r.speed_rpm,
                r.frequency_hz,
                sig4(r.measured),
                sig4(r.simulated),
            ));
        }
    }
}
