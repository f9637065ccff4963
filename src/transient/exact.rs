//! Exact discretization of a linear plant in a steady run (issue 15, item 2): the
//! integrator [`super::Method::Auto`] takes for a model with no engine whose equations are
//! affine in the state (shafts, gear meshes without free play, rubber chains without an
//! amplitude law or self-heating, modal damping, a governor), driven by `[[harmonic]]`s.
//!
//! The state is augmented by a constant 1 and, per harmonic order q, the oscillator
//! `(cos qΩt, sin qΩt)`, which generates the harmonic torques at the mean crank angle
//! exactly. The augmented system `ż = A·z` is then linear and time-invariant, and
//! `z(t + h) = e^{hA}·z(t)` holds to rounding at any step (the Padé exponential of
//! `nalgebra`, scaling and squaring).
//!
//! The remainder `N` is what the harmonics add because they act at the *vibrating* crank
//! angle (the time domain's crank-angle nonlinearity, ~1e-4 of the forcing; its formula
//! and evaluation, without trigonometry per step, are [`super::crank_remainder`]'s).
//! It is integrated by the second-order exponential Runge–Kutta method ETD2RK (Cox &
//! Matthews, *J. Comput. Phys.* 176, 2002, eq. 22), whose `φ1`, `φ2` come from one
//! exponential of a block matrix (Al-Mohy & Higham 2011, Thm. 2.1). The linear part is
//! exact, the remainder second order. (The multistep ETD2 of the same paper, eq. 6, takes
//! one remainder per step instead of two, but was 3.5× less accurate on the driven chain
//! of `tests/transient_exact.rs`: 2.0e-6 of the vibration against 5.6e-7.)
//!
//! The matrix A is not written out by hand: it is probed from the plant's own equations
//! ([`Plant::derivatives`] with the harmonics taken out), so it is what the other
//! integrators integrate. The probe also checks that those equations are affine; a plant
//! that is not goes to Dormand–Prince.
//!
//! Written here: the exponential is nalgebra's; the scheme around it is particular to this
//! plant, and the products a step takes are written out in [`super::exact_step`].

use super::TransientError;
use super::crank_remainder::{Term, mark_columns, remainder_into};
use super::dopri::hermite;
use super::exact_step::{StepMatrices, padded_len};
use super::forces::Scratch;
use super::plant::Plant;
use super::speed::SpeedProfile;
use nalgebra::{DMatrix, DVector};
use std::f64::consts::TAU;

/// Relative tolerance of the affinity probe: `f(2e_j) − f(0) = 2·(f(e_j) − f(0))`.
const AFFINE_TOLERANCE: f64 = 1e-9;

/// The exact integrator of one run.
pub struct Exact {
    /// Current time, s: `base_t + k·h` after `k` whole steps since the last shortened
    /// one, so that the recorded samples fall on step ends without drift.
    pub t: f64,
    base: (f64, u64),
    /// Length of the plant's state (the first entries of the augmented state).
    plant_len: usize,
    /// Steps taken (accepted, rejected: never any).
    pub steps: (u64, u64),
    /// The step, s.
    pub h: f64,
    /// The augmented state, padded to [`padded_len`] (the products' layout).
    z: Vec<f64>,
    a: DMatrix<f64>,
    /// `(e^{hA}, h·φ1(hA)·E, h·φ2(hA)·E)` at the step `h`.
    step_matrices: StepMatrices,
    /// Velocity rows the remainder acts on (E's columns).
    rows: Vec<usize>,
    terms: Vec<Term>,
    reference_dof: usize,
    /// Start of the last step: time and augmented state (for dense output).
    last: (f64, Vec<f64>),
    /// Buffers of a step: the stage and the remainder at its two points.
    scratch: (Vec<f64>, Vec<f64>, Vec<f64>),
}

impl Exact {
    /// The integrator for `plant` at steady `speed_rpm` from `y0` at t = 0 with step `h`,
    /// or `None` when the plant is not linear enough for it (an engine, or equations
    /// that are not affine in the state).
    pub fn new(plant: &Plant, speed_rpm: f64, y0: Vec<f64>, h: f64) -> Option<Self> {
        if plant.engine.is_some() || h.is_nan() || h <= 0.0 {
            return None;
        }
        let m = plant.state_len;
        let n = plant.n_dof;
        let omega = speed_rpm * TAU / 60.0;
        let mut orders: Vec<f64> = Vec::new();
        let mut rows: Vec<usize> = Vec::new();
        let mut terms = Vec::new();
        for hp in &plant.harmonics {
            let oscillator = match orders.iter().position(|q| *q == hp.order) {
                Some(i) => i,
                None => {
                    orders.push(hp.order);
                    orders.len() - 1
                }
            };
            let row = n + hp.dof;
            let column = match rows.iter().position(|r| *r == row) {
                Some(c) => c,
                None => {
                    rows.push(row);
                    rows.len() - 1
                }
            };
            terms.push(Term {
                cos_state: m + 1 + 2 * oscillator,
                column,
                starts_column: false,
                coefficient: hp.ratio * hp.amplitude_nm(speed_rpm) / plant.inertia_kg_m2[hp.dof],
                phase: (hp.phase_rad.cos(), hp.phase_rad.sin()),
                order: hp.order,
            });
        }
        mark_columns(&mut terms);
        let s = m + 1 + 2 * orders.len();
        let mut a = DMatrix::<f64>::zeros(s, s);
        let linear = probe(plant, speed_rpm)?;
        a.view_mut((0, 0), (m, m + 1)).copy_from(&linear);
        for (i, q) in orders.iter().enumerate() {
            let (c, sn) = (m + 1 + 2 * i, m + 2 + 2 * i);
            a[(c, sn)] = -q * omega;
            a[(sn, c)] = q * omega;
        }
        for t in &terms {
            let row = rows[t.column];
            let c = t.cos_state;
            a[(row, c)] += t.coefficient * t.phase.0;
            a[(row, c + 1)] -= t.coefficient * t.phase.1;
        }
        if y0.len() != m {
            return None;
        }
        let mut z = vec![0.0; padded_len(s)];
        z[..m].copy_from_slice(&y0);
        z[m] = 1.0;
        for i in 0..orders.len() {
            z[m + 1 + 2 * i] = 1.0;
        }
        let step_matrices = StepMatrices::new(&a, m, &rows, h);
        Some(Self {
            t: 0.0,
            base: (0.0, 0),
            plant_len: m,
            steps: (0, 0),
            h,
            last: (0.0, z.clone()),
            scratch: (
                vec![0.0; z.len()],
                vec![0.0; rows.len()],
                vec![0.0; rows.len()],
            ),
            z,
            a,
            step_matrices,
            rows,
            terms,
            reference_dof: plant.reference_dof,
        })
    }

