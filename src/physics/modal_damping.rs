//! Modal damping (`[modal_damping]`, [`crate::model::ModalDamping`]) as a damping matrix
//! every analysis reads: `C_m = M·Φ·diag(2ζ_r·ω_r)·Φᵀ·M`, Φ the mass-normalised shapes of
//! the undamped flexible modes (`Φᵀ·M·Φ = I`) and ω_r their frequencies, rad/s.
//!
//! For a model whose stiffness does not depend on frequency `Φᵀ·C_m·Φ = diag(2ζ_r·ω_r)`,
//! so mode r has exactly the ratio ζ_r the user gave (with no other damping the damped
//! eigenvalue is `−ζ_r·ω_r ± i·ω_r·√(1 − ζ_r²)`, `tests/modal_damping.rs`). Rigid-body
//! modes are left out of Φ, so the mean rotation is not damped. A rubber stage's chain
//! makes the stiffness depend on frequency; its modes are then each found at their own
//! frequency ([`crate::modal::modes`]) and C_m is built from those shapes, which diagonalise
//! it to within their non-orthogonality (the rubber's own loss comes on top, as the user's
//! ζ is meant in addition to the dampers and rubber the model already has).
//!
//! Written here: a few lines of nalgebra over torsim's own modes, which no crate has.

use super::system::System;
use crate::model::{ModalDamping, Model};
use nalgebra::DMatrix;
use std::f64::consts::TAU;

/// `C_m` of `damping` on `system`'s undamped modes, N·m·s/rad in referred DOFs; `None`
/// when the model has no flexible mode or its modes cannot be found.
pub fn modal_damping_matrix(system: &System, damping: &ModalDamping) -> Option<DMatrix<f64>> {
    let modes = crate::modal::modes(system).ok()?;
    let n = system.dof_count();
    if modes.is_empty() {
        return None;
    }
    let mut c = DMatrix::<f64>::zeros(n, n);
    for (r, mode) in modes.iter().enumerate() {
        let zeta = damping.zeta_of(r);
        if zeta == 0.0 {
            continue;
        }
        let coefficient = 2.0 * zeta * TAU * mode.frequency_hz;
        // M·φ_r, with M diagonal.
        let m_phi: Vec<f64> = mode
            .shape_dof
            .iter()
            .zip(&system.inertia_kg_m2)
            .map(|(p, j)| p * j)
            .collect();
        for i in 0..n {
            for j in 0..n {
                c[(i, j)] += coefficient * m_phi[i] * m_phi[j];
            }
        }
    }
    Some(c)
}

impl System {
    /// Puts the model's modal damping (if any) on this system, from its own modes: called
    /// last by [`System::nominal`] and [`System::new`], once the stiffness is final.
    pub(super) fn apply_modal_damping(&mut self, model: &Model) {
        self.modal_damping = None;
        if let Some(d) = &model.modal_damping {
            self.modal_damping = modal_damping_matrix(self, d);
        }
    }
}
