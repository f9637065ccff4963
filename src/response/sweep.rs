//! Steady forced response, order by order, over a speed sweep (frequency domain):
//! `(K(f)(1 + iξ) − ω²M + iωC) Θ_q = T̂_q` at `ω = q·2πn/60` for each speed n and order q.
//!
//! Magnitudes are `sqrt(re² + im²)` rather than `hypot`: the amplitudes here are far from
//! overflow, and `hypot` cost 15 % of the sweep.

use super::lu::LuWorkspace;
use super::peak::PeakSynthesizer;
use super::tree::TreeSolver;
use crate::physics::{Excitation, PhysicsError, System, distributed, matrices};
use nalgebra::DMatrix;
use num_complex::Complex64;
use std::f64::consts::{PI, TAU};

/// rad/s to rpm.
const RPM_PER_RAD_S: f64 = 60.0 / TAU;

/// Steady forced response over a speed sweep. Amplitudes are zero-to-peak, in each node's
/// or connection's own shaft.
#[derive(Debug, Clone, PartialEq)]
pub struct Response {
    /// Reference speeds, rpm.
    pub speeds_rpm: Vec<f64>,
    /// Orders.
    pub orders: Vec<f64>,
    /// `ias_amplitude_rpm[node][order][speed]`: IAS amplitude per order, rpm.
    pub ias_amplitude_rpm: Vec<Vec<Vec<f64>>>,
    /// `ias_half_peak_to_peak_rpm[node][speed]`: half the peak-to-peak IAS over a cycle,
    /// every order synthesized with its phase, rpm — the true counterpart of the sum of
    /// the per-order amplitudes, which is only its upper bound.
    pub ias_half_peak_to_peak_rpm: Vec<Vec<f64>>,
    /// Model connection index of each entry of the per-connection results (connections
    /// with an element; rigid gears carry no element and are left out).
    pub connections: Vec<usize>,
    /// `torque_amplitude_nm[connection][order][speed]`, N·m.
    pub torque_amplitude_nm: Vec<Vec<Vec<f64>>>,
    /// `torque_peak_nm[connection][speed]`: largest |torque| over a cycle, the mean
    /// torque plus every order synthesized with its phase, N·m.
    pub torque_peak_nm: Vec<Vec<f64>>,
    /// `power_loss_w[connection][speed]`: damping power, W. Rubber per DIN 740 — each
    /// order loses `ψ_T` times its elastic energy `½k|Δθ|²` per cycle — plus viscous
    /// `½cω²|Δθ|²` per order.
    pub power_loss_w: Vec<Vec<f64>>,
    /// `power_loss_by_order_w[connection][order][speed]`: the part of `power_loss_w` each
    /// order dissipates, W (orders at different frequencies add their mean powers).
    pub power_loss_by_order_w: Vec<Vec<Vec<f64>>>,
}

/// The forced response of `system` to `excitation` at `speeds_rpm`.
pub fn forced_response(
    system: &System,
    excitation: &Excitation,
    speeds_rpm: &[f64],
) -> Result<Response, PhysicsError> {
    sweep(system, excitation, speeds_rpm, true)
}

/// The forced response order by order only: as [`forced_response`], but without the
/// waveforms synthesized from all orders (`ias_half_peak_to_peak_rpm` and
/// `torque_peak_nm` stay zero), which cost a third of the sweep. For callers that compare
/// order amplitudes (the diagnosis' linear surrogate).
pub fn forced_response_orders(
    system: &System,
    excitation: &Excitation,
    speeds_rpm: &[f64],
) -> Result<Response, PhysicsError> {
    sweep(system, excitation, speeds_rpm, false)
}

/// Every order ≤ [`crate::limits::Limits::max_order`] (the synthesis samples a cycle at
/// 16 points per period of the highest order: order 10⁹ asked 137 GB, issue 13), and
/// speeds and speeds × orders ≤ [`crate::limits::Limits::max_sweep_points`].
fn check_sizes(orders: &[f64], n_speeds: usize) -> Result<(), PhysicsError> {
    let limits = crate::limits::current();
    for &q in orders {
        crate::limits::check_value("order (--orders)", q, limits.max_order, Some("--max-order"))?;
    }
    crate::limits::check_count(
        "speeds of the sweep (--from-rpm … --to-rpm by --step-rpm)",
        n_speeds as f64,
        limits.max_sweep_points,
        Some("--max-sweep-points"),
    )?;
    crate::limits::check_count(
        "speeds × orders of the sweep",
        (n_speeds * orders.len()) as f64,
        limits.max_sweep_points,
        Some("--max-sweep-points"),
    )?;
    Ok(())
}