    /// One step of `h`, or shorter to land on `t_end`.
    pub fn step(&mut self, t_end: f64) -> Result<(), TransientError> {
        let h = self.h.min(t_end - self.t);
        if h.is_nan() || h <= 0.0 {
            return Err(TransientError::Model(format!(
                "the exact integrator was asked to step from {} s back to {t_end} s",
                self.t
            )));
        }
        let full = h >= self.h * (1.0 - 1e-12);
        let shorter;
        let matrices = if full {
            &self.step_matrices
        } else {
            shorter = StepMatrices::new(&self.a, self.plant_len, &self.rows, h);
            &shorter
        };
        let (mut stage, mut n0, mut n1) = std::mem::take(&mut self.scratch);
        remainder_into(&self.terms, self.reference_dof, &self.z, &mut n0);
        matrices.predict(&self.z, &n0, &mut stage);
        remainder_into(&self.terms, self.reference_dof, &stage, &mut n1);
        for (a, b) in n1.iter_mut().zip(&n0) {
            *a -= b;
        }
        matrices.correct(&n1, &mut stage);
        // The previous state becomes the dense output's start; its buffer the next stage.
        std::mem::swap(&mut self.last.1, &mut self.z);
        std::mem::swap(&mut self.z, &mut stage);
        self.last.0 = self.t;
        self.scratch = (stage, n0, n1);
        if full {
            self.base.1 += 1;
            self.t = self.base.0 + self.base.1 as f64 * self.h;
        } else {
            self.t += h;
            self.base = (self.t, 0);
        }
        self.steps.0 += 1;
        Ok(())
    }

    /// Current plant state.
    pub fn y(&self) -> &[f64] {
        &self.z[..self.plant_len]
    }

    /// True when `t` (s) is the end of the last step, to rounding: where every recorded
    /// sample falls when the step divides the sample interval.
    pub fn is_at_end(&self, t: f64) -> bool {
        (t - self.t).abs() <= 1e-12 * self.t.abs().max(1.0)
    }

    /// The state at `t` within the last step (cubic Hermite between its ends; exact at
    /// the ends, [`Self::is_at_end`]).
    pub fn interpolate(&self, t: f64, out: &mut [f64]) {
        if self.is_at_end(t) {
            out.copy_from_slice(self.y());
            return;
        }
        let m = self.plant_len;
        let (t0, z0) = &self.last;
        let (d0, d1) = (self.derivative(z0), self.derivative(&self.z));
        hermite((*t0, &z0[..m], &d0), (self.t, self.y(), &d1), t, out);
    }

    /// `ẏ = A·z + E·N(z)`, the plant state's part.
    fn derivative(&self, z: &[f64]) -> Vec<f64> {
        let augmented = DVector::from_column_slice(&z[..self.a.ncols()]);
        let mut out: Vec<f64> = (&self.a * augmented).as_slice()[..self.plant_len].to_vec();
        let nz = self.remainder(z);
        for (c, row) in self.rows.iter().enumerate() {
            out[*row] += nz[c];
        }
        out
    }

    /// The crank-angle remainder per column, rad/s².
    fn remainder(&self, z: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.rows.len()];
        remainder_into(&self.terms, self.reference_dof, z, &mut out);
        out
    }
}

/// `[A | c]` of the plant without its harmonics, `ẏ = A·y + c`, probed column by column;
/// `None` when the equations are not affine.
fn probe(plant: &Plant, speed_rpm: f64) -> Option<DMatrix<f64>> {
    let mut bare = plant.clone();
    bare.harmonics.clear();
    let profile = SpeedProfile::steady(speed_rpm);
    let m = plant.state_len;
    let mut scratch = Scratch::new(plant.n_dof);
    let f = |y: &[f64], scratch: &mut Scratch| {
        let mut dy = vec![0.0; m];
        bare.derivatives(0.0, y, &mut dy, &profile, scratch);
        dy
    };
    let f0 = f(&vec![0.0; m], &mut scratch);
    let mut out = DMatrix::<f64>::zeros(m, m + 1);
    let mut y = vec![0.0; m];
    for j in 0..m {
        y[j] = 1.0;
        let f1 = f(&y, &mut scratch);
        y[j] = 2.0;
        let f2 = f(&y, &mut scratch);
        y[j] = 0.0;
        for i in 0..m {
            let column = f1[i] - f0[i];
            let scale = column.abs() + f0[i].abs() + f64::MIN_POSITIVE;
            if (f2[i] - f0[i] - 2.0 * column).abs() > AFFINE_TOLERANCE * scale {
                return None;
            }
            out[(i, j)] = column;
        }
    }
    for i in 0..m {
        out[(i, m)] = f0[i];
    }
    out.iter().all(|v| v.is_finite()).then_some(out)
}
