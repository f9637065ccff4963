//! The slow wobble of a bench's mean speed: the brake's speed control hunts a little, so the
//! whole driveline turns a fraction of a percent faster and slower over seconds.
//!
//! It is applied as a time warp of the simulated run: bench time `t` shows the driveline
//! as it was at simulation time `τ(t) = t + ∫₀ᵗ w`, so every shaft's angle is
//! `θ(τ(t))` and its speed `(1 + w(t))·θ̇(τ(t))`, with the relative speed deviation
//! `w(t) = a·(0.7·sin(2πt/P + φ₁) + 0.3·sin(2πt·2.7/P + φ₂))` (`|w| ≤ a`). The vibration
//! keeps its shape per crank angle — exactly right for orders far from a resonance; near
//! one, the response to a speed a fraction `a` off differs by about `a` times the slope
//! of the resonance curve, which a wobble of 0.1–0.5 % keeps small. The phases come from
//! the seed.

use crate::effects::rng::Rng;
use std::f64::consts::TAU;

/// The wobble of one recording.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wobble {
    /// Amplitude bound `a` (relative, e.g. 0.002 for 0.2 %).
    pub amplitude: f64,
    /// Period `P` of the main component, s.
    pub period_s: f64,
    /// Phases φ₁, φ₂, rad.
    pub phases: [f64; 2],
}

/// Ratio of the second component's frequency to the first's.
const SECOND: f64 = 2.7;

impl Wobble {
    /// A wobble of `amplitude_pct` % and main period `period_s`, phases from `rng`.
    pub fn new(amplitude_pct: f64, period_s: f64, rng: &mut Rng) -> Self {
        Self {
            amplitude: amplitude_pct / 100.0,
            period_s,
            phases: [rng.uniform_in(0.0, TAU), rng.uniform_in(0.0, TAU)],
        }
    }

    /// No wobble.
    pub fn none() -> Self {
        Self {
            amplitude: 0.0,
            period_s: 1.0,
            phases: [0.0; 2],
        }
    }

    fn parts(&self) -> [(f64, f64, f64); 2] {
        let w = TAU / self.period_s;
        [
            (0.7 * self.amplitude, w, self.phases[0]),
            (0.3 * self.amplitude, w * SECOND, self.phases[1]),
        ]
    }

    /// Relative speed deviation `w(t)`.
    pub fn deviation(&self, t: f64) -> f64 {
        self.parts()
            .iter()
            .map(|(a, w, p)| a * (w * t + p).sin())
            .sum()
    }

    /// `∫₀ᵗ w`, s.
    pub fn integral(&self, t: f64) -> f64 {
        self.parts()
            .iter()
            .map(|(a, w, p)| a / w * (p.cos() - (w * t + p).cos()))
            .sum()
    }

    /// A bound on `|∫₀ᵗ w|` for every t, s.
    pub fn max_shift_s(&self) -> f64 {
        self.parts().iter().map(|(a, w, _)| 2.0 * a / w).sum()
    }

    /// The bench time `t` at which the driveline is where the simulation was at `tau`
    /// (the inverse of `τ(t) = t + ∫₀ᵗ w`; Newton's method, `|w| < 1`).
    pub fn bench_time(&self, tau: f64) -> f64 {
        if self.amplitude == 0.0 {
            return tau;
        }
        let mut t = tau - self.integral(tau);
        for _ in 0..4 {
            t -= (t + self.integral(t) - tau) / (1.0 + self.deviation(t));
        }
        t
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn warp_inverts_and_integrates() {
        let mut rng = Rng::new(1);
        let w = Wobble::new(0.5, 5.0, &mut rng);
        for k in 0..200 {
            let t = -3.0 + 0.17 * k as f64;
            let tau = t + w.integral(t);
            assert!((w.bench_time(tau) - t).abs() < 1e-12);
            // d/dt of the integral is the deviation (central difference, h = 1e-4).
            let h = 1e-4;
            let d = (w.integral(t + h) - w.integral(t - h)) / (2.0 * h);
            assert!((d - w.deviation(t)).abs() < 1e-9);
            assert!(w.deviation(t).abs() <= 0.005 + 1e-15);
            assert!(w.integral(t).abs() <= w.max_shift_s());
        }
        assert_eq!(Wobble::none().bench_time(2.5), 2.5);
    }
}
