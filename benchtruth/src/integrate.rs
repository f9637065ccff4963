//! benchtruth's own integrator: the classical fourth-order Runge–Kutta scheme with a fixed
//! step. Chosen for its simplicity and accuracy on smooth, lightly damped oscillators:
//! at ≥ 40 steps per period of the highest mode its amplitude error is about
//! (ωh)⁶/144 ≈ 3·10⁻⁷ per step (ωh = 2π/40), its phase error (ωh)⁴/120 per step; the
//! stiff Maxwell branches (rate λ) stay stable while λ·h < 2.78. The step is chosen in
//! `plant.rs`: at most 1/40 of the shortest natural period, of the fastest branch's
//! relaxation time over 2, and of the sample interval.

// The stage loops index five parallel arrays; an index reads clearer than zips.
#![allow(clippy::needless_range_loop)]

/// A first-order system `dy/dt = f(t, y)`.
pub trait System {
    /// Writes dy/dt into `dy`.
    fn derivative(&self, t: f64, y: &[f64], dy: &mut [f64]);
}

/// Work space of the RK4 stepper (no allocation per step).
#[derive(Debug, Clone)]
pub struct Rk4 {
    k1: Vec<f64>,
    k2: Vec<f64>,
    k3: Vec<f64>,
    k4: Vec<f64>,
    tmp: Vec<f64>,
}

impl Rk4 {
    /// A stepper for states of length `n`.
    pub fn new(n: usize) -> Self {
        Rk4 {
            k1: vec![0.0; n],
            k2: vec![0.0; n],
            k3: vec![0.0; n],
            k4: vec![0.0; n],
            tmp: vec![0.0; n],
        }
    }

    /// Advances `y` from `t` to `t + h`.
    pub fn step(&mut self, sys: &impl System, t: f64, h: f64, y: &mut [f64]) {
        let n = y.len();
        sys.derivative(t, y, &mut self.k1);
        for i in 0..n {
            self.tmp[i] = y[i] + 0.5 * h * self.k1[i];
        }
        sys.derivative(t + 0.5 * h, &self.tmp, &mut self.k2);
        for i in 0..n {
            self.tmp[i] = y[i] + 0.5 * h * self.k2[i];
        }
        sys.derivative(t + 0.5 * h, &self.tmp, &mut self.k3);
        for i in 0..n {
            self.tmp[i] = y[i] + h * self.k3[i];
        }
        sys.derivative(t + h, &self.tmp, &mut self.k4);
        for i in 0..n {
            y[i] += h / 6.0 * (self.k1[i] + 2.0 * self.k2[i] + 2.0 * self.k3[i] + self.k4[i]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two inertias J1, J2 joined by a spring k and a damper c, free-free.
    struct TwoMass {
        j: [f64; 2],
        k: f64,
        c: f64,
    }

    impl System for TwoMass {
        fn derivative(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
            let t = self.k * (y[0] - y[1]) + self.c * (y[2] - y[3]);
            dy[0] = y[2];
            dy[1] = y[3];
            dy[2] = -t / self.j[0];
            dy[3] = t / self.j[1];
        }
    }

    fn energy(s: &TwoMass, y: &[f64]) -> f64 {
        0.5 * s.j[0] * y[2] * y[2] + 0.5 * s.j[1] * y[3] * y[3] + 0.5 * s.k * (y[0] - y[1]).powi(2)
    }

    #[test]
    fn two_dof_free_vibration_has_the_closed_form_frequency() {
        // ω = √(k·(1/J1 + 1/J2)) = √(1e4·(1/0.5 + 1/2)) = 158.11 rad/s (25.16 Hz).
        let s = TwoMass {
            j: [0.5, 2.0],
            k: 1.0e4,
            c: 0.0,
        };
        let w = (s.k * (1.0 / s.j[0] + 1.0 / s.j[1])).sqrt();
        let h = std::f64::consts::TAU / w / 40.0;
        let mut y = vec![0.01, 0.0, 0.0, 0.0];
        let mut rk = Rk4::new(4);
        let mut crossings = Vec::new();
        let mut prev = y[0] - y[1];
        let e0 = energy(&s, &y);
        for i in 0..(40 * 100) {
            rk.step(&s, i as f64 * h, h, &mut y);
            let d = y[0] - y[1];
            if prev < 0.0 && d >= 0.0 {
                // linear interpolation of the upward zero crossing
                crossings.push((i as f64 + prev / (prev - d)) * h);
            }
            prev = d;
        }
        let period = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
        // RK4 phase error at 40 steps per period ≈ (ωh)⁴/120 ≈ 2·10⁻⁵ relative.
        assert!(
            (period * w / std::f64::consts::TAU - 1.0).abs() < 1e-4,
            "{period}"
        );
        // Undamped: energy drift over 100 periods ≈ 100·40·3·10⁻⁷ ≈ 1.2·10⁻³ at most.
        assert!((energy(&s, &y) / e0 - 1.0).abs() < 2e-3);
    }

    #[test]
    fn damped_energy_balance_holds() {
        // E(0) − E(t) = ∫ c·Δθ̇² dt (trapezoidal sum of the dissipation).
        let s = TwoMass {
            j: [0.5, 2.0],
            k: 1.0e4,
            c: 5.0,
        };
        let h = 1e-4;
        let mut y = vec![0.0, 0.0, 10.0, 0.0];
        let mut rk = Rk4::new(4);
        let e0 = energy(&s, &y);
        let mut lost = 0.0;
        let mut p_prev = s.c * (y[2] - y[3]).powi(2);
        for i in 0..20000 {
            rk.step(&s, i as f64 * h, h, &mut y);
            let p = s.c * (y[2] - y[3]).powi(2);
            lost += 0.5 * h * (p + p_prev);
            p_prev = p;
        }
        let e1 = energy(&s, &y);
        assert!(e1 < 0.5 * e0, "the damper must take energy out");
        // trapezoid error on a 25 Hz power signal at h = 1e-4 s is ≈ 1e-4 relative
        assert!(
            ((e0 - e1) / lost - 1.0).abs() < 1e-3,
            "{} vs {}",
            e0 - e1,
            lost
        );
    }
}
