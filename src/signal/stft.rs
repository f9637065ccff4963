//! Short-time Fourier transform for run-ups (seed 001: 0.1 s windows, 10 Hz resolution):
//! Hann windows with overlap, amplitudes scaled so a sine of amplitude `a` peaks at `a`,
//! and order tracks picked at each window's exact order frequency.

use realfft::RealFftPlanner;

use super::SignalError;

/// How a uniformly sampled signal is cut into windows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Frames {
    /// Samples per window.
    pub len: usize,
    /// Samples between window starts.
    pub hop: usize,
    /// Windows that fit.
    pub count: usize,
}

impl Frames {
    /// Windows of `window_s` seconds overlapping by `overlap` (0 ≤ overlap < 1) over
    /// `samples` samples `dt_s` apart.
    pub fn new(
        samples: usize,
        dt_s: f64,
        window_s: f64,
        overlap: f64,
    ) -> Result<Self, SignalError> {
        if !(window_s > 0.0 && (0.0..1.0).contains(&overlap)) {
            return Err(SignalError::BadOption(format!(
                "STFT window {window_s} s, overlap {overlap}: need a window > 0 and 0 ≤ overlap < 1"
            )));
        }
        let len = (window_s / dt_s).round() as usize;
        if len < 4 || len > samples {
            return Err(SignalError::BadOption(format!(
                "STFT window {window_s} s is {len} samples; the recording has {samples}"
            )));
        }
        let hop = ((len as f64 * (1.0 - overlap)).round() as usize).max(1);
        Ok(Self {
            len,
            hop,
            count: (samples - len) / hop + 1,
        })
    }

    /// First sample of window `i`.
    pub fn start(&self, i: usize) -> usize {
        i * self.hop
    }

    /// The periodic Hann window.
    pub fn hann(&self) -> Vec<f64> {
        (0..self.len)
            .map(|i| 0.5 - 0.5 * (2.0 * std::f64::consts::PI * i as f64 / self.len as f64).cos())
            .collect()
    }

    /// Time of each window's centre, s, for samples from `t0_s` spaced `dt_s`.
    pub fn centres_s(&self, t0_s: f64, dt_s: f64) -> Vec<f64> {
        (0..self.count)
            .map(|i| t0_s + (self.start(i) as f64 + 0.5 * (self.len - 1) as f64) * dt_s)
            .collect()
    }

    /// Mean of `values` over each window (e.g. the reference speed, rpm).
    pub fn means(&self, values: &[f64]) -> Vec<f64> {
        (0..self.count)
            .map(|i| super::stats::mean(&values[self.start(i)..self.start(i) + self.len]))
            .collect()
    }
}

/// A spectrogram: magnitude per window and frequency.
#[derive(Debug, Clone, PartialEq)]
pub struct Stft {
    /// Centre of each window, s.
    pub times_s: Vec<f64>,
    /// Frequency of each line, Hz (0 … Nyquist, step 1 / window).
    pub frequencies_hz: Vec<f64>,
    /// Zero-to-peak amplitude per window (outer) and line (inner), in the signal's unit.
    pub magnitude: Vec<Vec<f64>>,
}

/// The STFT of `values` (uniform, `dt_s` apart, first at `t0_s`): each window's mean is
/// removed, then the Hann window applied.
pub fn stft(values: &[f64], t0_s: f64, dt_s: f64, frames: &Frames) -> Result<Stft, SignalError> {
    let window = frames.hann();
    let gain: f64 = window.iter().sum();
    let plan = RealFftPlanner::<f64>::new().plan_fft_forward(frames.len);
    let mut input = plan.make_input_vec();
    let mut spectrum = plan.make_output_vec();
    let mut magnitude = Vec::with_capacity(frames.count);
    for i in 0..frames.count {
        let chunk = &values[frames.start(i)..frames.start(i) + frames.len];
        let m = super::stats::mean(chunk);
        for ((x, v), w) in input.iter_mut().zip(chunk).zip(&window) {
            *x = (v - m) * w;
        }
        plan.process(&mut input, &mut spectrum)
            .map_err(|e| SignalError::Fft(e.to_string()))?;
        magnitude.push(spectrum.iter().map(|x| 2.0 * x.norm() / gain).collect());
    }
    let df = 1.0 / (frames.len as f64 * dt_s);
    Ok(Stft {
        times_s: frames.centres_s(t0_s, dt_s),
        frequencies_hz: (0..spectrum.len()).map(|k| k as f64 * df).collect(),
        magnitude,
    })
}

