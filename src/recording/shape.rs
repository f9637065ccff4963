//! A run's shape, in one vocabulary for the GUI, the CLI, the synthetic bench and the
//! diagnosis (issue 14, item 1): a steady regime, a long steady run, or a ramp (run-up or
//! run-down), with its speeds — and the one rule that derives it from a recording
//! ([`classify`]).
//!
//! The rule (the thresholds are documented on the constants):
//! - the sidecar's `kind` (`spec/recording-format.md`) decides steady or ramp:
//!   `"run-up"` is a [`RunShape::Ramp`] whichever way the speed goes;
//! - a steady recording of at least [`LONG_RUN_S`] (its duration as [`duration_s`]
//!   measures it) is a [`RunShape::LongRun`], which the diagnosis cuts into time blocks
//!   to see a drift;
//! - the speeds come from the measured reference trace: a steady run's is the sidecar's
//!   `speed_rpm` when given, else the trace's mean; a ramp's are the least-squares line
//!   through the whole trace at the recording's start and end.
//!
//! The sidecar keeps the spec's two spellings ([`RunKind`], `"steady"` and `"run-up"`):
//! a long run is written as `"steady"` ([`RunShape::sidecar_kind`]).

use super::types::{Recording, RunKind};

/// A steady recording at least this long is a long run, s (8 s: four blocks of 2 s, each
/// still long enough for the order analysis at idle; the shipped campaigns' regimes are
/// 4 s and their long runs 30 s). A duration of exactly 8 s is a long run.
pub const LONG_RUN_S: f64 = 8.0;

/// The shape of one run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RunShape {
    /// Constant mean speed, shorter than [`LONG_RUN_S`].
    Steady {
        /// Mean reference speed, rpm.
        speed_rpm: f64,
    },
    /// Constant mean speed for at least [`LONG_RUN_S`] (a drift can show in it).
    LongRun {
        /// Mean reference speed, rpm.
        speed_rpm: f64,
    },
    /// A ramp of the reference speed: a run-up, or a run-down when `to_rpm < from_rpm`.
    Ramp {
        /// Reference speed at the start, rpm.
        from_rpm: f64,
        /// Reference speed at the end, rpm.
        to_rpm: f64,
    },
}

impl RunShape {
    /// For people and reports: `"steady"`, `"long run"` or `"run-up"` (a run-down too, as
    /// the sidecar spells it; the report's `kind` key, `spec/diagnosis.md`).
    pub fn label(&self) -> &'static str {
        match self {
            Self::Steady { .. } => "steady",
            Self::LongRun { .. } => "long run",
            Self::Ramp { .. } => RunKind::RunUp.as_str(),
        }
    }

    /// The sidecar's `kind`: a long run is `"steady"`.
    pub fn sidecar_kind(&self) -> RunKind {
        match self {
            Self::Steady { .. } | Self::LongRun { .. } => RunKind::Steady,
            Self::Ramp { .. } => RunKind::RunUp,
        }
    }

    /// A steady shape: a long run when `duration_s` ≥ [`LONG_RUN_S`].
    pub const fn steady(speed_rpm: f64, duration_s: f64) -> Self {
        if duration_s >= LONG_RUN_S {
            Self::LongRun { speed_rpm }
        } else {
            Self::Steady { speed_rpm }
        }
    }

    /// Whether the speed ramps.
    pub fn is_ramp(&self) -> bool {
        matches!(self, Self::Ramp { .. })
    }

    /// The speeds at start and end, rpm (a steady run's twice).
    pub fn speeds_rpm(&self) -> [f64; 2] {
        match *self {
            Self::Steady { speed_rpm } | Self::LongRun { speed_rpm } => [speed_rpm, speed_rpm],
            Self::Ramp { from_rpm, to_rpm } => [from_rpm, to_rpm],
        }
    }

    /// The same shape with other speeds (`[start, end]`; a steady shape takes the first):
    /// for a caller that measures the speeds more finely but keeps the classification.
    pub fn with_speeds(self, speeds_rpm: [f64; 2]) -> Self {
        match self {
            Self::Steady { .. } => Self::Steady {
                speed_rpm: speeds_rpm[0],
            },
            Self::LongRun { .. } => Self::LongRun {
                speed_rpm: speeds_rpm[0],
            },
            Self::Ramp { .. } => Self::Ramp {
                from_rpm: speeds_rpm[0],
                to_rpm: speeds_rpm[1],
            },
        }
    }

    /// `"steady 3000 rpm"`, `"long run 3000 rpm"`, `"run-up 1000 to 6000 rpm"` or
    /// `"run-down 6000 to 1000 rpm"`.
    pub fn describe(&self) -> String {
        match *self {
            Self::Ramp { from_rpm, to_rpm } => {
                let what = if to_rpm >= from_rpm {
                    "run-up"
                } else {
                    "run-down"
                };
                format!("{what} {from_rpm:.0} to {to_rpm:.0} rpm")
            }
            Self::Steady { speed_rpm } | Self::LongRun { speed_rpm } => {
                format!("{} {speed_rpm:.0} rpm", self.label())
            }
        }
    }
}

