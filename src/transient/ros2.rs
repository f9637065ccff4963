//! ROS2, a linearly implicit (Rosenbrock W-) method of order 2, L-stable, for stiff models
//! (Verwer, Spee, Blom & Hundsdorfer, SIAM J. Sci. Comput. 20, 1999):
//!
//! `(I − γhJ)k₁ = f(tₙ, yₙ)`, `(I − γhJ)k₂ = f(tₙ + h, yₙ + hk₁) − 2k₁`,
//! `yₙ₊₁ = yₙ + (3/2)hk₁ + (1/2)hk₂`, `γ = 1 + 1/√2`, with the embedded first-order
//! `yₙ + hk₁` for error control. Order 2 holds for any approximation J of the Jacobian, so J
//! is computed by finite differences only now and then, and `I − γhJ` refactored only when
//! the step changes by more than 20 %. Dense output is the cubic Hermite of [`super::dopri`].
//!
//! It pays where stability, not accuracy, limits an explicit method: very stiff gear meshes,
//! fast Maxwell arms. For the oscillatory drivelines shipped, Dormand–Prince is faster at the
//! same accuracy (measured: see `RunOptions::method`).

use super::TransientError;
use crate::response::lu::LuWorkspace;
use nalgebra::DMatrix;

const GAMMA: f64 = 1.0 + std::f64::consts::FRAC_1_SQRT_2;
/// Accepted steps between Jacobian updates.
const JACOBIAN_EVERY: u64 = 50;

/// The integrator's state between calls.
pub struct Ros2 {
    /// Current time, s.
    pub t: f64,
    /// Current state.
    pub y: Vec<f64>,
    f: Vec<f64>,
    /// Time at the start of the last accepted step.
    pub t_prev: f64,
    y_prev: Vec<f64>,
    f_prev: Vec<f64>,
    jacobian: DMatrix<f64>,
    /// The step `I − γhJ` was last factored for, s; `None` when it must be (re)factored.
    factor_h: Option<f64>,
    /// `I − γhJ` factored in place ([`LuWorkspace::factor`]).
    factored: DMatrix<f64>,
    lu: LuWorkspace,
    /// Per-step buffers: the stages, ∂f/∂t, the stage state and the new state.
    k1: Vec<f64>,
    k2: Vec<f64>,
    f_t: Vec<f64>,
    stage: Vec<f64>,
    y_new: Vec<f64>,
    since_jacobian: u64,
    /// Proposed next step, s.
    pub h: f64,
    /// Largest step allowed, s.
    pub h_max: f64,
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance per state.
    pub atol: Vec<f64>,
    /// Accepted and rejected steps so far.
    pub steps: (u64, u64),
    /// Index of the state with the largest scaled error in the last step tried (the one
    /// that holds the step size back).
    pub worst_state: usize,
    scratch: Vec<f64>,
}

impl Ros2 {
    /// Starts at `t0`, `y0` with first step `h0`.
    pub fn new<F: FnMut(f64, &[f64], &mut [f64])>(
        t0: f64,
        y0: Vec<f64>,
        h0: f64,
        h_max: f64,
        rtol: f64,
        atol: Vec<f64>,
        rhs: &mut F,
    ) -> Self {
        let n = y0.len();
        let mut f = vec![0.0; n];
        rhs(t0, &y0, &mut f);
        Self {
            t: t0,
            t_prev: t0,
            y_prev: y0.clone(),
            f_prev: f.clone(),
            y: y0,
            f,
            jacobian: DMatrix::zeros(n, n),
            factor_h: None,
            factored: DMatrix::zeros(n, n),
            lu: LuWorkspace::default(),
            k1: vec![0.0; n],
            k2: vec![0.0; n],
            f_t: vec![0.0; n],
            stage: vec![0.0; n],
            y_new: vec![0.0; n],
            since_jacobian: JACOBIAN_EVERY,
            h: h0.min(h_max),
            h_max,
            rtol,
            atol,
            steps: (0, 0),
            worst_state: 0,
            scratch: vec![0.0; n],
        }
    }

