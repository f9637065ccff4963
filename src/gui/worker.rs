//! The simulation thread. The GUI thread never computes: on every edit it sends a
//! [`SimRequest`] with a new generation; the worker drops stale requests (only the newest
//! matters), computes the cheap results first (modes, Campbell, forced response) and sends
//! each as soon as it is ready, then a steady time run. A newer request cancels the run in
//! progress. Every send wakes the GUI (`request_repaint`).

use crossbeam_channel::{Receiver, Sender, TryRecvError, unbounded};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::thread::JoinHandle;
use torsim::modal::{Campbell, DampedMode, campbell, damped_modes, speed_grid};
use torsim::model::Model;
use torsim::physics::{Excitation, OperatingPoint, System};
use torsim::response::{Response, forced_response};
use torsim::transient::{RunKind, RunOptions, Simulation, simulate};

/// What the GUI asks for.
#[derive(Debug, Clone)]
pub enum SimRequest {
    /// Compute everything for this model.
    Run {
        /// Increases with every edit; results carry it back.
        generation: u64,
        /// The model as edited.
        model: Box<Model>,
        /// Speed of the steady time run, rpm.
        trace_speed_rpm: f64,
    },
    /// Stop the thread.
    Quit,
}

/// What the worker sends back, tagged with the request's generation.
#[derive(Debug, Clone)]
pub enum SimResult {
    /// Modes and the Campbell diagram (with the system they belong to).
    Campbell(u64, Arc<(System, Campbell, Vec<DampedMode>)>),
    /// The forced response over the speed range.
    Response(u64, Arc<Response>),
    /// A steady time run.
    Trace(u64, Arc<Simulation>),
    /// Progress of the time run, 0–1.
    Progress(u64, f32),
    /// An analysis failed; `0` names which (`"modes"`, `"response"`, `"trace"`).
    Error(u64, &'static str, String),
}

/// The worker thread and its channels.
pub struct Worker {
    requests: Sender<SimRequest>,
    /// Results, newest last.
    pub results: Receiver<SimResult>,
    latest: Arc<AtomicU64>,
    handle: Option<JoinHandle<()>>,
}

impl Worker {
    /// Starts the named thread; `wake` is called after every result (the GUI repaints).
    pub fn start(wake: impl Fn() + Send + 'static) -> Self {
        let (requests, inbox) = unbounded::<SimRequest>();
        let (outbox, results) = unbounded::<SimResult>();
        let latest = Arc::new(AtomicU64::new(0));
        let newest = latest.clone();
        let handle = std::thread::Builder::new()
            .name("torsim-sim".into())
            .spawn(move || worker_loop(&inbox, &outbox, &newest, &wake))
            .ok();
        Self {
            requests,
            results,
            latest,
            handle,
        }
    }

    /// Asks for results of `model`; older requests become stale at once.
    pub fn request(&self, generation: u64, model: &Model, trace_speed_rpm: f64) {
        self.latest.store(generation, Ordering::SeqCst);
        let _ = self.requests.send(SimRequest::Run {
            generation,
            model: Box::new(model.clone()),
            trace_speed_rpm,
        });
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

fn worker_loop(
    inbox: &Receiver<SimRequest>,
    outbox: &Sender<SimResult>,
    latest: &AtomicU64,
    wake: &dyn Fn(),
) {
    while let Ok(mut request) = inbox.recv() {
        // Only the newest request matters.
        loop {
            match inbox.try_recv() {
                Ok(newer) => request = newer,
                Err(TryRecvError::Empty) => break,
                Err(TryRecvError::Disconnected) => return,
            }
        }
        let SimRequest::Run {
            generation,
            model,
            trace_speed_rpm,
        } = request
        else {
            return;
        };
        let stale = || latest.load(Ordering::SeqCst) != generation;
        let send = |r: SimResult| {
            let _ = outbox.send(r);
            wake();
        };
        compute(generation, &model, trace_speed_rpm, &stale, &send);
    }
}

/// Computes one request's results, cheapest first, stopping as soon as it is stale.
pub fn compute(
    generation: u64,
    model: &Model,
    trace_speed_rpm: f64,
    stale: &dyn Fn() -> bool,
    send: &dyn Fn(SimResult),
) {
    let system = match System::new(model, OperatingPoint::default()) {
        Ok(s) => s,
        Err(e) => return send(SimResult::Error(generation, "modes", e.to_string())),
    };
    let [from, to] = model.operation.speed_range_rpm.unwrap_or([100.0, 3000.0]);
    let speeds = speed_grid(from, to, (to - from) / 200.0);
    let orders = model.orders();
    match campbell(&system, &speeds, &orders) {
        Ok(c) => {
            let damped = damped_modes(&system, &c.modes);
            send(SimResult::Campbell(
                generation,
                Arc::new((system.clone(), c, damped)),
            ));
        }
        Err(e) => send(SimResult::Error(generation, "modes", e.to_string())),
    }
    if stale() {
        return;
    }
    let excitation = Excitation::new(model, &system, 1.0, &orders);
    match forced_response(&system, &excitation, &speeds) {
        Ok(r) => send(SimResult::Response(generation, Arc::new(r))),
        Err(e) => send(SimResult::Error(generation, "response", e.to_string())),
    }
    if stale() {
        return;
    }
    let kind = RunKind::Steady {
        speed_rpm: trace_speed_rpm,
        duration_s: 0.5,
    };
    let options = RunOptions {
        rate_hz: 4096.0,
        max_settle_s: 10.0,
        ..RunOptions::default()
    };
    let mut progress = |f: f64| {
        send(SimResult::Progress(generation, f as f32));
        !stale()
    };
    match simulate(model, kind, options, &mut progress) {
        Ok(sim) => send(SimResult::Trace(generation, Arc::new(sim))),
        Err(torsim::transient::TransientError::Cancelled { .. }) => {}
        Err(e) => send(SimResult::Error(generation, "trace", e.to_string())),
    }
}
