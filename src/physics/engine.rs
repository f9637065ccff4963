//! The torque of one cylinder on the crank, seed 001 eq. 3–5 (first order in λ = r/l):
//!
//! `T = P·π(d/2)²·r_v − m_osc·(φ̇²·r_a + φ̈·r_v)·r_v` with
//! `r_v = r(sin φ + λ/2·sin 2φ)`, `r_a = r(cos φ + λ·cos 2φ)` (eq. 4) and
//! `m_osc = m_p + m_A − J0/l²` (the model's `reciprocating_mass − rod_inertia_correction`),
//! `φ` the crank angle from that cylinder's firing TDC (eq. 5: `φ_i = θ* − firing_angle_i`).

use crate::model::{Engine, Pressure, PressureCurve};

/// One bar in pascal.
const PA_PER_BAR: f64 = 1.0e5;

/// Oscillating mass `m_p + m_A − J0/l²` of one cylinder, kg.
pub fn oscillating_mass_kg(engine: &Engine) -> f64 {
    engine.reciprocating_mass_kg - engine.rod_inertia_correction_kg
}

/// λ = r/l.
pub fn lambda(engine: &Engine) -> f64 {
    engine.crank_radius_m / engine.conrod_length_m
}

/// `r_v(φ) = r(sin φ + λ/2 sin 2φ)`, m: the piston speed per unit crank speed (eq. 4).
pub fn r_v(engine: &Engine, phi_rad: f64) -> f64 {
    let l = lambda(engine);
    engine.crank_radius_m * (phi_rad.sin() + 0.5 * l * (2.0 * phi_rad).sin())
}

/// `r_a(φ) = r(cos φ + λ cos 2φ)`, m: the piston acceleration per unit crank speed² (eq. 4).
pub fn r_a(engine: &Engine, phi_rad: f64) -> f64 {
    let l = lambda(engine);
    engine.crank_radius_m * (phi_rad.cos() + l * (2.0 * phi_rad).cos())
}

/// Piston area `π(d/2)²`, m².
pub fn piston_area_m2(engine: &Engine) -> f64 {
    std::f64::consts::PI * engine.bore_m * engine.bore_m / 4.0
}

/// Cycle-mean inertia the reciprocating parts of one cylinder add to its crank node:
/// the mean of `m_osc·r_v²`, `m_osc·r²·(1/2 + λ²/8)`, kg·m².
pub fn mean_reciprocating_inertia_kg_m2(engine: &Engine) -> f64 {
    let l = lambda(engine);
    oscillating_mass_kg(engine) * engine.crank_radius_m.powi(2) * (0.5 + l * l / 8.0)
}

/// Periodic linear interpolation of a pressure curve at `angle_deg` from firing TDC, bar.
fn curve_bar(curve: &PressureCurve, angle_deg: f64, cycle_deg: f64) -> f64 {
    let angles = &curve.crank_angle_deg;
    let bars = &curve.pressure_bar;
    let (Some(&first), Some(&last)) = (angles.first(), angles.last()) else {
        return 0.0;
    };
    let a = first + (angle_deg - first).rem_euclid(cycle_deg);
    if a >= last {
        // Between the last point and the first one a cycle later.
        let span = first + cycle_deg - last;
        let t = if span > 0.0 { (a - last) / span } else { 0.0 };
        return bars[bars.len() - 1] + t * (bars[0] - bars[bars.len() - 1]);
    }
    let i = angles.partition_point(|&x| x <= a).saturating_sub(1);
    let t = (a - angles[i]) / (angles[i + 1] - angles[i]);
    bars[i] + t * (bars[i + 1] - bars[i])
}

/// Cylinder gauge pressure at `angle_deg` from firing TDC and engine load 0..1, bar;
/// curves by load are interpolated linearly in load and held beyond the end loads.
pub fn pressure_bar(engine: &Engine, load: f64, angle_deg: f64) -> f64 {
    let cycle = engine.cycle_deg();
    match &engine.pressure {
        Pressure::Single(curve) => curve_bar(curve, angle_deg, cycle),
        Pressure::ByLoad(curves) => {
            let Some(first) = curves.first() else {
                return 0.0;
            };
            if curves.len() == 1 || load <= first.load {
                return curve_bar(&first.curve, angle_deg, cycle);
            }
            for pair in curves.windows(2) {
                let (a, b) = (&pair[0], &pair[1]);
                if load <= b.load {
                    let t = (load - a.load) / (b.load - a.load);
                    return (1.0 - t) * curve_bar(&a.curve, angle_deg, cycle)
                        + t * curve_bar(&b.curve, angle_deg, cycle);
                }
            }
            curve_bar(&curves[curves.len() - 1].curve, angle_deg, cycle)
        }
    }
}

/// Gas torque of one cylinder at crank angle `phi_rad` from its firing TDC, N·m.
pub fn gas_torque_nm(engine: &Engine, load: f64, phi_rad: f64) -> f64 {
    let p_pa = pressure_bar(engine, load, phi_rad.to_degrees()) * PA_PER_BAR;
    p_pa * piston_area_m2(engine) * r_v(engine, phi_rad)
}

/// Oscillating-mass torque of one cylinder, N·m: `−m_osc(φ̇² r_a + φ̈ r_v) r_v` (eq. 3).
pub fn inertia_torque_nm(
    engine: &Engine,
    phi_rad: f64,
    speed_rad_s: f64,
    accel_rad_s2: f64,
) -> f64 {
    let rv = r_v(engine, phi_rad);
    -oscillating_mass_kg(engine)
        * (speed_rad_s * speed_rad_s * r_a(engine, phi_rad) + accel_rad_s2 * rv)
        * rv
}

/// Total torque of one cylinder (eq. 3), N·m.
pub fn cylinder_torque_nm(
    engine: &Engine,
    load: f64,
    phi_rad: f64,
    speed_rad_s: f64,
    accel_rad_s2: f64,
) -> f64 {
    gas_torque_nm(engine, load, phi_rad)
        + inertia_torque_nm(engine, phi_rad, speed_rad_s, accel_rad_s2)
}

/// Cycle-mean torque of one cylinder at `load`, N·m (the gas torque's mean; the
/// oscillating-mass torque has none at constant speed): the mean of the same samples
/// whose Fourier transform gives the harmonics.
pub fn mean_torque_per_cylinder_nm(engine: &Engine, load: f64) -> f64 {
    const STEPS: usize = super::excitation::SAMPLES_PER_CYCLE;
    let cycle_rad = engine.cycle_deg().to_radians();
    let sum: f64 = (0..STEPS)
        .map(|i| gas_torque_nm(engine, load, cycle_rad * i as f64 / STEPS as f64))
        .sum();
    sum / STEPS as f64
}
