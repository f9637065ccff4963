//! The time run as the GUI holds it: what runs ([`TraceLayout`], sent once when the run
//! starts recording), the samples in plot-ready groups ([`TraceChunk`], a few times per
//! second), accumulated in [`LiveTrace`].

use std::sync::Arc;
use torsim::recording::Run;
use torsim::transient::MeasuredSpeed;

/// What the GUI asks the worker to run in time.
#[derive(Debug, Clone, PartialEq)]
pub enum TraceSpec {
    /// A steady run, or a linear run-up (or run-down) of a finite duration > 0 between two
    /// different speeds.
    Run(Run),
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
    pub kind: Run,
    /// The measured mean speed a run-up follows, when it matches a recording (see
    /// [`super::recording_job::RecordingView::measured_speed`]); `None`: the line.
    pub along: Option<Arc<MeasuredSpeed>>,
    /// Engine load 0..1.
    pub load: f64,
    /// Reference node name.
    pub reference: String,
    /// Reference revolutions per working cycle (2 for a 4-stroke engine).
    pub cycle_rev: f64,
    /// Mean speed of each node over the reference's (magnitude), model order.
    pub speed_ratio: Vec<f64>,
    /// The groups, each with its kind.
    pub groups: Vec<(GroupKind, GroupLayout)>,
}

impl TraceLayout {
    /// Imposed mean speed of the reference at `t_s` from the start of recording, rpm.
    pub fn speed_at(&self, t_s: f64) -> f64 {
        match &self.along {
            Some(m) if self.kind.is_ramp() => m.speed_rpm(t_s),
            _ => profile_rpm(self.kind, t_s),
        }
    }

    /// The time range a plot opens on and a double-click returns to, s: the whole run.
    pub fn opening_range_s(&self) -> [f64; 2] {
        // Issue 16: a steady run opened on its first 6 cycles (0.48 s of 2 s), and a
        // double-click went back there; every run now opens, and resets, on all of it.
        [0.0, self.kind.duration_s]
    }

    /// True for a run-up or run-down.
    pub fn is_ramp(&self) -> bool {
        self.kind.is_ramp()
    }
}

/// Mean speed of the reference in a run of `kind` at `t_s` from the start of recording,
/// rpm.
pub fn profile_rpm(kind: Run, t_s: f64) -> f64 {
    let [from_rpm, to_rpm] = kind.speeds_rpm();
    if kind.is_ramp() && kind.duration_s > 0.0 {
        from_rpm + (to_rpm - from_rpm) * (t_s / kind.duration_s).clamp(0.0, 1.0)
    } else {
        from_rpm
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
