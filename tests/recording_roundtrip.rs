//! Recordings (spec/recording-format.md): writing and reading back is bit-exact, writing
//! refuses non-finite samples, and a 300 000-row recording reads fast.

mod synth;

use std::path::Path;
use synth::temp_dir;
use torsim::recording::{
    Channel, ChannelKind, Recording, RecordingMeta, RunKind, Sensor, read_recording,
    write_recording,
};

/// Everything the format can hold, written and read back bit-identical.
#[test]
fn write_then_read_is_bit_exact() {
    let n = 3000;
    let time_s: Vec<f64> = (0..n).map(|k| k as f64 / 2048.0 + 0.1).collect();
    let wave = |k: usize, s: f64| 1500.0 + 17.0 * (k as f64 * s).sin() + 1e-9 / 3.0;
    let mut meta = RecordingMeta::new(RunKind::RunUp, "crank");
    meta.speed_rpm = Some(1234.5);
    meta.load = 0.75;
    meta.temperature_c = Some(-5.25);
    meta.label = Some("Regime \"A\"".into());
    meta.strokes = 2;
    meta.sensors.insert(
        "crank".into(),
        Sensor {
            kind: "zebra".into(),
            lines_per_rev: Some(78),
        },
    );
    meta.sensors.insert(
        "brake side".into(),
        Sensor {
            kind: "encoder".into(),
            lines_per_rev: None,
        },
    );
    let recording = Recording {
        time_s,
        channels: vec![
            Channel::new(
                ChannelKind::SpeedRpm {
                    node: "crank".into(),
                },
                (0..n).map(|k| wave(k, 0.1)).collect(),
            ),
            Channel::new(
                ChannelKind::AngleRad {
                    node: "crank".into(),
                },
                (0..n).map(|k| k as f64 * 0.0767 + 1e-300).collect(),
            ),
            Channel::new(
                ChannelKind::TorqueNm {
                    connection: "coupling".into(),
                },
                (0..n).map(|k| -wave(k, 0.3) * 1e7).collect(),
            ),
        ],
        meta,
    };
    let dir = temp_dir("roundtrip");
    let path = dir.join("sim.csv");
    write_recording(&recording, &path).expect("write");
    let back = read_recording(&path, None).expect("read back");
    assert_eq!(back, recording);
    // No temporary files left behind.
    assert_eq!(std::fs::read_dir(&dir).map(|d| d.count()).unwrap_or(0), 2);

    // Non-finite samples are refused, naming the column and the CSV line, and nothing is written.
    let mut bad = recording.clone();
    bad.channels[2].values[10] = f64::NAN;
    let other = dir.join("bad.csv");
    let e = write_recording(&bad, &other).expect_err("NaN refused");
    assert_eq!(
        (e.line, e.key.as_deref()),
        (Some(12), Some("torque_coupling_nm")),
        "{e}"
    );
    assert!(!other.exists() && !Path::new(&dir.join("bad.toml")).exists());
}

/// A jittered clock is resampled onto its fitted grid on reading; that grid, written with
/// every digit, must read back as itself: bit-exact, not taken for jitter and resampled
/// again (the recording fuzzer's a99bd10d, kept in `fuzz/corpus/recording/`). Here 4000
/// rows at 10 240 Hz from a DAQ clock starting at 187.6 s, each stamp off by up to
/// ±0.2 step (a deterministic pattern, not a multiple of the step).
#[test]
fn a_resampled_jittered_clock_reads_back_bit_exact() {
    let dt_s = 1.0 / 10_240.0;
    let mut text = String::from("time_s,crank_rpm\n");
    for k in 0..20_000_u32 {
        let jitter = 0.2 * (f64::from(k) * 0.7).sin();
        let t = 1.0 + (f64::from(k) + jitter) * dt_s;
        let rpm = 1500.0 + 10.0 * (f64::from(k) * 0.01).sin();
        text.push_str(&format!("{t:.9},{rpm:.4}\n"));
    }
    let dir = temp_dir("jitter-roundtrip");
    let first = dir.join("jittered.csv");
    std::fs::write(&first, text).expect("write the jittered CSV");
    let meta = RecordingMeta::new(RunKind::Steady, "crank");
    std::fs::write(
        first.with_extension("toml"),
        torsim::recording::sidecar_string(&meta),
    )
    .expect("write its sidecar");
    let read = read_recording(&first, None).expect("the jittered clock is read");
    let dt_read = read.time_s[1] - read.time_s[0];
    assert!(
        (dt_read - dt_s).abs() < 1e-3 * dt_s,
        "fitted step {dt_read} s"
    );
    let again = dir.join("again.csv");
    write_recording(&read, &again).expect("write the resampled recording");
    let back = read_recording(&again, None).expect("read it back");
    assert_eq!(back, read);
}

/// Reading speed: 300 000 rows × 3 speed columns (30 s at 10 240 Hz). Run with
/// `cargo test --release -- --ignored --nocapture read_speed`; measured ≈ 60 ms (21 MB), writing ≈ 180 ms, analysing ≈ 165 ms.
#[test]
#[ignore = "timing; run in release"]
fn read_speed() {
    let rows = 300_000;
    let time_s: Vec<f64> = (0..rows).map(|k| k as f64 / 10240.0).collect();
    let col = |node: &str, s: f64| {
        Channel::new(
            ChannelKind::SpeedRpm { node: node.into() },
            (0..rows)
                .map(|k| 1500.0 + 20.0 * (k as f64 * s).sin())
                .collect(),
        )
    };
    let rec = Recording {
        time_s,
        channels: vec![col("crank", 0.01), col("es", 0.02), col("bs", 0.03)],
        meta: RecordingMeta::new(RunKind::Steady, "crank"),
    };
    let dir = temp_dir("speed");
    let path = dir.join("big.csv");
    let start = std::time::Instant::now();
    write_recording(&rec, &path).expect("write");
    let written = start.elapsed();
    let start = std::time::Instant::now();
    let back = read_recording(&path, None).expect("read");
    let read = start.elapsed();
    eprintln!(
        "write {written:?}, read {read:?} ({} bytes)",
        std::fs::metadata(&path).map(|m| m.len()).unwrap_or(0)
    );
    assert_eq!(back.time_s.len(), rows);
    let start = std::time::Instant::now();
    let analysis = torsim::signal::analyse(&back).expect("analyse");
    eprintln!("analyse {:?} ({} cycles)", start.elapsed(), analysis.cycles);
}
