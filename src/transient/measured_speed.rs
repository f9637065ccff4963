//! A recording's own mean-speed trajectory, to drive a simulated run-up along it.
//!
//! A bench's run-up is never the straight line between its end speeds. Its speed loop
//! is slow (a dyno's is a few tenths of a hertz), and where the run passes a lightly
//! damped resonance the vibration takes power from the mean rotation: the run lingers
//! there and then jumps on (the Sommerfeld effect). Benchtruth development case 3114
//! (`parameter_error`, first mode damped at 1.3 %): the crank stayed between 855 and
//! 870 rpm for two seconds of a 37 rpm/s ramp, mass 5 swung by 180 rpm RMS at the 1.5th
//! order, and the release from it filled orders 4.5–6 of the 900–1000 rpm bin. A linear
//! ramp passes the same resonance in 0.4 s; even the bench's true model then fitted
//! χ²/N 237 on the run-up, and hysteretic damping was named for what was a timing.
//!
//! So a run-up that departs from a straight ramp by more than [`FOLLOW_ABOVE`] is driven
//! along the measured speed: the recording's STFT window speeds
//! (their centres and mean reference speeds, as the order analysis bins them), smoothed
//! by a local straight-line fit over [`SPAN_S`] around knots [`KNOT_S`] apart, which
//! gives each knot a speed and a slope, joined by cubic Hermite pieces: the speed and the
//! acceleration are continuous, so the governor's feed-forward `J·α`
//! ([`super::plant::Governor`]) steps nowhere. Written here because no crate offers a
//! Hermite spline with its exact integral (the mean angle) and derivative at once, and
//! the smoothing is the local regression every order-analysis text uses for the speed.

use std::f64::consts::TAU;

/// Spacing of the knots, s: a dyno loop of 0.2 Hz and a capture lasting seconds are
/// resolved.
pub const KNOT_S: f64 = 0.25;
/// Span of the local straight-line fit at each knot, s: eleven periods of a 22 Hz first
/// mode, whose swing leaks into a single 0.1 s window's mean speed.
pub const SPAN_S: f64 = 0.5;

/// Departure from a straight ramp ([`MeasuredSpeed::departure_from_line`]) above which a
/// run-up is worth following: 2 % of its speed. A simulated run's own speed loop lags
/// through a lightly damped resonance too: torsim's run-up through a 0.7 % mode
/// (`diagnose/runup_tests.rs`) departs 1.5 % from its line, and a run driven along that
/// measured speed lags once more, 6.5 % of the peak off in a bin where the line is 1.5 %.
/// Case 3114 departs 3.2 %; of the 64 run-ups of development seeds 3000–3109, five depart
/// more than 2 % (2.4–4.4 %).
pub const FOLLOW_ABOVE: f64 = 0.02;

/// A smoothed mean-speed trajectory: knots from `start_s`, [`KNOT_S`] apart.
#[derive(Debug, Clone, PartialEq)]
pub struct MeasuredSpeed {
    /// Time of the first knot, s (the recording's time, from its first sample).
    start_s: f64,
    /// Knot speeds, rad/s.
    speed_rad_s: Vec<f64>,
    /// Knot accelerations, rad/s².
    accel_rad_s2: Vec<f64>,
    /// Mean angle at each knot from the first, rad.
    angle_rad: Vec<f64>,
}

/// The slope and the value at `at` of the least-squares line through the `(t, v)` pairs
/// within `span / 2` of `at`; `None` with fewer than three.
fn local_line(times_s: &[f64], values: &[f64], at: f64, span: f64) -> Option<(f64, f64)> {
    let near: Vec<(f64, f64)> = times_s
        .iter()
        .zip(values)
        .filter(|(t, v)| (*t - at).abs() <= span / 2.0 && v.is_finite())
        .map(|(t, v)| (*t - at, *v))
        .collect();
    if near.len() < 3 {
        return None;
    }
    let n = near.len() as f64;
    let mt = near.iter().map(|p| p.0).sum::<f64>() / n;
    let mv = near.iter().map(|p| p.1).sum::<f64>() / n;
    let stt: f64 = near.iter().map(|p| (p.0 - mt).powi(2)).sum();
    let stv: f64 = near.iter().map(|p| (p.0 - mt) * (p.1 - mv)).sum();
    let slope = if stt > 0.0 { stv / stt } else { 0.0 };
    Some((mv - slope * mt, slope))
}

