//! Uniform sampling, judged in one place (issue 13, "Accept what real files are"): the
//! recording reader and [`crate::signal::resample::uniform_interval`] (the analysis, the
//! GUI and the diagnosis) all ask [`judge`].
//!
//! The clock is fitted by least squares, `t_k = t0 + k·dt`; it may start anywhere (a
//! DAQ's 187.648 s). Then:
//! - every interval must lie within [`MIN_INTERVAL_STEPS`] … [`MAX_INTERVAL_STEPS`] steps
//!   (widened by the printed resolution of the time column). Longer is a **gap**, zero or
//!   negative is time **not increasing**, shorter is a **duplicate** (a second clock).
//!   These are the only refusals, and they name the sample. The bounds are what jitter
//!   of up to ±¼ step ([`MAX_JITTER_STEPS`]) can produce, so any such jitter passes
//!   (±20 µs at 10 240 Hz is ±0.2 step) and no jitter is taken for a gap;
//! - when every residual of the fit is within the printed resolution (6 decimals: 1 µs,
//!   5 decimals: 10 µs; a 2048 Hz clock printed to µs rounds by up to 0.1 % of a step)
//!   or within [`IN_MEMORY_TOLERANCE_STEPS`] if that is larger, the clock is uniform and
//!   only rounding scattered it: time stamps printed coarser than that tolerance are
//!   replaced by the fitted grid, finer ones are kept as written;
//! - otherwise the samples are at their true, jittered times, and [`regularize`]
//!   interpolates every channel onto the fitted uniform grid with a local cubic (see
//!   there why cubic) rather than pretend they are uniform.

/// Jitter accepted, steps either side of the fitted grid: ±¼ step keeps every interval
/// within ½ … 1½ steps, so jitter is never mistaken for a gap or a duplicate.
pub const MAX_JITTER_STEPS: f64 = 0.25;
/// Longest interval, steps: longer is a gap (1 + 2 × [`MAX_JITTER_STEPS`]).
pub const MAX_INTERVAL_STEPS: f64 = 1.0 + 2.0 * MAX_JITTER_STEPS;
/// Shortest interval, steps: shorter is a duplicate (1 − 2 × [`MAX_JITTER_STEPS`]).
pub const MIN_INTERVAL_STEPS: f64 = 1.0 - 2.0 * MAX_JITTER_STEPS;
/// Scatter that time stamps held in memory (not printed) may have and still count as
/// uniform, steps: 0.1 % of a step, a phase error of 0.36° at the Nyquist frequency.
pub const IN_MEMORY_TOLERANCE_STEPS: f64 = 1e-3;

/// The fitted clock of a recording.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Timing {
    /// Fitted time of sample 0, s.
    pub t0_s: f64,
    /// Fitted sampling interval, s.
    pub dt_s: f64,
    /// Largest distance of a time stamp from the fitted grid, s.
    pub max_residual_s: f64,
    /// Residual accepted as rounding (the printed resolution, or
    /// [`IN_MEMORY_TOLERANCE_STEPS`] of a step), s.
    pub tolerance_s: f64,
}

impl Timing {
    /// Whether the time stamps are the fitted grid to within rounding (else jittered).
    pub fn is_uniform(&self) -> bool {
        self.max_residual_s <= self.tolerance_s
    }
}

/// Why time stamps cannot be used; `index` is the 0-based sample.
#[derive(Debug, Clone, PartialEq)]
pub enum TimingFault {
    /// Fewer than two samples.
    TooFew,
    /// A time stamp not after the one before.
    NotIncreasing {
        /// The sample.
        index: usize,
        /// Its time, s.
        time_s: f64,
        /// The previous sample's time, s.
        previous_s: f64,
    },
    /// An interval longer than [`MAX_INTERVAL_STEPS`].
    Gap {
        /// The sample after the gap.
        index: usize,
        /// Its time, s.
        time_s: f64,
        /// The sample before the gap, s.
        previous_s: f64,
        /// The sampling interval, s.
        dt_s: f64,
    },
    /// An interval shorter than [`MIN_INTERVAL_STEPS`].
    Duplicate {
        /// The second sample.
        index: usize,
        /// Its time, s.
        time_s: f64,
        /// The previous sample's time, s.
        previous_s: f64,
        /// The sampling interval, s.
        dt_s: f64,
    },
}

impl TimingFault {
    /// The offending sample, 0-based.
    pub fn index(&self) -> Option<usize> {
        match self {
            Self::TooFew => None,
            Self::NotIncreasing { index, .. }
            | Self::Gap { index, .. }
            | Self::Duplicate { index, .. } => Some(*index),
        }
    }
}

