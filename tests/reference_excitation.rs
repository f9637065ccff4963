//! Engine excitation (seed 001 eq. 3–5) against an independent numerical Fourier integral,
//! and the cancellation of orders that even firing predicts.

use num_complex::Complex64;
use std::f64::consts::PI;
use torsim::model::parse_model;
use torsim::physics::excitation::cylinder_spectrum;
use torsim::physics::{Excitation, OperatingPoint, System};

const ENGINE: &str = r#"format = 1
name = "single cylinder"
[[inertia]]
name = "crank"
inertia = 0.2
[[inertia]]
name = "brake"
inertia = 1.0
[[connection]]
kind = "shaft"
from = "crank"
to = "brake"
stiffness = 5.0e4
[engine]
at = "crank"
cylinders = CYL
bore = 0.082
crank_radius = 0.045
conrod_length = 0.14
reciprocating_mass = 0.65
rod_inertia_correction = 0.05
pressure = { crank_angle_deg = [-360, -180, -60, -20, 0, 8, 20, 40, 90, 180, 360], bar = [0.0, 0.1, 4.0, 18.0, 45.0, 72.0, 60.0, 32.0, 9.0, 2.5, 0.0] }
"#;

/// Seed 001 eq. 3–4 written out again here, with its own table interpolation, so the test
/// does not share code with the library: torque of one cylinder at φ from firing TDC.
fn torque_by_hand(phi: f64, omega: f64) -> f64 {
    let angles = [
        -360.0, -180.0, -60.0, -20.0, 0.0, 8.0, 20.0, 40.0, 90.0, 180.0, 360.0,
    ];
    let bars = [0.0, 0.1, 4.0, 18.0, 45.0, 72.0, 60.0, 32.0, 9.0, 2.5, 0.0];
    let deg = (phi.to_degrees() + 360.0).rem_euclid(720.0) - 360.0;
    let i = (0..angles.len() - 1)
        .find(|&i| deg >= angles[i] && deg <= angles[i + 1])
        .unwrap();
    let p = bars[i] + (deg - angles[i]) / (angles[i + 1] - angles[i]) * (bars[i + 1] - bars[i]);
    let (r, l, d) = (0.045, 0.14, 0.082);
    let lambda = r / l;
    let rv = r * (phi.sin() + lambda / 2.0 * (2.0 * phi).sin());
    let ra = r * (phi.cos() + lambda * (2.0 * phi).cos());
    p * 1e5 * PI * d * d / 4.0 * rv - (0.65 - 0.05) * omega * omega * ra * rv
}

/// C_k = (2/Φ)∫₀^Φ T(φ) e^{−i k φ 2π/Φ} dφ by composite Simpson on 288 000 intervals
/// (error ~h² at the table's kinks: ~1e-8 of the largest coefficient).
fn fourier_by_hand(k: usize, omega: f64) -> Complex64 {
    let n = 288_000;
    let cycle = 4.0 * PI;
    let h = cycle / n as f64;
    let mut sum = Complex64::default();
    for i in 0..=n {
        let phi = i as f64 * h;
        let w = if i == 0 || i == n {
            1.0
        } else if i % 2 == 1 {
            4.0
        } else {
            2.0
        };
        sum += w
            * torque_by_hand(phi, omega)
            * Complex64::from_polar(1.0, -(k as f64) * phi * 2.0 * PI / cycle);
    }
    let integral = sum * h / 3.0;
    integral * if k == 0 { 1.0 / cycle } else { 2.0 / cycle }
}

/// The library's FFT of one cylinder's torque equals the direct Fourier integral for every
/// order 0 … 24 at 3000 rpm, within 1e-4 of the largest coefficient (the FFT's aliasing
/// bound with 8192 samples per cycle is 3e-5).
#[test]
fn single_cylinder_harmonics_match_direct_integral() {
    let model = parse_model(&ENGINE.replace("CYL", "1"), "engine.toml").unwrap();
    let engine = model.engine.as_ref().unwrap();
    let spectrum = cylinder_spectrum(engine, 1.0);
    let omega = 3000.0 * 2.0 * PI / 60.0;
    let library =
        |k: usize| spectrum.gas_nm[k] + spectrum.inertia_nm_per_rad2_s2[k] * (omega * omega);
    let largest = (1..=48).map(|k| library(k).norm()).fold(0.0, f64::max);
    assert!(largest > 50.0, "a real engine's harmonics: {largest}");
    for k in 0..=48 {
        let exact = fourier_by_hand(k, omega);
        let err = (library(k) - exact).norm();
        assert!(
            err < 1e-4 * largest,
            "cycle harmonic {k} (order {}): library {} vs integral {exact} (error {err})",
            k as f64 / 2.0,
            library(k)
        );
    }
    // The mean is the gas torque's mean alone: the oscillating masses do no net work.
    assert!(spectrum.inertia_nm_per_rad2_s2[0].norm() < 1e-12);
}

/// Four cylinders firing evenly every 180°: every order that is not a multiple of 2
/// cancels (sum of e^{−iqα_i} is zero), and multiples of 2 add four times one cylinder.
#[test]
fn even_firing_four_cylinders_cancels_odd_orders() {
    let model = parse_model(&ENGINE.replace("CYL", "4"), "engine.toml").unwrap();
    let system = System::new(&model, OperatingPoint::default()).unwrap();
    let orders = [0.5, 1.0, 1.5, 2.0, 4.0];
    let excitation = Excitation::new(&model, &system, 1.0, &orders);
    let single = cylinder_spectrum(model.engine.as_ref().unwrap(), 1.0);
    let speed_rpm = 2500.0;
    let omega = speed_rpm * 2.0 * PI / 60.0;
    let mut f = vec![Complex64::default(); system.dof_count()];
    let crank = system.dof_of_node[0];
    for (q, &order) in orders.iter().enumerate() {
        excitation.forcing(q, speed_rpm, &mut f);
        let k = (2.0 * order) as usize;
        let one = (single.gas_nm[k] + single.inertia_nm_per_rad2_s2[k] * omega * omega).norm();
        if order % 2.0 == 0.0 {
            assert!(
                (f[crank].norm() - 4.0 * one).abs() < 1e-9 * one,
                "order {order}"
            );
        } else {
            assert!(
                f[crank].norm() < 1e-9 * one,
                "order {order} should cancel: {}",
                f[crank].norm()
            );
        }
    }
}
