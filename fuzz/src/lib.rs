//! The bodies of torsim's fuzz targets (issue 13, deliverable 5): one function per
//! reader, taking the fuzzer's bytes.
//!
//! The same file is compiled into the main crate's stable replay test
//! (`tests/fuzz_corpus.rs` includes it by path), so a corpus file exercises exactly the
//! calls the fuzzer made. It therefore names only `torsim` and `std`.
//!
//! Each body:
//! - takes valid UTF-8 to the text reader (`parse_model`, `parse_recording`,
//!   `parse_sidecar`), and invalid UTF-8 to the file reader (`read_model_file`,
//!   `read_recording`) through a scratch file, so the byte-level path is fuzzed too;
//! - for what the reader accepts, checks that the writer's text reads back to the same
//!   value (issue 13: "no silent nonsense": torsim must read what it writes).
//!
//! A reader returning `Err` is fine; a panic, an abort or a hang is a finding.

use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

use torsim::model::{Model, parse_model, read_model_file, to_toml_string};
use torsim::recording::{
    Recording, RecordingMeta, check_recording, csv_string, parse_recording, parse_sidecar,
    read_recording, sidecar_string,
};

/// The fixed, valid sidecar the recording target reads its CSVs with: a steady run of
/// the `diagnosis-bench` preset (reference `engine`, 3000 rpm, 4 strokes).
pub const SIDECAR: &str = "format = 1
kind = \"steady\"
reference = \"engine\"
speed_rpm = 3000.0
label = \"Fuzz\"

[sensors.engine]
kind = \"encoder\"
lines_per_rev = 360

[sensors.coupling_es]
kind = \"zebra\"
lines_per_rev = 78
";

/// The model's nodes the recording target also checks columns against (the
/// `diagnosis-bench` preset's inertias).
pub const NODES: [&str; 4] = ["engine", "gearbox_out", "coupling_es", "brake"];

/// The model reader: `parse_model(text, "fuzz.toml")`; a model it accepts must write
/// to text that reads back equal.
pub fn model(data: &[u8]) {
    match std::str::from_utf8(data) {
        Ok(text) => {
            if let Ok(model) = parse_model(text, "fuzz.toml") {
                model_reads_back(&model);
            }
        }
        Err(_) => {
            let scratch = Scratch::new();
            let path = scratch.write("fuzz.toml", data);
            let _ = read_model_file(&path);
        }
    }
}

/// The recording reader: `parse_recording` on the CSV text with [`SIDECAR`], without and
/// with the model's node names [`NODES`]; a recording it accepts must pass the writer's
/// check and write to CSV text that reads back equal.
pub fn recording(data: &[u8]) {
    let meta = fixed_sidecar();
    let nodes: Vec<String> = NODES.iter().map(|n| (*n).to_string()).collect();
    match std::str::from_utf8(data) {
        Ok(text) => {
            for names in [None, Some(nodes.as_slice())] {
                if let Ok(recording) = parse_recording(text, "fuzz.csv", meta.clone(), names) {
                    recording_reads_back(&recording);
                }
            }
        }
        Err(_) => {
            let scratch = Scratch::new();
            scratch.write("fuzz.toml", SIDECAR.as_bytes());
            let csv = scratch.write("fuzz.csv", data);
            let _ = read_recording(&csv, Some(&nodes));
        }
    }
}

/// The sidecar reader: `parse_sidecar(text, "fuzz.toml")`; a sidecar it accepts must
/// write to text that reads back equal, and must read [`valid_csv`] without a panic.
pub fn sidecar(data: &[u8]) {
    match std::str::from_utf8(data) {
        Ok(text) => {
            if let Ok(meta) = parse_sidecar(text, "fuzz.toml") {
                let written = sidecar_string(&meta);
                match parse_sidecar(&written, "written.toml") {
                    Ok(again) => assert_eq!(again, meta, "written sidecar:\n{written}"),
                    Err(e) => panic!("a written sidecar does not read back: {e}\n{written}"),
                }
                if let Ok(recording) = parse_recording(&valid_csv(), "fuzz.csv", meta, None) {
                    recording_reads_back(&recording);
                }
            }
        }
        Err(_) => {
            let scratch = Scratch::new();
            scratch.write("fuzz.toml", data);
            let csv = scratch.write("fuzz.csv", valid_csv().as_bytes());
            let _ = read_recording(&csv, None);
        }
    }
}

/// A valid steady recording for [`SIDECAR`]: 2000 Hz, 300 rows (0.15 s, 3.75 working
/// cycles at 3000 rpm), `engine_rpm` with a small 2nd order and `coupling_es_rpm`.
pub fn valid_csv() -> String {
    let mut out = String::from("time_s,engine_rpm,coupling_es_rpm\n");
    for i in 0..300_u32 {
        let t = f64::from(i) * 0.0005;
        let wave = (2.0 * std::f64::consts::PI * 100.0 * t).sin();
        let engine = 3000.0 + 5.0 * wave;
        let coupling = 1000.0 + 2.0 * wave;
        out.push_str(&format!("{t},{engine:.3},{coupling:.3}\n"));
    }
    out
}

fn fixed_sidecar() -> RecordingMeta {
    match parse_sidecar(SIDECAR, "fuzz.toml") {
        Ok(meta) => meta,
        Err(e) => panic!("the fuzz targets' fixed sidecar no longer reads: {e}"),
    }
}

fn model_reads_back(model: &Model) {
    let written = to_toml_string(model);
    match parse_model(&written, "written.toml") {
        Ok(again) => assert_eq!(&again, model, "written model:\n{written}"),
        Err(e) => panic!("a written model does not read back: {e}\n{written}"),
    }
}

fn recording_reads_back(recording: &Recording) {
    if let Err(e) = check_recording(recording, "fuzz.csv") {
        panic!("the writer refuses a recording the reader accepted: {e}");
    }
    let written = csv_string(recording);
    match parse_recording(&written, "written.csv", recording.meta.clone(), None) {
        Ok(again) => assert_eq!(&again, recording, "written CSV:\n{written}"),
        Err(e) => panic!("a written recording does not read back: {e}\n{written}"),
    }
}

/// A scratch directory of its own (process id and a counter), removed when dropped.
struct Scratch {
    dir: PathBuf,
}

impl Scratch {
    fn new() -> Self {
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let dir = std::env::temp_dir().join(format!("torsim-fuzz-{}-{n}", std::process::id()));
        if let Err(e) = std::fs::create_dir_all(&dir) {
            panic!("cannot create {}: {e}", dir.display());
        }
        Self { dir }
    }

    fn write(&self, name: &str, data: &[u8]) -> PathBuf {
        let path = self.dir.join(name);
        if let Err(e) = std::fs::write(&path, data) {
            panic!("cannot write {}: {e}", path.display());
        }
        path
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}
