//! The sweep's per-connection results against a two-DOF closed form.

use super::forced_response;
use crate::model::parse_model;
use crate::physics::{Excitation, OperatingPoint, System};
use num_complex::Complex64;
use std::f64::consts::TAU;

const J_A: f64 = 0.4;
const J_B: f64 = 1.5;
const K_RUBBER: f64 = 6.0e3;
const PSI: f64 = 0.8;
const K_SHAFT: f64 = 4.0e4;
const C_SHAFT: f64 = 8.0;
/// (order, amplitude N·m, phase °) of the harmonics at `a`.
const HARMONICS: [(f64, f64, f64); 2] = [(1.0, 100.0, 0.0), (2.0, 70.0, 40.0)];

fn model_text() -> String {
    let mut text = format!(
        r#"format = 1
name = "two-dof"
[[inertia]]
name = "a"
inertia = {J_A}
[[inertia]]
name = "b"
inertia = {J_B}
[[connection]]
kind = "rubber"
name = "rubber"
from = "a"
to = "b"
stiffness = {K_RUBBER}
psi = {PSI}
[[connection]]
kind = "shaft"
name = "shaft"
from = "b"
to = "ground"
stiffness = {K_SHAFT}
damping = {C_SHAFT}
"#
    );
    for (order, amplitude, phase) in HARMONICS {
        text.push_str(&format!(
            "[[harmonic]]\nat = \"a\"\norder = {order}\namplitude = {amplitude}\nphase_deg = {phase}\n"
        ));
    }
    text
}

/// Θ_a, Θ_b of one order at `omega` by Cramer's rule on
/// `[[k* − ω²J_a, −k*], [−k*, k* + k_s + iωc_s − ω²J_b]] Θ = [T, 0]`, `k* = k(1 + iψ/2π)`.
fn exact_angles(omega: f64, torque: Complex64) -> (Complex64, Complex64) {
    let k_star = Complex64::new(K_RUBBER, K_RUBBER * PSI / TAU);
    let d11 = k_star - omega * omega * J_A;
    let d22 = k_star + Complex64::new(K_SHAFT - omega * omega * J_B, omega * C_SHAFT);
    let det = d11 * d22 - k_star * k_star;
    (torque * d22 / det, torque * k_star / det)
}

/// The two-DOF model's system with the nominal rubber law `k(1 + iψ/2π)` (the closed
/// form's; [`System::nominal`]) and its excitation at [`HARMONICS`].
fn two_dof() -> (System, Excitation) {
    let model = parse_model(&model_text(), "two-dof.toml").unwrap();
    let system = System::nominal(&model, OperatingPoint::default()).unwrap();
    let orders: Vec<f64> = HARMONICS.iter().map(|h| h.0).collect();
    let excitation = Excitation::new(&model, &system, 1.0, &orders);
    (system, excitation)
}

