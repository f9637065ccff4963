//! Excitation harmonics per engine order at constant speed.
//!
//! One cylinder's torque over a working cycle (seed 001 eq. 3–4 at constant speed, so
//! `φ̈ = 0`) is sampled and Fourier-transformed once: a gas part independent of speed and
//! an oscillating-mass part proportional to ω². Cylinder `i` fires `α_i` later, so its
//! order-q harmonic is cylinder 1's times `e^{−i q α_i}` (eq. 5). `[[harmonic]]` entries
//! add `amplitude·e^{i·phase}`. A cylinder's `pressure_scale` (extension) multiplies its
//! gas part and its share of the mean torque; its oscillating-mass part is unchanged.
//! A torque `T(θ*) = Re(T̂_q e^{i q θ*})`, θ* the absolute crank angle, is the convention
//! throughout.

use super::engine;
use super::system::System;
use crate::model::{Engine, HarmonicAmplitude, Model};
use num_complex::Complex64;
use realfft::RealFftPlanner;

/// Samples per working cycle for the Fourier transform. Orders up to 24 of a 4-stroke are
/// cycle harmonics up to 48; the piecewise-linear pressure's coefficients fall as 1/k², so
/// aliasing is below (48/8192)² ≈ 3·10⁻⁵ of the leading terms.
pub const SAMPLES_PER_CYCLE: usize = 8192;

/// Two orders closer than this are the same order.
const ORDER_TOLERANCE: f64 = 1e-9;

/// Fourier coefficients of one cylinder's torque over its working cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct CylinderSpectrum {
    /// Orders per cycle harmonic: `360/cycle_deg` (0.5 for a 4-stroke).
    pub order_step: f64,
    /// Gas torque coefficients `C_k`, N·m, k = 0.. (C_0 is the mean, real).
    pub gas_nm: Vec<Complex64>,
    /// Oscillating-mass torque coefficients per (rad/s)², N·m·s²/rad².
    pub inertia_nm_per_rad2_s2: Vec<Complex64>,
}

impl CylinderSpectrum {
    /// Cycle-mean torque of one cylinder, N·m: the gas torque's mean (the oscillating
    /// masses do no net work at constant speed).
    pub fn mean_torque_nm(&self) -> f64 {
        self.gas_nm.first().map_or(0.0, |c| c.re)
    }

    /// Gas and inertia coefficients at `order` (zero when `order` is no cycle harmonic).
    pub fn at_order(&self, order: f64) -> (Complex64, Complex64) {
        let k = (order / self.order_step).round();
        if k < 0.0 || (k * self.order_step - order).abs() > ORDER_TOLERANCE {
            return (Complex64::default(), Complex64::default());
        }
        let k = k as usize;
        (
            self.gas_nm.get(k).copied().unwrap_or_default(),
            self.inertia_nm_per_rad2_s2
                .get(k)
                .copied()
                .unwrap_or_default(),
        )
    }
}

/// Spectra kept by [`cylinder_spectrum`]: a fit or a GUI edit rebuilds the system many
/// times with the same engine, and the transform is most of a system's cost.
const SPECTRA_KEPT: usize = 16;

/// The spectrum of one cylinder's torque at engine load `load` (seed 001 eq. 3–4),
/// computed once per engine and load and then taken from a small cache.
pub fn cylinder_spectrum(engine: &Engine, load: f64) -> CylinderSpectrum {
    use std::sync::Mutex;
    type Kept = Vec<((Engine, u64), CylinderSpectrum)>;
    static KEPT: Mutex<Kept> = Mutex::new(Vec::new());
    // A cylinder's pressure scale is applied per cylinder, after the transform.
    let mut unscaled = engine.clone();
    unscaled.pressure_scale = None;
    let key = (unscaled, load.to_bits());
    if let Ok(kept) = KEPT.lock()
        && let Some((_, s)) = kept.iter().find(|(k, _)| *k == key)
    {
        return s.clone();
    }
    let spectrum = compute_cylinder_spectrum(engine, load);
    if let Ok(mut kept) = KEPT.lock() {
        if kept.len() >= SPECTRA_KEPT {
            kept.remove(0);
        }
        kept.push((key, spectrum.clone()));
    }
    spectrum
}

/// [`cylinder_spectrum`] without the cache.
fn compute_cylinder_spectrum(engine: &Engine, load: f64) -> CylinderSpectrum {
    let n = SAMPLES_PER_CYCLE;
    let cycle_rad = engine.cycle_deg().to_radians();
    let phis = (0..n).map(|i| cycle_rad * i as f64 / n as f64);
    let mut gas: Vec<f64> = phis
        .clone()
        .map(|p| engine::gas_torque_nm(engine, load, p))
        .collect();
    let mut inertia: Vec<f64> = phis
        .map(|p| engine::inertia_torque_nm(engine, p, 1.0, 0.0))
        .collect();
    let fft = RealFftPlanner::<f64>::new().plan_fft_forward(n);
    let scale = |spectrum: Vec<Complex64>| -> Vec<Complex64> {
        spectrum
            .iter()
            .enumerate()
            .map(|(k, c)| {
                if k == 0 {
                    c / n as f64
                } else {
                    2.0 * c / n as f64
                }
            })
            .collect()
    };
    let mut gas_spectrum = fft.make_output_vec();
    let mut inertia_spectrum = fft.make_output_vec();
    // Lengths match the plan, so the transforms cannot fail.
    let ok = fft.process(&mut gas, &mut gas_spectrum).is_ok()
        && fft.process(&mut inertia, &mut inertia_spectrum).is_ok();
    debug_assert!(ok);
    CylinderSpectrum {
        order_step: 360.0 / engine.cycle_deg(),
        gas_nm: scale(gas_spectrum),
        inertia_nm_per_rad2_s2: scale(inertia_spectrum),
    }
}

