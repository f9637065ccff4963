//! A run-up's order tracks averaged in speed bins ([`super::observe::BIN_RPM`]).
//!
//! The bins follow the *measured* speed of each STFT window, and a simulation of the same
//! ramp is binned by the same windows ([`bin_tracks`]), so measured and simulated
//! amplitudes of a bin come from the same stretch of the run.

use super::observe::{BIN_RPM, Observation, Observed};
use crate::signal::Analysis;

/// Hann window's equivalent noise bandwidth, bins.
const HANN_ENBW: f64 = 1.5;
/// Variance of a noise-only window magnitude (Rayleigh) over σ² per component.
const RAYLEIGH_VARIANCE: f64 = 2.0 - std::f64::consts::FRAC_PI_2;
/// The quantile over orders that [`window_scatter`] takes: low, so that the orders that
/// carry only noise set it, not those whose amplitude changes across the bin.
const SCATTER_QUANTILE: f64 = 0.25;

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

/// One window's noise σ per bin, rpm, from the scatter of consecutive windows' track
/// amplitudes within the bin (`tracks[order][window]`): per order `mean((Δa)²)/2`
/// (differences remove the sweep's slow trend), its [`SCATTER_QUANTILE`] over orders,
/// taken as a noise-only magnitude's variance. Pulse jitter makes the noise grow with
/// speed², so one value per record understates it at the top of a run-up. 0 where a bin
/// has fewer than two consecutive windows.
pub(super) fn window_scatter(
    tracks: &[Vec<f64>],
    window_bins: &[Option<usize>],
    n_bins: usize,
) -> Vec<f64> {
    (0..n_bins)
        .map(|b| {
            let mut per_order: Vec<f64> = tracks
                .iter()
                .filter_map(|track| {
                    let (sum, n) = track
                        .windows(2)
                        .zip(window_bins.windows(2))
                        .filter(|(_, w)| w[0] == Some(b) && w[1] == Some(b))
                        .map(|(a, _)| (a[1] - a[0]).powi(2) / 2.0)
                        .filter(|v| v.is_finite())
                        .fold((0.0, 0usize), |(s, n), v| (s + v, n + 1));
                    (n > 0).then(|| sum / n as f64)
                })
                .collect();
            if per_order.is_empty() {
                return 0.0;
            }
            per_order.sort_by(f64::total_cmp);
            let k = ((per_order.len() - 1) as f64 * SCATTER_QUANTILE).round() as usize;
            (per_order[k] / RAYLEIGH_VARIANCE).sqrt()
        })
        .collect()
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
        let sigma_record = sigma_n * (2.0 / window_samples).sqrt() * HANN_ENBW.sqrt();
        let scatter = station
            .stft
            .as_ref()
            .map(|s| window_scatter(&s.order_tracks_rpm, &window_bins, speeds.len()))
            .unwrap_or_default();
        for (order, track) in stft.orders.iter().zip(tracks) {
            for (b, (&a, &v)) in track.iter().zip(&speeds).enumerate() {
                if !(a.is_finite() && v.is_finite()) {
                    continue;
                }
                // Half-overlapping windows: about one independent estimate per 1.5.
                let independent = (count[b] as f64 / 1.5).max(1.0);
                // Floating-point resolution of the speed: a finite z for a noise-free
                // record (the quantisation floor is in `noise` already).
                let tiny = f64::EPSILON * v.abs().max(1.0);
                let sigma_window = sigma_record.max(scatter.get(b).copied().unwrap_or(0.0));
                observed.observations.push(Observation {
                    run,
                    part: b,
                    station: station.name.clone(),
                    order: *order,
                    speed_rpm: v,
                    time_s: middle,
                    measured_rpm: a,
                    sigma_rpm: (sigma_window / independent.sqrt()).max(tiny),
                    bias_sigma_rpm: sigma_window.max(tiny),
                });
            }
        }
    }
}