impl std::fmt::Display for TimingFault {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::TooFew => write!(f, "fewer than two samples"),
            Self::NotIncreasing {
                time_s, previous_s, ..
            } => write!(
                f,
                "time {time_s} s is not after the previous {previous_s} s (time must increase)"
            ),
            Self::Gap {
                time_s,
                previous_s,
                dt_s,
                ..
            } => write!(
                f,
                "gap in the sampling: {:.6} s from the sample at {previous_s} s to this one at \
                 {time_s} s, {:.1} steps of {:.3} µs (more than {MAX_INTERVAL_STEPS} steps is \
                 a gap, not jitter; cut the recording at the gap)",
                time_s - previous_s,
                (time_s - previous_s) / dt_s,
                dt_s * 1e6
            ),
            Self::Duplicate {
                time_s,
                previous_s,
                dt_s,
                ..
            } => write!(
                f,
                "duplicate sample: {time_s} s is only {:.3} steps of {:.3} µs after \
                 {previous_s} s (less than {MIN_INTERVAL_STEPS} step is a repeated sample or a \
                 second clock, not jitter)",
                (time_s - previous_s) / dt_s,
                dt_s * 1e6
            ),
        }
    }
}

/// Judges time stamps: see the module docs. `resolution_s` is the printed resolution of
/// the time column (`None` for time stamps held in memory: [`IN_MEMORY_TOLERANCE_STEPS`]).
pub fn judge(time_s: &[f64], resolution_s: Option<f64>) -> Result<Timing, TimingFault> {
    let n = time_s.len();
    if n < 2 {
        return Err(TimingFault::TooFew);
    }
    for k in 1..n {
        if time_s[k].is_nan() || time_s[k] <= time_s[k - 1] {
            return Err(TimingFault::NotIncreasing {
                index: k,
                time_s: time_s[k],
                previous_s: time_s[k - 1],
            });
        }
    }
    let (t0_s, dt_s) = fit(time_s);
    // Round-off of the parsed values themselves: a few ulps of the largest time.
    let ulps = 8.0 * f64::EPSILON * time_s[0].abs().max(time_s[n - 1].abs());
    // Scatter below the in-memory tolerance is rounding whatever the printing: a grid
    // this reader fitted and wrote with every digit carries ~10 ulps of the fit's own
    // round-off, and must read back as the uniform clock it is (the recording fuzzer's
    // a99bd10d: 2.8e-16 s of scatter on re-reading was taken for jitter and resampled
    // again, so the written CSV did not read back equal).
    let in_memory_s = IN_MEMORY_TOLERANCE_STEPS * dt_s;
    let tolerance_s = resolution_s.map_or(in_memory_s, |r| r.max(in_memory_s)) + ulps;
    // Intervals are judged against the median one: a gap skews the fitted step.
    let step_s = median_interval(time_s);
    let (lo, hi) = (
        MIN_INTERVAL_STEPS * step_s - tolerance_s,
        MAX_INTERVAL_STEPS * step_s + tolerance_s,
    );
    let mut max_residual_s: f64 = 0.0;
    for k in 0..n {
        max_residual_s = max_residual_s.max((time_s[k] - t0_s - k as f64 * dt_s).abs());
        if k == 0 {
            continue;
        }
        let (time_s, previous_s) = (time_s[k], time_s[k - 1]);
        let interval = time_s - previous_s;
        if interval > hi {
            return Err(TimingFault::Gap {
                index: k,
                time_s,
                previous_s,
                dt_s: step_s,
            });
        }
        if interval < lo {
            return Err(TimingFault::Duplicate {
                index: k,
                time_s,
                previous_s,
                dt_s: step_s,
            });
        }
    }
    Ok(Timing {
        t0_s,
        dt_s,
        max_residual_s,
        tolerance_s,
    })
}

/// The median sampling interval, s, of at most ~100 000 intervals spread over the
/// recording (so a 2²⁷-sample file needs no second copy of its time column).
fn median_interval(time_s: &[f64]) -> f64 {
    let stride = (time_s.len() / 100_000).max(1);
    let mut intervals: Vec<f64> = (1..time_s.len())
        .step_by(stride)
        .map(|k| time_s[k] - time_s[k - 1])
        .collect();
    let mid = intervals.len() / 2;
    let (_, median, _) = intervals.select_nth_unstable_by(mid, f64::total_cmp);
    *median
}

/// Least-squares line `t_k = t0 + k·dt` through the time stamps, in offsets from the
/// first one (so a clock at 187 s keeps its microseconds).
fn fit(time_s: &[f64]) -> (f64, f64) {
    let n = time_s.len() as f64;
    let origin = time_s[0];
    let k_mean = (n - 1.0) / 2.0;
    let t_mean = time_s.iter().map(|t| t - origin).sum::<f64>() / n;
    let (mut skt, mut skk) = (0.0, 0.0);
    for (k, t) in time_s.iter().enumerate() {
        let dk = k as f64 - k_mean;
        skt += dk * (t - origin - t_mean);
        skk += dk * dk;
    }
    let dt = skt / skk;
    (origin + t_mean - dt * k_mean, dt)
}

