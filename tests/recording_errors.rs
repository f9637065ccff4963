//! Recordings (spec/recording-format.md): every rejection names the file, the line and
//! the reason.

mod synth;

use std::path::PathBuf;
use synth::{put, temp_dir};
use torsim::recording::{ChannelKind, Reason, Recording, RecordingError, read_recording};

const SIDECAR: &str = "format = 1\nkind = \"steady\"\nreference = \"crank\"\nspeed_rpm = 1500.0\n";

/// A CSV of `rows` rows at 1000 Hz, crank at 1500 rpm (25 rev/s), with a comment line.
fn csv(rows: usize) -> String {
    let mut s = String::from("# bench 3, run 2\ntime_s,crank_rpm,flange_rpm\n");
    for k in 0..rows {
        s += &format!("{},{},{}\n", k as f64 / 1000.0, 1500.0, 1490.0);
    }
    s
}

/// Writes CSV + sidecar into a fresh directory and reads them.
fn read(
    test: &str,
    csv_text: &str,
    sidecar: &str,
    nodes: Option<&[String]>,
) -> (PathBuf, Result<Recording, RecordingError>) {
    let dir = temp_dir(test);
    let path = put(&dir, "run-a.csv", csv_text);
    put(&dir, "run-a.toml", sidecar);
    let result = read_recording(&path, nodes);
    (path, result)
}

/// Asserts the error's file (ends with `file`), line and that its message holds `text`.
fn rejects(
    test: &str,
    csv_text: &str,
    sidecar: &str,
    file: &str,
    line: Option<usize>,
    text: &str,
) -> RecordingError {
    let nodes = ["crank".to_string(), "flange".to_string()];
    let (_, result) = read(test, csv_text, sidecar, Some(&nodes));
    let e = result.expect_err("must be rejected");
    assert!(e.file.ends_with(file), "{test}: file {} in {e}", e.file);
    assert_eq!(e.line, line, "{test}: {e}");
    assert!(e.to_string().contains(text), "{test}: `{e}` lacks `{text}`");
    assert!(e.to_string().starts_with(&e.file), "{test}: {e}");
    e
}

#[test]
fn reads_a_good_recording() {
    let (_, r) = read("good", &csv(200), SIDECAR, None);
    let r = r.expect("reads");
    assert_eq!(r.time_s.len(), 200);
    assert_eq!(r.channels.len(), 2);
    assert_eq!(
        r.channels[1].kind,
        ChannelKind::SpeedRpm {
            node: "flange".into()
        }
    );
    assert_eq!(r.meta.speed_rpm, Some(1500.0));
    assert_eq!((r.meta.load, r.meta.strokes), (1.0, 4));
}