/// A `[[harmonic]]` whose amplitude is a table over speed.
#[derive(Debug, Clone, PartialEq)]
struct TabledHarmonic {
    /// Index into [`Excitation::orders`].
    order_index: usize,
    /// DOF it acts on.
    dof: usize,
    /// Referral ratio times `e^{i·phase}`.
    phase: Complex64,
    /// Reference speeds, rpm.
    speed_rpm: Vec<f64>,
    /// Amplitudes, N·m in the node's own shaft.
    amplitude_nm: Vec<f64>,
}

/// Forcing per order on every DOF, ready for a speed sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Excitation {
    /// The orders, in the order asked for.
    pub orders: Vec<f64>,
    /// Speed-independent part per order and DOF (gas, constant harmonics), N·m referred.
    constant: Vec<Vec<Complex64>>,
    /// Part per (crank rad/s)² per order and DOF (oscillating masses), referred.
    per_speed2: Vec<Vec<Complex64>>,
    /// Harmonics whose amplitude varies with speed.
    tabled: Vec<TabledHarmonic>,
    /// Mean engine torque per DOF, N·m referred.
    pub mean_nm: Vec<f64>,
}

impl Excitation {
    /// Harmonics of the model's engine (at `load`) and `[[harmonic]]` entries for `orders`.
    pub fn new(model: &Model, system: &System, load: f64, orders: &[f64]) -> Self {
        let n = system.dof_count();
        let zeros = || vec![vec![Complex64::default(); n]; orders.len()];
        let mut excitation = Excitation {
            orders: orders.to_vec(),
            constant: zeros(),
            per_speed2: zeros(),
            tabled: Vec::new(),
            mean_nm: vec![0.0; n],
        };
        let node_dof = |name: &str| {
            model
                .node_index(name)
                .map(|i| (system.dof_of_node[i], system.speed_ratio[i]))
        };
        if let Some(engine) = &model.engine {
            let computed;
            let spectrum = match &system.cylinder_spectrum {
                Some(s) if system.load == load => s,
                _ => {
                    computed = cylinder_spectrum(engine, load);
                    &computed
                }
            };
            let firing = engine.firing_angles_or_even_deg();
            for (cylinder, alpha_deg) in firing.iter().enumerate() {
                let Some((dof, ratio)) = node_dof(engine.node_of_cylinder(cylinder)) else {
                    continue;
                };
                let scale = engine.pressure_scale_of(cylinder);
                excitation.mean_nm[dof] += spectrum.mean_torque_nm() * scale * ratio;
                for (q, &order) in orders.iter().enumerate() {
                    let (gas, inertia) = spectrum.at_order(order);
                    let phase = Complex64::from_polar(ratio, -order * alpha_deg.to_radians());
                    excitation.constant[q][dof] += gas * scale * phase;
                    excitation.per_speed2[q][dof] += inertia * phase;
                }
            }
        }
        for h in &model.harmonics {
            let Some((dof, ratio)) = node_dof(&h.at) else {
                continue;
            };
            let Some(q) = orders
                .iter()
                .position(|&o| (o - h.order).abs() < ORDER_TOLERANCE)
            else {
                continue;
            };
            let phase = Complex64::from_polar(ratio, h.phase_deg.to_radians());
            match &h.amplitude {
                HarmonicAmplitude::Constant(a) => excitation.constant[q][dof] += phase * *a,
                HarmonicAmplitude::BySpeed {
                    speed_rpm,
                    amplitude_nm,
                } => excitation.tabled.push(TabledHarmonic {
                    order_index: q,
                    dof,
                    phase,
                    speed_rpm: speed_rpm.clone(),
                    amplitude_nm: amplitude_nm.clone(),
                }),
            }
        }
        excitation
    }

    /// Forcing vector of order number `order_index` at reference speed `speed_rpm`
    /// (referred N·m per DOF), written into `out`.
    pub fn forcing(&self, order_index: usize, speed_rpm: f64, out: &mut [Complex64]) {
        let omega = speed_rpm * std::f64::consts::TAU / 60.0;
        for ((o, c), s) in out
            .iter_mut()
            .zip(&self.constant[order_index])
            .zip(&self.per_speed2[order_index])
        {
            *o = c + s * (omega * omega);
        }
        for t in self.tabled.iter().filter(|t| t.order_index == order_index) {
            out[t.dof] += t.phase * interpolate_held(&t.speed_rpm, &t.amplitude_nm, speed_rpm);
        }
    }
}

/// Linear interpolation in a table, held at the end values.
pub fn interpolate_held(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    match (xs.first(), xs.last()) {
        (Some(&x0), _) if x <= x0 => ys[0],
        (_, Some(&x1)) if x >= x1 => ys[ys.len() - 1],
        (Some(_), Some(_)) => {
            let i = xs.partition_point(|&v| v <= x).saturating_sub(1);
            let t = (x - xs[i]) / (xs[i + 1] - xs[i]);
            ys[i] + t * (ys[i + 1] - ys[i])
        }
        _ => 0.0,
    }
}
