//! The diagnosis as a page for a person (`torsim diagnose … --report FILE.html`): one
//! self-contained HTML file (inline CSS and SVG, no script, nothing fetched) with the
//! verdict and its held-out fit, the mismatch map per station, the worst mismatches, the
//! resonances no mode explains, every candidate effect with its score, the before/after
//! overlays and the recordings used. No I/O: [`report_html`] returns the text.

mod map;
mod plot;
mod tables;
#[cfg(test)]
mod tests;

use super::report::Report;
use super::svg::{escape, sig};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// What each effect of `spec/diagnosis.md` means, in words.
pub fn effect_words(effect: &str) -> &'static str {
    match effect {
        "none" => "Nothing is missing: the model and the recordings agree within the noise",
        "parameter_error" => "No physics is missing; a parameter value is off",
        "coupling_amplitude_nonlinearity" => {
            "The rubber stiffness depends on the deflection (seed 000 eq. 1)"
        }
        "coupling_frequency_dependence" => {
            "The rubber stiffness depends on the vibration frequency (seed 000 eq. 8–9)"
        }
        "coupling_thermal_drift" => {
            "The rubber warms up by its own power loss and softens during the run (seed 000 eq. 10–11)"
        }
        "hysteretic_damping" => {
            "The rubber damping is frequency-independent per cycle, not viscous"
        }
        "unmodelled_mode" => {
            "A degree of freedom is missing: a resonance appears that no mode of the model explains"
        }
        "crank_variable_inertia" => {
            "The reciprocating masses make the engine inertia vary with crank angle"
        }
        "gear_backlash" => "There is free play in a gear stage",
        "cylinder_imbalance" => "One cylinder fires weaker or stronger than the others",
        "sensor_artifact" => {
            "The measurement, not the driveline: a zebra-tape joint or an encoder pitch error"
        }
        _ => "An effect this version of the page has no words for",
    }
}

