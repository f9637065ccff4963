//! The bench's own order analysis (issue 14, item 4; used by [`crate::visibility`]): the
//! Fourier coefficient of each station's measured speed against the crank's own angle,
//! per engine order (0.5 to [`MAX_ORDER`], up to 0.4 of the sampling rate), under a Hann
//! window over each steady record, over each third of a long run and over each
//! [`RUNUP_WINDOW_S`] of a run-up, with each window's straight line removed exactly.
//!
//! Written by hand: the bench shares no code with torsim, and a windowed Fourier sum over
//! the truth's own crank angle is a few lines.

use crate::draw::Case;
use std::f64::consts::PI;

/// Length of a run-up's analysis window, s.
pub const RUNUP_WINDOW_S: f64 = 0.5;
/// Highest engine order compared.
pub const MAX_ORDER: f64 = 12.0;
/// Blocks a long run is cut into (a drift shows as a change from one to the next).
pub const LONG_RUN_BLOCKS: usize = 3;

/// Fourier sums of one recording's windows: `[window][station][order]`, with what it
/// takes to remove each window's straight line (a held speed's mean, a run-up's ramp)
/// exactly, so that its leakage through the window's side lobes reaches no order.
#[derive(Debug, Clone)]
pub struct OrderMeter {
    window_len: usize,
    windows: Vec<Window>,
    samples: usize,
    /// Scratch: e^{−ikθ} of the current sample per order, shared by every station.
    phasors: Vec<(f64, f64)>,
}

/// The sums of one window; `x` is the position in the window, −½ to ½.
#[derive(Debug, Clone)]
struct Window {
    /// Σw·v·e^{−ikθ} per station and order.
    sums: Vec<Vec<(f64, f64)>>,
    /// Σw·e^{−ikθ} and Σw·x·e^{−ikθ} per order.
    e0: Vec<(f64, f64)>,
    e1: Vec<(f64, f64)>,
    /// Σw·v and Σw·v·x per station.
    v0: Vec<f64>,
    v1: Vec<f64>,
    /// Σw, Σw·x, Σw·x², Σw².
    w0: f64,
    w1: f64,
    w2: f64,
    ww: f64,
}

impl OrderMeter {
    /// A meter for `n_samples` samples at `rate_hz` of `stations` stations, a run-up in
    /// [`RUNUP_WINDOW_S`] windows, a long run in thirds, a steady regime whole; orders up
    /// to 0.4 of the rate at `top_rpm`.
    pub fn new(
        n_samples: usize,
        rate_hz: f64,
        stations: usize,
        run_up: bool,
        long_run: bool,
        top_rpm: f64,
    ) -> Self {
        let window_len = if run_up {
            (RUNUP_WINDOW_S * rate_hz).round() as usize
        } else if long_run {
            n_samples / LONG_RUN_BLOCKS
        } else {
            n_samples
        }
        .max(2);
        let nyquist_order = 0.4 * rate_hz * 60.0 / top_rpm.max(1.0);
        let orders = (2.0 * MAX_ORDER.min(nyquist_order)).floor().max(0.0) as usize;
        let window = Window {
            sums: vec![vec![(0.0, 0.0); orders]; stations],
            e0: vec![(0.0, 0.0); orders],
            e1: vec![(0.0, 0.0); orders],
            v0: vec![0.0; stations],
            v1: vec![0.0; stations],
            w0: 0.0,
            w1: 0.0,
            w2: 0.0,
            ww: 0.0,
        };
        OrderMeter {
            window_len,
            windows: vec![window; n_samples / window_len],
            samples: 0,
            phasors: vec![(0.0, 0.0); orders],
        }
    }

    /// Adds one sample: the crank's angle `crank_rad` and each station's measured speed.
    pub fn add(&mut self, crank_rad: f64, rpm: &[f64]) {
        let (w_idx, pos) = (
            self.samples / self.window_len,
            self.samples % self.window_len,
        );
        self.samples += 1;
        let Some(win) = self.windows.get_mut(w_idx) else {
            return;
        };
        let u = (pos as f64 + 0.5) / self.window_len as f64;
        let (w, x) = ((PI * u).sin().powi(2), u - 0.5);
        win.w0 += w;
        win.w1 += w * x;
        win.w2 += w * x * x;
        win.ww += w * w;
        // e^{−i·θ/2}, raised order by order (orders 0.5, 1, 1.5, … of the crank), once
        // per sample for the window's sums and every station's.
        let (s, c) = (-0.5 * crank_rad).sin_cos();
        let (mut re, mut im) = (c, s);
        for p in self.phasors.iter_mut() {
            *p = (re, im);
            (re, im) = (re * c - im * s, re * s + im * c);
        }
        for ((e0, e1), (re, im)) in win.e0.iter_mut().zip(win.e1.iter_mut()).zip(&self.phasors) {
            *e0 = (e0.0 + w * re, e0.1 + w * im);
            *e1 = (e1.0 + w * x * re, e1.1 + w * x * im);
        }
        for (k, (station, v)) in win.sums.iter_mut().zip(rpm).enumerate() {
            win.v0[k] += w * v;
            win.v1[k] += w * x * v;
            for (sum, (re, im)) in station.iter_mut().zip(&self.phasors) {
                sum.0 += w * v * re;
                sum.1 += w * v * im;
            }
        }
    }

