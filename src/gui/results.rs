//! The results the window shows: the latest of each kind from the simulation thread
//! ([`crate::gui::session::worker`]), taken from its channel once a frame. Results of an
//! older request (an edit since) are dropped; the last good ones stay on screen while an
//! edit is invalid or still computing.

use crate::gui::app::TorsimApp;
use crate::gui::session::messages::{
    Modal, PanelError, Payload, RatingsResult, RunAnalysis, SimResult,
};
use crate::gui::session::recording_job::RecordingView;
use crate::gui::session::trace_data::LiveTrace;
use crate::gui::trace_state;
use std::sync::Arc;
use torsim::response::Response;
use torsim::transient::Simulation;

/// The latest results for the model on screen (the last good ones stay while an edit is
/// invalid or still computing).
#[derive(Default)]
pub struct Results {
    /// Generation of the last request.
    pub generation: u64,
    /// Modes, Campbell diagram and damped modes.
    pub campbell: Option<Arc<Modal>>,
    /// The request the Campbell diagram on screen answers.
    pub campbell_generation: u64,
    /// Forced response.
    pub response: Option<Arc<Response>>,
    /// The coupling ratings on that response, and the linear range.
    pub ratings: Option<Arc<RatingsResult>>,
    /// The engine's working cycle at full load.
    pub engine_cycle: Option<Arc<torsim::physics::engine_cycle::EngineCycle>>,
    /// The finished time run.
    pub trace: Option<Arc<Simulation>>,
    /// Progress of the time run.
    pub trace_progress: f32,
    /// What the time run runs, for a person (`"run-up 1000 to 2000 rpm in 60 s"`).
    pub trace_label: String,
    /// The time run's samples as they arrive.
    pub live: Option<LiveTrace>,
    /// Orders and spectrograms of the finished time run.
    pub trace_analysis: Option<Arc<RunAnalysis>>,
    /// The open recording, read and analysed.
    pub recording: Option<Arc<RecordingView>>,
    /// Generation of the last time run cancelled.
    pub trace_cancelled: Option<u64>,
    /// Errors by panel.
    pub errors: Vec<PanelError>,
}
impl TorsimApp {
    /// Takes every result the worker sent; stale ones are dropped.
    pub fn receive(&mut self) {
        while let Ok(SimResult {
            generation,
            payload,
        }) = self.worker.results.try_recv()
        {
            if let Payload::Cancelled = payload {
                self.results.trace_cancelled = Some(generation);
                continue;
            }
            if generation != self.results.generation {
                continue;
            }
            match payload {
                Payload::Modal(c) => {
                    self.results.campbell = Some(c);
                    self.results.campbell_generation = generation;
                    self.latency.arrived(generation);
                }
                Payload::Response(r) => self.results.response = Some(r),
                Payload::Ratings(r) => self.results.ratings = Some(r),
                Payload::EngineCycle(c) => self.results.engine_cycle = Some(c),
                Payload::Trace(t) => {
                    self.results.trace = Some(t);
                    self.results.trace_progress = 1.0;
                }
                Payload::Progress(p) => self.results.trace_progress = p,
                Payload::Error(e) => self.results.errors.push(e),
                other => trace_state::receive(self, generation, other),
            }
        }
    }

    /// The error of a panel, if any.
    pub fn error_of(&self, panel: &str) -> Option<&str> {
        self.results
            .errors
            .iter()
            .find(|e| e.panel == panel)
            .map(|e| e.message.as_str())
    }
}