impl MeasuredSpeed {
    /// The trajectory through STFT windows centred at `times_s` (s from the first
    /// sample, increasing) with mean reference speeds `speeds_rpm`; `None` when they
    /// cover less than [`SPAN_S`] or any knot has fewer than three windows near it.
    pub fn from_windows(times_s: &[f64], speeds_rpm: &[f64]) -> Option<Self> {
        let (first, last) = (*times_s.first()?, *times_s.last()?);
        if times_s.len() != speeds_rpm.len() || !(last - first).is_finite() || last - first < SPAN_S
        {
            return None;
        }
        let knots = ((last - first) / KNOT_S).floor() as usize + 1;
        let to_rad_s = TAU / 60.0;
        let mut speed_rad_s = Vec::with_capacity(knots);
        let mut accel_rad_s2 = Vec::with_capacity(knots);
        for k in 0..knots {
            // The end knots fit over the span's inner half only: shift the centre inside.
            let at = first + k as f64 * KNOT_S;
            let centre = at.clamp(first + SPAN_S / 2.0, last - SPAN_S / 2.0);
            let (v, s) = local_line(times_s, speeds_rpm, centre, SPAN_S)?;
            speed_rad_s.push((v + s * (at - centre)) * to_rad_s);
            accel_rad_s2.push(s * to_rad_s);
        }
        let mut angle_rad = vec![0.0; knots];
        for k in 1..knots {
            let (w0, a0, w1, a1) = (
                speed_rad_s[k - 1],
                accel_rad_s2[k - 1],
                speed_rad_s[k],
                accel_rad_s2[k],
            );
            angle_rad[k] = angle_rad[k - 1] + piece(w0, a0, w1, a1, KNOT_S, 1.0).0;
        }
        Some(Self {
            start_s: first,
            speed_rad_s,
            accel_rad_s2,
            angle_rad,
        })
    }

    /// Mean angle from the first knot (rad), speed (rad/s) and acceleration (rad/s²) at
    /// recording time `t_s`; before the first knot and after the last, the straight line
    /// of the end knot's speed and slope.
    pub fn at(&self, t_s: f64) -> (f64, f64, f64) {
        let last = self.speed_rad_s.len() - 1;
        let x = (t_s - self.start_s) / KNOT_S;
        let end = |k: usize, dt: f64| {
            let (w, a) = (self.speed_rad_s[k], self.accel_rad_s2[k]);
            (
                self.angle_rad[k] + w * dt + 0.5 * a * dt * dt,
                w + a * dt,
                a,
            )
        };
        if x <= 0.0 || last == 0 {
            return end(0, t_s - self.start_s);
        }
        let k = x.floor() as usize;
        if k >= last {
            return end(last, t_s - self.start_s - last as f64 * KNOT_S);
        }
        let u = x - k as f64;
        let (w0, a0, w1, a1) = (
            self.speed_rad_s[k],
            self.accel_rad_s2[k],
            self.speed_rad_s[k + 1],
            self.accel_rad_s2[k + 1],
        );
        let (angle, speed, accel) = piece(w0, a0, w1, a1, KNOT_S, u);
        (self.angle_rad[k] + angle, speed, accel)
    }

