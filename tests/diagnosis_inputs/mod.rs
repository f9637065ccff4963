//! A diagnosis case folder read as `torsim diagnose` reads it: the user's `model.toml`
//! and every `*.csv` recording (sorted by name) with its sidecar, labelled by the
//! sidecar's `label`, else the file stem. Shared by `tests/diagnose_cases.rs` and
//! `tests/diagnose_daq_files.rs`.

use std::path::{Path, PathBuf};
use torsim::diagnose::LabelledRecording;
use torsim::model::{Model, parse_model};
use torsim::recording::read_recording;

/// The `*.csv` files of `dir`, sorted by name.
pub fn csv_files(dir: &Path) -> Vec<PathBuf> {
    let mut csv: Vec<PathBuf> = std::fs::read_dir(dir)
        .expect("case folder")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "csv"))
        .collect();
    csv.sort();
    csv
}

/// The user's model and the labelled recordings of the case folder `dir`.
pub fn inputs(dir: &Path) -> (Model, Vec<LabelledRecording>) {
    let text = std::fs::read_to_string(dir.join("model.toml")).expect("model.toml");
    let model = parse_model(&text, "model.toml").expect("the user's model parses");
    let nodes: Vec<String> = model.inertias.iter().map(|n| n.name.clone()).collect();
    let recordings = csv_files(dir)
        .iter()
        .map(|p| {
            let recording = read_recording(p, Some(&nodes))
                .unwrap_or_else(|e| panic!("{} reads: {e}", p.display()));
            let label = recording.meta.label.clone().unwrap_or_else(|| {
                p.file_stem()
                    .map_or(String::new(), |s| s.to_string_lossy().into())
            });
            LabelledRecording { label, recording }
        })
        .collect();
    (model, recordings)
}
