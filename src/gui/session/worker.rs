//! The simulation thread. The GUI thread never computes: on every edit it sends a
//! [`SimRequest`] with a new generation; the worker drops stale requests (only the newest
//! matters), computes the cheap results first ([`cheap_job`]: modes, Campbell, forced
//! response) and sends each as soon as it is ready, then reads the open recording ([`recording_job`]) and
//! runs the time run in chunks ([`trace_job`]). A newer request, or the Cancel button,
//! cancels the run in progress. Every send wakes the GUI (`request_repaint`).
//!
//! [`cheap_job`]: crate::gui::session::cheap_job
//! [`recording_job`]: crate::gui::session::recording_job
//! [`trace_job`]: crate::gui::session::trace_job

use crate::gui::session::cheap_job::compute;
use crate::gui::session::messages::{PanelError, Payload, SimRequest, SimResult};
use crate::gui::session::recording_job::RecordingCache;
use crate::gui::session::trace_data::TraceSpec;
use crate::gui::session::trace_job;
use crossbeam_channel::{Receiver, Sender, TryRecvError, unbounded};
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::thread::JoinHandle;
use torsim::model::Model;

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
