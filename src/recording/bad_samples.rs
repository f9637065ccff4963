//! Over-range and impossible samples in a recording (issue 13, "Bounds derived from
//! physics and memory"): a DAQ writes 1e300, 9.9e37 or NaN where a channel was out of
//! range, and one such sample used to crash the order analysis.
//!
//! A sample is bad when it is not finite, or, in a speed column (`<node>_rpm`), when it
//! is below 0 rpm, above 3 × the running median of its column over one revolution, or
//! above [`crate::limits::Limits::max_speed_rpm`]. The running median is the median of
//! the revolution-long block the sample lies in (one revolution at the column's median
//! speed; at least [`MIN_BLOCK`] samples), floored at [`MEDIAN_FLOOR_RPM`] so that a
//! shaft starting from standstill is not flagged. In torque and angle columns only
//! non-finite samples are bad.
//!
//! [`BadSamples`] says what to do with them: refuse (the default), interpolate, or drop.

use super::types::{Channel, ChannelKind};

/// Times the running median above which a speed sample is an over-range marker.
pub const MEDIAN_FACTOR: f64 = 3.0;
/// Floor of the running median, rpm (1 rev/s): a shaft at standstill has median 0.
pub const MEDIAN_FLOOR_RPM: f64 = 60.0;
/// Fewest samples of a median block.
pub const MIN_BLOCK: usize = 16;
/// Bad samples listed in a message; the rest are counted.
const LISTED: usize = 5;

/// What to do with bad samples (`--bad-samples`).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum BadSamples {
    /// Refuse the recording, listing the first few and the count (the default).
    #[default]
    Refuse,
    /// Replace each run of bad samples by the straight line between the good samples
    /// either side (the nearest good one at an end); a run longer than one revolution
    /// is refused (that would invent data).
    Interpolate,
    /// Keep the longest stretch of rows without a bad sample in any column.
    Drop,
}

impl BadSamples {
    /// The spelling of `--bad-samples`: `refuse`, `interpolate` or `drop`.
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Refuse => "refuse",
            Self::Interpolate => "interpolate",
            Self::Drop => "drop",
        }
    }

    /// Parses `refuse`, `interpolate` or `drop`.
    pub fn parse(text: &str) -> Option<Self> {
        [Self::Refuse, Self::Interpolate, Self::Drop]
            .into_iter()
            .find(|b| b.as_str() == text)
    }
}

/// One bad sample.
#[derive(Debug, Clone, PartialEq)]
pub struct BadSample {
    /// Index of the channel in [`crate::recording::Recording::channels`].
    pub channel: usize,
    /// Sample (row) index, 0-based.
    pub row: usize,
    /// The value as read.
    pub value: f64,
    /// The running median it was compared with, rpm (speed columns).
    pub median_rpm: Option<f64>,
}

/// Every bad sample of `channels` sampled every `dt_s` seconds, by channel then row.
pub fn find(channels: &[Channel], dt_s: f64) -> Vec<BadSample> {
    let max_rpm = crate::limits::current().max_speed_rpm;
    let mut bad = Vec::new();
    for (c, channel) in channels.iter().enumerate() {
        let values = &channel.values;
        if !matches!(channel.kind, ChannelKind::SpeedRpm { .. }) {
            let rows = values.iter().enumerate().filter(|(_, v)| !v.is_finite());
            bad.extend(rows.map(|(row, &value)| BadSample {
                channel: c,
                row,
                value,
                median_rpm: None,
            }));
            continue;
        }
        let block = block_len(values, dt_s);
        for (b, chunk) in values.chunks(block).enumerate() {
            let median = median(chunk).unwrap_or(0.0).max(MEDIAN_FLOOR_RPM);
            let limit = (MEDIAN_FACTOR * median).min(max_rpm);
            for (i, &value) in chunk.iter().enumerate() {
                if !(0.0..=limit).contains(&value) {
                    bad.push(BadSample {
                        channel: c,
                        row: b * block + i,
                        value,
                        median_rpm: Some(median),
                    });
                }
            }
        }
    }
    bad
}

