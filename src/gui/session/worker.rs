//! The simulation thread. The GUI thread never computes: on every edit it sends a
//! [`SimRequest`] with a new generation; the worker drops stale requests (only the newest
//! matters), computes the cheap results first (modes, Campbell, forced response) and sends
//! each as soon as it is ready, then reads the open recording ([`recording_job`]) and
//! runs the time run in chunks ([`trace_job`]). A newer request, or the Cancel button,
//! cancels the run in progress. Every send wakes the GUI (`request_repaint`).
//!
//! [`recording_job`]: crate::gui::session::recording_job
//! [`trace_job`]: crate::gui::session::trace_job

use crate::gui::session::recording_job::{RecordingCache, RecordingView};
use crate::gui::session::trace_data::{TraceChunk, TraceLayout, TraceSpec};
use crate::gui::session::trace_job::{self, RunAnalysis};
use crossbeam_channel::{Receiver, Sender, TryRecvError, unbounded};
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::thread::JoinHandle;
use torsim::modal::{Campbell, DampedMode, campbell, damped_modes, speed_grid};
use torsim::model::Model;
use torsim::physics::{Excitation, OperatingPoint, System};
use torsim::response::{Response, forced_response};
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

/// The worker thread and its channels.
pub struct Worker {
    requests: Sender<SimRequest>,
    /// Results, newest last.
    pub results: Receiver<SimResult>,
    latest: Arc<AtomicU64>,
    cancelled: Arc<AtomicU64>,
    /// Read by the window's tests only ([`Self::finished`]).
    #[cfg_attr(not(test), allow(dead_code))]
    finished: Arc<AtomicU64>,
    handle: Option<JoinHandle<()>>,
}

impl Worker {
    /// Starts the named thread; `wake` is called after every result (the GUI repaints).
    pub fn start(wake: impl Fn() + Send + 'static) -> Self {
        let (requests, inbox) = unbounded::<SimRequest>();
        let (outbox, results) = unbounded::<SimResult>();
        let latest = Arc::new(AtomicU64::new(0));
        let cancelled = Arc::new(AtomicU64::new(0));
        let finished = Arc::new(AtomicU64::new(0));
        let flags = Flags {
            latest: latest.clone(),
            cancelled: cancelled.clone(),
            finished: finished.clone(),
        };
        let handle = std::thread::Builder::new()
            .name("torsim-sim".into())
            .spawn(move || worker_loop(&inbox, &outbox, &flags, &wake))
            .ok();
        Self {
            requests,
            results,
            latest,
            cancelled,
            finished,
            handle,
        }
    }

    /// The generation of the last request the thread is done with: every result of it
    /// sent and the window woken after each (0: none yet). The window's tests wait for it
    /// before they call a frame idle.
    #[cfg(test)]
    pub fn finished(&self) -> u64 {
        self.finished.load(Ordering::SeqCst)
    }

    /// Asks for results of `model`; older requests become stale at once.
    pub fn request(
        &self,
        generation: u64,
        model: &Model,
        trace: TraceSpec,
        recording: Option<PathBuf>,
        stations: Vec<String>,
    ) {
        self.latest.store(generation, Ordering::SeqCst);
        let _ = self.requests.send(SimRequest::Run {
            generation,
            model: Box::new(model.clone()),
            trace,
            recording,
            stations,
        });
    }

    /// Stops the time run of `generation` (its other results stay).
    pub fn cancel(&self, generation: u64) {
        self.cancelled.store(generation, Ordering::SeqCst);
    }
}

impl Drop for Worker {
    fn drop(&mut self) {
        self.latest.store(u64::MAX, Ordering::SeqCst);
        let _ = self.requests.send(SimRequest::Quit);
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
    }
}

/// What the window and the thread share besides the channels.
struct Flags {
    /// The newest request's generation; older ones are stale.
    latest: Arc<AtomicU64>,
    /// The generation whose time run was cancelled.
    cancelled: Arc<AtomicU64>,
    /// The last generation answered in full ([`Worker::finished`]).
    finished: Arc<AtomicU64>,
}

fn worker_loop(
    inbox: &Receiver<SimRequest>,
    outbox: &Sender<SimResult>,
    flags: &Flags,
    wake: &dyn Fn(),
) {
    let mut recordings = RecordingCache::default();
    while let Ok(request) = inbox.recv() {
        match answer(request, inbox, outbox, flags, wake, &mut recordings) {
            Some(generation) => flags.finished.store(generation, Ordering::SeqCst),
            None => return,
        }
    }
}