/// A recording's duration, s: n samples cover n sampling intervals (as a simulation of
/// that duration records them); 0 with fewer than two samples.
pub fn duration_s(recording: &Recording) -> f64 {
    let t = &recording.time_s;
    match (t.first(), t.last()) {
        (Some(a), Some(b)) if t.len() > 1 => (b - a) * t.len() as f64 / (t.len() - 1) as f64,
        _ => 0.0,
    }
}

/// The one classifier: the shape of `recording` by the rule of this module's docs.
pub fn classify(recording: &Recording) -> RunShape {
    let meta = &recording.meta;
    let reference = recording.speed_rpm(&meta.reference).unwrap_or(&[]);
    match meta.kind {
        RunKind::RunUp => {
            let [from_rpm, to_rpm] = ramp_ends_rpm(&recording.time_s, reference);
            RunShape::Ramp { from_rpm, to_rpm }
        }
        RunKind::Steady => {
            let speed = meta.speed_rpm.unwrap_or_else(|| mean(reference));
            RunShape::steady(speed, duration_s(recording))
        }
    }
}

/// Mean of `v` (0 when empty).
fn mean(v: &[f64]) -> f64 {
    if v.is_empty() {
        0.0
    } else {
        v.iter().sum::<f64>() / v.len() as f64
    }
}

