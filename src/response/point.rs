//! One point of the steady forced response: the angles `Θ_q` of every DOF for one speed
//! and one order, `(K(f)(1 + iξ) − ω²M + iωC) Θ_q = T̂_q` at `ω = q·2πn/60`.
//!
//! Shared by the full sweep ([`super::sweep`], which goes on to the element torques,
//! losses and synthesized peaks) and the amplitude-only sweep ([`super::amplitudes`], the
//! diagnosis' linear surrogate), so that both solve each point with the very same
//! operations. The buffers (the tree solver's, the dense fallback's, each element's
//! complex stiffness) are made once per sweep and reused at every point.

use super::lu::LuWorkspace;
use super::tree::TreeSolver;
use crate::physics::{Excitation, PhysicsError, System, matrices};
use nalgebra::DMatrix;
use num_complex::Complex64;
use std::f64::consts::TAU;

/// rad/s to rpm.
pub(crate) const RPM_PER_RAD_S: f64 = 60.0 / TAU;

/// The solve of one (speed, order) point, with its reused buffers.
pub(crate) struct PointSolver<'a> {
    system: &'a System,
    excitation: &'a Excitation,
    /// O(n) elimination for tree-shaped drivelines; the dense LU for loops and near-zero
    /// pivots.
    tree: Option<TreeSolver>,
    lu: LuWorkspace,
    dynamic: DMatrix<Complex64>,
    /// Each element's complex stiffness `k(1 + iξ) + iωc` at the point, N·m/rad.
    pub(crate) element_z: Vec<Complex64>,
    /// (stiffness N·m/rad, loss factor) of each element at the point's frequency.
    pub(crate) stiffness: Vec<(f64, f64)>,
    /// Each element's viscous damping, N·m·s/rad.
    pub(crate) viscous: Vec<f64>,
    /// The point's solution: `Θ_q` of every DOF, rad (referred).
    pub(crate) angle: Vec<Complex64>,
}

impl<'a> PointSolver<'a> {
    /// The solver of `system` driven by `excitation`.
    pub(crate) fn new(system: &'a System, excitation: &'a Excitation) -> Self {
        let n = system.dof_count();
        let n_elements = system.elements.len();
        Self {
            system,
            excitation,
            tree: TreeSolver::new(system),
            lu: LuWorkspace::default(),
            dynamic: DMatrix::<Complex64>::zeros(n, n),
            element_z: vec![Complex64::default(); n_elements],
            stiffness: vec![(0.0, 0.0); n_elements],
            viscous: system
                .elements
                .iter()
                .map(|e| e.viscous_damping())
                .collect(),
            angle: vec![Complex64::default(); n],
        }
    }

    /// Solves order `q` (index into the excitation's orders) at `speed_rpm`, leaving `Θ_q`
    /// in [`Self::angle`]; returns ω of the order, rad/s. An error when the frequency is
    /// outside the model's validity or sits on an undamped resonance.
    pub(crate) fn solve(&mut self, speed_rpm: f64, q: usize) -> Result<f64, PhysicsError> {
        let system = self.system;
        let order = self.excitation.orders[q];
        let omega = order * (speed_rpm / RPM_PER_RAD_S);
        let frequency_hz = omega / TAU;
        system.check_frequency(frequency_hz)?;
        self.excitation.forcing(q, speed_rpm, &mut self.angle);
        for (slot, e) in self.stiffness.iter_mut().zip(&system.elements) {
            *slot = e.stiffness_at(frequency_hz);
        }
        for ((z, &(k, loss)), &c_visc) in self
            .element_z
            .iter_mut()
            .zip(&self.stiffness)
            .zip(&self.viscous)
        {
            *z = Complex64::new(k, k * loss + omega * c_visc);
        }
        let by_tree = self
            .tree
            .as_mut()
            .is_some_and(|t| t.solve(system, omega, &self.element_z, &mut self.angle));
        // Solved in place: `angle` holds the forcing on entry and Θ_q on return.
        let solved = by_tree || {
            self.excitation.forcing(q, speed_rpm, &mut self.angle);
            matrices::dynamic_stiffness_with(
                system,
                omega,
                self.stiffness.iter().copied(),
                &mut self.dynamic,
            );
            self.lu.factor_solve(&mut self.dynamic, &mut self.angle)
        };
        if !solved || !self.angle.iter().all(|v| v.is_finite()) {
            return Err(PhysicsError::Singular(format!(
                "order {order} at {speed_rpm} rpm ({frequency_hz:.3} Hz) sits on an undamped resonance"
            )));
        }
        Ok(omega)
    }

    /// The IAS amplitude of `node` (model node index) at the last solved point whose ω
    /// was `omega`, rpm, zero-to-peak, in the node's own shaft.
    pub(crate) fn ias_amplitude_rpm(&self, node: usize, omega: f64) -> f64 {
        let dof = self.system.dof_of_node[node];
        self.system.speed_ratio[node].abs()
            * omega
            * self.angle[dof].norm_sqr().sqrt()
            * RPM_PER_RAD_S
    }
}
