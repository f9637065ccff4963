//! From the truth and a plan to bench recordings: each planned run simulated with the
//! nonlinear time domain ([`crate::transient::simulate`]) a little longer than recorded
//! (the margins feed the filter and the first and last pulses), then measured at every
//! station by [`super::ias`] with the noise, wobble and artifacts of a [`Measurement`].

use super::SynthError;
use super::fir::Decimator;
use super::ias::{Chain, measure};
use super::measurement::Measurement;
use super::plan::{Plan, PlannedRun};
use super::shaft_angle::ShaftAngle;
use super::wobble::Wobble;
use crate::effects::Truth;
use crate::effects::rng::Rng;
use crate::effects::sensor::{SensorArtifact, line_angles};
use crate::recording::{Channel, ChannelKind, Recording, RecordingMeta, Run, RunShape, Sensor};
use crate::transient::{RunOptions, simulate};
use std::f64::consts::TAU;

/// One generated recording and the stem of its files.
#[derive(Debug, Clone, PartialEq)]
pub struct SynthRecording {
    /// File stem (`<stem>.csv`, `<stem>.toml`).
    pub file: String,
    /// The recording, as a bench would have written it.
    pub recording: Recording,
}

/// Generates every recording of `plan` from `truth`; `progress` gets the fraction done
/// (0–1) and cancels by returning false.
pub fn generate(
    truth: &Truth,
    plan: &Plan,
    m: &Measurement,
    progress: &mut dyn FnMut(f64) -> bool,
) -> Result<Vec<SynthRecording>, SynthError> {
    let reference = super::measurement::check(m, truth, plan)?;
    let weights: Vec<f64> = plan.runs.iter().map(|r| r.duration_s + 1.0).collect();
    let total: f64 = weights.iter().sum();
    let mut done = 0.0;
    let mut out = Vec::with_capacity(plan.runs.len());
    for (i, run) in plan.runs.iter().enumerate() {
        let w = weights[i] / total;
        let mut inner = |f: f64| progress(done + w * f);
        out.push(generate_run(truth, run, i, m, &reference, &mut inner)?);
        done += w;
    }
    progress(1.0);
    Ok(out)
}

/// Decimation factor from the output rate to the fine grid: at least 4, and the fine grid
/// at least 8192 Hz.
fn fine_factor(rate_hz: f64) -> usize {
    ((8192.0 / rate_hz).ceil() as usize).max(4)
}