/// Order tracks: for each window `i` and order `q`, the Hann-windowed amplitude at the
/// exact frequency `q · speeds_rpm[i] / 60` (no picket-fence loss between STFT lines).
/// Returns one track per order.
///
/// Each order's sum is a rotating phasor, a chain of dependent products per sample. The
/// orders are therefore advanced side by side, sample by sample, so that their chains
/// overlap; each order's own arithmetic, and so its result to the last bit, is the same
/// as summing it alone.
pub fn order_tracks(
    values: &[f64],
    dt_s: f64,
    frames: &Frames,
    speeds_rpm: &[f64],
    orders: &[f64],
) -> Vec<Vec<f64>> {
    let window = frames.hann();
    let gain: f64 = window.iter().sum();
    let n = orders.len();
    let mut tracks = vec![Vec::with_capacity(frames.count); n];
    let mut windowed = vec![0.0; frames.len];
    // Per order: the step's rotation (cos, sin), the phasor and the running sums.
    let (mut cos, mut sin) = (vec![0.0; n], vec![0.0; n]);
    let (mut re, mut im) = (vec![0.0; n], vec![0.0; n]);
    let (mut sum_re, mut sum_im) = (vec![0.0; n], vec![0.0; n]);
    for (i, &speed) in speeds_rpm.iter().enumerate().take(frames.count) {
        let chunk = &values[frames.start(i)..frames.start(i) + frames.len];
        let m = super::stats::mean(chunk);
        for ((x, v), w) in windowed.iter_mut().zip(chunk).zip(&window) {
            *x = (v - m) * w;
        }
        for (o, q) in orders.iter().enumerate() {
            let step = 2.0 * std::f64::consts::PI * q * speed / 60.0 * dt_s;
            (cos[o], sin[o]) = (step.cos(), step.sin());
            (re[o], im[o], sum_re[o], sum_im[o]) = (1.0, 0.0, 0.0, 0.0);
        }
        for &x in &windowed {
            for o in 0..n {
                sum_re[o] += x * re[o];
                sum_im[o] -= x * im[o];
                (re[o], im[o]) = (
                    re[o] * cos[o] - im[o] * sin[o],
                    re[o] * sin[o] + im[o] * cos[o],
                );
            }
        }
        for (track, (a, b)) in tracks.iter_mut().zip(sum_re.iter().zip(&sum_im)) {
            track.push(2.0 * a.hypot(*b) / gain);
        }
    }
    tracks
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Advancing the orders side by side changes nothing: every track equals, to the last
    /// bit, the windowed phasor sum of its order taken alone (written here as it was
    /// before, one order after another), on a wobbling-speed signal with four orders.
    #[test]
    fn orders_side_by_side_equal_each_alone() {
        let dt_s = 1.0 / 2048.0;
        let values: Vec<f64> = (0..8192)
            .map(|k| {
                let t = k as f64 * dt_s;
                1500.0 + 3.0 * (157.0 * t).sin() + 0.7 * (411.0 * t + 0.3).cos() + 1e-3 * t
            })
            .collect();
        let frames = Frames::new(values.len(), dt_s, 0.5, 0.75).expect("valid frames");
        let speeds_rpm: Vec<f64> = (0..frames.count).map(|i| 1500.0 + 7.0 * i as f64).collect();
        let orders = [0.5, 1.0, 2.5, 6.0];
        let tracks = order_tracks(&values, dt_s, &frames, &speeds_rpm, &orders);
        let window = frames.hann();
        let gain: f64 = window.iter().sum();
        for (o, &q) in orders.iter().enumerate() {
            assert_eq!(tracks[o].len(), frames.count);
            for (i, &speed) in speeds_rpm.iter().enumerate() {
                let chunk = &values[frames.start(i)..frames.start(i) + frames.len];
                let m = crate::signal::stats::mean(chunk);
                let step = 2.0 * std::f64::consts::PI * q * speed / 60.0 * dt_s;
                let (c, s) = (step.cos(), step.sin());
                let (mut re, mut im, mut sum_re, mut sum_im) = (1.0, 0.0, 0.0, 0.0);
                for (v, w) in chunk.iter().zip(&window) {
                    let x = (v - m) * w;
                    sum_re += x * re;
                    sum_im -= x * im;
                    (re, im) = (re * c - im * s, re * s + im * c);
                }
                let alone = 2.0 * f64::hypot(sum_re, sum_im) / gain;
                assert_eq!(
                    tracks[o][i].to_bits(),
                    alone.to_bits(),
                    "order {q} window {i}"
                );
            }
        }
    }
}
