//! On the simulation thread: the time run of a request. It resolves what to run (a
//! steady run, a run-up, or the regime of the open recording), runs it with
//! `torsim::transient::simulate_observed`, sends the samples in plot groups at most
//! every [`SEND_EVERY`] (not per step), then the finished `Simulation`, then its analysis
//! (`torsim::signal`: orders per station, STFT images of a run-up). It stops as soon as
//! the request is stale or cancelled.

use crate::gui::session::messages::{PanelError, Payload, RunAnalysis, SimResult};
use crate::gui::session::recording_job::{RecordingView, analysis_options, max_frequency_hz};
use crate::gui::session::spectrogram::SpectrogramSet;
use crate::gui::session::trace_data::{TraceChunk, TraceSpec};
use crate::gui::session::trace_series::SeriesBuilder;
use std::sync::Arc;
use std::time::{Duration, Instant};
use torsim::model::Model;
use torsim::physics::System;
use torsim::recording::Run;
use torsim::signal::{Analysis, analyse_with};
use torsim::transient::{
    Event, RunOptions, TransientError, simulate_observed, simulate_observed_along, to_recording,
};

/// Longest wait between two chunks sent to the window.
pub const SEND_EVERY: Duration = Duration::from_millis(200);

/// For a person: `"run-up 1000 to 2000 rpm in 60 s"`.
pub fn describe(kind: Run) -> String {
    if kind.is_ramp() {
        format!("{} in {:.0} s", kind.shape.describe(), kind.duration_s)
    } else {
        format!(
            "steady {:.0} rpm, {:.1} s",
            kind.speeds_rpm()[0],
            kind.duration_s
        )
    }
}

/// What to run for `spec`.
pub fn resolve(spec: &TraceSpec, recording: Option<&RecordingView>) -> Result<Run, String> {
    let kind = match *spec {
        TraceSpec::Run(run) if run.is_ramp() => {
            let [from_rpm, to_rpm] = run.speeds_rpm();
            let duration_ok = run.duration_s.is_finite() && run.duration_s > 0.0;
            if !duration_ok || from_rpm == to_rpm {
                let rate_rpm_per_s = (to_rpm - from_rpm).abs() / run.duration_s;
                return Err(format!(
                    "a run-up needs two different speeds and a rate > 0 rpm/s (got {from_rpm} to {to_rpm} rpm at {rate_rpm_per_s} rpm/s)"
                ));
            }
            run
        }
        TraceSpec::Run(run) => run,
        TraceSpec::MatchRecording => match recording {
            Some(r) => r.regime,
            None => return Err("no recording is open: File > Open recording…".into()),
        },
    };
    Ok(kind)
}

/// Output rate, Hz: 4096, or the next power of two above 2.5 × order 12 at the top speed;
/// at least a recording's own rate (to 20480 Hz).
fn rate_hz(kind: Run, recording: Option<&RecordingView>) -> f64 {
    let [from_rpm, to_rpm] = kind.speeds_rpm();
    let top = from_rpm.max(to_rpm);
    let needed = (2.5 * 12.0 * top / 60.0).max(4096.0);
    let mut rate = needed.log2().ceil().exp2();
    if let Some(r) = recording {
        let t = &r.recording.time_s;
        let own = (t.len() - 1) as f64 / (t[t.len() - 1] - t[0]);
        rate = rate.max(own.min(20480.0));
    }
    rate
}

