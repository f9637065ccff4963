//! The IAS of one station as a bench makes it: pulse times where the shaft passes each
//! line of its tape or encoder, moved by the wobble's time warp and by timing jitter; the
//! speed of each line interval (nominal pitch over measured time, at the interval's
//! middle); those speeds interpolated (4-point Lagrange) onto a grid at `factor` × the
//! output rate; the anti-aliasing FIR ([`super::fir`]) down to the output rate.
//!
//! What a perfect chain still does to the signal, and so what the recordings honestly
//! contain: each interval averages the speed over one line pitch, which scales shaft
//! order `k` by `sinc(k/N)` (−1 % at k/N = 0.078, e.g. engine order 2 on a 78-line tape
//! turning at 1/3 of engine speed); content above 0.45 × the output rate is filtered out.

use super::fir::Decimator;
use super::shaft_angle::ShaftAngle;
use super::wobble::Wobble;
use crate::effects::rng::Rng;
use std::f64::consts::TAU;

/// How one station's pulses become samples.
pub struct Chain<'a> {
    /// Line angles of one revolution, rad (from [`super::sensor::line_angles`]).
    pub lines: &'a [f64],
    /// Angle of line 0 from the shaft's angle 0 at the simulation's start, rad.
    pub offset_rad: f64,
    /// The bench's speed wobble.
    pub wobble: &'a Wobble,
    /// Simulation time at bench time 0 (before the warp), s.
    pub origin_s: f64,
    /// Standard deviation of each pulse's timing error, s.
    pub jitter_s: f64,
    /// Output rate, Hz.
    pub rate_hz: f64,
    /// Output samples, from bench time 0.
    pub samples: usize,
    /// The decimating filter (its factor sets the fine grid).
    pub decimator: &'a Decimator,
}

/// 4-point Lagrange interpolation of `(x, y)` at `t`, with `x[k] ≤ t ≤ x[k + 1]`.
fn lagrange4(x: &[f64], y: &[f64], k: usize, t: f64) -> f64 {
    let lo = k.saturating_sub(1).min(x.len() - 4);
    let xs = &x[lo..lo + 4];
    let ys = &y[lo..lo + 4];
    let mut sum = 0.0;
    for i in 0..4 {
        let mut w = 1.0;
        for j in 0..4 {
            if i != j {
                w *= (t - xs[j]) / (xs[i] - xs[j]);
            }
        }
        sum += w * ys[i];
    }
    sum
}

/// The measured IAS of `shaft` (simulation time, rad and rad/s) at the output rate, rpm.
/// Errors say why the pulses cannot make the samples asked for.
pub fn measure(shaft: &ShaftAngle, chain: &Chain, rng: &mut Rng) -> Result<Vec<f64>, String> {
    let n_lines = chain.lines.len();
    let total = shaft.total_angle();
    let mut targets = Vec::with_capacity((total / TAU * n_lines as f64) as usize + n_lines);
    let mut rev = -1.0;
    'revs: loop {
        for &line in chain.lines {
            let a = rev * TAU + line + chain.offset_rad;
            if a >= total {
                break 'revs;
            }
            if a > 0.0 {
                targets.push(a);
            }
        }
        rev += 1.0;
    }
    let sim_times = shaft.crossing_times(&targets).ok_or(
        "the shaft turns backwards at some moment (vibration larger than the mean speed): \
         no tape or encoder could measure it",
    )?;
    let mut times: Vec<f64> = sim_times
        .iter()
        .map(|tau| chain.wobble.bench_time(tau - chain.origin_s))
        .collect();
    if chain.jitter_s > 0.0 {
        for t in &mut times {
            *t += chain.jitter_s * rng.normal();
        }
    }
    if let Some(i) = times.windows(2).position(|w| w[1] <= w[0]) {
        return Err(format!(
            "pulse times do not increase near bench time {:.6} s: the timing jitter is too \
             large for the line rate",
            times[i]
        ));
    }
    let pitch = TAU / n_lines as f64;
    let mids: Vec<f64> = times.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
    let speeds: Vec<f64> = times.windows(2).map(|w| pitch / (w[1] - w[0])).collect();
    let d = chain.decimator;
    let fine_rate = chain.rate_hz * d.factor as f64;
    let n_fine = (chain.samples - 1) * d.factor + 2 * d.half + 1;
    let first = -(d.half as f64) / fine_rate;
    let last = first + (n_fine - 1) as f64 / fine_rate;
    if mids.len() < 4 || mids[1] > first || mids[mids.len() - 2] < last {
        return Err(format!(
            "the pulses cover bench time {:.4} … {:.4} s, not the {:.4} … {:.4} s needed \
             (a bug in the run's margins)",
            mids.first().copied().unwrap_or(0.0),
            mids.last().copied().unwrap_or(0.0),
            first,
            last
        ));
    }
    let mut fine = Vec::with_capacity(n_fine);
    let mut k = 0;
    for j in 0..n_fine {
        let t = first + j as f64 / fine_rate;
        while k + 2 < mids.len() && mids[k + 1] <= t {
            k += 1;
        }
        fine.push(lagrange4(&mids, &speeds, k, t));
    }
    Ok((0..chain.samples)
        .map(|i| d.output(&fine, i) * 60.0 / TAU)
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A shaft at 1500 rpm with a 30 rpm order-2 vibration, 360 lines, no jitter or
    /// wobble: the samples match the speed within the line averaging (sinc(2/360), 5e-5
    /// relative) and the interpolation, 0.01 rpm.
    #[test]
    fn perfect_chain_reproduces_the_speed() {
        let w0 = 1500.0 * TAU / 60.0;
        let a = 30.0 * TAU / 60.0;
        let h = 1.0 / 8192.0;
        let n = 8192 * 2;
        let speed = |t: f64| w0 + a * (2.0 * 25.0 * TAU * t).sin();
        let v: Vec<f64> = (0..n).map(|i| speed(i as f64 * h)).collect();
        let shaft = ShaftAngle::new(0.0, h, v);
        let lines: Vec<f64> = (0..360).map(|k| k as f64 * TAU / 360.0).collect();
        let decimator = Decimator::new(4);
        let chain = Chain {
            lines: &lines,
            offset_rad: 0.3,
            wobble: &Wobble::none(),
            origin_s: 0.2,
            jitter_s: 0.0,
            rate_hz: 2048.0,
            samples: 2048,
            decimator: &decimator,
        };
        let out = measure(&shaft, &chain, &mut Rng::new(1)).unwrap();
        let worst = out
            .iter()
            .enumerate()
            .map(|(i, x)| (x - speed(0.2 + i as f64 / 2048.0) * 60.0 / TAU).abs())
            .fold(0.0, f64::max);
        assert!(worst < 0.01, "{worst}");
    }
}
