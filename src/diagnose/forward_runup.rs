//! A simulated run-up, in segments: a long run-up is most of a campaign's simulation, so
//! it is cut into consecutive stretches of the measured ramp that run on different
//! threads. Each segment settles at the speed where its lead-in starts and follows the
//! measured mean speed from there ([`crate::transient::MeasuredSpeed`]: a bench that
//! lingers at a resonance is simulated lingering; the straight ramp when the run departs
//! from one by less than [`crate::transient::measured_speed::FOLLOW_ABOVE`]), so lightly
//! damped modes are passed transiently as in one run of the whole ramp
//! ([`crate::transient`]); the lead-in (on the same ramp, long enough for the slowest
//! mode to decay, [`super::settling`]) is discarded. Each segment
//! is analysed like the recording, and its STFT windows go to the speed bins of the
//! measured windows nearest in time; the bins' sums and window counts of all segments add
//! up.

use super::observe::{Observation, Observed, RunShape, analysis_options, slice};
use super::observe_runup::{bin_means, bins};
use crate::model::Model;
use crate::recording::RunKind as RecKind;
use crate::signal::analyse_with;
use crate::transient::{MeasuredSpeed, simulate, simulate_along};
use std::collections::BTreeMap;
use std::sync::Arc;

/// Segments of a run-up at least [`SEGMENT_MIN_S`] long: fixed, not the thread count, so
/// that a diagnosis gives the same numbers on any number of threads (each segment's
/// lead-in is its own settled start, so the segmentation is part of the forward model).
/// Two: the two cores a campaign is timed on (issue 14, item 7).
pub const SEGMENTS: usize = 2;
/// Run-ups shorter than this are one segment, s.
const SEGMENT_MIN_S: f64 = 10.0;
/// Lead-in of the first segment, s, shortened so the ramp starts above a quarter of its
/// first recorded speed: the simulated run settles at the lead-in's start speed (as long
/// as its slowest mode needs, [`super::settling::settle_s`]) and enters the recorded range
/// already sweeping, so its first bins carry no start transient.
const FIRST_LEAD_S: f64 = 0.1;
/// Each segment is analysed this much beyond its stretch on both sides (within what was
/// simulated), s, and keeps only the windows whose centres fall in the stretch: two STFT
/// windows of 0.1 s, so that the windows at a boundary are whole in one segment, as in
/// the recording's own analysis. (Cut exactly at the boundary, the bin holding it lost
/// its edge windows: 6.5 % of the peak off on a 0.7 % resonance's flank.)
const PAD_S: f64 = 0.2;

/// One stretch of a run-up: recorded time `[from_s, to_s)` of run `run`, simulated from
/// `lead_s` before it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// The run.
    pub run: usize,
    /// Start, s from the recording's start.
    pub from_s: f64,
    /// End, s.
    pub to_s: f64,
    /// Lead-in on the same ramp before `from_s`, s, whose windows are discarded.
    pub lead_s: f64,
    /// The model's slowest decay time at the run's load, s (how long it settles).
    pub decay_s: Option<f64>,
}

impl Segment {
    /// Simulated duration, s (to order the work).
    pub fn cost_s(&self) -> f64 {
        self.to_s - self.from_s + self.lead_s
    }
}

/// The lead-in of a segment starting at `from_s` of run-up `run`: the first's
/// [`FIRST_LEAD_S`] (or less, to stay above a quarter of the start speed); a later one's
/// [`super::settling::lead_s`] of the slowest decay time, within the ramp before it.
fn lead_in(observed: &Observed, run: usize, from_s: f64, decay_s: Option<f64>) -> f64 {
    let r = &observed.runs[run];
    let RunShape::Ramp { from_rpm, to_rpm } = r.regime else {
        return 0.0;
    };
    if from_s > 0.0 {
        return super::settling::lead_s(decay_s).min(from_s);
    }
    let slope = ((to_rpm - from_rpm) / r.duration_s.max(1e-9)).abs();
    FIRST_LEAD_S.min(0.75 * from_rpm.min(to_rpm) / slope.max(1e-9))
}

/// The segments of run-up `run`: `count` equal ones when it is longer than
/// [`SEGMENT_MIN_S`], else one; `decay_s` the model's slowest decay time at the run's
/// load ([`super::settling::slowest_decay_s`]).
pub fn segments(
    observed: &Observed,
    run: usize,
    count: usize,
    decay_s: Option<f64>,
) -> Vec<Segment> {
    let duration = observed.runs[run].duration_s;
    let count = if duration < SEGMENT_MIN_S {
        1
    } else {
        count.max(1)
    };
    (0..count)
        .map(|k| {
            let from_s = duration * k as f64 / count as f64;
            Segment {
                run,
                from_s,
                to_s: duration * (k + 1) as f64 / count as f64,
                lead_s: lead_in(observed, run, from_s, decay_s),
                decay_s,
            }
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
    let lead = seg.lead_s;
    let start = seg.from_s - lead;
    let end = seg.to_s + PAD_S;
    let run_spec = crate::recording::Run::ramp(
        from_rpm + slope * start,
        from_rpm + slope * end,
        end - start,
    );
    // Only the first segment starts where nothing before it has settled the start; a later
    // one's lead-in on the ramp does that ([`super::settling::lead_s`]).
    let first = seg.from_s <= 0.0;
    let options = super::forward::run_options(
        model,
        run,
        max_order,
        from_rpm.max(to_rpm),
        seg.decay_s,
        first,
    );
    // Driven along the measured speed where the run departs from a straight ramp
    // (`MeasuredSpeed::departs`): a bench that lingered at a resonance is simulated
    // lingering there.
    let sim = match MeasuredSpeed::to_follow(&run.window_times_s, &run.window_speeds_rpm) {
        Some(m) => simulate_along(model, run_spec, options, Arc::new(m), start, &mut |_| true),
        None => simulate(model, run_spec, options, &mut |_| true),
    }
    .map_err(|e| e.to_string())?;
    let rec = super::forward::station_recording(&sim, run, RecKind::RunUp)?;
    let pad = PAD_S.min(lead);
    let mut rec = slice(&rec, lead - pad, lead + seg.to_s - seg.from_s + PAD_S);
    // Recorded time of the slice's first sample.
    let offset_s = seg.from_s - pad;
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
            let t = t + offset_s;
            if t < seg.from_s || t >= seg.to_s {
                return None;
            }
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

/// The simulated amplitude of run-up observation `o` from its run's bin `sums`, rpm: the
/// mean of its bin (0 where no simulated window fell in it).
pub fn observation_rpm(sums: &BinSums, o: &Observation) -> f64 {
    sums.get(&(o.station.clone(), o.order.to_bits()))
        .and_then(|(sum, count)| bin_means(sum, count).get(o.part).copied())
        .filter(|v| v.is_finite())
        .unwrap_or(0.0)
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
