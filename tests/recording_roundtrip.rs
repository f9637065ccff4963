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
    let path = temp_dir("speed").join("big.csv");
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