/// Per order: the rubber's torque `|k*(Θ_a − Θ_b)|` and DIN 740 loss `ψ·½k|Δθ|²·f`, the
/// shaft's `|(k_s + iωc_s)Θ_b|` and viscous loss `½c_sω²|Θ_b|²`; the per-order losses add
/// up to the total. Tolerance 1e-11: one 2×2 complex LU solve against Cramer's rule.
/// Half the IAS peak-to-peak at `a` against a brute-force synthesis of the exact phasors
/// over 10⁵ points of a revolution (its own error ~1e-9); tolerance 1e-3 of the
/// amplitude sum, the parabola refinement's bound at 16 samples per period.
#[test]
fn two_dof_torque_loss_and_ias_peak_match_the_closed_form() {
    let (system, excitation) = two_dof();
    let speeds: Vec<f64> = (1..=90).map(|i| 20.0 * i as f64).collect();
    let r = forced_response(&system, &excitation, &speeds).unwrap();
    let rubber = r.connections.iter().position(|&c| c == 0).unwrap();
    let shaft = r.connections.iter().position(|&c| c == 1).unwrap();
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    for (s, &n) in speeds.iter().enumerate() {
        let mut velocity = Vec::new();
        for (q, &(order, amplitude, phase_deg)) in HARMONICS.iter().enumerate() {
            let omega = order * n * TAU / 60.0;
            let torque = Complex64::from_polar(amplitude, phase_deg.to_radians());
            let (a, b) = exact_angles(omega, torque);
            let twist = (a - b).norm();
            let k_star = Complex64::new(K_RUBBER, K_RUBBER * PSI / TAU);
            let rubber_torque = (k_star * (a - b)).norm();
            let shaft_torque = Complex64::new(K_SHAFT, omega * C_SHAFT).norm() * b.norm();
            let rubber_loss = PSI * 0.5 * K_RUBBER * twist * twist * omega / TAU;
            let shaft_loss = 0.5 * C_SHAFT * omega * omega * b.norm_sqr();
            assert!(rel(r.torque_amplitude_nm[rubber][q][s], rubber_torque) < 1e-11);
            assert!(rel(r.torque_amplitude_nm[shaft][q][s], shaft_torque) < 1e-11);
            assert!(rel(r.power_loss_by_order_w[rubber][q][s], rubber_loss) < 1e-11);
            assert!(rel(r.power_loss_by_order_w[shaft][q][s], shaft_loss) < 1e-11);
            velocity.push((order, Complex64::new(0.0, omega * 60.0 / TAU) * a));
        }
        for c in [rubber, shaft] {
            let sum: f64 = r.power_loss_by_order_w[c].iter().map(|o| o[s]).sum();
            assert!(rel(sum, r.power_loss_w[c][s]) < 1e-12);
        }
        let samples = 100_000;
        let wave: Vec<f64> = (0..samples)
            .map(|i| {
                let theta = TAU * i as f64 / samples as f64;
                velocity
                    .iter()
                    .map(|(q, v)| (v * Complex64::from_polar(1.0, q * theta)).re)
                    .sum()
            })
            .collect();
        let max = wave.iter().copied().fold(f64::MIN, f64::max);
        let min = wave.iter().copied().fold(f64::MAX, f64::min);
        let bound: f64 = velocity.iter().map(|(_, v)| v.norm()).sum();
        let got = r.ias_half_peak_to_peak_rpm[0][s];
        assert!(
            (got - 0.5 * (max - min)).abs() < 1e-3 * bound,
            "{n} rpm: {got} vs {}",
            0.5 * (max - min)
        );
        assert!(got <= bound * (1.0 + 1e-12));
    }
}

/// The order-only sweep gives the per-order results of the full one to the bit, and
/// leaves the synthesized peaks at zero.
#[test]
fn the_order_only_sweep_is_the_full_one_without_the_peaks() {
    let (system, excitation) = two_dof();
    let speeds: Vec<f64> = (1..=30).map(|i| 60.0 * i as f64).collect();
    let full = forced_response(&system, &excitation, &speeds).unwrap();
    let orders_only = super::forced_response_orders(&system, &excitation, &speeds).unwrap();
    assert_eq!(orders_only.ias_amplitude_rpm, full.ias_amplitude_rpm);
    assert_eq!(orders_only.torque_amplitude_nm, full.torque_amplitude_nm);
    assert_eq!(
        orders_only.power_loss_by_order_w,
        full.power_loss_by_order_w
    );
    assert_eq!(orders_only.power_loss_w, full.power_loss_w);
    assert!(full.ias_half_peak_to_peak_rpm[0].iter().all(|v| *v > 0.0));
    assert!(
        orders_only
            .ias_half_peak_to_peak_rpm
            .iter()
            .flatten()
            .all(|v| *v == 0.0)
    );
    assert!(
        orders_only
            .torque_peak_nm
            .iter()
            .flatten()
            .all(|v| *v == 0.0)
    );
}
