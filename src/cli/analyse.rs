//! `torsim analyse RECORDING.csv [--bad-samples refuse|interpolate|drop] [--json]`: order analysis of a recording or a simulated
//! CSV (the sidecar beside it): RMS, irregularity ratio and order amplitudes per station
//! and per pair of stations, and for run-ups the STFT with order tracks.

use super::error::CliError;
use super::format::{emit, number, numbers, order_key, outln, print_json, table};
use serde_json::{Map, Value, json};
use std::path::Path;
use torsim::recording::{BadSamples, ReadOptions, Run, read_recording_with};
use torsim::signal::{Analysis, StationAnalysis, analyse};

/// Parses `--bad-samples`: `refuse`, `interpolate` or `drop` (issue 13).
pub fn parse_bad_samples(text: &str) -> Result<BadSamples, String> {
    BadSamples::parse(text).ok_or_else(|| format!("`{text}` is none of refuse, interpolate, drop"))
}

/// Runs the command.
pub fn run(recording: &str, bad_samples: BadSamples, json: bool) -> Result<(), CliError> {
    let path = Path::new(recording);
    // Issue 13: a missing CSV is named before its sidecar is looked for.
    if !path.is_file() {
        return Err(CliError::input(anyhow::anyhow!(
            "{recording}: no such recording (the CSV does not exist or is not a file)"
        )));
    }
    let options = ReadOptions { bad_samples };
    let read = read_recording_with(path, None, &options).map_err(CliError::input)?;
    for note in &read.notes {
        eprintln!("note: {note}");
    }
    let rec = read.recording;
    let analysis =
        analyse(&rec).map_err(|e| CliError::input(anyhow::anyhow!("{recording}: {e}")))?;
    // The run as the GUI and the diagnosis see it: one classifier (issue 14, item 1).
    let run = Run::of(&rec);
    if json {
        let mut doc = to_json(&analysis)?;
        if let Value::Object(map) = &mut doc {
            map.insert("run".into(), run_json(&run)?);
        }
        return print_json(&doc);
    }
    let label = format!(
        "{recording} ({}, {:.3} s)",
        run.shape.describe(),
        run.duration_s
    );
    print_analysis(&label, &analysis, "")
}

/// `{"shape": "steady" | "long run" | "run-up", "speeds_rpm": [start, end], "duration_s"}`
/// of [`Run::of`] (an extension of `spec/cli.md`'s `analyse --json`).
fn run_json(run: &Run) -> Result<Value, CliError> {
    Ok(json!({
        "shape": run.shape.label(),
        "speeds_rpm": numbers(&run.speeds_rpm(), "run speed")?,
        "duration_s": number(run.duration_s, "run duration")?,
    }))
}

/// Prints an analysis as tables, headed by `label`, with `extra` lines at the end.
pub fn print_analysis(label: &str, analysis: &Analysis, extra: &str) -> Result<(), CliError> {
    let mut text = String::new();
    outln!(
        text,
        "{label} — {} run, reference `{}`, {} cycles averaged; orders zero-to-peak [rpm]",
        analysis.kind.as_str(),
        analysis.reference,
        analysis.cycles
    );
    let signals: Vec<&StationAnalysis> = analysis.stations.iter().chain(&analysis.n_rel).collect();
    let mut header = vec!["".to_string()];
    header.extend(signals.iter().map(|s| s.name.clone()));
    let mut rows = vec![
        row("mean [rpm]", &signals, |s| {
            format!("{:.2}", s.mean_speed_rpm)
        }),
        row("RMS [rpm]", &signals, |s| format!("{:.3}", s.rms_rpm)),
        row("IR [%]", &signals, |s| format!("{:.3}", s.irregularity_pct)),
    ];
    let orders: Vec<f64> = signals
        .first()
        .map(|s| s.orders.iter().map(|o| o.order).collect())
        .unwrap_or_default();
    for (i, q) in orders.iter().enumerate() {
        rows.push(row(&format!("order {}", order_key(*q)), &signals, |s| {
            format!("{:.3}", s.orders[i].amplitude)
        }));
    }
    text += &table(&header, &rows);
    if let Some(axes) = &analysis.stft {
        outln!(
            text,
            "STFT: {} windows of {:.3} s, {:.0} … {:.0} rpm (see --json for the tracks)",
            axes.times_s.len(),
            axes.frequencies_hz.get(1).map_or(0.0, |df| 1.0 / df),
            axes.speeds_rpm.first().copied().unwrap_or(0.0),
            axes.speeds_rpm.last().copied().unwrap_or(0.0)
        );
    }
    text += extra;
    emit(&text)
}

