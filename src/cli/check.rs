//! `torsim check [PRESET…]`: runs every `[expect]` block; exit 1 when one fails.

use super::error::CliError;
use super::format::{emit, outln, print_json};
use super::input::load_model;
use serde_json::json;
use std::path::Path;
use torsim::check::run_checks;
use torsim::model::presets::PRESETS;

/// The model files to check: those named, else every `*.toml` in `./presets/`, else the
/// presets shipped in the binary.
fn targets(named: &[String]) -> Result<Vec<String>, CliError> {
    if !named.is_empty() {
        return Ok(named.to_vec());
    }
    let dir = Path::new("presets");
    if dir.is_dir() {
        let mut files: Vec<String> = std::fs::read_dir(dir)?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .map(|p| p.display().to_string())
            .collect();
        files.sort();
        if !files.is_empty() {
            return Ok(files);
        }
    }
    Ok(PRESETS
        .iter()
        .map(|p| format!("preset:{}", p.name))
        .collect())
}

/// Runs the command.
pub fn run(named: &[String], json: bool) -> Result<(), CliError> {
    let mut all_passed = true;
    let mut text = String::new();
    let mut reports = Vec::new();
    for file in targets(named)? {
        let model = load_model(&file)?;
        let outcomes = run_checks(&model)?;
        let passed = outcomes.iter().all(|o| o.passed);
        all_passed &= passed;
        if !json {
            outln!(
                text,
                "{} {file} ({} checks)",
                if passed { "PASS" } else { "FAIL" },
                outcomes.len()
            );
            for o in &outcomes {
                let mark = if o.passed { "ok  " } else { "FAIL" };
                outln!(
                    text,
                    "  {mark} {}: expected {}; computed {}",
                    o.kind,
                    o.expected,
                    o.computed
                );
            }
            if outcomes.is_empty() {
                outln!(text, "  (no [expect] checks)");
            }
        }
        let checks: Vec<_> = outcomes
            .iter()
            .map(|o| {
                let mut check = json!({"kind": o.kind, "expected": o.expected, "computed": o.computed, "passed": o.passed});
                // `value` only where the check has a number: never null (issue 13); what
                // was found is in `computed`.
                if let Some(v) = o.value.filter(|v| v.is_finite()) {
                    check["value"] = json!(v);
                }
                check
            })
            .collect();
        reports.push(json!({"file": file, "passed": passed, "checks": checks}));
    }
    if json {
        print_json(&json!({ "presets": reports }))?;
    } else {
        emit(&text)?;
    }
    if all_passed {
        Ok(())
    } else {
        Err(CliError::failed(anyhow::anyhow!(
            "some expectations failed"
        )))
    }
}
