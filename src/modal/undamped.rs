//! Undamped natural frequencies and mode shapes: `K(f) φ = ω² M φ`.
//!
//! M is diagonal (lumped inertias), so the Cholesky reduction is `M^{-1/2} K M^{-1/2}`,
//! solved as a symmetric eigenproblem. Rigid-body modes — one per free component of the
//! driveline, counted from the graph, not guessed from small eigenvalues — are dropped.
//! Where rubber stiffness depends on frequency, each mode's frequency is the fixed point
//! `f = f_i(K(f))` found by secant iteration on that mode (DESIGN.md, numerics).

use crate::physics::{PhysicsError, System, matrices};
use nalgebra::{DMatrix, SymmetricEigen};
use std::f64::consts::TAU;

/// Relative tolerance on a mode's frequency in the fixed-point iteration.
const FREQUENCY_TOLERANCE: f64 = 1e-10;
/// Iterations allowed for one mode's fixed point.
const MAX_ITERATIONS: usize = 60;

/// One undamped mode.
#[derive(Debug, Clone, PartialEq)]
pub struct Mode {
    /// Natural frequency, Hz.
    pub frequency_hz: f64,
    /// Shape per DOF (referred coordinates), mass-normalised: `φᵀ M φ = 1`.
    pub shape_dof: Vec<f64>,
}

impl Mode {
    /// Shape per model node in the node's own shaft (`r·φ`), scaled so that the largest
    /// magnitude is 1 and positive.
    pub fn shape_by_node(&self, system: &System) -> Vec<f64> {
        let raw: Vec<f64> = system
            .dof_of_node
            .iter()
            .zip(&system.speed_ratio)
            .map(|(&d, &r)| self.shape_dof[d] * r)
            .collect();
        let peak = raw
            .iter()
            .copied()
            .fold(0.0_f64, |m, v| if v.abs() > m.abs() { v } else { m });
        if peak == 0.0 {
            return raw;
        }
        raw.iter().map(|v| v / peak).collect()
    }
}

/// Eigen-decomposition at one rubber frequency: flexible eigenvalues ω² ascending and,
/// when `vectors`, their shapes in referred coordinates (mass-normalised).
fn solve_at(
    system: &System,
    inv_sqrt_m: &[f64],
    frequency_hz: f64,
    vectors: bool,
) -> (Vec<f64>, Option<DMatrix<f64>>) {
    let n = system.dof_count();
    let mut a = matrices::stiffness_matrix(system, frequency_hz);
    for i in 0..n {
        for j in 0..n {
            a[(i, j)] *= inv_sqrt_m[i] * inv_sqrt_m[j];
        }
    }
    let skip = system.rigid_body_modes;
    if !vectors {
        let mut values: Vec<f64> = a.symmetric_eigenvalues().iter().copied().collect();
        values.sort_by(f64::total_cmp);
        return (values.split_off(skip.min(values.len())), None);
    }
    let eigen = SymmetricEigen::new(a);
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&i, &j| eigen.eigenvalues[i].total_cmp(&eigen.eigenvalues[j]));
    let order = &order[skip.min(n)..];
    let values = order.iter().map(|&i| eigen.eigenvalues[i]).collect();
    let mut shapes = DMatrix::<f64>::zeros(n, order.len());
    for (col, &i) in order.iter().enumerate() {
        for row in 0..n {
            shapes[(row, col)] = eigen.eigenvectors[(row, i)] * inv_sqrt_m[row];
        }
    }
    (values, Some(shapes))
}

fn to_hz(omega2: f64) -> f64 {
    omega2.max(0.0).sqrt() / TAU
}

/// Undamped flexible modes of `system`, ascending in frequency, rubber stiffness at each
/// mode's own frequency. A model with distributed shafts has its frequencies from the
/// exact elements ([`super::wittrick_williams`]) and its shapes from their segments.
pub fn modes(system: &System) -> Result<Vec<Mode>, PhysicsError> {
    let mut found = lumped_modes(system)?;
    if !system.distributed.is_empty() {
        let guess: Vec<f64> = found.iter().map(|m| m.frequency_hz).collect();
        let exact =
            super::wittrick_williams::exact_frequencies_hz(system, system.rigid_body_modes, &guess);
        for (mode, f) in found.iter_mut().zip(exact) {
            mode.frequency_hz = f;
        }
    }
    Ok(found)
}

/// The modes of the matrices as they stand (distributed shafts as their segments).
fn lumped_modes(system: &System) -> Result<Vec<Mode>, PhysicsError> {
    let inv_sqrt_m: Vec<f64> = system
        .inertia_kg_m2
        .iter()
        .map(|j| 1.0 / j.sqrt())
        .collect();
    // First pass with rubber at α_f(0): exact when nothing depends on frequency.
    let (values, shapes) = solve_at(system, &inv_sqrt_m, 0.0, true);
    let Some(shapes) = shapes else {
        return Ok(Vec::new());
    };
    if !system.is_frequency_dependent() {
        return Ok(values
            .iter()
            .enumerate()
            .map(|(i, &w2)| Mode {
                frequency_hz: to_hz(w2),
                shape_dof: shapes.column(i).iter().copied().collect(),
            })
            .collect());
    }
    // α_f ≤ 0 at rest or at a mode's frequency would be a negative stiffness: refused,
    // naming the stage and the frequency (issue 13), as the forced response does.
    system.check_frequency(0.0)?;
    (0..values.len())
        .map(|i| {
            let f = mode_fixed_point(system, &inv_sqrt_m, i, to_hz(values[i]))?;
            system.check_frequency(f)?;
            let (w2, shapes) = solve_at(system, &inv_sqrt_m, f, true);
            let shapes =
                shapes.ok_or_else(|| PhysicsError::NoConvergence("no mode shapes".into()))?;
            Ok(Mode {
                frequency_hz: to_hz(w2[i]),
                shape_dof: shapes.column(i).iter().copied().collect(),
            })
        })
        .collect()
}

/// The frequency `f` at which mode `index` of `K(f)` has frequency `f` (secant method on
/// `g(f) = f_index(K(f)) − f`, starting from the plain fixed-point step).
fn mode_fixed_point(
    system: &System,
    inv_sqrt_m: &[f64],
    index: usize,
    start_hz: f64,
) -> Result<f64, PhysicsError> {
    let mode_at = |f: f64| to_hz(solve_at(system, inv_sqrt_m, f, false).0[index]);
    let mut f0 = start_hz;
    let mut g0 = mode_at(f0) - f0;
    let mut f1 = f0 + g0;
    for _ in 0..MAX_ITERATIONS {
        let g1 = mode_at(f1) - f1;
        if g1.abs() <= FREQUENCY_TOLERANCE * f1.abs().max(1e-12) {
            return Ok(f1);
        }
        let slope = (g1 - g0) / (f1 - f0);
        let next = if slope.is_finite() && slope != 0.0 {
            f1 - g1 / slope
        } else {
            f1 + g1
        };
        (f0, g0, f1) = (f1, g1, if next > 0.0 { next } else { 0.5 * f1 });
    }
    Err(PhysicsError::NoConvergence(format!(
        "mode {} frequency with frequency-dependent rubber (last {f1:.6} Hz)",
        index + 1
    )))
}