fn row(
    label: &str,
    signals: &[&StationAnalysis],
    cell: impl Fn(&StationAnalysis) -> String,
) -> Vec<String> {
    std::iter::once(label.to_string())
        .chain(signals.iter().map(|s| cell(s)))
        .collect()
}

/// The `analyse --json` document: the keys of `simulate` (`rms_rpm`, `irregularity_pct`,
/// `orders`) plus `mean_speed_rpm`, `n_rel` and, for run-ups, `stft`.
pub fn to_json(analysis: &Analysis) -> Result<Value, CliError> {
    let mut doc = stats_json(&analysis.stations)?;
    doc.insert("reference".into(), json!(analysis.reference));
    doc.insert("kind".into(), json!(analysis.kind.as_str()));
    doc.insert("cycles".into(), json!(analysis.cycles));
    doc.insert("n_rel".into(), Value::Object(stats_json(&analysis.n_rel)?));
    if let Some(axes) = &analysis.stft {
        let mut stations = Map::new();
        for s in analysis.stations.iter().chain(&analysis.n_rel) {
            let Some(st) = &s.stft else { continue };
            let mut tracks = Map::new();
            for (q, track) in axes.orders.iter().zip(&st.order_tracks_rpm) {
                tracks.insert(order_key(*q), numbers(track, "order track")?);
            }
            let magnitude = st
                .magnitude_rpm
                .iter()
                .map(|m| numbers(m, "STFT magnitude"))
                .collect::<Result<Vec<_>, _>>()?;
            stations.insert(
                s.name.clone(),
                json!({ "order_tracks_rpm": tracks, "magnitude_rpm": magnitude }),
            );
        }
        doc.insert(
            "stft".into(),
            json!({
                "times_s": numbers(&axes.times_s, "STFT time")?,
                "speeds_rpm": numbers(&axes.speeds_rpm, "STFT speed")?,
                "frequencies_hz": numbers(&axes.frequencies_hz, "STFT frequency")?,
                "stations": stations,
            }),
        );
    }
    Ok(Value::Object(doc))
}

/// `{"rms_rpm":{name:…},"irregularity_pct":{…},"orders":{name:{order:…}},"mean_speed_rpm":{…}}`.
fn stats_json(signals: &[StationAnalysis]) -> Result<Map<String, Value>, CliError> {
    let (mut rms, mut ir, mut orders, mut mean) = (Map::new(), Map::new(), Map::new(), Map::new());
    for s in signals {
        rms.insert(s.name.clone(), number(s.rms_rpm, "RMS")?);
        ir.insert(
            s.name.clone(),
            number(s.irregularity_pct, "irregularity ratio")?,
        );
        mean.insert(s.name.clone(), number(s.mean_speed_rpm, "mean speed")?);
        let mut by_order = Map::new();
        for o in &s.orders {
            by_order.insert(order_key(o.order), number(o.amplitude, "order amplitude")?);
        }
        orders.insert(s.name.clone(), Value::Object(by_order));
    }
    let mut doc = Map::new();
    doc.insert("rms_rpm".into(), Value::Object(rms));
    doc.insert("irregularity_pct".into(), Value::Object(ir));
    doc.insert("orders".into(), Value::Object(orders));
    doc.insert("mean_speed_rpm".into(), Value::Object(mean));
    Ok(doc)
}