    /// Per window, station and order: the amplitude (rpm) of the speed less its
    /// weighted straight line, and the white noise's standard deviation per component for
    /// a unit noise σ.
    pub fn amplitudes(&self) -> Vec<(f64, Vec<Vec<f64>>)> {
        self.windows
            .iter()
            .filter(|w| w.w0 > 0.0)
            .map(|win| {
                let det = win.w0 * win.w2 - win.w1 * win.w1;
                let amps = win
                    .sums
                    .iter()
                    .zip(win.v0.iter().zip(&win.v1))
                    .map(|(st, (v0, v1))| {
                        // The weighted least-squares line m + s·x of this station's speed.
                        let m = (win.w2 * v0 - win.w1 * v1) / det;
                        let sl = (win.w0 * v1 - win.w1 * v0) / det;
                        st.iter()
                            .zip(win.e0.iter().zip(&win.e1))
                            .map(|((a, b), (e0, e1))| {
                                let re = a - m * e0.0 - sl * e1.0;
                                let im = b - m * e0.1 - sl * e1.1;
                                2.0 * re.hypot(im) / win.w0
                            })
                            .collect()
                    })
                    .collect();
                ((2.0 * win.ww).sqrt() / win.w0, amps)
            })
            .collect()
    }
}

/// The meter of recording `idx` of `case`.
pub fn meter_for(case: &Case, idx: usize) -> OrderMeter {
    let rec = &case.campaign.recordings[idx];
    let rate = case.campaign.rate_hz;
    OrderMeter::new(
        (rec.duration_s * rate).round() as usize,
        rate,
        case.campaign.stations.len(),
        rec.run_up,
        rec.stem == "long-run",
        rec.from_rpm.max(rec.to_rpm),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    /// A station's speed with known orders 0.5 and 3 at a constant crank speed: the meter
    /// gives their amplitudes, and nothing at an order the signal lacks. Hann leakage over
    /// 40 cycles is below 1e-6 of the amplitude; the crank's vibration is left out.
    #[test]
    fn the_meter_reads_known_orders() {
        let (rate, rpm) = (2048.0, 1500.0);
        let omega = rpm * TAU / 60.0;
        let n = (rate * 40.0 * 120.0 / rpm) as usize;
        let mut m = OrderMeter::new(n, rate, 1, false, false, rpm);
        for i in 0..n {
            let theta = omega * i as f64 / rate + 0.3;
            let v = rpm + 7.0 * (3.0 * theta + 1.1).cos() + 0.25 * (0.5 * theta - 0.4).sin();
            m.add(theta, &[v]);
        }
        let amps = m.amplitudes();
        assert_eq!(amps.len(), 1);
        let a = &amps[0].1[0];
        assert!((a[5] - 7.0).abs() < 7e-6, "order 3: {}", a[5]);
        assert!((a[0] - 0.25).abs() < 1e-6, "order 0.5: {}", a[0]);
        assert!(a[3] < 1e-6, "order 2: {}", a[3]);
        // The noise factor of a Hann window: √(2·Σw²)/Σw → √(3/N).
        let unit = amps[0].0;
        assert!(
            (unit / (3.0 / n as f64).sqrt() - 1.0).abs() < 1e-3,
            "{unit}"
        );
    }

    /// White noise alone reads as the factor says: the mean square of a pure-noise
    /// order's amplitude is 2σ²·factor² (two components), within 10 % over 400 windows.
    #[test]
    fn the_noise_factor_is_the_noise_seen() {
        let mut rng = crate::rng::Rng::new(7, 1);
        let (rate, rpm) = (1000.0, 1200.0);
        let n = 400 * 500;
        let mut m = OrderMeter::new(n, rate, 1, true, false, rpm);
        let omega = rpm * TAU / 60.0;
        for i in 0..n {
            m.add(omega * i as f64 / rate, &[rng.normal()]);
        }
        let amps = m.amplitudes();
        let unit = amps[0].0;
        let ms: f64 = amps.iter().map(|(_, a)| a[0][6].powi(2)).sum::<f64>() / amps.len() as f64;
        let ratio = ms / (2.0 * unit * unit);
        assert!((ratio - 1.0).abs() < 0.1, "{ratio}");
    }
}
