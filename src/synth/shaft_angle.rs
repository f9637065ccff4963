//! A shaft's angle from its simulated speed, and the times it passes given angles (the
//! pulse times of the lines of a tape or encoder).
//!
//! The speed between samples is the cubic Hermite interpolant with fourth-order
//! central-difference slopes; the angle is its exact integral (per segment
//! `h·(v₀ + v₁)/2 + h²·(d₀ − d₁)/12` at the end, quartic inside). Summed over segments
//! that is the Euler–Maclaurin formula, so the angle's error at the samples is
//! `h⁴/720·[v‴]` — for a vibration at ω, at most `(ωh)⁴/360` of its angle amplitude
//! (1.7e-6 for 200 Hz sampled at 8192 Hz); between samples the cubic's own error adds up
//! to `(ωh)⁵/720`; the one-sided slope at the start adds a constant. A crossing is found
//! by Newton's method on the quartic, with the speed as its derivative.

/// Angle and speed of one shaft over a uniformly sampled run.
#[derive(Debug, Clone)]
pub struct ShaftAngle {
    t0_s: f64,
    h_s: f64,
    speed: Vec<f64>,
    slope: Vec<f64>,
    angle: Vec<f64>,
}

impl ShaftAngle {
    /// From speeds `speed_rad_s` sampled every `h_s` from `t0_s`; the angle is 0 at `t0_s`.
    /// Needs at least two samples.
    pub fn new(t0_s: f64, h_s: f64, speed_rad_s: Vec<f64>) -> Self {
        let n = speed_rad_s.len();
        let v = &speed_rad_s;
        let slope: Vec<f64> = (0..n)
            .map(|i| match i {
                _ if n < 3 => (v[n - 1] - v[0]) / (h_s * (n - 1) as f64),
                0 => (-3.0 * v[0] + 4.0 * v[1] - v[2]) / (2.0 * h_s),
                i if i == n - 1 => (3.0 * v[i] - 4.0 * v[i - 1] + v[i - 2]) / (2.0 * h_s),
                i if i == 1 || i == n - 2 => (v[i + 1] - v[i - 1]) / (2.0 * h_s),
                i => (8.0 * (v[i + 1] - v[i - 1]) - v[i + 2] + v[i - 2]) / (12.0 * h_s),
            })
            .collect();
        let mut angle = Vec::with_capacity(n);
        let mut a = 0.0;
        angle.push(a);
        for i in 0..n - 1 {
            a += h_s * 0.5 * (v[i] + v[i + 1]) + h_s * h_s * (slope[i] - slope[i + 1]) / 12.0;
            angle.push(a);
        }
        Self {
            t0_s,
            h_s,
            speed: speed_rad_s,
            slope,
            angle,
        }
    }

    /// Time of the first sample, s.
    pub fn start_s(&self) -> f64 {
        self.t0_s
    }

    /// Time of the last sample, s.
    pub fn end_s(&self) -> f64 {
        self.t0_s + self.h_s * (self.speed.len() - 1) as f64
    }

    /// Angle at the last sample, rad.
    pub fn total_angle(&self) -> f64 {
        self.angle[self.angle.len() - 1]
    }

    /// Segment index and position `x ∈ [0, 1]` of time `t`.
    fn locate(&self, t: f64) -> (usize, f64) {
        let u = ((t - self.t0_s) / self.h_s).max(0.0);
        let i = (u.floor() as usize).min(self.speed.len() - 2);
        (i, (u - i as f64).min(1.0))
    }

    /// Speed at `t` (held inside the run), rad/s.
    pub fn speed_at(&self, t: f64) -> f64 {
        let (i, x) = self.locate(t);
        let (x2, x3) = (x * x, x * x * x);
        let h = self.h_s;
        (2.0 * x3 - 3.0 * x2 + 1.0) * self.speed[i]
            + (x3 - 2.0 * x2 + x) * h * self.slope[i]
            + (-2.0 * x3 + 3.0 * x2) * self.speed[i + 1]
            + (x3 - x2) * h * self.slope[i + 1]
    }

