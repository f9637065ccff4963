//! Damped natural frequencies and damping ratios from the complex eigenproblem.
//!
//! For each undamped mode the state matrix `[[0, I], [−M⁻¹K, −M⁻¹C]]` is built with the
//! rubber at that mode's frequency, its hysteretic damping as the equivalent viscous
//! `c = k·ξ_T/ω` at that frequency (seed 000 eq. 14, seed 001 eq. 2), and the viscous
//! damping of shafts, nodes and load. Its eigenvalues `λ = −ζω_n ± iω_d` give the damped
//! frequency `ω_d/2π` and the damping ratio `ζ = −Re λ/|λ|` of the eigenvalue nearest the
//! mode.

use super::undamped::Mode;
use crate::physics::{System, matrices};
use nalgebra::DMatrix;
use std::f64::consts::TAU;

/// Damped frequency and damping ratio of one mode.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DampedMode {
    /// Damped natural frequency `ω_d/2π`, Hz (0 for an overdamped mode).
    pub frequency_hz: f64,
    /// Damping ratio ζ (fraction of critical).
    pub damping_ratio: f64,
}

/// The damped counterpart of each undamped mode, in the same order.
pub fn damped_modes(system: &System, modes: &[Mode]) -> Vec<DampedMode> {
    let n = system.dof_count();
    modes
        .iter()
        .map(|mode| {
            let f = mode.frequency_hz;
            let omega = (TAU * f).max(f64::MIN_POSITIVE);
            let k = matrices::stiffness_matrix(system, f);
            let mut c = matrices::damping_matrix(system);
            for e in &system.elements {
                let (stiffness, loss) = e.stiffness_at(f);
                matrices::add_spring(&mut c, e.from_dof, e.to_dof, stiffness * loss / omega);
            }
            let mut a = DMatrix::<f64>::zeros(2 * n, 2 * n);
            for i in 0..n {
                a[(i, n + i)] = 1.0;
                let inv_j = 1.0 / system.inertia_kg_m2[i];
                for j in 0..n {
                    a[(n + i, j)] = -k[(i, j)] * inv_j;
                    a[(n + i, n + j)] = -c[(i, j)] * inv_j;
                }
            }
            let nearest = a
                .complex_eigenvalues()
                .iter()
                .filter(|l| l.im >= 0.0)
                .min_by(|x, y| {
                    (x.norm() - omega)
                        .abs()
                        .total_cmp(&(y.norm() - omega).abs())
                })
                .copied();
            match nearest {
                Some(l) if l.norm() > 0.0 => DampedMode {
                    frequency_hz: l.im / TAU,
                    damping_ratio: -l.re / l.norm(),
                },
                _ => DampedMode {
                    frequency_hz: f64::NAN,
                    damping_ratio: f64::NAN,
                },
            }
        })
        .collect()
}
