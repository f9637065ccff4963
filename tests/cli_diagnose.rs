//! `torsim diagnose`: bad input exits 2 with a message naming the file, the column or the
//! option; on the shipped `none` case the JSON report has the shape of spec/diagnosis.md
//! and `--report` writes the HTML page.

mod run_cli;
mod scratch;
use run_cli::{json, torsim};
use scratch::Scratch;

use std::path::Path;

const CASE: &str = "tests/data/diagnosis/none";

/// The case's recordings (every CSV beside `model.toml`), sorted.
fn case_recordings() -> Vec<String> {
    let mut csv: Vec<String> = std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join(CASE))
        .expect("case folder")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "csv"))
        .map(|p| format!("{CASE}/{}", p.file_name().unwrap().to_string_lossy()))
        .collect();
    csv.sort();
    csv
}

/// A fresh empty directory, removed when the returned guard is dropped.
fn temp_dir(test: &str) -> Scratch {
    Scratch::new(&format!("torsim-diagnose-{test}-"))
}

fn stderr_of(args: &[&str]) -> (Option<i32>, String) {
    let out = torsim(args);
    assert!(
        out.stdout.is_empty(),
        "{args:?}: nothing on stdout on error"
    );
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn the_case_has_ten_recordings() {
    assert_eq!(case_recordings().len(), 10, "{:?}", case_recordings());
}

#[test]
fn a_missing_recording_exits_2_naming_it() {
    let model = format!("{CASE}/model.toml");
    let good = format!("{CASE}/regime-a.csv");
    let (code, stderr) = stderr_of(&["diagnose", &model, &good, "no/such/recording.csv"]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stderr.contains("no/such/recording.csv"), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
}

#[test]
fn a_station_that_is_no_node_of_the_model_exits_2_naming_it() {
    let dir = temp_dir("station");
    let csv = std::fs::read_to_string(format!("{CASE}/regime-a.csv")).expect("case CSV");
    let (header, rest) = csv.split_once('\n').expect("header");
    assert_eq!(header, "time_s,engine_rpm,coupling_es_rpm");
    let path = dir.join("regime-a.csv");
    std::fs::write(&path, format!("time_s,engine_rpm,flange_x_rpm\n{rest}")).expect("write");
    // The sidecar without the CSV's fingerprint (the header was changed on purpose).
    let sidecar = std::fs::read_to_string(format!("{CASE}/regime-a.toml")).expect("sidecar");
    let sidecar: String = sidecar
        .lines()
        .filter(|l| !l.starts_with("csv_sha256") && !l.starts_with("csv_rows"))
        .map(|l| format!("{l}\n"))
        .collect();
    std::fs::write(dir.join("regime-a.toml"), sidecar).expect("sidecar");
    let path = path.display().to_string();
    let (code, stderr) = stderr_of(&["diagnose", "preset:diagnosis-bench", &path]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains(&format!("{path}:1")) && stderr.contains("flange_x_rpm"),
        "{stderr}"
    );
    assert!(stderr.contains("no node of the model"), "{stderr}");
}

#[test]
fn bad_options_and_repeated_recordings_exit_2() {
    let model = format!("{CASE}/model.toml");
    let a = format!("{CASE}/regime-a.csv");
    for (args, needle) in [
        (vec!["--threads", "0"], "--threads 0"),
        (vec!["--max-order=-1"], "--max-order -1"),
        (vec!["--max-order", "NaN"], "--max-order NaN"),
    ] {
        let mut all = vec!["diagnose", &model, &a];
        all.extend(args);
        let (code, stderr) = stderr_of(&all);
        assert_eq!(code, Some(2), "{stderr}");
        assert!(stderr.contains(needle), "{stderr}");
    }
    let (code, stderr) = stderr_of(&["diagnose", &model, &a, &a]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stderr.contains("given twice"), "{stderr}");
    let (code, stderr) = stderr_of(&["diagnose", &model]);
    assert_eq!(code, Some(2), "no recording: {stderr}");
    let (code, stderr) = stderr_of(&["diagnose", "preset:no-such", &a]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stderr.contains("no preset `no-such`"), "{stderr}");
}

#[test]
fn the_none_case_gives_a_report_and_a_page() {
    let dir = temp_dir("none");
    let page = dir.join("report.html");
    let page_arg = page.display().to_string();
    let model = format!("{CASE}/model.toml");
    // The six full-load regimes only: a quick run (the whole campaign of every shipped
    // case is diagnosed in tests/diagnose_cases.rs).
    let recordings: Vec<String> = case_recordings()
        .into_iter()
        .filter(|p| p.contains("regime-") && !p.contains("-part"))
        .collect();
    assert_eq!(recordings.len(), 6);
    let mut args = vec!["diagnose", model.as_str(), "--json", "--report", &page_arg];
    args.extend(recordings.iter().map(String::as_str));
    let report = json(&args);
    assert_eq!(report["format"], 1);
    let effect = report["verdict"]["effect"]
        .as_str()
        .expect("verdict.effect");
    assert_eq!(effect, "none", "{}", report["verdict"]["explanation"]);
    for key in ["mismatches", "candidates"] {
        assert!(report[key].is_array(), "{key}");
    }
    for key in ["metric", "before", "after", "validated_on"] {
        assert!(report["fit"].get(key).is_some(), "fit.{key}");
    }
    assert_eq!(report["recordings"].as_array().map(Vec::len), Some(6));
    let html = std::fs::read_to_string(&page).expect("the page is written");
    assert!(html.starts_with("<!DOCTYPE html>") && html.contains("<svg"));
    assert!(html.contains(effect));
    // Written atomically: no temporary file left beside it.
    let left: Vec<_> = std::fs::read_dir(&dir)
        .expect("dir")
        .filter_map(|e| e.ok())
        .map(|e| e.file_name())
        .collect();
    assert_eq!(left, [std::ffi::OsString::from("report.html")]);
}
