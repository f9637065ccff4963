//! Dormand–Prince 5(4) with error control (Hairer, Nørsett & Wanner, Solving ODEs I,
//! §II.4–5): seven stages with the first-same-as-last property, a PI step-size controller,
//! and cubic Hermite dense output between accepted steps (local error O(h⁴), below the
//! step's own error at the step sizes the controller picks).
//!
//! Written here rather than taken from a crate because the runs need, in one loop: dense
//! output at an arbitrary rate, a scratch buffer shared with the right-hand side, a stop
//! with the time and the state that blew up, a step size that says when it collapses, and
//! cancellation from a GUI thread.

use super::TransientError;

const C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];
const A: [[f64; 6]; 7] = [
    [0.0; 6],
    [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];
/// 5th-order weights minus the embedded 4th-order ones.
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// Smallest step allowed relative to the time, before the step counts as collapsed.
const MIN_STEP_RELATIVE: f64 = 1e-13;
/// ln 1e-4: the smallest last error the step controller remembers (Hairer's DOPRI5).
const LN_ERR_FLOOR: f64 = -9.210_340_371_976_182;

/// The integrator's state between calls.
pub struct Dopri5 {
    /// Current time, s.
    pub t: f64,
    /// Current state.
    pub y: Vec<f64>,
    /// Derivative at the current state (first stage of the next step).
    pub f: Vec<f64>,
    /// Time, state and derivative at the start of the last accepted step.
    pub t_prev: f64,
    y_prev: Vec<f64>,
    f_prev: Vec<f64>,
    k: [Vec<f64>; 6],
    y_stage: Vec<f64>,
    /// The step's error estimate per state (scratch).
    error: Vec<f64>,
    /// Proposed next step, s.
    pub h: f64,
    /// Largest step allowed, s.
    pub h_max: f64,
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance per state.
    pub atol: Vec<f64>,
    /// ln of the last accepted step's error (at least [`LN_ERR_FLOOR`]), for the PI
    /// controller.
    ln_err_prev: f64,
    /// Accepted and rejected steps so far.
    pub steps: (u64, u64),
    /// Index of the state with the largest scaled error in the last step tried (the one
    /// that holds the step size back).
    pub worst_state: usize,
}

impl Dopri5 {
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
            k: std::array::from_fn(|_| vec![0.0; n]),
            y_stage: vec![0.0; n],
            error: vec![0.0; n],
            h: h0.min(h_max),
            h_max,
            rtol,
            atol,
            ln_err_prev: LN_ERR_FLOOR,
            steps: (0, 0),
            worst_state: 0,
        }
    }

    /// Takes one accepted step, not beyond `t_end`.
    pub fn step<F: FnMut(f64, &[f64], &mut [f64])>(
        &mut self,
        t_end: f64,
        rhs: &mut F,
    ) -> Result<(), TransientError> {
        let n = self.y.len();
        loop {
            let h = self.h.min(self.h_max).min(t_end - self.t);
            if h <= MIN_STEP_RELATIVE * self.t.abs().max(1.0) {
                return Err(TransientError::StepCollapse {
                    time_s: self.t,
                    step_s: h,
                    state: format!("state #{}", self.worst_state),
                });
            }
            // Stages 2..7; stage 7 is evaluated at the new point (FSAL).
            // Each stage's sum runs over the state a term at a time (in the same order for
            // every entry as a sum per entry, so the same numbers), which vectorizes.
            for s in 1..7 {
                let a = &A[s];
                for (acc, f) in self.y_stage.iter_mut().zip(&self.f) {
                    *acc = a[0] * f;
                }
                for (kj, c) in self.k.iter().zip(&a[1..]).take(s - 1) {
                    for (acc, k) in self.y_stage.iter_mut().zip(kj) {
                        *acc += c * k;
                    }
                }
                for (acc, y) in self.y_stage.iter_mut().zip(&self.y) {
                    *acc = y + h * *acc;
                }
                let (t_s, out) = (self.t + C[s] * h, s - 1);
                rhs(t_s, &self.y_stage, &mut self.k[out]);
            }
            // y_stage holds the 5th-order solution (stage 7's argument); k[5] its f.
            let e = &mut self.error;
            for (e, f) in e.iter_mut().zip(&self.f) {
                *e = E[0] * f;
            }
            for (kj, c) in self.k.iter().zip(&E[1..]) {
                for (e, k) in e.iter_mut().zip(kj) {
                    *e += c * k;
                }
            }
            let mut sum = 0.0;
            let states = self.y.iter().zip(&self.y_stage).zip(&self.atol);
            for (e, ((y, y_new), atol)) in e.iter().zip(states) {
                let scale = atol + self.rtol * y.abs().max(y_new.abs());
                let r = h * e / scale;
                sum += r * r;
            }
            let err = (sum / n as f64).sqrt();
            // A NaN error counts as a failure too.
            if err.is_nan() || err > 1.0 {
                self.worst_state = self.worst_component(h);
            }
            if !err.is_finite() {
                self.h = 0.2 * h;
                self.steps.1 += 1;
                continue;
            }
            if err <= 1.0 {
                // PI controller (β = 0.04, as in Hairer's DOPRI5).
                // err^−0.17 · err_prev^0.04 as one exponential of the kept logarithm (two
                // `pow` calls a step were 3 % of a thermal-drift diagnosis, `perf`).
                let ln_err = err.max(1e-10).ln();
                let factor =
                    (0.9 * (-0.17 * ln_err + 0.04 * self.ln_err_prev).exp()).clamp(0.2, 5.0);
                self.ln_err_prev = ln_err.max(LN_ERR_FLOOR);
                std::mem::swap(&mut self.y_prev, &mut self.y);
                std::mem::swap(&mut self.f_prev, &mut self.f);
                self.y.copy_from_slice(&self.y_stage);
                self.f.copy_from_slice(&self.k[5]);
                self.t_prev = self.t;
                self.t += h;
                self.h = h * factor;
                self.steps.0 += 1;
                return Ok(());
            }
            self.h = h * (0.9 * err.powf(-0.2)).clamp(0.2, 1.0);
            self.steps.1 += 1;
        }
    }

    /// Index of the largest scaled error of a step of `h` just tried (stages in `k`); a
    /// non-finite one first. Only computed for rejected steps, to name the culprit.
    fn worst_component(&self, h: f64) -> usize {
        let mut worst = (0, -1.0);
        for i in 0..self.y.len() {
            let mut e = E[0] * self.f[i];
            for (ej, kj) in E[1..].iter().zip(&self.k) {
                e += ej * kj[i];
            }
            let scale = self.atol[i] + self.rtol * self.y[i].abs().max(self.y_stage[i].abs());
            let r = (h * e / scale).abs();
            let r = if r.is_finite() { r } else { f64::INFINITY };
            if r > worst.1 {
                worst = (i, r);
            }
        }
        worst.0
    }

    /// The state at `t` within the last accepted step, by cubic Hermite interpolation.
    pub fn interpolate(&self, t: f64, out: &mut [f64]) {
        hermite(
            (self.t_prev, &self.y_prev, &self.f_prev),
            (self.t, &self.y, &self.f),
            t,
            out,
        );
    }
}

