//! On the simulation thread: the library's chunks of a run ([`torsim::transient::Chunk`])
//! turned into the plot groups of [`TraceLayout`] — IAS per node, relative speed across
//! each rubber stage (seed 001's `n_rel = n_a − n_b`, referred to `a`'s shaft), torque per
//! connection, power loss per rubber stage averaged over each working cycle (the
//! instantaneous loss swings with every firing), and rubber temperatures.

use crate::gui::session::trace_data::{
    GroupKind, GroupLayout, GroupSamples, TraceChunk, TraceLayout,
};
use torsim::model::{ConnectionKind, GROUND, Model};
use torsim::physics::System;
use torsim::recording::Run;
use torsim::transient::Chunk;

/// Builds the groups chunk by chunk.
pub struct SeriesBuilder {
    /// The layout, fixed by the first chunk.
    pub layout: TraceLayout,
    /// Relative speeds: (node a, node b, speed of a's shaft over b's).
    pairs: Vec<(usize, usize, f64)>,
    /// Elements (indices into the chunk's power series) whose loss is shown.
    lossy: Vec<usize>,
    reference: usize,
    cycle_rev: f64,
    /// The working cycle being averaged: revolutions, time sum, power sums, samples.
    cycle: (f64, f64, Vec<f64>, usize),
    last_time_s: Option<f64>,
}

/// The name of the relative speed across rubber stage `connection` from node `a` to `b`.
pub fn relative_name(connection: &str, a: &str, b: &str) -> String {
    format!("{connection} ({a} - {b})")
}

/// Is connection `c` of `model` a rubber stage?
fn is_rubber(model: &Model, c: usize) -> bool {
    model
        .connections
        .get(c)
        .is_some_and(|c| matches!(c.kind, ConnectionKind::Rubber(_)))
}

impl SeriesBuilder {
    /// The layout of a run of `model` whose first chunk is `first`; `visible_nodes`
    /// are the nodes shown at first (a recording's stations), the others listed, hidden.
    pub fn new(
        model: &Model,
        system: &System,
        kind: Run,
        load: f64,
        label: String,
        first: &Chunk,
        visible_nodes: &[String],
    ) -> Self {
        let names = &system.node_names;
        let node = |name: &str| names.iter().position(|n| n == name);
        let mut groups = Vec::new();
        let all = |n: usize| vec![true; n];
        // Without measured stations: the reference, both sides of every rubber stage, and
        // the ends of the driveline (a crank's throws add little but clutter).
        let mut stations: Vec<&str> = visible_nodes.iter().map(String::as_str).collect();
        if stations.is_empty() {
            stations.push(&names[system.reference_node]);
            for c in &model.connections {
                if matches!(c.kind, ConnectionKind::Rubber(_)) {
                    stations.extend([c.from.as_str(), c.to.as_str()]);
                }
            }
            stations.extend(names.first().map(String::as_str));
            stations.extend(names.last().map(String::as_str));
        }
        let visible = names
            .iter()
            .map(|n| stations.contains(&n.as_str()))
            .collect();
        groups.push((
            GroupKind::Speed,
            GroupLayout {
                title: "IAS".into(),
                axis: "IAS [rpm] (own shaft)".into(),
                names: names.clone(),
                visible,
            },
        ));
        let mut pairs = Vec::new();
        let mut pair_names = Vec::new();
        for c in &model.connections {
            if let (ConnectionKind::Rubber(_), Some(a), Some(b)) =
                (&c.kind, node(&c.from), node(&c.to))
                && c.from != GROUND
                && c.to != GROUND
            {
                let ratio = system.speed_ratio[a].abs() / system.speed_ratio[b].abs();
                pairs.push((a, b, ratio));
                pair_names.push(relative_name(&c.name, &c.from, &c.to));
            }
        }
        if !pairs.is_empty() {
            groups.push((
                GroupKind::RelativeSpeed,
                GroupLayout {
                    title: "relative speed".into(),
                    axis: "n_rel [rpm]".into(),
                    visible: all(pair_names.len()),
                    names: pair_names,
                },
            ));
        }
        let connection = |c: usize| system.connection_names[c].clone();
        let any_rubber = first.torque_nm.iter().any(|(c, _)| is_rubber(model, *c));
        groups.push((
            GroupKind::Torque,
            GroupLayout {
                title: "torque".into(),
                axis: "torque [N·m]".into(),
                names: first
                    .torque_nm
                    .iter()
                    .map(|(c, _)| connection(*c))
                    .collect(),
                visible: first
                    .torque_nm
                    .iter()
                    .map(|(c, _)| !any_rubber || is_rubber(model, *c))
                    .collect(),
            },
        ));
        let lossy: Vec<usize> = (0..first.power_w.len())
            .filter(|&i| !any_rubber || is_rubber(model, first.power_w[i].0))
            .collect();
        groups.push((
            GroupKind::PowerLoss,
            GroupLayout {
                title: "power loss".into(),
                axis: "power loss [W]".into(),
                names: lossy
                    .iter()
                    .map(|&i| connection(first.power_w[i].0))
                    .collect(),
                visible: all(lossy.len()),
            },
        ));
        if !first.temperature_c.is_empty() {
            groups.push((
                GroupKind::Temperature,
                GroupLayout {
                    title: "rubber temperature".into(),
                    axis: "rubber [°C]".into(),
                    names: first
                        .temperature_c
                        .iter()
                        .map(|(c, _)| connection(*c))
                        .collect(),
                    visible: all(first.temperature_c.len()),
                },
            ));
        }
        let layout = TraceLayout {
            label,
            kind,
            along: None,
            load,
            reference: names[system.reference_node].clone(),
            cycle_rev: f64::from(model.strokes()) / 2.0,
            speed_ratio: system.speed_ratio.iter().map(|r| r.abs()).collect(),
            groups,
        };
        Self {
            layout,
            pairs,
            cycle: (0.0, 0.0, vec![0.0; lossy.len()], 0),
            lossy,
            reference: system.reference_node,
            cycle_rev: f64::from(model.strokes()) / 2.0,
            last_time_s: None,
        }
    }

