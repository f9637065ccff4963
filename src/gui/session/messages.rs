//! What the window and the simulation thread ([`super::worker`]) say to each other: the
//! request of one edit, and the results that answer it, each tagged with the request's
//! generation so that stale ones are dropped. The jobs that make the results
//! ([`super::cheap_job`], [`super::recording_job`], [`super::trace_job`]) and the window
//! ([`crate::gui::results`]) share these types and nothing else.

use crate::gui::session::recording_job::RecordingView;
use crate::gui::session::spectrogram::SpectrogramSet;
use crate::gui::session::trace_data::{TraceChunk, TraceLayout, TraceSpec};
use std::path::PathBuf;
use std::sync::Arc;
use torsim::modal::{Campbell, DampedMode};
use torsim::model::Model;
use torsim::physics::System;
use torsim::response::Response;
use torsim::signal::Analysis;
use torsim::transient::Simulation;

/// What the GUI asks for.
#[derive(Debug, Clone)]
pub enum SimRequest {
    /// Compute everything for this model.
    Run {
        /// Increases with every edit; results carry it back.
        generation: u64,
        /// The model as edited.
        model: Box<Model>,
        /// The time run.
        trace: TraceSpec,
        /// The open recording (CSV), if any.
        recording: Option<PathBuf>,
        /// Nodes shown at first in the time traces (all when empty).
        stations: Vec<String>,
    },
    /// Stop the thread.
    Quit,
}

/// What the worker sends back: a result of the request of `generation`.
#[derive(Debug, Clone)]
pub struct SimResult {
    /// The generation of the request it answers (stale ones are dropped).
    pub generation: u64,
    /// The result.
    pub payload: Payload,
}

impl SimResult {
    /// `payload` for the request of `generation`.
    pub fn new(generation: u64, payload: Payload) -> Self {
        Self {
            generation,
            payload,
        }
    }
}

/// The modes of a model: the system they belong to, the Campbell diagram (undamped modes
/// and crossings) and the damped modes.
#[derive(Debug, Clone)]
pub struct Modal {
    /// The linear system at the model's operating point.
    pub system: System,
    /// The Campbell diagram over the speed range.
    pub campbell: Campbell,
    /// The damped modes.
    pub damped: Vec<DampedMode>,
}

/// An analysis that failed, for the panel that shows it.
#[derive(Debug, Clone, PartialEq)]
pub struct PanelError {
    /// Which: `"modes"`, `"response"`, `"trace"` or `"recording"`.
    pub panel: &'static str,
    /// Why, for a person.
    pub message: String,
}

/// What a [`SimResult`] carries.
#[derive(Debug, Clone)]
pub enum Payload {
    /// Modes and the Campbell diagram.
    Modal(Arc<Modal>),
    /// The forced response over the speed range.
    Response(Arc<Response>),
    /// The coupling ratings checked on that response, and where it leaves the linear
    /// range ([`torsim::ratings`]).
    Ratings(Arc<RatingsResult>),
    /// The engine's working cycle at full load, for the engine editor.
    EngineCycle(Arc<torsim::physics::engine_cycle::EngineCycle>),
    /// The time run starts settling; what runs, for a person.
    TraceRunning(String),
    /// The time run starts recording: the layout of its chunks.
    TraceStarted(Arc<TraceLayout>),
    /// Samples of the time run since the last chunk (a few per second).
    TraceChunk(Arc<TraceChunk>),
    /// The finished time run.
    Trace(Arc<Simulation>),
    /// Orders and spectrograms of the finished time run.
    TraceAnalysis(Arc<RunAnalysis>),
    /// The open recording, read and analysed.
    Recording(Arc<RecordingView>),
    /// Progress of the time run, 0–1.
    Progress(f32),
    /// The time run was cancelled (a newer request, or the Cancel button).
    Cancelled,
    /// An analysis failed.
    Error(PanelError),
}

/// The ratings of every rated stage and the nodes beyond the linear range.
#[derive(Debug, Clone, Default)]
pub struct RatingsResult {
    /// Each rated rubber stage's checks over the sweep.
    pub stages: Vec<torsim::ratings::StageRating>,
    /// Where the IAS leaves the linear model's range.
    pub beyond: Vec<torsim::ratings::BeyondLinear>,
    /// Where a stage's twist leaves its amplitude law's measured range.
    pub outside_law: Vec<torsim::ratings::OutsideAmplitudeLaw>,
}

/// The analysis of a finished run.
#[derive(Debug)]
pub struct RunAnalysis {
    /// Orders, RMS, IR per station (and per rubber stage's relative speed).
    pub analysis: Analysis,
    /// Spectrograms of a run-up.
    pub spectrograms: Option<Arc<SpectrogramSet>>,
    /// Shift of a steady recording's time axis that puts its reference station's
    /// averaged cycle in phase with the simulation's, s (0 without one).
    pub overlay_shift_s: f64,
}