/// Cubic Hermite interpolation at `t` between `(t0, y0, f0)` and `(t1, y1, f1)` (states and
/// derivatives), into `out`.
pub fn hermite(start: (f64, &[f64], &[f64]), end: (f64, &[f64], &[f64]), t: f64, out: &mut [f64]) {
    let ((t0, y0, f0), (t1, y1, f1)) = (start, end);
    let h = t1 - t0;
    if h <= 0.0 {
        out.copy_from_slice(y1);
        return;
    }
    let s = ((t - t0) / h).clamp(0.0, 1.0);
    let (s2, s3) = (s * s, s * s * s);
    let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
    let h10 = s3 - 2.0 * s2 + s;
    let h01 = -2.0 * s3 + 3.0 * s2;
    let h11 = s3 - s2;
    for (i, o) in out.iter_mut().enumerate() {
        *o = h00 * y0[i] + h10 * h * f0[i] + h01 * y1[i] + h11 * h * f1[i];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// y'' = −y from (1, 0): y = cos t. After 20π (ten periods) at rtol 1e-8 the solution
    /// and the dense output at an off-step time agree with cos within 1e-6.
    #[test]
    fn harmonic_oscillator() {
        let mut rhs = |_t: f64, y: &[f64], dy: &mut [f64]| {
            dy[0] = y[1];
            dy[1] = -y[0];
        };
        let t_end = 20.0 * std::f64::consts::PI;
        let mut d = Dopri5::new(
            0.0,
            vec![1.0, 0.0],
            1e-3,
            0.5,
            1e-8,
            vec![1e-10; 2],
            &mut rhs,
        );
        let mut worst: f64 = 0.0;
        while d.t < t_end {
            d.step(t_end, &mut rhs).unwrap();
            let mid = 0.5 * (d.t_prev + d.t);
            let mut y = [0.0; 2];
            d.interpolate(mid, &mut y);
            worst = worst.max((y[0] - mid.cos()).abs());
        }
        assert!(
            (d.y[0] - 1.0).abs() < 1e-6 && d.y[1].abs() < 1e-6,
            "{:?}",
            d.y
        );
        assert!(worst < 1e-6, "dense output error {worst}");
    }
}
