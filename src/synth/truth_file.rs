//! `truth.toml`: what a generated folder's recordings really contain — the effect and its
//! parameters, every parameter error, the seed, the measurement, the plan and the exact
//! command. It sits beside the recordings for the tests that check a diagnosis; nothing in
//! the library reads it, and the diagnosis must not.

use super::measurement::Measurement;
use super::plan::Plan;
use crate::effects::ParamValue;
use crate::effects::SensorArtifact;
use crate::effects::Truth;
use crate::recording::RunShape;
use std::fmt::Write;

/// The file name of the truth in a generated folder.
pub const TRUTH_FILE: &str = "truth.toml";
/// The file name of the truth model (the user's model with the effect and the errors).
pub const TRUTH_MODEL_FILE: &str = "truth-model.toml";

/// A TOML basic string.
fn quote(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            c if (c as u32) < 0x20 || c as u32 == 0x7f => {
                let _ = write!(out, "\\u{:04X}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// A TOML float (always with a point or an exponent).
fn float(x: f64) -> String {
    format!("{x:?}")
}

fn value(v: &ParamValue) -> String {
    match v {
        ParamValue::Number(x) => float(*x),
        ParamValue::Text(s) => quote(s),
    }
}

/// The text of `truth.toml` for a folder made by `command` (as typed, for remaking it).
pub fn truth_toml(
    truth: &Truth,
    plan: &Plan,
    m: &Measurement,
    param_error_pct: f64,
    command: &str,
) -> String {
    let mut s = String::new();
    let mut line = |text: String| {
        s.push_str(&text);
        s.push('\n');
    };
    line("# The truth behind the recordings of this folder, written by `torsim synth`.".into());
    line("# Only tests read it: a diagnosis must not (spec/diagnosis.md).".into());
    line("format = 1".into());
    line(format!("command = {}", quote(command)));
    line(format!(
        "generator = {}",
        quote(&format!("torsim {}", env!("CARGO_PKG_VERSION")))
    ));
    line(format!("seed = {}", truth.seed));
    line(format!("param_error_pct = {}", float(param_error_pct)));
    line(format!("truth_model = {}", quote(TRUTH_MODEL_FILE)));
    line(String::new());
    line("[effect]".into());
    line(format!("name = {}", quote(truth.effect.effect.as_str())));
    line(format!("summary = {}", quote(&truth.effect.summary)));
    line(String::new());
    line("[effect.parameters]".into());
    for (k, v) in &truth.effect.parameters {
        line(format!("{k} = {}", value(v)));
    }
    for e in &truth.parameter_errors {
        line(String::new());
        line("[[parameter_error]]".into());
        line(format!("parameter = {}", quote(&e.parameter)));
        line(format!("user = {}", float(e.user_value)));
        line(format!("truth = {}", float(e.truth_value)));
        line(format!("factor = {}", float(e.factor())));
    }
    line(String::new());
    line("[measurement]".into());
    line(format!("rate_hz = {}", float(m.rate_hz)));
    line(format!("noise_rpm = {}", float(m.noise_rpm)));
    line(format!("jitter_ns = {}", float(m.jitter_ns)));
    line(format!("wobble_pct = {}", float(m.wobble_pct)));
    line(format!("wobble_period_s = {}", float(m.wobble_period_s)));
    line(format!("resolution_rpm = {}", float(m.resolution_rpm)));
    for st in &m.stations {
        line(String::new());
        line("[[measurement.station]]".into());
        line(format!("node = {}", quote(&st.node)));
        line(format!("kind = {}", quote(&st.kind)));
        line(format!("lines_per_rev = {}", st.lines_per_rev));
    }
    for a in m.artifacts.iter().chain(&truth.artifact) {
        line(String::new());
        line("[[measurement.artifact]]".into());
        match a {
            SensorArtifact::TapeJoint {
                station,
                joint_fraction,
            } => {
                line("kind = \"tape_joint\"".into());
                line(format!("station = {}", quote(station)));
                line(format!("joint_fraction = {}", float(*joint_fraction)));
            }
            SensorArtifact::PitchError { station, error_deg } => {
                line("kind = \"pitch_error\"".into());
                line(format!("station = {}", quote(station)));
                line(format!("error_deg = {}", float(*error_deg)));
            }
        }
    }
    for r in &plan.runs {
        line(String::new());
        line("[[recording]]".into());
        line(format!("file = {}", quote(&format!("{}.csv", r.file))));
        line(format!("label = {}", quote(&r.label)));
        match r.shape {
            RunShape::Steady { speed_rpm } | RunShape::LongRun { speed_rpm } => {
                line("kind = \"steady\"".into());
                line(format!("speed_rpm = {}", float(speed_rpm)));
            }
            RunShape::Ramp { from_rpm, to_rpm } => {
                line("kind = \"run-up\"".into());
                line(format!("from_rpm = {}", float(from_rpm)));
                line(format!("to_rpm = {}", float(to_rpm)));
            }
        }
        line(format!("duration_s = {}", float(r.duration_s)));
        line(format!("load = {}", float(r.load)));
        line(format!(
            "rate_hz = {}",
            float(r.rate_hz.unwrap_or(m.rate_hz))
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strings_and_floats_are_toml() {
        assert_eq!(quote("a \"b\"\\\n"), "\"a \\\"b\\\"\\\\\\n\"");
        assert_eq!(float(1.0), "1.0");
        assert_eq!(float(1e-5), "1e-5");
        let doc: toml_edit::Document<String> =
            format!("x = {}\ny = {}", float(2.5e-7), quote("é\u{1}"))
                .parse()
                .unwrap();
        assert_eq!(doc["x"].as_float(), Some(2.5e-7));
        assert_eq!(doc["y"].as_str(), Some("é\u{1}"));
    }
}
