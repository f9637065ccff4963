//! Recordings for the diagnosis: "Add recordings…" asks for CSV files (rfd, several at
//! once) on its own thread, which also reads them (`torsim::recording::read_recording`,
//! sidecar beside each, stations checked against the model's nodes), so the window
//! never freezes; the files and the errors (with file and line) come back over a channel.

use crate::gui::background::{self, Pending};
use std::path::{Path, PathBuf};
use torsim::diagnose::LabelledRecording;
use torsim::diagnose::labels::label_of;
use torsim::recording::{RunShape, classify, read_recording};

/// A recording in the diagnosis list.
#[derive(Debug, Clone)]
pub struct LoadedRecording {
    /// The CSV file.
    pub path: PathBuf,
    /// The recording with the label the report shows: its own
    /// ([`torsim::diagnose::labels::label_of`]), with the file name added when another
    /// recording in the list has the same one ([`torsim::diagnose::labels::unique_labels`]).
    pub labelled: LabelledRecording,
    /// Its own label: sidecar `label`, else the file stem.
    pub own_label: String,
    /// Steady, long run or ramp with its speeds, by the classifier the diagnosis uses
    /// ([`torsim::recording::classify`]); shown as its [`RunShape::label`].
    pub shape: RunShape,
    /// Engine load 0..1 (sidecar).
    pub load: f64,
    /// Duration, s.
    pub duration_s: f64,
}

impl LoadedRecording {
    /// `"3960 rpm"` or `"1000 to 6000 rpm"`.
    pub fn speed_text(&self) -> String {
        let [a, b] = self.shape.speeds_rpm();
        if self.shape.is_ramp() {
            format!("{a:.0} to {b:.0} rpm")
        } else {
            format!("{a:.0} rpm")
        }
    }
}

/// What a loading thread sends back: the recordings read, and one error per file that
/// could not be.
pub type Loaded = (Vec<LoadedRecording>, Vec<String>);

/// Reads one recording and describes it.
pub fn read_one(path: &Path, nodes: &[String]) -> Result<LoadedRecording, String> {
    let recording = read_recording(path, Some(nodes)).map_err(|e| e.to_string())?;
    let label = label_of(path, &recording);
    let meta = &recording.meta;
    let duration_s = match (recording.time_s.first(), recording.time_s.last()) {
        (Some(a), Some(b)) => b - a,
        _ => 0.0,
    };
    let shape = classify(&recording);
    let load = meta.load;
    Ok(LoadedRecording {
        path: path.to_path_buf(),
        own_label: label.clone(),
        labelled: LabelledRecording { label, recording },
        shape,
        load,
        duration_s,
    })
}

/// Reads `paths`; a file already in `have` (or twice in `paths`) is an error.
pub fn read_all(paths: &[PathBuf], nodes: &[String], have: &[PathBuf]) -> Loaded {
    let mut seen: Vec<PathBuf> = have.iter().map(|p| canonical(p)).collect();
    let (mut ok, mut errors) = (Vec::new(), Vec::new());
    for path in paths {
        let c = canonical(path);
        if seen.contains(&c) {
            errors.push(format!("{}: already in the list", path.display()));
            continue;
        }
        match read_one(path, nodes) {
            Ok(r) => {
                seen.push(c);
                ok.push(r);
            }
            Err(e) => errors.push(e),
        }
    }
    (ok, errors)
}

/// The path as the file system names it (the path itself when that fails).
pub fn canonical(path: &Path) -> PathBuf {
    std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())
}

/// Where the files come from: a file dialog, or given (tests, drag and drop).
pub enum Source {
    /// Ask with a file dialog (several CSV files).
    Dialog,
    /// These files.
    Paths(Vec<PathBuf>),
}

/// Starts a thread that picks (or takes) the files and reads them against `nodes`; the
/// answer comes back on the receiver (nothing when the dialog was cancelled), and `ctx`
/// repaints.
pub fn start(
    source: Source,
    nodes: Vec<String>,
    have: Vec<PathBuf>,
    ctx: &egui::Context,
) -> Result<Pending<Loaded>, String> {
    background::spawn("torsim-diagnosis-load", ctx, move || {
        let paths = match source {
            Source::Paths(p) => p,
            Source::Dialog => rfd::FileDialog::new()
                .set_title("Add recordings to diagnose")
                .add_filter("recording (CSV with a .toml sidecar)", &["csv"])
                .pick_files()
                .unwrap_or_default(),
        };
        read_all(&paths, &nodes, &have)
    })
}