/// The sweep; `synthesize`: also the synthesized peaks.
fn sweep(
    system: &System,
    excitation: &Excitation,
    speeds_rpm: &[f64],
    synthesize: bool,
) -> Result<Response, PhysicsError> {
    let n = system.dof_count();
    let orders = &excitation.orders;
    check_sizes(orders, speeds_rpm.len())?;
    let (n_nodes, n_orders, n_speeds) = (system.node_names.len(), orders.len(), speeds_rpm.len());
    let n_elements = system.elements.len();
    let (rows, row_of) = result_rows(system);
    let n_conn = rows.len();
    let mut response = Response {
        speeds_rpm: speeds_rpm.to_vec(),
        orders: orders.clone(),
        ias_amplitude_rpm: vec![vec![vec![0.0; n_speeds]; n_orders]; n_nodes],
        ias_half_peak_to_peak_rpm: vec![vec![0.0; n_speeds]; n_nodes],
        connections: rows
            .iter()
            .map(|&e| system.elements[e].connection)
            .collect(),
        torque_amplitude_nm: vec![vec![vec![0.0; n_speeds]; n_orders]; n_conn],
        torque_peak_nm: vec![vec![0.0; n_speeds]; n_conn],
        power_loss_w: vec![vec![0.0; n_speeds]; n_conn],
        power_loss_by_order_w: vec![vec![vec![0.0; n_speeds]; n_orders]; n_conn],
    };
    let mut dynamic = DMatrix::<Complex64>::zeros(n, n);
    let mut angle = vec![Complex64::default(); n];
    let mut lu = LuWorkspace::default();
    // O(n) elimination for tree-shaped drivelines; the dense LU for loops and near-zero
    // pivots.
    let mut tree = TreeSolver::new(system);
    let mut element_z = vec![Complex64::default(); n_elements];
    // (stiffness, loss factor) of each element at the current frequency, and its viscous
    // damping: evaluated once per (speed, order) for the matrix and the element results.
    let mut stiffness = vec![(0.0, 0.0); n_elements];
    let viscous: Vec<f64> = system
        .elements
        .iter()
        .map(|e| e.viscous_damping())
        .collect();
    let mut torques = vec![vec![Complex64::default(); n_orders]; n_conn];
    // Referred angular velocity phasor of each DOF per order, rpm.
    let mut velocities = vec![vec![Complex64::default(); n_orders]; n];
    let mut half_pp = vec![0.0; n];
    let mut synthesizer = PeakSynthesizer::new(orders);
    for (s, &speed) in speeds_rpm.iter().enumerate() {
        let omega_ref = speed / RPM_PER_RAD_S;
        for (q, &order) in orders.iter().enumerate() {
            let omega = order * omega_ref;
            let frequency_hz = omega / TAU;
            system.check_frequency(frequency_hz)?;
            excitation.forcing(q, speed, &mut angle);
            for (slot, e) in stiffness.iter_mut().zip(&system.elements) {
                *slot = e.stiffness_at(frequency_hz);
            }
            for ((z, &(k, loss)), &c_visc) in element_z.iter_mut().zip(&stiffness).zip(&viscous) {
                *z = Complex64::new(k, k * loss + omega * c_visc);
            }
            let by_tree = tree
                .as_mut()
                .is_some_and(|t| t.solve(system, omega, &element_z, &mut angle));
            // Solved in place: `angle` holds the forcing on entry and Θ_q on return.
            let solved = by_tree || {
                excitation.forcing(q, speed, &mut angle);
                matrices::dynamic_stiffness_with(
                    system,
                    omega,
                    stiffness.iter().copied(),
                    &mut dynamic,
                );
                lu.factor_solve(&mut dynamic, &mut angle)
            };
            if !solved || !angle.iter().all(|v| v.is_finite()) {
                return Err(PhysicsError::Singular(format!(
                    "order {order} at {speed} rpm ({frequency_hz:.3} Hz) sits on an undamped resonance"
                )));
            }
            for (node, (&dof, &ratio)) in system
                .dof_of_node
                .iter()
                .zip(&system.speed_ratio)
                .enumerate()
            {
                response.ias_amplitude_rpm[node][q][s] =
                    ratio.abs() * omega * angle[dof].norm_sqr().sqrt() * RPM_PER_RAD_S;
            }
            if synthesize {
                for (v, a) in velocities.iter_mut().zip(&angle) {
                    v[q] = Complex64::new(0.0, omega * RPM_PER_RAD_S) * a;
                }
            }
            for (c, e) in system.elements.iter().enumerate() {
                let (k, loss) = stiffness[c];
                let row = row_of[c];
                let (torque_ref, energy_per_cycle) = element_torque_and_loss(
                    e,
                    element_z[c],
                    k * loss + omega * viscous[c],
                    omega,
                    &angle,
                );
                if rows[row] == c {
                    let torque_own = torque_ref / e.torque_ratio;
                    torques[row][q] = torque_own;
                    response.torque_amplitude_nm[row][q][s] = torque_own.norm_sqr().sqrt();
                }
                response.power_loss_by_order_w[row][q][s] += energy_per_cycle * frequency_hz;
                response.power_loss_w[row][s] += energy_per_cycle * frequency_hz;
            }
        }
        if !synthesize {
            continue;
        }
        for (row, &e) in rows.iter().enumerate() {
            let mean = system.mean_torque_nm[system.elements[e].connection].unwrap_or(0.0);
            response.torque_peak_nm[row][s] = synthesizer.peak_abs(mean, &torques[row]);
        }
        // Nodes on one DOF share its phasors (scaled by |r|; a sign flips the whole wave).
        for (h, v) in half_pp.iter_mut().zip(&velocities) {
            *h = synthesizer.half_peak_to_peak(v);
        }
        for (node, (&dof, &ratio)) in system
            .dof_of_node
            .iter()
            .zip(&system.speed_ratio)
            .enumerate()
        {
            response.ias_half_peak_to_peak_rpm[node][s] = ratio.abs() * half_pp[dof];
        }
    }
    Ok(response)
}

