//! Property (issue 13, deliverable 5): no output file ever holds NaN.
//!
//! - `write_recording` of a recording whose samples may be NaN or infinite either refuses
//!   it and writes nothing, or writes a CSV and sidecar with no `NaN`, `inf` or `null`.
//! - The JSON that `torsim analyse --json` (random uniform recordings) and `torsim modes
//!   --json` (random valid models) print on success holds no `null` (serde_json prints
//!   a non-finite number as `null`).

mod proptest_support;
mod scratch;

use std::path::Path;
use std::process::Command;

use proptest::prelude::*;
use scratch::Scratch;
use torsim::model::save_model_file;
use torsim::recording::{sidecar_path, write_recording};

/// A directory of its own under the system temp dir, removed when dropped.
fn scratch_dir(tag: &str) -> Scratch {
    Scratch::new(&format!("torsim-proptest-{tag}-"))
}

/// The words a non-finite number leaves in CSV, TOML or JSON text (lowercased).
fn non_finite_word(text: &str) -> Option<&'static str> {
    let lower = text.to_lowercase();
    ["nan", "inf", "null"].into_iter().find(|w| {
        lower
            .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .any(|token| token == *w || token == "infinity")
    })
}

/// The path of the first `null` in a JSON document (serde_json prints NaN and ±∞ as
/// `null`), or why it is not JSON.
fn null_in_json(text: &str) -> Option<String> {
    fn walk(value: &serde_json::Value, path: &str) -> Option<String> {
        match value {
            serde_json::Value::Null => Some(path.to_string()),
            serde_json::Value::Array(items) => items
                .iter()
                .enumerate()
                .find_map(|(i, v)| walk(v, &format!("{path}[{i}]"))),
            serde_json::Value::Object(map) => map
                .iter()
                .find_map(|(k, v)| walk(v, &format!("{path}.{k}"))),
            _ => None,
        }
    }
    match serde_json::from_str::<serde_json::Value>(text) {
        Ok(value) => walk(&value, "$"),
        Err(e) => Some(format!("not JSON: {e}")),
    }
}

fn run_json(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_torsim"))
        .args(args)
        .output()
        .expect("runs torsim");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// A sample poisoned with NaN, +inf or -inf at `row` of channel `channel` (or of time).
#[derive(Debug, Clone)]
struct Poison {
    row: usize,
    channel: usize,
    value: f64,
}

fn poison() -> impl Strategy<Value = Option<Poison>> {
    prop::option::of(
        (
            any::<usize>(),
            0_usize..3,
            prop_oneof![Just(f64::NAN), Just(f64::INFINITY), Just(f64::NEG_INFINITY)],
        )
            .prop_map(|(row, channel, value)| Poison {
                row,
                channel,
                value,
            }),
    )
}

proptest! {
    // 128 cases: under 1 s in a debug build.
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn a_written_recording_holds_no_nan(
        case in proptest_support::recording_case(),
        poison in poison(),
    ) {
        let mut recording = case.recording();
        if let Some(p) = &poison {
            let row = p.row % recording.time_s.len();
            match recording.channels.get_mut(p.channel) {
                Some(channel) => channel.values[row] = p.value,
                None => recording.time_s[row] = p.value,
            }
        }
        let scratch = scratch_dir("write");
        let csv = scratch.join("rec.csv");
        match write_recording(&recording, &csv) {
            Ok(()) => {
                prop_assert!(poison.is_none(), "a non-finite sample was written: {:?}", poison);
                for path in [csv.clone(), sidecar_path(&csv)] {
                    let text = read(&path);
                    prop_assert_eq!(non_finite_word(&text), None, "{}:\n{}", path.display(), text);
                }
            }
            Err(_) => {
                prop_assert!(poison.is_some(), "a finite recording was refused");
                prop_assert!(!csv.exists() && !sidecar_path(&csv).exists(),
                    "a refused recording left files behind");
            }
        }
    }
}

proptest! {
    // 16 runs of the binary on recordings of up to 60 000 samples: about 1 s in a debug
    // build.
    #![proptest_config(ProptestConfig::with_cases(16))]

    #[test]
    fn analyse_json_holds_no_nan(case in proptest_support::recording_case()) {
        let scratch = scratch_dir("analyse");
        let csv = scratch.join("rec.csv");
        write_recording(&case.recording(), &csv).expect("a finite recording is written");
        let (ok, stdout, stderr) = run_json(&["analyse", csv.to_str().expect("utf-8"), "--json"]);
        if ok {
            prop_assert_eq!(null_in_json(&stdout), None, "{:?}:\n{}", case, stdout);
        } else {
            prop_assert!(stderr.contains("torsim:"), "no message: {}", stderr);
        }
    }
}

proptest! {
    // 32 runs of the binary (a model's modes take milliseconds): under 1 s.
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn modes_json_holds_no_nan(model in proptest_support::model()) {
        let scratch = scratch_dir("modes");
        let path = scratch.join("model.toml");
        save_model_file(&model, &path).expect("writes the model");
        // With a speed: without one, `speed_rpm` is printed as `null` (reported apart).
        let (ok, stdout, stderr) = run_json(&[
            "modes", path.to_str().expect("utf-8"), "--speed-rpm", "1500", "--json",
        ]);
        if ok {
            prop_assert_eq!(null_in_json(&stdout), None, "{}", stdout);
        } else {
            prop_assert!(stderr.contains("torsim:"), "no message: {}", stderr);
        }
    }
}
