//! `torsim campbell MODEL [--from-rpm A --to-rpm B --step-rpm S] [--csv FILE]`.

use super::error::CliError;
use super::format::{emit, number, numbers, order_key, outln, print_json, print_warnings, table};
use super::input::PRESET_PREFIX;
use super::input::Sweep;
use serde_json::{Value, json};
use std::path::Path;
use torsim::files::OutputGuard;
use torsim::modal::campbell;
use torsim::physics::{OperatingPoint, System};

/// Runs the command.
pub fn run(sweep: &Sweep, csv: Option<&str>, json: bool) -> Result<(), CliError> {
    let (model, speeds, load) = sweep.resolve()?;
    // Issue 13: an output never replaces the model.
    if let Some(path) = csv {
        let mut guard = OutputGuard::new();
        if !sweep.model.starts_with(PRESET_PREFIX) {
            guard.input("the model", Path::new(&sweep.model));
        }
        guard
            .output("--csv", Path::new(path))
            .map_err(CliError::input)?;
    }
    let system = System::new(
        &model,
        OperatingPoint {
            load,
            temperature_c: None,
        },
    )?;
    print_warnings(&system.warnings);
    let orders = model.orders();
    let diagram = campbell(&system, &speeds, &orders)?;
    let frequencies: Vec<f64> = diagram.modes.iter().map(|m| m.frequency_hz).collect();
    print_warnings(&system.frequency_range_warnings(&frequencies));
    let operating = model.operation.operating_range_rpm;
    let in_operating = |rpm: f64| operating.is_some_and(|[lo, hi]| rpm >= lo && rpm <= hi);
    let write = || csv.map_or(Ok(()), |path| write_csv(path, &diagram));
    if json {
        let modes = diagram
            .frequency_hz
            .iter()
            .enumerate()
            .map(|(i, f)| Ok(json!({"mode": i + 1, "frequency_hz": numbers(f, "mode frequency")?})))
            .collect::<Result<Vec<Value>, CliError>>()?;
        let crossings = diagram
            .crossings
            .iter()
            .map(|c| {
                Ok(json!({
                    "order": number(c.order, "order")?,
                    "mode": c.mode,
                    "rpm": number(c.speed_rpm, "crossing speed")?,
                    "frequency_hz": number(c.frequency_hz, "crossing frequency")?,
                    "in_operating_range": in_operating(c.speed_rpm),
                }))
            })
            .collect::<Result<Vec<Value>, CliError>>()?;
        let doc = json!({
            "speeds_rpm": numbers(&speeds, "speed")?,
            "orders": numbers(&orders, "order")?,
            "operating_range_rpm": operating,
            "modes": modes,
            "crossings": crossings,
        });
        write()?;
        return print_json(&doc);
    }
    let mut text = String::new();
    outln!(
        text,
        "{}: modes (Hz) — constant over speed in the linear model",
        model.name
    );
    for (i, m) in diagram.modes.iter().enumerate() {
        outln!(text, "  mode {}: {:.3} Hz", i + 1, m.frequency_hz);
    }
    outln!(
        text,
        "crossings {} … {} rpm:",
        speeds[0],
        speeds[speeds.len() - 1]
    );
    let rows: Vec<Vec<String>> = diagram
        .crossings
        .iter()
        .map(|c| {
            vec![
                order_key(c.order),
                format!("{}", c.mode),
                format!("{:.1}", c.speed_rpm),
                format!("{:.2}", c.frequency_hz),
                if in_operating(c.speed_rpm) {
                    "IN OPERATING RANGE".into()
                } else {
                    String::new()
                },
            ]
        })
        .collect();
    text += &table(
        &["order", "mode", "rpm", "f [Hz]", ""].map(String::from),
        &rows,
    );
    write()?;
    emit(&text)
}

/// Writes the diagram atomically: one row per speed, each mode's frequency and each
/// order line.
fn write_csv(path: &str, d: &torsim::modal::Campbell) -> Result<(), CliError> {
    let mut text = String::from("speed_rpm");
    for i in 0..d.frequency_hz.len() {
        text.push_str(&format!(",mode_{}_hz", i + 1));
    }
    for q in &d.orders {
        text.push_str(&format!(",order_{}_hz", order_key(*q)));
    }
    text.push('\n');
    for (s, speed) in d.speeds_rpm.iter().enumerate() {
        text.push_str(&format!("{speed}"));
        for f in &d.frequency_hz {
            text.push_str(&format!(",{}", f[s]));
        }
        for q in &d.orders {
            text.push_str(&format!(",{}", q * speed / 60.0));
        }
        text.push('\n');
    }
    torsim::files::write_atomic(Path::new(path), text)
        .map_err(|e| CliError::input(anyhow::anyhow!("--csv {path}: cannot write: {e}")))
}
