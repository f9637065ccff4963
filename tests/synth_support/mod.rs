//! Shared inputs for the `torsim synth` tests: the diagnosis bench and its variant user
//! models, short plans, and order amplitudes of generated recordings.
#![allow(dead_code)]

use std::path::PathBuf;
use torsim::model::{Model, parse_model, presets, read_model_file};
use torsim::recording::Recording;
use torsim::recording::RunShape;
use torsim::signal::{AnalysisOptions, analyse, analyse_with};
use torsim::synth::{
    EffectSpec, Measurement, Plan, PlannedRun, Station, SynthRecording, Truth, build_truth,
    generate,
};

#[path = "../scratch/mod.rs"]
mod scratch;
pub use scratch::Scratch;

/// The diagnosis bench preset.
pub fn bench() -> Model {
    let p = presets::preset("diagnosis-bench").expect("shipped");
    parse_model(p.text, "diagnosis-bench.toml").expect("parses")
}

/// A model file under tests/data/diagnosis/.
pub fn data_model(name: &str) -> Model {
    read_model_file(&data_dir().join(name)).expect("reads")
}

/// tests/data/diagnosis.
pub fn data_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/diagnosis")
}

/// A steady run of `duration_s` at `speed_rpm` and `load`.
pub fn steady(file: &str, speed_rpm: f64, load: f64, duration_s: f64) -> PlannedRun {
    PlannedRun {
        file: file.into(),
        label: file.into(),
        shape: RunShape::steady(speed_rpm, duration_s),
        duration_s,
        load,
        rate_hz: None,
    }
}

/// A full-load run-up.
pub fn run_up(from_rpm: f64, to_rpm: f64, duration_s: f64) -> PlannedRun {
    PlannedRun {
        file: "run-up".into(),
        label: "run-up".into(),
        shape: RunShape::Ramp { from_rpm, to_rpm },
        duration_s,
        load: 1.0,
        rate_hz: None,
    }
}

/// The bench's two stations: crank encoder (360 lines), coupling zebra tape (78 lines).
pub fn stations() -> Vec<Station> {
    vec![
        Station::parse("engine:encoder:360").expect("valid"),
        Station::parse("coupling_es:zebra:78").expect("valid"),
    ]
}

/// A noiseless bench at 2048 Hz with the two stations.
pub fn perfect() -> Measurement {
    Measurement::perfect(stations(), 2048.0)
}

/// The truth for `spec` on `user` (no parameter errors, seed 1).
pub fn truth(user: &Model, spec: &EffectSpec) -> Truth {
    build_truth(user, spec, 0.0, 1).expect("truth")
}

/// Generates `runs` from `truth` with measurement `m`.
pub fn make(truth: &Truth, runs: Vec<PlannedRun>, m: &Measurement) -> Vec<SynthRecording> {
    generate(truth, &Plan { runs }, m, &mut |_| true).expect("generates")
}

/// The recording of stem `file`.
pub fn rec<'a>(recs: &'a [SynthRecording], file: &str) -> &'a Recording {
    &recs
        .iter()
        .find(|r| r.file == file)
        .expect("planned")
        .recording
}

/// Zero-to-peak amplitude (rpm) of `order` at `station`.
pub fn order(recording: &Recording, station: &str, order: f64) -> f64 {
    let a = analyse(recording).expect("analyses");
    let s = a
        .stations
        .iter()
        .find(|s| s.name == station)
        .expect("station");
    s.orders
        .iter()
        .find(|o| (o.order - order).abs() < 1e-9)
        .map_or(0.0, |o| o.amplitude)
}

/// A run-up's order track at `station`: (reference speed rpm, amplitude rpm) per window.
pub fn track(recording: &Recording, station: &str, order: f64) -> Vec<(f64, f64)> {
    let a = analyse_with(recording, &AnalysisOptions::default()).expect("analyses");
    let axes = a.stft.as_ref().expect("a run-up");
    let q = axes
        .orders
        .iter()
        .position(|o| (o - order).abs() < 1e-9)
        .expect("tracked order");
    let s = a
        .stations
        .iter()
        .find(|s| s.name == station)
        .expect("station");
    let tracks = &s.stft.as_ref().expect("stft").order_tracks_rpm;
    axes.speeds_rpm
        .iter()
        .copied()
        .zip(tracks[q].iter().copied())
        .collect()
}

/// The largest amplitude of a track between two speeds, and its speed: (rpm, amplitude).
pub fn peak(track: &[(f64, f64)], from_rpm: f64, to_rpm: f64) -> (f64, f64) {
    track
        .iter()
        .filter(|(s, _)| (from_rpm..=to_rpm).contains(s))
        .fold(
            (0.0, 0.0),
            |best, &(s, a)| if a > best.1 { (s, a) } else { best },
        )
}

/// A fresh empty directory under the system temp dir, removed when the returned guard is
/// dropped.
pub fn temp_dir(test: &str) -> Scratch {
    Scratch::new(&format!("torsim-synth-{test}-"))
}
