//! The tables of the diagnosis page: fitted parameters, worst mismatches, unexplained
//! resonances, candidates and recordings. Every text is escaped; numbers are right-aligned
//! with units in the headers.

use super::super::report::{Candidate, ParameterValue, Report};
use super::super::svg::{diverging, escape, sig, tenth};
use super::map::Z_LIMIT;
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// A table: header cells (already HTML) and rows of cells (already HTML, `<td…>…</td>`).
fn table(out: &mut String, class: &str, header: &[&str], rows: &[(String, String)]) {
    let _ = write!(out, r#"<table class="{class}"><thead><tr>"#);
    for h in header {
        let _ = write!(out, "<th>{h}</th>");
    }
    out.push_str("</tr></thead><tbody>");
    for (row_class, cells) in rows {
        if row_class.is_empty() {
            let _ = write!(out, "<tr>{cells}</tr>");
        } else {
            let _ = write!(out, r#"<tr class="{row_class}">{cells}</tr>"#);
        }
    }
    out.push_str("</tbody></table>\n");
}

fn td(text: &str) -> String {
    format!("<td>{}</td>", escape(text))
}

fn num(value: f64, digits: usize) -> String {
    format!(r#"<td class="num">{}</td>"#, sig(value, digits))
}

/// A `z` cell coloured like the map.
fn z_cell(z: f64) -> String {
    let colour = diverging(z, Z_LIMIT);
    let ink = if z.is_finite() && z.abs() > 0.6 * Z_LIMIT {
        "#ffffff"
    } else {
        "#000000"
    };
    format!(
        r#"<td class="num" style="background:{colour};color:{ink}">{}</td>"#,
        sig(z, 3)
    )
}

/// A parameter's value for a person.
pub fn value_text(value: &ParameterValue) -> String {
    match value {
        ParameterValue::Number(v) => sig(*v, 4),
        ParameterValue::Text(t) => t.clone(),
    }
}

/// The unit a parameter's name carries (`…_hz` → Hz), if it is one torsim uses; plain
/// parameter scale factors (`scale.<name>`) have none.
pub fn unit_of(name: &str) -> &'static str {
    if name.starts_with("scale.") {
        return "factor";
    }
    const UNITS: [(&str, &str); 17] = [
        ("_nm_s_per_rad", "N·m·s/rad"),
        ("_nm_per_rad", "N·m/rad"),
        ("_kg_m2", "kg·m²"),
        ("_nm", "N·m"),
        ("_hz", "Hz"),
        ("_rpm", "rpm"),
        ("_deg", "°"),
        ("_rad", "rad"),
        ("_pct", "%"),
        ("_c", "°C"),
        ("_k", "K"),
        ("_s", "s"),
        ("_w", "W"),
        ("_bar", "bar"),
        ("_mm", "mm"),
        ("_m", "m"),
        ("_kg", "kg"),
    ];
    UNITS
        .iter()
        .find(|(suffix, _)| name.ends_with(suffix))
        .map_or("", |(_, unit)| unit)
}

/// Fitted parameters: name, value, unit from the name.
pub fn parameters(out: &mut String, parameters: &BTreeMap<String, ParameterValue>) {
    if parameters.is_empty() {
        out.push_str("<p>No parameters fitted.</p>\n");
        return;
    }
    let rows: Vec<(String, String)> = parameters
        .iter()
        .map(|(name, value)| {
            let cells = format!(
                r#"<td><code>{}</code></td><td class="num">{}</td>{}"#,
                escape(name),
                escape(&value_text(value)),
                td(unit_of(name))
            );
            (String::new(), cells)
        })
        .collect();
    table(
        out,
        "params",
        &["parameter", "fitted value", "unit (from the name)"],
        &rows,
    );
}

/// The worst mismatches, worst first.
pub fn mismatches(out: &mut String, report: &Report) {
    let rows: Vec<(String, String)> = report
        .mismatches
        .iter()
        .map(|m| {
            let cells = [
                td(&m.recording),
                td(&m.station),
                td(&m.order),
                format!(r#"<td class="num">{}</td>"#, tenth(m.speed_rpm)),
                num(m.frequency_hz, 4),
                num(m.measured, 4),
                num(m.simulated, 4),
                z_cell(m.z),
            ];
            (String::new(), cells.concat())
        })
        .collect();
    table(
        out,
        "mismatches",
        &[
            "recording",
            "station",
            "order",
            "speed [rpm]",
            "frequency [Hz]",
            "measured [rpm]",
            "simulated [rpm]",
            "z",
        ],
        &rows,
    );
}

/// Resonances no mode of the model explains.
pub fn resonances(out: &mut String, report: &Report) {
    let rows: Vec<(String, String)> = report
        .unexplained_resonances
        .iter()
        .map(|r| {
            let cells = [
                td(&r.station),
                td(&r.order),
                format!(r#"<td class="num">{}</td>"#, tenth(r.speed_rpm)),
                num(r.frequency_hz, 4),
                num(r.measured, 4),
                num(r.simulated, 4),
                num(r.nearest_mode_hz.unwrap_or(f64::NAN), 4),
            ];
            (String::new(), cells.concat())
        })
        .collect();
    table(
        out,
        "resonances",
        &[
            "station",
            "order",
            "speed [rpm]",
            "frequency [Hz]",
            "measured [rpm]",
            "model [rpm]",
            "nearest mode of the model [Hz]",
        ],
        &rows,
    );
}

/// The candidates, best first; the verdict's row (the first of its effect) highlighted.
pub fn candidates(out: &mut String, report: &Report) {
    let verdict_row = report
        .candidates
        .iter()
        .position(|c| c.effect == report.verdict.effect);
    let rows: Vec<(String, String)> = report
        .candidates
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let class = if Some(i) == verdict_row {
                "verdict"
            } else {
                ""
            };
            (class.to_string(), candidate_cells(i + 1, c))
        })
        .collect();
    table(
        out,
        "candidates",
        &[
            "#",
            "effect",
            "fitted parameters",
            "k",
            "χ²/N fitted",
            "χ²/N held out, before",
            "χ²/N held out, after",
            "score",
            "scored in",
            "signature in the data",
        ],
        &rows,
    );
}

fn candidate_cells(rank: usize, c: &Candidate) -> String {
    let parameters: Vec<String> = c
        .parameters
        .iter()
        .map(|(k, v)| {
            let unit = unit_of(k);
            let unit = if unit.is_empty() || unit == "factor" {
                String::new()
            } else {
                format!(" {unit}")
            };
            format!("{} = {}{unit}", escape(k), escape(&value_text(v)))
        })
        .collect();
    [
        format!(r#"<td class="num">{rank}</td>"#),
        format!("<td><code>{}</code></td>", escape(&c.effect)),
        format!(r#"<td class="small">{}</td>"#, parameters.join("<br>")),
        format!(r#"<td class="num">{}</td>"#, c.parameter_count),
        num(c.residual_fitted, 3),
        num(c.residual_before, 3),
        num(c.residual_after, 3),
        num(c.score, 3),
        format!(
            r#"<td class="small">{}</td>"#,
            if c.verified {
                "time domain"
            } else {
                "screening (estimate)"
            }
        ),
        format!(
            r#"<td class="small">{}{}</td>"#,
            escape(&c.signature),
            c.set_aside.as_ref().map_or(String::new(), |why| format!(
                "<br><b>Set aside:</b> {}",
                escape(why)
            ))
        ),
    ]
    .concat()
}

/// The recordings, numbered as the columns of the mismatch map.
pub fn recordings(out: &mut String, report: &Report) {
    let rows: Vec<(String, String)> = report
        .recordings
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let [a, b] = r.speed_rpm;
            let speed = if a == b || !b.is_finite() {
                tenth(a)
            } else {
                format!("{} → {}", tenth(a), tenth(b))
            };
            let cells = [
                format!(r#"<td class="num">{}</td>"#, i + 1),
                td(&r.label),
                td(&r.kind),
                format!(r#"<td class="num">{}</td>"#, escape(&speed)),
                format!(r#"<td class="num">{}</td>"#, tenth(100.0 * r.load)),
                match &r.set_aside {
                    Some(why) => td(&format!("{}: {why}", r.role)),
                    None => td(&r.role),
                },
            ];
            (String::new(), cells.concat())
        })
        .collect();
    table(
        out,
        "recordings",
        &["#", "label", "kind", "speed [rpm]", "load [%]", "role"],
        &rows,
    );
}
