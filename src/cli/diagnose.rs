//! `torsim diagnose MODEL RECORDING… [--json] [--report FILE.html] [--threads N]
//! [--max-order Q]`: where the model and the recordings disagree, the physics the model
//! left out, fitted and shown to improve on held-out recordings (`spec/diagnosis.md`).
//!
//! Each RECORDING is a CSV with its sidecar beside it (same stem, `.toml`); its label is
//! the sidecar's `label`, else the file stem (with the file name added where two
//! recordings would share a label). Every column must name a node of the model.

use super::error::CliError;
use super::format::{emit, outln, print_json, table};
use super::input::{PRESET_PREFIX, load_model};
use super::progress::Progress;
use std::path::{Path, PathBuf};
use torsim::diagnose::labels::{label_of, unique_labels};
use torsim::diagnose::report::ParameterValue;
use torsim::diagnose::{
    DiagnoseError, DiagnoseOptions, LabelledRecording, Report, diagnose, report_html,
};
use torsim::files::OutputGuard;
use torsim::recording::{BadSamples, ReadOptions, read_recording_with};

/// Options of the command.
#[derive(Debug, clap::Args)]
pub struct DiagnoseArgs {
    /// The user's model: file or preset:NAME.
    pub model: String,
    /// Recordings (CSV; each sidecar, same stem `.toml`, beside it); none with `--power`.
    #[arg(required_unless_present = "power", value_name = "RECORDING")]
    pub recordings: Vec<String>,
    /// Instead of a diagnosis: what a planned campaign can detect and tell apart, and at
    /// what size (issue 14, item 6); no recordings.
    #[arg(long, conflicts_with_all = ["recordings", "report"])]
    pub power: bool,
    /// With `--power`: the campaign plan (TOML, `[[run]]` tables, as `torsim synth
    /// --plan`); default: `torsim synth`'s default campaign.
    #[arg(long, value_name = "PLAN.toml", requires = "power")]
    pub plan: Option<String>,
    /// With `--power`: white noise of every sample, rpm (default 0.1, `torsim synth`'s).
    #[arg(long, value_name = "X", requires = "power")]
    pub noise_rpm: Option<f64>,
    /// With `--power`: pulse-edge jitter, ns (default 20, `torsim synth`'s).
    #[arg(long, value_name = "NS", requires = "power")]
    pub jitter_ns: Option<f64>,
    /// Print the report as one JSON document.
    #[arg(long)]
    pub json: bool,
    /// Also write the report for a person: one self-contained HTML page.
    #[arg(long, value_name = "FILE.html")]
    pub report: Option<String>,
    /// Worker threads for the simulations (default: the machine's cores, at most 8).
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
    /// Highest engine order compared (default 8).
    #[arg(long, value_name = "Q")]
    pub max_order: Option<f64>,
    /// Over-range or impossible samples in the recordings: refuse (list them),
    /// interpolate (from their neighbours) or drop (keep the longest stretch without them).
    #[arg(long, default_value = "refuse", value_parser = super::analyse::parse_bad_samples)]
    pub bad_samples: BadSamples,
}

/// Bad input is exit 2; a diagnosis that could not run is exit 1. The library names a
/// recording by its label; every label it quotes is followed by the file it came from
/// (`files`: label and path of each recording), so the message locates its cause.
fn cli_error(e: DiagnoseError, files: &[(String, String)]) -> CliError {
    let code_input = matches!(e, DiagnoseError::Input(_) | DiagnoseError::Analysis { .. });
    let mut text = e.to_string();
    for (label, path) in files {
        let quoted = format!("`{label}`");
        if text.contains(&quoted) && !text.contains(path.as_str()) {
            text = text.replacen(&quoted, &format!("{quoted} ({path})"), 1);
        }
    }
    let error = anyhow::anyhow!(text);
    if code_input {
        CliError::input(error)
    } else {
        CliError::failed(error)
    }
}

