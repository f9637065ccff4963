//! What the traces tab asks for and how it shows it: steady run or run-up (defaults from
//! the model's speed range: the whole range in 60 s), the open recording, the view
//! (traces, spectrogram, orders), the selected station; and the results of the time run
//! taken from the worker's messages.

use crate::gui::app::TorsimApp;
use crate::gui::background::Pending;
use crate::gui::session::messages::Payload;
use crate::gui::session::trace_data::{LiveTrace, TraceSpec};
use std::path::PathBuf;
use torsim::model::Model;
use torsim::recording::Run;

/// Duration of the default run-up over the model's speed range, s.
pub const DEFAULT_RUN_UP_S: f64 = 60.0;

/// Steady run or run-up.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TraceMode {
    /// A steady run at `app.trace_speed_rpm`.
    Steady,
    /// A linear run-up.
    RunUp,
    /// The regime of the open recording.
    Recording,
}

/// The view of the traces tab.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TraceView {
    /// Time traces, one plot per quantity, x axes linked.
    Traces,
    /// The STFT of a run-up with order lines, and order tracks.
    Spectrogram,
    /// Order amplitudes per station, measured against simulated.
    Orders,
}

/// The traces tab's state.
pub struct TraceState {
    /// Steady run, run-up, or the recording's regime.
    pub mode: TraceMode,
    /// Recorded duration of a steady run, s (default 2).
    pub steady_duration_s: f64,
    /// Run-up start, rpm.
    pub from_rpm: f64,
    /// Run-up end, rpm.
    pub to_rpm: f64,
    /// Run-up rate, rpm/s.
    pub rate_rpm_per_s: f64,
    /// The model speed range the run-up defaults were taken from.
    defaults_for: Option<[f64; 2]>,
    /// The open recording (CSV path).
    pub recording: Option<PathBuf>,
    /// A file dialog waiting for the user.
    pub dialog: Option<Pending<Option<PathBuf>>>,
    /// What the tab shows.
    pub view: TraceView,
    /// Station (node, or relative speed) of the spectrogram.
    pub station: String,
    /// Show the recording's spectrogram instead of the simulation's.
    pub measured_stft: bool,
    /// The order whose track is drawn under the spectrogram.
    pub track_order: f64,
    /// The spectrogram texture and what it shows: (generation, measured, station).
    pub texture: Option<((u64, bool, String), egui::TextureHandle)>,
    /// Per group of the time run's layout, per series: drawn.
    pub shown: Vec<Vec<bool>>,
    /// The view shown in the last frame.
    pub shown_view: Option<TraceView>,
    /// Show IAS about each station's mean speed (default) rather than absolute.
    pub ias_about_mean: bool,
    /// The kind of run last drawn (another kind resets zoom and legend).
    pub drawn: Option<torsim::recording::Run>,
    /// The orders whose tracks are drawn (default: the engine's main orders, multiples
    /// of the first number).
    pub track_orders: Option<(f64, Vec<f64>)>,
}

impl Default for TraceState {
    fn default() -> Self {
        Self {
            mode: TraceMode::Steady,
            steady_duration_s: 2.0,
            from_rpm: 1000.0,
            to_rpm: 2000.0,
            rate_rpm_per_s: 1000.0 / DEFAULT_RUN_UP_S,
            defaults_for: None,
            recording: None,
            dialog: None,
            view: TraceView::Traces,
            station: String::new(),
            measured_stft: false,
            track_order: 0.0,
            texture: None,
            shown: Vec::new(),
            shown_view: None,
            ias_about_mean: true,
            drawn: None,
            track_orders: None,
        }
    }
}

impl TraceState {
    /// What to run for `model`; the run-up defaults follow the model's speed range when
    /// it changes (another model, or the range edited).
    pub fn spec(&mut self, model: &Model, steady_rpm: f64) -> TraceSpec {
        let range = model.operation.speed_range_rpm;
        if range != self.defaults_for {
            self.defaults_for = range;
            let [from, to] = range.unwrap_or([1000.0, 2000.0]);
            self.from_rpm = from;
            self.to_rpm = to;
            self.rate_rpm_per_s = (to - from).abs() / DEFAULT_RUN_UP_S;
        }
        match self.mode {
            TraceMode::Steady => TraceSpec::Run(Run::steady(steady_rpm, self.steady_duration_s)),
            // A rate ≤ 0 gives a duration that is not finite, refused by `resolve`.
            TraceMode::RunUp => TraceSpec::Run(Run::ramp(
                self.from_rpm,
                self.to_rpm,
                (self.to_rpm - self.from_rpm).abs() / self.rate_rpm_per_s,
            )),
            TraceMode::Recording => TraceSpec::MatchRecording,
        }
    }
}

/// What a request's time run will be, for a person, until the worker says.
pub fn pending_label(spec: &TraceSpec) -> String {
    match crate::gui::session::trace_job::resolve(spec, None) {
        Ok(kind) => crate::gui::session::trace_job::describe(kind),
        Err(_) => "the recording's regime (reading the recording)".into(),
    }
}

/// Takes a time-run message of the current generation `g` (the app drops the others).
pub fn receive(app: &mut TorsimApp, g: u64, message: Payload) {
    let r = &mut app.results;
    match message {
        Payload::TraceRunning(label) => {
            r.trace_label = label;
            r.trace_progress = 0.0;
        }
        Payload::TraceStarted(layout) => {
            r.live = Some(LiveTrace::new(g, layout));
            r.trace_analysis = None;
        }
        Payload::TraceChunk(chunk) => {
            if let Some(live) = r.live.as_mut().filter(|l| l.generation == g) {
                live.append(&chunk);
            }
        }
        Payload::TraceAnalysis(a) => r.trace_analysis = Some(a),
        Payload::Recording(view) => {
            if r.recording.is_none() {
                app.status = format!("opened recording {}", view.file);
            }
            app.stations = view.stations();
            r.recording = Some(view);
        }
        _ => {}
    }
}
