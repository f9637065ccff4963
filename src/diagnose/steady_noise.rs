//! The σ of a steady record's order amplitudes, from their scatter over [`PARTS`] parts of
//! the record: the station's noise, pooled over its orders, and each order's own scatter
//! where it is far above that noise.
//!
//! For each order, with `a_k` its amplitude in part `k` and `A_w` the whole record's,
//! `E[a_k²] = A² + 2s²` and `A_w² = A² + 2s²/P`, so `2s²(1 − 1/P) = mean(a_k²) − A_w²`
//! (s the per-component noise of one part, `s/√P` that of the whole record).
//!
//! - **The station's noise** is the median of that over the orders: white noise is the
//!   same at every order, and the median resists the orders whose parts differ by more
//!   than noise (the bench's slow wobble of the speed on a resonance).
//! - **An order that is not stationary** keeps its own σ: one whose scatter is more than
//!   [`NONSTATIONARY`] times the station's. A gear that rattles in its play drives
//!   orders whose phase wanders from part to part (development seed 2054, regime E: order
//!   10 at 0.42, 0.98, 0.15 and 0.85 rpm in the four quarters, against a noise of
//!   0.013 rpm). The whole record's coherent average of such an order is not a
//!   deterministic quantity, and no model, the truth's included, predicts it closer than
//!   its scatter; with the pooled σ those few orders decided the backlash fit (the true
//!   0.228° scored 5× worse than 0.027°). A speed wobble that moves a resonance does the
//!   same on its order, which no steady simulation at the set speed reproduces either.
//!
//! A long run's blocks do not use the gate ([`super::observe`]): the drift of their
//! amplitudes is what they measure.
//!
//! With noise alone an order's own σ estimate has about 6 degrees of freedom, so it
//! exceeds three times the true σ with a probability near 1e-9: the gate does not touch a
//! stationary record.

use super::observe::slice;
use crate::recording::Recording;
use crate::signal::{Analysis, AnalysisOptions, analyse_with};

/// Parts of a record whose scatter gives the noise.
pub const PARTS: usize = 4;
/// An order's own scatter σ above this multiple of its station's noise makes it
/// non-stationary, and its σ its own.
pub const NONSTATIONARY: f64 = 3.0;

/// The noise of one steady record's order amplitudes.
#[derive(Debug, Clone, PartialEq)]
pub struct SteadyNoise {
    /// σ of a whole-record amplitude, per station (rpm).
    pub station_rpm: Vec<f64>,
    /// Per station, the orders that are not stationary and their own σ, rpm.
    pub nonstationary: Vec<Vec<(f64, f64)>>,
}

impl SteadyNoise {
    /// The noise of station `s`, never below `floor` (rpm).
    pub fn noise_rpm(&self, s: usize, floor: f64) -> f64 {
        self.station_rpm
            .get(s)
            .copied()
            .unwrap_or(f64::NAN)
            .max(floor)
    }

    /// The σ of order `order` at station `s`, never below `floor` (rpm): its own where
    /// it is not stationary, else the station's.
    pub fn sigma_rpm(&self, s: usize, order: f64, floor: f64) -> f64 {
        let station = self.noise_rpm(s, floor);
        self.nonstationary
            .get(s)
            .and_then(|v| v.iter().find(|(o, _)| *o == order))
            .map_or(station, |(_, own)| own.max(station))
    }
}

/// σ of a whole-record amplitude from the spread of the parts' amplitudes `parts` about
/// the whole record's `whole` (rpm): `√(2s²/P)` with `2s²(1 − 1/P) = mean(a_k²) − A_w²`.
fn sigma_from(parts: &[f64], whole: f64) -> f64 {
    let p = parts.len() as f64;
    let mean_sq = parts.iter().map(|x| x * x).sum::<f64>() / p;
    let excess = (mean_sq - whole * whole).max(0.0);
    (excess / (2.0 * (1.0 - 1.0 / p)) / p).sqrt()
}

/// The noise of `rec` (`whole`: its analysis; `duration`: its length, s) from its
/// [`PARTS`] parts, analysed with `options`.
pub fn steady_noise(
    rec: &Recording,
    duration: f64,
    options: &AnalysisOptions,
    whole: &Analysis,
) -> Result<SteadyNoise, String> {
    let parts: Vec<Analysis> = (0..PARTS)
        .map(|k| {
            let (a, b) = (
                duration * k as f64 / PARTS as f64,
                duration * (k + 1) as f64 / PARTS as f64,
            );
            analyse_with(&slice(rec, a, b), options).map_err(|e| e.to_string())
        })
        .collect::<Result<_, _>>()?;
    let mut noise = SteadyNoise {
        station_rpm: Vec::new(),
        nonstationary: Vec::new(),
    };
    for s in 0..whole.stations.len() {
        let Some(first) = parts[0].stations.get(s) else {
            noise.station_rpm.push(f64::NAN);
            noise.nonstationary.push(Vec::new());
            continue;
        };
        let mut own: Vec<(f64, f64)> = Vec::new();
        for (k, o) in first
            .orders
            .iter()
            .enumerate()
            .filter(|(_, o)| o.order > 0.0)
        {
            let xs: Vec<f64> = parts
                .iter()
                .filter_map(|p| p.stations.get(s)?.orders.get(k))
                .filter(|x| x.order == o.order)
                .map(|x| x.amplitude)
                .collect();
            let w = whole.stations[s].orders.iter().find(|x| x.order == o.order);
            if let (true, Some(w)) = (xs.len() == PARTS, w) {
                own.push((o.order, sigma_from(&xs, w.amplitude)));
            }
        }
        let mut sorted: Vec<f64> = own.iter().map(|(_, s)| *s).collect();
        sorted.sort_by(f64::total_cmp);
        let station = sorted.get(sorted.len() / 2).copied().unwrap_or(0.0);
        own.retain(|(_, s)| *s > NONSTATIONARY * station);
        noise.station_rpm.push(station);
        noise.nonstationary.push(own);
    }
    Ok(noise)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_scatter_of_the_parts_gives_the_whole_records_sigma() {
        // Parts 1 ± δ about a whole record of A_w: mean(a²) − A_w² = 2s²(1 − 1/P).
        let parts = [1.1, 0.9, 1.1, 0.9];
        let whole = 1.0;
        let mean_sq = (1.21 + 0.81 + 1.21 + 0.81) / 4.0;
        let expected = ((mean_sq - 1.0) / (2.0 * 0.75) / 4.0_f64).sqrt();
        assert!((sigma_from(&parts, whole) - expected).abs() < 1e-15);
        // Parts no larger than the whole: no noise, never a NaN.
        assert_eq!(sigma_from(&[1.0; 4], 1.0), 0.0);
        assert_eq!(sigma_from(&[0.5; 4], 1.0), 0.0);
    }

    #[test]
    fn only_an_order_far_above_the_station_noise_keeps_its_own_sigma() {
        let noise = SteadyNoise {
            station_rpm: vec![0.01],
            nonstationary: vec![vec![(10.0, 0.2)]],
        };
        assert_eq!(noise.sigma_rpm(0, 10.0, 0.0), 0.2, "the rattling order");
        assert_eq!(noise.sigma_rpm(0, 3.0, 0.0), 0.01, "a stationary order");
        assert_eq!(noise.sigma_rpm(0, 3.0, 0.05), 0.05, "never below the floor");
        assert_eq!(
            noise.sigma_rpm(1, 3.0, 0.02),
            0.02,
            "no such station: the floor"
        );
    }
}