/// The uniform grid of `timing` over the span of `time_s`: the fitted points from the
/// first at or after the first sample to the last at or before the last sample.
pub fn grid(time_s: &[f64], timing: &Timing) -> Vec<f64> {
    let (first, last) = (time_s[0], time_s[time_s.len() - 1]);
    let (t0, dt) = (timing.t0_s, timing.dt_s);
    let k0 = ((first - t0) / dt - 1e-9).ceil();
    let k1 = ((last - t0) / dt + 1e-9).floor();
    let count = (k1 - k0 + 1.0).max(0.0) as usize;
    (0..count).map(|j| t0 + (k0 + j as f64) * dt).collect()
}

/// Jittered samples onto the uniform grid of `timing` over their span: every column of
/// `columns` (sampled at `time_s`) is replaced by its [`cubic_onto`] the grid, which is
/// returned.
pub fn regularize(time_s: &[f64], timing: &Timing, columns: &mut [&mut Vec<f64>]) -> Vec<f64> {
    let grid = grid(time_s, timing);
    for values in columns.iter_mut() {
        **values = cubic_onto(time_s, values, &grid);
    }
    grid
}

/// `values` sampled at the (jittered) `time_s`, interpolated at the uniform `grid_s`.
///
/// A local cubic: the Lagrange cubic through the two samples either side of each grid
/// point (one-sided at the ends). Band-limited reconstruction from non-uniform samples
/// has no closed-form kernel (it needs a global iterative solve); the cubic is exact for
/// cubics, needs no solve, and its error vanishes with the jitter: with the grid point
/// δ from a sample, it is about (δ/Δt)·(ωΔt)⁴/12 of an amplitude, 3e-6 for an order with
/// 40 samples per period at δ = 0.2 step, 2.6e-3 at 10 samples per period.
pub fn cubic_onto(time_s: &[f64], values: &[f64], grid_s: &[f64]) -> Vec<f64> {
    let n = time_s.len();
    let mut out = Vec::with_capacity(grid_s.len());
    let mut k = 0;
    for &t in grid_s {
        while k + 2 < n && time_s[k + 1] <= t {
            k += 1;
        }
        // Nodes k-1 ..= k+2, shifted inside the data at the ends.
        let start = k.saturating_sub(1).min(n.saturating_sub(4));
        let end = (start + 4).min(n);
        let mut sum = 0.0;
        for i in start..end {
            let mut w = 1.0;
            for j in start..end {
                if j != i {
                    w *= (t - time_s[j]) / (time_s[i] - time_s[j]);
                }
            }
            sum += w * values[i];
        }
        out.push(sum);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 2048 Hz printed to µs: rounding up to 0.1 % of a step is uniform, not jitter.
    #[test]
    fn microsecond_rounding_is_uniform() {
        let t: Vec<f64> = (0..4096)
            .map(|k| ((187.648 + k as f64 / 2048.0) * 1e6).round() / 1e6)
            .collect();
        let timing = judge(&t, Some(1e-6)).expect("uniform");
        assert!(timing.is_uniform(), "{timing:?}");
        // The fitted step is the true one to well under the rounding over 4096 samples.
        assert!((timing.dt_s - 1.0 / 2048.0).abs() < 1e-9, "{}", timing.dt_s);
    }

    /// A cubic is reproduced exactly from jittered nodes.
    #[test]
    fn cubic_is_exact_for_cubics() {
        let t: Vec<f64> = (0..50)
            .map(|k| k as f64 + 0.2 * (k as f64 * 1.7).sin())
            .collect();
        let f = |x: f64| 1.0 + x - 0.03 * x * x + 0.0004 * x * x * x;
        let v: Vec<f64> = t.iter().map(|&x| f(x)).collect();
        let g: Vec<f64> = (1..49).map(|k| k as f64).collect();
        for (x, y) in g.iter().zip(cubic_onto(&t, &v, &g)) {
            assert!((y - f(*x)).abs() < 1e-9, "{x}: {y}");
        }
    }

    #[test]
    fn gaps_and_duplicates_name_the_sample() {
        let mut t: Vec<f64> = (0..1000).map(|k| k as f64 / 1000.0).collect();
        for x in &mut t[400..] {
            *x += 0.1;
        }
        let e = judge(&t, None).expect_err("gap");
        assert_eq!(e.index(), Some(400));
        assert!(e.to_string().contains("at 0.399 s"), "{e}");
        let mut t: Vec<f64> = (0..1000).map(|k| k as f64 / 1000.0).collect();
        t[500] = t[499] + 1e-5;
        assert_eq!(judge(&t, None).expect_err("dup").index(), Some(500));
    }
}
