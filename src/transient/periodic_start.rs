//! A run's start on its linear periodic state: the vibration the frequency domain gives at
//! the start speed, added to the static twist of [`super::start::initial_state`].
//!
//! A start without vibration rings every mode. A lightly damped one (0.5 % of critical,
//! issue 14's benches) rings for seconds, and where its frequency is near a whole number
//! of cycle harmonics the cycle-to-cycle change that ends settling
//! ([`super::run`]) barely sees it: validation control 1001 (mode 1 at 27.87 Hz, 0.56 %)
//! settled at 1640 rpm with 0.45 rpm of order 1 left at the crank, where the bench
//! measured 0.015 rpm (a 35 σ misfit named as missing physics). Started on the forced
//! response `Θ_q` of every cycle harmonic (`(K(f)(1 + iξ) − ω²M + iωC) Θ_q = T̂_q`,
//! [`crate::response`]), the transient is only what the time domain's nonlinearity and
//! causal chain add, a small part of the vibration.
//!
//! Only a model that is linear about its static state starts so. A stage with an amplitude
//! law or a gear with free play keeps the static start (excitation switched on at rest,
//! as a bench's truth is settled): such a model can hold more than one periodic state,
//! and the linear one is not the nonlinear one's start. Validation case 1036 (a rubber
//! whose α_x doubles within a cycle near mode 1, 24.6 Hz) measured 10.9 rpm of order 1.5
//! at 1250 rpm, a period-doubled response reached from rest; started on the linear state
//! the fitted amplitude law stayed on the period-one branch (0.11 rpm) and the held-out
//! χ²/N was 1535 against 27 from rest.
//!
//! The torque convention is [`crate::physics::excitation`]'s, `T = Re(T̂_q e^{i q θ*})`
//! with `θ* = 0` at `t = 0` ([`super::speed::SpeedProfile::at`]), so a DOF starts at
//! `Re Σ Θ_q` and speed `Re Σ i q Ω Θ_q`; a Maxwell arm (`u̇ = (x − u)/τ`) at
//! `Re Σ X_q / (1 + i q Ω τ)`. Written here because no crate solves this small complex
//! system in torsim's model terms; the solve is the sweep's in-place LU
//! ([`crate::response`]).

use super::plant::{Plant, PlantLaw};
use crate::model::Model;
use crate::physics::{ElementLaw, Excitation, System, matrices};
use crate::response::lu::LuWorkspace;
use nalgebra::DMatrix;
use num_complex::Complex64;
use std::f64::consts::TAU;

/// Highest cycle harmonic started on, as an order of the reference shaft: 24 (a
/// four-stroke's 48 harmonics; the response above has decayed with the gas torque's
/// 1/k² and the inertias' ω²).
const HIGHEST_ORDER: f64 = 24.0;
/// Largest start vibration accepted, rad, per DOF: beyond it the linear state is no start
/// (a resonance the time domain passes differently) and the static start is kept.
const LARGEST_ANGLE_RAD: f64 = 0.5;

/// Adds the linear periodic state at `speed_rpm` and `load` to the static start `y`
/// (angles, speeds and Maxwell arms of `plant`) and returns the mean power that state
/// dissipates, W (the excitation's input, `Σ_q ½ Re(T̂_q · conj(i ω_q Θ_q))`); leaves `y`
/// as it is and returns `None` when the linear system cannot be solved or its state is
/// implausibly large.
///
/// The power is what the driveline's vibration takes from the engine: at a held mean
/// speed the load receives the engine's mean torque less `P/Ω`. Handed to the governor
/// ([`super::plant::Governor::dissipation_torque_nm`]), it spares settling the governor's
/// slow loop: on the diagnosis bench at 4440 rpm the mean speed otherwise starts 0.056 rpm
/// low and takes 17 s to settle to 2e-6, and its drift leaks ~1e-3 rpm into order 0.5.
pub fn add_periodic_state(
    model: &Model,
    plant: &Plant,
    speed_rpm: f64,
    load: f64,
    y: &mut [f64],
) -> Option<f64> {
    if !linear_about_static_state(plant) {
        return None;
    }
    let (state, power_w) = periodic_state(model, plant, speed_rpm, load)?;
    for (a, d) in y.iter_mut().zip(state) {
        *a += d;
    }
    Some(power_w)
}

/// Whether no element of `plant` changes its stiffness with the vibration: no rubber whose
/// amplitude law acts (a law and elements to measure the deformation at, as
/// [`super::forces`] applies it) and no gear mesh with free play.
fn linear_about_static_state(plant: &Plant) -> bool {
    plant.elements.iter().all(|e| match &e.law {
        PlantLaw::Rubber(r) => {
            (r.amplitude_poly.is_none() && r.amplitude_saturation.is_none())
                || r.mm_per_rad.is_none()
        }
        PlantLaw::Backlash { contact, .. } => contact.is_linear(),
        PlantLaw::Linear { .. } => true,
    })
}

