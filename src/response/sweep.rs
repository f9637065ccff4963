//! Steady forced response, order by order, over a speed sweep (frequency domain):
//! `(K(f)(1 + iξ) − ω²M + iωC) Θ_q = T̂_q` at `ω = q·2πn/60` for each speed n and order q.
//!
//! Magnitudes are `sqrt(re² + im²)` rather than `hypot`: the amplitudes here are far from
//! overflow, and `hypot` cost 15 % of the sweep.

use super::peak::PeakSynthesizer;
use super::point::{PointSolver, RPM_PER_RAD_S};
use crate::physics::{Excitation, PhysicsError, System, distributed};
use num_complex::Complex64;
use std::f64::consts::{PI, TAU};

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
pub(super) fn check_sizes(orders: &[f64], n_speeds: usize) -> Result<(), PhysicsError> {
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
    let mut point = PointSolver::new(system, excitation);
    let mut torques = vec![vec![Complex64::default(); n_orders]; n_conn];
    // Referred angular velocity phasor of each DOF per order, rpm.
    let mut velocities = vec![vec![Complex64::default(); n_orders]; n];
    let mut half_pp = vec![0.0; n];
    let mut synthesizer = PeakSynthesizer::new(orders);
    for (s, &speed) in speeds_rpm.iter().enumerate() {
        for q in 0..n_orders {
            let omega = point.solve(speed, q)?;
            let frequency_hz = omega / TAU;
            for (node, amplitudes) in response.ias_amplitude_rpm.iter_mut().enumerate() {
                amplitudes[q][s] = point.ias_amplitude_rpm(node, omega);
            }
            if synthesize {
                for (v, a) in velocities.iter_mut().zip(&point.angle) {
                    v[q] = Complex64::new(0.0, omega * RPM_PER_RAD_S) * a;
                }
            }
            for (c, e) in system.elements.iter().enumerate() {
                let (k, loss) = point.stiffness[c];
                let row = row_of[c];
                let (torque_ref, energy_per_cycle) = element_torque_and_loss(
                    e,
                    point.element_z[c],
                    k * loss + omega * point.viscous[c],
                    omega,
                    &point.angle,
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
