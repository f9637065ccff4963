//! On the simulation thread: a recording opened in the window is read
//! (`torsim::recording::read_recording`, stations checked against the model's nodes),
//! analysed (`torsim::signal::analyse_with`: orders per station, STFT of run-ups), and its
//! regime turned into the simulation that matches it — a steady run at its speed, or a
//! linear run-up fitted to its reference speed. The last one is kept while the file and
//! the model's nodes stay the same.

use crate::gui::session::spectrogram::SpectrogramSet;
use crate::gui::session::trace_data::profile_rpm;
use crate::gui::session::trace_series::relative_name;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::SystemTime;
use torsim::model::{ConnectionKind, GROUND, Model};
use torsim::physics::System;
use torsim::recording::Run;
use torsim::recording::{Recording, RunShape, classify, read_recording};
use torsim::signal::{Analysis, AnalysisOptions, analyse_with};
use torsim::transient::MeasuredSpeed;

/// A recording as the traces panel shows it.
#[derive(Debug)]
pub struct RecordingView {
    /// Its file name, for labels.
    pub file: String,
    /// The samples and sidecar.
    pub recording: Recording,
    /// Time of its first sample, s (plots start at 0).
    pub t0_s: f64,
    /// The measured analysis.
    pub analysis: Analysis,
    /// Spectrograms of a run-up recording.
    pub spectrograms: Option<Arc<SpectrogramSet>>,
    /// The simulated run that matches it.
    pub regime: Run,
    /// A run-up's measured mean speed, which the matching run follows (as the diagnosis
    /// simulates it, `torsim::transient::MeasuredSpeed`); `None` for a steady run, too
    /// few STFT windows, or a run within 2 % of a straight ramp (`FOLLOW_ABOVE`).
    pub measured_speed: Option<Arc<MeasuredSpeed>>,
    /// Relative speed across each rubber stage whose two sides were measured, rpm, named
    /// as the time traces name it: `(name, samples)`.
    pub relative: Vec<(String, Vec<f64>)>,
    /// For a person: `"steady 3000 rpm, 4.0 s, stations engine, brake"`.
    pub summary: String,
}

impl RecordingView {
    /// The mean speed of station `node` at `t_s` from the first sample, rpm: its measured
    /// mean in a steady run, `ratio` × the measured mean speed in a run-up (the fitted
    /// ramp when it has too few windows).
    pub fn mean_speed_at(&self, node: &str, ratio: Option<f64>) -> impl Fn(f64) -> f64 + use<> {
        let mean = self
            .analysis
            .stations
            .iter()
            .find(|s| s.name == node)
            .map_or(0.0, |s| s.mean_speed_rpm);
        let (regime, ratio) = (self.regime, ratio.unwrap_or(1.0));
        let along = self.measured_speed.clone();
        move |t| {
            if let Some(m) = &along {
                ratio * m.speed_rpm(t)
            } else if regime.is_ramp() {
                ratio * profile_rpm(regime, t)
            } else {
                mean
            }
        }
    }

    /// The measured stations (nodes), in column order.
    pub fn stations(&self) -> Vec<String> {
        self.recording
            .speed_stations()
            .iter()
            .map(|(n, _)| n.to_string())
            .collect()
    }
}

/// The analysis options for `model`: each node's shaft ratio, and the relative speed
/// across each rubber stage only (as `torsim simulate` reports it).
pub fn analysis_options(model: &Model, system: &System) -> AnalysisOptions {
    let mut options = AnalysisOptions::default();
    for (node, ratio) in system.node_names.iter().zip(&system.speed_ratio) {
        options.shaft_ratio.insert(node.clone(), ratio.abs());
    }
    options.pairs = Some(
        model
            .connections
            .iter()
            .filter(|c| matches!(c.kind, ConnectionKind::Rubber(_)))
            .filter(|c| c.from != GROUND && c.to != GROUND)
            .map(|c| (c.from.clone(), c.to.clone()))
            .collect(),
    );
    options
}

/// The last recording read, and what it was read for.
#[derive(Default)]
pub struct RecordingCache {
    last: Option<(
        PathBuf,
        Option<SystemTime>,
        AnalysisOptions,
        Arc<RecordingView>,
    )>,
}

impl RecordingCache {
    /// The recording at `path` for `model`, read and analysed unless cached.
    pub fn load(
        &mut self,
        path: &Path,
        model: &Model,
        system: &System,
    ) -> Result<Arc<RecordingView>, String> {
        let modified = std::fs::metadata(path).and_then(|m| m.modified()).ok();
        let options = analysis_options(model, system);
        if let Some((p, m, o, view)) = &self.last
            && p == path
            && *m == modified
            && *o == options
        {
            return Ok(view.clone());
        }
        let mut view = read(path, &system.node_names, &options)?;
        view.relative = relative_speeds(&view.recording, model, system);
        let view = Arc::new(view);
        self.last = Some((path.to_path_buf(), modified, options, view.clone()));
        Ok(view)
    }
}

