//! `torsim modes MODEL [--speed-rpm N] [--load L]`: natural frequencies, damped
//! frequencies, damping ratios and mode shapes.

use super::error::CliError;
use super::format::{emit, number, outln, print_json, print_warnings, table};
use super::input::{check_load, load_model};
use super::values;
use serde_json::{Map, Value, json};
use torsim::modal::{DampedMode, LawDeviation, damped_modes, law_deviations, modes};
use torsim::physics::{OperatingPoint, System};

/// Runs the command.
pub fn run(model_arg: &str, speed_rpm: Option<f64>, load: f64, json: bool) -> Result<(), CliError> {
    let speed_rpm = speed_rpm
        .map(|n| values::speed_rpm("--speed-rpm", n))
        .transpose()?;
    let model = load_model(model_arg)?;
    let point = OperatingPoint {
        load: check_load(load)?,
        temperature_c: None,
    };
    let system = System::new(&model, point)?;
    print_warnings(&system.warnings);
    let modes = modes(&system)?;
    let damped = damped_modes(&system, &modes);
    let frequencies: Vec<f64> = modes.iter().map(|m| m.frequency_hz).collect();
    let nominal = System::nominal(&model, point)?;
    print_warnings(&nominal.frequency_range_warnings(&frequencies));
    let deviations = law_deviations(&system, &nominal, &modes);
    if json {
        let mut list = Vec::new();
        for (i, (m, d)) in modes.iter().zip(&damped).enumerate() {
            list.push(mode_entry(
                i,
                m.frequency_hz,
                &m.shape_by_node(&system),
                d,
                &system,
            )?);
        }
        let mut doc = json!({
            "model": model.name,
            "load": point.load,
            "rigid_body_modes": system.rigid_body_modes,
            "modes": list,
        });
        if !deviations.is_empty() {
            doc["rubber_law"] = law_json(&deviations)?;
        }
        // Echoed only when given: no null in the output (issue 13).
        if let Some(n) = speed_rpm {
            doc["speed_rpm"] = number(n, "speed")?;
        }
        return print_json(&doc);
    }
    let mut text = String::new();
    outln!(
        text,
        "{} — {} flexible modes ({} rigid-body mode(s) not listed), load {}",
        model.name,
        modes.len(),
        system.rigid_body_modes,
        point.load
    );
    let mut header: Vec<String> = ["mode", "f [Hz]", "f_d [Hz]", "ζ [%]"]
        .map(String::from)
        .to_vec();
    header.extend(system.node_names.iter().cloned());
    let rows: Vec<Vec<String>> = modes
        .iter()
        .zip(&damped)
        .enumerate()
        .map(|(i, (m, d))| {
            let known = |text: String| if damped_known(d) { text } else { "—".into() };
            let mut row = vec![
                format!("{}", i + 1),
                format!("{:.3}", m.frequency_hz),
                known(format!("{:.3}", d.frequency_hz)),
                // `+ 0.0` turns −0 into 0: an undamped mode prints 0.00, not -0.00.
                known(format!("{:.2}", 100.0 * d.damping_ratio + 0.0)),
            ];
            row.extend(m.shape_by_node(&system).iter().map(|v| format!("{v:+.4}")));
            row
        })
        .collect();
    text += &table(&header, &rows);
    if damped.iter().any(|d| !damped_known(d)) {
        outln!(text, "—: {NOT_DAMPED}");
    }
    if !deviations.is_empty() {
        text += &law_text(&deviations);
    }
    emit(&text)
}

/// The rubber-law table: each stage's causal chain against seed 000's nominal law at
/// each mode (`spec/model-format.md`, `kind = "rubber"`).
fn law_text(deviations: &[LawDeviation]) -> String {
    let mut text = String::new();
    outln!(
        text,
        "\nrubber law: each stage's causal chain (used by every analysis) against seed 000's \
         nominal law k·α_f(f)·(1 + iξ_T) (not causal), at each mode"
    );
    let header: Vec<String> = [
        "stage",
        "mode",
        "f [Hz]",
        "energy share [%]",
        "stiffness Δ [%]",
        "loss factor Δ [%]",
    ]
    .map(String::from)
    .to_vec();
    let rows: Vec<Vec<String>> = deviations
        .iter()
        .map(|d| {
            vec![
                d.connection.clone(),
                d.mode.to_string(),
                format!("{:.3}", d.frequency_hz),
                format!("{:.1}", 100.0 * d.energy_share + 0.0),
                format!("{:+.2}", 100.0 * d.stiffness_deviation + 0.0),
                format!("{:+.2}", 100.0 * d.loss_deviation + 0.0),
            ]
        })
        .collect();
    text += &table(&header, &rows);
    text
}