    /// The groups of one library chunk, appended to `out`.
    pub fn push(&mut self, chunk: &Chunk, out: &mut TraceChunk) {
        out.groups
            .resize(self.layout.groups.len(), GroupSamples::default());
        out.done = (chunk.first_sample + chunk.len()) as f64 / chunk.total_samples.max(1) as f64;
        let mut power = GroupSamples::default();
        self.cycle_power(chunk, &mut power);
        for ((kind, _), group) in self.layout.groups.iter().zip(&mut out.groups) {
            let values: Vec<Vec<f64>> = match kind {
                GroupKind::Speed => chunk.speed_rpm.clone(),
                GroupKind::RelativeSpeed => self
                    .pairs
                    .iter()
                    .map(|&(a, b, r)| {
                        let (va, vb) = (&chunk.speed_rpm[a], &chunk.speed_rpm[b]);
                        va.iter().zip(vb).map(|(x, y)| x - r * y).collect()
                    })
                    .collect(),
                GroupKind::Torque => chunk.torque_nm.iter().map(|(_, v)| v.clone()).collect(),
                GroupKind::Temperature => {
                    chunk.temperature_c.iter().map(|(_, v)| v.clone()).collect()
                }
                GroupKind::PowerLoss => {
                    group.time_s.extend_from_slice(&power.time_s);
                    append(&mut group.values, std::mem::take(&mut power.values));
                    continue;
                }
            };
            group.time_s.extend_from_slice(&chunk.time_s);
            append(&mut group.values, values);
        }
    }

    /// Power loss averaged over each whole working cycle of the reference shaft, at the
    /// cycle's mean time.
    fn cycle_power(&mut self, chunk: &Chunk, out: &mut GroupSamples) {
        out.values = vec![Vec::new(); self.lossy.len()];
        let reference = &chunk.speed_rpm[self.reference];
        for (k, &t) in chunk.time_s.iter().enumerate() {
            let dt = self.last_time_s.map_or(0.0, |last| t - last);
            self.last_time_s = Some(t);
            let (revs, time_sum, sums, count) = &mut self.cycle;
            *revs += reference[k].abs() / 60.0 * dt;
            *time_sum += t;
            *count += 1;
            for (s, &i) in sums.iter_mut().zip(&self.lossy) {
                *s += chunk.power_w[i].1[k];
            }
            if *revs >= self.cycle_rev {
                let n = *count as f64;
                out.time_s.push(*time_sum / n);
                for (series, s) in out.values.iter_mut().zip(sums.iter_mut()) {
                    series.push(*s / n);
                    *s = 0.0;
                }
                *revs -= self.cycle_rev;
                (*time_sum, *count) = (0.0, 0);
            }
        }
    }
}

/// Appends `more[i]` to `series[i]`.
fn append(series: &mut Vec<Vec<f64>>, more: Vec<Vec<f64>>) {
    series.resize(more.len(), Vec::new());
    for (a, b) in series.iter_mut().zip(more) {
        a.extend(b);
    }
}