const STYLE: &str = "
body{font:14px/1.45 system-ui,-apple-system,'Segoe UI',Roboto,sans-serif;color:#1d1d1d;max-width:1180px;margin:0 auto;padding:16px 24px 48px}
h1{font-size:22px;margin:8px 0 4px}h2{font-size:18px;margin:28px 0 8px;border-bottom:1px solid #ccc;padding-bottom:3px}
p.meta{color:#555;margin-top:0}code{font:13px ui-monospace,Menlo,Consolas,monospace}
.verdict-box{background:#f5f8fc;border:1px solid #c9d7e8;border-radius:6px;padding:10px 16px}
.effect{font-size:17px;font-weight:600}.fit{font-size:15px}.fit b{font-size:16px}
table{border-collapse:collapse;margin:6px 0 10px;font-size:13px}
th,td{border:1px solid #d4d4d4;padding:3px 7px;vertical-align:top;text-align:left}
th{background:#eee;font-weight:600}td.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}
td.small{font-size:12px;max-width:360px}tbody tr:nth-child(even){background:#fafafa}
tr.verdict,tbody tr.verdict:nth-child(even){background:#fff1b8;font-weight:600}
.figures{display:flex;flex-wrap:wrap;gap:10px 24px}figure{margin:4px 0}figcaption{font-weight:600;margin-bottom:2px}
svg text{font:11px system-ui,sans-serif;fill:#333}svg text.axis{font-size:12px;fill:#111}
svg text.panel{font-size:12px;font-weight:600}svg text.key{font-size:10px}svg text.empty{font-size:14px;fill:#888}
svg .frame{fill:none;stroke:#555}svg .lane{fill:#fbfbfb;stroke:#999}svg .grid{stroke:#e3e3e3}svg .tick{stroke:#555}
svg .cell{stroke:none}svg .line{fill:none;stroke-width:1.8}
svg .measured line{stroke:#222;stroke-width:1}svg .measured circle{fill:#222}
";

/// The whole page for `report` on the model called `model_name`.
pub fn report_html(report: &Report, model_name: &str) -> String {
    let mut out = String::with_capacity(64 * 1024);
    let title = format!("torsim diagnosis — {model_name}");
    let _ = writeln!(
        out,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"><title>{}</title><style>{STYLE}</style></head><body>",
        escape(&title)
    );
    let _ = writeln!(
        out,
        "<h1>Diagnosis of {}</h1><p class=\"meta\">{} recordings · noise σ {} rpm (median over the measured order amplitudes: the yardstick of every z) · computed in {} s · torsim {} · report format {}</p>",
        escape(model_name),
        report.recordings.len(),
        sig(report.noise_rpm, 3),
        sig(report.elapsed_s, 3),
        env!("CARGO_PKG_VERSION"),
        report.format
    );
    verdict(&mut out, report);
    mismatch_map(&mut out, report);
    out.push_str("<h2 id=\"mismatches\">Worst mismatches of your model</h2>\n<p>Worst first. Amplitudes are IAS order amplitudes, zero-to-peak, in rpm, in the station's own shaft; z = (measured − simulated)/σ, σ the noise of that amplitude with the model's floor.</p>\n");
    if report.mismatches.is_empty() {
        out.push_str("<p>None listed.</p>\n");
    } else {
        tables::mismatches(&mut out, report);
    }
    out.push_str("<h2 id=\"resonances\">Resonances no mode of the model explains</h2>\n");
    if report.unexplained_resonances.is_empty() {
        out.push_str(
            "<p>None: every resonance in the recordings lies near a mode of the model.</p>\n",
        );
    } else {
        tables::resonances(&mut out, report);
    }
    out.push_str(&format!("<h2 id=\"candidates\">Candidate effects</h2>\n<p>Every effect tried, best first. Each was screened cheaply on the fit recordings (on the linear model, or in the time domain of the recordings that show it), the most promising were fitted again in the time domain on every fit recording (its own parameters together with scale factors of the plain parameters), then scored on the held-out ones; only those (<em>time domain</em>) can be the verdict, the others' numbers are the screening's estimate. χ²/N is the mean of z² over the amplitudes compared. <b>Score</b> = held-out χ² per amplitude, counted from {noise} up (below it every model fits to the noise), + k·ln(n)/n (the BIC penalty of its k fitted parameters on n fitted amplitudes); lower is better. An effect is named only when it beats the plain parameters' score by {margin:.0} % and its own fit with the effect closed by as much; a row set aside says which rule passed it over. The verdict's row is highlighted.</p>\n",
        margin = 100.0 * super::decide::EFFECT_MARGIN,
        noise = super::decide::NOISE_CHI2
    ));
    tables::candidates(&mut out, report);
    if !report.not_fitted.is_empty() {
        out.push_str("<p class=\"small\">Not fitted, their signature being absent: ");
        let items: Vec<String> = report
            .not_fitted
            .iter()
            .map(|n| {
                format!(
                    "<code>{}</code> — {}",
                    escape(&n.candidate),
                    escape(&n.reason)
                )
            })
            .collect();
        out.push_str(&items.join("; "));
        out.push_str(".</p>\n");
    }
    overlays(&mut out, report);
    out.push_str("<h2 id=\"recordings\">Recordings</h2>\n");
    tables::recordings(&mut out, report);
    let _ = writeln!(
        out,
        "<p>Noise σ = {} rpm (median over all measured order amplitudes). The diagnosis took {} s.</p>\n</body></html>",
        sig(report.noise_rpm, 3),
        sig(report.elapsed_s, 3)
    );
    out
}

/// The verdict, its parameters, the explanation and the held-out fit.
fn verdict(out: &mut String, report: &Report) {
    let v = &report.verdict;
    let _ = writeln!(
        out,
        "<h2 id=\"verdict\">Verdict</h2><div class=\"verdict-box\"><p class=\"effect\">{} <code>{}</code></p><p>Confidence {} % (how clearly this beat the runner-up on held-out data).</p>",
        escape(effect_words(&v.effect)),
        escape(&v.effect),
        sig(100.0 * v.confidence, 2)
    );
    tables::parameters(out, &v.parameters);
    let _ = writeln!(out, "<p>{}</p>", escape(&v.explanation));
    let f = &report.fit;
    let change = if f.after < f.before && f.after > 0.0 && f.before.is_finite() {
        format!(" ({}× lower)", sig(f.before / f.after, 2))
    } else if f.after.is_finite() && f.after >= f.before {
        " (no improvement)".to_string()
    } else {
        String::new()
    };
    let on = if f.validated_on.is_empty() {
        "no held-out data".to_string()
    } else {
        f.validated_on.join("; ")
    };
    let _ = writeln!(
        out,
        "<p class=\"fit\">{}: <b>{} → {}</b>{} on held-out data: {}</p>",
        escape(&f.metric),
        sig(f.before, 3),
        sig(f.after, 3),
        escape(&change),
        escape(&on)
    );
    if let Some(why) = &f.swapped_because {
        let _ = writeln!(
            out,
            "<p class=\"fit\">Held out the other fold: {}.</p>",
            escape(why)
        );
    }
    out.push_str("</div>\n");
}

/// One heatmap per station, in the order of the map.
fn mismatch_map(out: &mut String, report: &Report) {
    out.push_str("<h2 id=\"map\">Mismatch map</h2>\n<p>Where your model and the recordings disagree, per station: x the mean speed of the reference shaft, y the engine order, colour z = (measured − simulated)/σ (red: the recording is above the model, blue: below; |z| ≲ 2 is noise). Hover a cell for its numbers.</p>\n");
    let mut stations: Vec<&str> = Vec::new();
    for c in &report.mismatch_map {
        if !stations.contains(&c.station.as_str()) {
            stations.push(&c.station);
        }
    }
    if stations.is_empty() {
        out.push_str("<p>No map cells.</p>\n");
        return;
    }
    let numbers: BTreeMap<&str, usize> = report
        .recordings
        .iter()
        .enumerate()
        .map(|(i, r)| (r.label.as_str(), i + 1))
        .collect();
    out.push_str("<div class=\"figures\">");
    for station in stations {
        let _ = writeln!(
            out,
            "<figure><figcaption>Station <code>{}</code></figcaption>{}</figure>",
            escape(station),
            map::station_map(report, station, &numbers)
        );
    }
    out.push_str("</div>\n");
}

/// The before/after plots on held-out data.
fn overlays(out: &mut String, report: &Report) {
    out.push_str("<h2 id=\"overlays\">Before and after, on data the fit did not use</h2>\n");
    if report.overlays.is_empty() {
        out.push_str("<p>No overlays.</p>\n");
        return;
    }
    out.push_str("<p>Measured order amplitude (points, ±σ bars), your model (dashed) and the verdict's fitted model (solid).</p>\n<div class=\"figures\">");
    let after = match report.verdict.effect.as_str() {
        "none" => "after: your model (nothing added)",
        _ => "after: fitted model",
    };
    for o in &report.overlays {
        let _ = writeln!(
            out,
            "<figure><figcaption>{} — <code>{}</code>, order {}</figcaption>{}</figure>",
            escape(&o.recording),
            escape(&o.station),
            escape(&o.order),
            plot::overlay_svg(o, after)
        );
    }
    out.push_str("</div>\n");
}