/// Simulates and measures one planned run.
fn generate_run(
    truth: &Truth,
    run: &PlannedRun,
    index: usize,
    m: &Measurement,
    reference: &str,
    progress: &mut dyn FnMut(f64) -> bool,
) -> Result<SynthRecording, SynthError> {
    let model = &truth.model;
    let rate = run.rate_hz.unwrap_or(m.rate_hz);
    let fail = |message: String| SynthError::Run {
        label: run.label.clone(),
        message,
    };
    let samples = (run.duration_s * rate).round() as usize;
    if samples < 16 {
        return Err(fail(format!(
            "{} s at {rate} Hz is too short",
            run.duration_s
        )));
    }
    let seed = truth.seed;
    let wobble = Wobble::new(
        m.wobble_pct,
        m.wobble_period_s,
        &mut Rng::stream(seed, "wobble", index as u64),
    );
    let decimator = Decimator::new(fine_factor(rate));
    let sim_rate = (2.0 * rate).max(8192.0);
    let [from_rpm, to_rpm] = run.shape.speeds_rpm();
    let lo_rpm = from_rpm.min(to_rpm);
    let system = crate::physics::System::new(model, crate::physics::OperatingPoint::default())
        .map_err(|e| fail(e.to_string()))?;
    let slowest_rev_s = m
        .stations
        .iter()
        .filter_map(|s| {
            let i = model.node_index(&s.node)?;
            Some(system.speed_ratio[i].abs() * lo_rpm / 60.0 * f64::from(s.lines_per_rev))
        })
        .fold(f64::INFINITY, f64::min);
    let margin_s = decimator.half as f64 / (rate * decimator.factor as f64)
        + 8.0 / slowest_rev_s
        + 2.0 * wobble.max_shift_s()
        + 16.0 / sim_rate
        + 0.02;
    let sim_duration = run.duration_s + 2.0 * margin_s;
    let kind = match run.shape {
        RunShape::Steady { speed_rpm } | RunShape::LongRun { speed_rpm } => {
            Run::steady(speed_rpm, sim_duration)
        }
        RunShape::Ramp { from_rpm, to_rpm } => {
            let slope = (to_rpm - from_rpm) / run.duration_s;
            let from = from_rpm - slope * margin_s;
            if from <= 0.0 || lo_rpm <= 0.0 {
                return Err(fail("the run-up starts at or below 0 rpm".into()));
            }
            Run::ramp(from, to_rpm + slope * margin_s, sim_duration)
        }
    };
    // The bench holds every run at its start speed before it records, and a warming
    // stage warms meanwhile: the rule the diagnosis' forward model assumes.
    let options = RunOptions {
        load: run.load,
        rate_hz: sim_rate,
        hold_s: crate::diagnose::settling::bench_hold_s(model, run.load),
        ..RunOptions::default()
    };
    let sim = simulate(model, kind, options, &mut |f| progress(0.9 * f)).map_err(|e| {
        SynthError::Simulation {
            label: run.label.clone(),
            source: e,
        }
    })?;
    let mut channels = Vec::new();
    let mut meta = RecordingMeta::new(run.shape.sidecar_kind(), reference);
    for (k, station) in m.stations.iter().enumerate() {
        let node = sim
            .node_names
            .iter()
            .position(|n| *n == station.node)
            .ok_or_else(|| fail(format!("no node `{}` in the simulation", station.node)))?;
        let speeds: Vec<f64> = sim.speed_rpm[node].iter().map(|n| n * TAU / 60.0).collect();
        let shaft = ShaftAngle::new(0.0, 1.0 / sim_rate, speeds);
        let artifacts: Vec<&SensorArtifact> = m
            .artifacts
            .iter()
            .chain(&truth.artifact)
            .filter(|a| a.station() == station.node)
            .collect();
        let lines = line_angles(station.lines_per_rev, &artifacts);
        let offset = Rng::stream(seed, "sensor_phase", k as u64).uniform_in(0.0, TAU);
        let chain = Chain {
            lines: &lines,
            offset_rad: offset,
            wobble: &wobble,
            origin_s: margin_s,
            jitter_s: m.jitter_ns * 1e-9,
            rate_hz: rate,
            samples,
            decimator: &decimator,
        };
        let stream = (index as u64) << 16 | k as u64;
        let mut values = measure(&shaft, &chain, &mut Rng::stream(seed, "jitter", stream))
            .map_err(|e| fail(format!("station `{}`: {e}", station.node)))?;
        let mut noise = Rng::stream(seed, "noise", stream);
        for v in &mut values {
            *v += m.noise_rpm * noise.normal();
            if m.resolution_rpm > 0.0 {
                // Divide by the (exact) inverse so that 0.01 rpm gives the double nearest
                // to the decimal, which prints short.
                let per_rpm = (1.0 / m.resolution_rpm).round().max(1.0);
                *v = if (per_rpm * m.resolution_rpm - 1.0).abs() < 1e-12 {
                    (*v * per_rpm).round() / per_rpm
                } else {
                    (*v / m.resolution_rpm).round() * m.resolution_rpm
                };
            }
        }
        channels.push(Channel::new(
            ChannelKind::SpeedRpm {
                node: station.node.clone(),
            },
            values,
        ));
        meta.sensors.insert(
            station.node.clone(),
            Sensor {
                kind: station.kind.clone(),
                lines_per_rev: Some(station.lines_per_rev),
            },
        );
    }
    if !run.shape.is_ramp() {
        meta.speed_rpm = Some(from_rpm);
    }
    meta.load = run.load;
    meta.strokes = model.strokes();
    meta.label = Some(run.label.clone());
    progress(1.0);
    Ok(SynthRecording {
        file: run.file.clone(),
        recording: Recording {
            time_s: super::measurement::time_stamps(samples, rate),
            channels,
            meta,
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fine_grid_is_at_least_four_times_and_8192_hz() {
        assert_eq!(fine_factor(2048.0), 4);
        assert_eq!(fine_factor(1000.0), 9);
        assert_eq!(fine_factor(10240.0), 4);
    }
}
