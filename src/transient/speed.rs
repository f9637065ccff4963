//! The mean rotation: constant speed, a linear ramp between two speeds, or a recording's
//! own measured speed ([`MeasuredSpeed`]).

use super::measured_speed::MeasuredSpeed;
use std::f64::consts::TAU;
use std::sync::Arc;

/// Mean speed of the reference shaft over time: `from_rpm` until `start_s`, a linear ramp
/// to `to_rpm` over `duration_s`, then `to_rpm`; or, with `along`, from `start_s` on the
/// measured trajectory.
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedProfile {
    /// Speed before the ramp, rpm.
    pub from_rpm: f64,
    /// Speed after the ramp, rpm.
    pub to_rpm: f64,
    /// Ramp start, s.
    pub start_s: f64,
    /// Ramp duration, s (0: a step is never used; steady runs have from = to).
    pub duration_s: f64,
    /// From `start_s` on, the mean speed of a recording instead of the line, read from
    /// its time `.1` (s) on (default `None`).
    pub along: Option<(Arc<MeasuredSpeed>, f64)>,
}

impl SpeedProfile {
    /// A constant speed.
    pub fn steady(speed_rpm: f64) -> Self {
        Self {
            from_rpm: speed_rpm,
            to_rpm: speed_rpm,
            start_s: 0.0,
            duration_s: 0.0,
            along: None,
        }
    }

    /// A ramp from `from_rpm` at `start_s` to `to_rpm` `duration_s` later.
    pub fn ramp(from_rpm: f64, to_rpm: f64, start_s: f64, duration_s: f64) -> Self {
        Self {
            from_rpm,
            to_rpm,
            start_s,
            duration_s,
            along: None,
        }
    }

    /// From `start_s` on, the measured trajectory `speed` from its time `from_s` on
    /// (before `start_s`, its speed there): a simulated run-up driven as the bench ran.
    pub fn along(speed: Arc<MeasuredSpeed>, from_s: f64, start_s: f64, duration_s: f64) -> Self {
        let from_rpm = speed.speed_rpm(from_s);
        let to_rpm = speed.speed_rpm(from_s + duration_s);
        Self {
            from_rpm,
            to_rpm,
            start_s,
            duration_s,
            along: Some((speed, from_s)),
        }
    }

    /// Mean angle (rad, 0 at t = 0), speed (rad/s) and acceleration (rad/s²) at `t`.
    pub fn at(&self, t: f64) -> (f64, f64, f64) {
        let w0 = self.from_rpm * TAU / 60.0;
        let w1 = self.to_rpm * TAU / 60.0;
        if t <= self.start_s || (self.duration_s <= 0.0 && self.along.is_none()) {
            return (w0 * t, w0, 0.0);
        }
        if let Some((speed, from_s)) = &self.along {
            let (a0, _, _) = speed.at(*from_s);
            let (a, w, alpha) = speed.at(from_s + t - self.start_s);
            return (w0 * self.start_s + a - a0, w, alpha);
        }
        let alpha = (w1 - w0) / self.duration_s;
        let tr = (t - self.start_s).min(self.duration_s);
        let angle = w0 * self.start_s + w0 * tr + 0.5 * alpha * tr * tr;
        if t - self.start_s <= self.duration_s {
            (angle, w0 + alpha * tr, alpha)
        } else {
            (angle + w1 * (t - self.start_s - self.duration_s), w1, 0.0)
        }
    }

    /// Speed at `t`, rpm.
    pub fn speed_rpm(&self, t: f64) -> f64 {
        self.at(t).1 * 60.0 / TAU
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The angle is the integral of the speed: check against a fine trapezoid sum.
    #[test]
    fn angle_integrates_speed() {
        let p = SpeedProfile::ramp(600.0, 1800.0, 0.5, 2.0);
        let (n, t_end) = (300_000, 3.0);
        let h = t_end / n as f64;
        let mut angle = 0.0;
        for i in 0..n {
            let (t0, t1) = (i as f64 * h, (i + 1) as f64 * h);
            angle += 0.5 * h * (p.at(t0).1 + p.at(t1).1);
        }
        assert!(
            (p.at(t_end).0 - angle).abs() < 1e-8,
            "{} vs {angle}",
            p.at(t_end).0
        );
        assert!((p.speed_rpm(1.5) - 1200.0).abs() < 1e-9);
    }

    /// Along a measured straight ramp, the profile is the linear ramp: same angle, speed
    /// and acceleration, before it and on it.
    #[test]
    fn along_a_straight_measured_ramp_is_the_ramp() {
        // Windows every 0.05 s of a 600 rpm/s ramp from 600 rpm; read from 1.0 s on.
        let times: Vec<f64> = (1..80).map(|k| 0.05 * k as f64).collect();
        let speeds: Vec<f64> = times.iter().map(|t| 600.0 + 600.0 * t).collect();
        let m = MeasuredSpeed::from_windows(&times, &speeds).expect("long enough");
        let along = SpeedProfile::along(Arc::new(m), 1.0, 0.5, 2.0);
        let line = SpeedProfile::ramp(1200.0, 2400.0, 0.5, 2.0);
        for t in [0.0, 0.3, 0.5, 0.9, 1.7, 2.5] {
            let (a, b) = (along.at(t), line.at(t));
            assert!((a.0 - b.0).abs() < 1e-9, "angle at {t}: {a:?} vs {b:?}");
            assert!(
                (a.1 - b.1).abs() < 1e-9 && (a.2 - b.2).abs() < 1e-9,
                "at {t}"
            );
        }
        assert!((along.from_rpm - 1200.0).abs() < 1e-9 && (along.to_rpm - 2400.0).abs() < 1e-9);
    }
}
