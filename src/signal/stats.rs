//! Time statistics of seed 001: RMS about the mean, the irregularity ratio, and the
//! relative speed across a coupling.

/// Mean of a signal (0 for none).
pub fn mean(values: &[f64]) -> f64 {
    if values.is_empty() {
        0.0
    } else {
        values.iter().sum::<f64>() / values.len() as f64
    }
}

/// RMS of a signal about its mean, in its unit (rpm for IAS). A sine of amplitude `a`
/// sampled over whole periods gives `a / √2`.
pub fn rms_about_mean(values: &[f64]) -> f64 {
    let m = mean(values);
    (values.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / values.len().max(1) as f64).sqrt()
}

/// Irregularity ratio, %: peak-to-peak of `cycle` (a synchronously averaged cycle, rpm)
/// over `mean_speed_rpm` (seed 001's IR). A sine of amplitude `a` gives `2a / mean · 100`.
pub fn irregularity_pct(cycle: &[f64], mean_speed_rpm: f64) -> f64 {
    let (lo, hi) = cycle
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
            (lo.min(x), hi.max(x))
        });
    if cycle.is_empty() {
        return 0.0;
    }
    (hi - lo) / mean_speed_rpm.abs() * 100.0
}

/// Relative speed `n_a − ratio · n_b`, rpm in station a's shaft: `ratio` is the speed of
/// a's shaft over b's (1 for two stations on one shaft, seed 001's `n_es − n_bs`).
pub fn relative_speed(a_rpm: &[f64], b_rpm: &[f64], ratio: f64) -> Vec<f64> {
    a_rpm
        .iter()
        .zip(b_rpm)
        .map(|(a, b)| a - ratio * b)
        .collect()
}
