//! A simulated run-up, in segments: a long run-up is most of a campaign's simulation, so
//! it is cut into consecutive stretches of the measured ramp that run on different
//! threads. Each segment starts a little earlier than its stretch (a lead-in on the same
//! ramp, so the start transient has decayed where the stretch begins), is analysed like
//! the recording, and its STFT windows go to the speed bins of the measured windows
//! nearest in time; the bins' sums and window counts of all segments add up.

use super::observe::{Observed, RunShape, analysis_options, slice};
use super::observe_runup::bins;
use crate::model::Model;
use crate::recording::RunKind as RecKind;
use crate::signal::analyse_with;
use crate::transient::{RunKind, simulate};
use std::collections::BTreeMap;

/// Run-ups shorter than this are one segment, s.
const SEGMENT_MIN_S: f64 = 10.0;
/// Lead-in of a segment after the first, s: the lowest mode of a driveline (≥ 20 Hz,
/// ζ ≥ 3 %) decays by e⁻¹ in ≤ 0.27 s, and the switch from the settled start to the
/// ramp excites it only through the ramp's small inertia torque.
const SEGMENT_LEAD_S: f64 = 0.5;
/// Lead-in of the first segment, s, shortened so the ramp starts above a quarter of its
/// first recorded speed: the simulated run enters the recorded range already sweeping.
const FIRST_LEAD_S: f64 = 0.1;

/// One stretch of a run-up: recorded time `[from_s, to_s)` of run `run`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// The run.
    pub run: usize,
    /// Start, s from the recording's start.
    pub from_s: f64,
    /// End, s.
    pub to_s: f64,
}

impl Segment {
    /// Its lead-in, s.
    fn lead_s(&self, observed: &Observed) -> f64 {
        let run = &observed.runs[self.run];
        let RunShape::Ramp { from_rpm, to_rpm } = run.regime else {
            return 0.0;
        };
        if self.from_s > 0.0 {
            return SEGMENT_LEAD_S.min(self.from_s);
        }
        let slope = ((to_rpm - from_rpm) / run.duration_s.max(1e-9)).abs();
        FIRST_LEAD_S.min(0.75 * from_rpm.min(to_rpm) / slope.max(1e-9))
    }

    /// Simulated duration, s (to order the work).
    pub fn cost_s(&self, observed: &Observed) -> f64 {
        self.to_s - self.from_s + self.lead_s(observed)
    }
}

/// The segments of run-up `run`: `count` equal ones when it is longer than
/// [`SEGMENT_MIN_S`], else one.
pub fn segments(observed: &Observed, run: usize, count: usize) -> Vec<Segment> {
    let duration = observed.runs[run].duration_s;
    let count = if duration < SEGMENT_MIN_S {
        1
    } else {
        count.max(1)
    };
    (0..count)
        .map(|k| Segment {
            run,
            from_s: duration * k as f64 / count as f64,
            to_s: duration * (k + 1) as f64 / count as f64,
        })
        .collect()
}

/// Per station and order (`(station, order bits)`), the sum of the simulated track
/// amplitudes and the window count of each speed bin.
pub type BinSums = BTreeMap<(String, u64), (Vec<f64>, Vec<usize>)>;

/// Simulates and analyses one segment of a run-up.
pub fn predict_segment(
    model: &Model,
    observed: &Observed,
    seg: Segment,
    max_order: f64,
) -> Result<BinSums, String> {
    let run = &observed.runs[seg.run];
    let RunShape::Ramp { from_rpm, to_rpm } = run.regime else {
        return Err("not a run-up".into());
    };
    let slope = (to_rpm - from_rpm) / run.duration_s.max(1e-9);
    let lead = seg.lead_s(observed);
    let start = seg.from_s - lead;
    let kind = RunKind::Ramp {
        from_rpm: from_rpm + slope * start,
        to_rpm: from_rpm + slope * seg.to_s,
        duration_s: seg.to_s - start,
    };
    let options = super::forward::run_options(run, max_order, from_rpm.max(to_rpm));
    let sim = simulate(model, kind, options, &mut |_| true).map_err(|e| e.to_string())?;
    let rec = super::forward::station_recording(&sim, run, RecKind::RunUp)?;
    let mut rec = slice(&rec, lead, lead + seg.to_s - seg.from_s);
    let t0 = rec.time_s.first().copied().unwrap_or(0.0);
    rec.time_s.iter_mut().for_each(|t| *t -= t0);
    let a = analyse_with(&rec, &analysis_options(max_order)).map_err(|e| e.to_string())?;
    let stft = a.stft.as_ref().ok_or("no STFT of the simulated run-up")?;
    // Each simulated window takes the bin of the measured window nearest in time.
    let (measured_bins, speeds) = bins(&run.window_speeds_rpm);
    let times = &run.window_times_s;
    let window_bins: Vec<Option<usize>> = stft
        .times_s
        .iter()
        .map(|t| {
            let t = t + seg.from_s;
            let k = times.partition_point(|x| *x < t);
            let near = [k.saturating_sub(1), k.min(times.len().saturating_sub(1))]
                .into_iter()
                .filter(|i| *i < times.len())
                .min_by(|a, b| (times[*a] - t).abs().total_cmp(&(times[*b] - t).abs()))?;
            measured_bins.get(near).copied().flatten()
        })
        .collect();
    let mut out = BinSums::new();
    for s in &a.stations {
        let Some(track) = &s.stft else { continue };
        for (order, amplitudes) in stft.orders.iter().zip(&track.order_tracks_rpm) {
            let (sum, count) = out
                .entry((s.name.clone(), order.to_bits()))
                .or_insert_with(|| (vec![0.0; speeds.len()], vec![0; speeds.len()]));
            for (w, v) in amplitudes.iter().enumerate() {
                if let Some(Some(b)) = window_bins.get(w)
                    && *b < speeds.len()
                    && v.is_finite()
                {
                    sum[*b] += v;
                    count[*b] += 1;
                }
            }
        }
    }
    Ok(out)
}

/// Adds the bin sums of one segment to those of the others.
pub fn accumulate(total: &mut BinSums, part: BinSums) {
    for (key, (sum, count)) in part {
        match total.get_mut(&key) {
            Some((s, c)) => {
                for (a, b) in s.iter_mut().zip(&sum) {
                    *a += b;
                }
                for (a, b) in c.iter_mut().zip(&count) {
                    *a += b;
                }
            }
            None => {
                total.insert(key, (sum, count));
            }
        }
    }
}
