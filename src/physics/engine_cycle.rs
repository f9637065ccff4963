//! One working cycle of the engine, for a person to look at (issue 16: the engine editor
//! said only "85 points"): a cylinder's gas pressure, its gas torque (seed 001 eq. 3–5,
//! [`super::engine::gas_torque_nm`]), the whole engine's gas torque with every cylinder at
//! its firing angle and pressure scale, and that torque's harmonic spectrum by engine
//! order, at one load. Gas torque only: the oscillating-mass torque grows with speed², and
//! the forced response shows it.

use super::engine::{gas_torque_nm, pressure_bar};
use crate::model::Engine;

/// Samples per working cycle: the excitation's own ([`super::excitation::SAMPLES_PER_CYCLE`]),
/// so that the mean and the harmonics are those every analysis uses.
pub const CYCLE_SAMPLES: usize = super::excitation::SAMPLES_PER_CYCLE;
/// The highest engine order of the spectrum: 12.
pub const MAX_ORDER: f64 = 12.0;

/// The cycle at one load.
#[derive(Debug, Clone, PartialEq)]
pub struct EngineCycle {
    /// The load, 0–1.
    pub load: f64,
    /// Crank angle of cylinder 1 from its firing TDC, degrees, over one cycle centred on
    /// it (−360 … 360° for a four-stroke).
    pub angle_deg: Vec<f64>,
    /// Cylinder 1's gauge pressure, bar.
    pub pressure_bar: Vec<f64>,
    /// Cylinder 1's gas torque on the crank, N·m.
    pub cylinder_torque_nm: Vec<f64>,
    /// Every cylinder's gas torque summed, N·m (as if the crank were rigid).
    pub engine_torque_nm: Vec<f64>,
    /// The engine torque's cycle mean, N·m.
    pub mean_torque_nm: f64,
    /// Engine orders of the spectrum: the cycle's harmonics up to [`MAX_ORDER`].
    pub orders: Vec<f64>,
    /// Amplitude of the engine torque at each order, N·m.
    pub order_amplitude_nm: Vec<f64>,
}

/// The cycle of `engine` at `load`.
pub fn engine_cycle(engine: &Engine, load: f64) -> EngineCycle {
    let cycle_deg = engine.cycle_deg();
    let n = CYCLE_SAMPLES;
    // Centred on cylinder 1's firing TDC: −360 … 360° for a four-stroke.
    let angle_deg: Vec<f64> = (0..n)
        .map(|i| cycle_deg * (i as f64 / n as f64 - 0.5))
        .collect();
    let firing = engine.firing_angles_or_even_deg();
    let torque_at = |a_deg: f64| gas_torque_nm(engine, load, a_deg.to_radians());
    let cylinder_torque_nm: Vec<f64> = angle_deg.iter().map(|&a| torque_at(a)).collect();
    let engine_torque_nm: Vec<f64> = angle_deg
        .iter()
        .map(|&a| {
            firing
                .iter()
                .enumerate()
                .map(|(c, &f)| {
                    let scale = engine.pressure_scale_of(c);
                    scale * torque_at((a - f).rem_euclid(cycle_deg))
                })
                .sum()
        })
        .collect();
    let mean_torque_nm = engine_torque_nm.iter().sum::<f64>() / n as f64;
    // The cycle's k-th harmonic is order k·360/cycle (0.5 steps for a four-stroke).
    let order_step = 360.0 / cycle_deg;
    let harmonics = (MAX_ORDER / order_step).round() as usize;
    let (orders, order_amplitude_nm) = (1..=harmonics)
        .map(|k| {
            let (mut re, mut im) = (0.0, 0.0);
            for (i, t) in engine_torque_nm.iter().enumerate() {
                let x = std::f64::consts::TAU * (k * i) as f64 / n as f64;
                re += t * x.cos();
                im -= t * x.sin();
            }
            (k as f64 * order_step, 2.0 * re.hypot(im) / n as f64)
        })
        .unzip();
    EngineCycle {
        load,
        pressure_bar: angle_deg
            .iter()
            .map(|&a| pressure_bar(engine, load, a))
            .collect(),
        angle_deg,
        cylinder_torque_nm,
        engine_torque_nm,
        mean_torque_nm,
        orders,
        order_amplitude_nm,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{parse_model, presets};
    use crate::physics::engine::mean_torque_per_cylinder_nm;
    use crate::physics::excitation::cylinder_spectrum;

    fn engine(preset: &str) -> Engine {
        let p = presets::preset(preset).expect("preset");
        parse_model(p.text, p.name)
            .expect("model")
            .engine
            .expect("engine")
    }

    /// cng-genset at full load: the mean is six cylinders' (1326 N·m, 250 kW at 1800 rpm,
    /// seed 000); an even-firing in-line six passes only the multiples of order 3 of its
    /// cylinders' torque (the others cancel, to the sampling's 1e-5 of the mean); and
    /// order 3 is six times one cylinder's order 3, from the excitation's own spectrum.
    #[test]
    fn the_six_cylinder_cycle_adds_up() {
        let e = engine("cng-genset");
        let c = engine_cycle(&e, 1.0);
        let per_cylinder = mean_torque_per_cylinder_nm(&e, 1.0);
        // Each cylinder is sampled 8192 times a cycle at its own phase of the pressure
        // table, so the sums differ by the sampling rule's error: measured 2.2e-7.
        assert!((c.mean_torque_nm - 6.0 * per_cylinder).abs() < 1e-6 * c.mean_torque_nm);
        assert!((c.mean_torque_nm - 250e3 / (1800.0 * std::f64::consts::TAU / 60.0)).abs() < 1.0);
        let one = cylinder_spectrum(&e, 1.0);
        for (q, a) in c.orders.iter().zip(&c.order_amplitude_nm) {
            let k = (q / one.order_step).round() as usize;
            let single = one.gas_nm.get(k).map_or(0.0, |z| z.norm());
            if (q / 3.0 - (q / 3.0).round()).abs() < 1e-9 {
                assert!(
                    (a - 6.0 * single).abs() < 1e-3 * a.max(1.0),
                    "order {q}: {a} vs 6 × {single}"
                );
            } else {
                assert!(*a < 1e-5 * c.mean_torque_nm, "order {q} should cancel: {a}");
            }
        }
    }
}