/// Samples per revolution at the column's median speed (at least [`MIN_BLOCK`]).
fn block_len(values: &[f64], dt_s: f64) -> usize {
    let stride = (values.len() / 100_000).max(1);
    let sample: Vec<f64> = values.iter().step_by(stride).copied().collect();
    let rpm = median(&sample).unwrap_or(0.0);
    let per_rev = 60.0 / (rpm.clamp(MEDIAN_FLOOR_RPM, 1e9) * dt_s);
    if per_rev.is_finite() {
        (per_rev.round() as usize).clamp(MIN_BLOCK, values.len().max(MIN_BLOCK))
    } else {
        values.len().max(MIN_BLOCK)
    }
}

/// Median of the finite values, `None` when there are none.
fn median(values: &[f64]) -> Option<f64> {
    let mut finite: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
    if finite.is_empty() {
        return None;
    }
    let mid = finite.len() / 2;
    let (_, m, _) = finite.select_nth_unstable_by(mid, f64::total_cmp);
    Some(*m)
}

/// "`engine_rpm` line 5002 = 1e300 (median 3000 rpm), …, and 3 more": the first few bad
/// samples with the file line of each (`lines[row]`).
pub fn describe(bad: &[BadSample], channels: &[Channel], lines: &[usize]) -> String {
    let mut sorted: Vec<&BadSample> = bad.iter().collect();
    sorted.sort_by_key(|b| (b.row, b.channel));
    let mut parts: Vec<String> = sorted
        .iter()
        .take(LISTED)
        .map(|b| {
            let line = lines.get(b.row).copied().unwrap_or(b.row + 1);
            let median = b
                .median_rpm
                .map(|m| format!(" (running median {m:.1} rpm)"))
                .unwrap_or_default();
            format!(
                "`{}` line {line} = {:e}{median}",
                channels[b.channel].column, b.value
            )
        })
        .collect();
    if bad.len() > LISTED {
        parts.push(format!("and {} more", bad.len() - LISTED));
    }
    parts.join(", ")
}

/// Replaces each run of bad samples by the line between its good neighbours. Returns
/// the longest run (samples) and its channel index, for the caller to refuse when it
/// is longer than a revolution; a channel with no good sample is left as it is and
/// reported as a run of its whole length.
pub fn interpolate(channels: &mut [Channel], bad: &[BadSample]) -> (usize, usize) {
    let mut longest = (0, 0);
    for (c, channel) in channels.iter_mut().enumerate() {
        let mut is_bad = vec![false; channel.values.len()];
        bad.iter()
            .filter(|b| b.channel == c)
            .for_each(|b| is_bad[b.row] = true);
        let values = &mut channel.values;
        let n = values.len();
        let mut k = 0;
        while k < n {
            if !is_bad[k] {
                k += 1;
                continue;
            }
            let start = k;
            while k < n && is_bad[k] {
                k += 1;
            }
            if k - start > longest.0 {
                longest = (k - start, c);
            }
            let before = start.checked_sub(1).map(|i| values[i]);
            let after = (k < n).then(|| values[k]);
            let (a, b) = match (before, after) {
                (Some(a), Some(b)) => (a, b),
                (Some(a), None) => (a, a),
                (None, Some(b)) => (b, b),
                (None, None) => continue,
            };
            let span = (k - start + 1) as f64;
            for (j, v) in values[start..k].iter_mut().enumerate() {
                *v = a + (b - a) * (j + 1) as f64 / span;
            }
        }
    }
    longest
}

/// The longest stretch of rows `[start, end)` with no bad sample in any column.
pub fn longest_clean_stretch(rows: usize, bad: &[BadSample]) -> (usize, usize) {
    let mut is_bad = vec![false; rows];
    bad.iter().for_each(|b| is_bad[b.row] = true);
    let (mut best, mut start) = ((0, 0), 0);
    for (k, &bad) in is_bad.iter().chain(std::iter::once(&true)).enumerate() {
        if bad {
            if k - start > best.1 - best.0 {
                best = (start, k);
            }
            start = k + 1;
        }
    }
    best
}