/// The periodic state's offset from the static start and the mean power it dissipates
/// (W), or `None`.
fn periodic_state(
    model: &Model,
    plant: &Plant,
    speed_rpm: f64,
    load: f64,
) -> Option<(Vec<f64>, f64)> {
    let n = plant.n_dof;
    if speed_rpm <= 0.0 || !speed_rpm.is_finite() {
        return None;
    }
    let system = causal_copy(model, plant);
    if system.dof_count() != n {
        return None;
    }
    let step = plant
        .system
        .cylinder_spectrum
        .as_ref()
        .map_or(0.5, |s| s.order_step);
    let count = (HIGHEST_ORDER / step).floor() as usize;
    let mut orders: Vec<f64> = (1..=count).map(|k| k as f64 * step).collect();
    for h in &model.harmonics {
        if !orders.iter().any(|q| (q - h.order).abs() < 1e-9) {
            orders.push(h.order);
        }
    }
    let excitation = Excitation::new(model, &system, load, &orders);
    let omega_ref = speed_rpm * TAU / 60.0;
    let mut offset = vec![0.0; plant.state_len];
    // The forcing on entry to each solve, `Θ_q` on return (solved in place, as the sweep).
    let mut theta = vec![Complex64::default(); n];
    let mut dynamic = DMatrix::<Complex64>::zeros(n, n);
    let mut lu = LuWorkspace::default();
    let mut forcing = vec![Complex64::default(); n];
    let mut power_w = 0.0;
    for (q, &order) in orders.iter().enumerate() {
        let omega = order * omega_ref;
        excitation.forcing(q, speed_rpm, &mut theta);
        if theta.iter().all(|f| f.norm_sqr() == 0.0) {
            continue;
        }
        forcing.copy_from_slice(&theta);
        matrices::dynamic_stiffness(&system, omega, &mut dynamic);
        if !lu.factor_solve(&mut dynamic, &mut theta) || !theta.iter().all(|v| v.is_finite()) {
            return None;
        }
        power_w += forcing
            .iter()
            .zip(&theta)
            .map(|(f, x)| 0.5 * (f * (Complex64::new(0.0, omega) * x).conj()).re)
            .sum::<f64>();
        for i in 0..n {
            offset[i] += theta[i].re;
            offset[n + i] += (Complex64::new(0.0, omega) * theta[i]).re;
        }
        for e in &plant.elements {
            if let PlantLaw::Rubber(r) = &e.law {
                let at = |d: Option<usize>| d.map_or(Complex64::default(), |d| theta[d]);
                let twist_own = (at(e.from_dof) - at(e.to_dof)) * e.ratio;
                for (j, &(_, tau)) in r.chain.arms.iter().enumerate() {
                    offset[r.arm_offset + j] += (twist_own / Complex64::new(1.0, omega * tau)).re;
                }
            }
        }
    }
    let plausible = offset[..n].iter().all(|a| a.abs() < LARGEST_ANGLE_RAD);
    plausible.then_some((offset, power_w))
}

/// Relaxation time of the stiff arm that stands in, in the linear system, for the
/// dashpot of arms taken out ([`crate::rubber::MaxwellChain::take_fast_arms`]): an arm of
/// stiffness `c_v/τ` is the dashpot `c_v` within `(ωτ)²` (1e-10 at 1.6 kHz).
const DASHPOT_TAU_S: f64 = 1e-9;

/// The plant's linear system with each rubber stage as the plant integrates it (its
/// chain, less the arms taken out, plus their dashpot), so that the start matches the
/// time domain's own stiffness and loss.
fn causal_copy(model: &Model, plant: &Plant) -> System {
    let mut system = plant.system.clone();
    // The time domain integrates a distributed shaft's lumped segments, not its exact
    // element: the start must be periodic for what is integrated.
    for e in &mut system.elements {
        if let ElementLaw::Linear {
            distributed_inertia_kg_m2,
            ..
        } = &mut e.law
        {
            *distributed_inertia_kg_m2 = 0.0;
        }
    }
    for p in &plant.elements {
        if let PlantLaw::Rubber(r) = &p.law {
            let mut chain = r.chain.clone();
            if r.viscous_s > 0.0 {
                chain
                    .arms
                    .push((r.viscous_s / DASHPOT_TAU_S, DASHPOT_TAU_S));
            }
            system.set_chain(model, p.connection, chain, None);
        }
    }
    system
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{ConnectionKind, parse_model, presets::preset};

    fn shipped(name: &str) -> Model {
        parse_model(preset(name).expect("preset").text, "p.toml").expect("model")
    }

    fn linear(model: &Model) -> bool {
        linear_about_static_state(&Plant::new(model, 1.0, None).expect("plant"))
    }

    /// The genset carries seed 000's amplitude law (eq. 1) on elements and keeps the
    /// static start; without the law it starts periodic. The diagnosis bench's gear starts
    /// periodic without free play and statically with 0.1°.
    #[test]
    fn only_a_model_linear_about_its_static_state_starts_periodic() {
        let mut genset = shipped("cng-genset");
        assert!(!linear(&genset));
        for c in &mut genset.connections {
            if let ConnectionKind::Rubber(r) = &mut c.kind {
                r.amplitude_poly = None;
            }
        }
        assert!(linear(&genset));
        let mut bench = shipped("diagnosis-bench");
        assert!(linear(&bench));
        let mut geared = false;
        for c in &mut bench.connections {
            if let ConnectionKind::Gear(g) = &mut c.kind {
                g.backlash_deg = 0.1;
                geared = true;
            }
        }
        assert!(geared, "the diagnosis bench has a gear");
        assert!(!linear(&bench));
    }
}
