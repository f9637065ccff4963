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

use super::observe::Observed;

/// A tape joint at one station.
#[derive(Debug, Clone, PartialEq)]
pub struct TapeJoint {
    /// Node of the station.
    pub station: String,
    /// Excess length of the joint interval, pitches.
    pub joint_fraction: f64,
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
fn lines_of(observed: &Observed, run: usize, station: &str) -> Option<u32> {
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

/// Adds the tape `joint`'s orders in power to amplitudes already measured.
pub fn add_joint(
    observed: &Observed,
    ratios: &[(String, f64)],
    joint: Option<&TapeJoint>,
    values: &mut [f64],
) {
    let Some(j) = joint else {
        return;
    };
    for (o, v) in observed.observations.iter().zip(values.iter_mut()) {
        let r = shaft_ratio(ratios, &o.station);
        let k = o.order / r;
        if j.station == o.station && (k - k.round()).abs() < 1e-6 && k.round() >= 1.0 {
            let n_lines = f64::from(lines_of(observed, o.run, &o.station).unwrap_or(60));
            let n_station = o.speed_rpm * r;
            let c = 2.0 * j.joint_fraction.abs() * n_station / n_lines * sinc(k / n_lines);
            *v = (*v * *v + c * c).sqrt();
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
}