/// Answers the newest of the waiting requests; its generation, or `None` on quit.
fn answer(
    mut request: SimRequest,
    inbox: &Receiver<SimRequest>,
    outbox: &Sender<SimResult>,
    flags: &Flags,
    wake: &dyn Fn(),
    recordings: &mut RecordingCache,
) -> Option<u64> {
    // Only the newest request matters.
    loop {
        match inbox.try_recv() {
            Ok(newer) => request = newer,
            Err(TryRecvError::Empty) => break,
            Err(TryRecvError::Disconnected) => return None,
        }
    }
    let SimRequest::Run {
        generation,
        model,
        trace,
        recording,
        stations,
    } = request
    else {
        return None;
    };
    let stale = || {
        flags.latest.load(Ordering::SeqCst) != generation
            || flags.cancelled.load(Ordering::SeqCst) == generation
    };
    let send = |r: SimResult| {
        let _ = outbox.send(r);
        wake();
    };
    let Some(system) = compute(generation, &model, &stale, &send) else {
        return Some(generation);
    };
    let view = match &recording {
        None => None,
        Some(path) => match recordings.load(path, &model, &system) {
            Ok(view) => {
                send(SimResult::new(generation, Payload::Recording(view.clone())));
                Some(view)
            }
            Err(e) => {
                send(SimResult::new(
                    generation,
                    Payload::Error(PanelError {
                        panel: "recording",
                        message: e,
                    }),
                ));
                None
            }
        },
    };
    if stale() {
        send(SimResult::new(generation, Payload::Cancelled));
        return Some(generation);
    }
    let stations = match &view {
        Some(v) => v.stations(),
        None => stations,
    };
    trace_job::run(
        generation,
        &model,
        &system,
        &trace,
        view.as_deref(),
        &stations,
        &stale,
        &send,
    );
    Some(generation)
}

/// Computes one request's cheap results (modes, Campbell, forced response) and returns
/// the system for the time run, or `None` when the model fails or the request is stale.
pub fn compute(
    generation: u64,
    model: &Model,
    stale: &dyn Fn() -> bool,
    send: &dyn Fn(SimResult),
) -> Option<System> {
    let system = match System::new(model, OperatingPoint::default()) {
        Ok(s) => s,
        Err(e) => {
            send(SimResult::new(
                generation,
                Payload::Error(PanelError {
                    panel: "modes",
                    message: e.to_string(),
                }),
            ));
            send(SimResult::new(
                generation,
                Payload::Error(PanelError {
                    panel: "trace",
                    message: format!("no time run: {e}"),
                }),
            ));
            return None;
        }
    };
    let [from, to] = model.operation.speed_range_rpm.unwrap_or([100.0, 3000.0]);
    let speeds = speed_grid(from, to, (to - from) / 200.0);
    let orders = model.orders();
    match campbell(&system, &speeds, &orders) {
        Ok(c) => {
            let damped = damped_modes(&system, &c.modes);
            send(SimResult::new(
                generation,
                Payload::Modal(Arc::new(Modal {
                    system: system.clone(),
                    campbell: c,
                    damped,
                })),
            ));
        }
        Err(e) => send(SimResult::new(
            generation,
            Payload::Error(PanelError {
                panel: "modes",
                message: e.to_string(),
            }),
        )),
    }
    if stale() {
        return None;
    }
    let excitation = Excitation::new(model, &system, 1.0, &orders);
    match forced_response(&system, &excitation, &speeds) {
        Ok(r) => {
            let ratings = RatingsResult {
                stages: torsim::ratings::check_ratings(model, &system, &r),
                beyond: torsim::ratings::beyond_linear_range(&system, &r),
                outside_law: torsim::ratings::beyond_amplitude_law(model, &system, &r),
            };
            send(SimResult::new(generation, Payload::Response(Arc::new(r))));
            send(SimResult::new(
                generation,
                Payload::Ratings(Arc::new(ratings)),
            ));
        }
        Err(e) => send(SimResult::new(
            generation,
            Payload::Error(PanelError {
                panel: "response",
                message: e.to_string(),
            }),
        )),
    }
    // After the plots an edit is waiting for: the editor's cycle drawing can come later.
    if let Some(engine) = &model.engine
        && !stale()
    {
        let cycle = torsim::physics::engine_cycle::engine_cycle(engine, 1.0);
        send(SimResult::new(
            generation,
            Payload::EngineCycle(Arc::new(cycle)),
        ));
    }
    (!stale()).then_some(system)
}
