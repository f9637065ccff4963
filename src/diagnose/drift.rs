//! The drift of a long run: do its order amplitudes change over the run?
//!
//! A coupling that warms up softens, and the amplitudes of the orders near its modes move
//! steadily through a long run at constant speed (seed 000 eqs. 10–11). Per station and
//! order, the slope of the amplitude over the run's time blocks is fitted by least
//! squares and divided by its standard error from the blocks' noise; with no drift these
//! `z` are standard normal, and their mean square is 1 ± √(2/n).

use super::observe::{Observed, RunShape};
use std::collections::BTreeMap;

/// Mean square of the slopes' `z` above which a long run drifts. Without drift it is
/// 1 ± 0.3 for the 24–32 slopes of a campaign (measured: 0.28–1.16 on the eleven shipped
/// cases and eight reference campaigns without thermal drift; 10.7 and 337 with it).
pub const DRIFT_CHI2: f64 = 3.0;

/// The mean square of the slope `z` over every station and order of the long runs of
/// `observed` (`None` without a long run of at least three blocks).
pub fn long_run_drift(observed: &Observed) -> Option<f64> {
    // (run, station, order bits) → (time s, amplitude rpm, σ rpm) of each block
    type Blocks = Vec<(f64, f64, f64)>;
    let mut groups: BTreeMap<(usize, &str, u64), Blocks> = BTreeMap::new();
    for o in &observed.observations {
        if matches!(observed.runs[o.run].regime, RunShape::LongRun { .. }) {
            groups
                .entry((o.run, o.station.as_str(), o.order.to_bits()))
                .or_default()
                .push((o.time_s, o.measured_rpm, o.sigma_rpm));
        }
    }
    let z: Vec<f64> = groups
        .values()
        .filter(|v| v.len() >= 3)
        .filter_map(|v| {
            let n = v.len() as f64;
            let t_mean = v.iter().map(|x| x.0).sum::<f64>() / n;
            let a_mean = v.iter().map(|x| x.1).sum::<f64>() / n;
            let sxx: f64 = v.iter().map(|x| (x.0 - t_mean).powi(2)).sum();
            let sigma = (v.iter().map(|x| x.2 * x.2).sum::<f64>() / n).sqrt();
            if sxx <= 0.0 || sigma <= 0.0 {
                return None;
            }
            let slope = v
                .iter()
                .map(|x| (x.0 - t_mean) * (x.1 - a_mean))
                .sum::<f64>()
                / sxx;
            Some(slope * sxx.sqrt() / sigma)
        })
        .collect();
    (!z.is_empty()).then(|| z.iter().map(|z| z * z).sum::<f64>() / z.len() as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::observe::{Observation, Run};

    fn long_run(slope_rpm_per_s: f64) -> Observed {
        let mut observations = Vec::new();
        // Eight blocks of 2.5 s, two orders, noise σ = 0.1 rpm drawn as ±σ alternately.
        for order in [2.0, 4.0] {
            for b in 0..8 {
                let t = 1.25 + 2.5 * f64::from(b);
                let noise = if b % 2 == 0 { 0.1 } else { -0.1 };
                observations.push(Observation {
                    run: 0,
                    part: b as usize,
                    station: "engine".into(),
                    order,
                    speed_rpm: 3000.0,
                    time_s: t,
                    measured_rpm: 5.0 + slope_rpm_per_s * t + noise,
                    sigma_rpm: 0.1,
                    bias_sigma_rpm: 0.1,
                });
            }
        }
        Observed {
            runs: vec![Run {
                label: "long run".into(),
                regime: RunShape::LongRun { speed_rpm: 3000.0 },
                load: 1.0,
                duration_s: 20.0,
                rate_hz: 2000.0,
                reference: "engine".into(),
                stations: vec!["engine".into()],
                window_speeds_rpm: Vec::new(),
                window_times_s: Vec::new(),
                lines_per_rev: vec![None],
                cycle_speeds_rpm: Vec::new(),
            }],
            observations,
            sample_noise_rpm: Vec::new(),
        }
    }

    /// A steady amplitude does not drift; one rising 0.05 rpm/s (1 rpm over 20 s,
    /// ten times the noise) does: its slope's z is 0.05·√262.5/0.1 = 8.1 (the
    /// alternating noise pulls it to 7.5), far above the threshold.
    #[test]
    fn finds_a_drift_and_only_a_drift() {
        let flat = long_run_drift(&long_run(0.0)).expect("a long run");
        assert!(flat < 1.0, "{flat}");
        let rising = long_run_drift(&long_run(0.05)).expect("a long run");
        assert!(rising > 10.0 * DRIFT_CHI2 && rising < 66.0, "{rising}");
    }
}