/// Reads and analyses one recording; errors name the file.
fn read(path: &Path, nodes: &[String], options: &AnalysisOptions) -> Result<RecordingView, String> {
    let file = path.file_name().map_or_else(
        || path.display().to_string(),
        |f| f.to_string_lossy().into(),
    );
    let recording = read_recording(path, Some(nodes)).map_err(|e| e.to_string())?;
    let mut options = options.clone();
    // Pairs the recording cannot have (a station not measured) are left out by the
    // analysis itself; keep only what both ends measure.
    if let Some(pairs) = &mut options.pairs {
        pairs.retain(|(a, b)| recording.speed_rpm(a).is_some() && recording.speed_rpm(b).is_some());
    }
    let analysis = analyse_with(&recording, &options)
        .map_err(|e| format!("{}: cannot analyse: {e}", path.display()))?;
    let t0_s = recording.time_s.first().copied().unwrap_or(0.0);
    let regime = regime_of(&recording).map_err(|e| format!("{}: {e}", path.display()))?;
    let stations: Vec<&str> = recording.speed_stations().iter().map(|s| s.0).collect();
    let duration_s = recording.time_s.last().copied().unwrap_or(0.0) - t0_s;
    let what = classify(&recording).describe();
    let label = recording
        .meta
        .label
        .as_ref()
        .map_or(String::new(), |l| format!(" ({})", l.replace('→', "->")));
    let summary = format!(
        "{what}, {duration_s:.1} s, load {:.2}, stations {}{label}",
        recording.meta.load,
        stations.join(", ")
    );
    let max_hz = max_frequency_hz(&analysis);
    let measured_speed = analysis
        .stft
        .as_ref()
        .filter(|_| regime.is_ramp())
        .and_then(|s| {
            let times: Vec<f64> = s.times_s.iter().map(|t| t - t0_s).collect();
            MeasuredSpeed::to_follow(&times, &s.speeds_rpm).map(Arc::new)
        });
    Ok(RecordingView {
        file,
        t0_s,
        spectrograms: SpectrogramSet::new(&analysis, t0_s, max_hz).map(Arc::new),
        analysis,
        regime,
        measured_speed,
        relative: Vec::new(),
        summary,
        recording,
    })
}

/// Seed 001's `n_rel = n_a − n_b` (b referred to a's shaft) across every rubber stage of
/// `model` whose two sides the recording measured.
fn relative_speeds(
    recording: &Recording,
    model: &Model,
    system: &System,
) -> Vec<(String, Vec<f64>)> {
    let ratio = |node: &str| {
        let i = system.node_names.iter().position(|n| n == node)?;
        Some(system.speed_ratio[i].abs())
    };
    model
        .connections
        .iter()
        .filter(|c| matches!(c.kind, ConnectionKind::Rubber(_)))
        .filter_map(|c| {
            let (a, b) = (recording.speed_rpm(&c.from)?, recording.speed_rpm(&c.to)?);
            let r = ratio(&c.from)? / ratio(&c.to)?;
            let values = a.iter().zip(b).map(|(x, y)| x - r * y).collect();
            Some((relative_name(&c.name, &c.from, &c.to), values))
        })
        .collect()
}

/// The highest frequency worth showing in a run-up's spectrogram: 1.25 × the highest
/// tracked order at the top speed, Hz.
pub fn max_frequency_hz(analysis: &Analysis) -> f64 {
    analysis.stft.as_ref().map_or(0.0, |s| {
        let top = s.speeds_rpm.iter().fold(0.0_f64, |m, v| m.max(*v));
        let order = s.orders.last().copied().unwrap_or(12.0);
        1.25 * order * top / 60.0
    })
}

/// The simulated run matching a recording, by the classifier the diagnosis uses
/// ([`torsim::recording::classify`]): a steady run (or a long run) at its nominal speed
/// (or the reference's mean) for its duration (at most 20 s), or a linear ramp between
/// the least-squares line's ends of the reference speed over its duration. The duration
/// of `n` uniform samples is `n` intervals.
pub fn regime_of(recording: &Recording) -> Result<Run, String> {
    if recording.speed_rpm(&recording.meta.reference).is_none() {
        return Err(format!("no `{}_rpm` column", recording.meta.reference));
    }
    let run = Run::of(recording);
    match run.shape {
        RunShape::Steady { speed_rpm } | RunShape::LongRun { speed_rpm } => {
            Ok(Run::steady(speed_rpm, run.duration_s.min(20.0)))
        }
        RunShape::Ramp { from_rpm, to_rpm } => {
            if from_rpm <= 0.0 || to_rpm <= 0.0 {
                return Err(format!(
                    "the reference speed fits a ramp {from_rpm:.0} to {to_rpm:.0} rpm: not a run-up above 0 rpm"
                ));
            }
            Ok(run)
        }
    }
}