/// Runs the time part of request `generation`.
#[allow(clippy::too_many_arguments)]
pub fn run(
    generation: u64,
    model: &Model,
    system: &System,
    spec: &TraceSpec,
    recording: Option<&RecordingView>,
    visible_nodes: &[String],
    stale: &dyn Fn() -> bool,
    send: &dyn Fn(SimResult),
) {
    let error = |e: String| {
        send(SimResult::new(
            generation,
            Payload::Error(PanelError {
                panel: "trace",
                message: e,
            }),
        ))
    };
    let kind = match resolve(spec, recording) {
        Ok(k) => k,
        Err(e) => return error(e),
    };
    let load = recording.map_or(1.0, |r| r.recording.meta.load);
    let options = RunOptions {
        load,
        rate_hz: rate_hz(kind, recording),
        max_settle_s: 30.0,
        ..RunOptions::default()
    };
    let label = describe(kind);
    send(SimResult::new(
        generation,
        Payload::TraceRunning(label.clone()),
    ));
    // The run matching a run-up recording follows its measured mean speed.
    let along = match spec {
        TraceSpec::MatchRecording => recording.and_then(|r| r.measured_speed.clone()),
        TraceSpec::Run(_) => None,
    };
    let mut builder: Option<SeriesBuilder> = None;
    let mut pending = TraceChunk::default();
    let mut last_sent = Instant::now();
    let mut last_progress = -1.0;
    let mut observer = |event: Event| {
        match event {
            Event::Progress(f) => {
                if f - last_progress >= 0.01 || f >= 1.0 {
                    last_progress = f;
                    send(SimResult::new(generation, Payload::Progress(f as f32)));
                }
            }
            Event::Chunk(chunk) => {
                let b = builder.get_or_insert_with(|| {
                    let mut b = SeriesBuilder::new(
                        model,
                        system,
                        kind,
                        load,
                        label.clone(),
                        &chunk,
                        visible_nodes,
                    );
                    b.layout.along = along.clone();
                    send(SimResult::new(
                        generation,
                        Payload::TraceStarted(Arc::new(b.layout.clone())),
                    ));
                    b
                });
                b.push(&chunk, &mut pending);
                if last_sent.elapsed() >= SEND_EVERY {
                    last_sent = Instant::now();
                    let chunk = std::mem::take(&mut pending);
                    send(SimResult::new(
                        generation,
                        Payload::TraceChunk(Arc::new(chunk)),
                    ));
                }
            }
        }
        !stale()
    };
    let simulated = match along.clone() {
        Some(m) => simulate_observed_along(model, kind, options, m, 0.0, &mut observer),
        None => simulate_observed(model, kind, options, &mut observer),
    };
    let sim = match simulated {
        Ok(sim) => sim,
        Err(TransientError::Cancelled { .. }) => {
            return send(SimResult::new(generation, Payload::Cancelled));
        }
        Err(e) => return error(format!("{}: {e}", label)),
    };
    if !pending.groups.is_empty() {
        send(SimResult::new(
            generation,
            Payload::TraceChunk(Arc::new(pending)),
        ));
    }
    let to_analyse = to_recording(&sim, kind, load, model.strokes(), &model.name);
    send(SimResult::new(generation, Payload::Trace(Arc::new(sim))));
    if stale() {
        return;
    }
    match analyse_with(&to_analyse, &analysis_options(model, system)) {
        Ok(analysis) => {
            let max_hz = recording
                .map(|r| max_frequency_hz(&r.analysis))
                .unwrap_or_else(|| max_frequency_hz(&analysis));
            let overlay_shift_s = recording.map_or(0.0, |r| cycle_shift_s(&analysis, r));
            send(SimResult::new(
                generation,
                Payload::TraceAnalysis(Arc::new(RunAnalysis {
                    spectrograms: SpectrogramSet::new(&analysis, 0.0, max_hz).map(Arc::new),
                    analysis,
                    overlay_shift_s,
                })),
            ));
        }
        Err(e) => error(format!("analysis of the {label}: {e}")),
    }
}

/// The time shift that puts a steady recording's averaged cycle of its reference
/// station in phase with the simulation's (circular cross-correlation of the two cycles,
/// both sampled at the same angles), s in (−cycle/2, cycle/2]; 0 for run-ups.
fn cycle_shift_s(sim: &Analysis, recording: &RecordingView) -> f64 {
    let measured = &recording.analysis;
    let station = |a: &Analysis| {
        a.stations
            .iter()
            .find(|s| s.name == measured.reference)
            .map(|s| (s.average_cycle_rpm.clone(), s.mean_speed_rpm))
    };
    let (Some((s, speed_rpm)), Some((m, _))) = (station(sim), station(measured)) else {
        return 0.0;
    };
    if recording.regime.is_ramp() {
        return 0.0;
    }
    let n = s.len();
    if n == 0 || m.len() != n || speed_rpm <= 0.0 {
        return 0.0;
    }
    let centred = |v: &[f64]| {
        let mean = v.iter().sum::<f64>() / n as f64;
        v.iter().map(|x| x - mean).collect::<Vec<f64>>()
    };
    let (s, m) = (centred(&s), centred(&m));
    let best = (0..n)
        .map(|k| (k, (0..n).map(|i| s[i] * m[(i + k) % n]).sum::<f64>()))
        .fold((0, f64::MIN), |b, x| if x.1 > b.1 { x } else { b })
        .0;
    let signed = if best > n / 2 {
        best as f64 - n as f64
    } else {
        best as f64
    };
    let cycle_s = sim.cycle_rev * 60.0 / speed_rpm;
    -signed / n as f64 * cycle_s
}
