//! The time run as the GUI holds it: what runs ([`TraceLayout`], sent once when the run
//! starts recording), the samples in plot-ready groups ([`TraceChunk`], a few times per
//! second), accumulated in [`LiveTrace`]; and [`decimate`], which keeps a long run cheap
//! to draw (the min and max of each pixel column).

use std::sync::Arc;
use torsim::transient::RunKind;

/// What the GUI asks the worker to run in time.
#[derive(Debug, Clone, PartialEq)]
pub enum TraceSpec {
    /// A steady run.
    Steady {
        /// Mean speed of the reference, rpm.
        speed_rpm: f64,
        /// Recorded duration, s.
        duration_s: f64,
    },
    /// A linear run-up (or run-down).
    RunUp {
        /// Start speed, rpm.
        from_rpm: f64,
        /// End speed, rpm.
        to_rpm: f64,
        /// Rate, rpm/s (> 0).
        rate_rpm_per_s: f64,
    },
    /// The regime of the open recording (its speed, or its run-up profile).
    MatchRecording,
}

/// One plot's worth of series: a quantity in one unit.
#[derive(Debug, Clone, PartialEq)]
pub struct GroupLayout {
    /// What it is, e.g. `"IAS"`.
    pub title: String,
    /// Axis label with unit, e.g. `"IAS [rpm] (own shaft)"`.
    pub axis: String,
    /// Series names (nodes or connections).
    pub names: Vec<String>,
    /// Per series: shown at first (the others are listed in the legend, hidden).
    pub visible: Vec<bool>,
}

/// The groups of a run, in this order; groups the model lacks are left out.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GroupKind {
    /// IAS of every node, own shaft, rpm.
    Speed,
    /// Relative speed across every rubber stage, rpm.
    RelativeSpeed,
    /// Torque of every connection with an element, N·m.
    Torque,
    /// Power loss per rubber stage, W, averaged over each working cycle.
    PowerLoss,
    /// Rubber temperature, °C.
    Temperature,
}

/// What a run records, announced before its first samples.
#[derive(Debug, Clone, PartialEq)]
pub struct TraceLayout {
    /// For a person: `"run-up 1000 to 2000 rpm in 60 s"`.
    pub label: String,
    /// What is run.
    pub kind: RunKind,
    /// Engine load 0..1.
    pub load: f64,
    /// Reference node name.
    pub reference: String,
    /// Mean speed of each node over the reference's (magnitude), model order.
    pub speed_ratio: Vec<f64>,
    /// The groups, each with its kind.
    pub groups: Vec<(GroupKind, GroupLayout)>,
}

impl TraceLayout {
    /// Recorded duration, s.
    pub fn duration_s(&self) -> f64 {
        match self.kind {
            RunKind::Steady { duration_s, .. } | RunKind::Ramp { duration_s, .. } => duration_s,
        }
    }

    /// Imposed mean speed of the reference at `t_s` from the start of recording, rpm.
    pub fn speed_at(&self, t_s: f64) -> f64 {
        profile_rpm(self.kind, t_s)
    }

    /// True for a run-up or run-down.
    pub fn is_ramp(&self) -> bool {
        matches!(self.kind, RunKind::Ramp { .. })
    }
}

/// Mean speed of the reference in a run of `kind` at `t_s` from the start of recording,
/// rpm.
pub fn profile_rpm(kind: RunKind, t_s: f64) -> f64 {
    match kind {
        RunKind::Steady { speed_rpm, .. } => speed_rpm,
        RunKind::Ramp {
            from_rpm,
            to_rpm,
            duration_s,
        } => from_rpm + (to_rpm - from_rpm) * (t_s / duration_s).clamp(0.0, 1.0),
    }
}

/// The samples of one group: times and one value series per name.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct GroupSamples {
    /// Times from the start of recording, s.
    pub time_s: Vec<f64>,
    /// `[series][sample]`.
    pub values: Vec<Vec<f64>>,
}

impl GroupSamples {
    fn append(&mut self, more: &GroupSamples) {
        self.time_s.extend_from_slice(&more.time_s);
        self.values.resize(more.values.len(), Vec::new());
        for (a, b) in self.values.iter_mut().zip(&more.values) {
            a.extend_from_slice(b);
        }
    }
}

/// Samples since the last chunk, per group of the layout.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TraceChunk {
    /// In the layout's group order.
    pub groups: Vec<GroupSamples>,
    /// Fraction of the recording done, 0–1.
    pub done: f64,
}

/// The running (or finished) time run as received so far.
#[derive(Debug, Clone)]
pub struct LiveTrace {
    /// Generation of the request it belongs to.
    pub generation: u64,
    /// What runs.
    pub layout: Arc<TraceLayout>,
    /// Samples so far, per group of the layout.
    pub groups: Vec<GroupSamples>,
    /// Chunks received.
    pub chunks: usize,
    /// Fraction of the recording received, 0–1.
    pub done: f64,
}