/// The options, checked.
fn options(a: &DiagnoseArgs) -> Result<DiagnoseOptions, CliError> {
    let mut options = DiagnoseOptions::default();
    if let Some(threads) = a.threads {
        if !(1..=256).contains(&threads) {
            return Err(CliError::input(anyhow::anyhow!(
                "--threads {threads}: must be within 1 … 256"
            )));
        }
        options.threads = threads;
    }
    if let Some(q) = a.max_order {
        // The same bound as every other order (`limits::max_order`, 100 by default).
        let limit = torsim::limits::current().max_order;
        if !(q.is_finite() && q > 0.0 && q <= limit) {
            return Err(CliError::input(anyhow::anyhow!(
                "--max-order {q}: must be within 0 … {limit} (exclusive of 0)"
            )));
        }
        options.max_order = q;
    }
    Ok(options)
}

/// Reads every recording, checked against the model's nodes, with its label.
fn read_all(
    paths: &[String],
    nodes: &[String],
    options: &ReadOptions,
) -> Result<Vec<LabelledRecording>, CliError> {
    let mut seen: Vec<PathBuf> = Vec::new();
    let mut recordings = Vec::with_capacity(paths.len());
    for path in paths {
        let file = Path::new(path);
        std::fs::metadata(file)
            .map_err(|e| CliError::input(anyhow::anyhow!("{path}: cannot read: {e}")))?;
        let canonical = std::fs::canonicalize(file).unwrap_or_else(|_| file.to_path_buf());
        if seen.contains(&canonical) {
            return Err(CliError::input(anyhow::anyhow!(
                "{path}: the same recording is given twice"
            )));
        }
        seen.push(canonical);
        let read = read_recording_with(file, Some(nodes), options).map_err(CliError::input)?;
        for note in &read.notes {
            eprintln!("note: {note}");
        }
        let recording = read.recording;
        let label = label_of(file, &recording);
        recordings.push(LabelledRecording { label, recording });
    }
    // Labels name recordings in the report: repeated ones take their file names.
    let labels: Vec<String> = recordings.iter().map(|r| r.label.clone()).collect();
    let files: Vec<&Path> = paths.iter().map(Path::new).collect();
    for (r, label) in recordings.iter_mut().zip(unique_labels(&labels, &files)) {
        r.label = label;
    }
    Ok(recordings)
}

/// Writes `text` to `path` atomically: a temporary file in the same directory, renamed
/// over the target once complete.
fn write_atomic(path: &Path, text: &str) -> Result<(), CliError> {
    torsim::files::write_atomic(path, text)
        .map_err(|e| CliError::input(anyhow::anyhow!("{}: cannot write: {e}", path.display())))
}

/// Issue 13: `--report` never replaces the model, a recording or its sidecar.
fn guard_report(a: &DiagnoseArgs) -> Result<(), CliError> {
    let Some(report) = &a.report else {
        return Ok(());
    };
    let mut guard = OutputGuard::new();
    if !a.model.starts_with(PRESET_PREFIX) {
        guard.input("the model", Path::new(&a.model));
    }
    for recording in &a.recordings {
        guard.recording_input(Path::new(recording));
    }
    guard
        .output("--report", Path::new(report))
        .map_err(CliError::input)
}

/// Runs the command.
pub fn run(a: &DiagnoseArgs) -> Result<(), CliError> {
    if a.power {
        let options = options(a)?;
        return super::diagnose_power::run(a, options.threads, options.max_order);
    }
    let model = load_model(&a.model)?;
    guard_report(a)?;
    let options = options(a)?;
    let nodes: Vec<String> = model.inertias.iter().map(|i| i.name.clone()).collect();
    let recordings = read_all(
        &a.recordings,
        &nodes,
        &ReadOptions {
            bad_samples: a.bad_samples,
        },
    )?;
    let progress = Progress::new("diagnosing");
    let result = diagnose(&model, &recordings, &options, &mut |fraction, stage| {
        progress.message(&format!("diagnosing: {stage}"));
        progress.set(fraction)
    });
    progress.finish();
    let files: Vec<(String, String)> = recordings
        .iter()
        .zip(&a.recordings)
        .map(|(r, path)| (r.label.clone(), path.clone()))
        .collect();
    let report = result.map_err(|e| cli_error(e, &files))?;
    // Everything that can fail comes before the page is written (issue 13).
    let doc = match a.json {
        true => {
            let doc = serde_json::to_value(&report).map_err(CliError::failed)?;
            super::json_guard::check(&doc).map_err(|e| CliError::failed(anyhow::anyhow!(e)))?;
            Some(doc)
        }
        false => None,
    };
    if let Some(path) = &a.report {
        write_atomic(Path::new(path), &report_html(&report, &model.name))?;
    }
    if let Some(doc) = doc {
        return print_json(&doc);
    }
    let mut text = summary(&report, &model.name);
    if let Some(path) = &a.report {
        outln!(text, "report: {path}");
    }
    emit(&text)
}