    /// Angle at `t` (held inside the run), rad.
    pub fn angle_at(&self, t: f64) -> f64 {
        let (i, x) = self.locate(t);
        self.angle[i] + self.segment_integral(i, x)
    }

    fn segment_integral(&self, i: usize, x: f64) -> f64 {
        let h = self.h_s;
        let (x2, x3, x4) = (x * x, x * x * x, x * x * x * x);
        h * ((0.5 * x4 - x3 + x) * self.speed[i]
            + (0.25 * x4 - 2.0 * x3 / 3.0 + 0.5 * x2) * h * self.slope[i]
            + (-0.5 * x4 + x3) * self.speed[i + 1]
            + (0.25 * x4 - x3 / 3.0) * h * self.slope[i + 1])
    }

    /// The times at which the angle reaches each of `targets` (rad, increasing, within
    /// `0 … total_angle()`). `None` when the speed is not positive throughout (the angle
    /// would not be monotonic, and a target could be passed more than once).
    pub fn crossing_times(&self, targets: &[f64]) -> Option<Vec<f64>> {
        if self.speed.iter().any(|v| *v <= 0.0) {
            return None;
        }
        let mut out = Vec::with_capacity(targets.len());
        let mut i = 0;
        for &target in targets {
            while i + 2 < self.angle.len() && self.angle[i + 1] <= target {
                i += 1;
            }
            let span = self.angle[i + 1] - self.angle[i];
            let mut x = ((target - self.angle[i]) / span).clamp(0.0, 1.0);
            for _ in 0..8 {
                let err = self.angle[i] + self.segment_integral(i, x) - target;
                let t = self.t0_s + self.h_s * (i as f64 + x);
                let step = err / (self.speed_at(t) * self.h_s);
                x = (x - step).clamp(0.0, 1.0);
                if step.abs() < 1e-13 {
                    break;
                }
            }
            out.push(self.t0_s + self.h_s * (i as f64 + x));
        }
        Some(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ω(t) = ω0 + a·sin(2πft): the angle is ω0·t + a(1 − cos 2πft)/(2πf). At 16 samples
    /// per period (ωh = 0.39) the error of angle differences between interior times is
    /// below (ωh)⁴/360 + 2·(ωh)⁵/720 = 9.2e-5 of the vibration angle (the module's bounds,
    /// the second for both ends of the difference; measured 8.6e-5).
    #[test]
    fn angle_and_crossings_match_the_closed_form() {
        let (w0, a, f) = (100.0, 20.0, 50.0);
        let h = 1.0 / (16.0 * f);
        let n = 801;
        let v: Vec<f64> = (0..n)
            .map(|i| w0 + a * (std::f64::consts::TAU * f * i as f64 * h).sin())
            .collect();
        let s = ShaftAngle::new(0.0, h, v);
        let exact = |t: f64| {
            w0 * t + a * (1.0 - (std::f64::consts::TAU * f * t).cos()) / (std::f64::consts::TAU * f)
        };
        let vib = a / (std::f64::consts::TAU * f);
        let wh = std::f64::consts::TAU * f * h;
        let bound = (wh.powi(4) / 360.0 + wh.powi(5) / 360.0) * vib;
        let t_ref = 0.0101;
        let offset = s.angle_at(t_ref) - exact(t_ref);
        let mut worst: f64 = 0.0;
        for k in 0..980 {
            let t = t_ref + k as f64 * 0.000_997;
            worst = worst.max((s.angle_at(t) - exact(t) - offset).abs());
        }
        assert!(worst < bound, "{worst} vs {bound}");
        let targets: Vec<f64> = (1..195)
            .map(|k| s.angle_at(t_ref) + k as f64 * 0.05)
            .collect();
        let times = s.crossing_times(&targets).unwrap();
        for (t, target) in times.iter().zip(&targets) {
            assert!((s.angle_at(*t) - target).abs() < 1e-12);
            assert!((exact(*t) + offset - target).abs() < bound);
        }
        let backwards = ShaftAngle::new(0.0, 0.1, vec![1.0, -1.0, 1.0]);
        assert!(backwards.crossing_times(&[0.05]).is_none());
    }
}
