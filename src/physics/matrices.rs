//! Assembly helpers for the lumped matrices.

use nalgebra::{DMatrix, Scalar};
use num_complex::Complex64;
use std::ops::{AddAssign, Neg};

/// Adds a spring of stiffness `k` between DOFs `a` and `b` (`None`: ground).
pub fn add_spring<T>(matrix: &mut DMatrix<T>, a: Option<usize>, b: Option<usize>, k: T)
where
    T: Scalar + Copy + AddAssign + Neg<Output = T>,
{
    add_two_port(matrix, a, b, k, -k);
}

/// Adds a symmetric two-port between DOFs `a` and `b` (`None`: ground, whose row and
/// column are dropped): `diagonal` on both diagonal entries, `off_diagonal` on both
/// couplings. A spring is `(k, −k)`; a distributed shaft's exact element `(D_aa, D_ab)`.
pub fn add_two_port<T>(
    matrix: &mut DMatrix<T>,
    a: Option<usize>,
    b: Option<usize>,
    diagonal: T,
    off_diagonal: T,
) where
    T: Scalar + Copy + AddAssign,
{
    for d in [a, b].into_iter().flatten() {
        matrix[(d, d)] += diagonal;
    }
    if let (Some(a), Some(b)) = (a, b) {
        matrix[(a, b)] += off_diagonal;
        matrix[(b, a)] += off_diagonal;
    }
}

/// Real stiffness matrix at vibration frequency `frequency_hz` (rubber at α_f(f)).
pub fn stiffness_matrix(system: &super::System, frequency_hz: f64) -> DMatrix<f64> {
    let n = system.dof_count();
    let mut k = DMatrix::<f64>::zeros(n, n);
    for e in &system.elements {
        add_spring(&mut k, e.from_dof, e.to_dof, e.stiffness_at(frequency_hz).0);
    }
    k
}

/// Viscous damping matrix: absolute damping, shafts, modal damping; rubber (hysteretic)
/// not included.
pub fn damping_matrix(system: &super::System) -> DMatrix<f64> {
    let mut c = DMatrix::<f64>::from_diagonal(&nalgebra::DVector::from_column_slice(
        &system.absolute_damping_nm_s_per_rad,
    ));
    for e in &system.elements {
        add_spring(&mut c, e.from_dof, e.to_dof, e.viscous_damping());
    }
    if let Some(m) = &system.modal_damping {
        c += m;
    }
    c
}

/// Dynamic stiffness `K(f)(1 + iξ) − ω²M + iωC` at angular frequency `omega_rad_s`,
/// written into `out` (n×n); a distributed shaft's segments as exact elements.
pub fn dynamic_stiffness(system: &super::System, omega_rad_s: f64, out: &mut DMatrix<Complex64>) {
    let frequency_hz = omega_rad_s / std::f64::consts::TAU;
    dynamic_stiffness_with(
        system,
        omega_rad_s,
        system.elements.iter().map(|e| e.stiffness_at(frequency_hz)),
        out,
    );
}

/// [`dynamic_stiffness`] with each element's `(stiffness, loss factor)` at `ω/2π` already
/// evaluated (in element order), for a sweep that needs them again afterwards.
pub(crate) fn dynamic_stiffness_with(
    system: &super::System,
    omega_rad_s: f64,
    element_stiffness: impl Iterator<Item = (f64, f64)>,
    out: &mut DMatrix<Complex64>,
) {
    out.fill(Complex64::new(0.0, 0.0));
    for (i, (&j, &c)) in system
        .inertia_kg_m2
        .iter()
        .zip(&system.absolute_damping_nm_s_per_rad)
        .enumerate()
    {
        out[(i, i)] += Complex64::new(-omega_rad_s * omega_rad_s * j, omega_rad_s * c);
    }
    for (e, (k, loss)) in system.elements.iter().zip(element_stiffness) {
        let z = Complex64::new(k, k * loss + omega_rad_s * e.viscous_damping());
        add_spring(out, e.from_dof, e.to_dof, z);
        let inertia = e.distributed_inertia();
        if inertia > 0.0 {
            super::distributed::add_exact_correction(
                out,
                e.from_dof,
                e.to_dof,
                z,
                inertia,
                omega_rad_s,
            );
        }
    }
    if let Some(m) = &system.modal_damping {
        for (o, c) in out.iter_mut().zip(m.iter()) {
            *o += Complex64::new(0.0, omega_rad_s * c);
        }
    }
}