/// The least-squares line through `(t, v)` at the first sample and one sampling interval
/// after the last (the end of the recorded duration, [`duration_s`]), rpm; a flat line at
/// the mean when `t` does not vary, 0 when empty.
fn ramp_ends_rpm(t: &[f64], v: &[f64]) -> [f64; 2] {
    let n = t.len().min(v.len());
    if n == 0 {
        return [0.0, 0.0];
    }
    let (t, v) = (&t[..n], &v[..n]);
    let (tm, vm) = (mean(t), mean(v));
    let (mut sxy, mut sxx) = (0.0, 0.0);
    for (ti, vi) in t.iter().zip(v) {
        sxy += (ti - tm) * (vi - vm);
        sxx += (ti - tm) * (ti - tm);
    }
    let slope = if sxx > 0.0 { sxy / sxx } else { 0.0 };
    let t0 = t[0];
    let end = t0 + (t[n - 1] - t0) * n as f64 / (n - 1).max(1) as f64;
    [vm + slope * (t0 - tm), vm + slope * (end - tm)]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recording::{Channel, ChannelKind, RecordingMeta};

    /// A recording of `n` samples at `rate_hz` whose reference speed is `speed(t)`.
    fn recording(kind: RunKind, n: usize, rate_hz: f64, speed: impl Fn(f64) -> f64) -> Recording {
        let time_s: Vec<f64> = (0..n).map(|i| 0.25 + i as f64 / rate_hz).collect();
        let values = time_s.iter().map(|&t| speed(t - 0.25)).collect();
        let kind_of = ChannelKind::SpeedRpm {
            node: "engine".into(),
        };
        Recording {
            time_s,
            channels: vec![Channel::new(kind_of, values)],
            meta: RecordingMeta::new(kind, "engine"),
        }
    }

    /// A wiggle on the mean: order-like vibration that must average out.
    fn wiggle(t: f64) -> f64 {
        5.0 * (std::f64::consts::TAU * 73.0 * t).sin()
    }

    #[test]
    fn a_short_steady_recording_is_steady_at_its_mean() {
        let r = recording(RunKind::Steady, 4096, 1024.0, |t| 3000.0 + wiggle(t));
        let RunShape::Steady { speed_rpm } = classify(&r) else {
            panic!("{:?}", classify(&r));
        };
        // 4 s hold 292 whole periods of the 73 Hz wiggle: its mean is ~1e-12 rpm.
        assert!((speed_rpm - 3000.0).abs() < 1e-9, "{speed_rpm}");
        assert_eq!(classify(&r).label(), "steady");
        assert_eq!(classify(&r).sidecar_kind().as_str(), "steady");
    }

    #[test]
    fn the_sidecar_speed_wins_over_the_mean() {
        let mut r = recording(RunKind::Steady, 1024, 1024.0, |_| 2990.0);
        r.meta.speed_rpm = Some(3000.0);
        assert_eq!(classify(&r), RunShape::Steady { speed_rpm: 3000.0 });
    }

    #[test]
    fn a_long_steady_recording_is_a_long_run() {
        let r = recording(RunKind::Steady, 30 * 1024, 1024.0, |_| 1500.0);
        assert_eq!(classify(&r), RunShape::LongRun { speed_rpm: 1500.0 });
        assert_eq!(classify(&r).label(), "long run");
        assert_eq!(classify(&r).sidecar_kind().as_str(), "steady");
    }

    #[test]
    fn borderline_durations() {
        // n samples at 1024 Hz cover n/1024 s: 8192 samples are exactly 8 s, a long run;
        // one sample fewer is 7.999 s, steady.
        let at = |n| classify(&recording(RunKind::Steady, n, 1024.0, |_| 1000.0));
        assert!(matches!(at(8192), RunShape::LongRun { .. }));
        assert!(matches!(at(8191), RunShape::Steady { .. }));
        assert!(matches!(at(8193), RunShape::LongRun { .. }));
        // One or no sample: duration 0, steady; never NaN.
        assert_eq!(at(1), RunShape::Steady { speed_rpm: 1000.0 });
        assert_eq!(at(0), RunShape::Steady { speed_rpm: 0.0 });
        // A run-up is a ramp however short or long.
        let ramp = |n| classify(&recording(RunKind::RunUp, n, 1024.0, |t| 1000.0 + t));
        assert!(ramp(100).is_ramp() && ramp(20 * 1024).is_ramp());
    }

    #[test]
    fn a_run_up_is_a_ramp_along_the_measured_trace() {
        // 1000 → 6000 rpm in 50 s (51200 samples at 1024 Hz), with a vibration on it.
        let r = recording(RunKind::RunUp, 51200, 1024.0, |t| {
            1000.0 + 100.0 * t + wiggle(t)
        });
        let RunShape::Ramp { from_rpm, to_rpm } = classify(&r) else {
            panic!("{:?}", classify(&r));
        };
        // The fit over 3650 wiggle periods leaves < 0.01 rpm of the 5 rpm wiggle.
        assert!((from_rpm - 1000.0).abs() < 0.01, "{from_rpm}");
        assert!((to_rpm - 6000.0).abs() < 0.01, "{to_rpm}");
        assert_eq!(classify(&r).label(), "run-up");
        assert!(classify(&r).describe().starts_with("run-up 1000 to 6000"));
    }

    #[test]
    fn a_run_down_is_a_ramp_too() {
        let r = recording(RunKind::RunUp, 20480, 1024.0, |t| 4000.0 - 150.0 * t);
        let RunShape::Ramp { from_rpm, to_rpm } = classify(&r) else {
            panic!("{:?}", classify(&r));
        };
        // An exact line: the fit is exact to round-off.
        assert!((from_rpm - 4000.0).abs() < 1e-6 && (to_rpm - 1000.0).abs() < 1e-6);
        assert_eq!(classify(&r).label(), "run-up");
        assert_eq!(classify(&r).sidecar_kind(), RunKind::RunUp);
        assert!(classify(&r).describe().starts_with("run-down 4000 to 1000"));
    }

    #[test]
    fn with_speeds_keeps_the_shape() {
        let long = RunShape::LongRun { speed_rpm: 1.0 };
        assert_eq!(
            long.with_speeds([2.0, 3.0]),
            RunShape::LongRun { speed_rpm: 2.0 }
        );
        let ramp = RunShape::Ramp {
            from_rpm: 1.0,
            to_rpm: 2.0,
        };
        assert_eq!(ramp.with_speeds([5.0, 6.0]).speeds_rpm(), [5.0, 6.0]);
    }
}
