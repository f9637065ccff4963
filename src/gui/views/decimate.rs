//! Drawing long series cheaply: at most one min/max pair per pixel column of what is on
//! screen. Few samples are drawn as they are; many are drawn as their envelope (a line
//! through thousands of zigzags per pixel is both slow and, with mitred joins, spiky).

/// What to draw of a series at the current zoom.
#[derive(Debug, Clone, PartialEq)]
pub enum Decimated {
    /// Every sample in view (and one either side).
    Points(Vec<[f64; 2]>),
    /// The min and max of each bucket of samples, at the bucket's middle time.
    Envelope {
        /// Middle time of each bucket, s.
        time_s: Vec<f64>,
        /// Smallest value in each bucket.
        min: Vec<f64>,
        /// Largest value in each bucket.
        max: Vec<f64>,
    },
}

/// `(time_s, values − baseline(time_s))` within `x_range`: every sample when there are at
/// most `2 · buckets` of them, else the envelope over `buckets` buckets.
pub fn decimate(
    time_s: &[f64],
    values: &[f64],
    baseline: &dyn Fn(f64) -> f64,
    x_range: [f64; 2],
    buckets: usize,
) -> Decimated {
    let n = time_s.len().min(values.len());
    let lo = time_s[..n]
        .partition_point(|&t| t < x_range[0])
        .saturating_sub(1);
    let hi = (time_s[..n].partition_point(|&t| t <= x_range[1]) + 1).min(n);
    let value = |i: usize| values[i] - baseline(time_s[i]);
    let count = hi.saturating_sub(lo);
    let buckets = buckets.max(1);
    if count <= 2 * buckets {
        return Decimated::Points((lo..hi).map(|i| [time_s[i], value(i)]).collect());
    }
    let per = count.div_ceil(buckets);
    let mut out = (Vec::new(), Vec::new(), Vec::new());
    for start in (lo..hi).step_by(per) {
        let end = (start + per).min(hi);
        let (lo_v, hi_v) = (start..end).fold((f64::MAX, f64::MIN), |(a, b), i| {
            let v = value(i);
            (a.min(v), b.max(v))
        });
        out.0.push(0.5 * (time_s[start] + time_s[end - 1]));
        out.1.push(lo_v);
        out.2.push(hi_v);
    }
    Decimated::Envelope {
        time_s: out.0,
        min: out.1,
        max: out.2,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 1 Hz sine sampled at 10 kHz for 10 s, in 500 buckets: an envelope whose extremes
    /// are the samples' (±1 exactly), in time order; a zoomed range keeps its own samples;
    /// a baseline is subtracted before the extremes are picked.
    #[test]
    fn decimation_keeps_peaks_and_order() {
        let t: Vec<f64> = (0..100_000).map(|i| i as f64 * 1e-4).collect();
        let v: Vec<f64> = t
            .iter()
            .map(|t| (std::f64::consts::TAU * (t + 0.25)).sin())
            .collect();
        let none = |_: f64| 0.0;
        let Decimated::Envelope { time_s, min, max } = decimate(&t, &v, &none, [0.0, 10.0], 500)
        else {
            panic!("100 000 samples make an envelope");
        };
        assert_eq!(time_s.len(), 500);
        assert!(time_s.windows(2).all(|w| w[0] < w[1]));
        let top = max.iter().cloned().fold(f64::MIN, f64::max);
        let bottom = min.iter().cloned().fold(f64::MAX, f64::min);
        assert_eq!(top, v.iter().cloned().fold(f64::MIN, f64::max));
        assert_eq!(bottom, v.iter().cloned().fold(f64::MAX, f64::min));
        assert!(min.iter().zip(&max).all(|(a, b)| a <= b));
        let Decimated::Points(zoom) = decimate(&t, &v, &none, [1.0, 1.01], 500) else {
            panic!("a zoomed range is drawn sample by sample");
        };
        assert!(
            (102..=104).contains(&zoom.len()),
            "the ~101 samples inside and one either side: {}",
            zoom.len()
        );
        assert!(matches!(
            decimate(&t, &v, &none, [20.0, 30.0], 500),
            Decimated::Points(p) if p.len() <= 1
        ));
        // A ramp of 1000 per second under the sine: subtracting it leaves the sine.
        let ramp: Vec<f64> = t.iter().zip(&v).map(|(t, v)| 1000.0 * t + v).collect();
        let Decimated::Envelope { max, .. } =
            decimate(&t, &ramp, &|t| 1000.0 * t, [0.0, 10.0], 500)
        else {
            panic!("envelope");
        };
        let top = max.iter().cloned().fold(f64::MIN, f64::max);
        assert!((top - 1.0).abs() < 1e-9, "{top}");
    }
}