    /// The trajectory of [`MeasuredSpeed::from_windows`] when the run [`departs`] from a
    /// straight ramp, so that a simulation should follow it; `None` otherwise. The one
    /// rule the diagnosis' forward model and the GUI's matching run share.
    ///
    /// [`departs`]: MeasuredSpeed::departs
    pub fn to_follow(times_s: &[f64], speeds_rpm: &[f64]) -> Option<Self> {
        Self::from_windows(times_s, speeds_rpm).filter(Self::departs)
    }

    /// The largest departure of the knots from the least-squares line through them,
    /// relative to their mean speed: how far the run was from a straight ramp.
    pub fn departure_from_line(&self) -> f64 {
        let n = self.speed_rad_s.len() as f64;
        let t: Vec<f64> = (0..self.speed_rad_s.len())
            .map(|k| k as f64 * KNOT_S)
            .collect();
        let (mt, mw) = (
            t.iter().sum::<f64>() / n,
            self.speed_rad_s.iter().sum::<f64>() / n,
        );
        let stt: f64 = t.iter().map(|x| (x - mt).powi(2)).sum();
        let stw: f64 = t
            .iter()
            .zip(&self.speed_rad_s)
            .map(|(x, w)| (x - mt) * (w - mw))
            .sum();
        let slope = if stt > 0.0 { stw / stt } else { 0.0 };
        let worst = t
            .iter()
            .zip(&self.speed_rad_s)
            .map(|(x, w)| (w - mw - slope * (x - mt)).abs())
            .fold(0.0, f64::max);
        if mw > 0.0 { worst / mw } else { f64::INFINITY }
    }

    /// Whether the run departs from a straight ramp by more than [`FOLLOW_ABOVE`].
    pub fn departs(&self) -> bool {
        self.departure_from_line() > FOLLOW_ABOVE
    }

    /// Speed at recording time `t_s`, rpm.
    pub fn speed_rpm(&self, t_s: f64) -> f64 {
        self.at(t_s).1 * 60.0 / TAU
    }

    /// The highest speed between recording times `from_s` and `to_s`, rpm (at the knots
    /// and both ends; a Hermite piece overshoots its knots by little).
    pub fn max_speed_rpm(&self, from_s: f64, to_s: f64) -> f64 {
        let inner = (0..self.speed_rad_s.len())
            .map(|k| self.start_s + k as f64 * KNOT_S)
            .filter(|t| *t > from_s && *t < to_s);
        std::iter::once(from_s)
            .chain(inner)
            .chain(std::iter::once(to_s))
            .map(|t| self.speed_rpm(t))
            .fold(f64::NEG_INFINITY, f64::max)
    }
}

/// The cubic Hermite piece of length `h` (s) from speed `w0`, acceleration `a0` to `w1`,
/// `a1`, at `u` ∈ [0, 1]: the angle swept since its start (the exact integral), the speed
/// and the acceleration.
fn piece(w0: f64, a0: f64, w1: f64, a1: f64, h: f64, u: f64) -> (f64, f64, f64) {
    let (u2, u3, u4) = (u * u, u * u * u, u * u * u * u);
    let (m0, m1) = (a0 * h, a1 * h);
    let speed = (2.0 * u3 - 3.0 * u2 + 1.0) * w0
        + (u3 - 2.0 * u2 + u) * m0
        + (-2.0 * u3 + 3.0 * u2) * w1
        + (u3 - u2) * m1;
    let accel = ((6.0 * u2 - 6.0 * u) * w0
        + (3.0 * u2 - 4.0 * u + 1.0) * m0
        + (-6.0 * u2 + 6.0 * u) * w1
        + (3.0 * u2 - 2.0 * u) * m1)
        / h;
    let angle = h
        * ((0.5 * u4 - u3 + u) * w0
            + (0.25 * u4 - 2.0 * u3 / 3.0 + 0.5 * u2) * m0
            + (-0.5 * u4 + u3) * w1
            + (0.25 * u4 - u3 / 3.0) * m1);
    (angle, speed, accel)
}

#[cfg(test)]
#[path = "measured_speed_tests.rs"]
mod tests;
