//! What the bench's sensors do to the amplitudes, applied to the simulated side.
//!
//! - **Line averaging** (always, from the sidecar's `lines_per_rev`): a tape or encoder of
//!   `N` lines measures the mean speed over each line pitch, which scales shaft order `k`
//!   by `sinc(k/N) = sin(πk/N)/(πk/N)`; engine order `q` at a station turning at `r` times
//!   the reference speed is shaft order `k = q/r` (on a 78-line tape at 1/3 of the crank
//!   speed, engine order 8 loses 15 %).
//! - **A tape joint** (effect `sensor_artifact`): the interval across the joint is
//!   `(1 + f)` pitches long, so the speed reads low by `f·n` over one pitch per
//!   revolution: every integer order `k` of that shaft gets `2 f n/N · sinc(k/N)` rpm
//!   (zero-to-peak, `n` the station's mean speed). Synchronous averaging per working cycle
//!   keeps only the engine orders `q` whose `k = q/r` is an integer. Its phase against
//!   the driveline's own order depends on where the joint sits, which the amplitudes do
//!   not tell; the two are added in power, `√(A² + c²)`, their mean over the phase.
//! - **A pitch error** (effect `sensor_artifact`, `kind = pitch_error`): line `j` of `N`
//!   sits at `j·2π/N + ε·sin(j·2π/N)` (an eccentric tape or encoder disc). The interval
//!   from line `j` to `j + 1` is then `(2π/N)(1 + ε·sinc(1/N)·cos(θ + π/N))`, so the speed
//!   reads `ε·n·sinc(1/N)` (ε in rad, zero-to-peak) at shaft order 1 and nowhere else;
//!   added in power like the joint.
//!
//! Where the station's shaft order is no engine order (a gear of ratio 3.11), the
//! artifact leaks into the engine orders through the order analysis: its amplitude per
//! unit size is then measured on the analysis itself ([`super::sensor_gain`]) and
//! carried in `gains`.

use super::observe::Observed;
use std::sync::Arc;

/// The two forms a bench's sensor artifact takes (issue 14).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArtifactForm {
    /// A zebra tape's butt joint: size = excess length of the joint interval, pitches.
    TapeJoint,
    /// A once-per-revolution pitch error (eccentricity): size = ε, degrees.
    PitchError,
}

impl ArtifactForm {
    /// The report's `kind`: `tape_joint` or `pitch_error`.
    pub fn key(self) -> &'static str {
        match self {
            Self::TapeJoint => "tape_joint",
            Self::PitchError => "pitch_error",
        }
    }
}

/// A sensor artifact at one station (named for the first form it had: a tape joint).
#[derive(Debug, Clone, PartialEq)]
pub struct TapeJoint {
    /// Node of the station.
    pub station: String,
    /// Its form.
    pub form: ArtifactForm,
    /// Its size: joint fraction (pitches) or pitch error ε (degrees).
    pub size: f64,
    /// Amplitude per unit size at each observation (rpm; `None`: the closed forms above at
    /// integer shaft orders only), from [`super::sensor_gain::unit_gains`].
    pub gains: Option<Arc<Vec<f64>>>,
}

/// The artifact's amplitude (rpm, zero-to-peak) at shaft order `k` of a station turning
/// at `n_station` rpm with `n_lines` lines, for size `size` of `form`; zero at a
/// non-integer order.
pub fn closed_form(form: ArtifactForm, size: f64, k: f64, n_station: f64, n_lines: f64) -> f64 {
    if (k - k.round()).abs() >= 1e-6 || k.round() < 1.0 {
        return 0.0;
    }
    match form {
        ArtifactForm::TapeJoint => 2.0 * size.abs() * n_station / n_lines * sinc(k / n_lines),
        ArtifactForm::PitchError if k.round() == 1.0 => {
            size.abs().to_radians() * n_station * sinc(1.0 / n_lines)
        }
        ArtifactForm::PitchError => 0.0,
    }
}

/// `sin(πx)/(πx)`.
pub fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-12 {
        1.0
    } else {
        (std::f64::consts::PI * x).sin() / (std::f64::consts::PI * x)
    }
}

/// The station's mean speed over the reference's, from the observations' run (1 when
/// unknown).
fn shaft_ratio(ratios: &[(String, f64)], station: &str) -> f64 {
    ratios
        .iter()
        .find(|(n, _)| n == station)
        .map_or(1.0, |(_, r)| r.abs())
}

/// Lines per revolution of `station` in run `run`, if the sidecar says.
pub(crate) fn lines_of(observed: &Observed, run: usize, station: &str) -> Option<u32> {
    let run = &observed.runs[run];
    run.stations
        .iter()
        .position(|s| s == station)
        .and_then(|i| run.lines_per_rev.get(i).copied().flatten())
}