    /// Forward-difference Jacobian at the current point.
    fn update_jacobian<F: FnMut(f64, &[f64], &mut [f64])>(&mut self, rhs: &mut F) {
        let n = self.y.len();
        let mut y = self.y.clone();
        for j in 0..n {
            let delta = 1e-7 * self.y[j].abs().max(self.atol[j] * 1e3).max(1e-9);
            y[j] += delta;
            rhs(self.t, &y, &mut self.scratch);
            for i in 0..n {
                self.jacobian[(i, j)] = (self.scratch[i] - self.f[i]) / delta;
            }
            y[j] = self.y[j];
        }
        self.since_jacobian = 0;
        self.factor_h = None;
    }

    /// Takes one accepted step, not beyond `t_end`.
    pub fn step<F: FnMut(f64, &[f64], &mut [f64])>(
        &mut self,
        t_end: f64,
        rhs: &mut F,
    ) -> Result<(), TransientError> {
        let n = self.y.len();
        if self.since_jacobian >= JACOBIAN_EVERY {
            self.update_jacobian(rhs);
        }
        loop {
            let h = self.h.min(self.h_max).min(t_end - self.t);
            if h <= 1e-13 * self.t.abs().max(1.0) {
                return Err(TransientError::StepCollapse {
                    time_s: self.t,
                    step_s: h,
                    state: format!("state #{}", self.worst_state),
                });
            }
            let refactor = self.factor_h.is_none_or(|h0| (h / h0 - 1.0).abs() > 0.2);
            if refactor {
                self.factored.copy_from(&self.jacobian);
                self.factored.scale_mut(-(GAMMA * h));
                for i in 0..n {
                    self.factored[(i, i)] += 1.0;
                }
                self.lu.factor(&mut self.factored);
                self.factor_h = Some(h);
            }
            // The factor may belong to a step up to 20 % off: `I − γ·h_lu·J` is `I − γ·h·J'`
            // with `J' = J·h_lu/h`, and a W-method keeps its order for any J'.
            // The model depends on time (the mean rotation): with t as a state, its column
            // of the Jacobian, ∂f/∂t by a forward difference, enters as ±γh·∂f/∂t.
            // √ε-sized step relative to t, taken as the exactly representable difference.
            let dt = (self.t + 1.5e-8 * self.t.abs().max(1.0)) - self.t;
            rhs(self.t + dt, &self.y, &mut self.scratch);
            let f_t = &mut self.f_t;
            for ((d, s), f) in f_t.iter_mut().zip(&self.scratch).zip(&self.f) {
                *d = (s - f) / dt;
            }
            let k1 = &mut self.k1;
            for i in 0..n {
                k1[i] = self.f[i] + GAMMA * h * f_t[i];
            }
            if !self.lu.solve(&self.factored, k1) {
                k1.fill(f64::NAN);
            }
            for ((x, y), k) in self.stage.iter_mut().zip(&self.y).zip(k1.iter()) {
                *x = y + h * k;
            }
            rhs(self.t + h, &self.stage, &mut self.scratch);
            let k2 = &mut self.k2;
            for i in 0..n {
                k2[i] = self.scratch[i] - 2.0 * k1[i] - GAMMA * h * f_t[i];
            }
            if !self.lu.solve(&self.factored, k2) {
                k2.fill(f64::NAN);
            }
            let (k1, k2) = (&self.k1, &self.k2);
            let mut sum = 0.0;
            for i in 0..n {
                self.y_new[i] = self.y[i] + 1.5 * h * k1[i] + 0.5 * h * k2[i];
            }
            let y_new = &self.y_new;
            for i in 0..n {
                let e = 0.5 * h * (k1[i] + k2[i]);
                let scale = self.atol[i] + self.rtol * self.y[i].abs().max(y_new[i].abs());
                sum += (e / scale).powi(2);
            }
            let err = (sum / n as f64).sqrt();
            if !err.is_finite() || err > 1.0 {
                self.worst_state = (0..n)
                    .map(|i| {
                        let e = 0.5 * h * (k1[i] + k2[i]);
                        let scale = self.atol[i] + self.rtol * self.y[i].abs().max(y_new[i].abs());
                        let r = (e / scale).abs();
                        (i, if r.is_finite() { r } else { f64::INFINITY })
                    })
                    .fold((0, -1.0), |w, x| if x.1 > w.1 { x } else { w })
                    .0;
                self.h = h * if err.is_finite() {
                    (0.9 / err.sqrt()).clamp(0.2, 0.9)
                } else {
                    0.2
                };
                self.steps.1 += 1;
                if self.steps.1.is_multiple_of(4) {
                    self.update_jacobian(rhs);
                }
                continue;
            }
            std::mem::swap(&mut self.y_prev, &mut self.y);
            std::mem::swap(&mut self.f_prev, &mut self.f);
            self.y.copy_from_slice(&self.y_new);
            rhs(self.t + h, &self.y, &mut self.f);
            self.t_prev = self.t;
            self.t += h;
            self.h = h * (0.9 / err.max(1e-10).sqrt()).clamp(0.2, 4.0);
            self.steps.0 += 1;
            self.since_jacobian += 1;
            return Ok(());
        }
    }

