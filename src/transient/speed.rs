//! The mean rotation: constant speed, or a linear ramp between two speeds.

use std::f64::consts::TAU;

/// Mean speed of the reference shaft over time: `from_rpm` until `start_s`, a linear ramp
/// to `to_rpm` over `duration_s`, then `to_rpm`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedProfile {
    /// Speed before the ramp, rpm.
    pub from_rpm: f64,
    /// Speed after the ramp, rpm.
    pub to_rpm: f64,
    /// Ramp start, s.
    pub start_s: f64,
    /// Ramp duration, s (0: a step is never used; steady runs have from = to).
    pub duration_s: f64,
}

impl SpeedProfile {
    /// A constant speed.
    pub fn steady(speed_rpm: f64) -> Self {
        Self {
            from_rpm: speed_rpm,
            to_rpm: speed_rpm,
            start_s: 0.0,
            duration_s: 0.0,
        }
    }

    /// A ramp from `from_rpm` at `start_s` to `to_rpm` `duration_s` later.
    pub fn ramp(from_rpm: f64, to_rpm: f64, start_s: f64, duration_s: f64) -> Self {
        Self {
            from_rpm,
            to_rpm,
            start_s,
            duration_s,
        }
    }

    /// Mean angle (rad, 0 at t = 0), speed (rad/s) and acceleration (rad/s²) at `t`.
    pub fn at(&self, t: f64) -> (f64, f64, f64) {
        let w0 = self.from_rpm * TAU / 60.0;
        let w1 = self.to_rpm * TAU / 60.0;
        if t <= self.start_s || self.duration_s <= 0.0 {
            return (w0 * t, w0, 0.0);
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
}
