//! A run: its [`RunShape`] and its duration — the one description of "what is run" that
//! the time domain ([`crate::transient::simulate`]), a campaign's plan
//! ([`crate::campaign::PlannedRun`]), the GUI's time traces and the diagnosis share
//! (issue 14, item 1). [`Run::of`] derives it from a recording by the one classifier,
//! [`super::classify`].

use super::shape::{RunShape, classify, duration_s};
use super::types::Recording;

/// A run of `duration_s` seconds of the shape `shape`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Run {
    /// Steady, long run or ramp, with its speeds.
    pub shape: RunShape,
    /// Recorded duration, s (a ramp's is its ramp time).
    pub duration_s: f64,
}

impl Run {
    /// A steady run at `speed_rpm` for `duration_s`: a long run when it lasts at least
    /// [`super::LONG_RUN_S`] (the classifier's rule, [`RunShape::steady`]).
    pub const fn steady(speed_rpm: f64, duration_s: f64) -> Self {
        Self {
            shape: RunShape::steady(speed_rpm, duration_s),
            duration_s,
        }
    }

    /// A linear ramp from `from_rpm` to `to_rpm` over `duration_s` (a run-down when
    /// `to_rpm < from_rpm`).
    pub const fn ramp(from_rpm: f64, to_rpm: f64, duration_s: f64) -> Self {
        Self {
            shape: RunShape::Ramp { from_rpm, to_rpm },
            duration_s,
        }
    }

    /// The run a recording shows: its shape by [`classify`] and its duration by
    /// [`duration_s`] (n samples cover n sampling intervals).
    pub fn of(recording: &Recording) -> Self {
        Self {
            shape: classify(recording),
            duration_s: duration_s(recording),
        }
    }

    /// The reference speed at the start and at the end, rpm (a steady run's twice).
    pub fn speeds_rpm(&self) -> [f64; 2] {
        self.shape.speeds_rpm()
    }

    /// Whether the speed ramps.
    pub fn is_ramp(&self) -> bool {
        self.shape.is_ramp()
    }

    /// The ramp rate, rpm/s (0 for a steady run or a zero duration).
    pub fn rate_rpm_per_s(&self) -> f64 {
        let [from, to] = self.speeds_rpm();
        if self.duration_s > 0.0 {
            (to - from) / self.duration_s
        } else {
            0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::recording::{Channel, ChannelKind, RecordingMeta, RunKind};

    #[test]
    fn constructors_follow_the_classifier_rule() {
        // 8 s is the long-run threshold (LONG_RUN_S), inclusive.
        assert!(matches!(
            Run::steady(1500.0, 4.0).shape,
            RunShape::Steady { .. }
        ));
        assert!(matches!(
            Run::steady(1500.0, 8.0).shape,
            RunShape::LongRun { .. }
        ));
        let down = Run::ramp(3000.0, 1000.0, 10.0);
        assert!(down.is_ramp());
        assert_eq!(down.speeds_rpm(), [3000.0, 1000.0]);
        assert_eq!(down.rate_rpm_per_s(), -200.0);
        assert_eq!(Run::steady(1500.0, 4.0).rate_rpm_per_s(), 0.0);
    }

    #[test]
    fn a_recording_gives_back_the_run_it_was_made_from() {
        // 1000 samples at 250 Hz from a clock at 187.6 s: 4 s, steady at 1200 rpm.
        let time_s: Vec<f64> = (0..1000).map(|i| 187.6 + i as f64 / 250.0).collect();
        let kind = ChannelKind::SpeedRpm {
            node: "crank".into(),
        };
        let recording = Recording {
            channels: vec![Channel::new(kind, vec![1200.0; time_s.len()])],
            time_s,
            meta: RecordingMeta::new(RunKind::Steady, "crank"),
        };
        let run = Run::of(&recording);
        assert_eq!(run.shape, RunShape::Steady { speed_rpm: 1200.0 });
        // n samples cover n intervals of 4 ms; round-off of 187.6 + i/250 only.
        assert!((run.duration_s - 4.0).abs() < 1e-9, "{}", run.duration_s);
    }
}