    /// The state at `t` within the last accepted step, by cubic Hermite interpolation.
    pub fn interpolate(&self, t: f64, out: &mut [f64]) {
        super::dopri::hermite(
            (self.t_prev, &self.y_prev, &self.f_prev),
            (self.t, &self.y, &self.f),
            t,
            out,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stiff test, y₁' = −10⁵(y₁ − cos t) − sin t (solution y₁ = cos t) and y₂' = −y₁:
    /// Dormand–Prince would be held below ~3.3e-5 s by stability; ROS2 takes steps more
    /// than ten times longer (accuracy, not stability, sets them) and stays within 1e-4 of
    /// the exact solution.
    #[test]
    fn stiff_problem_with_large_steps() {
        let mut rhs = |t: f64, y: &[f64], dy: &mut [f64]| {
            dy[0] = -1.0e5 * (y[0] - t.cos()) - t.sin();
            dy[1] = -y[0];
        };
        let mut r = Ros2::new(
            0.0,
            vec![1.0, 0.0],
            1e-4,
            0.1,
            1e-5,
            vec![1e-8; 2],
            &mut rhs,
        );
        while r.t < 10.0 {
            r.step(10.0, &mut rhs).unwrap();
        }
        assert!((r.y[0] - 10f64.cos()).abs() < 1e-4, "{}", r.y[0]);
        assert!((r.y[1] + 10f64.sin()).abs() < 1e-4, "{}", r.y[1]);
        let mean_step = 10.0 / r.steps.0 as f64;
        assert!(mean_step > 3.3e-4, "mean step {mean_step}");
    }

    /// A damped oscillator forced above resonance (ω₀ = 300, ζ = 0.05, ω = 393 rad/s):
    /// the steady amplitude is 1/|ω₀² − ω² + 2iζω₀ω| within 1 %.
    #[test]
    fn forced_oscillator_amplitude() {
        let (w0, z, w) = (300.0_f64, 0.05, 393.0_f64);
        let mut rhs = |t: f64, y: &[f64], dy: &mut [f64]| {
            dy[0] = y[1];
            dy[1] = -w0 * w0 * y[0] - 2.0 * z * w0 * y[1] + (w * t).cos();
        };
        let mut r = Ros2::new(
            0.0,
            vec![0.0, 0.0],
            1e-5,
            1e-3,
            1e-6,
            vec![1e-10; 2],
            &mut rhs,
        );
        let mut peak: f64 = 0.0;
        while r.t < 3.0 {
            r.step(3.0, &mut rhs).unwrap();
            if r.t > 2.0 {
                peak = peak.max(r.y[0].abs());
            }
        }
        let exact = 1.0 / ((w0 * w0 - w * w).powi(2) + (2.0 * z * w0 * w).powi(2)).sqrt();
        assert!((peak - exact).abs() / exact < 0.01, "{peak} vs {exact}");
    }
}