/// The result rows ([`distributed::connection_rows`]): each row's element that gives its
/// torque (a distributed shaft's first segment: the torque at its `from` end), and the row
/// of every element (a distributed shaft's segments all add their loss to its row).
fn result_rows(system: &System) -> (Vec<usize>, Vec<usize>) {
    let rows = distributed::connection_rows(system.elements.iter().map(|e| e.connection));
    let firsts = rows
        .iter()
        .enumerate()
        .filter(|(_, (_, first))| *first)
        .map(|(i, _)| i)
        .collect();
    (firsts, rows.iter().map(|(row, _)| *row).collect())
}

/// An element's referred torque at its `from` end and the energy it dissipates per cycle,
/// J: `z·Δθ` and `π·|Δθ|²·im` for a spring of complex stiffness `z` (`im` its loss
/// modulus, N·m/rad); a distributed shaft's segment exactly, `D_aa·θ_a + D_ab·θ_b` and
/// `π·Im(θᴴ·D·θ)` ([`distributed::exact_ends`]).
fn element_torque_and_loss(
    e: &crate::physics::Element,
    z: Complex64,
    im: f64,
    omega: f64,
    angle: &[Complex64],
) -> (Complex64, f64) {
    let at = |d: Option<usize>| d.map_or(Complex64::default(), |d| angle[d]);
    let (a, b) = (at(e.from_dof), at(e.to_dof));
    let inertia = e.distributed_inertia();
    if inertia > 0.0 {
        let (aa, ab) = distributed::exact_ends(z, inertia, omega);
        let cross = (a.conj() * b).re;
        let loss = PI * (aa.im * (a.norm_sqr() + b.norm_sqr()) + 2.0 * ab.im * cross);
        return (aa * a + ab * b, loss);
    }
    let twist = a - b;
    (z * twist, PI * twist.norm_sqr() * im)
}