#[test]
fn csv_errors_name_file_line_and_reason() {
    let good = csv(200);
    let e = rejects(
        "no-time",
        &good.replace("time_s,", "t,"),
        SIDECAR,
        "run-a.csv",
        Some(2),
        "first column must be `time_s`",
    );
    assert!(matches!(e.reason, Reason::MissingTime(_)));
    let e = rejects(
        "unknown-node",
        &good.replace("flange_rpm", "pulley_rpm"),
        SIDECAR,
        "run-a.csv",
        Some(2),
        "names no node",
    );
    assert_eq!(e.key.as_deref(), Some("pulley_rpm"));
    let e = rejects(
        "bad-column",
        &good.replace("flange_rpm", "flange_deg"),
        SIDECAR,
        "run-a.csv",
        Some(2),
        "is not `<node>_rpm`",
    );
    assert!(matches!(e.reason, Reason::BadColumn(_)));
    // Line 3 is the first data row (line 1 is the comment, line 2 the header).
    let e = rejects(
        "not-numeric",
        &good.replacen("0.001,1500,", "0.001,15o0,", 1),
        SIDECAR,
        "run-a.csv",
        Some(4),
        "`15o0` is not a number",
    );
    assert_eq!(e.key.as_deref(), Some("crank_rpm"));
    let e = rejects(
        "not-finite",
        &good.replacen("0.002,1500,1490", "0.002,1500,NaN", 1),
        SIDECAR,
        "run-a.csv",
        Some(5),
        "not finite",
    );
    assert_eq!(e.key.as_deref(), Some("flange_rpm"));
    rejects(
        "inf",
        &good.replacen("0.002,1500,1490", "0.002,inf,1490", 1),
        SIDECAR,
        "run-a.csv",
        Some(5),
        "not finite",
    );
    let e = rejects(
        "time-back",
        &good.replacen("0.003,", "0.001,", 1),
        SIDECAR,
        "run-a.csv",
        Some(6),
        "time must increase",
    );
    assert!(matches!(e.reason, Reason::TimeNotIncreasing { .. }));
    rejects(
        "time-equal",
        &good.replacen("0.003,", "0.002,", 1),
        SIDECAR,
        "run-a.csv",
        Some(6),
        "not after",
    );
    let e = rejects(
        "short-row",
        &good.replacen("0.002,1500,1490", "0.002,1500", 1),
        SIDECAR,
        "run-a.csv",
        Some(5),
        "2 fields, the header has 3",
    );
    assert_eq!(
        e.reason,
        Reason::FieldCount {
            expected: 3,
            found: 2
        }
    );
    rejects(
        "long-row",
        &good.replacen("0.002,1500,1490", "0.002,1500,1490,7", 1),
        SIDECAR,
        "run-a.csv",
        Some(5),
        "4 fields",
    );
    // 150 rows at 1 ms is 0.15 s at 25 rev/s: 3.7 revolutions, under two 4-stroke cycles.
    let e = rejects(
        "short",
        &csv(150),
        SIDECAR,
        "run-a.csv",
        Some(152),
        "fewer than two working cycles (4 revolutions)",
    );
    assert_eq!(e.key.as_deref(), Some("crank_rpm"));
    // A 2-stroke engine needs only 2 revolutions.
    let (_, r) = read(
        "short-2s",
        &csv(150),
        &format!("{SIDECAR}strokes = 2\n"),
        None,
    );
    assert_eq!(r.expect("2-stroke: 3.7 rev is enough").meta.strokes, 2);
    // Without node names any node is accepted.
    let (_, r) = read(
        "any-node",
        &good.replace("flange_rpm", "pulley_rpm"),
        SIDECAR,
        None,
    );
    assert!(r.is_ok());
    rejects(
        "no-header",
        "# only a comment\n",
        SIDECAR,
        "run-a.csv",
        None,
        "no header",
    );
}

#[test]
fn sidecar_errors_name_file_line_and_key() {
    let good = csv(200);
    let dir = temp_dir("no-sidecar");
    let path = put(&dir, "run-a.csv", &good);
    let e = read_recording(&path, None).expect_err("no sidecar");
    assert!(
        e.file.ends_with("run-a.toml") && e.to_string().contains("cannot read the sidecar"),
        "{e}"
    );
    rejects(
        "syntax",
        &good,
        "format = 1\nkind = \"steady\nreference = \"crank\"\n",
        "run-a.toml",
        Some(2),
        "TOML syntax error",
    );
    let e = rejects(
        "unknown-key",
        &good,
        &format!("{SIDECAR}rpm = 3\n"),
        "run-a.toml",
        Some(5),
        "unknown key",
    );
    assert_eq!(e.key.as_deref(), Some("rpm"));
    for key in ["format", "kind", "reference"] {
        let text: String = SIDECAR
            .lines()
            .filter(|l| !l.starts_with(key))
            .map(|l| format!("{l}\n"))
            .collect();
        let e = rejects(
            &format!("missing-{key}"),
            &good,
            &text,
            "run-a.toml",
            None,
            "missing required key",
        );
        assert_eq!(e.key.as_deref(), Some(key));
    }
    rejects(
        "kind",
        &good,
        &SIDECAR.replace("steady", "ramp"),
        "run-a.toml",
        Some(2),
        "neither \"steady\" nor \"run-up\"",
    );
    rejects(
        "format-2",
        &good,
        &SIDECAR.replace("format = 1", "format = 2"),
        "run-a.toml",
        Some(1),
        "format 2 is not supported",
    );
    let e = rejects(
        "no-reference-column",
        &good,
        &SIDECAR.replace("\"crank\"", "\"flywheel\""),
        "run-a.csv",
        Some(2),
        "has no column `flywheel_rpm`",
    );
    assert!(matches!(e.reason, Reason::MissingReference { .. }));
    rejects(
        "load",
        &good,
        &format!("{SIDECAR}load = 1.5\n"),
        "run-a.toml",
        Some(5),
        "within 0 … 1",
    );
    rejects(
        "strokes",
        &good,
        &format!("{SIDECAR}strokes = 3\n"),
        "run-a.toml",
        Some(5),
        "must be 2 or 4",
    );
    rejects(
        "sensor-key",
        &good,
        &format!("{SIDECAR}[sensors.crank]\nkind = \"zebra\"\nlines = 78\n"),
        "run-a.toml",
        Some(7),
        "unknown key",
    );
}
