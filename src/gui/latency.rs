//! Edit-to-plot latency, measured in the real window (issue 16): from the moment an edit
//! is committed to the end of the first frame that draws the Campbell diagram of the
//! edited model, in milliseconds and in frames. With `TORSIM_LOG_LATENCY=1` in the
//! environment every edit's latency is printed to stderr (`scripts/gui-latency.sh`
//! drives the window under Xvfb and reads them); otherwise nothing is measured.

use std::time::Instant;

/// The environment variable that turns the log on.
pub const LOG_ENV: &str = "TORSIM_LOG_LATENCY";

/// One edit waiting for its plot.
#[derive(Debug, Clone, Copy)]
pub struct Probe {
    /// The request of the edit.
    generation: u64,
    /// When the edit was committed.
    at: Instant,
    /// Frames begun since.
    frames: u32,
    /// When its Campbell diagram arrived from the simulation thread.
    arrived: Option<Instant>,
}

/// The probe of the last edit, when the log is on.
#[derive(Debug, Default)]
pub struct Latency {
    on: bool,
    probe: Option<Probe>,
}

impl Latency {
    /// On when [`LOG_ENV`] is set.
    pub fn from_env() -> Self {
        Self {
            on: std::env::var_os(LOG_ENV).is_some(),
            probe: None,
        }
    }

    /// An edit sent request `generation`.
    pub fn edited(&mut self, generation: u64) {
        if self.on {
            self.probe = Some(Probe {
                generation,
                at: Instant::now(),
                frames: 0,
                arrived: None,
            });
        }
    }

    /// A frame begins.
    pub fn frame(&mut self) {
        if let Some(p) = &mut self.probe {
            p.frames += 1;
        }
    }

    /// The Campbell diagram of request `generation` arrived.
    pub fn arrived(&mut self, generation: u64) {
        if let Some(p) = &mut self.probe
            && p.generation == generation
            && p.arrived.is_none()
        {
            p.arrived = Some(Instant::now());
        }
    }

    /// A frame ended having drawn the Campbell diagram of request `generation`: the
    /// latency of the edit that asked for it, if that is the one waiting.
    pub fn drawn(&mut self, generation: u64) {
        if let Some(p) = self.probe
            && p.generation == generation
        {
            self.probe = None;
            let arrived_ms = p
                .arrived
                .map_or(f64::NAN, |t| 1e3 * (t - p.at).as_secs_f64());
            eprintln!(
                "torsim latency: edit to plot {:.1} ms, {} frame(s); the results arrived \
                 after {arrived_ms:.1} ms (request {generation})",
                1e3 * p.at.elapsed().as_secs_f64(),
                p.frames
            );
        }
    }
}