/// The rubber-law deviations as JSON: one entry per stage and mode.
fn law_json(deviations: &[LawDeviation]) -> Result<Value, CliError> {
    let mut list = Vec::new();
    for d in deviations {
        list.push(json!({
            "connection": d.connection,
            "mode": d.mode,
            "frequency_hz": number(d.frequency_hz, "natural frequency")?,
            "energy_share": number(d.energy_share, "energy share")?,
            "stiffness_deviation": number(d.stiffness_deviation, "stiffness deviation")?,
            "loss_factor_deviation": number(d.loss_deviation, "loss factor deviation")?,
        }));
    }
    Ok(json!({
        "representation": "causal Maxwell chain, fitted at the modes and over the model's band",
        "compared_with": "seed 000 nominal law k·α_f(f)·(1 + iξ_T), not causal",
        "deviations": list,
    }))
}

/// One mode's JSON: a damped frequency not found is said (`not_computed`), never null.
fn mode_entry(
    i: usize,
    frequency_hz: f64,
    shape_by_node: &[f64],
    d: &DampedMode,
    system: &System,
) -> Result<Value, CliError> {
    let mut shape = Map::new();
    for (name, &v) in system.node_names.iter().zip(shape_by_node) {
        shape.insert(name.clone(), number(v, "mode shape")?);
    }
    let mut entry = json!({
        "mode": i + 1,
        "frequency_hz": number(frequency_hz, "natural frequency")?,
        "shape": shape,
    });
    if damped_known(d) {
        entry["damped_frequency_hz"] = number(d.frequency_hz, "damped frequency")?;
        entry["damping_ratio"] = number(d.damping_ratio, "damping ratio")?;
    } else {
        entry["not_computed"] = json!(NOT_DAMPED);
    }
    Ok(entry)
}

/// Why a mode has no damped frequency (issue 13: said instead of NaN or null).
const NOT_DAMPED: &str = "damped frequency and damping ratio not computed: neither the \
     Rayleigh iteration nor the state matrix gave a damped eigenvalue near this mode";

/// True when the damped eigenvalue of a mode was found.
fn damped_known(d: &DampedMode) -> bool {
    d.frequency_hz.is_finite() && d.damping_ratio.is_finite()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_damped_frequency_not_found_is_said_not_null() {
        let model = torsim::model::parse_model(
            torsim::model::presets::preset("test-rig-mod1")
                .unwrap()
                .text,
            "rig",
        )
        .unwrap();
        let system = System::new(&model, OperatingPoint::default()).unwrap();
        let nan = DampedMode {
            frequency_hz: f64::NAN,
            damping_ratio: f64::NAN,
        };
        let shape = vec![1.0; system.node_names.len()];
        let entry = mode_entry(0, 10.0, &shape, &nan, &system).unwrap();
        assert_eq!(entry["not_computed"], json!(NOT_DAMPED));
        assert!(entry.get("damped_frequency_hz").is_none());
        assert!(!entry.to_string().contains("null"), "{entry}");
    }

    #[test]
    fn nonsense_speeds_are_refused() {
        for n in [f64::NAN, -5.0, 0.0, 1e300] {
            let e = super::run("preset:test-rig-mod1", Some(n), 1.0, true).unwrap_err();
            assert_eq!(e.code, 2);
            let text = e.error.to_string();
            assert!(text.starts_with("--speed-rpm "), "{text}");
            assert!(
                text.contains("finite, > 0 and at most 100000 rpm"),
                "{text}"
            );
        }
    }
}