/// A parameter's value for the terminal.
fn value_text(value: &ParameterValue) -> String {
    match value {
        ParameterValue::Number(v) => format!("{v:.4}"),
        ParameterValue::Text(t) => t.clone(),
    }
}

/// The human summary: verdict, explanation, the held-out fit, the candidates and the
/// ten worst mismatches.
fn summary(report: &Report, model_name: &str) -> String {
    let mut text = String::new();
    let v = &report.verdict;
    outln!(
        text,
        "{model_name}: {} recordings, noise {:.3} rpm, {:.1} s",
        report.recordings.len(),
        report.noise_rpm,
        report.elapsed_s
    );
    let parameters: Vec<String> = v
        .parameters
        .iter()
        .map(|(k, x)| format!("{k} = {}", value_text(x)))
        .collect();
    let parameters = if parameters.is_empty() {
        String::new()
    } else {
        format!(": {}", parameters.join(", "))
    };
    outln!(
        text,
        "verdict: {} (confidence {:.0} %){parameters}",
        v.effect,
        100.0 * v.confidence
    );
    for line in wrap(&v.explanation, 88) {
        outln!(text, "  {line}");
    }
    for sentence in report
        .recordings
        .iter()
        .filter_map(|r| r.set_aside_sentence())
    {
        outln!(text, "  {sentence}");
    }
    let f = &report.fit;
    outln!(
        text,
        "fit: {} {:.3} → {:.3} on {}",
        f.metric,
        f.before,
        f.after,
        if f.validated_on.is_empty() {
            "no held-out data".to_string()
        } else {
            f.validated_on.join("; ")
        }
    );
    outln!(
        text,
        "\ncandidates, best first (score = max(held-out χ²/N, {}) + k·ln(n)/n, lower is better; * verdict):",
        torsim::diagnose::decide::NOISE_CHI2
    );
    let header: Vec<String> = ["", "effect", "k", "χ²/N held out after", "score"]
        .map(String::from)
        .to_vec();
    let rows: Vec<Vec<String>> = report
        .candidates
        .iter()
        .map(|c| {
            vec![
                if c.effect == v.effect { "*" } else { "" }.to_string(),
                c.effect.clone(),
                c.parameter_count.to_string(),
                format!("{:.3}", c.residual_after),
                format!("{:.3}", c.score),
            ]
        })
        .collect();
    if rows.is_empty() {
        outln!(text, "  none tried");
    } else {
        text += &table(&header, &rows);
    }
    for c in &report.candidates {
        if let Some(why) = &c.set_aside {
            outln!(text, "  {} set aside: {why}", c.effect);
        }
    }
    let worst = report.mismatches.len().min(10);
    if worst == 0 {
        outln!(text, "\nno mismatches listed");
        return text;
    }
    outln!(
        text,
        "\n{worst} worst mismatches of the model (IAS order amplitudes, zero-to-peak; z = (measured − simulated)/σ):"
    );
    let header: Vec<String> = [
        "recording",
        "station",
        "order",
        "speed [rpm]",
        "f [Hz]",
        "measured [rpm]",
        "simulated [rpm]",
        "z",
    ]
    .map(String::from)
    .to_vec();
    let rows: Vec<Vec<String>> = report.mismatches[..worst]
        .iter()
        .map(|m| {
            vec![
                m.recording.clone(),
                m.station.clone(),
                m.order.clone(),
                format!("{:.0}", m.speed_rpm),
                format!("{:.1}", m.frequency_hz),
                format!("{:.3}", m.measured),
                format!("{:.3}", m.simulated),
                format!("{:+.1}", m.z),
            ]
        })
        .collect();
    text += &table(&header, &rows);
    text
}

