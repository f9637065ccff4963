//! Recordings (spec/recording-format.md): every rejection names the file, the line and
//! the reason.

mod synth;

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

/// Writes CSV + sidecar into a fresh directory and reads them (the directory is removed
/// on return).
fn read(
    test: &str,
    csv_text: &str,
    sidecar: &str,
    nodes: Option<&[String]>,
) -> Result<Recording, RecordingError> {
    let dir = temp_dir(test);
    let path = put(&dir, "run-a.csv", csv_text);
    put(&dir, "run-a.toml", sidecar);
    read_recording(&path, nodes)
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
    let result = read(test, csv_text, sidecar, Some(&nodes));
    let e = result.expect_err("must be rejected");
    assert!(e.file.ends_with(file), "{test}: file {} in {e}", e.file);
    assert_eq!(e.line, line, "{test}: {e}");
    assert!(e.to_string().contains(text), "{test}: `{e}` lacks `{text}`");
    assert!(e.to_string().starts_with(&e.file), "{test}: {e}");
    e
}

#[test]
fn reads_a_good_recording() {
    let r = read("good", &csv(200), SIDECAR, None);
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
    let r = read(
        "short-2s",
        &csv(150),
        &format!("{SIDECAR}strokes = 2\n"),
        None,
    );
    assert_eq!(r.expect("2-stroke: 3.7 rev is enough").meta.strokes, 2);
    // Without node names any node is accepted.
    let r = read(
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

/// A CSV at 10 240 Hz, crank at 1500 rpm, time printed by `time` from the exact time.
fn csv_at(rows: usize, start_s: f64, time: &dyn Fn(f64, usize) -> String) -> String {
    let mut s = String::from("time_s,crank_rpm,flange_rpm\n");
    for k in 0..rows {
        let t = start_s + k as f64 / 10240.0;
        s += &format!("{},{},{}\n", time(t, k), 1500.0, 1490.0);
    }
    s
}

/// Issue 13: Excel's "CSV UTF-8" BOM is stripped from CSV and sidecar; bytes that are
/// not UTF-8 are refused with the line and byte offset.
#[test]
fn bom_is_stripped_and_bad_utf8_located() {
    let r = read(
        "bom",
        &format!("\u{feff}{}", csv(200)),
        &format!("\u{feff}{SIDECAR}"),
        None,
    );
    assert_eq!(r.expect("BOM stripped").time_s.len(), 200);
    let dir = temp_dir("bad-utf8");
    let good = csv(200);
    // Line 4 (comment, header, two rows before it): byte 0xFF in place of a digit.
    let at = good
        .match_indices('\n')
        .nth(2)
        .map(|(i, _)| i + 1)
        .unwrap_or(0);
    let mut bytes = good.into_bytes();
    bytes[at + 2] = 0xFF;
    let path = dir.join("run-a.csv");
    std::fs::write(&path, &bytes).expect("write");
    put(&dir, "run-a.toml", SIDECAR);
    let e = read_recording(&path, None).expect_err("invalid UTF-8");
    assert_eq!(e.line, Some(4), "{e}");
    assert_eq!(e.reason, Reason::InvalidUtf8 { offset: at + 2 }, "{e}");
    assert!(e.to_string().contains(&format!("byte {}", at + 2)), "{e}");
    let path = put(&dir, "side.csv", &csv(200));
    std::fs::write(dir.join("side.toml"), b"format = 1\nkind = \"st\xE9ady\"\n").expect("write");
    let e = read_recording(&path, None).expect_err("invalid UTF-8 in the sidecar");
    assert!(e.file.ends_with("side.toml") && e.line == Some(2), "{e}");
}

/// Issue 13: time stamps printed to 6 or 5 decimals, ±20 µs of jitter and a clock that
/// starts at 187.648 s are accepted; the recording comes out on a uniform grid.
#[test]
fn real_clocks_are_accepted() {
    let rows = 4000;
    let six = csv_at(rows, 0.0, &|t, _| format!("{t:.6}"));
    let five = csv_at(rows, 0.0, &|t, _| format!("{t:.5}"));
    // Deterministic ±20 µs jitter (a full-period pseudo-random pattern).
    let jitter = |k: usize| 20e-6 * (((k * 7919) % 2001) as f64 / 1000.0 - 1.0);
    let jittered = csv_at(rows, 187.648, &|t, k| format!("{:.6}", t + jitter(k)));
    for (name, text) in [("dec6", six), ("dec5", five), ("jitter", jittered)] {
        let dir = temp_dir(&format!("clock-{name}"));
        let path = put(&dir, "run-a.csv", &text);
        put(&dir, "run-a.toml", SIDECAR);
        let read = torsim::recording::read_recording_with(&path, None, &Default::default())
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let t = &read.recording.time_s;
        let dt =
            torsim::signal::resample::uniform_interval(t).unwrap_or_else(|e| panic!("{name}: {e}"));
        // The fitted step is the true one to 1e-6 of itself (4000 samples average the
        // rounding down).
        assert!((dt * 10240.0 - 1.0).abs() < 1e-6, "{name}: dt {dt}");
        assert_eq!(
            read.notes.is_empty(),
            name != "jitter",
            "{name}: {:?}",
            read.notes
        );
    }
}

/// Issue 13: only gaps, duplicates and time going backwards are refused, at the line of
/// the offending sample with its time ("a 100 ms gap at 0.4 s" names 0.4 s and 0.5 s).
#[test]
fn gaps_and_duplicates_name_their_line() {
    let rows = 6000;
    let gap = csv_at(rows, 0.0, &|t, _| format!("{t:.6}"));
    let text: String = gap
        .lines()
        .filter(|l| {
            l.split(',')
                .next()
                .and_then(|t| t.parse::<f64>().ok())
                .is_none_or(|t| !(0.40005..0.5).contains(&t))
        })
        .map(|l| format!("{l}\n"))
        .collect();
    // Line 1 is the header; the sample at 0.4 s is row 4097 (line 4098), 0.5 s the next.
    let e = rejects(
        "gap",
        &text,
        SIDECAR,
        "run-a.csv",
        Some(4099),
        "gap in the sampling",
    );
    assert!(
        e.to_string().contains("at 0.4 s") && e.to_string().contains("0.5 s"),
        "{e}"
    );
    assert_eq!(e.key.as_deref(), Some("time_s"));
    let dup = csv_at(rows, 0.0, &|t, k| {
        format!("{:.7}", if k == 300 { t - 9e-5 } else { t })
    });
    rejects(
        "dup",
        &dup,
        SIDECAR,
        "run-a.csv",
        Some(302),
        "duplicate sample",
    );
}

/// Issue 13: over-range markers and impossible speeds are reported by column and line
/// (the first few and the count), refused by default, interpolated or dropped on request.
#[test]
fn bad_samples_are_reported_and_handled() {
    use torsim::recording::{BadSamples, ReadOptions, read_recording_with};
    let good = csv_at(6000, 0.0, &|t, _| format!("{t}"));
    let mark = |value: &str, rows: &[usize]| {
        let mut lines: Vec<String> = good.lines().map(str::to_string).collect();
        for &r in rows {
            lines[r] = lines[r].replacen(",1500,", &format!(",{value},"), 1);
        }
        lines.join("\n") + "\n"
    };
    for value in ["1e300", "9.9e37", "1e15", "1e12", "1e6", "NaN", "inf", "-5"] {
        let e = rejects(
            &format!("bad-{value}"),
            &mark(value, &[3000]),
            SIDECAR,
            "run-a.csv",
            Some(3001),
            "1 bad sample",
        );
        assert_eq!(e.key.as_deref(), Some("crank_rpm"), "{e}");
        assert!(e.to_string().contains("line 3001"), "{e}");
    }
    let many = mark("9.9e37", &(100..120).collect::<Vec<_>>());
    let e = rejects(
        "many",
        &many,
        SIDECAR,
        "run-a.csv",
        Some(101),
        "20 bad samples",
    );
    assert!(e.to_string().contains("and 15 more"), "{e}");
    let dir = temp_dir("bad-handled");
    let path = put(&dir, "run-a.csv", &mark("1e300", &[3000, 4500]));
    put(&dir, "run-a.toml", SIDECAR);
    let options = |bad_samples| ReadOptions { bad_samples };
    let read =
        read_recording_with(&path, None, &options(BadSamples::Interpolate)).expect("interpolated");
    let crank = read.recording.speed_rpm("crank").expect("crank");
    assert_eq!(
        (crank.len(), crank[2999], crank[4499]),
        (6000, 1500.0, 1500.0)
    );
    assert!(
        read.notes[0].contains("interpolated 2 bad samples"),
        "{:?}",
        read.notes
    );
    let read = read_recording_with(&path, None, &options(BadSamples::Drop)).expect("dropped");
    // Rows 0..2999 (3000 rows) are the longest stretch; 3000..4499 is 1499 rows.
    assert_eq!(read.recording.time_s.len(), 2999);
    assert!(
        read.notes[0].contains("kept lines 2 … 3000"),
        "{:?}",
        read.notes
    );
    // A run of bad samples longer than a revolution (410 samples at 1500 rpm) is not
    // invented by interpolation.
    let path = put(
        &dir,
        "long.csv",
        &mark("1e300", &(1000..1500).collect::<Vec<_>>()),
    );
    put(&dir, "long.toml", SIDECAR);
    let e = read_recording_with(&path, None, &options(BadSamples::Interpolate))
        .expect_err("too long to interpolate");
    assert!(e.to_string().contains("run of 500 bad samples"), "{e}");
}

/// Issue 13: inline tables are tables; an impossible temperature and a `speed_rpm` the
/// data contradict are refused with the key and line.
#[test]
fn sidecar_is_toml_and_checked_against_the_data() {
    let good = csv(200);
    let inline =
        format!("{SIDECAR}sensors = {{ crank = {{ kind = \"encoder\", lines_per_rev = 360 }} }}\n");
    let r = read("inline", &good, &inline, None);
    assert_eq!(
        r.expect("inline tables").meta.sensors["crank"].lines_per_rev,
        Some(360)
    );
    for t in ["-300", "-273.16", "301"] {
        let e = rejects(
            &format!("temp{t}"),
            &good,
            &format!("{SIDECAR}temperature_c = {t}\n"),
            "run-a.toml",
            Some(5),
            "must be within -273.15 … 300 °C",
        );
        assert_eq!(e.key.as_deref(), Some("temperature_c"));
    }
    let r = read(
        "temp-ok",
        &good,
        &format!("{SIDECAR}temperature_c = -40\n"),
        None,
    );
    assert!(r.is_ok());
    let e = rejects(
        "speed",
        &good,
        &SIDECAR.replace("1500.0", "3000.0"),
        "run-a.toml",
        Some(4),
        "speed_rpm = 3000 but the reference's mean speed in",
    );
    assert!(e.to_string().contains("is 1500.0 rpm") && e.to_string().contains("run-a.csv"));
    // Within 10 %: a bench holds its speed to 1–2 %.
    let r = read(
        "speed-ok",
        &good,
        &SIDECAR.replace("1500.0", "1600.0"),
        None,
    );
    assert!(r.is_ok());
}
