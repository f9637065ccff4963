//! What a sensor artifact at a geared station does to the engine orders.
//!
//! A tape joint or a pitch error sits at integer orders of its own shaft ([`super::sensor`]).
//! At a station turning at a ratio `r` of the reference that is no multiple of ½ (a gear of
//! 3.11), shaft order 1 is engine order 3.11: no analysed order, yet it leaks into the
//! engine orders near it through the order analysis (the synchronous average of a steady
//! regime, the STFT of a run-up), and a closed form would have to copy the analysis. So
//! the analysis is asked: each recording is rebuilt with, at every station other than its
//! reference, the station's speed trend plus the artifact of unit size on the station's
//! own angle, and analysed exactly as the measured recordings are ([`super::observe`]).
//! The amplitude it finds at each observation is the artifact's per unit size (it is
//! linear in its size while the size is small); the diagnosis adds it in power like the
//! closed form. At the reference station the closed form stands (its shaft orders are
//! engine orders).

use super::LabelledRecording;
use super::candidates::Candidate;
use super::observe::{Observed, observe};
use super::sensor::{ArtifactForm, closed_form, lines_of, sinc};
use crate::effects::Effect;
use crate::recording::ChannelKind;
use std::collections::HashMap;
use std::f64::consts::TAU;
use std::sync::Arc;

/// Lines per revolution assumed when a sidecar does not say (as [`super::sensor`]).
const DEFAULT_LINES: u32 = 60;

/// The amplitude per unit size of one form of artifact at one station, at each
/// observation of the campaign (rpm; zero at other stations).
#[derive(Debug, Clone, PartialEq)]
pub struct UnitGains {
    /// Node of the station.
    pub station: String,
    /// The form.
    pub form: ArtifactForm,
    /// Per observation, in the order of [`Observed::observations`].
    pub gains: Arc<Vec<f64>>,
}

/// Least-squares line `a + b·t` through `values` at `t`: the speed without its orders.
fn trend(t: &[f64], values: &[f64]) -> Vec<f64> {
    let n = t.len().max(1) as f64;
    let (mt, mv) = (t.iter().sum::<f64>() / n, values.iter().sum::<f64>() / n);
    let (mut stt, mut stv) = (0.0, 0.0);
    for (x, y) in t.iter().zip(values) {
        stt += (x - mt) * (x - mt);
        stv += (x - mt) * (y - mv);
    }
    let b = if stt > 0.0 { stv / stt } else { 0.0 };
    t.iter().map(|x| mv + b * (x - mt)).collect()
}

/// The artifact of unit size on a shaft at angle `theta_rad` turning at `n_rpm` with
/// `lines` lines, engine orders up to `max_order` at ratio `ratio` (rpm).
fn artifact_rpm(form: ArtifactForm, theta_rad: f64, n_rpm: f64, lines: f64, k_max: usize) -> f64 {
    match form {
        ArtifactForm::PitchError => 1f64.to_radians() * n_rpm * sinc(1.0 / lines) * theta_rad.cos(),
        ArtifactForm::TapeJoint => (1..=k_max)
            .map(|k| {
                let k = k as f64;
                2.0 * n_rpm / lines * sinc(k / lines) * (k * theta_rad).cos()
            })
            .sum(),
    }
}

/// The recordings rebuilt with `form`'s artifact of unit size at every station other than
/// each one's reference; `None` when they do not match `observed`'s runs.
fn rebuilt(
    recordings: &[LabelledRecording],
    observed: &Observed,
    form: ArtifactForm,
    max_order: f64,
) -> Option<Vec<LabelledRecording>> {
    if recordings.len() != observed.runs.len() {
        return None;
    }
    let mut out = recordings.to_vec();
    for (i, lr) in out.iter_mut().enumerate() {
        let run = &observed.runs[i];
        let rec = &mut lr.recording;
        let t = rec.time_s.clone();
        let mean_of = |node: &str| -> Option<f64> {
            let c = rec.channels.iter().find(|c| c.kind.node() == Some(node))?;
            Some(c.values.iter().sum::<f64>() / c.values.len().max(1) as f64)
        };
        let reference_rpm = mean_of(&run.reference).filter(|n| n.abs() > 0.0)?;
        for ch in rec.channels.iter_mut() {
            let ChannelKind::SpeedRpm { node } = &ch.kind else {
                continue;
            };
            if *node == run.reference {
                continue;
            }
            let lines = f64::from(lines_of(observed, i, node).unwrap_or(DEFAULT_LINES));
            let base = trend(&t, &ch.values);
            let ratio = (base.iter().sum::<f64>() / base.len().max(1) as f64 / reference_rpm).abs();
            // Shaft orders up to two beyond the highest engine order leak into it.
            let k_max = ((max_order + 2.0) / ratio.max(1e-3))
                .ceil()
                .min(lines / 2.0) as usize;
            let mut theta = 0.0;
            let mut values = Vec::with_capacity(t.len());
            for j in 0..t.len() {
                if j > 0 {
                    let dt = t[j] - t[j - 1];
                    theta += 0.5 * (ch.values[j] + ch.values[j - 1]) / 60.0 * TAU * dt;
                }
                values.push(base[j] + artifact_rpm(form, theta, base[j], lines, k_max));
            }
            ch.values = values;
        }
    }
    Some(out)
}

/// The amplitude per unit size of each form at each station, measured by the campaign's
/// own order analysis where the station is not the run's reference and from the closed
/// form where it is. Empty when the rebuilt recordings cannot be analysed (the closed form
/// then stands everywhere).
pub fn unit_gains(
    recordings: &[LabelledRecording],
    observed: &Observed,
    max_order: f64,
) -> Vec<UnitGains> {
    let mut out = Vec::new();
    let mut stations: Vec<&String> = observed.runs.iter().flat_map(|r| &r.stations).collect();
    stations.sort();
    stations.dedup();
    for form in [ArtifactForm::TapeJoint, ArtifactForm::PitchError] {
        let Some(synthetic) = rebuilt(recordings, observed, form, max_order)
            .and_then(|r| observe(&r, max_order).ok())
        else {
            return Vec::new();
        };
        let key =
            |o: &super::observe::Observation| (o.run, o.part, o.station.clone(), o.order.to_bits());
        let measured: HashMap<_, f64> = synthetic
            .observations
            .iter()
            .map(|o| (key(o), o.measured_rpm))
            .collect();
        for s in &stations {
            let gains: Vec<f64> = observed
                .observations
                .iter()
                .map(|o| {
                    if o.station != **s {
                        return 0.0;
                    }
                    let run = &observed.runs[o.run];
                    match measured.get(&key(o)) {
                        Some(g) if run.reference != **s => *g,
                        _ => {
                            let lines = lines_of(observed, o.run, s).unwrap_or(DEFAULT_LINES);
                            closed_form(form, 1.0, o.order, o.speed_rpm, f64::from(lines))
                        }
                    }
                })
                .collect();
            out.push(UnitGains {
                station: (*s).clone(),
                form,
                gains: Arc::new(gains),
            });
        }
    }
    out
}

/// Gives every sensor-artifact candidate of `list` its station's and form's gains.
pub fn attach(list: &mut [Candidate], gains: &[UnitGains]) {
    for c in list
        .iter_mut()
        .filter(|c| c.effect == Effect::SensorArtifact)
    {
        let station = c.fixed.first().map(|(_, v)| v.as_str());
        let form = c.artifact_form();
        c.artifact_gains = gains
            .iter()
            .find(|g| Some(g.station.as_str()) == station && g.form == form)
            .map(|g| g.gains.clone());
    }
}