/// `text` in lines of at most `width` characters, broken at spaces.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;
    use torsim::diagnose::report::{Candidate, Fit, Mismatch, REPORT_FORMAT, Verdict};

    fn report() -> Report {
        let candidate = |effect: &str, score: f64| Candidate {
            effect: effect.into(),
            parameters: BTreeMap::new(),
            score,
            residual_before: 2.0,
            residual_after: score,
            residual_fitted: 1.0,
            parameter_count: 1,
            signature: String::new(),
            verified: true,
            rejected: None,
            rejected_steps: Vec::new(),
            set_aside: None,
        };
        let mismatch = |z: f64| Mismatch {
            recording: "Regime A".into(),
            station: "coupling_es".into(),
            order: "1.5".into(),
            speed_rpm: 3000.0,
            frequency_hz: 75.0,
            measured: 1.25,
            simulated: 1.0,
            quantity: "ias_amplitude_rpm".into(),
            z,
        };
        Report {
            format: REPORT_FORMAT,
            verdict: Verdict {
                effect: "gear_backlash".into(),
                confidence: 0.8,
                parameters: BTreeMap::from([(
                    "backlash_deg".to_string(),
                    ParameterValue::Number(0.1),
                )]),
                explanation: "word ".repeat(40),
                equivalent_places: Vec::new(),
            },
            mismatches: (0..12).map(|i| mismatch(9.0 - f64::from(i))).collect(),
            candidates: vec![candidate("gear_backlash", 0.5), candidate("none", 2.0)],
            fit: Fit {
                metric: "held-out χ² per amplitude".into(),
                before: 2.0,
                after: 0.5,
                validated_on: vec!["Regime C, 30 % load".into()],
                swapped_because: None,
            },
            mismatch_map: vec![],
            unexplained_resonances: vec![],
            overlays: vec![],
            recordings: vec![],
            noise_rpm: 0.05,
            not_fitted: Vec::new(),
            elapsed_s: 3.0,
        }
    }

    #[test]
    fn the_summary_has_verdict_fit_candidates_and_ten_mismatches() {
        let text = summary(&report(), "bench");
        assert!(text.contains("verdict: gear_backlash (confidence 80 %): backlash_deg = 0.1000"));
        assert!(
            text.contains("fit: held-out χ² per amplitude 2.000 → 0.500 on Regime C, 30 % load")
        );
        let marked: Vec<&str> = text.lines().filter(|l| l.starts_with('*')).collect();
        assert_eq!(marked.len(), 1, "{text}");
        assert!(marked[0].contains(" gear_backlash "), "{text}");
        assert!(text.contains("10 worst mismatches"));
        assert_eq!(text.matches("coupling_es").count(), 10);
        assert!(text.contains("+9.0") && text.contains("+0.0") && !text.contains("-1.0"));
        assert!(text.lines().all(|l| l.chars().count() <= 100), "{text}");
    }

    #[test]
    fn wraps_at_spaces() {
        assert_eq!(wrap("aa bb cc dd", 5), ["aa bb", "cc dd"]);
        assert_eq!(wrap("", 5), Vec::<String>::new());
        assert_eq!(wrap("abcdefgh ij", 5), ["abcdefgh", "ij"]);
    }

    #[test]
    fn the_page_is_written_atomically_or_not_at_all() {
        let scratch = tempfile::Builder::new()
            .prefix("torsim-cli-page-")
            .tempdir()
            .unwrap();
        let dir = scratch.path();
        let page = dir.join("r.html");
        write_atomic(&page, "<html></html>").unwrap();
        write_atomic(&page, "<html>2</html>").unwrap();
        assert_eq!(std::fs::read_to_string(&page).unwrap(), "<html>2</html>");
        assert_eq!(
            std::fs::read_dir(dir).unwrap().count(),
            1,
            "no temporary left"
        );
        let missing = dir.join("no/such/dir/r.html");
        let e = write_atomic(&missing, "x").unwrap_err();
        assert_eq!(e.code, 2);
        assert!(format!("{:#}", e.error).contains("no/such/dir/r.html"));
    }
}
