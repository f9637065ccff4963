//! What a recording holds (`spec/recording-format.md`): samples in time per column, and
//! the sidecar's description of the run.

use std::collections::BTreeMap;

/// A bench or simulated recording: time stamps, one channel per CSV column after
/// `time_s`, and the sidecar.
#[derive(Debug, Clone, PartialEq)]
pub struct Recording {
    /// Sample times, s, strictly increasing (the CSV's `time_s`).
    pub time_s: Vec<f64>,
    /// The other columns, in CSV order; each has `time_s.len()` samples.
    pub channels: Vec<Channel>,
    /// The sidecar.
    pub meta: RecordingMeta,
}

/// One CSV column after `time_s`.
#[derive(Debug, Clone, PartialEq)]
pub struct Channel {
    /// The column name as in the CSV header, e.g. `engine_rpm`.
    pub column: String,
    /// What the column measures, parsed from its name.
    pub kind: ChannelKind,
    /// The samples, in the unit of `kind`.
    pub values: Vec<f64>,
}

/// What a column measures, from its name.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ChannelKind {
    /// `<node>_rpm`: instantaneous angular speed of a node in its own shaft, rev/min.
    SpeedRpm {
        /// Model node.
        node: String,
    },
    /// `<node>_rad`: angle of a node, rad.
    AngleRad {
        /// Model node.
        node: String,
    },
    /// `torque_<connection>_nm`: torque in a connection, N·m.
    TorqueNm {
        /// Model connection.
        connection: String,
    },
}

impl ChannelKind {
    /// Parses a column name; `None` when it has none of the three forms.
    pub fn from_column(column: &str) -> Option<Self> {
        let nonempty = |s: &str| (!s.is_empty()).then(|| s.to_string());
        if let Some(rest) = column.strip_prefix("torque_")
            && let Some(connection) = rest.strip_suffix("_nm")
        {
            return nonempty(connection).map(|connection| Self::TorqueNm { connection });
        }
        if let Some(node) = column.strip_suffix("_rpm") {
            return nonempty(node).map(|node| Self::SpeedRpm { node });
        }
        if let Some(node) = column.strip_suffix("_rad") {
            return nonempty(node).map(|node| Self::AngleRad { node });
        }
        None
    }

    /// The column name of this kind: `<node>_rpm`, `<node>_rad`, `torque_<connection>_nm`.
    pub fn column(&self) -> String {
        match self {
            Self::SpeedRpm { node } => format!("{node}_rpm"),
            Self::AngleRad { node } => format!("{node}_rad"),
            Self::TorqueNm { connection } => format!("torque_{connection}_nm"),
        }
    }

    /// The node of a speed or angle column.
    pub fn node(&self) -> Option<&str> {
        match self {
            Self::SpeedRpm { node } | Self::AngleRad { node } => Some(node),
            Self::TorqueNm { .. } => None,
        }
    }
}

impl Channel {
    /// A channel whose column name follows from its kind.
    pub fn new(kind: ChannelKind, values: Vec<f64>) -> Self {
        Self {
            column: kind.column(),
            kind,
            values,
        }
    }
}

/// Steady regime or run-up (the sidecar's `kind`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RunKind {
    /// `"steady"`: constant mean speed.
    Steady,
    /// `"run-up"`: the speed sweeps up or down.
    RunUp,
}

impl RunKind {
    /// The sidecar spelling: `"steady"` or `"run-up"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Steady => "steady",
            Self::RunUp => "run-up",
        }
    }

    /// Parses the sidecar spelling.
    pub fn parse(text: &str) -> Option<Self> {
        match text {
            "steady" => Some(Self::Steady),
            "run-up" => Some(Self::RunUp),
            _ => None,
        }
    }
}

/// How a station's IAS was measured (`[sensors.<node>]`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Sensor {
    /// E.g. `"zebra"`, `"encoder"`, `"simulated"`.
    pub kind: String,
    /// Lines (pulses) per revolution of a zebra tape or encoder.
    pub lines_per_rev: Option<u32>,
}

/// The sidecar: what the samples are.
#[derive(Debug, Clone, PartialEq)]
pub struct RecordingMeta {
    /// Steady regime or run-up.
    pub kind: RunKind,
    /// The node whose speed defines engine orders (it must have a `<reference>_rpm`
    /// column).
    pub reference: String,
    /// Nominal mean speed of the reference for a steady run, rpm.
    pub speed_rpm: Option<f64>,
    /// Engine load 0..1 (default 1).
    pub load: f64,
    /// Rubber temperature at the start, °C, if known.
    pub temperature_c: Option<f64>,
    /// E.g. `"Regime A"`.
    pub label: Option<String>,
    /// Engine strokes, 4 (default: orders in steps of 0.5, a cycle is 2 revolutions) or 2
    /// (orders in steps of 1, a cycle is 1 revolution). Extension key `strokes`.
    pub strokes: u32,
    /// How each station was measured, by node.
    pub sensors: BTreeMap<String, Sensor>,
}

impl RecordingMeta {
    /// A sidecar with the defaults: load 1, 4 strokes, nothing else known.
    pub fn new(kind: RunKind, reference: impl Into<String>) -> Self {
        Self {
            kind,
            reference: reference.into(),
            speed_rpm: None,
            load: 1.0,
            temperature_c: None,
            label: None,
            strokes: 4,
            sensors: BTreeMap::new(),
        }
    }

    /// Revolutions of the reference shaft per working cycle: `strokes / 2`.
    pub fn cycle_rev(&self) -> f64 {
        f64::from(self.strokes) / 2.0
    }
}

impl Recording {
    /// The channel with this column name.
    pub fn channel(&self, column: &str) -> Option<&Channel> {
        self.channels.iter().find(|c| c.column == column)
    }

    /// The speed (rpm) of a node, if recorded.
    pub fn speed_rpm(&self, node: &str) -> Option<&[f64]> {
        self.channels.iter().find_map(|c| match &c.kind {
            ChannelKind::SpeedRpm { node: n } if n == node => Some(c.values.as_slice()),
            _ => None,
        })
    }

    /// The speed stations in column order: (node, speed in rpm).
    pub fn speed_stations(&self) -> Vec<(&str, &[f64])> {
        self.channels
            .iter()
            .filter_map(|c| match &c.kind {
                ChannelKind::SpeedRpm { node } => Some((node.as_str(), c.values.as_slice())),
                _ => None,
            })
            .collect()
    }

    /// Revolutions of the reference shaft over the recording (trapezoid rule), or `None`
    /// when it has no speed column.
    pub fn reference_revolutions(&self) -> Option<f64> {
        let n = self.speed_rpm(&self.meta.reference)?;
        Some(revolutions(&self.time_s, n))
    }
}

/// Revolutions turned by a shaft with speed `speed_rpm` at `time_s` (trapezoid rule).
pub fn revolutions(time_s: &[f64], speed_rpm: &[f64]) -> f64 {
    time_s
        .windows(2)
        .zip(speed_rpm.windows(2))
        .map(|(t, n)| (t[1] - t[0]) * (n[0] + n[1]) / 120.0)
        .sum()
}