impl LiveTrace {
    /// A run that has announced itself and has no samples yet.
    pub fn new(generation: u64, layout: Arc<TraceLayout>) -> Self {
        let groups = layout
            .groups
            .iter()
            .map(|(_, g)| GroupSamples {
                time_s: Vec::new(),
                values: vec![Vec::new(); g.names.len()],
            })
            .collect();
        Self {
            generation,
            layout,
            groups,
            chunks: 0,
            done: 0.0,
        }
    }

    /// Appends a chunk.
    pub fn append(&mut self, chunk: &TraceChunk) {
        for (g, more) in self.groups.iter_mut().zip(&chunk.groups) {
            g.append(more);
        }
        self.chunks += 1;
        self.done = chunk.done;
    }

    /// The samples and layout of a group kind, if the run has it.
    pub fn group(&self, kind: GroupKind) -> Option<(&GroupLayout, &GroupSamples)> {
        self.layout
            .groups
            .iter()
            .zip(&self.groups)
            .find(|((k, _), _)| *k == kind)
            .map(|((_, l), s)| (l, s))
    }
}

/// At most `2 · buckets` points of `(time_s, values − baseline(time_s))` within
/// `x_range` (plus one point either side): the min and max of each bucket, in time
/// order, so peaks survive at any zoom. Series short enough are returned whole.
pub fn decimate(
    time_s: &[f64],
    values: &[f64],
    baseline: &dyn Fn(f64) -> f64,
    x_range: [f64; 2],
    buckets: usize,
) -> Vec<[f64; 2]> {
    let n = time_s.len().min(values.len());
    let lo = time_s[..n]
        .partition_point(|&t| t < x_range[0])
        .saturating_sub(1);
    let hi = (time_s[..n].partition_point(|&t| t <= x_range[1]) + 1).min(n);
    if hi <= lo {
        return Vec::new();
    }
    let count = hi - lo;
    let buckets = buckets.max(1);
    let value = |i: usize| values[i] - baseline(time_s[i]);
    if count <= 2 * buckets {
        return (lo..hi).map(|i| [time_s[i], value(i)]).collect();
    }
    let mut points = Vec::with_capacity(2 * buckets + 2);
    let per = count.div_ceil(buckets);
    for start in (lo..hi).step_by(per) {
        let end = (start + per).min(hi);
        let (mut i_min, mut v_min, mut i_max, mut v_max) = (start, f64::MAX, start, f64::MIN);
        for i in start..end {
            let v = value(i);
            if v < v_min {
                (i_min, v_min) = (i, v);
            }
            if v > v_max {
                (i_max, v_max) = (i, v);
            }
        }
        let ((a, va), (b, vb)) = if i_min <= i_max {
            ((i_min, v_min), (i_max, v_max))
        } else {
            ((i_max, v_max), (i_min, v_min))
        };
        points.push([time_s[a], va]);
        if b != a {
            points.push([time_s[b], vb]);
        }
    }
    points
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 1 Hz sine sampled at 10 kHz for 10 s, decimated to 500 buckets: the extremes
    /// ±1 survive exactly (they are samples), the points stay in time order and number at
    /// most 1000; a zoomed range keeps its own samples whole.
    #[test]
    fn decimation_keeps_peaks_and_order() {
        let t: Vec<f64> = (0..100_000).map(|i| i as f64 * 1e-4).collect();
        let v: Vec<f64> = t
            .iter()
            .map(|t| (std::f64::consts::TAU * (t + 0.25)).sin())
            .collect();
        let none = |_: f64| 0.0;
        let d = decimate(&t, &v, &none, [0.0, 10.0], 500);
        assert!(d.len() <= 1000, "{}", d.len());
        assert!(d.windows(2).all(|w| w[0][0] < w[1][0]));
        let max = d.iter().fold(f64::MIN, |m, p| m.max(p[1]));
        let min = d.iter().fold(f64::MAX, |m, p| m.min(p[1]));
        assert_eq!(max, v.iter().cloned().fold(f64::MIN, f64::max));
        assert_eq!(min, v.iter().cloned().fold(f64::MAX, f64::min));
        let zoom = decimate(&t, &v, &none, [1.0, 1.01], 500);
        assert!(
            (102..=104).contains(&zoom.len()),
            "the ~101 samples inside and one either side: {}",
            zoom.len()
        );
        assert!(decimate(&t, &v, &none, [20.0, 30.0], 500).len() <= 1);
        // A baseline is subtracted before the extremes are picked: a ramp of 1000 per
        // second under the sine leaves the sine.
        let ramp: Vec<f64> = t.iter().zip(&v).map(|(t, v)| 1000.0 * t + v).collect();
        let d = decimate(&t, &ramp, &|t| 1000.0 * t, [0.0, 10.0], 500);
        let max = d.iter().fold(f64::MIN, |m, p| m.max(p[1]));
        assert!((max - 1.0).abs() < 1e-9, "{max}");
    }
}
