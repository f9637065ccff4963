//! A run-up's order tracks averaged in speed bins ([`super::observe::BIN_RPM`]).
//!
//! The bins follow the *measured* speed of each STFT window, and a simulation of the same
//! ramp is binned by the same windows ([`bin_tracks`]), so measured and simulated
//! amplitudes of a bin come from the same stretch of the run.

use super::observe::{BIN_RPM, Observation, Observed};
use crate::signal::Analysis;

/// Hann window's equivalent noise bandwidth, bins.
const HANN_ENBW: f64 = 1.5;
/// Fewest windows a bin needs.
const MIN_WINDOWS: usize = 2;

/// Per bin, `sum / count`, or `NaN` for a bin with fewer than [`MIN_WINDOWS`] windows.
pub fn bin_means(sum: &[f64], count: &[usize]) -> Vec<f64> {
    sum.iter()
        .zip(count)
        .map(|(s, c)| {
            if *c >= MIN_WINDOWS {
                s / *c as f64
            } else {
                f64::NAN
            }
        })
        .collect()
}

/// The bin of each window (`None` below the first full bin), and the bins' mean speeds.
pub fn bins(window_speeds_rpm: &[f64]) -> (Vec<Option<usize>>, Vec<f64>) {
    let lo = window_speeds_rpm
        .iter()
        .copied()
        .fold(f64::INFINITY, f64::min);
    let lo = (lo / BIN_RPM).floor() * BIN_RPM;
    let index: Vec<Option<usize>> = window_speeds_rpm
        .iter()
        .map(|v| {
            let b = ((v - lo) / BIN_RPM).floor();
            (b.is_finite() && b >= 0.0).then_some(b as usize)
        })
        .collect();
    let n_bins = index.iter().flatten().max().map_or(0, |m| m + 1);
    let mut sum = vec![0.0; n_bins];
    let mut count = vec![0usize; n_bins];
    for (b, v) in index.iter().zip(window_speeds_rpm) {
        if let Some(b) = b {
            sum[*b] += v;
            count[*b] += 1;
        }
    }
    (index, bin_means(&sum, &count))
}

/// Per station (in `analysis` order), order and bin: the mean track amplitude over the
/// bin's windows (`NaN` for a bin with too few windows), `[station][order][bin]`, with
/// the window count per bin.
pub fn bin_tracks(
    analysis: &Analysis,
    window_bins: &[Option<usize>],
    n_bins: usize,
) -> (Vec<Vec<Vec<f64>>>, Vec<usize>) {
    let mut count = vec![0usize; n_bins];
    for b in window_bins.iter().flatten() {
        if *b < n_bins {
            count[*b] += 1;
        }
    }
    let tracks = analysis
        .stations
        .iter()
        .map(|s| {
            let Some(stft) = &s.stft else {
                return Vec::new();
            };
            stft.order_tracks_rpm
                .iter()
                .map(|track| {
                    let mut sum = vec![0.0; n_bins];
                    for (w, a) in track.iter().enumerate() {
                        if let Some(Some(b)) = window_bins.get(w)
                            && *b < n_bins
                        {
                            sum[*b] += a;
                        }
                    }
                    bin_means(&sum, &count)
                })
                .collect()
        })
        .collect();
    (tracks, count)
}

/// Pushes the binned order tracks of run-up `run` (`noise`: sample noise per station of
/// `analysis`, rpm).
pub fn push_run_up(observed: &mut Observed, run: usize, analysis: &Analysis, noise: &[f64]) {
    let Some(stft) = &analysis.stft else {
        return;
    };
    let r = &observed.runs[run];
    let (window_bins, speeds) = bins(&r.window_speeds_rpm);
    let (tracks, count) = bin_tracks(analysis, &window_bins, speeds.len());
    let window_samples = (0.1 * r.rate_hz).max(1.0);
    let middle = r.duration_s / 2.0;
    for ((station, tracks), sigma_n) in analysis.stations.iter().zip(&tracks).zip(noise) {
        let sigma_window = sigma_n * (2.0 / window_samples).sqrt() * HANN_ENBW.sqrt();
        for (order, track) in stft.orders.iter().zip(tracks) {
            for (b, (&a, &v)) in track.iter().zip(&speeds).enumerate() {
                if !(a.is_finite() && v.is_finite()) {
                    continue;
                }
                // Half-overlapping windows: about one independent estimate per 1.5.
                let independent = (count[b] as f64 / 1.5).max(1.0);
                observed.observations.push(Observation {
                    run,
                    part: b,
                    station: station.name.clone(),
                    order: *order,
                    speed_rpm: v,
                    time_s: middle,
                    measured_rpm: a,
                    sigma_rpm: (sigma_window / independent.sqrt()).max(1e-4),
                });
            }
        }
    }
}