/// Applies line averaging (and the tape `joint`, if any) to the simulated amplitudes
/// `values` of `observed`, in place. `ratios`: each node's mean speed over the
/// reference's.
pub fn measure(
    observed: &Observed,
    ratios: &[(String, f64)],
    joint: Option<&TapeJoint>,
    values: &mut [f64],
) {
    for (o, v) in observed.observations.iter().zip(values.iter_mut()) {
        let k = o.order / shaft_ratio(ratios, &o.station);
        if let Some(n) = lines_of(observed, o.run, &o.station) {
            *v *= sinc(k / f64::from(n));
        }
    }
    add_joint(observed, ratios, joint, values);
}

/// Adds the artifact `joint`'s orders in power to amplitudes already measured.
pub fn add_joint(
    observed: &Observed,
    ratios: &[(String, f64)],
    joint: Option<&TapeJoint>,
    values: &mut [f64],
) {
    let Some(j) = joint else {
        return;
    };
    for (i, (o, v)) in observed
        .observations
        .iter()
        .zip(values.iter_mut())
        .enumerate()
    {
        if j.station != o.station {
            continue;
        }
        let c = match &j.gains {
            Some(g) => j.size.abs() * g.get(i).copied().unwrap_or(0.0),
            None => {
                let r = shaft_ratio(ratios, &o.station);
                let n_lines = f64::from(lines_of(observed, o.run, &o.station).unwrap_or(60));
                closed_form(j.form, j.size, o.order / r, o.speed_rpm * r, n_lines)
            }
        };
        if c > 0.0 && c.is_finite() {
            *v = v.hypot(c);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sinc_is_one_at_zero_and_zero_at_integers() {
        assert_eq!(sinc(0.0), 1.0);
        assert!(sinc(1.0).abs() < 1e-15);
        // Engine order 8 on a 78-line tape at a third of the crank speed: shaft order 24.
        assert!(
            (sinc(24.0 / 78.0) - 0.8514).abs() < 1e-4,
            "{}",
            sinc(24.0 / 78.0)
        );
    }

    /// A pitch error ε at N lines reads `ε·n·sinc(1/N)` at shaft order 1 and nothing at
    /// any other order; against the line positions of the effect library
    /// ([`crate::effects::sensor::line_angles`]) read at constant speed, the first Fourier
    /// coefficient of the per-line speed error.
    #[test]
    fn pitch_error_is_shaft_order_one_of_eps_times_speed() {
        use crate::effects::SensorArtifact;
        let (lines, n_rpm, eps_deg) = (78_u32, 3000.0, 0.1);
        let a = SensorArtifact::PitchError {
            station: "x".into(),
            error_deg: eps_deg,
        };
        let angles = crate::effects::sensor::line_angles(lines, &[&a]);
        let pitch = std::f64::consts::TAU / f64::from(lines);
        // Constant true speed: the time between lines is their angle apart; the IAS
        // processing divides the nominal pitch by it.
        let speeds: Vec<f64> = (0..lines as usize)
            .map(|j| {
                let next = angles.get(j + 1).copied().unwrap_or(std::f64::consts::TAU);
                n_rpm * pitch / (next - angles[j])
            })
            .collect();
        let amplitude = |k: f64| {
            let (mut c, mut s) = (0.0, 0.0);
            for (j, v) in speeds.iter().enumerate() {
                let x = k * (j as f64 + 0.5) * pitch;
                c += v * x.cos();
                s += v * x.sin();
            }
            2.0 * c.hypot(s) / f64::from(lines)
        };
        let n_lines = f64::from(lines);
        let predicted = closed_form(ArtifactForm::PitchError, eps_deg, 1.0, n_rpm, n_lines);
        // ε·n = 5.24 rpm; the second-order term of 1/(1 + x) is (ε·sinc)²·n/2 ≈ 1.4e-3 rpm
        // at order 2, so 1e-3 relative at order 1 and 1e-2 rpm elsewhere.
        assert!((predicted - eps_deg.to_radians() * n_rpm).abs() < 1e-3 * predicted);
        assert!(
            (amplitude(1.0) - predicted).abs() < 1e-3 * predicted,
            "{}",
            amplitude(1.0)
        );
        for k in 2..10 {
            assert!(
                amplitude(f64::from(k)) < 1e-2,
                "order {k}: {}",
                amplitude(f64::from(k))
            );
            assert_eq!(
                closed_form(
                    ArtifactForm::PitchError,
                    eps_deg,
                    f64::from(k),
                    n_rpm,
                    n_lines
                ),
                0.0
            );
        }
    }
}
